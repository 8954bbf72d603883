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
    signal closeRequested()

    padding: Theme.spacing / 2
    background: Rectangle {
        color: Theme.panelBackground
        Rectangle { width: parent.width; height: 1; color: Theme.toolbarBorder }
    }

    BasisPlot {
        id: basis
        objectName: "basisPlot"
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 2

        // Header: collapse, title, the family and its size, close.
        Flow {
            Layout.fillWidth: true
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
                model: [qsTr("Of the selected curve"), qsTr("Bernstein"), qsTr("B-spline"), qsTr("Bell functions"), qsTr("Hermite")]
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
            ToolButton {
                objectName: "basisCloseButton"
                text: "\u2715"
                implicitWidth: Theme.touchMinimum
                height: Math.max(Theme.touchMinimum, implicitHeight)
                onClicked: panel.closeRequested()
                Accessible.name: qsTr("Close the basis functions")
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
            elide: Text.ElideRight
            text: basis.knotText
        }
        Label {
            objectName: "basisValuesText"
            visible: panel.expanded
            Layout.fillWidth: true
            elide: Text.ElideRight
            color: Theme.mutedText
            text: basis.valuesText
        }
    }
}
