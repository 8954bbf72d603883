// SidePanel: the selected curve at a glance with its most used controls (what the bottom sheet shows
// at its peek height), the curves of the document, the selected curve's settings, its coordinates
// table (the seed's coordinates window), information about it, and the background image. Every
// control is at least Theme.touchMinimum tall.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Pane {
    id: panel

    required property EditController editor
    // The window's action registry: the selected knot's and curve's edits (none in tests without one).
    property AppActions actions: null
    // Asks the window to open the background image dialog.
    signal loadBackgroundRequested()
    // The selected curve's marks as a garment piece (none in tests without the window's); asks the
    // window for the piece bar.
    property PieceMarkEdits pieceMarks: null
    signal pieceRequested()

    // How far down the content the peek part ends: the bottom sheet's peek height shows this much.
    readonly property real peekHeight: peek.y + peek.height + Theme.spacing / 2

    // Back to the beginning of the content, where the peek part is (the sheet lowered to its peek).
    function scrollToTop() { scroll.contentItem.contentY = 0 }

    // Rounded for showing, in exponent form when very large or small (C++ decides the form).
    function number(value, decimals) {
        return Numbers.shown(value, decimals)
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

            // ---- Peek: the selected curve (name, kind) and its most used controls ----
            ColumnLayout {
                id: peek
                objectName: "peekSection"
                Layout.fillWidth: true
                Layout.leftMargin: Theme.spacing
                Layout.rightMargin: Theme.spacing
                spacing: 0
                Label {
                    objectName: "noSelectionLabel"
                    visible: panel.editor.selection.curveRow < 0
                    Layout.fillWidth: true
                    Layout.minimumHeight: Theme.touchMinimum
                    verticalAlignment: Text.AlignVCenter
                    wrapMode: Text.Wrap
                    color: Theme.mutedText
                    text: curveList.count === 0 ? qsTr("No curves yet.") : qsTr("No curve selected. Tap a curve to edit it.")
                }
                // A positioner, not a layout, holds the delegate: Qt 6.4's layouts keep a removed child until
                // their next polish, and a width change before it (the window resized, the panel moved between
                // the sheet and the drawer) laid out the deleted delegate and crashed.
                Column {
                    Layout.fillWidth: true
                    Repeater {
                        model: panel.editor.selectedCurve
                        delegate: ColumnLayout {
                            id: glance
                            required property int curveId
                            required property string name
                            required property string kindName
                            required property bool curveVisible
                            required property bool locked
                            readonly property var commands: panel.editor.commands
                            width: parent ? parent.width : 0
                            spacing: 0
                            Column {
                                Layout.fillWidth: true
                                Layout.minimumHeight: Theme.touchMinimum
                                Label {
                                    objectName: "peekName"
                                    width: parent.width
                                    text: glance.name
                                    font.bold: true
                                    elide: Text.ElideRight
                                }
                                Label {
                                    objectName: "peekKind"
                                    width: parent.width
                                    text: glance.kindName
                                    color: Theme.mutedText
                                    elide: Text.ElideRight
                                }
                            }
                            Flow {
                                Layout.fillWidth: true
                                spacing: Theme.spacing
                                PanelSwitch {
                                    objectName: "visibleSwitch"
                                    text: qsTr("Visible")
                                    Accessible.name: qsTr("Curve visible")
                                    checked: glance.curveVisible
                                    onToggled: glance.commands.setCurveVisible(glance.curveId, checked)
                                }
                                PanelSwitch {
                                    objectName: "lockSwitch"
                                    text: qsTr("Locked")
                                    Accessible.name: qsTr("Curve locked")
                                    checked: glance.locked
                                    onToggled: glance.commands.setCurveLocked(glance.curveId, checked)
                                }
                            }
                        }
                    }
                }
            }

            // ---- Curves ----
            SectionLabel { text: qsTr("Curves") }
            ListView {
                id: curveList
                objectName: "curveList"
                Layout.fillWidth: true
                Layout.preferredHeight: Math.min(contentHeight, 5 * 56)
                clip: true
                interactive: contentHeight > height
                highlightFollowsCurrentItem: false // as in CoordinatesTable: no animated empty highlight
                cacheBuffer: 0 // as in CoordinatesTable: no row made ahead that a reset must cancel
                model: panel.editor.curves
                delegate: ItemDelegate {
                    id: curveRow
                    required property int curveId
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
                    onClicked: panel.editor.selection.selectCurve(curveId)
                    Accessible.role: Accessible.ListItem
                    Accessible.name: name
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
                            font.pixelSize: Theme.smallFontSize
                            // Two lines before eliding: the length must not be cut off behind the kind's name.
                            wrapMode: Text.Wrap
                            maximumLineCount: 2
                            elide: Text.ElideRight
                            // A binding with qsTr is evaluated again after a language switch,
                            // numbers included.
                            text: curveRow.problem
                                  ? qsTr("%1 · cannot be drawn from these points").arg(curveRow.kindName)
                                    //: %1 is the curve's kind, %2 its length with its unit (12.5 mm).
                                  : qsTr("%1 · %n point(s) · length %2", "", curveRow.pointCount)
                                    .arg(curveRow.kindName)
                                    .arg(Numbers.shownLength(curveRow.length, 1, panel.editor.document.units,
                                                             Language.current))
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

            // ---- The selected curve: its row of the curve list as a model of one row, read by role ----
            // A positioner, not a layout, holds the delegate: Qt 6.4's layouts keep a removed child until
            // their next polish, and a width change before it (the window resized, the panel moved between
            // the sheet and the drawer) laid out the deleted delegate and crashed.
            Column {
                Layout.fillWidth: true
                Repeater {
                    model: panel.editor.selectedCurve
                    delegate: ColumnLayout {
                        id: selected
                        required property int curveId
                        required property string name
                        required property int kind
                        required property string kindName
                        required property color color
                        required property bool curveVisible
                        required property bool locked
                        required property int parameterization
                        required property real length
                        required property real fitRms
                        required property real fitMaxError
                        required property string continuity
                        required property int degree
                        readonly property var commands: panel.editor.commands
                        readonly property Selection selection: panel.editor.selection
                        width: parent ? parent.width : 0
                        spacing: Theme.spacing / 2

                        SectionLabel { text: qsTr("Selected curve") }
                        // One column: labels above their controls, so that long words of every language fit.
                        GridLayout {
                            Layout.fillWidth: true
                            Layout.leftMargin: Theme.spacing
                            Layout.rightMargin: Theme.spacing
                            columns: 1
                            columnSpacing: Theme.spacing
                            rowSpacing: 0

                            Label { text: qsTr("Name") }
                            TextField {
                                objectName: "curveNameField"
                                Accessible.name: qsTr("Curve name")
                                Layout.minimumHeight: Theme.touchMinimum
                                Layout.fillWidth: true
                                text: selected.name
                                enabled: !selected.locked
                                onEditingFinished: if (text !== selected.name) selected.commands.setCurveName(selected.curveId, text)
                            }
                            //: Label (noun): the kind of the selected curve, for example “Bézier curve” or “Natural
                            //: spline”.
                            Label { text: qsTr("Kind") }
                            Label {
                                Layout.fillWidth: true
                                text: selected.kindName + (selected.degree > 0 ? " · " + qsTr("degree %1").arg(selected.degree) : "")
                                wrapMode: Text.Wrap
                            }
                            Label {
                                text: qsTr("Parameterization")
                                visible: selected.parameterization >= 0
                            }
                            ChoiceBox {
                                objectName: "parameterizationBox"
                                Accessible.name: qsTr("Parameterization")
                                visible: selected.parameterization >= 0
                                Layout.fillWidth: true
                                model: [qsTr("Uniform"), qsTr("Chord length"), qsTr("Centripetal")]
                                chosen: Math.max(0, selected.parameterization)
                                onActivated: (index) => selected.commands.setCurveParameterization(selected.curveId, index)
                            }
                            Label {
                                //: Label (noun): the order k of a B-spline (degree + 1), a number; not a sequence and
                                //: not a command.
                                text: qsTr("Order")
                                visible: orderBox.visible
                            }
                            SpinBox {
                                id: orderBox
                                objectName: "orderBox"
                                Accessible.name: qsTr("Order")
                                visible: selected.kind === CurveKind.BSpline
                                from: 2
                                to: 10
                                value: selected.degree + 1
                                onValueModified: selected.commands.setCurveOrder(selected.curveId, value)
                            }
                            Label {
                                text: qsTr("Node type")
                                visible: nodeTypeBox.visible
                            }
                            ChoiceBox {
                                id: nodeTypeBox
                                objectName: "nodeTypeBox"
                                Accessible.name: qsTr("Node type")
                                // The selected knot's (or its handle's knot's) type, followed through the selection.
                                visible: selected.selection.nodeType >= 0
                                Layout.fillWidth: true
                                // The continuity of the composite curve at the selected knot (adjectives for a knot).
                                model: [
                                    //: Knot type: the handles on both sides stay on one line (G1).
                                    qsTr("Smooth"),
                                    //: Knot type: the handles on both sides stay on one line and have equal lengths
                                    //: (C1).
                                    qsTr("Symmetric"),
                                    //: Knot type: the handles on both sides move independently (a corner).
                                    qsTr("Corner")]
                                chosen: Math.max(0, selected.selection.nodeType)
                                onActivated: (index) => selected.commands.setNodeType(selected.curveId, selected.selection.knot, index)
                            }
                            Label { text: qsTr("Colour") }
                            Flow {
                                Layout.fillWidth: true
                                spacing: 0
                                Repeater {
                                    // The swatch is small; its target is a touch target of its own.
                                    model: [{ colour: "#000000", name: qsTr("Black") }, { colour: "#d00000", name: qsTr("Red") },
                                            { colour: "#1f6fd1", name: qsTr("Blue") }, { colour: "#1b8a3a", name: qsTr("Green") },
                                            { colour: "#e07b00", name: qsTr("Orange") }, { colour: "#7a3fb0", name: qsTr("Purple") },
                                            { colour: "#00838f", name: qsTr("Teal") }, { colour: "#8d6e63", name: qsTr("Brown") }]
                                    delegate: Item {
                                        id: swatch
                                        required property var modelData
                                        readonly property bool chosen: Qt.colorEqual(selected.color, modelData.colour)
                                        width: Theme.touchMinimum
                                        height: Theme.touchMinimum
                                        Accessible.role: Accessible.Button
                                        Accessible.name: qsTr("Colour: %1").arg(modelData.name)
                                        Rectangle {
                                            anchors.centerIn: parent
                                            width: 28
                                            height: 28
                                            radius: 14
                                            color: swatch.modelData.colour
                                            border.width: swatch.chosen ? 3 : 1
                                            border.color: swatch.chosen ? Theme.accent : Theme.controlPolygon
                                        }
                                        TapHandler { onTapped: selected.commands.setCurveColor(selected.curveId, swatch.modelData.colour) }
                                    }
                                }
                            }
                        }
                        // The selected knot's edits and the composite curve's, as the registry's actions.
                        Flow {
                            objectName: "pieceButtons"
                            Layout.fillWidth: true
                            Layout.leftMargin: Theme.spacing
                            spacing: 0
                            visible: panel.actions !== null && selected.kind === CurveKind.Composite
                            Repeater {
                                model: panel.actions ? ["pieceMakeLine", "pieceDeleteKnot", "pieceSmooth", "pieceSymmetric",
                                                        "pieceCorner", "pieceClose", "pieceJoin", "pieceSimplify"] : []
                                delegate: Button {
                                    required property string modelData
                                    objectName: "panel_" + modelData
                                    action: panel.actions.pieceActions[modelData]
                                    Accessible.name: action ? action.text : ""
                                    // Knot edits only while a knot is selected; the curve's always.
                                    visible: action !== null && (action.enabled || modelData === "pieceClose"
                                                                 || modelData === "pieceJoin" || modelData === "pieceSimplify")
                                    flat: true
                                    height: Theme.touchMinimum
                                }
                            }
                        }
                        Flow {
                            Layout.fillWidth: true
                            Layout.leftMargin: Theme.spacing
                            spacing: 0
                            Button {
                                text: qsTr("Close curve")
                                Accessible.name: text
                                flat: true
                                // Without the registry (tests of the panel alone); the window's is pieceClose.
                                visible: selected.kind === CurveKind.Composite && panel.actions === null
                                onClicked: selected.commands.closeCurve(selected.curveId)
                            }
                            Button {
                                objectName: "pieceButton"
                                //: Opens the bar that makes the closed curve a garment pattern piece and edits its marks.
                                text: qsTr("Pattern piece…")
                                Accessible.name: qsTr("Pattern piece")
                                flat: true
                                visible: panel.pieceMarks !== null
                                         && (panel.pieceMarks.isPiece || panel.pieceMarks.canBePiece)
                                onClicked: panel.pieceRequested()
                            }
                            Button {
                                text: qsTr("Move up")
                                Accessible.name: text
                                flat: true
                                enabled: selected.selection.curveRow > 0
                                onClicked: selected.commands.moveCurveBy(selected.curveId, -1)
                            }
                            Button {
                                text: qsTr("Move down")
                                Accessible.name: text
                                flat: true
                                enabled: selected.selection.curveRow < curveList.count - 1
                                onClicked: selected.commands.moveCurveBy(selected.curveId, 1)
                            }
                            Button {
                                objectName: "deleteCurveButton"
                                text: qsTr("Delete curve")
                                Accessible.name: text
                                flat: true
                                onClicked: selected.commands.deleteCurve(selected.curveId)
                            }
                        }

                        // ---- Coordinates table (the seed's coordinates window) ----
                        SectionLabel { text: qsTr("Coordinates") }
                        CoordinatesTable {
                            id: table
                            objectName: "coordinatesTable"
                            editor: panel.editor
                            Layout.fillWidth: true
                            Layout.preferredHeight: implicitHeight
                        }

                        // ---- Info ----
                        //: Heading (noun): figures about the selected curve (length, fit error, continuity).
                        SectionLabel { text: qsTr("Info") }
                        GridLayout {
                            Layout.fillWidth: true
                            Layout.leftMargin: Theme.spacing
                            Layout.rightMargin: Theme.spacing
                            columns: 1
                            rowSpacing: 0
                            Label { text: qsTr("Length"); color: Theme.mutedText }
                            Label {
                                objectName: "lengthLabel"
                                // With the document's unit (mm, cm or in once the background is calibrated).
                                text: Numbers.length(selected.length, panel.editor.document.units, Language.current)
                            }
                            Label { text: qsTr("Fit error (RMS / max)"); color: Theme.mutedText; visible: selected.fitRms >= 0 }
                            Label {
                                visible: selected.fitRms >= 0
                                //: The fit error as RMS / maximum: %1 and %2 are numbers.
                                text: qsTr("%1 / %2").arg(panel.number(selected.fitRms, 4)).arg(panel.number(selected.fitMaxError, 4))
                            }
                            Label { text: qsTr("Continuity"); color: Theme.mutedText; visible: selected.continuity.length > 0 }
                            Label {
                                visible: selected.continuity.length > 0
                                Layout.fillWidth: true
                                wrapMode: Text.Wrap
                                // Read again whenever the weakest joint or the length (any move) changes.
                                text: {
                                    const joints = selected.length >= 0 ? selected.commands.jointReport(selected.curveId, 12) : []
                                    const parts = joints.map(j => qsTr("joint %1: %2").arg(j.joint).arg(j.level))
                                    return selected.continuity + (parts.length > 0 ? " (" + parts.join(", ") + ")" : "")
                                }
                            }
                        }
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
                    // As wide as the panel: measured before a font change, its name was elided.
                    Layout.fillWidth: true
                    text: qsTr("Load image…")
                    Accessible.name: qsTr("Load background image")
                    onClicked: panel.loadBackgroundRequested()
                }
                Label {
                    Layout.fillWidth: true
                    visible: panel.editor.background.file.length > 0
                    text: panel.editor.background.file
                    elide: Text.ElideMiddle
                    color: Theme.mutedText
                    font.pixelSize: Theme.smallFontSize
                }
                PanelSwitch {
                    objectName: "backgroundVisibleSwitch"
                    visible: panel.editor.background.file.length > 0
                    text: qsTr("Show background")
                    Accessible.name: text
                    checked: panel.editor.background.visible
                    onToggled: panel.editor.background.visible = checked
                }
                RowLayout {
                    visible: panel.editor.background.file.length > 0
                    Label { text: qsTr("Opacity") }
                    Slider {
                        objectName: "backgroundOpacitySlider"
                        Accessible.name: qsTr("Background opacity")
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
                    Accessible.name: text
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
