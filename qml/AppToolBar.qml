// AppToolBar: the window's tool bar — the File, New curve, Teaching, Trace and language menus, the
// editing and view buttons, and the keyboard commands. Every command is an Action, written once and
// shared by its button or menu entry and its shortcut; keys beyond an Action's one shortcut are
// small Actions that trigger it. A checkable Action's handler never reads `checked` (a button and
// its Action each toggle it): it changes the state its `checked` is bound to. The bar scrolls
// sideways on narrow screens.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

ToolBar {
    id: bar

    required property EditController editor
    required property FileActions fileActions
    required property CurveCanvas canvas
    required property TeachingController teaching
    required property TraceController trace
    // Narrow windows show the side panel as a drawer; the Panel button opens it there.
    property bool narrow: false
    // The basis functions plot under the canvas (Teaching menu).
    property bool showBasis: false
    // Whether the side panel is open (the window decides what that means in each layout).
    property bool panelOpen: true
    // A menu of the bar is open over the canvas.
    readonly property bool menuOpen: fileMenu.visible || newCurveMenu.visible || teachingMenu.visible
                                     || traceMenu.visible || languageMenu.visible
    readonly property bool placing: editor.mode === EditController.Place

    signal panelToggleRequested()
    signal functionSplineRequested()
    signal rungeRequested()
    signal practicumRequested()

    // A plain light background: Material's elevation shadow is a shader effect, which Qt Quick's
    // software backend cannot draw. Dark text on a light bar stays readable in every state.
    Material.accent: Theme.accent
    Material.foreground: Theme.toolbarText
    background: Rectangle {
        color: Theme.toolbar
        Rectangle {
            anchors.bottom: parent.bottom
            width: parent.width
            height: 1
            color: Theme.toolbarBorder
        }
    }

    // Arrow keys nudge the selected point by a pixel on screen (Shift: ten).
    function nudge(dx, dy) { editor.commands.nudgeSelected(Qt.point(dx / canvas.zoom, dy / canvas.zoom)) }

    // --- editing ---
    Action {
        id: newBezierAction
        objectName: "newBezierAction"
        text: qsTr("New Bézier")
        shortcut: "B"
        checkable: true
        checked: bar.placing && bar.editor.placement.kind === CurveKind.Bezier
        onTriggered: {
            if (bar.placing && bar.editor.placement.kind === CurveKind.Bezier)
                bar.editor.mode = EditController.Select
            else
                bar.editor.startPlacing(CurveKind.Bezier)
        }
    }
    Action {
        id: doneAction
        objectName: "doneAction"
        text: qsTr("Done")
        enabled: bar.placing && bar.editor.placement.pendingCount > 0
        onTriggered: bar.editor.placement.finish()
    }
    // Enter finishes the curve being placed, unless a text field has the focus: there it applies
    // what was typed (text fields leave Enter to shortcuts, for dialogs' default buttons).
    Action {
        shortcut: "Return"
        enabled: doneAction.enabled && !(bar.Window.activeFocusItem instanceof TextInput)
        onTriggered: doneAction.trigger()
    }
    Action {
        shortcut: "Enter"
        enabled: doneAction.enabled && !(bar.Window.activeFocusItem instanceof TextInput)
        onTriggered: doneAction.trigger()
    }
    Action {
        shortcut: "Backspace"
        onTriggered: bar.editor.placement.removeLast()
    }
    Action {
        id: selectAction
        text: qsTr("Move points")
        checkable: true
        checked: bar.editor.mode === EditController.Select
        onTriggered: bar.editor.mode = EditController.Select
    }
    // Esc leaves the trace tool, else the placement, else placing.
    Action {
        shortcut: "Esc"
        onTriggered: {
            if (bar.trace.tool !== TraceController.None)
                bar.trace.tool = TraceController.None
            else if (bar.editor.placement.pendingCount > 0)
                bar.editor.placement.cancel()
            else
                bar.editor.mode = EditController.Select
        }
    }
    Action {
        id: constrainedAction
        text: qsTr("Constrained")
        checkable: true
        checked: bar.editor.handleMode === EditController.Constrained
        onTriggered: bar.editor.handleMode = bar.editor.handleMode === EditController.Constrained
                     ? EditController.Free : EditController.Constrained
    }
    Action {
        shortcut: StandardKey.Delete
        enabled: !bar.placing && bar.editor.selection.hasCurve
        onTriggered: bar.editor.commands.deleteSelection()
    }
    Action { shortcut: "Left"; onTriggered: bar.nudge(-1, 0) }
    Action { shortcut: "Right"; onTriggered: bar.nudge(1, 0) }
    Action { shortcut: "Up"; onTriggered: bar.nudge(0, 1) }
    Action { shortcut: "Down"; onTriggered: bar.nudge(0, -1) }
    Action { shortcut: "Shift+Left"; onTriggered: bar.nudge(-10, 0) }
    Action { shortcut: "Shift+Right"; onTriggered: bar.nudge(10, 0) }
    Action { shortcut: "Shift+Up"; onTriggered: bar.nudge(0, 10) }
    Action { shortcut: "Shift+Down"; onTriggered: bar.nudge(0, -10) }
    Action {
        id: undoAction
        objectName: "undoAction"
        text: qsTr("Undo")
        shortcut: StandardKey.Undo
        enabled: bar.editor.canUndo
        onTriggered: bar.editor.undo()
    }
    Action {
        id: redoAction
        objectName: "redoAction"
        text: qsTr("Redo")
        shortcut: StandardKey.Redo
        enabled: bar.editor.canRedo
        onTriggered: bar.editor.redo()
    }
    // Where the platform's redo key is another (Ctrl+Y). Where it is this one too, each press still
    // redoes once: the shortcut map hands a key held twice to one of them at a time.
    Action {
        shortcut: "Ctrl+Shift+Z"
        enabled: redoAction.enabled
        onTriggered: redoAction.trigger()
    }
    Action {
        id: resetAction
        text: qsTr("Reset all")
        enabled: bar.editor.document.curveCount > 0 || bar.editor.background.file.length > 0
        onTriggered: resetDialog.open()
    }

    // --- view ---
    Action {
        id: zoomInAction
        text: "+"
        shortcut: StandardKey.ZoomIn
        onTriggered: bar.canvas.zoomIn()
    }
    Action { shortcut: "+"; onTriggered: zoomInAction.trigger() }
    Action { shortcut: "="; onTriggered: zoomInAction.trigger() }
    Action {
        id: zoomOutAction
        text: "\u2212"
        shortcut: StandardKey.ZoomOut
        onTriggered: bar.canvas.zoomOut()
    }
    Action { shortcut: "-"; onTriggered: zoomOutAction.trigger() }
    Action {
        id: fitAction
        text: qsTr("Fit")
        shortcut: "F"
        onTriggered: bar.canvas.fitToView()
    }
    Action {
        id: gridAction
        text: qsTr("Grid")
        shortcut: "G"
        checkable: true
        checked: bar.canvas.showGrid
        onTriggered: bar.canvas.showGrid = !bar.canvas.showGrid
    }
    Action {
        id: presentationAction
        text: qsTr("Presentation mode (F5)")
        shortcut: "F5"
        checkable: true
        checked: Presentation.enabled
        onTriggered: Presentation.toggle()
    }

    ConfirmDialog {
        id: resetDialog
        objectName: "resetDialog"
        title: qsTr("Reset all")
        text: bar.editor.resetQuestion
        onAccepted: bar.editor.commands.resetAll()
    }

    // On narrow screens the bar scrolls sideways instead of cutting buttons off.
    Flickable {
        id: toolFlick
        anchors.fill: parent
        implicitHeight: toolRow.implicitHeight
        contentWidth: Math.max(toolRow.implicitWidth, width)
        contentHeight: height
        interactive: toolRow.implicitWidth > width
        flickableDirection: Flickable.HorizontalFlick
        clip: true

        RowLayout {
            id: toolRow
            width: Math.max(implicitWidth, toolFlick.width)
            height: toolFlick.height
            spacing: 0

            ToolButton {
                id: fileButton
                objectName: "fileButton"
                text: qsTr("File")
                onClicked: fileMenu.open()
                ToolbarMenu {
                    id: fileMenu
                    MenuItem { action: bar.fileActions.newAction }
                    MenuItem { action: bar.fileActions.openAction }
                    Menu {
                        title: qsTr("Open recent")
                        enabled: bar.fileActions.files.recentFiles.length > 0
                        Repeater {
                            model: bar.fileActions.files.recentFiles
                            MenuItem {
                                required property string modelData
                                text: modelData
                                onTriggered: bar.fileActions.openRecent(modelData)
                            }
                        }
                    }
                    MenuItem { action: bar.fileActions.saveAction }
                    MenuItem { action: bar.fileActions.saveAsAction }
                    MenuSeparator {}
                    MenuItem { action: bar.fileActions.importAction }
                    MenuItem { action: bar.fileActions.exportSvgAction }
                    MenuItem { action: bar.fileActions.exportCsvAction }
                    MenuItem { action: bar.fileActions.appendAction }
                    MenuItem {
                        text: qsTr("Export PNG (view size)…")
                        onTriggered: bar.fileActions.exportPng(1, false)
                    }
                    MenuItem {
                        text: qsTr("Export PNG (2× view size)…")
                        onTriggered: bar.fileActions.exportPng(2, false)
                    }
                    MenuItem {
                        text: qsTr("Export PNG (4× view size)…")
                        onTriggered: bar.fileActions.exportPng(4, false)
                    }
                    MenuItem {
                        text: qsTr("Export PNG of the whole document (2×)…")
                        onTriggered: bar.fileActions.exportPng(2, true)
                    }
                    MenuSeparator {}
                    MenuItem {
                        text: qsTr("Quit")
                        onTriggered: bar.Window.window.close()
                    }
                }
            }
            ToolButton {
                objectName: "newBezierButton"
                action: newBezierAction
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Place 4 control points to make a cubic Bézier curve (B)")
            }
            ToolButton {
                id: newCurveButton
                objectName: "newCurveButton"
                text: qsTr("New curve")
                checked: bar.placing && bar.editor.placement.kind !== CurveKind.Bezier
                onClicked: newCurveMenu.open()
                ToolTip.visible: hovered && !newCurveMenu.visible
                ToolTip.delay: 600
                ToolTip.text: qsTr("Choose the kind of curve to place")

                ToolbarMenu {
                    id: newCurveMenu
                    Repeater {
                        // The names are translated: the list is announced again on a language switch.
                        model: bar.editor.placement.kinds
                        MenuItem {
                            required property var modelData
                            objectName: "newKind" + modelData.kind
                            text: modelData.name
                            onTriggered: bar.editor.startPlacing(modelData.kind)
                        }
                    }
                }
            }
            ToolButton {
                objectName: "doneButton"
                action: doneAction
                visible: bar.placing
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Finish the curve with the points placed so far (Enter)")
            }
            ToolButton {
                objectName: "selectButton"
                action: selectAction
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Drag points to change curves; drag the canvas to pan (Esc)")
            }
            ToolButton {
                objectName: "constrainedButton"
                action: constrainedAction
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Composite handles keep their direction and change only their length (or drag with the right button or Shift)")
            }
            ToolSeparator {}
            ToolButton {
                objectName: "undoButton"
                action: undoAction
            }
            ToolButton {
                objectName: "redoButton"
                action: redoAction
            }
            ToolSeparator {}
            ToolButton {
                id: teachingMenuButton
                objectName: "teachingMenuButton"
                text: qsTr("Teaching")
                checked: bar.teaching.view !== TeachingController.None
                onClicked: teachingMenu.open()
                ToolTip.visible: hovered && !teachingMenu.visible
                ToolTip.delay: 600
                ToolTip.text: qsTr("Views that show how curves are built")

                ToolbarMenu {
                    id: teachingMenu
                    objectName: "teachingMenu"
                    minimumWidth: 320
                    MenuItem {
                        objectName: "teachingDeCasteljau"
                        text: qsTr("de Casteljau construction")
                        checkable: true
                        checked: bar.teaching.view === TeachingController.DeCasteljau
                        onTriggered: bar.teaching.view = bar.teaching.view === TeachingController.DeCasteljau ? TeachingController.None : TeachingController.DeCasteljau
                    }
                    MenuItem {
                        objectName: "teachingElevation"
                        text: qsTr("Degree elevation")
                        checkable: true
                        checked: bar.teaching.view === TeachingController.Elevation
                        onTriggered: bar.teaching.view = bar.teaching.view === TeachingController.Elevation ? TeachingController.None : TeachingController.Elevation
                    }
                    MenuItem {
                        objectName: "teachingCompare"
                        text: qsTr("Compare curve kinds")
                        checkable: true
                        checked: bar.teaching.view === TeachingController.Compare
                        onTriggered: bar.teaching.view = bar.teaching.view === TeachingController.Compare ? TeachingController.None : TeachingController.Compare
                    }
                    MenuItem {
                        objectName: "teachingComb"
                        text: qsTr("Curvature comb and continuity")
                        checkable: true
                        checked: bar.teaching.view === TeachingController.Comb
                        onTriggered: bar.teaching.view = bar.teaching.view === TeachingController.Comb ? TeachingController.None : TeachingController.Comb
                    }
                    MenuItem {
                        objectName: "teachingBasis"
                        text: qsTr("Basis functions")
                        checkable: true
                        checked: bar.showBasis
                        onTriggered: bar.showBasis = !bar.showBasis
                    }
                    MenuItem {
                        objectName: "teachingFunctionSpline"
                        text: qsTr("Function spline y(x)…")
                        onTriggered: bar.functionSplineRequested()
                    }
                    MenuItem {
                        objectName: "teachingRunge"
                        text: qsTr("Runge comparison…")
                        onTriggered: bar.rungeRequested()
                    }
                    MenuItem {
                        objectName: "teachingPracticum"
                        text: qsTr("Cubic segments…")
                        onTriggered: bar.practicumRequested()
                    }
                    MenuSeparator {}
                    MenuItem {
                        objectName: "presentationItem"
                        action: presentationAction
                    }
                }
            }
            ToolButton {
                id: traceMenuButton
                objectName: "traceMenuButton"
                text: qsTr("Trace")
                checked: bar.trace.tool !== TraceController.None
                onClicked: traceMenu.open()
                ToolTip.visible: hovered && !traceMenu.visible
                ToolTip.delay: 600
                ToolTip.text: qsTr("Trace a pattern: freehand, calibrate, measure, compare")
                TraceMenu {
                    id: traceMenu
                    objectName: "traceMenu"
                    minimumWidth: 380
                    trace: bar.trace
                }
            }
            Item { Layout.fillWidth: true }
            ToolButton {
                objectName: "zoomOutButton"
                action: zoomOutAction
                font.pixelSize: 20
                Accessible.name: qsTr("Zoom out")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Zoom out")
            }
            Label {
                objectName: "zoomReadout"
                // Whole percents from 1 % to 100,000 %, three significant digits beyond (0.0025 %, 1.5E+12 %).
                text: qsTr("%1 %").arg(bar.canvas.zoom >= 0.01 && bar.canvas.zoom < 1000
                                       ? Number(bar.canvas.zoom * 100).toLocaleString(Qt.locale(Language.current), "f", 0)
                                       : Number(bar.canvas.zoom * 100).toLocaleString(Qt.locale(Language.current), "g", 3))
                horizontalAlignment: Text.AlignHCenter
                Layout.minimumWidth: 64
            }
            ToolButton {
                objectName: "zoomInButton"
                action: zoomInAction
                font.pixelSize: 20
                Accessible.name: qsTr("Zoom in")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Zoom in")
            }
            ToolButton {
                objectName: "gridButton"
                action: gridAction
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Show or hide the grid and the axes (G)")
            }
            ToolButton {
                action: fitAction
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Show all curves (F)")
            }
            ToolSeparator {}
            ToolButton {
                id: languageButton
                objectName: "languageButton"
                text: Language.current.toUpperCase()
                onClicked: languageMenu.open()
                Accessible.name: qsTr("Language")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Language")

                ToolbarMenu {
                    id: languageMenu
                    minimumWidth: 200
                    Repeater {
                        model: Language.available
                        MenuItem {
                            required property var modelData
                            text: modelData.name
                            checkable: true
                            checked: Language.current === modelData.code
                            onTriggered: {
                                Language.current = modelData.code
                                Language.remember(modelData.code)
                            }
                        }
                    }
                }
            }
            ToolButton {
                objectName: "resetButton"
                action: resetAction
            }
            ToolButton {
                id: panelButton
                objectName: "panelButton"
                text: qsTr("Panel")
                checked: bar.panelOpen
                onClicked: bar.panelToggleRequested()
            }
        }
    }
}
