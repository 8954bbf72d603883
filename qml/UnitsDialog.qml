// UnitsDialog: which units a drawing is in, asked once for a file that does not say (a DXF without
// $INSUNITS): mm, cm, in or px. DocumentFiles remembers the answer for files of that kind and uses
// it from then on; `chosen(units)` hands it over, after which the file is opened or imported. With
// `changing` it changes that answer later (offered by the message after such a file was read).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur

Dialog {
    id: dialog

    // The file's name, for the question.
    property string fileName
    // Changing the remembered units rather than asking for the first time; `current` is checked first.
    property bool changing: false
    property string current: "mm"
    readonly property string units: group.checkedButton ? group.checkedButton.text : "mm"

    signal chosen(string units)

    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width * 0.9 : 460, 460)
    modal: true
    title: qsTr("Units of the drawing")
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24

    footer: DialogButtonBox {
        Button {
            objectName: "unitsAccept"
            text: qsTr("OK")
            DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
        }
        Button {
            text: qsTr("Cancel")
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
    }
    onAccepted: dialog.chosen(dialog.units)
    onAboutToShow: {
        for (let i = 0; i < group.buttons.length; ++i)
            group.buttons[i].checked = group.buttons[i].text === dialog.current
    }

    ButtonGroup {
        id: group
    }
    ColumnLayout {
        width: parent ? parent.width : 0
        Label {
            Layout.fillWidth: true
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            text: dialog.changing
                  ? qsTr("Read DXF files that do not say which units their numbers are in as:")
                  : qsTr("“%1” does not say which units its numbers are in. Read them as (asked once for such files):")
                    .arg(dialog.fileName)
        }
        Flow {
            Layout.fillWidth: true
            Repeater {
                model: ["mm", "cm", "in", "px"]
                RadioButton {
                    required property string modelData
                    required property int index
                    objectName: "units_" + modelData
                    text: modelData
                    checked: index === 0
                    ButtonGroup.group: group
                    Accessible.name: modelData
                }
            }
        }
    }
}
