// Start-up: command line, Controls style, language, main window.
#include "app/application.h"

#include "app/language.h"
#include "io/fileio.h"
#include "io/translations.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickStyle>
#include <QQuickWindow>
#include <QScreen>
#include <QtQml/qqmlextensionplugin.h>

#include <cstring>
#include <iostream>

// The QML modules are static libraries: pull their plugins into every binary that starts the UI.
Q_IMPORT_QML_PLUGIN(KonturPlugin)
Q_IMPORT_QML_PLUGIN(Kontur_ModelsPlugin)

namespace kontur {

bool isTextOnlyRequest(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (std::strcmp(a, "-h") == 0 || std::strcmp(a, "--help") == 0 || std::strcmp(a, "-?") == 0 ||
            std::strcmp(a, "--help-all") == 0 || std::strcmp(a, "-v") == 0 || std::strcmp(a, "--version") == 0)
            return true;
    }
    return false;
}

bool parseCommandLine(const QCoreApplication &app, StartOptions &options)
{
    // Help is shown in the language asked for, so install its translator before building the text.
    static std::unique_ptr<QTranslator> helpTranslator;
    // Without --lang, the help follows the language the window would start in.
    // --lang is read before QCommandLineParser runs so that its help is translated.
    QString requested = requestedLanguage(app.arguments());
    if (requested.isEmpty())
        requested = Language::systemDefault();
    if (Language::isSupported(requested))
        helpTranslator = installTranslator(requested);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("cli", "Kontur: construct, modify and compare Bézier curves and splines."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption langOption(QStringLiteral("lang"),
                                        QCoreApplication::translate("cli", "Language of the user interface: %1.")
                                            .arg(Language::codes().join(QStringLiteral(", "))),
                                        QStringLiteral("code"));
    parser.addOption(langOption);
    parser.addPositionalArgument(QStringLiteral("file"),
                                 QCoreApplication::translate("cli", "A Kontur document to open."),
                                 QStringLiteral("[file]"));
    parser.process(app);

    options.language = parser.isSet(langOption) ? parser.value(langOption) : Language::systemDefault();
    if (!Language::isSupported(options.language)) {
        // The same message as kontur-cli's (one context, one translation); %1 is the program's name.
        //: %1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.
        std::cerr << qPrintable(
                         QCoreApplication::translate("kontur::cli", "%1: unknown language \"%2\"; choose one of: %3.")
                             .arg(QStringLiteral("kontur"), options.language,
                                  Language::codes().join(QStringLiteral(", "))))
                  << std::endl;
        return false;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        std::cerr << qPrintable(QCoreApplication::translate("cli", "kontur: give at most one file to open."))
                  << std::endl;
        return false;
    }
    if (!files.isEmpty()) {
        options.file = files.first();
        // Said as what it is: a folder, a named pipe or a link loop is no missing file.
        QString why;
        switch (io::fileKindOf(options.file)) {
        case io::FileKind::Regular:
            break;
        case io::FileKind::Missing:
        case io::FileKind::DanglingLink:
            why = QCoreApplication::translate("cli", "kontur: cannot open \"%1\": no such file.");
            break;
        case io::FileKind::LinkLoop:
            why = QCoreApplication::translate("cli", "kontur: cannot open \"%1\": its symbolic links form a loop.");
            break;
        case io::FileKind::NoPermission:
            why = QCoreApplication::translate("cli", "kontur: cannot open \"%1\": permission denied.");
            break;
        case io::FileKind::Folder:
            why = QCoreApplication::translate("cli", "kontur: cannot open \"%1\": it is a folder, not a file.");
            break;
        case io::FileKind::Pipe:
        case io::FileKind::Device:
        case io::FileKind::Other:
            why = QCoreApplication::translate(
                "cli", "kontur: cannot open \"%1\": it is not a regular file (a named pipe or a device).");
            break;
        }
        if (!why.isEmpty()) {
            std::cerr << qPrintable(why.arg(options.file)) << std::endl;
            return false;
        }
    }
    return true;
}

QQuickWindow *loadMainWindow(QQmlApplicationEngine &engine, const StartOptions &options)
{
    // A frame starts as soon as the events at hand are handled, not 5 ms later (Qt's default
    // pause to gather updates): a point follows the finger a frame sooner. Read by Qt at the
    // window's first update request; whoever set it explicitly keeps their value.
    if (!qEnvironmentVariableIsSet("QT_QPA_UPDATE_IDLE_TIME"))
        qputenv("QT_QPA_UPDATE_IDLE_TIME", "0");
    // Windows and item layers without depth and stencil buffers (Qt Quick's documented switches,
    // read when the first window is made): a flat 2D picture drawn back to front needs neither,
    // and clips here are all axis-aligned rectangles (scissors). Where the GPU is a software
    // rasterizer (Mesa's llvmpipe) a bound depth buffer alone sends every pixel down the general
    // shading path; without it plain fills and copies take the fast linear path, a third less
    // work a frame at 1280×800.
    for (const char *name : {"QSG_NO_DEPTH_BUFFER", "QSG_NO_STENCIL_BUFFER"})
        if (!qEnvironmentVariableIsSet(name))
            qputenv(name, "1");
    // Text through the platform's glyph rasterizer (hinted, cached glyph images) rather than
    // distance fields: as crisp at the sizes the UI uses, and about 2 ms a frame cheaper where
    // the GPU is a software rasterizer (Mesa's llvmpipe at 1280×800).
    QQuickWindow::setTextRenderType(QQuickWindow::NativeTextRendering);
    // Material: large touch targets by default, which suits tablets and projectors alike.
    QQuickStyle::setStyle(QStringLiteral("Material"));
    // Qt >= 6.5: the default import path includes qrc:/qt/qml and loadFromModule() can be used.
    engine.addImportPath(QStringLiteral("qrc:/qt/qml"));
    auto *language = new Language(&engine);
    language->setCurrent(options.language);
    // The document to open goes in before the window completes, so it opens with the window.
    // The size goes in before the window completes too: set afterwards, the window would first be
    // laid out (and drawn) for the shape it was made with, then again for its own.
    QSize size = options.size;
    if (size.isEmpty()) {
        size = QSize(1100, 720);
        if (const QScreen *screen = QGuiApplication::primaryScreen())
            size = size.boundedTo(screen->availableSize());
    }
    engine.setInitialProperties(
        {{QStringLiteral("startupFile"),
          options.file.isEmpty() ? QUrl() : QUrl::fromLocalFile(QFileInfo(options.file).absoluteFilePath())},
         {QStringLiteral("width"), size.width()},
         {QStringLiteral("height"), size.height()}});
    engine.load(QUrl(QStringLiteral("qrc:/qt/qml/Kontur/Main.qml")));
    if (engine.rootObjects().isEmpty())
        return nullptr;
    auto *window = qobject_cast<QQuickWindow *>(engine.rootObjects().constFirst());
    return window;
}

} // namespace kontur
