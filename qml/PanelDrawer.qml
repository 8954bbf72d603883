// PanelDrawer: the side panel's drawer at the window's right edge. Beside the canvas (wide desktops,
// and a pinned drawer on landscape tablets) it is open, not modal, not draggable and as tall as the
// canvas, as Qt's sidepanel example; otherwise it slides over the whole window, modal, closed by Esc
// or a press outside. On landscape tablets its header has a pin button. The window says which, and
// opens and closes it (show()).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur

Drawer {
    id: drawer

    // Beside the canvas (docked or pinned), or over it.
    property bool beside: true
    // Whether the panel is wanted at all (the window's panel toggle).
    property bool wanted: true
    // The drawer is the panel's place in this layout (not the bottom sheet's).
    property bool used: true
    // A pin button in the header: on landscape tablets.
    property bool pinnable: false
    property bool pinned: false
    // Where the window puts the panel's content.
    readonly property Item contentArea: area

    signal pinToggled()

    // Opened or closed as the window's state asks (after its bindings have settled).
    function show() {
        const wasBeside = shownBeside
        shownBeside = used && beside
        if (!used) // a modal drawer sliding out while the window turns would block the sheet's input
            withoutSlide(() => close())
        else if (beside) // a column beside the canvas, as in Qt's sidepanel example
            withoutSlide(() => { open(); position = 1 })
        else if (wanted)
            open()
        else if (wasBeside) // the column goes as it came, at once: sliding, it would lie over the tool bar
            withoutSlide(() => close())
        else
            close()
    }
    // Shown as a column beside the canvas by the last show().
    property bool shownBeside: false
    // Runs `change` at once, without the slide in or out (a slide would also keep the window drawing
    // frames while the canvas is used).
    function withoutSlide(change) {
        const slideIn = enter, slideOut = exit
        enter = null
        exit = null
        change()
        enter = slideIn
        exit = slideOut
    }
    onBesideChanged: Qt.callLater(show)
    onWantedChanged: Qt.callLater(show)
    onUsedChanged: Qt.callLater(show)

    edge: Qt.RightEdge
    // Modal only while it is wanted over the canvas: sliding away (hidden from the tool bar, or a
    // docked column hidden) it must not take the next tap meant for the tool bar, such as the toggle
    // that brings it back.
    modal: used && !beside && wanted
    interactive: used && !beside
    // Beside the canvas the panel itself meets the canvas (the style's one-pixel divider column
    // would take a pixel from one of them).
    leftPadding: beside ? 0 : undefined
    topPadding: 0
    bottomPadding: 0
    // A popup that closes on Esc or an outside press keeps shortcuts from everything outside it.
    closePolicy: beside ? Popup.NoAutoClose : Popup.CloseOnEscape | Popup.CloseOnPressOutside
    // Over the canvas it lies under the tool bar (the window sets y), so the bar's Side panel button
    // stays in sight. Qt sizes a right-edge drawer's dimmer to the drawer's own rows and closes on an
    // outside press only inside the dimmer, while the modal drawer blocks the whole window: the bar
    // would be dead. The dimmer answers "inside" everywhere, so a press on the bar (on the Side panel
    // button too) puts the drawer away, as a press on the canvas does.
    Overlay.modal: Rectangle {
        color: drawer.Material.backgroundDimColor
        containmentMask: QtObject {
            function contains(point: point): bool { return true }
        }
    }

    // The style's background is an item layer with a shadow effect, drawn again with every frame of
    // the canvas beside it: on Mesa's llvmpipe that was about a sixth of each pinch-zoom frame. A plain
    // panel with a shadow of its own (a gradient, only while it lies over the canvas) looks the same.
    background: Rectangle {
        color: Theme.panelBackground
        Rectangle {
            visible: !drawer.beside
            anchors.right: parent.left
            width: 12
            height: parent.height
            gradient: Gradient {
                orientation: Gradient.Horizontal
                GradientStop { position: 0; color: "#00000000" }
                GradientStop { position: 1; color: "#38000000" }
            }
        }
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 0
        // What a screen reader announces as the drawer opens.
        Accessible.role: Accessible.Pane
        Accessible.name: qsTr("Curves and settings")

        // The header: what this is, and the pin.
        Rectangle {
            visible: drawer.pinnable
            Layout.fillWidth: true
            Layout.preferredHeight: Theme.touchMinimum
            color: Theme.panelBackground
            RowLayout {
                anchors.fill: parent
                anchors.leftMargin: Theme.spacing
                spacing: 0
                Label {
                    Layout.fillWidth: true
                    text: qsTr("Curves and settings")
                    font.bold: true
                    elide: Text.ElideRight
                }
                ToolButton {
                    objectName: "pinButton"
                    Layout.preferredHeight: Theme.touchMinimum
                    text: drawer.pinned
                          //: Button (verb): let the side panel slide over the canvas instead of staying beside it.
                          ? qsTr("Unpin")
                          //: Button (verb): keep the side panel open beside the canvas.
                          : qsTr("Pin")
                    // Shown pressed while pinned; the window holds the state.
                    checked: drawer.pinned
                    Accessible.role: Accessible.Button
                    Accessible.name: drawer.pinned ? qsTr("Unpin the panel: let it slide over the canvas")
                                                   : qsTr("Pin the panel beside the canvas")
                    onClicked: drawer.pinToggled()
                }
            }
        }
        Item {
            id: area
            objectName: "drawerContent"
            Layout.fillWidth: true
            Layout.fillHeight: true
        }
    }
}
