// SidePanel: the curves of the document, the selected curve's settings, its coordinates table (the
// seed's coordinates window), information about it, and the background image.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Pane {
    id: panel

    required property EditController editor
    // Asks the window to open the background image dialog.
    signal loadBackgroundRequested()

    readonly property int curve: editor.selectedCurve
    readonly property bool hasCurve: curve >= 0
    // The selected curve's row of the curve list, re-read when that row changes.
    property var curveData: ({})

    function refreshCurveData() {
        const model = editor.curves
        // `curve`, not `hasCurve`: in onCurveChanged the hasCurve binding may not be updated yet.
        if (curve < 0 || curve >= model.rowCount()) {
            curveData = ({})
            return
        }
        const index = model.index(curve, 0)
        const roles = ["name", "kind", "kindName", "color", "curveVisible", "locked", "parameterization",
                       "pointCount", "length", "fitRms", "fitMaxError", "continuity", "problem"]
        const data = {}
        for (const role of roles)
            data[role] = model.data(index, CurveListModel.NameRole + roles.indexOf(role))
        curveData = data
    }
    // Rounded for showing, in exponent form when very large or small (C++ decides the form).
    function number(value, decimals) {
        return editor.displayNumber(value, decimals)
    }

    onCurveChanged: refreshCurveData()
    Connections {
        target: panel.editor.curves
        function onDataChanged() { panel.refreshCurveData() }
        function onRowsInserted() { panel.refreshCurveData() }
        function onRowsRemoved() { panel.refreshCurveData() }
        function onRowsMoved() { panel.refreshCurveData() }
    }

    padding: 0
    clip: true
    background: Rectangle { color: Theme.panelBackground }

    ScrollView {
        id: scroll
        anchors.fill: parent
        contentWidth: availableWidth
        clip: true

        ColumnLayout {
            width: scroll.availableWidth
            spacing: Theme.spacing / 2

            // ---- Curves ----
            SectionLabel { text: qsTr("Curves") }
            ListView {
                id: curveList
                objectName: "curveList"
                Layout.fillWidth: true
                Layout.preferredHeight: Math.min(contentHeight, 5 * 56)
                clip: true
                interactive: contentHeight > height
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
                    required property bool curveVisible
                    width: ListView.view.width
                    highlighted: selected
                    opacity: curveVisible ? 1 : 0.55
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
                            // Two lines before eliding: the length must not be cut off behind the kind's name.
                            wrapMode: Text.Wrap
                            maximumLineCount: 2
                            elide: Text.ElideRight
                            // Language.current: numbers and words follow a language switch.
                            text: Language.current, curveRow.problem
                                  ? qsTr("%1 · cannot be drawn from these points").arg(curveRow.kindName)
                                  : qsTr("%1 · %n point(s) · length %2", "", curveRow.pointCount)
                                    .arg(curveRow.kindName).arg(panel.number(curveRow.length, 1))
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

            // ---- The selected curve ----
            SectionLabel { text: qsTr("Selected curve"); visible: panel.hasCurve }
            // One column: labels above their controls, so that long words of every language fit.
            GridLayout {
                visible: panel.hasCurve
                Layout.fillWidth: true
                Layout.leftMargin: Theme.spacing
                Layout.rightMargin: Theme.spacing
                columns: 1
                columnSpacing: Theme.spacing
                rowSpacing: 0

                Label { text: qsTr("Name") }
                TextField {
                    objectName: "curveNameField"
                    Layout.fillWidth: true
                    text: panel.curveData.name ?? ""
                    enabled: !(panel.curveData.locked ?? false)
                    onEditingFinished: if (text !== panel.curveData.name) panel.editor.setCurveName(panel.curve, text)
                }
                Label { text: qsTr("Kind") }
                Label {
                    Layout.fillWidth: true
                    text: (panel.curveData.kindName ?? "")
                          + (panel.editor.degreeOf(panel.curve) > 0
                             ? " · " + qsTr("degree %1").arg(panel.editor.degreeOf(panel.curve)) : "")
                    wrapMode: Text.Wrap
                }
                Label {
                    text: qsTr("Parameterization")
                    visible: (panel.curveData.parameterization ?? -1) >= 0
                }
                ComboBox {
                    objectName: "parameterizationBox"
                    visible: (panel.curveData.parameterization ?? -1) >= 0
                    Layout.fillWidth: true
                    model: [qsTr("Uniform"), qsTr("Chord length"), qsTr("Centripetal")]
                    currentIndex: panel.curveData.parameterization ?? 0
                    onActivated: (index) => panel.editor.setCurveParameterization(panel.curve, index)
                }
                Label {
                    text: qsTr("Order")
                    visible: orderBox.visible
                }
                SpinBox {
                    id: orderBox
                    objectName: "orderBox"
                    visible: panel.curveData.kind === EditController.BSplineKind
                    from: 2
                    to: 10
                    // Re-read whenever the curve's row changes (curveData).
                    value: panel.curveData, panel.editor.degreeOf(panel.curve) + 1
                    onValueModified: panel.editor.setCurveOrder(panel.curve, value)
                }
                Label {
                    text: qsTr("Node type")
                    visible: nodeTypeBox.visible
                }
                ComboBox {
                    id: nodeTypeBox
                    objectName: "nodeTypeBox"
                    readonly property int nodeType: panel.editor.selectedPoint >= 0
                        ? panel.editor.points.data(panel.editor.points.index(panel.editor.selectedPoint, 0),
                                                   PointListModel.NodeTypeRole) ?? -1 : -1
                    visible: panel.curveData.kind === EditController.CompositeKind && nodeType >= 0
                    Layout.fillWidth: true
                    model: [qsTr("Smooth"), qsTr("Symmetric"), qsTr("Corner")]
                    currentIndex: Math.max(0, nodeType)
                    onActivated: (index) => panel.editor.setNodeType(panel.curve, panel.editor.selectedPoint / 3, index)
                }
                Label { text: qsTr("Colour") }
                Flow {
                    Layout.fillWidth: true
                    spacing: 4
                    Repeater {
                        model: ["#000000", "#d00000", "#1f6fd1", "#1b8a3a", "#e07b00", "#7a3fb0", "#00838f", "#8d6e63"]
                        delegate: Rectangle {
                            required property string modelData
                            width: 28
                            height: 28
                            radius: 14
                            color: modelData
                            border.width: Qt.colorEqual(panel.curveData.color ?? "transparent", modelData) ? 3 : 1
                            border.color: Qt.colorEqual(panel.curveData.color ?? "transparent", modelData)
                                          ? Theme.accent : Theme.controlPolygon
                            Accessible.role: Accessible.Button
                            Accessible.name: modelData
                            TapHandler { onTapped: panel.editor.setCurveColor(panel.curve, parent.modelData) }
                        }
                    }
                }
                PanelSwitch {
                    objectName: "visibleSwitch"
                    text: qsTr("Visible")
                    checked: panel.curveData.curveVisible ?? true
                    onToggled: panel.editor.setCurveVisible(panel.curve, checked)
                }
                PanelSwitch {
                    objectName: "lockSwitch"
                    text: qsTr("Locked")
                    checked: panel.curveData.locked ?? false
                    onToggled: panel.editor.setCurveLocked(panel.curve, checked)
                }
            }
            Flow {
                visible: panel.hasCurve
                Layout.fillWidth: true
                Layout.leftMargin: Theme.spacing
                spacing: 0
                Button {
                    text: qsTr("Close curve")
                    flat: true
                    visible: panel.curveData.kind === EditController.CompositeKind
                    onClicked: panel.editor.closeCurve(panel.curve)
                }
                Button {
                    text: qsTr("Move up")
                    flat: true
                    enabled: panel.curve > 0
                    onClicked: panel.editor.moveCurve(panel.curve, panel.curve - 1)
                }
                Button {
                    text: qsTr("Move down")
                    flat: true
                    enabled: panel.curve < curveList.count - 1
                    onClicked: panel.editor.moveCurve(panel.curve, panel.curve + 1)
                }
                Button {
                    objectName: "deleteCurveButton"
                    text: qsTr("Delete curve")
                    flat: true
                    onClicked: panel.editor.deleteCurve(panel.curve)
                }
            }

            // ---- Coordinates table (the seed's coordinates window) ----
            SectionLabel { text: qsTr("Coordinates"); visible: panel.hasCurve }
            CoordinatesTable {
                id: table
                objectName: "coordinatesTable"
                visible: panel.hasCurve
                editor: panel.editor
                Layout.fillWidth: true
                Layout.preferredHeight: implicitHeight
            }

            // ---- Info ----
            SectionLabel { text: qsTr("Info"); visible: panel.hasCurve }
            GridLayout {
                visible: panel.hasCurve
                Layout.fillWidth: true
                Layout.leftMargin: Theme.spacing
                Layout.rightMargin: Theme.spacing
                columns: 1
                rowSpacing: 0
                Label { text: qsTr("Length"); color: Theme.mutedText }
                Label {
                    objectName: "lengthLabel"
                    // With the document's unit (mm, cm or in once the background is calibrated).
                    text: Language.current, qsTr("%1 %2").arg(panel.number(panel.curveData.length ?? 0, 3))
                                                         .arg(panel.editor.document.units)
                }
                Label { text: qsTr("Fit error (RMS / max)"); color: Theme.mutedText; visible: (panel.curveData.fitRms ?? -1) >= 0 }
                Label {
                    visible: (panel.curveData.fitRms ?? -1) >= 0
                    text: Language.current, panel.number(panel.curveData.fitRms ?? 0, 4) + " / "
                          + panel.number(panel.curveData.fitMaxError ?? 0, 4)
                }
                Label { text: qsTr("Continuity"); color: Theme.mutedText; visible: (panel.curveData.continuity ?? "").length > 0 }
                Label {
                    visible: (panel.curveData.continuity ?? "").length > 0
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    text: {
                        const joints = panel.editor.jointReport(panel.curve, 12)
                        const parts = joints.map(j => qsTr("joint %1: %2").arg(j.joint).arg(j.level))
                        return (panel.curveData.continuity ?? "") + (parts.length > 0 ? " (" + parts.join(", ") + ")" : "")
                    }
                }
            }

            // ---- Background ----
            SectionLabel { text: qsTr("Background image") }
            ColumnLayout {
                Layout.fillWidth: true
                Layout.leftMargin: Theme.spacing
                Layout.rightMargin: Theme.spacing
                spacing: 0
                Button {
                    objectName: "loadBackgroundButton"
                    text: qsTr("Load image…")
                    onClicked: panel.loadBackgroundRequested()
                }
                Label {
                    Layout.fillWidth: true
                    visible: panel.editor.background.file.length > 0
                    text: panel.editor.background.file
                    elide: Text.ElideMiddle
                    color: Theme.mutedText
                    font.pixelSize: 12
                }
                PanelSwitch {
                    objectName: "backgroundVisibleSwitch"
                    visible: panel.editor.background.file.length > 0
                    text: qsTr("Show background")
                    checked: panel.editor.background.visible
                    onToggled: panel.editor.background.visible = checked
                }
                RowLayout {
                    visible: panel.editor.background.file.length > 0
                    Label { text: qsTr("Opacity") }
                    Slider {
                        objectName: "backgroundOpacitySlider"
                        Layout.fillWidth: true
                        from: 0.1
                        to: 1
                        value: panel.editor.background.opacity
                        // One undo step per gesture: the value is committed when the handle is let go.
                        onPressedChanged: if (!pressed) panel.editor.background.opacity = value
                    }
                }
                Button {
                    visible: panel.editor.background.file.length > 0
                    text: qsTr("Remove background")
                    flat: true
                    onClicked: panel.editor.background.clear()
                }
            }
            Item { Layout.preferredHeight: Theme.spacing }
        }
    }

    component SectionLabel: Label {
        font.bold: true
        leftPadding: Theme.spacing
        topPadding: Theme.spacing
    }
}
