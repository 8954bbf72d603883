// ConfirmDialog: a question with Kontur's own answer buttons, Yes and No unless named otherwise, and a
// destructive one when `discardText` is given (the unsaved-changes question: Save, Don't save,
// Cancel); an empty `rejectText` leaves that button out (the recovery question: Recover, Discard). Kontur's own buttons, not standardButtons: Qt writes a standard button's text once, in the
// language of that moment (a switch leaves it behind), and Debian's Qt has none in Slovak.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import Kontur

Dialog {
    id: dialog

    // The question.
    property string text
    property string acceptText: qsTr("Yes")
    property string rejectText: qsTr("No")
    property string discardText

    // Centred over the whole window, whatever item declares it.
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width * 0.9 : 460, 460)
    modal: true
    // Flat where the software backend cannot draw the elevation shadow (it loses the background too).
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24

    footer: DialogButtonBox {
        id: buttons
        Button {
            text: dialog.acceptText
            DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
        }
        Button {
            id: discardButton
            text: dialog.discardText
            DialogButtonBox.buttonRole: DialogButtonBox.DestructiveRole
        }
        Button {
            id: rejectButton
            text: dialog.rejectText
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
    }
    Component.onCompleted: {
        if (discardText.length === 0)
            buttons.removeItem(discardButton)
        if (rejectText.length === 0)
            buttons.removeItem(rejectButton)
    }
    // A destructive answer does not close a dialog by itself.
    Connections {
        target: dialog
        function onDiscarded() { dialog.close() }
    }

    Label {
        width: parent ? parent.width : 0
        // Wrapped only while shown: wrapped while the dialog was made (in a window that already had
        // its size), the text's height fed the dialog's height in the middle of its own binding.
        wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
        text: dialog.text
    }
}
