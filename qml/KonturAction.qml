// KonturAction: a command of the window's action registry (AppActions). An Action with what the
// responsive tool bar, its overflow menu and the tests need besides: a priority (the higher, the
// longer it keeps its place on a narrow bar), whether it never overflows, its icon by name (an SVG
// of qml/icons, tinted with the text colour by the style), a longer tool tip, and for a tool-bar
// menu the entries it opens.
import QtQuick
import QtQuick.Controls

Action {
    id: action

    // 0–100; on a bar too narrow for all, the lowest go to the overflow menu (⋮) first.
    property int priority: 50
    // Never goes to the overflow menu (undo, redo, the active tool, the panel toggle).
    property bool pinned: false
    // The icon's file name in qml/icons without ".svg".
    property string iconName
    // Shown on hover and on a long press; the name where there is nothing more to say.
    property string toolTip: text
    // Whether it applies at all now (Done only while placing a curve): hidden, not merely disabled.
    property bool relevant: true
    // For a tool-bar menu: its entries, KonturActions or "-" for a separator. Null for a command.
    property var entries: null
    // For a tool-bar menu: its width at least (long entries, or short ones); 0: the bar's usual 300.
    property int menuWidth: 0
    // On the tool bar, the room left over goes before this action (the view's commands stand right).
    property bool spaceBefore: false
    // Shown only for a while (Done, while a curve is placed): it takes the room of the space before
    // the view's commands, and the others are arranged as if it were absent, so that none moves or
    // loses its name when it comes and goes.
    property bool temporary: false

    icon.source: iconName.length > 0 ? Qt.resolvedUrl("icons/" + iconName + ".svg") : ""
}
