// FunctionSplineView: seed 001's function splines y(x) and the Runge comparison, in a page over the
// window (issue 9). The inputs are typed as in the seed ('Function values', 'Interval', 'Derivatives',
// regular knots) in the UI language's number format; knots and derivative handles are dragged on the
// plot. Every change is a step of the view's own undo (Ctrl+Z inside the view).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Popup {
    id: view
    objectName: "functionSplineView"

    property alias spline: spline
    // The document's editor, for "Add to document" (one undo step there).
    property EditController editor: null
    property string addedName: ""
    readonly property bool wide: width >= 900

    // Opens the view for a plain function spline, or for Runge's example with the polynomial.
    function openSpline() {
        spline.showPolynomial = false
        open()
    }
    function openRunge() {
        spline.loadRungeExample(11)
        open()
    }

    // Each opening starts the steppers at the first number of their fields.
    onAboutToShow: {
        for (const stepper of [valuesStepper, intervalStepper, knotsStepper, derivativesStepper])
            stepper.index = 0
    }

    modal: true
    focus: true
    closePolicy: Popup.CloseOnEscape
    x: 0
    y: 0
    width: parent ? parent.width : 800
    height: parent ? parent.height : 600
    padding: Theme.spacing
    background: Rectangle { color: Theme.panelBackground }

    // Its texts, summary and error follow the UI language by themselves.
    FunctionSplinePlot {
        id: spline
        objectName: "functionSplinePlot"
        onInputChanged: view.addedName = "" // the note was about the spline drawn before
    }

    Shortcut { sequences: [StandardKey.Undo]; enabled: view.visible; onActivated: spline.undo() }
    Shortcut { sequences: [StandardKey.Redo, "Ctrl+Shift+Z"]; enabled: view.visible; onActivated: spline.redo() }

    // The title across the page and Close at its top right, in every language and size at one place,
    // never under the form's first control nor elided (in the form's column it was both).
    Item {
        id: header
        anchors.left: parent.left
        anchors.right: parent.right
        anchors.top: parent.top
        height: Math.max(title.implicitHeight, closeButton.height)
        Label {
            id: title
            anchors.left: parent.left
            anchors.right: closeButton.left
            anchors.rightMargin: Theme.spacing
            anchors.verticalCenter: parent.verticalCenter
            text: qsTr("Function spline y(x)")
            font.bold: true
            font.pixelSize: Theme.titleFontSize
            wrapMode: Text.Wrap
        }
        Button {
            id: closeButton
            flat: true
            objectName: "functionSplineClose"
            anchors.right: parent.right
            anchors.top: parent.top
            height: Math.max(Theme.touchMinimum, implicitHeight)
            //: Button (verb): closes this teaching view and returns to the drawing.
            text: qsTr("Close")
            onClicked: view.close()
        }
    }

    GridLayout {
        anchors.left: parent.left
        anchors.right: parent.right
        anchors.top: header.bottom
        anchors.bottom: parent.bottom
        anchors.topMargin: Theme.spacing / 2
        columns: view.wide ? 2 : 1
        columnSpacing: Theme.spacing
        rowSpacing: Theme.spacing

        ScrollView {
            id: inputs
            Layout.preferredWidth: view.wide ? Theme.formWidth : -1
            Layout.fillWidth: !view.wide
            Layout.fillHeight: view.wide
            Layout.preferredHeight: view.wide ? -1 : Math.min(form.implicitHeight, view.height * 0.5)
            contentWidth: availableWidth
            clip: true

            ColumnLayout {
                id: form
                width: inputs.availableWidth
                spacing: Theme.spacing / 2
                // The course's examples, one tap each (the fields need a keyboard otherwise).
                //: Heading: buttons that load the course's worked examples.
                Label { text: qsTr("Course examples"); font.bold: true }
                Flow {
                    Layout.fillWidth: true
                    spacing: Theme.spacing / 2
                    Button {
                        flat: true
                        objectName: "torokExampleButton"
                        //: Button: loads Török's example (values 3 2 −1 0,5, end slopes 0, his solver).
                        text: qsTr("Török's example")
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.loadExample(FunctionSplinePlot.TorokExample)
                    }
                    Button {
                        flat: true
                        objectName: "example123Button"
                        //: Button: loads the course's Example 1.23 (a global B-spline); keep the number.
                        text: qsTr("Example 1.23")
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.loadExample(FunctionSplinePlot.Example123)
                    }
                    Button {
                        flat: true
                        objectName: "example130Button"
                        //: Button: loads the course's Example 1.30 (a Hermite spline); keep the number.
                        text: qsTr("Example 1.30")
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.loadExample(FunctionSplinePlot.Example130)
                    }
                    Button {
                        flat: true
                        objectName: "rungeExampleTopButton"
                        text: qsTr("Runge's example")
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.loadRungeExample(rungePoints.value)
                    }
                }
                //: Heading (noun): the kind of spline to draw.
                Label { text: qsTr("Spline"); font.bold: true }
                WrappingChoiceBox {
                    objectName: "functionSplineMethod"
                    Layout.fillWidth: true
                    Layout.minimumHeight: Theme.touchMinimum
                    model: spline.methodNames
                    chosen: spline.method
                    onActivated: (index) => spline.method = index
                    Accessible.name: qsTr("Spline")
                }
                Label {
                    text: spline.method === FunctionSplinePlot.BellSpline ? qsTr("Control values") : qsTr("Function values")
                    font.bold: true
                }
                TextField {
                    id: valuesField
                    objectName: "functionValuesField"
                    Layout.fillWidth: true
                    persistentSelection: true // the number the steppers below change stays marked
                    Layout.minimumHeight: Theme.touchMinimum
                    text: spline.valuesText
                    onTextEdited: spline.valuesText = text
                    onAccepted: spline.apply()
                    inputMethodHints: Qt.ImhFormattedNumbersOnly
                    Accessible.name: qsTr("Function values")
                }
                NumberStepper {
                    id: valuesStepper
                    objectName: "functionValuesStepper"
                    Layout.fillWidth: true
                    plot: spline
                    field: FunctionSplinePlot.ValuesField
                    textField: valuesField
                }
                CheckBox {
                    objectName: "uniformKnotsBox"
                    text: qsTr("Regular (uniform) knots")
                    checked: spline.uniformKnots
                    onToggled: spline.uniformKnots = checked
                }
                //: Heading (noun): the interval [a, b] of evenly spaced knots; otherwise the knots x₀ … xₙ are typed
                //: one by one.
                Label { text: spline.uniformKnots ? qsTr("Interval") : qsTr("Knots"); font.bold: true }
                TextField {
                    id: intervalField
                    objectName: "intervalField"
                    visible: spline.uniformKnots
                    Layout.fillWidth: true
                    persistentSelection: true // the number the steppers below change stays marked
                    Layout.minimumHeight: Theme.touchMinimum
                    text: spline.intervalText
                    onTextEdited: spline.intervalText = text
                    onAccepted: spline.apply()
                    Accessible.name: qsTr("Interval")
                }
                NumberStepper {
                    id: intervalStepper
                    objectName: "intervalStepper"
                    visible: spline.uniformKnots
                    Layout.fillWidth: true
                    plot: spline
                    field: FunctionSplinePlot.IntervalField
                    textField: intervalField
                }
                TextField {
                    id: knotsField
                    objectName: "knotsField"
                    visible: !spline.uniformKnots
                    Layout.fillWidth: true
                    persistentSelection: true // the number the steppers below change stays marked
                    Layout.minimumHeight: Theme.touchMinimum
                    text: spline.knotsText
                    onTextEdited: spline.knotsText = text
                    onAccepted: spline.apply()
                    Accessible.name: qsTr("Knots")
                }
                NumberStepper {
                    id: knotsStepper
                    objectName: "knotsStepper"
                    visible: !spline.uniformKnots
                    Layout.fillWidth: true
                    plot: spline
                    field: FunctionSplinePlot.KnotsField
                    textField: knotsField
                }
                Label {
                    visible: spline.derivativeCount > 0
                    text: spline.method === FunctionSplinePlot.Hermite ? qsTr("Derivatives (one per knot)")
                                                                        : qsTr("Derivatives (first and last knot)")
                    font.bold: true
                }
                TextField {
                    id: derivativesField
                    objectName: "derivativesField"
                    visible: spline.derivativeCount > 0
                    Layout.fillWidth: true
                    persistentSelection: true // the number the steppers below change stays marked
                    Layout.minimumHeight: Theme.touchMinimum
                    text: spline.derivativesText
                    onTextEdited: spline.derivativesText = text
                    onAccepted: spline.apply()
                    //: Screen-reader name of the field for the derivatives at the two ends (clamped spline).
                    Accessible.name: qsTr("Derivatives")
                }
                NumberStepper {
                    id: derivativesStepper
                    objectName: "derivativesStepper"
                    visible: spline.derivativeCount > 0
                    Layout.fillWidth: true
                    plot: spline
                    field: FunctionSplinePlot.DerivativesField
                    textField: derivativesField
                }
                Label {
                    visible: spline.method === FunctionSplinePlot.Clamped
                    text: qsTr("Solver")
                    font.bold: true
                }
                ChoiceBox {
                    objectName: "functionSplineSolver"
                    visible: spline.method === FunctionSplinePlot.Clamped
                    Layout.fillWidth: true
                    Layout.minimumHeight: Theme.touchMinimum
                    model: [qsTr("Classical: k − 2 unknowns"), qsTr("Török: half-size system")]
                    chosen: spline.solver
                    onActivated: (index) => spline.solver = index
                    Accessible.name: qsTr("Solver")
                }
                Flow {
                    Layout.fillWidth: true
                    spacing: Theme.spacing / 2
                    Button {
                        objectName: "functionSplineDraw"
                        //: Button (verb): draws the spline from the values typed above.
                        text: qsTr("Draw")
                        highlighted: true
                        flat: true // Material's raised background is a shader effect the software backend cannot draw
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.apply()
                    }
                    Button {
                        flat: true
                        objectName: "functionSplineUndo"
                        text: qsTr("Undo")
                        enabled: spline.canUndo
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.undo()
                    }
                    Button {
                        flat: true
                        text: qsTr("Redo")
                        enabled: spline.canRedo
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.redo()
                    }
                    Button {
                        flat: true
                        objectName: "functionSplineAdd"
                        text: qsTr("Add to document")
                        enabled: view.editor !== null && spline.hasCurve
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: view.addedName = spline.addToDocument(view.editor)
                        ToolTip.visible: hovered
                        ToolTip.delay: 600
                        ToolTip.text: qsTr("Add this spline to the drawing as a curve (undone in one step)")
                        Accessible.name: text
                    }
                }
                Label {
                    objectName: "functionSplineAdded"
                    visible: view.addedName.length > 0
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: Theme.mutedText
                    text: qsTr("Added to the document as “%1”.").arg(view.addedName)
                }
                Label {
                    objectName: "functionSplineError"
                    visible: text.length > 0
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: "#b00020"
                    text: spline.error.text
                }
                Label { text: qsTr("Runge phenomenon: comparison"); font.bold: true }
                CheckBox {
                    objectName: "showPolynomialBox"
                    Layout.fillWidth: true
                    text: qsTr("Interpolating polynomial through the same points")
                    checked: spline.showPolynomial
                    onToggled: spline.showPolynomial = checked
                    contentItem: Label {
                        leftPadding: parent.indicator.width + parent.spacing
                        text: parent.text
                        wrapMode: Text.Wrap
                        verticalAlignment: Text.AlignVCenter
                    }
                }
                Flow {
                    // Wraps in narrow columns and long languages rather than pushing the column wider.
                    Layout.fillWidth: true
                    spacing: Theme.spacing / 2
                    Button {
                        flat: true
                        objectName: "rungeExampleButton"
                        text: qsTr("Runge's example")
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        onClicked: spline.loadRungeExample(rungePoints.value)
                    }
                    SpinBox {
                        id: rungePoints
                        objectName: "rungePointsBox"
                        from: 3; to: 31
                        value: 11
                        editable: true
                        height: Math.max(Theme.touchMinimum, implicitHeight)
                        Accessible.name: qsTr("Points of Runge's example")
                    }
                }
                Label {
                    objectName: "functionSplineSummary"
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: Theme.mutedText
                    text: spline.summary
                }
                Label {
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    color: Theme.mutedText
                    text: qsTr("Drag a green knot up or down, or a grey handle to change the derivative: its slope to the knot is the derivative.")
                }
            }
        }

        PlotView {
            id: plotView
            objectName: "functionSplinePlotView"
            source: spline
            fontPixelSize: Theme.plotFontSize
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.minimumHeight: 200
        }
    }
}
