// Theme: every size and colour of the UI in one place.
pragma Singleton
import QtQuick
import Kontur

QtObject {
    // A point on the canvas answers within 44 px (about 7 mm), whatever the visible size of its dot.
    readonly property real pointTarget: 44
    // Every control (button, field, slider, drop-down) is at least this wide and tall (the README's
    // 48 px); in presentation mode more, so that a field's larger text is not cut at its top.
    readonly property real touchMinimum: presentation ? 56 : 48
    readonly property real spacing: 8
    // The side panel's width; the larger font of presentation mode needs more.
    readonly property real panelWidth: presentation ? 400 : 280

    // The seed's colours: curve black, control points red, control polygon light grey.
    readonly property color curve: "#000000"
    readonly property color controlPoint: "#d00000"
    readonly property color controlPolygon: "#c4c4c4"
    readonly property color accent: "#1f6fd1"
    readonly property color canvasBackground: "#ffffff"
    readonly property color panelBackground: "#f4f5f7"
    readonly property color mutedText: "#5f6368"
    // A file dialog's message that a typed path leads nowhere.
    readonly property color errorText: "#b3261e"
    readonly property color toolbar: "#e9edf3"
    readonly property color toolbarBorder: "#c9d0da"
    readonly property color toolbarText: "#1d2733"

    readonly property color bannerBackground: "#fff4d6"
    readonly property color bannerBorder: "#e0c070"
    readonly property color tangentEnd: "#5a6470"
    readonly property color grid: "#eceff3"
    readonly property color axis: "#a0a8b2"

    // Presentation mode (projectors, F5): lines, points and fonts larger by this factor.
    readonly property bool presentation: Presentation.enabled
    readonly property real scale: Presentation.factor
    readonly property real curveWidth: 2 * scale
    readonly property real pointRadius: 4.5 * scale
    // The window's font in presentation mode (otherwise the style's own size).
    readonly property real presentationFontSize: 22
    // The titles of the teaching pages, larger than the window's font in either mode.
    readonly property real titleFontSize: presentation ? 30 : 18
    // The column of inputs beside a teaching page's plot: wider with the larger font.
    readonly property real formWidth: presentation ? 560 : 340

    // Teaching views: de Casteljau levels (level 1, 2, …), the B(t) marker, the elevated polygon,
    // the curvature comb, joint marks, and the palette of compared curves (distinct, colour-blind safe).
    readonly property var teachingLevels: ["#2e7d32", "#1565c0", "#8e24aa", "#ef6c00", "#00838f", "#c2185b"]
    readonly property color teachingMarker: "#1f6fd1"
    readonly property color teachingHalf: "#ef6c00"
    readonly property color teachingElevated: "#00897b"
    readonly property color teachingComb: "#e65100"
    readonly property color teachingJoint: "#2e7d32"
    readonly property color teachingWeakJoint: "#c62828"
    readonly property color teachingLabelBackground: "#e6ffffff"
    // One colour per kind the Compare view can show (nine): with eight, the ninth (contour) took the
    // first's blue, the Bézier curve's.
    readonly property var comparePalette: ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#7b3294", "#8c564b", "#999933"]
    readonly property real teachingFontSize: 13 * scale
    // Secondary lines (the curve list's second line, the grid's step, the picture's file): in
    // presentation mode no text under 16 px, which a class cannot read from the back.
    readonly property real smallFontSize: presentation ? 16 : 12
    // The teaching plots' tick and curve labels.
    readonly property real plotFontSize: 11 * scale
    readonly property color teachingBar: "#f4f5f7"
}
