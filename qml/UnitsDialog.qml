// UnitsDialog: which units a drawing is in, asked once for a file that does not say (a DXF without
// $INSUNITS): mm, cm, in or px. FileController remembers the answer for files of that kind and uses
// it from then on; `chosen(units)` hands it over, after which the file is opened or imported.
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

    ButtonGroup {
        id: group
    }
    ColumnLayout {
        width: parent ? parent.width : 0
        Label {
            Layout.fillWidth: true
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            text: qsTr("“%1” does not say which units its numbers are in. Read them as (asked once for such files):")
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
