// CanvasView in QML: taps place points, a drag on empty canvas pans, the view transform has y up.
import QtQuick
import QtTest
import Kontur
import Kontur.Models

Item {
    id: root
    width: 400
    height: 300

    EditController { id: editor }
    CanvasView {
        id: canvas
        anchors.fill: parent
        controller: editor
    }

    TestCase {
        name: "CanvasView"
        when: windowShown

        function init() {
            editor.mode = EditController.Select
            canvas.resetView()
        }

        // The geometry's enumerations reach QML by name (Q_ENUM_NS), with the geometry's values.
        function test_enumerationsByName() {
            compare(CurveKind.Bezier, 0)
            compare(CurveKind.Composite, 3)
            compare(CurveKind.FunctionSpline, 13)
            compare(NodeType.Corner, 2)
            compare(Parameterization.ChordLength, 1)
        }

        // The selection is read through its properties; a tap on the placed curve's first point selects it.
        function test_selectionFollowsATap() {
            editor.startPlacing(CurveKind.Bezier)
            for (const p of [Qt.point(60, 60), Qt.point(120, 40), Qt.point(200, 40), Qt.point(260, 60)])
                mouseClick(canvas, p.x, p.y)
            editor.mode = EditController.Select
            editor.selection.clear()
            compare(editor.selection.hasCurve, false)
            mouseClick(canvas, 60, 60)
            compare(editor.selection.hasCurve, true)
            compare(editor.selection.point, 0)
            compare(editor.selection.knot, 0)
            compare(editor.selection.curveRow, editor.curves.rowCount() - 1)
            compare(editor.selection.nodeType, -1)
            editor.commands.deleteCurve(editor.selection.curveId)
            compare(editor.selection.hasCurve, false)
        }

        function test_touchTargetsAreTouchSized() {
            verify(Theme.pointTarget >= 44)
            compare(canvas.hitRadius * 2, Theme.pointTarget)
        }

        function test_worldHasYUpAndRoundTrips() {
            const upper = canvas.toWorld(Qt.point(200, 100))
            const lower = canvas.toWorld(Qt.point(200, 200))
            verify(upper.y > lower.y)
            const centre = canvas.toWorld(Qt.point(200, 150))
            fuzzyCompare(centre.x, canvas.center.x, 1e-9)
            fuzzyCompare(centre.y, canvas.center.y, 1e-9)
            const back = canvas.toScreen(canvas.toWorld(Qt.point(37, 251)))
            fuzzyCompare(back.x, 37, 1e-9)
            fuzzyCompare(back.y, 251, 1e-9)
        }

        function test_tapsPlaceACurve() {
            const before = editor.document.curveCount
            editor.mode = EditController.Place
            mouseClick(canvas, 40, 250)
            mouseClick(canvas, 100, 40)
            compare(editor.placement.pendingCount, 2)
            mouseClick(canvas, 300, 40)
            mouseClick(canvas, 360, 250)
            compare(editor.placement.pendingCount, 0)
            compare(editor.document.curveCount, before + 1)
            compare(editor.curves.rowCount(), before + 1)
            compare(editor.points.rowCount(), 4)
        }

        function test_fingerTapsPlacePoints() {
            editor.mode = EditController.Place
            const before = editor.placement.pendingCount
            let touch = touchEvent(canvas)
            touch.press(0, canvas, 100, 100).commit()
            touch.release(0, canvas, 100, 100).commit()
            compare(editor.placement.pendingCount, before + 1)
            editor.placement.cancel()
        }

        function test_dragOnEmptyCanvasPans() {
            const zoom = canvas.zoom
            // A copy: in Qt 6.4 a value-type property read into a variable still follows the property.
            const start = Qt.point(canvas.center.x, canvas.center.y)
            // Start far from every point; the drag handler needs to pass its threshold first.
            mouseDrag(canvas, 200, 150, 60, 40)
            tryVerify(() => !canvas.panning)
            // The world point under the pointer moved with it: the view went the other way.
            fuzzyCompare(canvas.center.x, start.x - 60 / zoom, 1e-6)
            fuzzyCompare(canvas.center.y, start.y + 40 / zoom, 1e-6)
        }

        function test_dragWhilePlacingDoesNotPan() {
            editor.mode = EditController.Place
            const start = Qt.point(canvas.center.x, canvas.center.y)
            mouseDrag(canvas, 200, 150, 60, 40)
            compare(canvas.center.x, start.x)
            compare(canvas.center.y, start.y)
            compare(editor.placement.pendingCount, 0)
        }
    }
}
