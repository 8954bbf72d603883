// TraceOverlay: the tracing tools over the canvas (issue #10): the C++ TracePainter draws the stroke
// and the marks and takes the tools' input (two fingers fall through to the canvas's PinchHandler);
// the result of a measure, seam or deviation is written next to its mark, as TraceController writes
// it (the UI language's number format with the document's unit).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Item {
    id: overlay

    required property CurveCanvas canvas
    required property TraceController trace

    // After a calibration the picture stays where it was on the screen.
    Connections {
        target: overlay.trace
        function onWorldMapped(scale, radians) { overlay.canvas.followWorldMapping(scale, radians) }
    }

    TracePainter {
        id: painter
        objectName: "tracePainter"
        anchors.fill: parent
        canvas: overlay.canvas
        trace: overlay.trace
        lineWidth: Theme.curveWidth
        palmDiameter: 2 * Theme.pointTarget
    }

    Rectangle {
        id: label
        objectName: "traceLabel"
        visible: overlay.trace.hasLabel
        // Follows the view: the anchor is in world coordinates.
        readonly property point at: (overlay.canvas.zoom, overlay.canvas.center,
                                     overlay.canvas.toScreen(overlay.trace.labelAnchor))
        x: Math.max(0, Math.min(overlay.width - width, at.x + 12))
        y: Math.max(0, Math.min(overlay.height - height, at.y - height - 12))
        width: labelText.implicitWidth + Theme.spacing
        height: labelText.implicitHeight + Theme.spacing / 2
        radius: 4
        color: "#e6ffffff"
        border.color: "#c9d0da"
        Label {
            id: labelText
            objectName: "traceLabelText"
            anchors.centerIn: parent
            text: {
                const t = overlay.trace
                switch (t.tool) {
                case TraceController.Measure: return t.measure.distanceText
                //: Label on the canvas: %1 is the seam length with its unit, for example “412,50 mm”.
                case TraceController.Seam: return qsTr("seam %1").arg(t.seam.lengthText)
                //: Label on the canvas: the largest deviation from the reference curve, %1 a length with its unit.
                case TraceController.Deviation: return qsTr("max %1").arg(t.deviation.maximumText)
                //: %1 is a distance in pixels of the background picture (a number).
                case TraceController.Calibrate: return qsTr("%1 px on the picture").arg(t.calibration.imageDistanceText)
                }
                return ""
            }
        }
    }
}
