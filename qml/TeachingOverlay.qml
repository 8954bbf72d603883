// TeachingOverlay: what the teaching views draw over the canvas (through the C++ TeachingPainter),
// their gestures — the B(t) marker dragged along the curve, Alt+click or a long press to add or
// remove a control point in the elevation view. (The legend of the compared curves is in the
// teaching bar.)
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Item {
    id: overlay

    required property CurveCanvas canvas
    required property TeachingController teaching
    required property EditController editor

    visible: teaching.view !== TeachingController.None

    TeachingPainter {
        objectName: "teachingPainter"
        anchors.fill: parent
        canvas: overlay.canvas
        teaching: overlay.teaching
        levelColors: Theme.teachingLevels
        palette: Theme.comparePalette
        markerColor: Theme.teachingMarker
        halfColor: Theme.teachingHalf
        elevatedColor: Theme.teachingElevated
        combColor: Theme.teachingComb
        jointColor: Theme.teachingJoint
        weakJointColor: Theme.teachingWeakJoint
        labelBackground: Theme.teachingLabelBackground
        lineWidth: Theme.curveWidth
        pointRadius: Theme.pointRadius
        fontPixelSize: Theme.teachingFontSize
    }

    readonly property bool elevationEdits: teaching.view === TeachingController.Elevation && teaching.isBezier
                                           && editor.mode === EditController.Select

    // Alt+click adds a control point on empty canvas or removes the one clicked (seed 002's demo).
    // It takes the press for itself, so the canvas does not also pick or pan.
    TapHandler {
        enabled: overlay.elevationEdits
        acceptedModifiers: Qt.AltModifier
        gesturePolicy: TapHandler.WithinBounds
        onTapped: (eventPoint) => overlay.teaching.toggleControlPoint(overlay.canvas.toWorld(eventPoint.position),
                                                                       overlay.canvas.hitRadiusWorld())
    }
    // The same by a long press, for fingers.
    TapHandler {
        enabled: overlay.elevationEdits
        acceptedModifiers: Qt.NoModifier
        onLongPressed: overlay.teaching.toggleControlPoint(overlay.canvas.toWorld(point.position),
                                                           overlay.canvas.hitRadiusWorld())
    }

    // The point B(t): drag it along the curve to change t (a 44 px target around the dot).
    Item {
        id: marker
        objectName: "teachingMarker"
        visible: overlay.teaching.view === TeachingController.DeCasteljau && overlay.teaching.applicable
        // toScreen depends on the view and on the canvas's size.
        readonly property point at: overlay.canvas.zoom, overlay.canvas.center, overlay.canvas.width,
                                    overlay.canvas.height, overlay.canvas.toScreen(overlay.teaching.curvePoint)
        x: at.x - width / 2
        y: at.y - height / 2
        width: Theme.pointTarget
        height: Theme.pointTarget
        DragHandler {
            target: null
            // Once it moves the marker, the canvas may not take the drag over to pan.
            grabPermissions: PointerHandler.CanTakeOverFromAnything
            onCentroidChanged: {
                if (active)
                    overlay.teaching.dragMarkerTo(
                        overlay.canvas.toWorld(overlay.canvas.mapFromItem(null, centroid.scenePosition)))
            }
        }
        HoverHandler { cursorShape: Qt.SizeAllCursor }
    }
}
