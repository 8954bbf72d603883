// NumberStepper: one number of a typed list (a field of the function-spline view) changed by taps,
// without a keyboard: ‹ and › choose the number (marked in the field), − and + change it by its step
// (a unit of its last shown decimal, at least 0,01), which the buttons show. The rules live in
// FunctionSplinePlot (numberCount, stepText, stepNumber); every other number stays as typed.
// Steppers rather than an on-screen number pad: a lesson changes one value of a worked example a
// little and watches the curve, which a tap per step shows at once; a pad would take the form's
// height, hide the plot on a small screen and still need the list's separators typed.
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

RowLayout {
    id: stepper

    required property FunctionSplinePlot plot
    required property int field
    required property TextField textField
    // The chosen number of the list (kept within the list's length when it shrinks).
    property int index: 0
    // Read again whenever the field's text changes.
    readonly property int count: textField.text.length >= 0 ? plot.numberCount(field) : 0
    readonly property int shown: Math.min(index, count - 1)
    readonly property string step: textField.text.length >= 0 && shown >= 0 ? plot.stepText(field, shown) : ""

    // Marks the chosen number in the field (only on a tap here: marking while the user types would
    // let the next key replace it).
    function mark() {
        if (shown >= 0)
            textField.select(plot.numberStart(field, shown), plot.numberEnd(field, shown))
    }
    function choose(i) {
        index = i
        mark()
    }
    function change(direction) {
        if (plot.stepNumber(field, shown, direction))
            mark()
    }

    spacing: Theme.spacing / 2
    enabled: count > 0

    // The widest texts, so that nothing moves when another number (another step) is chosen.
    TextMetrics {
        id: widestStep
        font: minus.font
        text: "−0" + Qt.locale().decimalPoint + "00"
    }
    TextMetrics {
        id: widestPosition
        font: position.font
        //: Which number of a typed list the − and + buttons change: %1 its place, %2 how many there are.
        text: qsTr("%1 of %2").arg(88).arg(88)
    }

    Button {
        objectName: "previousNumber"
        flat: true
        text: "‹"
        enabled: stepper.shown > 0
        Layout.preferredWidth: Theme.touchMinimum
        Layout.preferredHeight: Theme.touchMinimum
        onClicked: stepper.choose(stepper.shown - 1)
        //: Screen-reader name: chooses the previous number of the list for the − and + buttons.
        Accessible.name: qsTr("Previous number")
    }
    Label {
        id: position
        objectName: "numberPosition"
        horizontalAlignment: Text.AlignHCenter
        Layout.preferredWidth: Math.ceil(widestPosition.advanceWidth) + 2
        text: stepper.shown >= 0 ? qsTr("%1 of %2").arg(stepper.shown + 1).arg(stepper.count) : ""
    }
    Button {
        objectName: "nextNumber"
        flat: true
        text: "›"
        enabled: stepper.shown < stepper.count - 1
        Layout.preferredWidth: Theme.touchMinimum
        Layout.preferredHeight: Theme.touchMinimum
        onClicked: stepper.choose(stepper.shown + 1)
        //: Screen-reader name: chooses the next number of the list for the − and + buttons.
        Accessible.name: qsTr("Next number")
    }
    Button {
        id: minus
        objectName: "decreaseNumber"
        flat: true
        text: stepper.step.length > 0 ? "−" + stepper.step : "−"
        enabled: stepper.step.length > 0
        // A few pixels over the measured text: at exactly its width the label was elided ("+0.…").
        Layout.preferredWidth: Math.max(Theme.touchMinimum,
                                        Math.ceil(widestStep.advanceWidth) + leftPadding + rightPadding + 6)
        Layout.preferredHeight: Theme.touchMinimum
        onClicked: stepper.change(-1)
        //: Screen-reader name: makes the marked number of the list smaller by the step shown.
        Accessible.name: qsTr("Decrease the marked number")
    }
    Button {
        objectName: "increaseNumber"
        flat: true
        text: stepper.step.length > 0 ? "+" + stepper.step : "+"
        enabled: stepper.step.length > 0
        Layout.preferredWidth: minus.Layout.preferredWidth
        Layout.preferredHeight: Theme.touchMinimum
        onClicked: stepper.change(1)
        //: Screen-reader name: makes the marked number of the list larger by the step shown.
        Accessible.name: qsTr("Increase the marked number")
    }
}
