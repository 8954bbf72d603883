// Loading Kontur's translations and Qt's own, shared by the app and kontur-cli (Qt Core only).
// The .qm files are embedded under :/i18n/ by each executable's CMake (qt_add_translations, qt_add_lrelease).
#pragma once

#include <QString>
#include <QStringList>
#include <QTranslator>

#include <memory>

namespace kontur {

// The codes Kontur is translated to, English (the source language) first.
[[nodiscard]] QStringList translationCodes();
// The first language of the system's UI languages (LANGUAGE, LC_ALL, LC_MESSAGES, LANG) that Kontur
// has, else English.
[[nodiscard]] QString systemTranslationCode();
// The value of --lang CODE or --lang=CODE in `args` (args[0] is the program), or empty. Read before
// QCommandLineParser runs, so that its help text is already translated.
[[nodiscard]] QString requestedLanguage(const QStringList &args);

// Installs the translator for `code` into the application. Returns the translator to keep alive, or
// null for English or an unknown code.
[[nodiscard]] std::unique_ptr<QTranslator> installTranslator(const QString &code);
// The same for Qt's own strings (standard buttons, dialogs, QCommandLineParser), when the system has
// them (Debian: qt6-translations-l10n).
[[nodiscard]] std::unique_ptr<QTranslator> installQtTranslator(const QString &code);

} // namespace kontur
