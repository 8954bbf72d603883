// kontur-cli fit, bezier and composite (see commands.h and the issue's command list).
#include "cli/commands.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "cli/pointfile.h"
#include "geometry/arclength.h"
#include "geometry/composite.h"
#include "geometry/fit.h"
#include "geometry/nearest.h"
#include "geometry/piecewise.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

namespace kontur::cli {

namespace {

// Reads --in, requiring at least `minimum` points; on failure prints the message and returns false.
// `tooFew` is the whole translated sentence for too few points (%1 the file, %2 its count), so each
// language words it for its own curve, not around an English name.
bool readInput(const QCommandLineParser &parser, std::size_t minimum, const QString &tooFew, PointFile &file, int &code)
{
    if (!parser.isSet(QStringLiteral("in"))) {
        code = fail(tr("--in FILE is required"), 2);
        return false;
    }
    const QString path = parser.value(QStringLiteral("in"));
    file = readPointFile(path);
    if (!file.error.isEmpty()) {
        code = fail(file.error);
        return false;
    }
    if (file.points.size() < minimum) {
        code = fail(tooFew.arg(path).arg(file.points.size()));
        return false;
    }
    return true;
}

// A geometry error about the points of `file`, with the file's name (every error about a file names it).
int geometryError(const PointFile &file, const geo::Error &error)
{
    return fail(QStringLiteral("%1: %2").arg(file.path, QString::fromStdString(error.message)));
}

} // namespace

int runFit(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(tr("Fit a cubic Bézier curve to points (one \"x y\" per line)."));
    parser.addOptions({
        {QStringLiteral("method"), tr("interpolate (exactly 4 points) or least-squares."), QStringLiteral("method"),
         QStringLiteral("least-squares")},
        {QStringLiteral("param"), tr("uniform, chord or centripetal."), QStringLiteral("param"),
         QStringLiteral("chord")},
        {QStringLiteral("in"), tr("The points file."), QStringLiteral("file")},
        {QStringLiteral("reparameterize"),
         tr("Rounds of parameter correction (default 0: the parameters are used as computed)."),
         QStringLiteral("rounds"), QStringLiteral("0")},
    });
    if (const int code = parseCommandLine(parser, args); code != 0)
        return code < 0 ? 0 : code;
    const QString method = parser.value(QStringLiteral("method"));
    if (method != QLatin1String("interpolate") && method != QLatin1String("least-squares"))
        return fail(tr("unknown --method \"%1\" (interpolate or least-squares)").arg(method), 2);
    geo::Parameterization param;
    if (const int code = readParam(parser, param); code != 0)
        return code;
    bool roundsOk = false;
    const int rounds = parser.value(QStringLiteral("reparameterize")).toInt(&roundsOk);
    if (!roundsOk || rounds < 0)
        return fail(tr("--reparameterize needs a non-negative integer"), 2);

    PointFile file;
    int code = 0;
    const bool interpolate = method == QLatin1String("interpolate");
    //: %1 is a file name, %2 the number of points in it.
    const QString tooFew = interpolate ? tr("%1: %2 points; interpolate needs exactly 4")
                                       //: %1 is a file name, %2 the number of points in it.
                                       : tr("%1: %2 points; a least-squares cubic needs at least 4");
    if (!readInput(parser, 4, tooFew, file, code))
        return code;
    if (interpolate && file.points.size() != 4)
        return fail(tr("%1: %2 points; interpolate needs exactly 4")
                        .arg(parser.value(QStringLiteral("in")))
                        .arg(file.points.size()));
    const auto fit = interpolate ? geo::interpolateCubic(file.points, param)
                                 : geo::fitCubic(file.points, geo::FitOptions{geo::exponentOf(param), rounds, false});
    if (!fit)
        return geometryError(file, fit.error());
    Json json;
    json.beginObject();
    json.key("control_points").points(fit->control);
    json.key("params").numbers(fit->params);
    json.key("rms").value(fit->rms);
    json.key("max_error").value(fit->maxError);
    json.endObject();
    return printResult(json);
}

int runBezier(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Work with the Bézier curve whose control points are in the file. Prints the control points (JSON key "
           "control_points) when --elevate is given or when nothing else is asked for."));
    parser.addOptions({
        {QStringLiteral("in"), tr("The control points file."), QStringLiteral("file")},
        {QStringLiteral("elevate"), tr("Elevate the degree R times."), QStringLiteral("R")},
        {QStringLiteral("at"), tr("Evaluate at t1,t2,…"), QStringLiteral("t-list")},
        {QStringLiteral("length"), tr("Arc length to this absolute accuracy."), QStringLiteral("accuracy")},
        {QStringLiteral("nearest"), tr("Nearest point to x,y."), QStringLiteral("x,y")},
        {QStringLiteral("bbox"), tr("The tight bounding box.")},
    });
    if (const int code = parseCommandLine(parser, args); code != 0)
        return code < 0 ? 0 : code;
    PointFile file;
    int code = 0;
    //: %1 is a file name, %2 the number of points in it.
    if (!readInput(parser, 2, tr("%1: %2 points; a Bézier curve needs at least 2"), file, code))
        return code;
    geo::Bezier curve(file.points);

    const bool elevate = parser.isSet(QStringLiteral("elevate"));
    if (elevate) {
        bool ok = false;
        const int r = parser.value(QStringLiteral("elevate")).toInt(&ok);
        if (!ok || r < 0 || r > 10000)
            return fail(tr("--elevate needs an integer from 0 to 10000"), 2);
        curve = curve.elevated(r);
    }
    std::vector<double> ts;
    if (const int code = readAt(parser, ts); code != 0)
        return code;
    double accuracy = 0.0;
    if (parser.isSet(QStringLiteral("length"))) {
        const auto a = parseNumber(parser.value(QStringLiteral("length")).toStdString());
        if (!a || !(*a > 0.0))
            return fail(tr("--length needs a positive accuracy"), 2);
        accuracy = *a;
    }
    geo::Point query = geo::Point::Zero();
    if (parser.isSet(QStringLiteral("nearest"))) {
        const auto xy = parseNumberList(parser.value(QStringLiteral("nearest")).toStdString());
        if (!xy || xy->size() != 2)
            return fail(tr("--nearest needs x,y"), 2);
        query = geo::Point((*xy)[0], (*xy)[1]);
    }
    const bool anything = parser.isSet(QStringLiteral("at")) || accuracy > 0.0 ||
                          parser.isSet(QStringLiteral("nearest")) || parser.isSet(QStringLiteral("bbox"));

    Json json;
    json.beginObject();
    if (elevate || !anything)
        json.key("control_points").points(curve.controlPoints());
    if (parser.isSet(QStringLiteral("at"))) {
        json.key("points").beginArray();
        for (double t : ts)
            json.point(curve.eval(t));
        json.endArray();
    }
    if (accuracy > 0.0) {
        const geo::LengthEstimate length = geo::arcLengthEstimate(curve, 0.0, 1.0, accuracy);
        json.key("length").value(length.length);
        json.key("length_accuracy").value(length.accuracy);
    }
    if (parser.isSet(QStringLiteral("nearest"))) {
        const geo::Nearest n = geo::nearest(curve, query);
        json.key("nearest").beginObject();
        json.key("t").value(n.t);
        json.key("point").point(n.point);
        json.key("distance").value(n.distance);
        json.endObject();
    }
    if (parser.isSet(QStringLiteral("bbox"))) {
        const geo::Box box = curve.boundingBox();
        json.key("bbox").beginArray().point(box.min()).point(box.max()).endArray();
    }
    json.endObject();
    return printResult(json);
}

int runComposite(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(tr("Build the composite curve through the knots in the file."));
    parser.addOptions({
        {QStringLiteral("in"), tr("The knots file."), QStringLiteral("file")},
        {QStringLiteral("closed"), tr("Close the curve.")},
        {QStringLiteral("tolerance"), tr("Relative tolerance of the continuity report (default 1e-9)."),
         QStringLiteral("tolerance"), QStringLiteral("1e-9")},
    });
    if (const int code = parseCommandLine(parser, args); code != 0)
        return code < 0 ? 0 : code;
    const auto tolerance = parseNumber(parser.value(QStringLiteral("tolerance")).toStdString());
    if (!tolerance || !(*tolerance >= 0.0))
        return fail(tr("--tolerance needs a non-negative number"), 2);
    PointFile file;
    int code = 0;
    const bool closed = parser.isSet(QStringLiteral("closed"));
    //: %1 is a file name, %2 the number of points in it.
    const QString tooFew = closed ? tr("%1: %2 points; a closed composite curve needs at least 3")
                                  //: %1 is a file name, %2 the number of points in it.
                                  : tr("%1: %2 points; a composite curve needs at least 2");
    if (!readInput(parser, closed ? 3 : 2, tooFew, file, code))
        return code;
    geo::CompositeCurve curve(file.points);
    if (closed) {
        if (auto r = curve.close(); !r)
            return geometryError(file, r.error());
    }
    Json json;
    json.beginObject();
    json.key("control_points").points(curve.controlPoints());
    json.key("closed").value(curve.isClosed());
    json.key("continuity").beginArray();
    for (const geo::JointContinuity &j : curve.toPiecewise().continuity(*tolerance)) {
        json.beginObject();
        json.key("knot").value(j.right);
        json.key("level").value(geo::nameOf(j.level));
        json.key("G0").value(j.g0);
        json.key("G1").value(j.g1);
        json.key("C1").value(j.c1);
        json.key("G2").value(j.g2);
        json.key("C2").value(j.c2);
        json.key("gap").value(j.gap);
        json.key("angle").value(j.angle);
        json.key("c1_jump").value(j.c1Jump);
        json.key("curvature_jump").value(j.curvatureJump);
        json.key("c2_jump").value(j.c2Jump);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return printResult(json);
}

} // namespace kontur::cli
