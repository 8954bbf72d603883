// TeachingBar: the controls of the teaching view that is shown (de Casteljau, degree elevation,
// comparison, curvature comb) in a compact bar under the canvas. Every control is a focusable Qt
// Quick control; P plays or pauses, "," and "." step back and forward.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Rectangle {
    id: bar

    required property TeachingController teaching

    readonly property int view: teaching.view
    readonly property bool animated: view === TeachingController.DeCasteljau || view === TeachingController.Elevation

    visible: view !== TeachingController.None
    // The document's unit, for the distances the bar shows.
    readonly property string units: editorUnits.units
    QtObject {
        id: editorUnits
        readonly property var document: bar.teaching.editor ? bar.teaching.editor.document : null
        readonly property string units: document ? document.units : "px"
    }
    implicitHeight: Math.max(flow.implicitHeight, closeButton.height) + Theme.spacing
    color: Theme.teachingBar

    Rectangle {
        width: parent.width
        height: 1
        color: Theme.toolbarBorder
    }

    function stepBy(delta) {
        if (view === TeachingController.DeCasteljau)
            teaching.parameter = Math.round((teaching.parameter + delta * 0.01) * 100) / 100
        else if (view === TeachingController.Elevation)
            teaching.elevationStep = teaching.elevationStep + delta
    }

    // A label's new text (the view's title, the hint, a read-out) changes its width while the flow is
    // placing what follows it, and Qt 6.4's positioner keeps the old places (the title lay under the
    // next control): after the view or its scene changes, the flow is laid out again in the next frames.
    property int relayoutFrames: 0
    Connections {
        target: bar.teaching
        function onViewChanged() { bar.relayoutFrames = 3 }
        function onSceneChanged() { bar.relayoutFrames = 3 }
    }
    Connections {
        target: bar.Window.window
        enabled: bar.relayoutFrames > 0
        function onAfterAnimating() {
            bar.relayoutFrames = bar.relayoutFrames - 1
            flow.forceLayout()
        }
    }

    Shortcut { sequence: "P"; enabled: bar.visible && bar.animated; onActivated: bar.teaching.playing = !bar.teaching.playing }
    Shortcut { sequence: ","; enabled: bar.visible && bar.animated; onActivated: bar.stepBy(-1) }
    Shortcut { sequence: "."; enabled: bar.visible && bar.animated; onActivated: bar.stepBy(1) }

    // Close stands at the bar's bottom right whatever the view, the language and the texts beside it
    // (the bar's bottom stays where it is as the Compare legend adds rows above): in the flow it was
    // pushed along, and into another row, by every control before it.
    Button {
        id: closeButton
        objectName: "teachingCloseButton"
        flat: true
        anchors.right: parent.right
        anchors.bottom: parent.bottom
        anchors.rightMargin: Theme.spacing
        anchors.bottomMargin: Theme.spacing / 2
        height: Theme.touchMinimum
        //: Button (verb): closes the teaching view and returns to the drawing.
        text: qsTr("Close")
        onClicked: bar.teaching.view = TeachingController.None
        ToolTip.visible: hovered
        ToolTip.delay: 600
        ToolTip.text: qsTr("Leave the teaching view")
    }

    Flow {
        id: flow
        anchors.left: parent.left
        anchors.right: closeButton.left
        anchors.top: parent.top
        anchors.leftMargin: Theme.spacing
        anchors.rightMargin: Theme.spacing
        anchors.topMargin: Theme.spacing / 2
        spacing: Theme.spacing

        Label {
            objectName: "teachingTitle"
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            font.bold: true
            text: {
                switch (bar.view) {
                case TeachingController.DeCasteljau: return qsTr("de Casteljau")
                case TeachingController.Elevation: return qsTr("Degree elevation")
                //: Name of a teaching view (verb used as a title): compare curve kinds or parameterizations side by
                //: side.
                case TeachingController.Compare: return qsTr("Compare")
                case TeachingController.Comb: return qsTr("Curvature comb")
                }
                return ""
            }
        }

        // What to do when the view has nothing to show for the selected curve.
        Label {
            objectName: "teachingHint"
            visible: !bar.teaching.applicable
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            text: bar.view === TeachingController.Elevation ? qsTr("Select a Bézier curve.") : qsTr("Select a curve.")
        }

        // --- de Casteljau: t ---
        Row {
            visible: bar.view === TeachingController.DeCasteljau && bar.teaching.applicable
            spacing: Theme.spacing / 2
            Label {
                id: parameterReadout
                height: Theme.touchMinimum
                // As wide as its widest value, so that nothing beside it moves as t changes.
                width: Math.max(implicitWidth, parameterWidest.advanceWidth)
                verticalAlignment: Text.AlignVCenter
                //: The curve parameter t and its value (a number); keep “t”.
                text: qsTr("t = %1").arg(Numbers.fixed(bar.teaching.parameter, 2, Language.current))
                TextMetrics {
                    id: parameterWidest
                    font: parameterReadout.font
                    text: qsTr("t = %1").arg(Numbers.fixed(0.88, 2, Language.current))
                }
            }
            // One step of t each (held, they repeat): the keys "," and "." for a pointer.
            ToolButton {
                objectName: "teachingStepBack"
                text: "\u2212"
                width: Math.max(Theme.touchMinimum, implicitWidth)
                height: Theme.touchMinimum
                enabled: bar.teaching.parameter > 0
                autoRepeat: true
                onClicked: bar.stepBy(-1)
                Accessible.name: qsTr("One step back in t")
            }
            Slider {
                objectName: "teachingParameterSlider"
                width: 220
                height: Theme.touchMinimum
                from: 0
                to: 1
                stepSize: 0.01
                value: bar.teaching.parameter
                onMoved: bar.teaching.parameter = value
                Accessible.name: qsTr("Parameter t")
            }
            ToolButton {
                objectName: "teachingStepForward"
                text: "+"
                width: Math.max(Theme.touchMinimum, implicitWidth)
                height: Theme.touchMinimum
                enabled: bar.teaching.parameter < 1
                autoRepeat: true
                onClicked: bar.stepBy(1)
                Accessible.name: qsTr("One step forward in t")
            }
        }

        // --- elevation: step ---
        // The readout stands after the slider and its step buttons: as its text widens with the
        // degree, nothing under the pointer moves. A step of a slider with up to 97 of them in
        // 220 px is under a pixel: the buttons take one step each (held, they repeat).
        Row {
            visible: bar.view === TeachingController.Elevation && bar.teaching.applicable
            spacing: Theme.spacing / 2
            ToolButton {
                objectName: "elevationLessButton"
                text: "\u2212"
                width: Math.max(Theme.touchMinimum, implicitWidth)
                height: Theme.touchMinimum
                enabled: bar.teaching.elevationStep > 0
                autoRepeat: true
                onClicked: bar.teaching.elevationStep = bar.teaching.elevationStep - 1
                Accessible.name: qsTr("One elevation step less")
            }
            Slider {
                objectName: "elevationSlider"
                width: 220
                height: Theme.touchMinimum
                from: 0
                to: Math.max(1, bar.teaching.maximumStep)
                enabled: bar.teaching.maximumStep > 0
                stepSize: 1
                snapMode: Slider.SnapAlways
                value: bar.teaching.elevationStep
                onMoved: bar.teaching.elevationStep = Math.round(value)
                Accessible.name: qsTr("Elevation steps")
            }
            ToolButton {
                objectName: "elevationMoreButton"
                text: "+"
                width: Math.max(Theme.touchMinimum, implicitWidth)
                height: Theme.touchMinimum
                enabled: bar.teaching.elevationStep < bar.teaching.maximumStep
                autoRepeat: true
                onClicked: bar.teaching.elevationStep = bar.teaching.elevationStep + 1
                Accessible.name: qsTr("One elevation step more")
            }
            Label {
                id: elevationReadout
                objectName: "elevationReadout"
                height: Theme.touchMinimum
                // As wide as at the highest degree, so that what follows it does not move as it widens.
                width: Math.max(implicitWidth, elevationWidest.advanceWidth)
                verticalAlignment: Text.AlignVCenter
                text: qsTr("degree %1 → %2 (%n point(s))", "", bar.teaching.degree + bar.teaching.elevationStep + 1)
                      .arg(bar.teaching.degree).arg(bar.teaching.degree + bar.teaching.elevationStep)
                TextMetrics {
                    id: elevationWidest
                    font: elevationReadout.font
                    text: qsTr("degree %1 → %2 (%n point(s))", "", bar.teaching.degree + bar.teaching.maximumStep + 1)
                          .arg(bar.teaching.degree).arg(bar.teaching.degree + bar.teaching.maximumStep)
                }
            }
        }

        // --- animation: play, direction, speed ---
        Row {
            visible: bar.animated && bar.teaching.applicable
            spacing: 0
            Button {
                id: playButton
                objectName: "teachingPlayButton"
                flat: true
                height: Theme.touchMinimum
                // As wide as the wider of its two names: Pause pushed what follows along.
                // Measured by two unseen buttons of the same style (its capitals and letter spacing):
                // text metrics were 2-3 px short with some fonts.
                width: Math.max(playProbe.implicitWidth, pauseProbe.implicitWidth)
                text: bar.teaching.playing ? qsTr("Pause") : qsTr("Play")
                Button { id: playProbe; visible: false; flat: true; font: playButton.font; text: qsTr("Play") }
                Button { id: pauseProbe; visible: false; flat: true; font: playButton.font; text: qsTr("Pause") }
                onClicked: bar.teaching.playing = !bar.teaching.playing
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("Play or pause the animation (P)")
            }
            Button {
                objectName: "teachingDirectionButton"
                flat: true
                height: Theme.touchMinimum
                text: bar.teaching.direction > 0 ? "\u25B6" : "\u25C0"
                onClicked: bar.teaching.direction = -bar.teaching.direction
                //: Screen-reader name of the button that reverses the direction of the animation (forwards or backwards
                //: in t).
                Accessible.name: qsTr("Direction")
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: bar.teaching.direction > 0 ? qsTr("Forward; press to go backward")
                                                          : qsTr("Backward; press to go forward")
            }
            Label {
                height: Theme.touchMinimum
                leftPadding: Theme.spacing / 2
                rightPadding: Theme.spacing / 2
                verticalAlignment: Text.AlignVCenter
                text: qsTr("Speed")
            }
            ChoiceBox {
                objectName: "teachingSpeedBox"
                height: Theme.touchMinimum
                width: 96
                readonly property var speeds: [0.25, 0.5, 1, 2, 4]
                //: Animation speed factor: %1 is a number (0,5 → “0,5×”).
                model: speeds.map(s => qsTr("%1×").arg(Numbers.significant(s, 3, Language.current)))
                chosen: Math.max(0, speeds.indexOf(bar.teaching.speed))
                onActivated: (index) => bar.teaching.speed = speeds[index]
                Accessible.name: qsTr("Speed")
            }
        }

        // --- edits ---
        Button {
            objectName: "splitButton"
            visible: bar.view === TeachingController.DeCasteljau && bar.teaching.applicable
            enabled: bar.teaching.parameter > 0 && bar.teaching.parameter < 1
            height: Theme.touchMinimum
            // Not in capitals: t is the parameter, T the chord in the cubic segments.
            font.capitalization: Font.MixedCase
            text: qsTr("Split at t")
            onClicked: bar.teaching.splitAtParameter()
            ToolTip.visible: hovered
            ToolTip.delay: 600
            ToolTip.text: qsTr("Split the curve at t into two curves (a spline becomes a composite curve first)")
        }
        Button {
            objectName: "reduceButton"
            visible: bar.view === TeachingController.Elevation && bar.teaching.applicable
            enabled: bar.teaching.degree >= 2
            height: Theme.touchMinimum
            text: qsTr("Reduce degree")
            onClicked: bar.teaching.reduceDegree()
            ToolTip.visible: hovered
            ToolTip.delay: 600
            ToolTip.text: qsTr("Replace the curve by the closest curve of one degree less")
        }
        Label {
            objectName: "reductionErrorLabel"
            visible: bar.view === TeachingController.Elevation && bar.teaching.applicable && bar.teaching.reductionError >= 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            //: Degree reduction: %1 is the largest distance between the curve and its reduced curve (a number).
            // A distance in the document's unit with that unit's fixed decimals (it read "30", "48,8", "275").
            text: visible ? qsTr("reduction error %1").arg(Numbers.length(bar.teaching.reductionError, bar.units,
                                                                         Language.current))
                          : ""
        }
        Label {
            visible: bar.view === TeachingController.Elevation && bar.teaching.applicable
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            text: qsTr("Alt+click or long press: add or remove a control point")
        }

        // --- compare ---
        ChoiceBox {
            objectName: "compareModeBox"
            visible: bar.view === TeachingController.Compare
            height: Theme.touchMinimum
            // As wide as its longer entry, in every language and font size, whichever is chosen.
            implicitContentWidthPolicy: ComboBox.WidestText
            //: What the Compare view sets side by side: one curve drawn as each kind, or with each parameterization.
            model: [qsTr("Curve kinds"), qsTr("Parameterizations")]
            chosen: bar.teaching.compareMode === TeachingController.Parameterizations ? 1 : 0
            onActivated: (index) => bar.teaching.compareMode = index === 1 ? TeachingController.Parameterizations
                                                                          : TeachingController.Kinds
            Accessible.name: qsTr("Compare")
        }

        // --- comb ---
        Row {
            visible: bar.view === TeachingController.Comb
            spacing: Theme.spacing / 2
            Label {
                height: Theme.touchMinimum
                verticalAlignment: Text.AlignVCenter
                //: %1 is the scale factor of the curvature comb (a number such as 2,5).
                text: qsTr("Scale %1").arg(Numbers.significant(bar.teaching.combScale, 2, Language.current))
            }
            Slider {
                objectName: "combScaleSlider"
                width: 180
                height: Theme.touchMinimum
                // Logarithmic: each step doubles or halves the teeth.
                from: -4
                to: 4
                stepSize: 0.25
                value: Math.log(bar.teaching.combScale) / Math.LN2
                onMoved: bar.teaching.combScale = Math.pow(2, value)
                Accessible.name: qsTr("Comb scale")
            }
            CheckBox {
                objectName: "combAllCheck"
                height: Theme.touchMinimum
                text: qsTr("All curves")
                checked: bar.teaching.combAllCurves
                onToggled: bar.teaching.combAllCurves = checked
            }
        }

        // The legend of the compared curves, in the bar rather than over the canvas, where it
        // covered the curves' start; each entry shows or hides its curve. Rows of its own.
        Flow {
            objectName: "compareLegend"
            visible: bar.view === TeachingController.Compare && legendEntries.count > 0
            width: flow.width
            spacing: Theme.spacing
            Repeater {
                id: legendEntries
                // The names are translated: the legend is announced again on a language switch.
                model: bar.teaching.legend
                CheckBox {
                    id: entry
                    required property var modelData
                    required property int index
                    objectName: "legendEntry" + index
                    height: Theme.touchMinimum
                    checked: modelData.shown
                    enabled: modelData.available
                    // The message keeps the context it was translated in.
                    text: modelData.available ? modelData.name
                                              : qsTranslate("TeachingOverlay", "%1 (not possible for these points)").arg(modelData.name)
                    onToggled: bar.teaching.setCompareShown(index, checked)
                    contentItem: Row {
                        leftPadding: entry.indicator.width + entry.spacing
                        spacing: Theme.spacing / 2
                        Rectangle {
                            anchors.verticalCenter: parent.verticalCenter
                            width: 24 * Theme.scale
                            height: 4 * Theme.scale
                            color: Theme.comparePalette[entry.modelData.palette % Theme.comparePalette.length]
                        }
                        Label {
                            anchors.verticalCenter: parent.verticalCenter
                            text: entry.text
                            font: entry.font
                            color: entry.enabled ? Theme.toolbarText : Theme.mutedText
                        }
                    }
                }
            }
        }

    }
}
