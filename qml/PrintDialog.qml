// PrintDialog: File → Print pattern… (issue 22). The paper, the orientation (automatic: the one with
// fewer pages) and the overlap, and what they give (PrintController decides: pages, rows × columns,
// the orientation chosen) before the PDF's name is asked. Big controls for fingers at 800 × 1280 and
// 1280 × 800.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

Dialog {
    id: dialog

    required property PrintController printer
    // Asked for the PDF's name when the user chose Print.
    signal printRequested()

    objectName: "printDialog"
    title: qsTr("Print pattern")
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width * 0.92 : 520, 520)
    modal: true
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24
    onAboutToShow: printer.refresh()

    footer: DialogButtonBox {
        Button {
            objectName: "printDialogPrint"
            text: qsTr("Print to PDF…")
            enabled: dialog.printer.ready
            Accessible.name: text
            implicitHeight: Theme.touchMinimum
            DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
        }
        Button {
            objectName: "printDialogCancel"
            text: qsTr("Cancel")
            Accessible.name: text
            implicitHeight: Theme.touchMinimum
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
    }
    onAccepted: printRequested()

    GridLayout {
        width: parent ? parent.width : 0
        columns: 2
        columnSpacing: Theme.spacing * 2
        rowSpacing: Theme.spacing

        Label {
            text: qsTr("Paper")
        }
        ChoiceBox {
            objectName: "printPaper"
            Layout.fillWidth: true
            Layout.preferredHeight: Theme.touchMinimum
            model: ["A4",
                    //: The US paper size Letter (8.5 × 11 in), not a letter of the alphabet or a message.
                    qsTr("Letter")]
            chosen: dialog.printer.paper
            Accessible.name: qsTr("Paper")
            onActivated: (index) => dialog.printer.paper = index
        }
        Label {
            text: qsTr("Orientation")
        }
        ChoiceBox {
            objectName: "printOrientation"
            Layout.fillWidth: true
            Layout.preferredHeight: Theme.touchMinimum
            model: [qsTr("Automatic (fewer pages)"), qsTr("Portrait"), qsTr("Landscape")]
            chosen: dialog.printer.orientation
            Accessible.name: qsTr("Orientation")
            onActivated: (index) => dialog.printer.orientation = index
        }
        Label {
            text: qsTr("Overlap (mm)")
        }
        SpinBox {
            objectName: "printOverlap"
            Layout.fillWidth: true
            Layout.preferredHeight: Theme.touchMinimum
            from: 0
            to: dialog.printer.maxOverlap
            editable: true
            value: Math.round(dialog.printer.overlap)
            Accessible.name: qsTr("Overlap (mm)")
            onValueModified: dialog.printer.overlap = value
        }
        Label {
            objectName: "printSummary"
            Layout.columnSpan: 2
            Layout.fillWidth: true
            Layout.topMargin: Theme.spacing
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            font.bold: true
            text: dialog.printer.ready
                  ? qsTr("%n page(s) to tape together: %1 × %2 (rows × columns), %3.", "", dialog.printer.pageCount)
                        .arg(dialog.printer.rows).arg(dialog.printer.columns)
                        .arg(dialog.printer.landscape ? qsTr("landscape") : qsTr("portrait"))
                  : dialog.printer.problem.text
        }
        Label {
            Layout.columnSpan: 2
            Layout.fillWidth: true
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            color: Theme.mutedText
            text: qsTr("Before them, a first page with a 10 cm test square and the overview. Print at 100 % "
                       + "(actual size). The visible curves are printed; the background picture is not.")
        }
        Label {
            Layout.columnSpan: 2
            Layout.fillWidth: true
            visible: dialog.printer.pixelUnits
            wrapMode: dialog.visible ? Text.Wrap : Text.NoWrap
            color: Theme.mutedText
            text: qsTr("The drawing is in px: it is printed at 96 px per inch. Choose real units for true size.")
        }
    }
}
