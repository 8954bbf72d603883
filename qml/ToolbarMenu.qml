// ToolbarMenu: a menu that drops from a toolbar button. Modal without dimming: a press outside
// closes it and goes no further, and a press on an item never reaches the canvas beneath (an open
// popup does not otherwise keep a pointer handler under it from answering), so that picking or
// closing a menu over the canvas never places a point. As wide as its longest item in the
// language shown (Bulgarian and Russian need about 480 px), within the window; flat where the
// software backend cannot draw the elevation shadow. Its items are made from `entries`: actions of
// the registry (AppActions), "-" for a separator, and {header: action} for a section headed by a
// menu's name (the overflow menu lists the menus that did not fit on the bar that way, so that every
// command stays two taps away).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import Kontur

Menu {
    id: menu

    // The narrowest the menu gets.
    property real minimumWidth: 300
    property var entries: []
    // Put before each item's objectName (the action's): the overflow menu's items differ by it from
    // the same actions' items in the tool bar's own menus.
    property string namePrefix

    y: parent ? parent.height : 0
    modal: true
    dim: false
    Material.accent: Theme.accent
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 8
    width: {
        let widest = minimumWidth
        for (let i = 0; i < count; ++i)
            widest = Math.max(widest, itemAt(i)?.implicitWidth ?? 0)
        const windowWidth = parent && parent.Window.window ? parent.Window.width : widest
        return Math.min(windowWidth, widest + leftPadding + rightPadding)
    }
    // The items' own heights added up. Not the style's implicitHeight: that follows the list's
    // contentHeight, which a ListView estimates from the items it shows, so a menu shorter than its
    // items fed its own height back through which items were shown (a binding loop after a resize).
    readonly property real itemsHeight: {
        let total = 0
        for (let i = 0; i < count; ++i)
            total += itemAt(i)?.height ?? 0
        return total
    }
    // Never taller than the window: a long menu scrolls inside it. Measured from where the menu is
    // asked to drop (under its button), not from its `y`: that follows where the popup was moved to
    // fit the window, and so fed this binding back into itself after a resize (a binding loop).
    height: {
        const wanted = Math.max(implicitBackgroundHeight + topInset + bottomInset,
                                itemsHeight + topPadding + bottomPadding)
        return Math.min(wanted, parent && parent.Window.window ? parent.Window.height - parent.height - 8 : wanted)
    }

    // The style lets the list scroll only when its items are taller than the whole window; this menu
    // stops 8 px under its button, so items that fit the window but not the menu were out of reach.
    Component.onCompleted: contentItem.interactive = Qt.binding(() => menu.itemsHeight + menu.topPadding
                                                                       + menu.bottomPadding > menu.height + 0.5)

    // The entries' items are made when the menu opens, and again only when the entries really
    // changed (the overflow menu's list is computed afresh on every resize; the kinds of curve are
    // new actions after a language switch). Made with the window, the menus' items and their icons
    // were about a quarter of the time to the first frame.
    property var builtEntries: []
    onAboutToShow: rebuild()
    onEntriesChanged: if (visible) rebuild()
    function same(a, b) {
        if (typeof a === "string" || typeof b === "string")
            return a === b
        return a.header !== undefined || b.header !== undefined ? a.header === b.header : a === b
    }
    function rebuild() {
        const list = entries ?? []
        if (list.length === builtEntries.length && list.every((entry, i) => same(entry, builtEntries[i])))
            return
        builtEntries = list
        while (count > 0)
            removeItem(itemAt(0))
        for (const entry of list) {
            if (typeof entry === "string")
                addItem(separatorComponent.createObject(menu.contentItem))
            else if (entry.header)
                addItem(headerComponent.createObject(menu.contentItem, {action: entry.header}))
            else
                addItem(itemComponent.createObject(menu.contentItem, {entry: entry, objectName: namePrefix + entry.objectName}))
        }
    }

    Component {
        id: itemComponent
        MenuItem {
            required property KonturAction entry
            action: entry
            // Tall enough for a finger, whatever the style's density.
            implicitHeight: Math.max(Theme.touchMinimum, implicitContentHeight + topPadding + bottomPadding)
            // (The entry is null for a moment when the actions are made again, on a language switch.)
            visible: entry ? entry.relevant : false
            // By relevance, not by `visible`: the menu's list hides the items it scrolls out of view,
            // and a height following that changed the list's content height, the menu's height and
            // so which items the list shows (a binding loop on the menu's height after a resize).
            height: entry && entry.relevant ? implicitHeight : 0
            Accessible.name: text
            ToolTip.visible: hovered && entry !== null && entry.toolTip !== text
            ToolTip.delay: 600
            ToolTip.text: entry ? entry.toolTip : ""
        }
    }
    Component {
        id: separatorComponent
        MenuSeparator {}
    }
    Component {
        id: headerComponent
        // A section's name in the overflow menu: what the menu button would have said.
        Label {
            required property Action action
            text: action.text
            font.bold: true
            color: Theme.mutedText
            leftPadding: 16
            topPadding: 12
            bottomPadding: 4
            Accessible.role: Accessible.Heading
            Accessible.name: text
        }
    }
}
