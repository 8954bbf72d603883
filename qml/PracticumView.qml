// PracticumView: seed 003's cubic segments with guide vectors (KG-202) and the multi-segment
// spline (KG-203), drawn with a number of lines per segment, by lines or by points (issue 9).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Popup {
    id: view
    objectName: "practicumView"

    property alias practicum: practicum
    readonly property bool wide: width >= 900

    modal: true
    focus: true
    closePolicy: Popup.CloseOnEscape
    x: 0
    y: 0
    width: parent ? parent.width : 800
    height: parent ? parent.height : 600
    padding: Theme.spacing
    background: Rectangle { color: Theme.panelBackground }

    PracticumPlot {
        id: practicum
        objectName: "practicumPlot"
    }
    Shortcut { sequences: [StandardKey.Undo]; enabled: view.visible; onActivated: practicum.undo() }
    Shortcut { sequences: [StandardKey.Redo, "Ctrl+Shift+Z"]; enabled: view.visible; onActivated: practicum.redo() }

    // The title across the page and Close at its top right, in every language and size at one place,
    // never under the form's first control nor elided (in the form's column it was both).
    Item {
        id: header
        anchors.left: parent.left
        anchors.right: parent.right
        anchors.top: parent.top
        height: Math.max(title.implicitHeight, closeButton.height)
        Label {
            id: title
            anchors.left: parent.left
            anchors.right: closeButton.left
            anchors.rightMargin: Theme.spacing
            anchors.verticalCenter: parent.verticalCenter
            text: qsTr("Cubic segments")
            font.bold: true
            font.pixelSize: Theme.titleFontSize
            wrapMode: Text.Wrap
        }
        Button {
            id: closeButton
            flat: true
            objectName: "practicumClose"
            anchors.right: parent.right
            anchors.top: parent.top
            height: Math.max(Theme.touchMinimum, implicitHeight)
            //: Button (verb): closes this teaching view and returns to the drawing.
            text: qsTr("Close")
            onClicked: view.close()
        }
    }

    GridLayout {
        anchors.left: parent.left
        anchors.right: parent.right
        anchors.top: header.bottom
        anchors.bottom: parent.bottom
        anchors.topMargin: Theme.spacing / 2
        columns: view.wide ? 2 : 1
        columnSpacing: Theme.spacing
        rowSpacing: Theme.spacing

        ScrollView {
            id: inputs
            Layout.preferredWidth: view.wide ? Theme.formWidth : -1
            Layout.fillWidth: !view.wide
            Layout.fillHeight: view.wide
            Layout.preferredHeight: view.wide ? -1 : Math.min(form.implicitHeight, view.height * 0.45)
            contentWidth: availableWidth
            clip: true

            ColumnLayout {
                id: form
                width: inputs.availableWidth
                spacing: Theme.spacing / 2
                ChoiceBox {
                    objectName: "practicumMode"
                    Layout.fillWidth: true
                    implicitHeight: Theme.touchMinimum
                    model: [qsTr("Function segment y(x)"), qsTr("Parametric segment"), qsTr("Spline through several points")]
                    chosen: practicum.mode
                    onActivated: (index) => practicum.mode = index
                    Accessible.name: qsTr("Kind of segment")
                }
                Label { text: qsTr("Lines per segment"); Layout.fillWidth: true; wrapMode: Text.Wrap }
                SpinBox {
                    objectName: "linesPerSegmentBox"
                    from: 1; to: 200
                    value: practicum.linesPerSegment
                    editable: true
                    Layout.minimumHeight: Theme.touchMinimum
                    onValueModified: practicum.linesPerSegment = value
                    Accessible.name: qsTr("Lines per segment")
                }
                Flow {
                    Layout.fillWidth: true
                    RadioButton {
                        objectName: "drawByLines"
                        text: qsTr("By lines")
                        checked: !practicum.byPoints
                        onToggled: if (checked) practicum.byPoints = false
                    }
                    RadioButton {
                        objectName: "drawByPoints"
                        text: qsTr("By points")
                        checked: practicum.byPoints
                        onToggled: if (checked) practicum.byPoints = true
                    }
                }
                Flow {
                    Layout.fillWidth: true
                    spacing: Theme.spacing / 2
                    Button {
                        flat: true
                        text: qsTr("Undo")
                        enabled: practicum.canUndo
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: practicum.undo()
                    }
                    Button {
                        flat: true
                        text: qsTr("Redo")
                        enabled: practicum.canRedo
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: practicum.redo()
                    }
                    Button {
                        flat: true
                        objectName: "practicumSegmentExample"
                        //: Button: loads the practicum's single-segment example (KG-202: two points, guide vectors
                        //: rising and falling at 45°), in the segment kind chosen.
                        text: qsTr("Segment example")
                        implicitHeight: Theme.touchMinimum
                        onClicked: practicum.loadSegmentExample()
                    }
                    Button {
                        flat: true
                        objectName: "practicumDebugExample"
                        text: qsTr("Test example")
                        implicitHeight: Theme.touchMinimum
                        onClicked: practicum.loadDebugExample()
                    }
                }
                Label {
                    objectName: "practicumError"
                    visible: text.length > 0
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: "#b00020"
                    text: practicum.error.text
                }
                Label {
                    objectName: "practicumDetails"
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    text: practicum.details
                }
                Label {
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: Theme.mutedText
                    text: qsTr("Drag the green points, or the grey grips at the ends of the guide vectors to change the end directions.")
                }
            }
        }

        PlotView {
            objectName: "practicumPlotView"
            source: practicum
            fontPixelSize: Theme.plotFontSize
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.minimumHeight: 200
        }
    }
}
