// PanelSwitch: Material's Switch, with a handle that shows on every backend. Material draws the
// handle through a layer with an elevation shadow (a shader effect), which Qt Quick's software
// backend cannot draw: there the handle vanished and only the track told on from off. Flat there.
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material

Switch {
    id: control

    readonly property bool flat: GraphicsInfo.api === GraphicsInfo.Software

    function applyElevation() {
        if (indicator)
            indicator.Material.elevation = flat ? 0 : 1
    }
    onFlatChanged: applyElevation()
    Component.onCompleted: applyElevation()
}
