// kontur-cli spline (see splinecommand.h and issue 4's command line): the options become a curve
// record, geo::CurveParts, and geo::buildShape draws it, the same function the app's curves use.
#include "cli/splinecommand.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "cli/pointfile.h"
#include "geometry/composite.h"
#include "geometry/curveshape.h"
#include "geometry/piecewise.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace kontur::cli {

namespace {

std::optional<geo::Point> parsePoint(const QString &text)
{
    const auto xy = parseNumberList(text.toStdString());
    if (!xy || xy->size() != 2)
        return std::nullopt;
    return geo::Point((*xy)[0], (*xy)[1]);
}

// The largest coordinate difference between two tangent lists of the same length.
double largestDifference(const std::vector<geo::Point> &a, const std::vector<geo::Point> &b)
{
    double most = 0.0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        most = std::max({most, std::abs(a[i].x() - b[i].x()), std::abs(a[i].y() - b[i].y())});
    return most;
}

} // namespace

int runSpline(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("The curve of a kind through the points of a file (one \"x y\" per line), built by the same function "
           "as the app's curve of that kind: bezier (the points are its control points), interpolating, "
           "least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (the "
           "points are its control polygon), global-bspline, polynomial, function-spline (the natural spline y(x)) "
           "or contour (Bézier pieces joined at the midpoints of pairs of points). Prints {\"knots\": parameter of "
           "each point (the knot vector for bspline; 0, 1, … one per piece for bezier, interpolating, least-squares, "
           "composite and contour), \"segments\": Bézier control points of each piece, \"points\": [u, x, y] at "
           "--at}. Parameters are unnormalised: uniform 0, 1, 2, …; chord the cumulative chord length; centripetal "
           "the cumulative square roots."));
    parser.addOptions({
        {QStringLiteral("kind"), tr("The family (see above)."), QStringLiteral("kind")},
        {QStringLiteral("param"), tr("uniform, chord (default) or centripetal."), QStringLiteral("param"),
         QStringLiteral("chord")},
        {QStringLiteral("function"),
         tr("A function spline y(x) over the points' increasing x; --at then takes x values and points are [x, y].")},
        {QStringLiteral("start-tangent"), tr("Start tangent x,y (clamped, global-bspline; default the first chord)."),
         QStringLiteral("x,y")},
        {QStringLiteral("end-tangent"), tr("End tangent x,y (clamped, global-bspline; default the last chord)."),
         QStringLiteral("x,y")},
        {QStringLiteral("solver"),
         tr("clamped on evenly spaced knots (--function over evenly spaced x, or --param uniform): classical "
            "(default, k - 2 unknowns) or torok (Török's half-size system); prints the JSON key "
            "\"solverDifference\": the largest difference of the derivatives from the other solver."),
         QStringLiteral("solver"), QStringLiteral("classical")},
        {QStringLiteral("order"),
         tr("B-spline order k, 2 to 10 (default as in the app: 4, cubic, or the number of points when fewer)."),
         QStringLiteral("k")},
        {QStringLiteral("knots"),
         tr("B-spline knot vector: open-uniform (default, the app's knots), uniform, or u0,u1,… (n + k values)."),
         QStringLiteral("knots"), QStringLiteral("open-uniform")},
        {QStringLiteral("tangents"),
         tr("hermite: a file with one tangent \"x y\" per point (default Catmull–Rom tangents, as in the app)."),
         QStringLiteral("file")},
        {QStringLiteral("closed"), tr("composite: the closed curve (as Close curve makes it in the app).")},
        {QStringLiteral("at"), tr("Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5)."),
         QStringLiteral("list")},
        {QStringLiteral("in"), tr("The points file."), QStringLiteral("file")},
    });
    if (const int code = parseCommandLine(parser, args); code != 0)
        return code < 0 ? 0 : code;
    const QString kind = parser.value(QStringLiteral("kind"));
    const std::optional<geo::CurveKind> curveKind = geo::kindFromId(kind.toStdString());
    if (!curveKind) {
        QStringList kinds;
        for (const geo::KindTraits &t : geo::kKinds)
            kinds << QString::fromLatin1(t.id);
        return fail(tr("--kind must be one of %1").arg(kinds.join(QStringLiteral(", "))), 2);
    }
    geo::Parameterization param;
    if (const int code = readParam(parser, param); code != 0)
        return code;
    const bool function = parser.isSet(QStringLiteral("function"));
    const QString solverName = parser.value(QStringLiteral("solver"));
    if (solverName != QLatin1String("classical") && solverName != QLatin1String("torok"))
        return fail(tr("unknown --solver \"%1\" (classical or torok)").arg(solverName), 2);
    const bool torok = solverName == QLatin1String("torok");
    if (parser.isSet(QStringLiteral("solver")) && *curveKind != geo::CurveKind::ClampedSpline)
        return fail(tr("--solver is for --kind clamped"), 2);
    if (torok && !function && param != geo::Parameterization::Uniform)
        return fail(tr("Török's procedure needs evenly spaced knots: use --param uniform or --function"), 2);
    std::optional<geo::Point> startTangent, endTangent;
    for (const auto &[name, target] : {std::pair{QStringLiteral("start-tangent"), &startTangent},
                                       std::pair{QStringLiteral("end-tangent"), &endTangent}}) {
        if (!parser.isSet(name))
            continue;
        *target = parsePoint(parser.value(name));
        if (!*target)
            return fail(tr("--%1 needs x,y").arg(name), 2);
    }
    std::optional<int> order;
    if (parser.isSet(QStringLiteral("order"))) {
        bool orderOk = false;
        order = parser.value(QStringLiteral("order")).toInt(&orderOk);
        if (!orderOk)
            return fail(tr("--order needs an integer"), 2);
    }
    std::vector<double> at;
    if (const int code = readAt(parser, at); code != 0)
        return code;
    if (!parser.isSet(QStringLiteral("in")))
        return fail(tr("--in FILE is required"), 2);
    const PointFile file = readPointFile(parser.value(QStringLiteral("in")));
    if (!file.error.isEmpty())
        return fail(file.error);
    if (parser.isSet(QStringLiteral("closed")) && *curveKind != geo::CurveKind::Composite)
        return fail(tr("--closed is for --kind composite (the periodic spline is closed by its kind)"), 2);
    if (function && *curveKind == geo::CurveKind::Contour)
        return fail(tr("a contour curve is drawn through its points in the plane: drop --function"), 2);
    if (function && *curveKind == geo::CurveKind::BSpline)
        return fail(tr("a function B-spline takes a knot vector and control values, not points: drop --function"), 2);
    // Every error about the points names their file.
    auto error = [&file](const geo::Error &e) {
        return fail(QStringLiteral("%1: %2").arg(file.path, QString::fromStdString(e.message)));
    };

    // The record, as the app's document keeps it: the options that the app has as a curve setting set
    // it (order, parameterization, knot vector), tangents given as derivatives by the parameter
    // become the tangent ends the app stores.
    geo::CurveParts parts;
    parts.kind = *curveKind;
    parts.points = file.points;
    parts.parameterization = param;
    parts.function = function;
    parts.order = order.value_or(geo::defaultOrder(parts.points.size()));
    parts.solver = torok ? geo::ClampedSolver::Torok : geo::ClampedSolver::Classical;
    if (geo::traitsOf(*curveKind).takesOrder) {
        const QString knots = parser.value(QStringLiteral("knots"));
        if (knots == QLatin1String("uniform")) {
            auto u = geo::uniformKnots(static_cast<int>(parts.points.size()), parts.order);
            if (!u)
                return error(u.error());
            parts.knotVector = std::move(u).value();
        } else if (knots != QLatin1String("open-uniform")) {
            const auto list = parseNumberList(knots.toStdString());
            if (!list)
                return fail(tr("--knots needs open-uniform, uniform or numbers separated by commas"), 2);
            parts.knotVector = *list;
        }
    }
    if (function && geo::traitsOf(parts.kind).knotParameters) {
        if (auto x = geo::knotParameters(parts); !x)
            return error(x.error());
        if (parts.points.size() < 2)
            return fail(QStringLiteral("%1: %2").arg(file.path, tr("at least 2 points are needed")));
        for (const auto &t : {startTangent, endTangent})
            if (t && geo::hasEndTangents(parts.kind) && !std::isfinite(t->y() / t->x()))
                return fail(QStringLiteral("%1: %2").arg(file.path, tr("a vertical or zero end tangent has no slope")));
    }
    parts.tangentEnds = geo::defaultTangentEnds(parts);
    const bool givenEnds = geo::hasEndTangents(parts.kind) && (startTangent || endTangent);
    const bool givenTangents = geo::hasKnotTangents(parts.kind) && parser.isSet(QStringLiteral("tangents"));
    if (givenEnds || givenTangents) {
        auto s = geo::knotParameters(parts);
        if (!s)
            return error(s.error());
        if (givenEnds) {
            const std::size_t n = parts.points.size();
            if (startTangent && n >= 2)
                parts.tangentEnds[0] = geo::endsFromTangents(parts, *s, {*startTangent, *startTangent})[0];
            if (endTangent && n >= 2)
                parts.tangentEnds[1] = geo::endsFromTangents(parts, *s, {*endTangent, *endTangent})[1];
        } else {
            const PointFile tangents = readPointFile(parser.value(QStringLiteral("tangents")));
            if (!tangents.error.isEmpty())
                return fail(tangents.error);
            if (tangents.points.size() != parts.points.size())
                return fail(
                    QStringLiteral("%1: %2").arg(tangents.path, QStringLiteral("one tangent per point is needed")));
            parts.tangentEnds = geo::endsFromTangents(parts, *s, tangents.points);
        }
    }

    // The shape: the one record → shape function, or for a composite curve its construction
    // through the knots, which is how the app places one.
    geo::CurveShape shape;
    std::vector<double> knots;
    if (*curveKind == geo::CurveKind::Composite) {
        if (function)
            return error(
                geo::Error{geo::ErrorCode::InvalidArgument, "a curve of kind \"composite\" has no function form y(x)"});
        if (parts.points.size() < 2)
            return fail(QStringLiteral("%1: %2").arg(file.path, tr("at least 2 points are needed")));
        geo::CompositeCurve composite(parts.points);
        if (parser.isSet(QStringLiteral("closed")))
            if (auto closed = composite.close(); !closed)
                return error(closed.error());
        const geo::PiecewiseBezier drawn = composite.toPiecewise();
        shape.pieces = drawn.segments();
        shape.closed = drawn.isClosed();
        knots = shape.parameters();
    } else {
        auto built = geo::buildShape(parts);
        if (!built)
            return error(built.error());
        shape = std::move(built).value();
        if (geo::traitsOf(parts.kind).knotParameters) {
            auto s = geo::knotParameters(parts);
            if (!s)
                return error(s.error());
            knots = std::move(s).value();
            if (shape.closed)
                knots.pop_back(); // one per point: not the closing one
        } else {
            knots = shape.parameters();
        }
    }
    // With --solver: the largest difference of the derivatives from the other solver's.
    std::optional<double> solverDifference;
    if (parser.isSet(QStringLiteral("solver")) && shape.hermite) {
        geo::CurveParts other = parts;
        other.solver = torok ? geo::ClampedSolver::Classical : geo::ClampedSolver::Torok;
        if (auto check = geo::buildShape(other); check && check->hermite)
            solverDifference = largestDifference(shape.hermite->tangents(), check->hermite->tangents());
    }

    const geo::PiecewiseBezier pieces = shape.toPiecewise();
    Json json;
    json.beginObject();
    json.key("kind").value(kind.toStdString());
    json.key("knots").numbers(knots);
    json.key("closed").value(pieces.isClosed());
    if (solverDifference) {
        json.key("solver").value(solverName.toStdString());
        json.key("solverDifference").value(*solverDifference);
    }
    json.key("segments").beginArray();
    for (const geo::Bezier &b : pieces.segments())
        json.points(b.controlPoints());
    json.endArray();
    json.key("points").beginArray();
    for (double u : at) {
        const geo::Point p = shape.eval(u);
        json.beginArray();
        if (function) {
            json.value(u).value(p.y());
        } else {
            json.value(u).value(p.x()).value(p.y());
        }
        json.endArray();
    }
    json.endArray();
    json.endObject();
    return printResult(json);
}

} // namespace kontur::cli
