// kontur-cli spline (see splinecommand.h and issue 4's command line).
#include "cli/splinecommand.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "cli/pointfile.h"
#include "geometry/piecewise.h"
#include "geometry/splines/bspline.h"
#include "geometry/splines/contour.h"
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/hermite.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/polynomial.h"
#include "geometry/splines/torok.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
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

// What every family hands to the printer: the knots line, the pieces, and an evaluator.
struct Built
{
    std::vector<double> knots;
    geo::PiecewiseBezier pieces;
    std::function<geo::Point(double)> eval;
};

// Default end tangents where none are given: the chord slopes of the end segments with respect to
// the parameter (δ_0 and δ_{n-2}).
void defaultTangents(const std::vector<double> &s, const std::vector<geo::Point> &p, geo::Point &t0, geo::Point &t1)
{
    const std::size_t n = p.size();
    t0 = (p[1] - p[0]) / (s[1] - s[0]);
    t1 = (p[n - 1] - p[n - 2]) / (s[n - 1] - s[n - 2]);
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
        tr("The spline through the points of a file (one \"x y\" per line): natural, clamped, not-a-knot, "
           "periodic, catmull-rom, hermite, bspline (the points are its control polygon), global-bspline, "
           "polynomial or contour (Bézier pieces joined at the midpoints of pairs of points; knots 0, 1, …, "
           "one per piece). Prints {\"knots\": parameter of each point (the knot vector for bspline), \"segments\": "
           "Bézier control points of each piece, \"points\": [u, x, y] at --at}. Parameters are unnormalised: "
           "uniform 0, 1, 2, …; chord the cumulative chord length; centripetal the cumulative square roots."));
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
        {QStringLiteral("order"), tr("B-spline order k, 2 to 10 (default 4, cubic)."), QStringLiteral("k"),
         QStringLiteral("4")},
        {QStringLiteral("knots"),
         tr("B-spline knot vector: open-uniform (default), uniform, or u0,u1,… (n + k values)."),
         QStringLiteral("knots"), QStringLiteral("open-uniform")},
        {QStringLiteral("tangents"),
         tr("hermite: a file with one tangent \"x y\" per point (default finite differences)."),
         QStringLiteral("file")},
        {QStringLiteral("at"), tr("Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5)."),
         QStringLiteral("list")},
        {QStringLiteral("in"), tr("The points file."), QStringLiteral("file")},
    });
    if (const int code = parseCommandLine(parser, args); code != 0)
        return code < 0 ? 0 : code;
    const QString kind = parser.value(QStringLiteral("kind"));
    static const QStringList kinds{QStringLiteral("natural"),     QStringLiteral("clamped"),
                                   QStringLiteral("not-a-knot"),  QStringLiteral("periodic"),
                                   QStringLiteral("catmull-rom"), QStringLiteral("hermite"),
                                   QStringLiteral("bspline"),     QStringLiteral("global-bspline"),
                                   QStringLiteral("polynomial"),  QStringLiteral("contour")};
    if (!kinds.contains(kind))
        return fail(tr("--kind must be one of %1").arg(kinds.join(QStringLiteral(", "))), 2);
    geo::Parameterization param;
    if (const int code = readParam(parser, param); code != 0)
        return code;
    const bool function = parser.isSet(QStringLiteral("function"));
    const QString solverName = parser.value(QStringLiteral("solver"));
    if (solverName != QLatin1String("classical") && solverName != QLatin1String("torok"))
        return fail(tr("unknown --solver \"%1\" (classical or torok)").arg(solverName), 2);
    const bool torok = solverName == QLatin1String("torok");
    if (parser.isSet(QStringLiteral("solver")) && kind != QLatin1String("clamped"))
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
    bool orderOk = false;
    const int order = parser.value(QStringLiteral("order")).toInt(&orderOk);
    if (!orderOk)
        return fail(tr("--order needs an integer"), 2);
    std::vector<double> at;
    if (const int code = readAt(parser, at); code != 0)
        return code;
    if (!parser.isSet(QStringLiteral("in")))
        return fail(tr("--in FILE is required"), 2);
    const PointFile file = readPointFile(parser.value(QStringLiteral("in")));
    if (!file.error.isEmpty())
        return fail(file.error);
    const std::vector<geo::Point> &pts = file.points;
    if (function && kind == QLatin1String("contour"))
        return fail(tr("a contour curve is drawn through its points in the plane: drop --function"), 2);
    if (function && kind == QLatin1String("bspline"))
        return fail(tr("a function B-spline takes a knot vector and control values, not points: drop --function"), 2);

    Built built;
    std::optional<double> solverDifference; // with --solver: the largest difference from the other solver
    // Every error about the points names their file.
    auto error = [&file](const geo::Error &e) {
        return fail(QStringLiteral("%1: %2").arg(file.path, QString::fromStdString(e.message)));
    };
    const std::string k = kind.toStdString();
    geo::EndCondition end{};
    const bool cubic = geo::parseEndCondition(k, end);

    if (function) {
        std::vector<double> x(pts.size()), y(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) {
            x[i] = pts[i].x();
            y[i] = pts[i].y();
        }
        if (auto ok = geo::checkStrictlyIncreasing(x, "x"); !ok)
            return error(ok.error());
        if (pts.size() < 2)
            return fail(QStringLiteral("%1: %2").arg(file.path, tr("at least 2 points are needed")));
        const double slope0 = startTangent ? startTangent->y() / startTangent->x() : (y[1] - y[0]) / (x[1] - x[0]);
        const std::size_t n = x.size();
        const double slope1 =
            endTangent ? endTangent->y() / endTangent->x() : (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]);
        if (!std::isfinite(slope0) || !std::isfinite(slope1))
            return fail(QStringLiteral("%1: %2").arg(file.path, tr("a vertical or zero end tangent has no slope")));
        built.knots = x;
        if (cubic || kind == QLatin1String("catmull-rom") || kind == QLatin1String("hermite")) {
            geo::Result<geo::HermiteSpline> s = geo::HermiteSpline{};
            if (cubic && end == geo::EndCondition::Clamped && parser.isSet(QStringLiteral("solver"))) {
                const auto other = torok ? geo::ClampedSolver::Classical : geo::ClampedSolver::Torok;
                s = geo::uniformClampedSpline(x, y, slope0, slope1,
                                              torok ? geo::ClampedSolver::Torok : geo::ClampedSolver::Classical);
                auto check = geo::uniformClampedSpline(x, y, slope0, slope1, other);
                if (s && check)
                    solverDifference = largestDifference(s->tangents(), check->tangents());
            } else if (cubic) {
                s = geo::functionSpline(x, y, end, slope0, slope1);
            } else {
                // The tangent rules with parameters x give tangents (1, y'), so x(u) = u.
                const auto m = kind == QLatin1String("catmull-rom") ? geo::catmullRomTangents(x, pts, false)
                                                                    : geo::finiteDifferenceTangents(x, pts, false);
                std::vector<double> slopes(n);
                for (std::size_t i = 0; i < n; ++i)
                    slopes[i] = m[i].y() / m[i].x();
                s = geo::HermiteSpline::function(x, y, slopes);
            }
            if (!s)
                return error(s.error());
            built.pieces = s->toPiecewise();
            built.eval = [spline = std::move(s).value()](double u) { return spline.eval(u); };
        } else if (kind == QLatin1String("global-bspline")) {
            auto g = geo::globalBSplineFunction(x, y, slope0, slope1);
            if (!g)
                return error(g.error());
            built.pieces = g->spline.toPiecewise();
            built.eval = [spline = g->spline](double u) { return spline.eval(u); };
        } else { // polynomial
            auto p = geo::functionPolynomial(x, y);
            if (!p)
                return error(p.error());
            built.pieces = p->toPiecewise();
            built.eval = [poly = std::move(p).value()](double u) { return poly.eval(u); };
        }
    } else if (cubic || kind == QLatin1String("global-bspline")) {
        const bool closed = end == geo::EndCondition::Periodic && cubic;
        std::vector<geo::Point> input = pts;
        if (closed && input.size() >= 2 && input.front() == input.back())
            input.pop_back(); // the closing point repeats the first
        auto s = geo::splineParameters(input, param, closed);
        if (!s)
            return error(s.error());
        geo::Point t0, t1;
        defaultTangents(*s, input, t0, t1);
        t0 = startTangent.value_or(t0);
        t1 = endTangent.value_or(t1);
        built.knots.assign(s->begin(), s->begin() + static_cast<std::ptrdiff_t>(input.size()));
        if (cubic && end == geo::EndCondition::Clamped && parser.isSet(QStringLiteral("solver"))) {
            // Each coordinate is a function of the uniform parameter 0, 1, 2, …: solve both with each solver.
            std::vector<geo::Point> tangents[2];
            for (int which = 0; which < 2; ++which) {
                const bool useTorok = (which == 0) == torok;
                std::vector<double> slopes[2];
                for (int c = 0; c < 2; ++c) {
                    std::vector<double> v(input.size());
                    for (std::size_t i = 0; i < input.size(); ++i)
                        v[i] = c == 0 ? input[i].x() : input[i].y();
                    auto d =
                        geo::uniformClampedSlopes(v, 1.0, c == 0 ? t0.x() : t0.y(), c == 0 ? t1.x() : t1.y(),
                                                  useTorok ? geo::ClampedSolver::Torok : geo::ClampedSolver::Classical);
                    if (!d)
                        return error(d.error());
                    slopes[c] = std::move(d).value();
                }
                for (std::size_t i = 0; i < input.size(); ++i)
                    tangents[which].emplace_back(slopes[0][i], slopes[1][i]);
            }
            solverDifference = largestDifference(tangents[0], tangents[1]);
            auto spline = geo::hermiteSpline(input, tangents[0], param);
            if (!spline)
                return error(spline.error());
            built.pieces = spline->toPiecewise();
            built.eval = [sp = std::move(spline).value()](double u) { return sp.eval(u); };
        } else if (cubic) {
            auto spline = geo::cubicSpline(*s, input, end, t0, t1);
            if (!spline)
                return error(spline.error());
            built.pieces = spline->toPiecewise();
            built.eval = [sp = std::move(spline).value()](double u) { return sp.eval(u); };
        } else {
            auto g = geo::globalBSpline(*s, input, t0, t1);
            if (!g)
                return error(g.error());
            built.pieces = g->toPiecewise();
            built.eval = [sp = std::move(g).value()](double u) { return sp.eval(u); };
        }
    } else if (kind == QLatin1String("catmull-rom") || kind == QLatin1String("hermite")) {
        geo::Result<geo::HermiteSpline> s = geo::HermiteSpline{};
        if (kind == QLatin1String("hermite") && parser.isSet(QStringLiteral("tangents"))) {
            const PointFile tan = readPointFile(parser.value(QStringLiteral("tangents")));
            if (!tan.error.isEmpty())
                return fail(tan.error);
            s = geo::hermiteSpline(pts, tan.points, param);
        } else {
            s = geo::hermiteSpline(pts, param,
                                   kind == QLatin1String("hermite") ? geo::TangentRule::FiniteDifference
                                                                    : geo::TangentRule::CatmullRom);
        }
        if (!s)
            return error(s.error());
        built.knots = s->parameters();
        built.pieces = s->toPiecewise();
        built.eval = [sp = std::move(s).value()](double u) { return sp.eval(u); };
    } else if (kind == QLatin1String("contour")) {
        auto pieces = geo::contourPieces(pts);
        if (!pieces)
            return error(pieces.error());
        for (std::size_t i = 0; i <= pieces->size(); ++i)
            built.knots.push_back(static_cast<double>(i));
        built.pieces = geo::PiecewiseBezier(std::move(pieces).value());
        built.eval = [pw = built.pieces](double u) { return pw.eval(u); };
    } else if (kind == QLatin1String("bspline")) {
        const QString knots = parser.value(QStringLiteral("knots"));
        geo::Result<geo::BSpline> b = geo::BSpline{};
        if (knots == QLatin1String("open-uniform") || knots == QLatin1String("uniform")) {
            b = geo::BSpline::create(
                order, knots == QLatin1String("uniform") ? geo::KnotKind::Uniform : geo::KnotKind::OpenUniform, pts);
        } else {
            const auto list = parseNumberList(knots.toStdString());
            if (!list)
                return fail(tr("--knots needs open-uniform, uniform or numbers separated by commas"), 2);
            b = geo::BSpline::create(order, *list, pts);
        }
        if (!b)
            return error(b.error());
        built.knots = b->knots();
        built.pieces = b->toPiecewise();
        built.eval = [sp = std::move(b).value()](double u) { return sp.eval(u); };
    } else { // polynomial
        auto p = geo::polynomialInterpolant(pts, param);
        if (!p)
            return error(p.error());
        built.knots = p->parameters();
        built.pieces = p->toPiecewise();
        built.eval = [poly = std::move(p).value()](double u) { return poly.eval(u); };
    }

    Json json;
    json.beginObject();
    json.key("kind").value(k);
    json.key("knots").numbers(built.knots);
    json.key("closed").value(built.pieces.isClosed());
    if (solverDifference) {
        json.key("solver").value(solverName.toStdString());
        json.key("solverDifference").value(*solverDifference);
    }
    json.key("segments").beginArray();
    for (const geo::Bezier &b : built.pieces.segments())
        json.points(b.controlPoints());
    json.endArray();
    json.key("points").beginArray();
    for (double u : at) {
        const geo::Point p = built.eval(u);
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
