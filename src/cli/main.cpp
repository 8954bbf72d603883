// kontur-cli: the headless command-line tool. It works on files and prints results for scripts.
#include <QCoreApplication>
#include <QCommandLineParser>
#include <QTextStream>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("kontur-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(KONTUR_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("cli", "Kontur command-line tool: Bézier curves and splines without a window."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"), QCoreApplication::translate("cli", "The command to run."));
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.isEmpty()) {
        parser.showHelp(1);
    }
    QTextStream err(stderr);
    err << QCoreApplication::translate("cli", "kontur-cli: unknown command \"%1\"").arg(args.first()) << '\n';
    return 2;
}
