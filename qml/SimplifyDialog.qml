// SimplifyDialog: the tolerance for "Simplify curve…", typed in the UI language's number format;
// PieceEdits parses it, refits the curve and says why when nothing simpler stays within it. Kontur's
// own buttons, as ConfirmDialog explains.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

Dialog {
    id: dialog

    required property PieceEdits pieceEdits
    // The document's unit, shown beside the field.
    property string units
    property int curveId: 0

    function openFor(curve) {
        curveId = curve
        toleranceField.text = pieceEdits.suggestedToleranceText()
        refused = false
        open()
        toleranceField.forceActiveFocus()
    }
    function apply() {
        if (dialog.pieceEdits.simplifyText(dialog.curveId, toleranceField.text))
            close()
        else
            refused = true
    }
    property bool refused: false

    title: qsTr("Simplify curve")
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width * 0.9 : 420, 420)
    modal: true
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24

    ColumnLayout {
        width: parent ? parent.width : 0
        spacing: Theme.spacing / 2
        Label {
            Layout.fillWidth: true
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            text: qsTr("The new curve stays within this distance of the old one.")
        }
        RowLayout {
            Layout.fillWidth: true
            Label { text: qsTr("Tolerance") }
            TextField {
                id: toleranceField
                objectName: "simplifyTolerance"
                Accessible.name: qsTr("Tolerance")
                Layout.fillWidth: true
                Layout.preferredHeight: Theme.touchMinimum
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                onAccepted: dialog.apply()
            }
            Label { text: Numbers.unit(dialog.units, Language.current) }
        }
        Label {
            objectName: "simplifyMessage"
            Layout.fillWidth: true
            visible: dialog.refused && text.length > 0
            wrapMode: Text.Wrap
            text: dialog.pieceEdits.message.text
        }
    }

    footer: DialogButtonBox {
        Button {
            objectName: "simplifyApply"
            text: qsTr("Simplify")
            Accessible.name: text
            DialogButtonBox.buttonRole: DialogButtonBox.ApplyRole
            onClicked: dialog.apply()
        }
        Button {
            text: qsTr("Cancel")
            Accessible.name: text
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
    }
}
