// CanvasView: the drawing surface with its gestures. It only forwards them to the C++ canvas,
// which turns them into world coordinates and hands them to the EditController.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

CurveCanvas {
    id: canvas

    // While a menu is open over the canvas, presses on it are the menu's: Qt 6.4 still lets a tap
    // handler under an open popup answer now and then, which placed a point where a menu item was
    // clicked.
    property bool menuOpen: false
    // How much of the canvas's bottom the panel's sheet covers: no gesture of the canvas starts there.
    // (Qt 6 offers a press that an item on top accepted to the pointer handlers under it as well; a
    // handler only sees points inside its parent, so the handlers live in the uncovered part.)
    property real coveredBottom: 0

    clip: true
    hitRadius: Theme.pointTarget / 2
    curveColor: Theme.curve
    polygonColor: Theme.controlPolygon
    controlPointColor: Theme.controlPoint
    accentColor: Theme.accent
    tangentColor: Theme.tangentEnd
    gridColor: Theme.grid
    axisColor: Theme.axis
    curveWidth: Theme.curveWidth
    pointRadius: Theme.pointRadius

    // On a GPU the window's colour is the background (Main.qml): a rectangle over it would cost a
    // fill of the whole canvas every frame, which a software rasterizer such as llvmpipe feels. A
    // grab of the canvas alone (the PNG export, with the layer off) needs it, and so does Qt Quick's
    // software backend, which repaints only what changed and leaves stray pixels (a button's ripple
    // drawn out of place) on a canvas without a background of its own.
    Rectangle {
        anchors.fill: parent
        z: -1
        visible: !canvas.layered || canvas.graphicsApi === "software"
        color: Theme.canvasBackground
    }

    // The grid's step, so that distances can be read off it.
    Label {
        objectName: "gridLabel"
        visible: canvas.showGrid
        anchors.left: parent.left
        anchors.bottom: parent.bottom
        anchors.margins: 6
        color: Theme.mutedText
        font.pixelSize: Theme.smallFontSize
        //: %1 is the grid spacing in the document's units (a number).
        text: qsTr("grid %1").arg(Numbers.significant(canvas.gridStep, 6, Language.current))
    }

    Item {
        id: input
        objectName: "canvasInput"
        width: canvas.width
        height: Math.max(0, canvas.height - canvas.coveredBottom)

        // A tap (finger, stylus or left click) places a point or picks one, depending on the mode.
        TapHandler {
            objectName: "canvasTap"
            enabled: !canvas.menuOpen
            gesturePolicy: TapHandler.DragThreshold
            // A finger that rests a while before it lifts still taps (the canvas has no long press):
            // points are placed deliberately, and a busy machine can stretch a quick tap too.
            longPressThreshold: 10
            onTapped: (eventPoint) => canvas.tapAt(eventPoint.position)
        }

        // One finger or a mouse button: drags a point, or pans when it starts on empty canvas. The right
        // button or Shift asks for the seed's constrained handle move.
        DragHandler {
            id: dragHandler
            target: null
            minimumPointCount: 1
            maximumPointCount: 1
            acceptedButtons: Qt.LeftButton | Qt.RightButton
            onActiveChanged: {
                if (active)
                    canvas.dragStarted(centroid.pressPosition,
                                       (centroid.pressedButtons & Qt.RightButton) !== 0
                                       || (centroid.modifiers & Qt.ShiftModifier) !== 0)
                else
                    canvas.dragEnded()
            }
            onCentroidChanged: {
                if (active)
                    canvas.dragMoved(centroid.position)
            }
        }

        // Two fingers: zoom about their centroid and pan with it.
        PinchHandler {
            target: null
            minimumPointCount: 2
            maximumPointCount: 2
            onActiveChanged: {
                // The content under the fingers when they touched down stays under them.
                if (active)
                    canvas.pinchStarted(centroid.pressPosition)
                else
                    canvas.pinchEnded()
            }
            // Qt >= 6.5: persistentScale / activeScaleChanged; 6.4 reports every step with updated().
            onUpdated: {
                if (active)
                    canvas.pinchUpdated(activeScale, centroid.position)
            }
        }

        // The mouse wheel zooms about the cursor.
        WheelHandler {
            target: null
            acceptedDevices: PointerDevice.Mouse | PointerDevice.TouchPad
            onWheel: (event) => canvas.wheelAt(point.position, event.angleDelta.y)
        }

        // The rubber band follows a hovering mouse or stylus.
        HoverHandler {
            onPointChanged: {
                if (hovered)
                    canvas.hoverAt(point.position)
            }
            onHoveredChanged: {
                if (!hovered)
                    canvas.hoverEnded()
            }
        }
    }
}
