// Theme: every size and colour of the UI in one place.
pragma Singleton
import QtQuick

QtObject {
    // Touch targets at least 44 px (about 7 mm), whatever the visible size of a dot.
    readonly property real touchTarget: 44
    readonly property real spacing: 8
    readonly property real panelWidth: 280

    // The seed's colours: curve black, control points red, control polygon light grey.
    readonly property color curve: "#000000"
    readonly property color controlPoint: "#d00000"
    readonly property color controlPolygon: "#c4c4c4"
    readonly property color accent: "#1f6fd1"
    readonly property color canvasBackground: "#ffffff"
    readonly property color panelBackground: "#f4f5f7"
    readonly property color mutedText: "#5f6368"
    readonly property color toolbar: "#e9edf3"
    readonly property color toolbarBorder: "#c9d0da"
    readonly property color toolbarText: "#1d2733"

    readonly property color bannerBackground: "#fff4d6"
    readonly property color bannerBorder: "#e0c070"
    readonly property color tangentEnd: "#5a6470"
    readonly property color grid: "#eceff3"
    readonly property color axis: "#a0a8b2"

    readonly property real curveWidth: 2
    readonly property real pointRadius: 4.5
}
