// Main: the application window — tool bar, canvas, side panel and message line.
// Over 600 lines for now: tool bar, file dialogs and the message line are still inline; issue #18
// moves them into AppToolBar, FileActions, ConfirmDialog and MessageBanner.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Dialogs
import QtQuick.Layouts
import Kontur
import Kontur.Models

ApplicationWindow {
    id: root

    // A document given on the command line, opened when the window is ready.
    property url startupFile
    // What to do once the user has answered the unsaved-changes question.
    property var afterUnsaved: null
    property bool closeConfirmed: false
    // Resolution of the next PNG export, as a multiple of the view's size, and whether it shows
    // every curve (the view is fitted for the picture and put back afterwards).
    property real pngScale: 2
    property bool pngWholeDocument: false
    readonly property bool narrow: width < 720
    // The basis functions plot under the canvas (Teaching menu).
    property bool showBasis: false

    width: 1100
    height: 720
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
    FileController {
        id: files
        objectName: "files"
        editor: editor
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
    // Presentation mode for projectors: larger fonts everywhere (lines and points via the Theme).
    Binding {
        target: root
        property: "font.pixelSize"
        value: Theme.presentationFontSize
        when: Theme.presentation
    }
    Shortcut { sequence: "F5"; onActivated: Presentation.toggle() }

    Component.onCompleted: {
        if (startupFile.toString().length > 0)
            files.open(startupFile)
        else if (files.hasRecovery)
            recoveryDialog.open()
    }
    onClosing: (close) => {
        if (editor.modified && !closeConfirmed) {
            close.accepted = false
            askUnsaved(() => { root.closeConfirmed = true; root.close() })
            return
        }
        files.closing()
    }

    // Runs `action` at once, or after the user saved or discarded the unsaved changes.
    function askUnsaved(action) {
        if (!editor.modified) {
            action()
            return
        }
        afterUnsaved = action
        unsavedDialog.open()
    }
    function saveThen(action) {
        if (files.save()) {
            action()
            return
        }
        afterUnsaved = action
        saveDialog.open()
    }

    // Curves from a file: show them all.
    Connections {
        target: editor
        function onDocumentReplaced() { Qt.callLater(canvas.fitToView) }
    }

    readonly property bool placing: editor.mode === EditController.Place
    // Qt Quick's software backend (machines without GPU drivers) cannot draw the Material style's
    // elevation shadow, and with it loses the whole background of dialogs and menus: they go flat there.
    readonly property bool softwareRendering: canvas.graphicsApi === "software"

    function toggleNewBezier() {
        if (placing && editor.placementKind === EditController.BezierKind)
            editor.mode = EditController.Select
        else
            editor.startPlacing(EditController.BezierKind)
    }

    Shortcut { sequences: [StandardKey.Undo]; onActivated: editor.undo() }
    Shortcut { sequences: [StandardKey.Save]; onActivated: root.saveThen(() => {}) }
    Shortcut { sequences: [StandardKey.Open]; onActivated: root.askUnsaved(() => openDialog.open()) }
    Shortcut { sequences: [StandardKey.New]; onActivated: root.askUnsaved(() => files.newDocument()) }
    Shortcut { sequences: [StandardKey.Redo, "Ctrl+Shift+Z"]; onActivated: editor.redo() }
    Shortcut { sequence: "B"; onActivated: root.toggleNewBezier() }
    Shortcut { sequences: [StandardKey.ZoomIn, "+", "="]; onActivated: canvas.zoomIn() }
    Shortcut { sequences: [StandardKey.ZoomOut, "-"]; onActivated: canvas.zoomOut() }
    Shortcut { sequence: "F"; onActivated: canvas.fitToView() }
    Shortcut { sequence: "G"; onActivated: canvas.showGrid = !canvas.showGrid }
    Shortcut {
        sequence: "Esc"
        onActivated: {
            if (trace.tool !== TraceController.None)
                trace.tool = TraceController.None
            else if (editor.pendingCount > 0)
                editor.cancelPlacement()
            else
                editor.mode = EditController.Select
        }
    }
    Shortcut { sequence: "Backspace"; onActivated: editor.removeLastPending() }
    // Enter finishes the curve being placed, unless a text field has the focus: there it applies
    // what was typed (text fields leave Enter to shortcuts, for dialogs' default buttons).
    Shortcut {
        sequences: ["Return", "Enter"]
        enabled: root.placing && !(root.activeFocusItem instanceof TextInput)
        onActivated: editor.finishPlacement()
    }
    Shortcut {
        sequences: [StandardKey.Delete]
        enabled: !root.placing && editor.selectedCurve >= 0
        onActivated: editor.deleteSelection()
    }
    // Arrow keys nudge the selected point by a pixel on screen (Shift: ten).
    function nudge(dx, dy) { editor.nudgeSelected(Qt.point(dx / canvas.zoom, dy / canvas.zoom)) }
    Shortcut { sequence: "Left"; onActivated: root.nudge(-1, 0) }
    Shortcut { sequence: "Right"; onActivated: root.nudge(1, 0) }
    Shortcut { sequence: "Up"; onActivated: root.nudge(0, 1) }
    Shortcut { sequence: "Down"; onActivated: root.nudge(0, -1) }
    Shortcut { sequence: "Shift+Left"; onActivated: root.nudge(-10, 0) }
    Shortcut { sequence: "Shift+Right"; onActivated: root.nudge(10, 0) }
    Shortcut { sequence: "Shift+Up"; onActivated: root.nudge(0, 10) }
    Shortcut { sequence: "Shift+Down"; onActivated: root.nudge(0, -10) }

    header: ToolBar {
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
                    MenuItem { text: qsTr("New"); onTriggered: root.askUnsaved(() => files.newDocument()) }
                    MenuItem { text: qsTr("Open…"); onTriggered: root.askUnsaved(() => openDialog.open()) }
                    Menu {
                        title: qsTr("Open recent")
                        enabled: files.recentFiles.length > 0
                        Repeater {
                            model: files.recentFiles
                            MenuItem {
                                required property string modelData
                                text: modelData
                                onTriggered: root.askUnsaved(() => files.open("file://" + modelData))
                            }
                        }
                    }
                    MenuItem { text: qsTr("Save"); onTriggered: root.saveThen(() => {}) }
                    MenuItem { text: qsTr("Save as…"); onTriggered: { root.afterUnsaved = null; saveDialog.open() } }
                    MenuSeparator {}
                    MenuItem { text: qsTr("Import points, CSV or SVG…"); onTriggered: importDialog.open() }
                    MenuItem { text: qsTr("Export SVG…"); onTriggered: svgDialog.open() }
                    MenuItem {
                        text: qsTr("Export the selected curve as CSV…")
                        enabled: editor.selectedCurve >= 0
                        onTriggered: csvDialog.open()
                    }
                    MenuItem {
                        text: qsTr("Append the selected curve to a points file…")
                        enabled: editor.selectedCurve >= 0
                        onTriggered: appendDialog.open()
                    }
                    MenuItem { text: qsTr("Export PNG (view size)…"); onTriggered: { root.pngScale = 1; pngDialog.open() } }
                    MenuItem { text: qsTr("Export PNG (2× view size)…"); onTriggered: { root.pngScale = 2; pngDialog.open() } }
                    MenuItem { text: qsTr("Export PNG (4× view size)…"); onTriggered: { root.pngScale = 4; pngDialog.open() } }
                    MenuItem {
                        text: qsTr("Export PNG of the whole document (2×)…")
                        onTriggered: { root.pngScale = 2; root.pngWholeDocument = true; pngDialog.open() }
                    }
                    MenuSeparator {}
                    MenuItem { text: qsTr("Quit"); onTriggered: root.close() }
                }
            }
            ToolButton {
                objectName: "newBezierButton"
                text: qsTr("New Bézier")
                checkable: true
                checked: root.placing && editor.placementKind === EditController.BezierKind
                onClicked: root.toggleNewBezier()
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Place 4 control points to make a cubic Bézier curve (B)")
            }
            ToolButton {
                id: newCurveButton
                objectName: "newCurveButton"
                text: qsTr("New curve")
                checked: root.placing && editor.placementKind !== EditController.BezierKind
                onClicked: newCurveMenu.open()
                ToolTip.visible: hovered && !newCurveMenu.visible
                ToolTip.delay: 600
                ToolTip.text: qsTr("Choose the kind of curve to place")

                ToolbarMenu {
                    id: newCurveMenu
                    Repeater {
                        // The names are translated: the list is announced again on a language switch.
                        model: editor.kinds
                        MenuItem {
                            required property var modelData
                            objectName: "newKind" + modelData.kind
                            text: modelData.name
                            onTriggered: editor.startPlacing(modelData.kind)
                        }
                    }
                }
            }
            ToolButton {
                objectName: "doneButton"
                text: qsTr("Done")
                visible: root.placing
                enabled: editor.pendingCount > 0
                onClicked: editor.finishPlacement()
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Finish the curve with the points placed so far (Enter)")
            }
            ToolButton {
                objectName: "selectButton"
                text: qsTr("Move points")
                checkable: true
                checked: editor.mode === EditController.Select
                onClicked: editor.mode = EditController.Select
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Drag points to change curves; drag the canvas to pan (Esc)")
            }
            ToolButton {
                objectName: "constrainedButton"
                text: qsTr("Constrained")
                checkable: true
                checked: editor.handleMode === EditController.Constrained
                onToggled: editor.handleMode = checked ? EditController.Constrained : EditController.Free
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Composite handles keep their direction and change only their length (or drag with the right button or Shift)")
            }
            ToolSeparator {}
            ToolButton {
                objectName: "undoButton"
                text: qsTr("Undo")
                enabled: editor.canUndo
                onClicked: editor.undo()
            }
            ToolButton {
                objectName: "redoButton"
                text: qsTr("Redo")
                enabled: editor.canRedo
                onClicked: editor.redo()
            }
            ToolSeparator {}
            ToolButton {
                id: teachingMenuButton
                objectName: "teachingMenuButton"
                text: qsTr("Teaching")
                checked: teaching.view !== TeachingController.None
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
                        checked: teaching.view === TeachingController.DeCasteljau
                        onTriggered: teaching.view = teaching.view === TeachingController.DeCasteljau ? TeachingController.None : TeachingController.DeCasteljau
                    }
                    MenuItem {
                        objectName: "teachingElevation"
                        text: qsTr("Degree elevation")
                        checkable: true
                        checked: teaching.view === TeachingController.Elevation
                        onTriggered: teaching.view = teaching.view === TeachingController.Elevation ? TeachingController.None : TeachingController.Elevation
                    }
                    MenuItem {
                        objectName: "teachingCompare"
                        text: qsTr("Compare curve kinds")
                        checkable: true
                        checked: teaching.view === TeachingController.Compare
                        onTriggered: teaching.view = teaching.view === TeachingController.Compare ? TeachingController.None : TeachingController.Compare
                    }
                    MenuItem {
                        objectName: "teachingComb"
                        text: qsTr("Curvature comb and continuity")
                        checkable: true
                        checked: teaching.view === TeachingController.Comb
                        onTriggered: teaching.view = teaching.view === TeachingController.Comb ? TeachingController.None : TeachingController.Comb
                    }
                    MenuItem {
                        objectName: "teachingBasis"
                        text: qsTr("Basis functions")
                        checkable: true
                        checked: root.showBasis
                        onTriggered: root.showBasis = !root.showBasis
                    }
                    MenuItem {
                        objectName: "teachingFunctionSpline"
                        text: qsTr("Function spline y(x)…")
                        onTriggered: functionSplineView.openSpline()
                    }
                    MenuItem {
                        objectName: "teachingRunge"
                        text: qsTr("Runge comparison…")
                        onTriggered: functionSplineView.openRunge()
                    }
                    MenuItem {
                        objectName: "teachingPracticum"
                        text: qsTr("Cubic segments…")
                        onTriggered: practicumView.open()
                    }
                    MenuSeparator {}
                    MenuItem {
                        objectName: "presentationItem"
                        text: qsTr("Presentation mode (F5)")
                        checkable: true
                        checked: Presentation.enabled
                        onTriggered: Presentation.toggle()
                    }
                }
            }
            ToolButton {
                id: traceMenuButton
                objectName: "traceMenuButton"
                text: qsTr("Trace")
                checked: trace.tool !== TraceController.None
                onClicked: traceMenu.open()
                ToolTip.visible: hovered && !traceMenu.visible
                ToolTip.delay: 600
                ToolTip.text: qsTr("Trace a pattern: freehand, calibrate, measure, compare")
                TraceMenu {
                    id: traceMenu
                    objectName: "traceMenu"
                    minimumWidth: 380
                    trace: trace
                }
            }
            Item { Layout.fillWidth: true }
            ToolButton {
                objectName: "zoomOutButton"
                text: "\u2212"
                font.pixelSize: 20
                onClicked: canvas.zoomOut()
                Accessible.name: qsTr("Zoom out")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Zoom out")
            }
            Label {
                objectName: "zoomReadout"
                // Whole percents from 1 % to 100,000 %, three significant digits beyond (0.0025 %, 1.5E+12 %).
                text: qsTr("%1 %").arg(canvas.zoom >= 0.01 && canvas.zoom < 1000
                                       ? Number(canvas.zoom * 100).toLocaleString(Qt.locale(Language.current), "f", 0)
                                       : Number(canvas.zoom * 100).toLocaleString(Qt.locale(Language.current), "g", 3))
                horizontalAlignment: Text.AlignHCenter
                Layout.minimumWidth: 64
            }
            ToolButton {
                objectName: "zoomInButton"
                text: "+"
                font.pixelSize: 20
                onClicked: canvas.zoomIn()
                Accessible.name: qsTr("Zoom in")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Zoom in")
            }
            ToolButton {
                objectName: "gridButton"
                text: qsTr("Grid")
                checkable: true
                checked: canvas.showGrid
                onToggled: canvas.showGrid = checked
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Show or hide the grid and the axes (G)")
            }
            ToolButton {
                text: qsTr("Fit")
                onClicked: canvas.fitToView()
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
                id: resetButton
                objectName: "resetButton"
                text: qsTr("Reset all")
                enabled: editor.document.curveCount > 0 || editor.backgroundFile.length > 0
                onClicked: resetDialog.open()
            }
            ToolButton {
                id: panelButton
                objectName: "panelButton"
                text: qsTr("Panel")
                checkable: !root.narrow
                checked: true
                onClicked: if (root.narrow) panelDrawer.open()
            }
        }
        }
    }

    // The canvas and panel, and under them the message line (a plain row of the layout rather than
    // the window's footer, so that a wrapped second line always gets its room).
    ColumnLayout {
        anchors.fill: parent
        spacing: 0

        RowLayout {
            Layout.fillWidth: true
            Layout.fillHeight: true
            spacing: 0

            CanvasView {
                id: canvas
                objectName: "canvas"
                controller: editor
                menuOpen: fileMenu.visible || newCurveMenu.visible || teachingMenu.visible || traceMenu.visible
                          || languageMenu.visible
                Layout.fillWidth: true
                Layout.fillHeight: true

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

                // Files dropped on the canvas: a document opens, anything else is imported.
                DropArea {
                    anchors.fill: parent
                    keys: ["text/uri-list"]
                    onDropped: (drop) => {
                        for (const url of drop.urls) {
                            if (url.toString().toLowerCase().endsWith(".kontur"))
                                root.askUnsaved(() => files.open(url))
                            else
                                files.importFile(url, EditController.CompositeKind)
                        }
                        drop.accept()
                    }
                }

                // Refusals and problems as a banner over the canvas; it does not block anything.
                Rectangle {
                    id: banner
                    objectName: "messageBanner"
                    visible: editor.message.id !== 0
                    anchors.top: parent.top
                    anchors.horizontalCenter: parent.horizontalCenter
                    anchors.topMargin: Theme.spacing
                    width: Math.min(parent.width - 2 * Theme.spacing, bannerRow.implicitWidth + 2 * Theme.spacing)
                    height: bannerRow.implicitHeight + Theme.spacing
                    radius: 6
                    color: Theme.bannerBackground
                    border.color: Theme.bannerBorder
                    RowLayout {
                        id: bannerRow
                        anchors.fill: parent
                        anchors.leftMargin: Theme.spacing
                        Label {
                            objectName: "messageText"
                            Layout.fillWidth: true
                            wrapMode: Text.Wrap
                            // Translated when shown: it follows a language switch.
                            text: editor.messageText
                        }
                        ToolButton {
                            text: "\u2715"
                            Accessible.name: qsTr("Close message")
                            onClicked: editor.clearMessage()
                        }
                    }
                    Timer {
                        running: banner.visible
                        interval: 8000
                        onTriggered: editor.clearMessage()
                    }
                }
            }

            SidePanel {
                objectName: "sidePanel"
                visible: panelButton.checked && !root.narrow
                editor: editor
                Layout.preferredWidth: Theme.panelWidth
                Layout.maximumWidth: Theme.panelWidth
                Layout.fillHeight: true
                onLoadBackgroundRequested: backgroundDialog.open()
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

        // The basis functions of the selected curve, under the canvas; its t is the de Casteljau view's.
        BasisPlotPanel {
            id: basisPanel
            objectName: "basisPanel"
            visible: root.showBasis
            editor: editor
            Layout.fillWidth: true
            Layout.preferredHeight: expanded ? Math.min(270, root.height * 0.32) : implicitHeight
            onCloseRequested: root.showBasis = false
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
                    if (root.placing && editor.placementOpenEnded)
                        return qsTr("New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.")
                            .arg(editor.pendingCount)
                    if (root.placing)
                        return qsTr("New curve: tap or click point %1 of %2. Esc cancels.")
                            .arg(editor.pendingCount + 1).arg(editor.requiredPoints)
                    if (editor.document.curveCount === 0)
                        return qsTr("Press “New Bézier” and tap 4 points to draw your first curve.")
                    return qsTr("Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.")
                }
            }
        }
    }

    // On narrow screens (a tablet held upright) the panel slides in from the right.
    Drawer {
        id: panelDrawer
        objectName: "panelDrawer"
        edge: Qt.RightEdge
        width: Math.min(root.width * 0.85, Theme.panelWidth + 60)
        height: root.height
        interactive: root.narrow
        SidePanel {
            anchors.fill: parent
            editor: editor
            onLoadBackgroundRequested: backgroundDialog.open()
        }
    }

    readonly property var documentFilters: [qsTr("Kontur documents (*.kontur)"),
        qsTr("Points, CSV and SVG files (*.txt *.csv *.svg)"), qsTr("All files (*)")]
    FileDialog {
        id: openDialog
        title: qsTr("Open")
        nameFilters: root.documentFilters
        onAccepted: files.open(selectedFile)
    }
    FileDialog {
        id: saveDialog
        title: qsTr("Save as")
        fileMode: FileDialog.SaveFile
        defaultSuffix: "kontur"
        nameFilters: [qsTr("Kontur documents (*.kontur)")]
        onAccepted: {
            if (files.saveAs(selectedFile) && root.afterUnsaved) {
                const action = root.afterUnsaved
                root.afterUnsaved = null
                action()
            }
        }
    }
    FileDialog {
        id: importDialog
        title: qsTr("Import")
        nameFilters: [qsTr("Points, CSV, SVG and Kontur files (*.txt *.csv *.svg *.kontur)"), qsTr("All files (*)")]
        onAccepted: files.importFile(selectedFile, editor.placementKind === EditController.BezierKind
                                                   ? EditController.CompositeKind : editor.placementKind)
    }
    FileDialog {
        id: svgDialog
        title: qsTr("Export SVG")
        fileMode: FileDialog.SaveFile
        defaultSuffix: "svg"
        nameFilters: [qsTr("SVG images (*.svg)")]
        onAccepted: files.exportSvg(selectedFile)
    }
    FileDialog {
        id: csvDialog
        title: qsTr("Export CSV")
        fileMode: FileDialog.SaveFile
        defaultSuffix: "csv"
        nameFilters: [qsTr("CSV files (*.csv)")]
        onAccepted: files.exportCsv(selectedFile)
    }
    FileDialog {
        id: appendDialog
        title: qsTr("Append to a points file")
        fileMode: FileDialog.SaveFile
        defaultSuffix: "txt"
        options: FileDialog.DontConfirmOverwrite // it appends, it never overwrites
        nameFilters: [qsTr("Points files (*.txt)")]
        onAccepted: files.appendPoints(selectedFile)
    }
    FileDialog {
        id: pngDialog
        title: qsTr("Export PNG")
        fileMode: FileDialog.SaveFile
        defaultSuffix: "png"
        nameFilters: [qsTr("PNG images (*.png)")]
        onAccepted: {
            const path = decodeURIComponent(selectedFile.toString().replace(/^file:\/\//, ""))
            const zoom = canvas.zoom
            const centre = Qt.point(canvas.center.x, canvas.center.y)
            const whole = root.pngWholeDocument
            root.pngWholeDocument = false
            if (whole)
                canvas.fitToView()
            // Every curve drawn as lines at the picture's scale, not from the on-screen cache.
            canvas.layered = false
            canvas.grabToImage(result => {
                result.saveToFile(path)
                canvas.layered = true
                if (whole)
                    canvas.restoreView(zoom, centre)
            }, Qt.size(canvas.width * root.pngScale, canvas.height * root.pngScale))
        }
        onRejected: root.pngWholeDocument = false
    }
    Dialog {
        id: unsavedDialog
        objectName: "unsavedDialog"
        title: qsTr("Unsaved changes")
        modal: true
        Material.elevation: root.softwareRendering ? 0 : 24
        anchors.centerIn: parent
        width: Math.min(root.width * 0.9, 460)
        // Kontur's own buttons, not standardButtons: Qt writes a standard button's text once, in the
        // language of that moment (a switch leaves it behind), and Debian's Qt has none in Slovak.
        footer: DialogButtonBox {
            Button { text: qsTr("Save"); DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole }
            Button { text: qsTr("Don’t save"); DialogButtonBox.buttonRole: DialogButtonBox.DestructiveRole }
            Button { text: qsTr("Cancel"); DialogButtonBox.buttonRole: DialogButtonBox.RejectRole }
        }
        Label {
            width: parent ? parent.width : 0
            wrapMode: Text.Wrap
            text: qsTr("“%1” has changes that are not saved. Save them first?").arg(files.displayName)
        }
        onAccepted: {
            const action = root.afterUnsaved
            root.afterUnsaved = null
            root.saveThen(action ?? (() => {}))
        }
        onDiscarded: {
            const action = root.afterUnsaved
            root.afterUnsaved = null
            close()
            editor.markSaved()
            if (action)
                action()
        }
        onRejected: root.afterUnsaved = null
    }
    Dialog {
        id: recoveryDialog
        objectName: "recoveryDialog"
        title: qsTr("Recover unsaved work")
        modal: true
        Material.elevation: root.softwareRendering ? 0 : 24
        anchors.centerIn: parent
        width: Math.min(root.width * 0.9, 460)
        footer: DialogButtonBox { // Kontur's own buttons: see unsavedDialog
            Button { text: qsTr("Recover"); DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole }
            Button { text: qsTr("Discard"); DialogButtonBox.buttonRole: DialogButtonBox.DestructiveRole }
        }
        Label {
            width: parent ? parent.width : 0
            wrapMode: Text.Wrap
            text: qsTr("Kontur was not closed properly last time. Recover the unsaved work?")
        }
        onAccepted: files.recover()
        onDiscarded: { files.discardRecovery(); close() }
    }

    FileDialog {
        id: backgroundDialog
        title: qsTr("Load background image")
        nameFilters: [qsTr("Images (*.png *.jpg *.jpeg *.bmp *.gif *.webp)"), qsTr("All files (*)")]
        onAccepted: editor.loadBackground(selectedFile)
    }

    Dialog {
        id: resetDialog
        objectName: "resetDialog"
        title: qsTr("Reset all")
        modal: true
        Material.elevation: root.softwareRendering ? 0 : 24
        anchors.centerIn: parent
        width: Math.min(root.width * 0.9, 460)
        footer: DialogButtonBox { // Kontur's own buttons: see unsavedDialog
            Button { text: qsTr("Yes"); DialogButtonBox.buttonRole: DialogButtonBox.YesRole }
            Button { text: qsTr("No"); DialogButtonBox.buttonRole: DialogButtonBox.NoRole }
        }
        Label {
            width: parent ? parent.width : 0
            wrapMode: Text.Wrap
            text: editor.resetQuestion
        }
        onAccepted: editor.resetAll()
    }

    // Teaching pages over the window: seed 001's function splines and Runge, seed 003's segments.
    FunctionSplineView { id: functionSplineView }
    PracticumView { id: practicumView }
}
