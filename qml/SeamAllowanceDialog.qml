// SeamAllowanceDialog (Trace menu "Seam allowance…", issue #22): the seam allowance of the selected
// curve — its width in the document's unit, the side, the corner join and the miter limit. For a
// plain curve "Add" makes a linked allowance and closes the dialog; for a selected allowance "Apply" changes its settings
// and "Detach" makes it a free curve. Each is one undo step; SeamAllowance (C++) parses and decides.
// Add and Apply compute on a worker thread: when one has run for a moment (SeamAllowance decides
// when) a progress bar and Cancel appear, and the dialog stays open until it ends or is cancelled.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material
import QtQuick.Layouts
import Kontur
import Kontur.Models

Dialog {
    id: dialog

    required property SeamAllowance seam

    objectName: "seamAllowanceDialog"
    title: qsTr("Seam allowance")
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width * 0.95 : 420, 420)
    modal: true
    // While a job runs, Cancel is the way out (closing would hide its progress).
    closePolicy: seam.busy ? Popup.NoAutoClose : (Popup.CloseOnEscape | Popup.CloseOnPressOutside)
    Material.elevation: parent && parent.GraphicsInfo.api === GraphicsInfo.Software ? 0 : 24

    // The fields show the model's settings whenever the dialog opens or the selection changes.
    function reload() {
        distanceField.text = seam.distanceText
        limitField.text = seam.miterLimitText
        sideBox.chosen = seam.closed ? Math.min(seam.side, 1) : Math.max(seam.side - 2, 0)
        joinBox.chosen = seam.join
    }
    onAboutToShow: reload()
    Connections {
        target: dialog.seam
        function onStateChanged() {
            if (dialog.visible && !distanceField.activeFocus && !limitField.activeFocus)
                dialog.reload()
        }
        // Add is a finished step: the dialog leaves and the message line says what was added (the
        // allowance, selected, opens this dialog again to change it). Apply keeps it open.
        function onFinished(done) {
            if (done && dialog.adding)
                dialog.close()
            else if (done)
                dialog.reload()
            dialog.adding = false
        }
    }
    property bool adding: false // Add was pressed and its job has not ended
    // Outside / Inside for a closed curve, Left / Right (of its direction) for an open one.
    readonly property int chosenSide: seam.closed ? sideBox.currentIndex : sideBox.currentIndex + 2

    GridLayout {
        width: parent ? parent.width : 0
        columns: 2
        columnSpacing: Theme.spacing
        rowSpacing: Theme.spacing / 2

        //: Label: the seam allowance's width; %1 is the unit (mm, cm…).
        Label { text: qsTr("Width (%1)").arg(Numbers.unit(dialog.seam.units, Language.current)) }
        TextField {
            id: distanceField
            objectName: "seamDistance"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            inputMethodHints: Qt.ImhFormattedNumbersOnly
            Accessible.name: qsTr("Seam allowance width")
        }
        Label { text: qsTr("Side") }
        ChoiceBox {
            id: sideBox
            objectName: "seamSide"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            model: dialog.seam.closed ? [qsTr("Outside"), qsTr("Inside")] : [qsTr("Left of the direction"),
                                                                              qsTr("Right of the direction")]
            Accessible.name: qsTr("Side")
        }
        Label { text: qsTr("Corners") }
        ChoiceBox {
            id: joinBox
            objectName: "seamJoin"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            model: [qsTr("Mitered"), qsTr("Bevelled"), qsTr("Rounded")]
            Accessible.name: qsTr("Corners")
        }
        //: Label: the longest pointed corner; %1 is the unit (mm, cm…).
        Label { text: qsTr("Miter limit (%1)").arg(Numbers.unit(dialog.seam.units, Language.current)) }
        TextField {
            id: limitField
            objectName: "seamMiterLimit"
            Layout.fillWidth: true
            Layout.minimumHeight: Theme.touchMinimum
            enabled: joinBox.currentIndex === SeamAllowance.Miter
            inputMethodHints: Qt.ImhFormattedNumbersOnly
            Accessible.name: qsTr("Miter limit")
        }
        // Why the last Add or Apply was refused (a width that leaves nothing, or out of proportion).
        Label {
            objectName: "seamRefusal"
            Layout.columnSpan: 2
            Layout.fillWidth: true
            visible: text !== ""
            text: dialog.seam.refusal.text
            wrapMode: Text.Wrap
            color: Material.color(Material.Red)
        }
        // A long Add or Apply: its progress and Cancel (which leaves the document as it was).
        Label {
            id: progressLabel
            Layout.columnSpan: 2
            Layout.fillWidth: true
            visible: dialog.seam.progressShown
            text: qsTr("Computing the seam allowance…")
            wrapMode: Text.Wrap
        }
        ProgressBar {
            objectName: "seamProgress"
            Layout.fillWidth: true
            visible: dialog.seam.progressShown
            value: dialog.seam.progress
            Accessible.name: progressLabel.text
        }
        Button {
            objectName: "seamCancel"
            Layout.minimumHeight: Theme.touchMinimum
            visible: dialog.seam.progressShown
            text: qsTr("Cancel")
            Accessible.name: qsTr("Cancel the seam allowance")
            onClicked: dialog.seam.cancel()
        }
    }

    footer: DialogButtonBox {
        Button {
            objectName: "seamAdd"
            text: dialog.seam.isAllowance
                  //: Button (verb): applies the changed settings to this seam allowance.
                  ? qsTr("Apply")
                  //: Button (verb): adds a seam allowance to the selected curve.
                  : qsTr("Add")
            enabled: dialog.seam.available && !dialog.seam.busy
            Accessible.name: text
            // The fields are reloaded when the job ends (onFinished above).
            onClicked: {
                dialog.adding = !dialog.seam.isAllowance
                if (dialog.seam.isAllowance)
                    dialog.seam.apply(distanceField.text, dialog.chosenSide, joinBox.currentIndex, limitField.text)
                else
                    dialog.seam.create(distanceField.text, dialog.chosenSide, joinBox.currentIndex, limitField.text)
            }
        }
        Button {
            objectName: "seamDetach"
            //: Button (verb): cut the link between the seam allowance and its curve, so it can be edited on its own.
            text: qsTr("Detach")
            visible: dialog.seam.isAllowance
            enabled: !dialog.seam.busy
            Accessible.name: qsTr("Detach from its curve")
            onClicked: dialog.seam.detach()
        }
        Button {
            objectName: "seamClose"
            //: Button (verb): closes this dialog.
            text: qsTr("Close")
            enabled: !dialog.seam.busy
            Accessible.name: text
            onClicked: dialog.close()
        }
    }
}
