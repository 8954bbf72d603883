// The options several kontur-cli commands share (see options.h).
#include "cli/options.h"
#include "cli/output.h"

#include "cli/pointfile.h"

#include <QCoreApplication>

namespace kontur::cli {

int parseCommandLine(QCommandLineParser &parser, const QStringList &args, int positional)
{
    parser.addHelpOption();
    if (!parser.parse(args))
        return fail(parser.errorText(), 2);
    if (parser.isSet(QStringLiteral("help"))) {
        printHelp(parser, args);
        return -1;
    }
    const QStringList given = parser.positionalArguments();
    if (positional == 0 && !given.isEmpty())
        return fail(tr("unexpected argument \"%1\"").arg(given.first()), 2);
    if (given.size() != positional)
        return fail(QCoreApplication::translate("kontur::cli", "expected %n file name(s), got %1", nullptr, positional)
                        .arg(given.size()),
                    2);
    return 0;
}

int readParam(const QCommandLineParser &parser, geo::Parameterization &out)
{
    const QString name = parser.value(QStringLiteral("param"));
    if (!geo::parseParameterization(name.toStdString(), out))
        return fail(tr("unknown --param \"%1\" (uniform, chord or centripetal)").arg(name), 2);
    return 0;
}

int readAt(const QCommandLineParser &parser, std::vector<double> &out)
{
    out.clear();
    if (!parser.isSet(QStringLiteral("at")))
        return 0;
    auto list = parseNumberList(parser.value(QStringLiteral("at")).toStdString());
    if (!list)
        return fail(tr("--at needs numbers separated by commas"), 2);
    out = std::move(*list);
    return 0;
}

} // namespace kontur::cli
