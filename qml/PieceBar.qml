// PieceBar: the selected closed curve as a garment piece (io/piece.h), in a bar under the canvas:
// make it a piece; its size, how many to cut and the material (typed, set on Enter or when the field
// is left); and the tools that place its marks on the canvas by touch (PiecePainter): the grainline
// and the fold line by two taps, a notch by a tap on the seam (drag a notch to slide it along), a
// drill hole by a tap, and Delete mark by a tap on one; Seam allowance: a tap chooses a seam, and its
// width is set with − / + or typed (SeamWidths). The rules are PieceMarkEdits' and SeamWidths'.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

Rectangle {
    id: bar

    required property PieceMarkEdits marks
    required property SeamWidths seams
    required property PiecePainter painter
    property bool open: false
    // A seam is chosen for its own seam allowance width.
    readonly property bool seamChosen: marks.isPiece && painter.tool === PiecePainter.Seam && seams.seam >= 0
    signal closeRequested()

    visible: open
    implicitHeight: flow.implicitHeight + Theme.spacing
    color: "#f6f0fa"

    // Leaving the bar leaves the tool too.
    onOpenChanged: if (!open) painter.tool = PiecePainter.None

    Rectangle {
        width: parent.width
        height: 1
        color: Theme.toolbarBorder
    }

    // A tool's button: raised and bold while its tool is chosen; a second tap leaves it.
    component ToolChoice: Button {
        required property int tool
        height: Theme.touchMinimum
        flat: bar.painter.tool !== tool
        font.bold: bar.painter.tool === tool
        enabled: bar.marks.isPiece
        Accessible.name: text
        onClicked: bar.painter.tool = bar.painter.tool === tool ? PiecePainter.None : tool
    }

    component Field: TextField {
        required property string value
        signal committed(string text)
        height: Theme.touchMinimum
        width: 110
        enabled: bar.marks.isPiece
        text: value
        // Another piece selected (or an undo): the field shows its value again.
        onValueChanged: text = value
        selectByMouse: true
        onEditingFinished: if (text !== value) committed(text)
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
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            font.bold: true
            //: Title of the bar that edits a garment pattern piece's marks.
            text: qsTr("Pattern piece")
        }
        Button {
            objectName: "pieceMake"
            visible: !bar.marks.isPiece
            enabled: bar.marks.canBePiece
            height: Theme.touchMinimum
            text: qsTr("Make a pattern piece")
            Accessible.name: text
            onClicked: bar.marks.makePiece()
        }
        Label {
            visible: !bar.marks.isPiece && !bar.marks.canBePiece
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            text: qsTr("Select a closed curve: the outline of a pattern piece.")
        }
        Row {
            visible: bar.marks.isPiece
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                //: A garment size (38, M) of the pattern piece.
                text: qsTr("Size")
            }
            Field {
                objectName: "pieceSize"
                value: bar.marks.size
                Accessible.name: qsTr("Size")
                onCommitted: (text) => bar.marks.setSize(text)
            }
        }
        Row {
            visible: bar.marks.isPiece
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                //: How many pieces to cut from the fabric (“cut 2”).
                text: qsTr("Cut")
            }
            Field {
                id: quantityField
                objectName: "pieceQuantity"
                width: 70
                value: String(bar.marks.quantity)
                inputMethodHints: Qt.ImhDigitsOnly
                Accessible.name: qsTr("How many to cut")
                // A refused number stays as typed, with the bar's message saying why.
                onCommitted: (text) => bar.marks.setQuantityText(text)
            }
        }
        Row {
            visible: bar.marks.isPiece
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                //: The fabric the pattern piece is cut from.
                text: qsTr("Material")
            }
            Field {
                objectName: "pieceMaterial"
                value: bar.marks.material
                Accessible.name: qsTr("Material")
                onCommitted: (text) => bar.marks.setMaterial(text)
            }
        }
        ToolChoice {
            objectName: "pieceGrainline"
            visible: bar.marks.isPiece
            tool: PiecePainter.Grainline
            //: Tool: draw the pattern piece's grainline with two taps.
            text: qsTr("Grainline")
        }
        ToolChoice {
            objectName: "pieceFold"
            visible: bar.marks.isPiece
            tool: PiecePainter.Fold
            //: Tool: the fold line, the edge laid on the fabric's fold (two taps).
            text: qsTr("On fold")
        }
        ToolChoice {
            objectName: "pieceNotch"
            visible: bar.marks.isPiece
            tool: PiecePainter.Notch
            //: Tool: place a notch by tapping the seam.
            text: qsTr("Notch")
        }
        ChoiceBox {
            objectName: "pieceNotchKind"
            visible: bar.marks.isPiece && bar.painter.tool === PiecePainter.Notch
            height: Theme.touchMinimum
            width: Math.max(130, implicitContentWidth + leftPadding + rightPadding)
            // In io::NotchKind's order.
            model: [qsTr("Slit notch"), qsTr("V notch"), qsTr("Castle notch")]
            chosen: bar.painter.notchKind
            onActivated: (index) => bar.painter.notchKind = index
            Accessible.name: qsTr("Notch kind")
        }
        ToolChoice {
            objectName: "pieceDrillHole"
            visible: bar.marks.isPiece
            tool: PiecePainter.DrillHole
            //: Tool: mark a drill hole by a tap.
            text: qsTr("Drill hole")
        }
        ToolChoice {
            objectName: "pieceDeleteMark"
            visible: bar.marks.isPiece
            tool: PiecePainter.Delete
            //: Tool: delete the notch, drill hole, grainline or fold line tapped.
            text: qsTr("Delete mark")
        }
        ToolChoice {
            objectName: "pieceSeamTool"
            visible: bar.marks.isPiece
            tool: PiecePainter.Seam
            //: Tool: tap a seam of the pattern piece to set its own seam allowance width.
            text: qsTr("Seam allowance")
        }
        Row {
            objectName: "pieceSeamRow"
            visible: bar.seamChosen
            spacing: Theme.spacing / 2
            height: Theme.touchMinimum
            Label {
                anchors.verticalCenter: parent.verticalCenter
                //: The seam tapped (numbered from 1 along the piece) whose seam allowance the bar shows.
                text: qsTr("Seam %1").arg(bar.seams.seam + 1)
            }
            Button {
                objectName: "pieceSeamNarrower"
                height: Theme.touchMinimum
                width: Math.max(Theme.touchMinimum, implicitWidth)
                text: "\u2212"
                Accessible.name: qsTr("Seam allowance %1 %2 narrower").arg(bar.seams.stepText).arg(bar.seams.units)
                onClicked: bar.seams.stepWidth(-1)
            }
            Field {
                objectName: "pieceSeamWidth"
                width: 80
                value: bar.seams.widthText
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                font.bold: bar.seams.ownWidth
                Accessible.name: qsTr("Seam allowance of the seam")
                // A refused number stays as typed, with the bar's message saying why.
                onCommitted: (text) => bar.seams.setWidthText(text)
            }
            Button {
                objectName: "pieceSeamWider"
                height: Theme.touchMinimum
                width: Math.max(Theme.touchMinimum, implicitWidth)
                text: "+"
                Accessible.name: qsTr("Seam allowance %1 %2 wider").arg(bar.seams.stepText).arg(bar.seams.units)
                onClicked: bar.seams.stepWidth(1)
            }
            Label {
                anchors.verticalCenter: parent.verticalCenter
                text: bar.seams.units
            }
        }
        // Flow's own items, so that the bar wraps between them in long languages.
        Button {
            objectName: "pieceSeamHem"
            visible: bar.seamChosen
            height: Theme.touchMinimum
            checkable: true
            checked: bar.seams.hem
            //: Toggle: the tapped seam is a hem, so its seam allowance's corners are turned back (mirrored about the hem line) rather than mitred.
            text: qsTr("Hem: turned-back corners")
            Accessible.name: text
            onToggled: bar.seams.setHem(checked)
        }
        Button {
            objectName: "pieceSeamReset"
            visible: bar.seamChosen && bar.seams.ownWidth
            height: Theme.touchMinimum
            //: Give the seam the piece's own seam allowance width again.
            text: qsTr("As the piece")
            Accessible.name: text
            onClicked: bar.seams.resetWidth()
        }
        Label {
            objectName: "pieceMessage"
            visible: text.length > 0
            height: Theme.touchMinimum
            verticalAlignment: Text.AlignVCenter
            color: Theme.mutedText
            text: !bar.marks.message.isEmpty ? bar.marks.message.text : bar.seams.message.text
        }
        Button {
            objectName: "pieceDone"
            height: Theme.touchMinimum
            text: qsTr("Done")
            Accessible.name: qsTr("Close the pattern piece bar")
            onClicked: bar.closeRequested()
        }
    }
}
