// WrappingChoiceBox: a ChoiceBox for a column of fixed width whose choice may be longer than the column
// ("Сплайн с заданными производными на концах (C-сплайн)" in 300 px): the choice wraps onto a second line
// where Material's box shows it in a field that cuts it. Not for a box sized to its widest entry
// (ComboBox.WidestText): Qt 6.4 measures the entries only for a field.
import QtQuick
import QtQuick.Controls

ChoiceBox {
    id: box

    // Material's paddings for a box that is not editable.
    contentItem: Label {
        leftPadding: box.mirrored ? 0 : 12
        rightPadding: box.mirrored ? 12 : 0
        topPadding: 6
        bottomPadding: 6
        text: box.displayText
        font: box.font
        wrapMode: Text.Wrap
        verticalAlignment: Text.AlignVCenter
    }
}
