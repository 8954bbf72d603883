// ChoiceBox: a ComboBox that shows `chosen` (bound by its user to the model's state) also after its
// list of texts is replaced, as translated lists are on every language switch. A ComboBox moves to
// its first entry when its model changes, and a binding on currentIndex is not asked again then.
// An entry longer than the box is wrapped onto a second line in its list (Material's list elides it);
// WrappingChoiceBox wraps the choice shown in the box too.
import QtQuick
import QtQuick.Controls
import QtQuick.Controls.Material

ComboBox {
    id: box

    property int chosen: 0

    currentIndex: chosen
    onModelChanged: currentIndex = Qt.binding(() => box.chosen)
    // Qt 6.4 measures the widest entry (ComboBox.WidestText) when the model changes but not when the
    // font does (presentation mode): setting the policy anew measures again.
    onFontChanged: {
        if (implicitContentWidthPolicy === ComboBox.WidestText) {
            implicitContentWidthPolicy = ComboBox.ContentItemImplicitWidth
            implicitContentWidthPolicy = ComboBox.WidestText
        }
    }

    // Material's entry, its text wrapped.
    delegate: MenuItem {
        id: entry
        width: ListView.view.width
        text: box.textRole ? (Array.isArray(box.model) ? modelData[box.textRole] : model[box.textRole]) : modelData
        Material.foreground: box.currentIndex === index ? ListView.view.contentItem.Material.accent
                                                        : ListView.view.contentItem.Material.foreground
        highlighted: box.highlightedIndex === index
        hoverEnabled: box.hoverEnabled
        contentItem: Label {
            text: entry.text
            font: entry.font
            color: entry.Material.foreground
            wrapMode: Text.Wrap
            verticalAlignment: Text.AlignVCenter
        }
    }
}
