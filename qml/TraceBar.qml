// TraceBar: the controls and results of the tracing tool in use (issue #10), in a bar under the
// canvas: the fitting tolerance of freehand strokes, the real distance and unit of a calibration,
// the measured distance, seam length or deviation with the document's unit, snapping, and what to
// do next. Keys (AppActions): T freehand, K calibrate, Shift+K perspective, M measure, L seam, D deviation, S snapping;
// Esc leaves.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Rectangle {
    id: bar

    required property TraceController trace

    readonly property int tool: trace.tool
    // The perspective calibration's choices (PerspectiveTool.Rectangle, .Orientation).
    property int rectangleChoice: PerspectiveTool.A4
    property int orientationChoice: PerspectiveTool.AutoOrientation
    // The scale calibration's alignment (CalibrationTool.Align): kept across language switches.
    property int alignChoice: CalibrationTool.NoAlign

    function number(value, decimals) {
        return Numbers.fixed(value, decimals, Language.current)
    }

    visible: tool !== TraceController.None
    // At least two rows whatever the tool, so the canvas does not jump when the tool changes.
    implicitHeight: Math.max(flow.implicitHeight, 2 * Theme.touchMinimum + Theme.spacing) + Theme.spacing
    color: "#eef6f5"

    // Its keys are the Trace actions' shortcuts (AppActions), one place for each command.

    Rectangle {
        width: parent.width
        height: 1
        color: Theme.toolbarBorder
    }

    Flow {
        id: flow
        anchors.left: parent.left
        anchors.right: parent.right
        anchors.verticalCenter: parent.verticalCenter
        anchors.leftMargin: Theme.spacing
        anchors.rightMargin: Theme.spacing
        spacing: Theme.spacing

        Label {
            objectName: "traceTitle"
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            font.bold: true
            text: {
                switch (bar.tool) {
                case TraceController.Freehand: return qsTr("Freehand")
                case TraceController.Calibrate: return qsTr("Calibrate")
                case TraceController.Measure: return qsTr("Measure")
                case TraceController.Seam: return qsTr("Seam length")
                case TraceController.Deviation: return qsTr("Deviation")
                case TraceController.MoveBackground: return qsTr("Move background")
                case TraceController.Perspective: return qsTr("Perspective")
                case TraceController.Outline: return qsTr("Trace outline")
                }
                return ""
            }
        }

        // ---- Freehand: the tolerance in document units ----
        Row {
            visible: bar.tool === TraceController.Freehand
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                text: qsTr("Tolerance")
            }
            TextField {
                id: toleranceField
                objectName: "traceTolerance"
                anchors.verticalCenter: parent.verticalCenter
                width: 90
                height: Theme.touchMinimum
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                text: bar.number(bar.trace.freehand.tolerance, 3)
                Accessible.name: qsTr("Tolerance")
                // Bad input leaves the tolerance as it was (with a message); either way the field
                // shows the tolerance in use again, also after the units change.
                onEditingFinished: {
                    bar.trace.freehand.setToleranceText(text)
                    text = Qt.binding(() => bar.number(bar.trace.freehand.tolerance, 3))
                }
            }
            Label {
                anchors.verticalCenter: parent.verticalCenter
                text: Numbers.unit(bar.trace.units, Language.current)
            }
        }
        // At a low zoom a pointer's pixel steps are coarser than the tolerance typed: strokes are then
        // fitted within those steps, and the user sees so (the typed number stays as it is).
        Label {
            objectName: "traceEffectiveTolerance"
            visible: bar.tool === TraceController.Freehand
                     && bar.trace.freehand.effectiveTolerance > bar.trace.freehand.tolerance
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            // Only while shown: the figure changes with every zoom step, and a hidden bar laid out
            // anew for each would cost the canvas a frame per step.
            //: %1 is the freehand tolerance that applies at the current zoom, with its unit (0,50 mm).
            text: visible ? qsTr("in effect at this zoom: %1").arg(Numbers.length(bar.trace.freehand.effectiveTolerance,
                                                                                   bar.trace.units, Language.current))
                          : ""
            Accessible.name: text
        }
        CheckBox {
            objectName: "traceSnapEdges"
            visible: bar.tool === TraceController.Freehand
            height: Theme.touchMinimum
            text: qsTr("Snap to edges")
            checked: bar.trace.freehand.snapToEdges
            onToggled: bar.trace.freehand.snapToEdges = checked
            Accessible.name: qsTr("Snap the stroke to the picture's edges")
        }
        Label {
            objectName: "traceSegments"
            visible: bar.tool === TraceController.Freehand && bar.trace.freehand.lastSegmentCount > 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            text: qsTr("last stroke: %n segment(s)", "", bar.trace.freehand.lastSegmentCount)
        }

        // ---- Calibrate: the real distance, its unit, and an optional alignment ----
        Row {
            visible: bar.tool === TraceController.Calibrate
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                text: qsTr("Real distance")
            }
            TextField {
                id: distanceField
                objectName: "traceDistance"
                anchors.verticalCenter: parent.verticalCenter
                width: 90
                height: Theme.touchMinimum
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                placeholderText: bar.number(100, 0)
                Accessible.name: qsTr("Real distance")
                onAccepted: applyButton.clicked()
            }
            ComboBox {
                id: unitBox
                objectName: "traceUnit"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                implicitContentWidthPolicy: ComboBox.WidestText // unit names differ in length by language
                onFontChanged: { // measured anew for presentation mode's font (see ChoiceBox)
                    implicitContentWidthPolicy = ComboBox.ContentItemImplicitWidth
                    implicitContentWidthPolicy = ComboBox.WidestText
                }
                width: Math.max(80, implicitContentWidth + leftPadding + rightPadding)
                // The codes stay the values (calibrate takes them); the names are the UI language's.
                textRole: "text"
                valueRole: "value"
                model: ["mm", "cm", "in"].map(code => ({value: code, text: Numbers.unit(code, Language.current)}))
                Accessible.name: qsTr("Unit")
            }
            ChoiceBox {
                objectName: "traceAlign"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                // At least 210 px so the bar does not jump between entries; wider where a translation
                // or presentation mode's larger font needs it.
                implicitContentWidthPolicy: ComboBox.WidestText
                width: Math.max(210, implicitContentWidth + leftPadding + rightPadding)
                // In CalibrationTool.Align's order.
                model: [qsTr("Keep the angle"), qsTr("Make it horizontal"), qsTr("Make it vertical")]
                chosen: bar.alignChoice
                onActivated: (index) => bar.alignChoice = index
                Accessible.name: qsTr("Alignment")
            }
            Button {
                id: applyButton
                objectName: "traceApplyCalibration"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                text: qsTr("Apply")
                enabled: bar.trace.calibration.points === 2
                onClicked: {
                    if (bar.trace.calibration.calibrate(distanceField.text, unitBox.currentValue, bar.alignChoice))
                        distanceField.text = ""
                }
            }
        }

        // ---- Perspective: the sheet found in the picture, the known rectangle, its orientation; apply,
        // or clear the calibration; its estimated error; on to tracing the outlines ----
        Row {
            visible: bar.tool === TraceController.Perspective
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Button {
                objectName: "traceFindSheet"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                text: qsTr("Find the sheet")
                Accessible.name: qsTr("Find the sheet in the background image")
                onClicked: bar.trace.perspective.findSheet(bar.rectangleChoice, rectWidthField.text,
                                                           rectHeightField.text)
            }
            ChoiceBox {
                objectName: "perspectiveRectangle"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                // At least 270 px so the bar does not jump between entries; wider where a translation
                // or presentation mode's larger font needs it.
                implicitContentWidthPolicy: ComboBox.WidestText
                width: Math.max(270, implicitContentWidth + leftPadding + rightPadding)
                // In PerspectiveTool.Rectangle's order.
                model: [qsTr("A4 sheet (210 × 297 mm)"), qsTr("A3 sheet (297 × 420 mm)"),
                        qsTr("Letter sheet (8.5 × 11 in)"), qsTr("Mat square 1 cm"), qsTr("Mat square 10 cm"),
                        qsTr("Mat square 1 in"), qsTr("Mat square 6 in"), qsTr("Other size")]
                chosen: bar.rectangleChoice
                onActivated: (index) => bar.rectangleChoice = index
                Accessible.name: qsTr("Known rectangle")
            }
            TextField {
                id: rectWidthField
                objectName: "perspectiveWidth"
                visible: bar.rectangleChoice === PerspectiveTool.CustomRectangle
                anchors.verticalCenter: parent.verticalCenter
                width: 70
                height: Theme.touchMinimum
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                placeholderText: bar.number(210, 0)
                Accessible.name: qsTr("Width")
            }
            Label {
                visible: rectWidthField.visible
                anchors.verticalCenter: parent.verticalCenter
                text: "×"
            }
            TextField {
                id: rectHeightField
                objectName: "perspectiveHeight"
                visible: rectWidthField.visible
                anchors.verticalCenter: parent.verticalCenter
                width: 70
                height: Theme.touchMinimum
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                placeholderText: bar.number(297, 0)
                Accessible.name: qsTr("Height")
            }
            ComboBox {
                id: rectUnitBox
                objectName: "perspectiveUnit"
                visible: rectWidthField.visible
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                implicitContentWidthPolicy: ComboBox.WidestText // unit names differ in length by language
                onFontChanged: { // measured anew for presentation mode's font (see ChoiceBox)
                    implicitContentWidthPolicy = ComboBox.ContentItemImplicitWidth
                    implicitContentWidthPolicy = ComboBox.WidestText
                }
                width: Math.max(80, implicitContentWidth + leftPadding + rightPadding)
                // The codes stay the values (calibrate takes them); the names are the UI language's.
                textRole: "text"
                valueRole: "value"
                model: ["mm", "cm", "in"].map(code => ({value: code, text: Numbers.unit(code, Language.current)}))
                Accessible.name: qsTr("Unit")
            }
            ChoiceBox {
                objectName: "perspectiveOrientation"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                // At least 250 px so the bar does not jump between entries; wider where a translation
                // or presentation mode's larger font needs it.
                implicitContentWidthPolicy: ComboBox.WidestText
                width: Math.max(250, implicitContentWidth + leftPadding + rightPadding)
                // In PerspectiveTool.Orientation's order; the first says what the marks suggest.
                model: [bar.trace.perspective.marks === 4
                            ? (bar.trace.perspective.landscape ? qsTr("As marked: landscape")
                                                              : qsTr("As marked: portrait"))
                            : qsTr("As marked"),
                        qsTr("Portrait"), qsTr("Landscape")]
                chosen: bar.orientationChoice
                onActivated: (index) => bar.orientationChoice = index
                Accessible.name: qsTr("Orientation")
            }
            Button {
                objectName: "traceApplyPerspective"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                text: qsTr("Apply")
                enabled: bar.trace.perspective.marks === 4
                onClicked: bar.trace.perspective.calibratePerspective(bar.rectangleChoice, bar.orientationChoice,
                                                          rectWidthField.text, rectHeightField.text,
                                                          rectUnitBox.currentValue)
            }
            Button {
                objectName: "traceClearPerspective"
                anchors.verticalCenter: parent.verticalCenter
                height: Theme.touchMinimum
                visible: bar.trace.perspective.calibrated
                text: qsTr("Clear perspective")
                onClicked: bar.trace.perspective.clearPerspective()
            }
        }
        Label {
            objectName: "perspectiveError"
            visible: bar.tool === TraceController.Perspective && bar.trace.perspective.calibrated
                     && bar.trace.perspective.calibrationError >= 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            readonly property double error: bar.trace.perspective.calibrationError
            color: error > 0.5 ? "#b3261e" : Theme.mutedText
            text: visible ? qsTr("Estimated error at the far side: %1 mm").arg(bar.number(error, error < 10 ? 2 : 0))
                          : ""
            Accessible.name: text
        }
        Button {
            objectName: "traceOutlineButton"
            visible: bar.tool === TraceController.Perspective && bar.trace.perspective.calibrated
            height: Theme.touchMinimum
            text: qsTr("Trace outline")
            onClicked: bar.trace.tool = TraceController.Outline
        }
        Label {
            objectName: "outlineKnots"
            visible: bar.tool === TraceController.Outline && bar.trace.outline.lastKnotCount > 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            text: visible ? qsTr("Knots in the last outline: %1").arg(bar.trace.outline.lastKnotCount) : ""
        }

        // ---- Results ----
        Label {
            objectName: "traceResult"
            visible: text.length > 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            font.bold: true
            // The lengths come written from C++ (units.h), following units and language.
            text: {
                const t = bar.trace
                switch (bar.tool) {
                case TraceController.Measure:
                    //: %1 is a length with its unit, for example “12,35 mm”.
                    return t.measure.points === 2 ? qsTr("Distance %1").arg(t.measure.distanceText) : ""
                case TraceController.Seam:
                    //: %1 is the seam length with its unit, for example “412,50 mm”.
                    return t.seam.length >= 0 ? qsTr("Seam %1").arg(t.seam.lengthText) : ""
                case TraceController.Deviation:
                    //: Deviation of a traced curve from the reference curve: %1 and %2 are lengths with their unit.
                    return t.deviation.hasResult ? qsTr("Maximum %1 · mean %2").arg(t.deviation.maximumText)
                                                                       .arg(t.deviation.meanText) : ""
                }
                return ""
            }
        }

        CheckBox {
            objectName: "traceSnapBox"
            height: Theme.touchMinimum
            //: Check box (verb): snap freehand strokes to the edges seen in the picture.
            text: qsTr("Snap")
            checked: bar.trace.snapping
            onToggled: bar.trace.snapping = checked
        }

        Label {
            objectName: "traceHint"
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: !bar.trace.message.isEmpty ? "#b3261e" : Theme.mutedText
            text: !bar.trace.message.isEmpty ? bar.trace.message.text : bar.trace.hint
        }

        ToolButton {
            objectName: "traceClose"
            width: Math.max(Theme.touchMinimum, implicitWidth)
            height: Theme.touchMinimum
            text: "\u2715"
            Accessible.name: qsTr("Leave the tracing tool")
            onClicked: bar.trace.tool = TraceController.None
        }
    }
}
