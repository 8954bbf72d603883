// SidePanel: the curves of the document and the coordinates of the selected curve's points.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Pane {
    id: panel

    required property EditController editor

    padding: 0
    background: Rectangle { color: Theme.panelBackground }

    ColumnLayout {
        anchors.fill: parent
        spacing: 0

        Label {
            text: qsTr("Curves")
            font.bold: true
            padding: Theme.spacing
        }
        ListView {
            id: curveList
            objectName: "curveList"
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, panel.height / 2)
            clip: true
            model: panel.editor.curves
            delegate: ItemDelegate {
                id: curveRow
                required property int index
                required property string name
                required property string kindName
                required property int pointCount
                required property real length
                required property string continuity
                required property bool problem
                required property bool selected
                width: ListView.view.width
                highlighted: selected
                onClicked: panel.editor.selectedCurve = index
                contentItem: Column {
                    spacing: 2
                    Label {
                        width: parent.width
                        text: curveRow.name
                        font.bold: true
                        elide: Text.ElideRight
                    }
                    Label {
                        width: parent.width
                        color: curveRow.problem ? Theme.controlPoint : Theme.mutedText
                        font.pixelSize: 12
                        elide: Text.ElideRight
                        // Language.current: numbers and words follow a language switch.
                        text: Language.current, curveRow.problem
                              ? qsTr("%1 · cannot be drawn from these points").arg(curveRow.kindName)
                              : qsTr("%1 · %n point(s) · length %2", "", curveRow.pointCount)
                                .arg(curveRow.kindName)
                                .arg(Number(curveRow.length).toLocaleString(Qt.locale(Language.current), "f", 1))
                                + (curveRow.continuity.length > 0 ? " · " + curveRow.continuity : "")
                    }
                }
            }
        }

        Label {
            objectName: "noCurvesLabel"
            visible: curveList.count === 0
            text: qsTr("No curves yet.")
            color: Theme.mutedText
            leftPadding: Theme.spacing
        }

        Label {
            text: qsTr("Points")
            font.bold: true
            padding: Theme.spacing
            visible: panel.editor.selectedCurve >= 0
        }
        RowLayout {
            visible: panel.editor.selectedCurve >= 0
            Layout.fillWidth: true
            Layout.leftMargin: 2 * Theme.spacing
            Layout.rightMargin: 2 * Theme.spacing
            Item { Layout.preferredWidth: 40 }
            Label { text: "X"; color: Theme.mutedText; horizontalAlignment: Text.AlignRight; Layout.fillWidth: true }
            Label { text: "Y"; color: Theme.mutedText; horizontalAlignment: Text.AlignRight; Layout.fillWidth: true }
        }
        ListView {
            objectName: "pointList"
            Layout.fillWidth: true
            Layout.fillHeight: true
            clip: true
            visible: panel.editor.selectedCurve >= 0
            model: panel.editor.points
            delegate: ItemDelegate {
                id: pointRow
                required property int index
                // The roles are named x and y like the coordinates window; read them through
                // `model` because an Item has x and y of its own.
                required property var model
                width: ListView.view.width
                highlighted: index === panel.editor.selectedPoint
                contentItem: RowLayout {
                    Label { text: pointRow.model.label; font.bold: true; Layout.preferredWidth: 40 }
                    Label {
                        text: Number(pointRow.model.x).toLocaleString(Qt.locale(Language.current), "f", 2)
                        horizontalAlignment: Text.AlignRight
                        Layout.fillWidth: true
                    }
                    Label {
                        text: Number(pointRow.model.y).toLocaleString(Qt.locale(Language.current), "f", 2)
                        horizontalAlignment: Text.AlignRight
                        Layout.fillWidth: true
                    }
                }
            }
        }
        Item { Layout.fillHeight: true; visible: panel.editor.selectedCurve < 0 }
    }
}
