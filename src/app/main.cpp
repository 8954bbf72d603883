// kontur: the application. Everything is in the libraries; this only starts it.
#include "app/application.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QQmlApplicationEngine>

int main(int argc, char *argv[])
{
    QCoreApplication::setApplicationName(QStringLiteral("kontur"));
    QCoreApplication::setOrganizationName(QStringLiteral("Kontur"));
    QCoreApplication::setApplicationVersion(QStringLiteral(KONTUR_VERSION));

    kontur::StartOptions options;
    if (kontur::isTextOnlyRequest(argc, argv)) {
        // --help and --version need no display: answer them without a GUI application.
        QCoreApplication app(argc, argv);
        return kontur::parseCommandLine(app, options) ? 0 : 2;
    }

    QGuiApplication app(argc, argv);
    QGuiApplication::setApplicationDisplayName(QStringLiteral("Kontur"));
    QGuiApplication::setDesktopFileName(QStringLiteral("org.kontur.Kontur"));
    if (!kontur::parseCommandLine(app, options))
        return 2;
    QQmlApplicationEngine engine;
    if (!kontur::loadMainWindow(engine, options))
        return 1;
    return QGuiApplication::exec();
}
