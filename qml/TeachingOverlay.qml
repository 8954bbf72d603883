// TeachingOverlay: what the teaching views draw over the canvas (through the C++ TeachingPainter),
// their gestures — the B(t) marker dragged along the curve, Alt+click or a long press to add or
// remove a control point in the elevation view — and the legend of the compared curves.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
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

    // The legend of the compared curves; each entry shows or hides its curve.
    Rectangle {
        objectName: "compareLegend"
        visible: overlay.teaching.view === TeachingController.Compare && legendColumn.children.length > 1
        anchors.left: parent.left
        anchors.bottom: parent.bottom
        anchors.leftMargin: Theme.spacing
        anchors.bottomMargin: Theme.spacing + 24 // above the grid's step
        width: legendColumn.implicitWidth + 2 * Theme.spacing
        height: legendColumn.implicitHeight + Theme.spacing
        radius: 6
        color: Theme.teachingLabelBackground
        border.color: Theme.toolbarBorder
        // In as many columns as it takes to leave most of the canvas free.
        Grid {
            id: legendColumn
            anchors.centerIn: parent
            flow: Grid.TopToBottom
            rows: Math.max(1, Math.floor(overlay.height * 0.4 / Theme.touchMinimum))
            columnSpacing: Theme.spacing
            Repeater {
                // The names are translated: the legend is announced again on a language switch.
                model: overlay.teaching.legend
                CheckBox {
                    id: entry
                    required property var modelData
                    required property int index
                    objectName: "legendEntry" + index
                    checked: modelData.shown
                    enabled: modelData.available
                    text: modelData.available ? modelData.name : qsTr("%1 (not possible for these points)").arg(modelData.name)
                    font.pixelSize: Theme.teachingFontSize
                    onToggled: overlay.teaching.setCompareShown(index, checked)
                    indicator.opacity: 0.9
                    contentItem: RowLayout {
                        spacing: Theme.spacing / 2
                        Rectangle {
                            Layout.leftMargin: entry.indicator.width + entry.spacing
                            width: 24 * Theme.scale
                            height: 4 * Theme.scale
                            color: Theme.comparePalette[entry.modelData.palette % Theme.comparePalette.length]
                        }
                        Label {
                            text: entry.text
                            font: entry.font
                            color: entry.enabled ? Theme.toolbarText : Theme.mutedText
                        }
                    }
                }
            }
        }
    }
}
