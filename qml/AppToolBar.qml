// AppToolBar: the window's tool bar. Its commands and menus (File, New curve, Teaching, Trace,
// Language) are the registry's actions (AppActions), one button each, made from its bar list in that order; what
// does not fit the width goes, lowest priority first, into the overflow menu (⋮), where a menu's
// entries follow its name as a section, so that every command is at most two taps away and none is
// reached only by scrolling. Pinned actions (undo, redo, the tool in use, the panel toggle) never
// overflow. Names go beside the icons, highest priority first, only where the room allows; every
// button explains itself in a tool tip on hover and on a long press.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

ToolBar {
    id: bar

    required property EditController editor
    required property FileActions fileActions
    required property CurveCanvas canvas
    required property TeachingController teaching
    required property TraceController trace
    // The basis functions plot under the canvas (Teaching menu).
    property alias showBasis: registry.showBasis
    // Whether the window shows its side panel: the panel toggle's state. The window decides.
    property bool panelOpen: true
    // The registry, for the window and the tests.
    readonly property alias actions: registry
    // A menu of the bar is open over the canvas.
    readonly property bool menuOpen: openMenus > 0 || overflowMenu.visible
    // How many of the bar's menus are open (each counts itself in and out).
    property int openMenus: 0

    // How the bar's actions are arranged at this width: {bar: on the bar, text: with their names
    // beside the icons, overflow: in the overflow menu, in priority order}.
    readonly property var arrangement: {
        let all = []
        let temporary = []
        // A temporary action's icon has its room kept free of names (the space before the view's
        // commands) while it is away: the names are the same whether it shows or not.
        let reserved = 0
        for (let i = 0; i < registry.barActions.length; ++i) {
            const action = registry.barActions[i]
            if (action.temporary)
                reserved += buttonSize
            if (action.relevant)
                (action.temporary ? temporary : all).push(action)
        }
        const pinned = all.filter(action => action.pinned)
        const others = all.filter(action => !action.pinned).sort((a, b) => b.priority - a.priority)
        const cost = action => buttonSize + (action.objectName === "zoomOutAction" ? readoutWidth : 0)
        const room = width - leftPadding - rightPadding
        let used = pinned.length * buttonSize
        // The overflow button takes its place only when something overflows.
        const limit = used + others.reduce((sum, action) => sum + cost(action), 0) <= room ? room : room - buttonSize
        let onBar = pinned.slice()
        for (const action of others) {
            if (used + cost(action) <= limit) {
                used += cost(action)
                onBar.push(action)
            }
        }
        // The kept room takes from the names, never an icon's place (a narrow bar keeps its menus).
        used = Math.min(limit, used + reserved)
        // Names beside the icons from the left, in the bar's order: a tool pinned while it is in use
        // (the trace menu, a new curve being placed) takes no name from another, so no button moves.
        let text = []
        for (const action of all.filter(a => onBar.includes(a))) {
            const extra = textWidth(action)
            if (used + extra <= limit) {
                used += extra
                text.push(action)
            }
        }
        // A temporary action (Done) in its kept room, with its name if what is left allows: the
        // others keep their places and names.
        for (const action of temporary) {
            onBar.push(action)
            if (used + textWidth(action) <= limit) {
                used += textWidth(action)
                text.push(action)
            }
        }
        return {bar: onBar, text: text, overflow: others.filter(action => !onBar.includes(action))}
    }
    readonly property real buttonSize: Theme.touchMinimum
    readonly property real readoutWidth: 64

    signal panelToggleRequested()
    signal functionSplineRequested()
    signal rungeRequested()
    signal practicumRequested()
    signal seamAllowanceRequested()

    // What a name beside an icon adds to a button's width.
    function textWidth(action) {
        // Read so that every binding that measures also depends on the font: presentation mode
        // enlarges it, and names measured in the old font were elided to a few letters.
        const font = metrics.font
        return Math.ceil(metrics.advanceWidth(action.text)) + 10
    }

    // One row of finger-sized buttons (the bar holds more than one child, so it cannot tell itself).
    contentHeight: buttonSize
    // A plain light background: Material's elevation shadow is a shader effect, which Qt Quick's
    // software backend cannot draw. Dark text on a light bar stays readable in every state.
    Material.accent: Theme.accent
    Material.foreground: Theme.toolbarText
    background: Rectangle {
        color: Theme.toolbar
        Rectangle {
            anchors.bottom: parent.bottom
            width: parent.width
            height: 1
            color: Theme.toolbarBorder
        }
    }

    AppActions {
        id: registry
        objectName: "appActions"
        editor: bar.editor
        fileActions: bar.fileActions
        canvas: bar.canvas
        teaching: bar.teaching
        trace: bar.trace
        panelOpen: bar.panelOpen
        onPanelToggleRequested: bar.panelToggleRequested()
        onFunctionSplineRequested: bar.functionSplineRequested()
        onRungeRequested: bar.rungeRequested()
        onPracticumRequested: bar.practicumRequested()
        onSeamAllowanceRequested: bar.seamAllowanceRequested()
    }
    // The buttons' font (Material's buttons have their own weight), from a button never shown.
    FontMetrics {
        id: metrics
        font: fontProbe.font
    }
    BarButton {
        id: fontProbe
        visible: false
        host: bar
        command: registry.barActions[0]
    }

    // A button of an action: its icon, its name where the bar has room, a tool tip on hover or a long
    // press (which does not trigger it), and a menu if the action is a menu's.
    component BarButton: ToolButton {
        id: button

        required property KonturAction command
        // The bar (an inline component does not see the ids of the file around it).
        required property AppToolBar host
        property Menu menu: null
        // A long press shows the tool tip for a while instead of triggering the action.
        property bool held: false

        action: command
        visible: host.arrangement.bar.includes(command)
        display: host.arrangement.text.includes(command) ? AbstractButton.TextBesideIcon : AbstractButton.IconOnly
        font.capitalization: Font.MixedCase
        padding: 12
        implicitWidth: host.buttonSize + (display === AbstractButton.IconOnly ? 0 : host.textWidth(command))
        implicitHeight: host.buttonSize
        Accessible.name: command.text
        Accessible.description: command.toolTip
        onClicked: if (menu) menu.open()
        onPressAndHold: {
            held = true
            holdTimer.restart()
        }
        Timer {
            id: holdTimer
            interval: 2500
            onTriggered: button.held = false
        }
        ToolTip.visible: held || (hovered && !(menu && menu.visible))
        ToolTip.delay: held ? 0 : 600
        ToolTip.text: command.toolTip
    }

    RowLayout {
        anchors.fill: parent
        spacing: 0

        // One button per action of the registry's bar list, in its order: the button is named after
        // its action ("undoAction": "undoButton"), a menu's after its menu ("traceMenuAction":
        // "traceMenu"); the zoom read-out stands after Zoom out. Made once (the list does not change)
        // with createObject, which gives each slot the row as its parent object too, so the buttons and
        // menus can be found by name (a Repeater's items have no parent object).
        RowLayout {
            id: slots
            spacing: 0
            Layout.fillWidth: true
            Component.onCompleted: {
                for (const action of registry.barActions)
                    slotComponent.createObject(slots, {modelData: action})
            }
        }
        Component {
            id: slotComponent

            RowLayout {
                id: slot

                required property KonturAction modelData
                readonly property string stem: modelData.objectName.replace(/Action$/, "")

                spacing: 0
                // Hidden with its button (a layout whose items all hide keeps its last width, Qt 6.4);
                // from the arrangement, not from the button, whose `visible` reads false in a hidden slot.
                visible: bar.arrangement.bar.includes(modelData) || modelData.spaceBefore
                Layout.fillWidth: modelData.spaceBefore

                Item {
                    visible: slot.modelData.spaceBefore
                    Layout.fillWidth: true
                }
                BarButton {
                    id: slotButton
                    objectName: slot.stem + "Button"
                    host: bar
                    command: slot.modelData
                    menu: slot.modelData.entries ? slotMenu : null

                    ToolbarMenu {
                        id: slotMenu
                        objectName: slot.stem
                        minimumWidth: slot.modelData.menuWidth > 0 ? slot.modelData.menuWidth : 300
                        entries: slot.modelData.entries ?? []
                        onVisibleChanged: bar.openMenus += visible ? 1 : -1
                    }
                }
                Label {
                    readonly property bool zoom: slot.modelData.objectName === "zoomOutAction"
                    objectName: zoom ? "zoomReadout" : ""
                    visible: zoom && bar.arrangement.bar.includes(slot.modelData)
                    // Whole percents from 1 % to 100,000 %, three significant digits beyond (0.0025 %,
                    // 1.5E+12 %).
                    //: Zoom as a percentage: %1 is a number (150 → “150 %”); write the percent sign as your language
                    //: does.
                    text: qsTr("%1 %").arg(bar.canvas.zoom >= 0.01 && bar.canvas.zoom < 1000
                                           ? Numbers.fixed(bar.canvas.zoom * 100, 0, Language.current)
                                           : Numbers.significant(bar.canvas.zoom * 100, 3, Language.current))
                    horizontalAlignment: Text.AlignHCenter
                    elide: Text.ElideRight
                    Layout.preferredWidth: bar.readoutWidth
                    //: Screen-reader name: %1 is the zoom percentage, for example “150 %”.
                    Accessible.name: qsTr("Zoom %1").arg(text)
                }
            }
        }
        // What did not fit, in priority order; a menu as a section of its entries under its name.
        ToolButton {
            id: overflowButton
            objectName: "overflowButton"
            visible: bar.arrangement.overflow.length > 0
            icon.source: "icons/view-more-symbolic.svg"
            display: AbstractButton.IconOnly
            //: Tool-bar button that opens a menu with the commands that do not fit on the bar.
            text: qsTr("More")
            padding: 12
            implicitWidth: bar.buttonSize
            implicitHeight: bar.buttonSize
            Accessible.name: text
            ToolTip.visible: hovered && !overflowMenu.visible
            ToolTip.delay: 600
            ToolTip.text: qsTr("More commands")
            // As the bar's menu buttons have it (the tests find a button's menu by it).
            readonly property Menu menu: overflowMenu
            onClicked: overflowMenu.open()

            ToolbarMenu {
                id: overflowMenu
                objectName: "overflowMenu"
                namePrefix: "overflow:"
                // At the window's right edge, under the button.
                x: overflowButton.width - width
                entries: {
                    // The single commands first, then the menus' sections (long lists).
                    let list = bar.arrangement.overflow.filter(action => !action.entries)
                    for (const action of bar.arrangement.overflow.filter(action => action.entries)) {
                        if (list.length > 0)
                            list.push("-")
                        list.push({header: action})
                        list.push(...action.entries)
                    }
                    return list
                }
            }
        }
    }
}
