// BottomSheet: the side panel as a sheet over the bottom of the canvas, on portrait and narrow
// windows. Its handle drags it (finger or mouse) between three heights where it snaps: peek (the
// first part of the panel: the selected curve and its most used controls), half and full. A tap on
// the handle raises it a step (from full, back to peek); the handle takes the keyboard focus (Up and
// Down raise and lower, Space and Enter as a tap). Dragged below half its peek it goes away, and the
// window's panel toggle brings it back. Its content scrolls inside it.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur

Item {
    id: sheet

    // Heights from the sheet's bottom edge up, handle included. The window gives the full height
    // (what leaves the canvas its share); peek and half never pass it.
    property real peekHeight: 160
    property real fullHeight: 400
    readonly property real peekStop: Math.min(peekHeight, fullHeight)
    readonly property real halfStop: (peekStop + fullHeight) / 2
    // Shown at one of its stops, or gone below the edge.
    property bool open: true
    // The stop it rests at: 0 peek, 1 half, 2 full.
    property int stop: 0
    readonly property real stopHeight: stop === 2 ? fullHeight : stop === 1 ? halfStop : peekStop
    // While the handle is dragged the sheet follows the pointer.
    property bool dragging: false
    // How much of the canvas it covers now (0 when gone).
    readonly property real shownHeight: height
    // Where the window puts the panel's content.
    readonly property Item contentArea: area
    readonly property real handleHeight: Theme.touchMinimum

    // Dragged or stepped below the peek: the window closes the panel.
    signal closeRequested()
    // Lowered to the peek: the content scrolls back to its first part.
    signal lowered()

    function setStop(index) {
        stop = Math.max(0, Math.min(2, index))
        if (stop === 0)
            lowered()
    }
    function raise() { setStop(stop + 1) }
    function lower() {
        if (stop === 0)
            closeRequested()
        else
            setStop(stop - 1)
    }
    // A tap on the handle: a step up, and from full back down to peek.
    function step() { setStop(stop === 2 ? 0 : stop + 1) }
    // Let go after a drag: to the nearest stop, or away when below half the peek.
    function settle() {
        const h = dragged
        dragging = false
        if (h < peekStop / 2) {
            closeRequested()
            return
        }
        const stops = [peekStop, halfStop, fullHeight]
        let best = 0
        for (let i = 1; i < stops.length; ++i)
            if (Math.abs(stops[i] - h) < Math.abs(stops[best] - h))
                best = i
        setStop(best)
    }

    property real dragStart: 0
    property real dragged: 0
    height: !open ? 0 : dragging ? dragged : stopHeight
    clip: true
    Behavior on height {
        enabled: !sheet.dragging
        NumberAnimation { duration: 150; easing.type: Easing.OutCubic }
    }
    onOpenChanged: if (open) setStop(0)

    // Presses, touches and wheel turns on the sheet are the sheet's: none reaches the canvas under it.
    // A touch is taken as a touch (a MouseArea would only see it turned into a mouse press, while
    // the canvas's pointer handlers underneath could still take part in it); the wheel apart.
    MultiPointTouchArea {
        anchors.fill: parent
        mouseEnabled: true
    }
    MouseArea {
        anchors.fill: parent
        acceptedButtons: Qt.NoButton
        onWheel: (wheel) => wheel.accepted = true
    }

    Rectangle {
        anchors.fill: parent
        color: Theme.panelBackground
        // The sheet's top edge, a line against the canvas.
        Rectangle {
            width: parent.width
            height: 1
            color: Theme.toolbarBorder
        }
    }

    Item {
        id: handle
        objectName: "sheetHandle"
        width: parent.width
        height: sheet.handleHeight
        activeFocusOnTab: true
        Accessible.role: Accessible.Button
        Accessible.name: qsTr("Panel size: tap to show more, drag to resize")
        Accessible.onPressAction: sheet.step()
        // The window's shortcuts (arrow keys nudge points, Enter finishes a curve) give way while the
        // handle has the focus.
        Keys.onShortcutOverride: (event) => event.accepted = event.modifiers === Qt.NoModifier
                                 && [Qt.Key_Up, Qt.Key_Down, Qt.Key_Space, Qt.Key_Return, Qt.Key_Enter].includes(event.key)
        Keys.onUpPressed: sheet.raise()
        Keys.onDownPressed: sheet.lower()
        Keys.onSpacePressed: sheet.step()
        Keys.onReturnPressed: sheet.step()
        Keys.onEnterPressed: sheet.step()

        // The grip: a short rounded bar, accent-coloured while the handle has the keyboard focus.
        Rectangle {
            anchors.centerIn: parent
            width: 40
            height: 5
            radius: 2.5
            color: handle.activeFocus ? Theme.accent : Theme.controlPolygon
        }

        // A finger or the mouse: a move past the drag threshold drags the sheet, which follows the
        // pointer and snaps when let go; a press without a move is a tap. A MultiPointTouchArea takes
        // touches as touches (a MouseArea would depend on Qt's touch-to-mouse synthesis, which follows
        // one touch at a time) and the mouse as one more touch point; the press stops here, never
        // reaching the canvas under the handle.
        MultiPointTouchArea {
            id: handleArea
            property real pressY: 0
            anchors.fill: parent
            maximumTouchPoints: 1
            mouseEnabled: true
            // The pointer's height in the window, steady while the handle moves under it.
            function windowY(point) { return handleArea.mapToItem(null, 0, point.y).y }
            onPressed: (points) => {
                pressY = windowY(points[0])
                sheet.dragStart = sheet.height
                sheet.dragged = sheet.height
            }
            onUpdated: (points) => {
                const moved = pressY - windowY(points[0])
                if (!sheet.dragging && Math.abs(moved) < Qt.styleHints.startDragDistance)
                    return
                sheet.dragging = true
                sheet.dragged = Math.max(0, Math.min(sheet.fullHeight, sheet.dragStart + moved))
            }
            onReleased: {
                if (sheet.dragging)
                    sheet.settle()
                else
                    sheet.step()
            }
            onCanceled: if (sheet.dragging) sheet.settle()
        }
    }

    // The panel's content, below the handle; it scrolls inside this.
    Item {
        id: area
        objectName: "sheetContent"
        y: sheet.handleHeight
        width: parent.width
        height: Math.max(0, sheet.height - sheet.handleHeight)
    }
}
