// PointBar: the selected knot's commands over the canvas, for touch (Make line, Delete knot, the node
// types, Close): the registry's actions as buttons of Theme.touchMinimum, shown while a knot or handle
// of a composite curve is selected and the canvas edits points.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import Kontur
import Kontur.Models

Pane {
    id: bar

    required property AppActions actions
    // Whether the canvas edits points now (no placement, no trace tool).
    property bool editing: true
    // The widest the bar may be: its buttons wrap to a second row beyond this.
    property real maximumWidth: 480

    visible: editing && actions.pieceEdits.canEditKnot
    padding: Theme.spacing / 4
    background: Rectangle {
        color: Theme.toolbar
        border.color: Theme.toolbarBorder
        radius: 6
    }

    contentWidth: flow.childrenRect.width
    contentHeight: flow.childrenRect.height

    Flow {
        id: flow
        width: bar.maximumWidth - 2 * bar.padding
        spacing: 0
        Repeater {
            model: ["pieceMakeLine", "pieceDeleteKnot", "pieceSmooth", "pieceCorner", "pieceClose"]
            delegate: ToolButton {
                required property string modelData
                objectName: "pointBar_" + modelData
                action: bar.actions.pieceActions[modelData]
                Accessible.name: action ? action.text : ""
                height: Theme.touchMinimum
                width: Math.max(Theme.touchMinimum, implicitWidth)
                display: AbstractButton.TextOnly
            }
        }
    }
}
