// BasisPlotPanel: the basis functions of the selected curve, plotted under the canvas (issue 9):
// Bernstein, B-spline (with its knot vector), seed 001's bells or Hermite bases. The selected
// control point's function is highlighted; the t marker can be dragged, tapped or moved with the
// arrow keys, and follows `parameter` (bound to the de Casteljau view's t by Main).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Pane {
    id: panel

    property alias editor: basis.editor
    property alias parameter: basis.parameter
    property alias basis: basis
    property bool expanded: true
    // Enlarged by its button: the plot takes most of the window's height (a class at a projector).
    property bool enlarged: false
    signal closeRequested()

    padding: Theme.spacing / 2
    background: Rectangle {
        color: Theme.panelBackground
        Rectangle { width: parent.width; height: 1; color: Theme.toolbarBorder }
    }

    BasisPlot {
        id: basis
        objectName: "basisPlot"
        // The header's boxes change with the family: laid out again in the next frames (Qt 6.4's
        // positioner kept old places while the texts widened, and stacked them at its left).
        onPlotChanged: panel.relayoutFrames = 3
    }
    property int relayoutFrames: 0
    Connections {
        target: panel.Window.window
        enabled: panel.relayoutFrames > 0
        function onAfterAnimating() {
            panel.relayoutFrames = panel.relayoutFrames - 1
            headerFlow.forceLayout()
        }
    }
    onVisibleChanged: relayoutFrames = 3

    ColumnLayout {
        anchors.fill: parent
        spacing: 2

        // Header: collapse, title, the family and its size; enlarge and close at its top right, where
        // they stay whatever family is shown (in the flow they moved with its boxes).
        Item {
            Layout.fillWidth: true
            implicitHeight: Math.max(headerFlow.implicitHeight, corner.implicitHeight)
        Row {
            id: corner
            anchors.right: parent.right
            anchors.top: parent.top
            spacing: Theme.spacing / 2
            ToolButton {
                objectName: "basisEnlargeButton"
                visible: panel.expanded
                text: panel.enlarged ? "\u2b07" : "\u2b06"
                implicitWidth: Theme.touchMinimum
                height: Math.max(Theme.touchMinimum, implicitHeight)
                onClicked: panel.enlarged = !panel.enlarged
                Accessible.name: panel.enlarged ? qsTr("Make the basis functions smaller") : qsTr("Enlarge the basis functions")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: Accessible.name
            }
            ToolButton {
                objectName: "basisCloseButton"
                text: "\u2715"
                implicitWidth: Theme.touchMinimum
                height: Math.max(Theme.touchMinimum, implicitHeight)
                onClicked: panel.closeRequested()
                Accessible.name: qsTr("Close the basis functions")
            }
        }
        Flow {
            id: headerFlow
            anchors.left: parent.left
            anchors.right: corner.left
            anchors.rightMargin: Theme.spacing
            spacing: Theme.spacing
            ToolButton {
                objectName: "basisCollapseButton"
                text: panel.expanded ? "\u25be" : "\u25b8"
                implicitWidth: Theme.touchMinimum
                height: Math.max(Theme.touchMinimum, implicitHeight)
                onClicked: panel.expanded = !panel.expanded
                Accessible.name: panel.expanded ? qsTr("Collapse the basis functions") : qsTr("Expand the basis functions")
            }
            Label {
                objectName: "basisTitle"
                height: Math.max(Theme.touchMinimum, implicitHeight)
                verticalAlignment: Text.AlignVCenter
                font.bold: true
                text: basis.title
            }
            ChoiceBox {
                id: familyBox
                objectName: "basisFamilyBox"
                implicitHeight: Theme.touchMinimum
                // At least 250 px; wider where a translation or presentation mode's larger font needs it.
                implicitContentWidthPolicy: ComboBox.WidestText
                implicitWidth: Math.max(250, implicitContentWidth + leftPadding + rightPadding)
                //: Choices of the basis functions plotted: the selected curve's own, or a family named with its basis.
                model: [qsTr("Of the selected curve"), qsTr("Bernstein basis"), qsTr("B-spline"), qsTr("Bell functions"), qsTr("Hermite basis")]
                chosen: basis.family
                onActivated: (index) => basis.family = index
                Accessible.name: qsTr("Basis functions")
            }
            Label {
                visible: degreeBox.visible
                height: Math.max(Theme.touchMinimum, implicitHeight)
                verticalAlignment: Text.AlignVCenter
                text: qsTr("Degree")
            }
            SpinBox {
                id: degreeBox
                objectName: "basisDegreeBox"
                visible: basis.shownFamily === BasisPlot.Bernstein && basis.family !== BasisPlot.Auto
                height: Math.max(Theme.touchMinimum, implicitHeight)
                from: 1; to: 30
                value: basis.degree
                editable: true
                onValueModified: basis.degree = value
                Accessible.name: qsTr("Degree")
            }
            Label {
                visible: orderBox.visible
                height: Math.max(Theme.touchMinimum, implicitHeight)
                verticalAlignment: Text.AlignVCenter
                //: Label (noun): the order k of the B-spline basis functions (degree + 1), a number.
                text: qsTr("Order")
            }
            SpinBox {
                id: orderBox
                objectName: "basisOrderBox"
                visible: (basis.shownFamily === BasisPlot.BSpline || basis.shownFamily === BasisPlot.Bell)
                         && basis.family !== BasisPlot.Auto
                height: Math.max(Theme.touchMinimum, implicitHeight)
                from: 2; to: 10
                value: basis.order
                editable: true
                onValueModified: basis.order = value
                Accessible.name: qsTr("Order")
            }
            Label {
                visible: orderBox.visible
                height: Math.max(Theme.touchMinimum, implicitHeight)
                verticalAlignment: Text.AlignVCenter
                //: Label (noun): how many basis functions are drawn (a number beside it).
                text: qsTr("Functions")
            }
            SpinBox {
                objectName: "basisCountBox"
                visible: orderBox.visible
                height: Math.max(Theme.touchMinimum, implicitHeight)
                from: 2; to: 30
                value: basis.count
                editable: true
                onValueModified: basis.count = value
                Accessible.name: qsTr("Number of basis functions")
            }
        }
        }

        PlotView {
            id: plot
            objectName: "basisPlotView"
            visible: panel.expanded
            source: basis
            fontPixelSize: Theme.plotFontSize
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.minimumHeight: 100
            Accessible.name: qsTr("Plot of the basis functions; the left and right arrow keys move t")
        }
        Label {
            objectName: "basisKnotText"
            visible: panel.expanded && text.length > 0
            Layout.fillWidth: true
            // Wrapped, not elided: a class reads all of it.
            wrapMode: Text.Wrap
            text: basis.knotText
        }
        Label {
            objectName: "basisValuesText"
            visible: panel.expanded
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            color: Theme.mutedText
            text: basis.valuesText
        }
    }
}
