// MessageBanner: the editor's message (a refusal, a problem, a file saved) over the top of the canvas,
// in the current language: the text is a property of the editor that follows a language switch. It
// blocks nothing and goes after 8 seconds or with its close button; a message that offers a change
// (the units of DXF files that name none) shows its button and stays until it is closed or replaced.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Rectangle {
    id: banner

    required property EditController editor

    // The user asked to change the units of files that name none (the message offers it).
    signal unitsRequested()

    visible: editor.message.id !== 0
    width: Math.min((parent ? parent.width : 0) - 2 * Theme.spacing, row.implicitWidth + 2 * Theme.spacing)
    height: row.implicitHeight + Theme.spacing
    radius: 6
    color: Theme.bannerBackground
    border.color: Theme.bannerBorder

    RowLayout {
        id: row
        anchors.fill: parent
        anchors.leftMargin: Theme.spacing
        Label {
            objectName: "messageText"
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: banner.editor.message.text
        }
        Button {
            objectName: "messageChangeUnits"
            visible: banner.editor.message.offersUnits
            flat: true
            //: Button in the message that a DXF without units was read in the units chosen for such files.
            text: qsTr("Change units…")
            Accessible.name: text
            Layout.minimumHeight: Theme.touchMinimum
            onClicked: banner.unitsRequested()
        }
        ToolButton {
            text: "\u2715"
            Accessible.name: qsTr("Close message")
            onClicked: banner.editor.clearMessage()
        }
    }
    Timer {
        running: banner.visible && !banner.editor.message.offersUnits
        interval: 8000
        onTriggered: banner.editor.clearMessage()
    }
}
