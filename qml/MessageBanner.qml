// MessageBanner: the editor's message (a refusal, a problem, a file saved) over the top of the canvas,
// in the current language: the text is a property of the editor that follows a language switch. It
// blocks nothing and goes after 8 seconds or with its close button.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Rectangle {
    id: banner

    required property EditController editor

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
            text: banner.editor.messageText
        }
        ToolButton {
            text: "\u2715"
            Accessible.name: qsTr("Close message")
            onClicked: banner.editor.clearMessage()
        }
    }
    Timer {
        running: banner.visible
        interval: 8000
        onTriggered: banner.editor.clearMessage()
    }
}
