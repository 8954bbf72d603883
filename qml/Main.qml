// Main: the application window — its controllers, the layout (tool bar, canvas with its overlays,
// teaching and trace bars, basis plot, hint line) and the side panel, and the wiring between them.
// The side panel takes one of three places by the window's shape: a bottom sheet over the canvas on
// portrait or narrow windows, a drawer sliding over the canvas from the right (and pinned beside it
// if the user likes) on landscape tablets, the docked column beside the canvas on wide desktops.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

ApplicationWindow {
    id: root

    // A document given on the command line, opened when the window is ready.
    property url startupFile
    readonly property bool placing: editor.mode === EditController.Place
    // A teaching view is shown (a bar, the basis plot or a page): the first-run starts make room for it.
    readonly property bool teachingShown: teaching.view !== TeachingController.None || toolBar.showBasis
                                          || (practicumView.item !== null && practicumView.item.visible)
                                          || (functionSplineView.item !== null && functionSplineView.item.visible)

    // ---- The layout by the window's shape: its thresholds here and nowhere else ----
    // Narrower than this, or portrait: the bottom sheet.
    readonly property real sheetBelowWidth: 900
    // This wide or wider (and landscape): the docked column of a desktop; between: the drawer.
    readonly property real dockFromWidth: 1400
    // The share of the window the canvas keeps uncovered in every layout and state.
    readonly property real canvasShare: 0.6
    // What the fully raised bottom sheet leaves of a window too short for canvasShare (a phone).
    readonly property real phoneCanvasShare: 0.3
    readonly property string panelLayout: width < sheetBelowWidth || height > width ? "sheet"
                                          : width >= dockFromWidth ? "docked" : "drawer"
    // The panel toggle: docked, shown or hidden; drawer, open or closed; sheet, at a height or away.
    property bool panelOpen: true
    // On landscape tablets the drawer can be pinned beside the canvas; pinned, it behaves as docked.
    property bool panelPinned: true
    readonly property bool panelBeside: panelOpen && (panelLayout === "docked" || panelLayout === "drawer" && panelPinned)
    readonly property real panelWidth: Math.min(Theme.panelWidth, width * (1 - canvasShare))
    // How much of the canvas's bottom the sheet covers now.
    readonly property real sheetCover: panelLayout === "sheet" ? sheet.shownHeight : 0
    // The trace start of the first-run hint: once its picture is loaded, it is fitted to the view and
    // the perspective tool looks for the reference sheet in it at once (Apply then calibrates; where
    // there is none, the bar asks for four taps at its corners).
    property bool traceAfterLoad: false
    // The pattern piece bar is open (PieceBar): the selected closed curve's marks as a garment piece.
    property bool pieceEditing: false

    // The size is given when the window is made (loadMainWindow: StartOptions::size).
    // The canvas's background is the window's own colour, cleared with every frame at no cost.
    color: Theme.canvasBackground
    minimumWidth: 360
    minimumHeight: 400
    visible: true
    title: files.displayName + (editor.modified ? " *" : "") + " — " + qsTr("Kontur")

    EditController {
        id: editor
        objectName: "editor"
    }
    // The document's file (new, open, save, import, the units of DXF files that name none, the
    // folders the dialogs start in), the exports, the recovery copy and the recent files: a job each.
    DocumentFiles {
        id: files
        objectName: "files"
        editor: editor
        recent: recent
    }
    Exporter {
        id: exporter
        objectName: "exporter"
        editor: editor
        files: files
    }
    Recovery {
        id: recovery
        objectName: "recovery"
        editor: editor
        files: files
    }
    RecentFiles {
        id: recent
        objectName: "recent"
    }
    // The teaching views (issue #9): which one is shown and what it computes.
    TeachingController {
        id: teaching
        objectName: "teaching"
        editor: editor
    }
    // The tracing tools (issue #10): freehand, calibration, measure, seam, deviation, snapping.
    TraceController {
        id: trace
        objectName: "trace"
        editor: editor
        gridStep: canvas.gridStep
    }
    // A garment piece's own marks (grainline, notches, drill holes, fold, size, quantity, material).
    PieceMarkEdits {
        id: pieceMarks
        objectName: "pieceMarks"
        editor: editor
    }
    // A piece's seam allowance per seam: the seam tapped and its width.
    SeamWidths {
        id: seamWidths
        objectName: "seamWidths"
        editor: editor
    }
    FileActions {
        id: fileActions
        objectName: "fileActions"
        editor: editor
        files: files
        exporter: exporter
        recovery: recovery
        recent: recent
        canvas: canvas
    }
    // Presentation mode for projectors: larger fonts everywhere (lines and points via the Theme).
    Binding {
        target: root
        property: "font.pixelSize"
        value: Theme.presentationFontSize
        when: Theme.presentation
    }

    Component.onCompleted: fileActions.start(startupFile)
    onClosing: (close) => fileActions.closing(close)

    // The compared curves run beyond the document's own: the Compare view brings them all into view
    // as it opens and as its mode changes.
    Connections {
        target: teaching
        function fitCompared() {
            if (teaching.view === TeachingController.Compare)
                canvas.fitToViewWith(teaching.sceneBounds())
        }
        function onViewChanged() { Qt.callLater(fitCompared) }
        function onCompareModeChanged() { Qt.callLater(fitCompared) }
    }
    // The bar under the canvas takes its height after the view has opened: fitted again to the
    // canvas's new height while Compare is shown.
    Connections {
        target: canvas
        enabled: teaching.view === TeachingController.Compare
        function onHeightChanged() { Qt.callLater(canvas.fitToViewWith, teaching.sceneBounds()) }
    }
    // Curves from a file: show them all.
    Connections {
        target: editor
        function onDocumentReplaced() { Qt.callLater(canvas.fitToView) }
    }

    header: AppToolBar {
        id: toolBar
        objectName: "toolBar"
        editor: editor
        fileActions: fileActions
        canvas: canvas
        teaching: teaching
        trace: trace
        panelOpen: root.panelOpen
        onPanelToggleRequested: root.panelOpen = !root.panelOpen
        onFunctionSplineRequested: functionSplineView.openSpline()
        onRungeRequested: functionSplineView.openRunge()
        onPracticumRequested: practicumView.open()
        onSeamAllowanceRequested: seamDialog.open()
    }
    SeamAllowance {
        id: seamAllowance
        objectName: "seamAllowance"
        editor: editor
    }
    SeamAllowanceDialog {
        id: seamDialog
        seam: seamAllowance
    }

    // The canvas, and under it the bars and the hint line (a plain row of the layout rather than the
    // window's footer, so that a wrapped second line always gets its room).
    ColumnLayout {
        anchors.fill: parent
        spacing: 0

        CanvasView {
            id: canvas
            objectName: "canvas"
            controller: editor
            menuOpen: toolBar.menuOpen
            // While a finger drags the sheet, the canvas's input keeps the shape it had when the drag
            // began: a finger the sheet slid away from must not land on the canvas mid-gesture (a tap
            // handler would wait for the release of a touch it never saw pressed).
            coveredBottom: sheet.dragging ? Math.max(sheet.dragStart, root.sheetCover) : root.sheetCover
            Layout.fillWidth: true
            Layout.fillHeight: true
            // The docked (or pinned) panel lies over the window's right edge: the canvas ends where
            // it begins.
            Layout.rightMargin: root.panelBeside ? panelDrawer.width : 0

            // The teaching views' drawing and gestures over the curves.
            TeachingOverlay {
                objectName: "teachingOverlay"
                anchors.fill: parent
                canvas: canvas
                teaching: teaching
                editor: editor
            }

            // The tracing tools' drawing and input over the curves (above the teaching views).
            TraceOverlay {
                objectName: "traceOverlay"
                anchors.fill: parent
                canvas: canvas
                trace: trace
            }

            // A garment piece's marks, and their placing by touch while a piece tool is chosen.
            PiecePainter {
                id: piecePainter
                objectName: "piecePainter"
                anchors.fill: parent
                canvas: canvas
                marks: pieceMarks
                seams: seamWidths
                lineWidth: Theme.curveWidth
            }

            // Files dropped on the canvas: a document opens, anything else is imported.
            DropArea {
                anchors.fill: parent
                keys: ["text/uri-list"]
                onDropped: (drop) => {
                    for (const url of drop.urls)
                        fileActions.openDropped(url)
                    drop.accept()
                }
            }

            // Three large starts on an empty document, in the room the sheet leaves.
            FirstRunHint {
                objectName: "firstRunHint"
                anchors.fill: parent
                anchors.bottomMargin: root.sheetCover
                shown: editor.document.curveCount === 0 && !root.placing
                       && editor.background.file.length === 0 && trace.tool === TraceController.None
                       && !root.teachingShown
                onNewCurveRequested: editor.startPlacing(CurveKind.Bezier)
                onOpenRequested: fileActions.openAction.trigger()
                onTraceRequested: {
                    root.traceAfterLoad = true
                    fileActions.loadBackground()
                }
            }

            // The selected knot's commands within reach of a finger, above the sheet.
            PointBar {
                objectName: "pointBar"
                actions: toolBar.actions
                editing: !root.placing
                maximumWidth: canvas.width - 2 * Theme.spacing
                anchors.horizontalCenter: parent.horizontalCenter
                anchors.bottom: parent.bottom
                anchors.bottomMargin: root.sheetCover + Theme.spacing
            }

            // Refusals and problems as a banner over the canvas; it does not block anything.
            MessageBanner {
                objectName: "messageBanner"
                editor: editor
                onUnitsRequested: fileActions.changeUnitlessUnits()
                anchors.top: parent.top
                anchors.horizontalCenter: parent.horizontalCenter
                anchors.topMargin: Theme.spacing
            }
        }

        TeachingBar {
            objectName: "teachingBar"
            teaching: teaching
            Layout.fillWidth: true
        }

        TraceBar {
            objectName: "traceBar"
            trace: trace
            Layout.fillWidth: true
        }

        PieceBar {
            objectName: "pieceBar"
            marks: pieceMarks
            seams: seamWidths
            painter: piecePainter
            open: root.pieceEditing
            onCloseRequested: root.pieceEditing = false
            Layout.fillWidth: true
        }

        // The basis functions of the selected curve, under the canvas; its t is the de Casteljau view's.
        BasisPlotPanel {
            id: basisPanel
            objectName: "basisPanel"
            visible: toolBar.showBasis
            editor: editor
            Layout.fillWidth: true
            // In presentation mode taller (its header and labels are larger); enlarged, most of the window.
            Layout.preferredHeight: !expanded ? implicitHeight
                                    : enlarged ? root.height * 0.6
                                    : Math.min(Theme.presentation ? 440 : 270, root.height * (Theme.presentation ? 0.42 : 0.32))
            onCloseRequested: toolBar.showBasis = false
            Binding { target: basisPanel.basis; property: "parameter"; value: teaching.parameter }
            Connections {
                target: basisPanel.basis
                function onParameterChanged() { teaching.parameter = basisPanel.basis.parameter }
            }
        }

        Pane {
            Layout.fillWidth: true
            padding: Theme.spacing / 2
            leftPadding: Theme.spacing
            // As tall as the wrapped hint needs.
            contentHeight: messageLine.implicitHeight
            Label {
                id: messageLine
                objectName: "messageLine"
                width: parent.width
                // Long hints in long languages take a second line rather than being cut.
                wrapMode: Text.WordWrap
                text: {
                    // The tracing tool in use says what it does (not how the canvas pans).
                    if (trace.tool !== TraceController.None)
                        return trace.hint
                    switch (piecePainter.tool) {
                    case PiecePainter.Grainline:
                        return piecePainter.pending ? qsTr("Grainline: tap its other end.")
                                                    : qsTr("Grainline: tap one end, then the other.")
                    case PiecePainter.Fold:
                        return piecePainter.pending ? qsTr("On fold: tap the fold line's other end.")
                                                    : qsTr("On fold: tap one end of the fold line, then the other.")
                    case PiecePainter.Notch:
                        return qsTr("Notch: tap the seam to place one; drag a notch to slide it along the seam.")
                    case PiecePainter.DrillHole:
                        return qsTr("Drill hole: tap where it goes.")
                    case PiecePainter.Delete:
                        return qsTr("Delete mark: tap a notch, drill hole, grainline or fold line.")
                    case PiecePainter.Seam:
                        return qsTr("Seam allowance: tap a seam, then set its width in the bar.")
                    }
                    if (root.placing && editor.placement.openEnded)
                        return qsTr("New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.")
                            .arg(editor.placement.pendingCount)
                    if (root.placing)
                        return qsTr("New curve: tap or click point %1 of %2. Esc cancels.")
                            .arg(editor.placement.pendingCount + 1).arg(editor.placement.requiredPoints)
                    if (editor.document.curveCount === 0)
                        return qsTr("Press “New Bézier” and tap 4 points to draw your first curve.")
                    return qsTr("Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.")
                }
            }
        }
    }

    // The side panel: one instance, in the drawer or in the bottom sheet as the layout says.
    PanelDrawer {
        id: panelDrawer
        objectName: "panelDrawer"
        beside: root.panelBeside
        wanted: root.panelOpen
        used: root.panelLayout !== "sheet"
        pinnable: root.panelLayout === "drawer"
        pinned: root.panelPinned
        // Under the tool bar also when it slides over the canvas: the bar's panel button stays free.
        y: toolBar.height
        width: root.panelWidth
        height: beside ? canvas.height : root.height - toolBar.height
        onPinToggled: root.panelPinned = !root.panelPinned
        // Closed by Esc or a press outside, or opened by a swipe from the edge: the toggle follows.
        onClosed: if (root.panelLayout === "drawer" && !root.panelPinned) root.panelOpen = false
        onOpened: root.panelOpen = true
        Component.onCompleted: show()
    }

    // Over the bottom of the canvas, as wide as it (portrait and narrow windows).
    BottomSheet {
        id: sheet
        objectName: "bottomSheet"
        visible: root.panelLayout === "sheet" && height > 0
        open: root.panelOpen && root.panelLayout === "sheet"
        width: canvas.width
        y: canvas.y + canvas.height - height
        peekHeight: handleHeight + sidePanel.peekHeight
        // The canvas keeps its share of the window's height above the sheet at its fullest, where
        // that leaves the sheet room to grow past its peek. On a phone it would not (peek, half and
        // full were one height with two rows of the table): there the full sheet may leave the
        // canvas down to root.phoneCanvasShare, and grows to twice its peek.
        fullHeight: {
            const keepShare = Math.max(handleHeight, canvas.height - root.canvasShare * root.height)
            if (keepShare >= 1.5 * peekHeight)
                return keepShare
            return Math.max(keepShare, Math.min(2 * peekHeight, canvas.height - root.phoneCanvasShare * root.height))
        }
        onCloseRequested: root.panelOpen = false
        onLowered: sidePanel.scrollToTop()
    }

    SidePanel {
        id: sidePanel
        objectName: "sidePanel"
        parent: root.panelLayout === "sheet" ? sheet.contentArea : panelDrawer.contentArea
        anchors.fill: parent
        editor: editor
        actions: toolBar.actions
        pieceMarks: pieceMarks
        onPieceRequested: root.pieceEditing = true
        onLoadBackgroundRequested: {
            root.traceAfterLoad = false
            fileActions.loadBackground()
        }
    }

    // The first-run hint's picture is in: fit it, and find its sheet.
    Connections {
        target: editor.background
        function onChanged() {
            if (root.traceAfterLoad && editor.background.file.length > 0) {
                Qt.callLater(canvas.fitToView) // after the canvas has the new picture
                trace.tool = TraceController.Perspective
                trace.perspective.findSheet()
            }
            root.traceAfterLoad = false
        }
    }

    // Teaching pages over the window: function splines and Runge's example, and the cubic segments
    // with their guide vectors. Each is made when first opened (made with the window, the two were a
    // tenth of its start-up), over the window's content as before.
    Loader {
        id: functionSplineView
        active: false
        source: "FunctionSplineView.qml"
        onLoaded: {
            item.parent = root.contentItem
            item.editor = editor
        }
        function openSpline() {
            active = true
            item.openSpline()
        }
        function openRunge() {
            active = true
            item.openRunge()
        }
    }
    Loader {
        id: practicumView
        active: false
        source: "PracticumView.qml"
        onLoaded: item.parent = root.contentItem
        function open() {
            active = true
            item.open()
        }
    }
}
