// Start-up shared by the kontur executable and the end-to-end tests: command line, style,
// language, and loading the main window.
#pragma once

#include <QSize>
#include <QString>

class QCoreApplication;
class QQmlApplicationEngine;
class QQuickWindow;

namespace kontur {

struct StartOptions
{
    QString language; // a code from Language::codes()
    QString file;     // a document to open, or empty
    // The window's size from its start, so that its first frame already has the layout of its
    // shape. Empty: 1100×720, or less where the primary screen's free area is smaller.
    QSize size;
};

// True when the command line only asks for text (--help, --version): no display is needed.
[[nodiscard]] bool isTextOnlyRequest(int argc, char **argv);

// Parses kontur's command line. Prints help or version and exits the process for -h / -v;
// returns false (after printing why) for a bad option value.
[[nodiscard]] bool parseCommandLine(const QCoreApplication &app, StartOptions &options);

// Registers the QML modules, applies the language and loads Main.qml into `engine`.
// Returns the main window, or null when loading failed (QML's errors are printed).
[[nodiscard]] QQuickWindow *loadMainWindow(QQmlApplicationEngine &engine, const StartOptions &options);

} // namespace kontur
