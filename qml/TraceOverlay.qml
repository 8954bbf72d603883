// TraceOverlay: the tracing tools over the canvas (issue #10): the C++ TracePainter draws the stroke
// and the marks and takes the tools' input; the result of a measure, seam or deviation is written
// next to its mark, in the UI language's number format with the document's unit.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Item {
    id: overlay

    required property CurveCanvas canvas
    required property TraceController trace

    readonly property var locale: Qt.locale(Language.current)

    // Numbers as the UI shows them: enough decimals for the unit (0.01 mm, 0.001 cm or in).
    function length(value) {
        const u = trace.units
        const decimals = u === "mm" ? 2 : (u === "cm" || u === "in") ? 3 : 1
        return qsTr("%1 %2").arg(Number(value).toLocaleString(locale, "f", decimals)).arg(u)
    }

    // After a calibration the picture stays where it was on the screen.
    Connections {
        target: overlay.trace
        function onWorldMapped(scale, radians) {
            const c = overlay.canvas.center
            const x = scale * (Math.cos(radians) * c.x - Math.sin(radians) * c.y)
            const y = scale * (Math.sin(radians) * c.x + Math.cos(radians) * c.y)
            overlay.canvas.restoreView(overlay.canvas.zoom / scale, Qt.point(x, y))
        }
    }

    TracePainter {
        id: painter
        objectName: "tracePainter"
        anchors.fill: parent
        canvas: overlay.canvas
        trace: overlay.trace
        lineWidth: Theme.curveWidth
        palmDiameter: 2 * Theme.touchTarget
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
                Language.current
                const t = overlay.trace
                switch (t.tool) {
                case TraceController.Measure: return overlay.length(t.measureDistance)
                case TraceController.Seam: return qsTr("seam %1").arg(overlay.length(t.seamLength))
                case TraceController.Deviation: return qsTr("max %1").arg(overlay.length(t.deviationMaximum))
                case TraceController.Calibrate:
                    return qsTr("%1 px on the picture").arg(Number(t.calibrationImageDistance).toLocaleString(overlay.locale, "f", 1))
                }
                return ""
            }
        }
    }
}
