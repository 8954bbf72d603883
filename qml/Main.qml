// Main: the application window — its controllers, the layout (tool bar, canvas with its overlays,
// teaching and trace bars, basis plot, hint line) and the side panel, and the wiring between them.
// The side panel is one Drawer: docked beside the canvas on wide windows (as Qt's sidepanel
// example), slid in from the right by the Panel button on narrow ones.
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
    readonly property bool narrow: width < 720
    // Wide windows show the side panel beside the canvas while the Panel button is on.
    readonly property bool panelDocked: !narrow && panelOpen
    // The tool bar's panel toggle shows or hides the side panel.
    property bool panelOpen: true
    readonly property bool placing: editor.mode === EditController.Place

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
    FileActions {
        id: fileActions
        objectName: "fileActions"
        editor: editor
        files: files
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
        // Narrow windows show the panel as a drawer, which the toggle opens.
        onPanelToggleRequested: {
            if (root.narrow)
                panelDrawer.open()
            else
                root.panelOpen = !root.panelOpen
        }
        onFunctionSplineRequested: functionSplineView.openSpline()
        onRungeRequested: functionSplineView.openRunge()
        onPracticumRequested: practicumView.open()
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
            Layout.fillWidth: true
            Layout.fillHeight: true
            // The docked panel lies over the window's right edge: the canvas ends where it begins.
            Layout.rightMargin: root.panelDocked ? panelDrawer.width : 0

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
                    for (const url of drop.urls)
                        fileActions.openDropped(url)
                    drop.accept()
                }
            }

            // Refusals and problems as a banner over the canvas; it does not block anything.
            MessageBanner {
                objectName: "messageBanner"
                editor: editor
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

        // The basis functions of the selected curve, under the canvas; its t is the de Casteljau view's.
        BasisPlotPanel {
            id: basisPanel
            objectName: "basisPanel"
            visible: toolBar.showBasis
            editor: editor
            Layout.fillWidth: true
            Layout.preferredHeight: expanded ? Math.min(270, root.height * 0.32) : implicitHeight
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

    // The side panel. Docked (wide windows, Panel on): open, not modal, not draggable, beside the
    // canvas and as tall as it, closed by nothing but the Panel button. Otherwise an ordinary modal
    // drawer over the whole window, opened by the Panel button on narrow windows.
    Drawer {
        id: panelDrawer
        objectName: "panelDrawer"
        edge: Qt.RightEdge
        y: root.panelDocked ? toolBar.height : 0
        width: root.panelDocked ? Theme.panelWidth : Math.min(root.width * 0.85, Theme.panelWidth + 60)
        // Docked, the panel itself meets the canvas (the style's one-pixel divider column would take
        // a pixel from one of them).
        leftPadding: root.panelDocked ? 0 : undefined
        height: root.panelDocked ? canvas.height : root.height
        modal: !root.panelDocked
        interactive: root.narrow
        position: root.panelDocked ? 1 : 0
        visible: root.panelDocked
        // A popup that closes on Esc or an outside press keeps shortcuts from everything outside it.
        closePolicy: root.panelDocked ? Popup.NoAutoClose : Popup.CloseOnEscape | Popup.CloseOnPressOutside

        SidePanel {
            objectName: "sidePanel"
            anchors.fill: parent
            editor: editor
            onLoadBackgroundRequested: fileActions.loadBackground()
        }
    }

    // Teaching pages over the window: seed 001's function splines and Runge, seed 003's segments.
    FunctionSplineView { id: functionSplineView }
    PracticumView { id: practicumView }
}
