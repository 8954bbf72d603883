// ToolbarMenu: a menu that drops from a toolbar button. Modal without dimming: a press outside
// closes it and goes no further, and a press on an item never reaches the canvas beneath (an open
// popup does not otherwise keep a pointer handler under it from answering), so that picking or
// closing a menu over the canvas never places a point. As wide as its longest item in the
// language shown (Bulgarian and Russian need about 480 px), within the window; flat where the
// software backend cannot draw the elevation shadow.
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material

Menu {
    id: menu

    // The narrowest the menu gets.
    property real minimumWidth: 300

    y: parent ? parent.height : 0
    modal: true
    dim: false
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 8
    width: {
        let widest = minimumWidth
        for (let i = 0; i < count; ++i)
            widest = Math.max(widest, itemAt(i)?.implicitWidth ?? 0)
        const windowWidth = parent && parent.Window.window ? parent.Window.width : widest
        return Math.min(windowWidth, widest + leftPadding + rightPadding)
    }
}
