// TraceMenu: the "Trace" tool group of the toolbar (issue #10): freehand tracing, calibration of the
// background, measure, seam length, deviation, snapping and the background lock. The keys T, K, M,
// L, D and S (in TraceBar) do the same.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur.Models

ToolbarMenu {
    id: menu

    required property TraceController trace

    function toggle(tool) {
        trace.tool = trace.tool === tool ? TraceController.None : tool
    }

    MenuItem {
        objectName: "traceFreehand"
        text: qsTr("Freehand (T)")
        checkable: true
        checked: menu.trace.tool === TraceController.Freehand
        onTriggered: menu.toggle(TraceController.Freehand)
    }
    MenuItem {
        objectName: "traceCalibrate"
        text: qsTr("Calibrate background (K)")
        checkable: true
        checked: menu.trace.tool === TraceController.Calibrate
        onTriggered: menu.toggle(TraceController.Calibrate)
    }
    MenuItem {
        objectName: "traceMeasure"
        text: qsTr("Measure distance (M)")
        checkable: true
        checked: menu.trace.tool === TraceController.Measure
        onTriggered: menu.toggle(TraceController.Measure)
    }
    MenuItem {
        objectName: "traceSeam"
        text: qsTr("Seam length between knots (L)")
        checkable: true
        checked: menu.trace.tool === TraceController.Seam
        onTriggered: menu.toggle(TraceController.Seam)
    }
    MenuItem {
        objectName: "traceDeviation"
        text: qsTr("Deviation from a reference (D)")
        checkable: true
        checked: menu.trace.tool === TraceController.Deviation
        onTriggered: menu.toggle(TraceController.Deviation)
    }
    MenuItem {
        objectName: "traceMoveBackground"
        text: qsTr("Move background (O)")
        checkable: true
        enabled: menu.trace.editor && menu.trace.editor.background.file.length > 0
        checked: menu.trace.tool === TraceController.MoveBackground
        onTriggered: menu.toggle(TraceController.MoveBackground)
    }
    MenuSeparator {}
    MenuItem {
        objectName: "traceSnap"
        text: qsTr("Snap to knots, grid and marks (S)")
        checkable: true
        checked: menu.trace.snapping
        onTriggered: menu.trace.snapping = !menu.trace.snapping
    }
    MenuItem {
        objectName: "traceLock"
        text: qsTr("Lock background")
        checkable: true
        enabled: menu.trace.editor && menu.trace.editor.background.file.length > 0
        checked: menu.trace.backgroundLocked
        onTriggered: menu.trace.backgroundLocked = !menu.trace.backgroundLocked
    }
}
