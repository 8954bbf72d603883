// kontur-cli: the headless command-line tool. It works on files and prints JSON results for scripts:
// fit, bezier, composite, spline, and bench (timings of the geometry core).
#include "cli/commands.h"
#include "cli/iocommands.h"
#include "cli/splinecommand.h"
#include "cli/tracecommand.h"
#include "io/translations.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QTextStream>

#include <algorithm>
#include <memory>
#include <utility>

namespace {

void usage(QTextStream &out)
{
    out << QCoreApplication::translate(
        "kontur::cli", "Usage: kontur-cli <command> [options]   (kontur-cli <command> --help for its options)\n"
                       "Kontur command-line tool: Bézier curves and splines without a window.\n\n"
                       "Commands:\n"
                       "  fit        cubic through 4 points or least-squares cubic through n >= 4 points\n"
                       "  bezier     evaluate, elevate, measure and query a Bézier curve of any degree\n"
                       "  composite  the composite curve through knots, with its continuity report\n"
                       "  spline     a curve of any kind through points, built as the app builds it (bezier,\n"
                       "             composite, natural, clamped, hermite, bspline, function-spline, contour, …)\n"
                       "  convert    convert IN OUT between points text (.txt), CSV, .kontur, SVG, DXF and PDF (by\n"
                       "             extension; a PDF output is the pattern printed at true size)\n"
                       "  info       the curves of a file as JSON: kinds, lengths, bounding box, continuity\n"
                       "  offset     seam allowances: offset curves IN OUT at a distance, outside or inside\n"
                       "  trace      trace a pattern photographed beside a reference sheet into a document in mm\n"
                       "  bench      time an operation of the geometry core (for developers)\n\n"
                       "Input files hold one \"x y\" pair per line; '#' starts a comment. Output is JSON on stdout;\n"
                       "errors go to stderr with exit code 1 (bad input) or 2 (bad usage).\n");
    out << QCoreApplication::translate(
               "kontur::cli",
               "\nFor every command:\n  --lang CODE  the language of help and messages: %1 (default: the system's)\n")
               .arg(kontur::translationCodes().join(QStringLiteral(", ")));
}

// Removes "--lang CODE" or "--lang=CODE" wherever it is, so that the commands' own parsers never see it.
QStringList withoutLanguage(QStringList args)
{
    for (qsizetype i = 1; i < args.size();) {
        if (args[i] == QLatin1String("--lang"))
            args.remove(i, std::min<qsizetype>(2, args.size() - i));
        else if (args[i].startsWith(QLatin1String("--lang=")))
            args.remove(i);
        else
            ++i;
    }
    return args;
}

// Whether the command writes a PDF: painting its text needs Qt Gui's fonts, so a QGuiApplication on
// the offscreen platform (no display needed) instead of a QCoreApplication.
bool needsGui(int argc, char *argv[])
{
    bool convert = false, pdf = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        convert = convert || arg == "convert";
        pdf = pdf || arg.toLower().endsWith(".pdf");
    }
    return convert && pdf;
}

// The offscreen platform warns on stderr when XDG_RUNTIME_DIR is not set (as under cron, ssh or ctest);
// kontur-cli's stderr is for its own messages, so that one is dropped and every other is passed on.
QtMessageHandler g_defaultHandler = nullptr;
void quietRuntimeDirWarning(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if (type == QtWarningMsg && message.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    g_defaultHandler(type, context, message);
}

} // namespace

int main(int argc, char *argv[])
{
    std::unique_ptr<QCoreApplication> application;
    if (needsGui(argc, argv)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        g_defaultHandler = qInstallMessageHandler(quietRuntimeDirWarning);
        application = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        application = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("kontur-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(KONTUR_VERSION));

    // Messages and help in the language asked for with --lang, else in the system's (LANGUAGE,
    // LC_MESSAGES, LANG) when Kontur has it; numbers in files and JSON stay locale-independent.
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QString requested = kontur::requestedLanguage(QCoreApplication::arguments());
    if (!requested.isEmpty() && !kontur::translationCodes().contains(requested)) {
        //: %1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.
        err << QCoreApplication::translate("kontur::cli", "%1: unknown language \"%2\"; choose one of: %3.")
                   .arg(QStringLiteral("kontur-cli"), requested, kontur::translationCodes().join(QStringLiteral(", ")))
            << '\n';
        return 2;
    }
    const QString language = requested.isEmpty() ? kontur::systemTranslationCode() : requested;
    const std::unique_ptr<QTranslator> translator = kontur::installTranslator(language);
    const std::unique_ptr<QTranslator> qtTranslator = kontur::installQtTranslator(language);

    const QStringList args = withoutLanguage(QCoreApplication::arguments());
    if (args.size() < 2) {
        usage(err);
        return 2;
    }
    const QString command = args.at(1);
    // The command's own parser sees "kontur-cli <command> [options]" with the command as its name.
    QStringList rest = args.mid(1);
    rest.first() = args.first() + QLatin1Char(' ') + command;
    using Run = int (*)(const QStringList &);
    static const std::pair<const char *, Run> commands[] = {
        {"fit", kontur::cli::runFit},
        {"bezier", kontur::cli::runBezier},
        {"composite", kontur::cli::runComposite},
        {"spline", kontur::cli::runSpline},
        {"convert", kontur::cli::runConvert},
        {"info", kontur::cli::runInfo},
        {"offset", kontur::cli::runOffset},
        {"trace", kontur::cli::runTrace},
        {"bench", kontur::cli::runBench},
    };
    for (const auto &[name, run] : commands)
        if (command == QLatin1String(name))
            return run(rest);
    if (command == QLatin1String("--help") || command == QLatin1String("-h") || command == QLatin1String("help")) {
        usage(out);
        return 0;
    }
    if (command == QLatin1String("--version") || command == QLatin1String("-v")) {
        out << "kontur-cli " << QCoreApplication::applicationVersion() << '\n';
        return 0;
    }
    err << QCoreApplication::translate("kontur::cli", "kontur-cli: unknown command \"%1\"").arg(command) << '\n';
    usage(err);
    return 2;
}
