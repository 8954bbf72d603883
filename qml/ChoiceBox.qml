// ChoiceBox: a ComboBox that shows `chosen` (bound by its user to the model's state) also after its
// list of texts is replaced, as translated lists are on every language switch. A ComboBox moves to
// its first entry when its model changes, and a binding on currentIndex is not asked again then.
import QtQuick
import QtQuick.Controls

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
}
