// CoordinatesTable: the seed's coordinates window for the selected curve. X and Y are typed in the
// UI language's number format; "OK" applies the typed cells as one undo step (a cell not typed is
// not sent: it keeps its full double, whatever the table shows of it), "Reset" drops the typing,
// rows are added and deleted within the kind's limits, and the table can be copied with every digit.
pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Kontur
import Kontur.Models

ColumnLayout {
    id: table

    required property EditController editor
    // Typed but not yet applied: row → {x, y} texts, only the axes typed.
    property var edits: ({})
    readonly property bool dirty: Object.keys(edits).length > 0

    function edit(row, axis, text) {
        const copy = Object.assign({}, edits)
        const entry = Object.assign({}, copy[row] ?? {})
        entry[axis] = text
        copy[row] = entry
        edits = copy
    }
    function apply() {
        // Only what was typed goes to C++: {row, x} or {row, y} or both.
        const list = []
        for (const key of Object.keys(edits))
            list.push(Object.assign({ row: Number(key) }, edits[key]))
        if (editor.commands.applyEdits(editor.selection.curveId, list))
            edits = ({})
    }

    spacing: 0
    // What was typed for one curve is dropped when the table shows another. The rows' delegates
    // stay (the model announces the other curve's data in the rows both have), so the table also
    // goes back to its first row and no cell stays being edited, as when every row was made anew.
    Connections {
        target: table.editor.points
        function onCurveChanged() {
            table.edits = ({})
            rows.positionViewAtBeginning()
            if (rows.activeFocus)
                rows.focus = false
        }
    }

    RowLayout {
        Layout.fillWidth: true
        Layout.leftMargin: 2 * Theme.spacing
        Layout.rightMargin: 2 * Theme.spacing
        Item { Layout.preferredWidth: 40 }
        // With the document's unit (px, or mm, cm or in once the background is calibrated).
        Label {
            objectName: "xHeader"
            text: "X, " + Numbers.unit(table.editor.document.units, Language.current)
            color: Theme.mutedText; horizontalAlignment: Text.AlignHCenter; Layout.fillWidth: true
        }
        Label {
            objectName: "yHeader"
            text: "Y, " + Numbers.unit(table.editor.document.units, Language.current)
            color: Theme.mutedText; horizontalAlignment: Text.AlignHCenter; Layout.fillWidth: true
        }
    }
    ListView {
        id: rows
        objectName: "pointList"
        Layout.fillWidth: true
        // From the row count (every row is touchMinimum tall), not contentHeight: a ListView only
        // estimates that while it creates delegates, and each new estimate laid the panel out again
        // and cost the canvas a frame, for as many frames as the curve has rows.
        Layout.preferredHeight: Math.min(count, 8) * Theme.touchMinimum
        clip: true
        // The selected row is drawn by its delegate. Without this, the view still makes an empty
        // highlight item for its current row and animates its width to the row's for seconds after
        // the panel is laid out, and every animation step is a frame of the whole window.
        highlightFollowsCurrentItem: false
        // Rows are made when shown, never ahead in the background: Qt 6.4 cancels a row still being
        // made ahead by its old index after the model was reset (a curve deleted), and warns
        // "DelegateModel::cancel: index out range" (found by the random-input run, seed 281756240).
        cacheBuffer: 0
        model: table.editor.points
        delegate: ItemDelegate {
            id: pointRow
            required property int index
            // The roles are named x and y like the coordinates window; read them through
            // `model` because an Item has x and y of its own.
            required property var model
            // Looked up only while something is typed: the row number as a key is a new string.
            readonly property var typed: table.dirty ? table.edits[index] ?? null : null
            width: ListView.view.width
            height: Theme.touchMinimum
            // The cells are the row's whole height: touch targets of Theme.touchMinimum.
            topPadding: 0
            bottomPadding: 0
            // `table` is null while the section that holds the table is being destroyed (nothing
            // selected any more) and a row not yet gone hears of the selected point once more.
            highlighted: index === table?.editor.selection.point
            onClicked: table.editor.selection.selectPoint(table.editor.selection.curveId, index)
            Accessible.name: pointRow.model.label ?? ""
            contentItem: RowLayout {
                Label {
                    text: pointRow.model.label
                    font.bold: true
                    color: pointRow.model.editable ? Theme.curve : Theme.mutedText
                    Layout.preferredWidth: 40
                }
                TextField {
                    objectName: "x" + pointRow.index
                    // Read out as the row and the column ("C1 X, mm"): a screen reader said nothing.
                    Accessible.name: (pointRow.model.label ?? "") + " X, " + table.editor.document.units
                    Layout.fillWidth: true
                    Layout.preferredHeight: Theme.touchMinimum
                    Layout.minimumWidth: 0
                    Layout.preferredWidth: 1 // the two columns share the width
                    horizontalAlignment: Text.AlignRight
                    readOnly: !pointRow.model.editable
                    inputMethodHints: Qt.ImhFormattedNumbersOnly
                    // Rounded to fit (exponent form for very large and very small values); every
                    // digit while the cell is being edited. The model formats both in the UI language.
                    // A row on its way out (its curve no longer shown) has no data: empty, not a warning.
                    text: pointRow.typed?.x ?? (activeFocus ? pointRow.model.xExact : pointRow.model.xText) ?? ""
                    onTextEdited: table.edit(pointRow.index, "x", text)
                    onAccepted: table.apply()
                }
                TextField {
                    objectName: "y" + pointRow.index
                    // Read out as the row and the column ("C1 Y, mm"): a screen reader said nothing.
                    Accessible.name: (pointRow.model.label ?? "") + " Y, " + table.editor.document.units
                    Layout.fillWidth: true
                    Layout.preferredHeight: Theme.touchMinimum
                    Layout.minimumWidth: 0
                    Layout.preferredWidth: 1
                    horizontalAlignment: Text.AlignRight
                    readOnly: !pointRow.model.editable
                    inputMethodHints: Qt.ImhFormattedNumbersOnly
                    text: pointRow.typed?.y ?? (activeFocus ? pointRow.model.yExact : pointRow.model.yText) ?? ""
                    onTextEdited: table.edit(pointRow.index, "y", text)
                    onAccepted: table.apply()
                }
            }
        }
    }
    Flow {
        Layout.fillWidth: true
        // A Flow's height follows its width: the layout must ask for what the wrapped rows need.
        Layout.preferredHeight: implicitHeight
        Layout.leftMargin: Theme.spacing
        Button {
            objectName: "applyCoordinatesButton"
            text: qsTr("OK")
            enabled: table.dirty
            highlighted: table.dirty
            onClicked: table.apply()
        }
        Button {
            //: Button: throws away the values typed in the table; the curve stays as it was.
            text: qsTr("Reset")
            flat: true
            enabled: table.dirty
            onClicked: table.edits = ({})
        }
        Button {
            objectName: "addRowButton"
            text: qsTr("Add row")
            flat: true
            onClicked: table.editor.commands.addRowAfterSelection()
        }
        Button {
            objectName: "deleteRowButton"
            text: qsTr("Delete row")
            flat: true
            enabled: table.editor.selection.point >= 0
            onClicked: table.editor.commands.deleteSelectedRow()
        }
        Button {
            text: qsTr("Copy")
            flat: true
            onClicked: {
                clipboardHelper.text = table.editor.commands.coordinatesText(table.editor.selection.curveId)
                clipboardHelper.selectAll()
                clipboardHelper.copy()
            }
        }
    }
    // Qt Quick has no clipboard object; a hidden text editor's copy() reaches the system clipboard.
    TextEdit {
        id: clipboardHelper
        visible: false
    }
}
