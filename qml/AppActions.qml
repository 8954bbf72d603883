// AppActions: the action registry — every command of the main window once, with its id
// (objectName), translated name, icon, shortcut, priority and enabled state. The tool bar's buttons,
// its menus, the overflow menu (⋮), the keyboard and the tests all take their commands from here.
// What is enabled and what a command does are the controllers' (EditController, TraceController,
// TeachingController, FileActions); the actions only bind to them. Keys beyond an action's one
// shortcut are small Actions that trigger it. A checkable action's handler never reads `checked`
// (a button and its action each toggle it): it changes the state its `checked` is bound to.
// An Item rather than a QtObject: a shortcut finds its window through its parents. Over 600 lines
// because it is the one registry: splitting it would give the commands two places again.
// Over 600 lines because it is that one list: 53 commands, each a few declarative lines; split
// by menu, a command's id, key and enabled state would be looked up across files.
// Over 600 lines because it is the one registry: splitting the commands over files would give the
// tool bar, the menus, the keys and the tests several lists to keep in step.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Item {
    id: actions

    required property EditController editor
    required property FileActions fileActions
    required property CurveCanvas canvas
    required property TeachingController teaching
    required property TraceController trace
    // The basis functions plot under the canvas (Teaching menu).
    property bool showBasis: false
    // Whether the window shows its side panel: the panel toggle's state. The window decides.
    property bool panelOpen: true

    // What the window does: show or hide the panel, open a teaching page.
    signal panelToggleRequested()
    signal functionSplineRequested()
    signal rungeRequested()
    signal practicumRequested()
    signal seamAllowanceRequested()

    readonly property bool placing: editor.mode === EditController.Place

    // The tool bar's commands and menus, in their order on the bar. (A var: Qt 6.4's compiled
    // bindings crash on a list<KonturAction> of ids. Qt >= 6.5: list<KonturAction>.)
    readonly property var barActions: [fileMenu, newBezier, newCurveMenu, select,
        constrained, undo, redo, teachingMenu, traceMenu, done, grid, fit, zoomOut, zoomIn, languageMenu,
        reset, panel]
    // Every command: the bar's and its menus' entries (the menus themselves open, they do nothing).
    readonly property var all: {
        let list = []
        for (let i = 0; i < barActions.length; ++i) {
            const action = barActions[i]
            list.push(action)
            for (const entry of action.entries ?? [])
                if (typeof entry !== "string")
                    list.push(entry)
        }
        return list
    }

    // The actions made from a model's entries (the recent files, the kinds of curve, the languages),
    // made again when the model changes; those made before are destroyed.
    function remake(old, component, model) {
        for (const action of old)
            action.destroy()
        let list = []
        for (let i = 0; i < model.length; ++i)
            list.push(component.createObject(actions, {modelData: model[i]}))
        return list
    }
    Component.onCompleted: {
        recentActions = remake([], recentComponent, fileActions.recent.paths)
        kindActions = remake([], kindComponent, editor.placement.kinds)
        languageActions = remake([], languageComponent, Language.available)
    }

    // The action called `name` (its objectName), or null.
    function named(name) {
        return all.find(action => action.objectName === name) ?? null
    }

    // Arrow keys nudge the selected point by a pixel on screen (Shift: ten).
    function nudge(dx, dy) { editor.commands.nudgeSelected(Qt.point(dx / canvas.zoom, dy / canvas.zoom)) }
    function toggleTrace(tool) { trace.tool = trace.tool === tool ? TraceController.None : tool }
    function toggleTeaching(view) { teaching.view = teaching.view === view ? TeachingController.None : view }

    // --- File ---
    KonturAction {
        id: fileMenu
        objectName: "fileMenuAction"
        //: Menu title (noun): the file commands.
        text: qsTr("File")
        toolTip: qsTr("New, open, save, import and export")
        iconName: "kontur-file-menu"
        priority: 80
        entries: [actions.fileActions.newAction, actions.fileActions.openAction, ...actions.recentActions,
            actions.fileActions.saveAction, actions.fileActions.saveAsAction, actions.fileActions.printAction, "-",
            actions.fileActions.importAction, actions.fileActions.exportSvgAction,
            actions.fileActions.exportDxfAction, actions.fileActions.exportDxfPolylineAction,
            actions.fileActions.exportAamaAction,
            actions.fileActions.exportCsvAction, actions.fileActions.appendAction,
            exportPng1, exportPng2, exportPng4, exportPngDocument, "-", quit]
    }
    // The recent documents, as entries of the File menu after Open.
    property var recentActions: []
    Component {
        id: recentComponent
        KonturAction {
            required property string modelData
            objectName: "openRecent:" + modelData
            text: qsTr("Open %1").arg(modelData.substring(modelData.lastIndexOf("/") + 1))
            toolTip: modelData
            iconName: "document-open-recent-symbolic"
            onTriggered: actions.fileActions.openRecent(modelData)
        }
    }
    Connections {
        target: actions.fileActions.recent
        function onPathsChanged() {
            actions.recentActions = actions.remake(actions.recentActions, recentComponent,
                                                   actions.fileActions.recent.paths)
        }
    }
    KonturAction {
        id: exportPng1
        objectName: "exportPng1"
        text: qsTr("Export PNG (view size)…")
        iconName: "image-x-generic-symbolic"
        onTriggered: actions.fileActions.exportPng(1, false)
    }
    KonturAction {
        id: exportPng2
        objectName: "exportPng2"
        text: qsTr("Export PNG (2× view size)…")
        iconName: "image-x-generic-symbolic"
        onTriggered: actions.fileActions.exportPng(2, false)
    }
    KonturAction {
        id: exportPng4
        objectName: "exportPng4"
        text: qsTr("Export PNG (4× view size)…")
        iconName: "image-x-generic-symbolic"
        onTriggered: actions.fileActions.exportPng(4, false)
    }
    KonturAction {
        id: exportPngDocument
        objectName: "exportPngDocument"
        text: qsTr("Export PNG of the whole document (2×)…")
        iconName: "image-x-generic-symbolic"
        onTriggered: actions.fileActions.exportPng(2, true)
    }
    KonturAction {
        id: quit
        objectName: "quitAction"
        text: qsTr("Quit")
        shortcut: StandardKey.Quit
        iconName: "application-exit-symbolic"
        onTriggered: actions.Window.window.close()
    }

    // --- editing ---
    KonturAction {
        id: newBezier
        objectName: "newBezierAction"
        //: Tool-bar button, short for “New Bézier curve”: starts placing the control points of a new Bézier curve.
        text: qsTr("New Bézier")
        toolTip: qsTr("Place 4 control points to make a cubic Bézier curve (B)")
        shortcut: "B"
        iconName: "kontur-bezier"
        priority: 90
        pinned: checked
        checkable: true
        checked: actions.placing && actions.editor.placement.kind === CurveKind.Bezier
        onTriggered: {
            if (actions.placing && actions.editor.placement.kind === CurveKind.Bezier)
                actions.editor.mode = EditController.Select
            else
                actions.editor.startPlacing(CurveKind.Bezier)
        }
    }
    KonturAction {
        id: newCurveMenu
        objectName: "newCurveMenuAction"
        text: qsTr("New curve")
        toolTip: qsTr("Choose the kind of curve to place")
        iconName: "kontur-curve"
        priority: 85
        checked: actions.placing && actions.editor.placement.kind !== CurveKind.Bezier
        pinned: checked
        entries: actions.kindActions
    }
    // One entry per kind of curve, with its translated name and its icon from the kinds' list in C++
    // (Placement::kinds); the list is announced again on a language switch.
    property var kindActions: []
    Component {
        id: kindComponent
        KonturAction {
            required property var modelData
            objectName: "newKind" + modelData.kind
            text: modelData.name
            iconName: modelData.icon
            onTriggered: actions.editor.startPlacing(modelData.kind)
        }
    }
    Connections {
        target: actions.editor.placement
        function onKindsChanged() {
            actions.kindActions = actions.remake(actions.kindActions, kindComponent, actions.editor.placement.kinds)
        }
    }
    KonturAction {
        id: done
        objectName: "doneAction"
        //: Button: finishes the curve being placed (keeps the points placed so far).
        text: qsTr("Done")
        toolTip: qsTr("Finish the curve with the points placed so far (Enter)")
        iconName: "object-select-symbolic"
        relevant: actions.placing
        pinned: true
        // Last before the space: it came in after New curve and pushed Teaching 66 px to the right.
        temporary: true
        enabled: actions.placing && actions.editor.placement.pendingCount > 0
        onTriggered: actions.editor.placement.finish()
    }
    // Enter finishes the curve being placed, unless a text field has the focus: there it applies
    // what was typed (text fields leave Enter to shortcuts, for dialogs' default buttons).
    Action {
        shortcut: "Return"
        enabled: done.enabled && !(actions.Window.activeFocusItem instanceof TextInput)
        onTriggered: done.trigger()
    }
    Action {
        shortcut: "Enter"
        enabled: done.enabled && !(actions.Window.activeFocusItem instanceof TextInput)
        onTriggered: done.trigger()
    }
    Action {
        shortcut: "Backspace"
        onTriggered: actions.editor.placement.removeLast()
    }
    KonturAction {
        id: select
        objectName: "selectAction"
        text: qsTr("Move points")
        toolTip: qsTr("Drag points to change curves; drag the canvas to pan (Esc)")
        iconName: "kontur-move-points"
        pinned: true
        checkable: true
        // Moving points is a tool of its own: it leaves a tracing tool, so that a drag pans or moves
        // a point and never draws a stroke.
        checked: actions.editor.mode === EditController.Select && actions.trace.tool === TraceController.None
        onTriggered: {
            actions.trace.tool = TraceController.None
            actions.editor.mode = EditController.Select
        }
    }
    // Esc leaves the trace tool, else the placement, else placing.
    Action {
        shortcut: "Esc"
        onTriggered: {
            if (actions.trace.tool !== TraceController.None)
                actions.trace.tool = TraceController.None
            else if (actions.editor.placement.pendingCount > 0)
                actions.editor.placement.cancel()
            else
                actions.editor.mode = EditController.Select
        }
    }
    KonturAction {
        id: constrained
        objectName: "constrainedAction"
        text: qsTr("Constrained handles")
        toolTip: qsTr("The handles of composite curves keep their direction and change only their length (or drag with the right button or Shift)")
        iconName: "kontur-constrained"
        priority: 40
        checkable: true
        checked: actions.editor.handleMode === EditController.Constrained
        onTriggered: actions.editor.handleMode = actions.editor.handleMode === EditController.Constrained
                     ? EditController.Free : EditController.Constrained
    }
    Action {
        shortcut: StandardKey.Delete
        enabled: !actions.placing && actions.editor.selection.hasCurve
        onTriggered: actions.editor.commands.deleteSelection()
    }
    Action { shortcut: "Left"; onTriggered: actions.nudge(-1, 0) }
    Action { shortcut: "Right"; onTriggered: actions.nudge(1, 0) }
    Action { shortcut: "Up"; onTriggered: actions.nudge(0, 1) }
    Action { shortcut: "Down"; onTriggered: actions.nudge(0, -1) }
    Action { shortcut: "Shift+Left"; onTriggered: actions.nudge(-10, 0) }
    Action { shortcut: "Shift+Right"; onTriggered: actions.nudge(10, 0) }
    Action { shortcut: "Shift+Up"; onTriggered: actions.nudge(0, 10) }
    Action { shortcut: "Shift+Down"; onTriggered: actions.nudge(0, -10) }
    KonturAction {
        id: undo
        objectName: "undoAction"
        text: qsTr("Undo")
        toolTip: qsTr("Undo (Ctrl+Z)")
        shortcut: StandardKey.Undo
        iconName: "edit-undo-symbolic"
        pinned: true
        enabled: actions.editor.canUndo
        onTriggered: actions.editor.undo()
    }
    KonturAction {
        id: redo
        objectName: "redoAction"
        text: qsTr("Redo")
        toolTip: qsTr("Redo (Ctrl+Shift+Z)")
        shortcut: StandardKey.Redo
        iconName: "edit-redo-symbolic"
        pinned: true
        enabled: actions.editor.canRedo
        onTriggered: actions.editor.redo()
    }
    // Where the platform's redo key is another (Ctrl+Y). Where it is this one too, each press still
    // redoes once: the shortcut map hands a key held twice to one of them at a time.
    Action {
        shortcut: "Ctrl+Shift+Z"
        enabled: redo.enabled
        onTriggered: redo.trigger()
    }
    KonturAction {
        id: reset
        objectName: "resetAction"
        text: qsTr("Reset all")
        toolTip: qsTr("Remove every curve and the background picture")
        iconName: "edit-clear-all-symbolic"
        priority: 10
        enabled: actions.editor.document.curveCount > 0 || actions.editor.background.file.length > 0
        onTriggered: resetDialog.open()
    }
    ConfirmDialog {
        id: resetDialog
        objectName: "resetDialog"
        title: qsTr("Reset all")
        text: actions.editor.resetQuestion
        onAccepted: actions.editor.commands.resetAll()
    }

    // --- Teaching ---
    KonturAction {
        id: teachingMenu
        objectName: "teachingMenuAction"
        menuWidth: 320
        //: Menu title (noun): the teaching views (de Casteljau, degree elevation, basis functions…).
        text: qsTr("Teaching")
        toolTip: qsTr("Views that show how curves are built")
        iconName: "kontur-teaching"
        priority: 50
        checked: actions.teaching.view !== TeachingController.None
        entries: [deCasteljau, elevation, compare, comb, basis, functionSpline, runge, practicum, "-", presentation]
    }
    KonturAction {
        id: deCasteljau
        objectName: "teachingDeCasteljau"
        text: qsTr("de Casteljau construction")
        iconName: "kontur-teaching"
        checkable: true
        checked: actions.teaching.view === TeachingController.DeCasteljau
        onTriggered: actions.toggleTeaching(TeachingController.DeCasteljau)
    }
    KonturAction {
        id: elevation
        objectName: "teachingElevation"
        text: qsTr("Degree elevation")
        iconName: "kontur-elevation"
        checkable: true
        checked: actions.teaching.view === TeachingController.Elevation
        onTriggered: actions.toggleTeaching(TeachingController.Elevation)
    }
    KonturAction {
        id: compare
        objectName: "teachingCompare"
        text: qsTr("Compare curve kinds")
        iconName: "kontur-compare"
        checkable: true
        checked: actions.teaching.view === TeachingController.Compare
        onTriggered: actions.toggleTeaching(TeachingController.Compare)
    }
    KonturAction {
        id: comb
        objectName: "teachingComb"
        text: qsTr("Curvature comb and continuity")
        iconName: "kontur-comb"
        checkable: true
        checked: actions.teaching.view === TeachingController.Comb
        onTriggered: actions.toggleTeaching(TeachingController.Comb)
    }
    KonturAction {
        id: basis
        objectName: "teachingBasis"
        text: qsTr("Basis functions")
        iconName: "kontur-basis"
        checkable: true
        checked: actions.showBasis
        onTriggered: actions.showBasis = !actions.showBasis
    }
    KonturAction {
        id: functionSpline
        objectName: "teachingFunctionSpline"
        text: qsTr("Function spline y(x)…")
        iconName: "kontur-function"
        onTriggered: actions.functionSplineRequested()
    }
    KonturAction {
        id: runge
        objectName: "teachingRunge"
        text: qsTr("Runge phenomenon: comparison…")
        iconName: "kontur-runge"
        onTriggered: actions.rungeRequested()
    }
    KonturAction {
        id: practicum
        objectName: "teachingPracticum"
        text: qsTr("Cubic segments with guide vectors…")
        iconName: "kontur-segments"
        onTriggered: actions.practicumRequested()
    }
    KonturAction {
        id: presentation
        objectName: "presentationItem"
        text: qsTr("Presentation mode (F5)")
        shortcut: "F5"
        iconName: "x-office-presentation-symbolic"
        checkable: true
        checked: Presentation.enabled
        onTriggered: Presentation.toggle()
    }

    // --- Trace (issue #10): freehand tracing, calibration of the background, measure, seam length,
    // deviation, snapping and the background lock ---
    KonturAction {
        id: traceMenu
        objectName: "traceMenuAction"
        menuWidth: 380
        //: Menu title: the tools for tracing a pattern from a photo; a title, not an order.
        text: qsTr("Trace")
        toolTip: qsTr("Trace a pattern: freehand, calibrate, measure, compare")
        iconName: "kontur-trace"
        priority: 70
        checked: actions.trace.tool !== TraceController.None
        // The tool in use stays on the bar.
        pinned: checked
        entries: [freehand, calibrate, perspective, traceOutline, measure, seam, seamAllowance, deviation, moveBackground, "-",
            snap, lockBackground, "-", makeLine, deleteKnot, smoothNode, symmetricNode, cornerNode, closeCurve,
            joinCurves, simplifyCurve]
    }
    KonturAction {
        id: freehand
        objectName: "traceFreehand"
        text: qsTr("Freehand (T)")
        shortcut: "T"
        iconName: "kontur-freehand"
        checkable: true
        checked: actions.trace.tool === TraceController.Freehand
        onTriggered: actions.toggleTrace(TraceController.Freehand)
    }
    KonturAction {
        id: calibrate
        objectName: "traceCalibrate"
        text: qsTr("Calibrate background (K)")
        shortcut: "K"
        iconName: "kontur-calibrate"
        checkable: true
        checked: actions.trace.tool === TraceController.Calibrate
        onTriggered: actions.toggleTrace(TraceController.Calibrate)
    }
    KonturAction {
        id: perspective
        objectName: "tracePerspective"
        text: qsTr("Calibrate perspective (Shift+K)")
        shortcut: "Shift+K"
        iconName: "kontur-perspective"
        checkable: true
        enabled: actions.editor.background.file.length > 0
        checked: actions.trace.tool === TraceController.Perspective
        onTriggered: actions.toggleTrace(TraceController.Perspective)
    }
    KonturAction {
        id: traceOutline
        objectName: "traceOutline"
        text: qsTr("Trace outline")
        iconName: "kontur-closed-curve"
        checkable: true
        enabled: actions.editor.background.file.length > 0
        checked: actions.trace.tool === TraceController.Outline
        onTriggered: actions.toggleTrace(TraceController.Outline)
    }
    KonturAction {
        id: measure
        objectName: "traceMeasure"
        text: qsTr("Measure distance (M)")
        shortcut: "M"
        iconName: "kontur-measure"
        checkable: true
        checked: actions.trace.tool === TraceController.Measure
        onTriggered: actions.toggleTrace(TraceController.Measure)
    }
    KonturAction {
        id: seam
        objectName: "traceSeam"
        text: qsTr("Seam length between knots (L)")
        shortcut: "L"
        iconName: "kontur-seam"
        checkable: true
        checked: actions.trace.tool === TraceController.Seam
        onTriggered: actions.toggleTrace(TraceController.Seam)
    }
    // Issue #22: the offset of the selected curve, linked to it (a dialog; not a canvas tool).
    KonturAction {
        id: seamAllowance
        objectName: "traceSeamAllowance"
        text: qsTr("Seam allowance…")
        iconName: "kontur-seam"
        enabled: actions.editor.selection.hasCurve
        onTriggered: actions.seamAllowanceRequested()
    }
    KonturAction {
        id: deviation
        objectName: "traceDeviation"
        text: qsTr("Deviation from a reference curve (D)")
        shortcut: "D"
        iconName: "kontur-deviation"
        checkable: true
        checked: actions.trace.tool === TraceController.Deviation
        onTriggered: actions.toggleTrace(TraceController.Deviation)
    }
    KonturAction {
        id: moveBackground
        objectName: "traceMoveBackground"
        text: qsTr("Move background (O)")
        shortcut: "O"
        iconName: "kontur-move-background"
        checkable: true
        enabled: actions.editor.background.file.length > 0
        checked: actions.trace.tool === TraceController.MoveBackground
        onTriggered: actions.toggleTrace(TraceController.MoveBackground)
    }
    KonturAction {
        id: snap
        objectName: "traceSnap"
        text: qsTr("Snap to knots, grid and marks (S)")
        shortcut: "S"
        iconName: "kontur-snap"
        checkable: true
        checked: actions.trace.snapping
        onTriggered: actions.trace.snapping = !actions.trace.snapping
    }
    KonturAction {
        id: lockBackground
        objectName: "traceLock"
        text: qsTr("Lock background")
        iconName: "changes-prevent-symbolic"
        checkable: true
        enabled: actions.editor.background.file.length > 0
        checked: actions.trace.backgroundLocked
        onTriggered: actions.trace.backgroundLocked = !actions.trace.backgroundLocked
    }

    // --- Finishing a traced piece: the selected knot's or segment's edits and whole-curve edits of
    // composite curves (PieceEdits decides what applies). Two ends count as one point within the
    // touch radius at the zoom the user sees.
    PieceEdits {
        id: pieceEdits
        objectName: "pieceEdits"
        editor: actions.editor
    }
    readonly property alias pieceEdits: pieceEdits
    // The piece edits by their ids, for the point bar and the side panel (a lookup that does not walk
    // `all`, whose model-made actions are remade when the language changes).
    readonly property var pieceActions: ({pieceMakeLine: makeLine, pieceDeleteKnot: deleteKnot,
        pieceSmooth: smoothNode, pieceSymmetric: symmetricNode, pieceCorner: cornerNode, pieceClose: closeCurve,
        pieceJoin: joinCurves, pieceSimplify: simplifyCurve})
    readonly property real touchRadius: actions.canvas.hitRadius / Math.max(actions.canvas.zoom, 1e-300)
    KonturAction {
        id: makeLine
        objectName: "pieceMakeLine"
        iconName: "kontur-make-line"
        text: qsTr("Make line")
        toolTip: qsTr("Make the selected segment a straight line; its knots become corners (Shift+L)")
        shortcut: "Shift+L"
        enabled: pieceEdits.canMakeLine
        onTriggered: pieceEdits.makeSelectedLine()
    }
    KonturAction {
        id: deleteKnot
        objectName: "pieceDeleteKnot"
        iconName: "kontur-delete-knot"
        text: qsTr("Delete knot")
        toolTip: qsTr("Delete the selected knot; its two segments become one")
        enabled: pieceEdits.canDeleteKnot
        onTriggered: pieceEdits.deleteSelectedKnot()
    }
    KonturAction {
        id: smoothNode
        objectName: "pieceSmooth"
        iconName: "kontur-knot-smooth"
        text: qsTr("Smooth knot")
        toolTip: qsTr("The handles of the selected knot stay on one line (Shift+S)")
        shortcut: "Shift+S"
        checkable: true
        checked: actions.editor.selection.nodeType === 0
        enabled: pieceEdits.canEditKnot
        onTriggered: pieceEdits.setSelectedNodeType(0)
    }
    KonturAction {
        id: symmetricNode
        objectName: "pieceSymmetric"
        iconName: "kontur-knot-symmetric"
        text: qsTr("Symmetric knot")
        toolTip: qsTr("The handles of the selected knot mirror each other (Shift+Y)")
        shortcut: "Shift+Y"
        checkable: true
        checked: actions.editor.selection.nodeType === 1
        enabled: pieceEdits.canEditKnot
        onTriggered: pieceEdits.setSelectedNodeType(1)
    }
    KonturAction {
        id: cornerNode
        objectName: "pieceCorner"
        iconName: "kontur-knot-corner"
        text: qsTr("Corner knot")
        toolTip: qsTr("The handles of the selected knot move independently (Shift+C)")
        shortcut: "Shift+C"
        checkable: true
        checked: actions.editor.selection.nodeType === 2
        enabled: pieceEdits.canEditKnot
        onTriggered: pieceEdits.setSelectedNodeType(2)
    }
    KonturAction {
        id: closeCurve
        objectName: "pieceClose"
        iconName: "kontur-closed-curve"
        text: qsTr("Close curve")
        toolTip: qsTr("Join the curve's last knot to its first; ends that meet become one knot (Shift+O)")
        shortcut: "Shift+O"
        enabled: pieceEdits.canClose
        onTriggered: pieceEdits.closeSelected(actions.touchRadius)
    }
    KonturAction {
        id: joinCurves
        objectName: "pieceJoin"
        iconName: "kontur-join"
        text: qsTr("Join curves")
        toolTip: qsTr("Join the selected curve with the curve whose end is nearest to one of its ends (Shift+J)")
        shortcut: "Shift+J"
        enabled: pieceEdits.canJoin
        onTriggered: pieceEdits.joinSelected(actions.touchRadius)
    }
    KonturAction {
        id: simplifyCurve
        objectName: "pieceSimplify"
        iconName: "kontur-simplify"
        text: qsTr("Simplify curve…")
        toolTip: qsTr("Fewer knots within a tolerance you type")
        enabled: pieceEdits.canSimplify
        onTriggered: simplifyDialog.openFor(actions.editor.selection.curveId)
    }
    SimplifyDialog {
        id: simplifyDialog
        objectName: "simplifyDialog"
        pieceEdits: pieceEdits
        units: actions.trace.units
    }

    // --- view ---
    KonturAction {
        id: zoomIn
        objectName: "zoomInAction"
        text: qsTr("Zoom in")
        toolTip: qsTr("Zoom in (+)")
        shortcut: StandardKey.ZoomIn
        iconName: "zoom-in-symbolic"
        priority: 36
        onTriggered: actions.canvas.zoomIn()
    }
    Action { shortcut: "+"; onTriggered: zoomIn.trigger() }
    Action { shortcut: "="; onTriggered: zoomIn.trigger() }
    KonturAction {
        id: zoomOut
        objectName: "zoomOutAction"
        text: qsTr("Zoom out")
        toolTip: qsTr("Zoom out (−)")
        shortcut: StandardKey.ZoomOut
        iconName: "zoom-out-symbolic"
        priority: 35
        onTriggered: actions.canvas.zoomOut()
    }
    Action { shortcut: "-"; onTriggered: zoomOut.trigger() }
    KonturAction {
        id: fit
        objectName: "fitAction"
        //: Command: zoom so that all curves fit in the window.
        text: qsTr("Fit to view")
        toolTip: qsTr("Show all curves (F)")
        shortcut: "F"
        iconName: "zoom-fit-best-symbolic"
        priority: 45
        // In the Compare view the compared curves too: they run beyond the document's own.
        onTriggered: actions.canvas.fitToViewWith(actions.teaching.view === TeachingController.Compare
                                                  ? actions.teaching.sceneBounds() : Qt.rect(0, 0, 0, 0))
    }
    KonturAction {
        id: grid
        objectName: "gridAction"
        spaceBefore: true
        //: Toggle (noun): show or hide the grid on the canvas.
        text: qsTr("Grid")
        toolTip: qsTr("Show or hide the grid and the axes (G)")
        shortcut: "G"
        iconName: "kontur-grid"
        priority: 20
        checkable: true
        checked: actions.canvas.showGrid
        onTriggered: actions.canvas.showGrid = !actions.canvas.showGrid
    }

    // --- language ---
    KonturAction {
        id: languageMenu
        objectName: "languageMenuAction"
        menuWidth: 200
        text: qsTr("Language")
        iconName: "preferences-desktop-locale-symbolic"
        priority: 25
        entries: actions.languageActions
    }
    property var languageActions: []
    Component {
        id: languageComponent
        KonturAction {
            required property var modelData
            objectName: "language_" + modelData.code
            text: modelData.name
            iconName: "preferences-desktop-locale-symbolic"
            checkable: true
            checked: Language.current === modelData.code
            onTriggered: {
                Language.current = modelData.code
                Language.remember(modelData.code)
            }
        }
    }

    // --- the panel: the window shows or hides it, on whichever layout it has ---
    KonturAction {
        id: panel
        objectName: "panelAction"
        text: qsTr("Side panel")
        toolTip: qsTr("Show or hide the side panel: the curves, their points and settings")
        iconName: "sidebar-show-right-symbolic"
        pinned: true
        checkable: true
        checked: actions.panelOpen
        onTriggered: actions.panelToggleRequested()
    }
}
