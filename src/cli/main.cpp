// kontur-cli: the headless command-line tool. It works on files and prints JSON results for scripts:
// fit, bezier, composite, spline, and bench (timings of the geometry core).
#include "cli/commands.h"
#include "cli/iocommands.h"
#include "cli/splinecommand.h"

#include <QCoreApplication>
#include <QTextStream>

namespace {

void usage(QTextStream &out)
{
    out << QCoreApplication::translate(
        "cli", "Usage: kontur-cli <command> [options]   (kontur-cli <command> --help for its options)\n"
               "Kontur command-line tool: Bézier curves and splines without a window.\n\n"
               "Commands:\n"
               "  fit        cubic through 4 points or least-squares cubic through n >= 4 points\n"
               "  bezier     evaluate, elevate, measure and query a Bézier curve of any degree\n"
               "  composite  the composite curve through knots, with its continuity report\n"
               "  spline     the spline families through points (natural, clamped, not-a-knot, periodic,\n"
               "             catmull-rom, hermite, bspline, global-bspline, polynomial)\n"
               "  convert    convert IN OUT between points text (.txt), CSV, .kontur and SVG (by extension)\n"
               "  info       the curves of a file as JSON: kinds, lengths, bounding box, continuity\n"
               "  bench      time an operation of the geometry core\n\n"
               "Input files hold one \"x y\" pair per line; '#' starts a comment. Output is JSON on stdout;\n"
               "errors go to stderr with exit code 1 (bad input) or 2 (bad usage).\n");
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("kontur-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(KONTUR_VERSION));

    const QStringList args = QCoreApplication::arguments();
    QTextStream out(stdout);
    QTextStream err(stderr);
    if (args.size() < 2) {
        usage(err);
        return 2;
    }
    const QString command = args.at(1);
    // The command's own parser sees "kontur-cli <command> [options]" with the command as its name.
    QStringList rest = args.mid(1);
    rest.first() = args.first() + QLatin1Char(' ') + command;
    if (command == QLatin1String("fit"))
        return kontur::cli::runFit(rest);
    if (command == QLatin1String("bezier"))
        return kontur::cli::runBezier(rest);
    if (command == QLatin1String("composite"))
        return kontur::cli::runComposite(rest);
    if (command == QLatin1String("spline"))
        return kontur::cli::runSpline(rest);
    if (command == QLatin1String("convert"))
        return kontur::cli::runConvert(rest);
    if (command == QLatin1String("info"))
        return kontur::cli::runInfo(rest);
    if (command == QLatin1String("bench"))
        return kontur::cli::runBench(rest);
    if (command == QLatin1String("--help") || command == QLatin1String("-h") || command == QLatin1String("help")) {
        usage(out);
        return 0;
    }
    if (command == QLatin1String("--version") || command == QLatin1String("-v")) {
        out << "kontur-cli " << QCoreApplication::applicationVersion() << '\n';
        return 0;
    }
    err << QCoreApplication::translate("cli", "kontur-cli: unknown command \"%1\"").arg(command) << '\n';
    usage(err);
    return 2;
}
