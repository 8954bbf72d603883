// Qt's own texts that Kontur's dialogs show, under Qt's own contexts, for the languages where Debian's
// qt6-translations-l10n (Qt 6.4) has none: Slovak lacks every standard button text (QPlatformTheme,
// QGnomeTheme), and no language has the labels of Qt Quick's file dialog (FileDialog). lupdate collects
// them into i18n/*.ts; at run time QCoreApplication asks every installed translator, Qt's first (it is
// installed last), so Kontur's translation only answers where Qt's has nothing.
#include <QtGlobal>

namespace kontur {

struct QtString
{
    const char *context;
    const char *source;
};

// Not read by code: the table is for lupdate; tst_scenarios (dialogsSpeakTheLanguage) checks the screen.
extern const QtString kQtDialogStrings[];
const QtString kQtDialogStrings[] = {
    // The standard buttons of Qt Quick's file dialog (QPlatformTheme::defaultStandardButtonText;
    // GNOME desktops use QGnomeTheme's). Kontur's own dialogs have buttons of their own (Main.qml).
    {"QPlatformTheme", QT_TRANSLATE_NOOP("QPlatformTheme", "Open")},
    {"QPlatformTheme", QT_TRANSLATE_NOOP("QPlatformTheme", "Save")},
    {"QPlatformTheme", QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel")},
    {"QGnomeTheme", QT_TRANSLATE_NOOP("QGnomeTheme", "&Save")},
    {"QGnomeTheme", QT_TRANSLATE_NOOP("QGnomeTheme", "&Cancel")},
    // The labels of Qt Quick's own file dialog (QtQuick.Dialogs, non-native).
    {"FileDialog", QT_TRANSLATE_NOOP("FileDialog", "File name")},
    {"FileDialog", QT_TRANSLATE_NOOP("FileDialog", "Filter")},
};

} // namespace kontur
