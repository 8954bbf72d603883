// FirstRunHint: three large starts over an empty canvas — a new curve, a file to open, a picture to
// trace. Only its buttons take input: a press beside them reaches the canvas under it. It goes as
// soon as the document has a curve or a picture (the window says when: `shown`).
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur

Item {
    id: hint

    property bool shown: true

    signal newCurveRequested()
    signal openRequested()
    signal traceRequested()

    visible: shown

    ColumnLayout {
        id: starts
        anchors.centerIn: parent
        width: Math.min(hint.width - 2 * Theme.spacing, 420)
        spacing: Theme.spacing

        Start {
            objectName: "hintNewCurve"
            text: qsTr("New curve")
            detail: qsTr("Tap four points of a Bézier curve")
            glyph: "curve"
            onClicked: hint.newCurveRequested()
        }
        Start {
            objectName: "hintOpen"
            text: qsTr("Open a file")
            detail: qsTr("A Kontur document")
            glyph: "folder"
            onClicked: hint.openRequested()
        }
        Start {
            objectName: "hintTrace"
            text: qsTr("Trace a picture")
            detail: qsTr("Load a photo or scan and draw over it")
            glyph: "picture"
            onClicked: hint.traceRequested()
        }
    }

    // One start: a large button with a drawn icon, its name and a line on what it does.
    component Start: Button {
        id: start
        property string detail
        // "curve", "folder" or "picture": drawn here (no icon files of their own).
        property string glyph

        Layout.fillWidth: true
        Layout.minimumHeight: 72
        Accessible.role: Accessible.Button
        Accessible.name: text
        Accessible.description: detail
        highlighted: glyph === "curve"
        // Drawn here rather than by the style: Material's raised background is a shader effect that
        // Qt Quick's software backend leaves out, which left white text on the white canvas.
        background: Rectangle {
            implicitHeight: 72
            radius: 8
            color: start.highlighted ? (start.down ? Qt.darker(Theme.accent, 1.15) : Theme.accent)
                                     : (start.down ? Theme.toolbar : Theme.panelBackground)
            border.width: start.highlighted ? 0 : 1
            border.color: start.visualFocus ? Theme.accent : Theme.toolbarBorder
        }
        // The texts wrap: the content asks for a modest width, and takes what the column gives.
        contentItem: Item {
            implicitWidth: 240
            implicitHeight: row.implicitHeight
            RowLayout {
                id: row
                anchors.fill: parent
                spacing: Theme.spacing * 1.5
                Canvas {
                    id: picture
                    Layout.preferredWidth: 40
                    Layout.preferredHeight: 40
                    readonly property color ink: start.highlighted ? "#ffffff" : Theme.accent
                    onInkChanged: requestPaint()
                    onPaint: {
                        const c = getContext("2d")
                        c.reset()
                        c.lineWidth = 3
                        c.lineJoin = "round"
                        c.lineCap = "round"
                        c.strokeStyle = ink
                        c.fillStyle = ink
                        c.beginPath()
                        if (start.glyph === "curve") {
                            c.moveTo(4, 34)
                            c.bezierCurveTo(10, 2, 30, 2, 36, 34)
                            c.stroke()
                            for (const p of [[4, 34], [36, 34]]) {
                                c.beginPath()
                                c.arc(p[0], p[1], 4, 0, 2 * Math.PI)
                                c.fill()
                            }
                        } else if (start.glyph === "folder") {
                            c.moveTo(4, 10)
                            c.lineTo(15, 10)
                            c.lineTo(19, 14)
                            c.lineTo(36, 14)
                            c.lineTo(36, 33)
                            c.lineTo(4, 33)
                            c.closePath()
                            c.stroke()
                        } else {
                            c.rect(4, 7, 32, 26)
                            c.stroke()
                            c.beginPath()
                            c.moveTo(8, 29)
                            c.lineTo(17, 18)
                            c.lineTo(23, 24)
                            c.lineTo(27, 20)
                            c.lineTo(32, 29)
                            c.stroke()
                            c.beginPath()
                            c.arc(28, 13, 3, 0, 2 * Math.PI)
                            c.fill()
                        }
                    }
                }
                ColumnLayout {
                    Layout.fillWidth: true
                    spacing: 2
                    Label {
                        Layout.fillWidth: true
                        text: start.text
                        font.bold: true
                        font.pixelSize: start.font.pixelSize * 1.15
                        color: start.highlighted ? "#ffffff" : Theme.toolbarText
                        wrapMode: Text.Wrap
                    }
                    Label {
                        Layout.fillWidth: true
                        text: start.detail
                        color: start.highlighted ? "#e8f0fb" : Theme.mutedText
                        wrapMode: Text.Wrap
                    }
                }
            }
        }
    }
}
