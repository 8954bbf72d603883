// From a curve's defining parts to its shape, for every kind (see curveshape.h).
#include "geometry/curveshape.h"

#include "geometry/splines/bspline.h"
#include "geometry/splines/contour.h"
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/polynomial.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace kontur::geo {

namespace {

// Pieces converted one by one (de Boor insertion, the polynomial's per-piece change of basis) can
// disagree at a joint in the last bits. A drawn curve is one connected path (an SVG export would
// otherwise start a new subpath there): each piece starts exactly where the one before ends.
std::vector<Bezier> joined(std::vector<Bezier> pieces)
{
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        if (pieces[i].controlPoints().front() == pieces[i - 1].controlPoints().back())
            continue;
        std::vector<Point> c = pieces[i].controlPoints();
        c.front() = pieces[i - 1].controlPoints().back();
        pieces[i] = Bezier(std::move(c));
    }
    return pieces;
}

} // namespace

std::optional<CurveKind> kindFromId(std::string_view id)
{
    for (const KindTraits &t : kKinds)
        if (id == t.id)
            return t.kind;
    return std::nullopt;
}

int defaultOrder(std::size_t controlPoints)
{
    return static_cast<int>(std::clamp<std::size_t>(controlPoints, 2, 4));
}

bool isFunctionForm(const CurveParts &parts)
{
    return parts.function || parts.kind == CurveKind::FunctionSpline;
}

Result<std::vector<double>> knotParameters(const CurveParts &parts)
{
    if (!isFunctionForm(parts)) {
        std::span<const Point> points = parts.points;
        const bool closed = traitsOf(parts.kind).closed;
        if (closed && points.size() >= 2 && points.front() == points.back())
            points = points.first(points.size() - 1); // the closing point repeats the first (cubicSpline)
        return splineParameters(points, parts.parameterization, closed);
    }
    std::vector<double> x;
    x.reserve(parts.points.size());
    for (const Point &p : parts.points)
        x.push_back(p.x());
    if (auto ok = checkStrictlyIncreasing(x, "x"); !ok)
        return ok.error();
    return x;
}

std::vector<Point> defaultTangentEnds(const CurveParts &parts)
{
    const std::vector<Point> &points = parts.points;
    const std::size_t n = points.size();
    if (n < 2)
        return {};
    if (hasEndTangents(parts.kind)) {
        // Guide vectors along the end chords (seed 003), drawn a third of the chord long: the
        // derivative is the end chord's slope by the parameter, δ_0 and δ_{n-2}.
        return {points[0] + (points[1] - points[0]) / 3.0, points[n - 1] + (points[n - 1] - points[n - 2]) / 3.0};
    }
    if (!hasKnotTangents(parts.kind))
        return {};
    const auto s = knotParameters(parts);
    if (!s.ok()) {
        // Knots the spline cannot take yet (coincident while being placed): any handle will do, the
        // curve is not drawn until the knots are valid.
        std::vector<Point> ends(n);
        for (std::size_t k = 0; k < n; ++k)
            ends[k] = points[k] + Point(1, 0);
        return ends;
    }
    return endsFromTangents(parts, *s, catmullRomTangents(*s, points, false));
}

std::vector<Point> defaultTangentEnds(CurveKind kind, const std::vector<Point> &points,
                                      Parameterization parameterization)
{
    CurveParts parts;
    parts.kind = kind;
    parts.points = points;
    parts.parameterization = parameterization;
    return defaultTangentEnds(parts);
}

namespace {

// The parameter step next to knot i that its tangent end is measured by: the one after it, the one
// before it at the last knot.
double stepAt(const std::vector<double> &s, std::size_t n, std::size_t i)
{
    return i + 1 < n ? s[i + 1] - s[i] : s[i] - s[i - 1];
}

// The knots a tangent list belongs to: first and last, or every one.
std::size_t knotOfTangent(const CurveParts &parts, std::size_t i)
{
    return hasEndTangents(parts.kind) && i == 1 ? parts.points.size() - 1 : i;
}

} // namespace

std::vector<Point> endsFromTangents(const CurveParts &parts, const std::vector<double> &s,
                                    const std::vector<Point> &tangents)
{
    const std::size_t n = parts.points.size();
    std::vector<Point> ends;
    ends.reserve(tangents.size());
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        const std::size_t k = knotOfTangent(parts, i);
        ends.push_back(parts.points[k] + tangents[i] * (stepAt(s, n, k) / 3.0));
    }
    return ends;
}

std::vector<Point> tangentsFromEnds(const CurveParts &parts, const std::vector<double> &s)
{
    const std::size_t n = parts.points.size();
    std::vector<Point> tangents;
    tangents.reserve(parts.tangentEnds.size());
    for (std::size_t i = 0; i < parts.tangentEnds.size(); ++i) {
        const std::size_t k = knotOfTangent(parts, i);
        tangents.push_back(3.0 * (parts.tangentEnds[i] - parts.points[k]) / stepAt(s, n, k));
    }
    return tangents;
}

std::vector<double> CurveShape::parameters() const
{
    if (hermite)
        return hermite->parameters();
    if (bspline)
        return bspline->knots();
    if (polynomial)
        return polynomial->parameters();
    if (!pieces.empty()) {
        std::vector<double> u(pieces.size() + 1);
        for (std::size_t i = 0; i < u.size(); ++i)
            u[i] = static_cast<double>(i);
        return u;
    }
    if (single)
        return {0.0, 1.0};
    return {};
}

Point CurveShape::eval(double u) const
{
    if (hermite)
        return hermite->eval(u);
    if (bspline)
        return bspline->eval(u);
    if (polynomial)
        return polynomial->eval(u);
    if (!pieces.empty())
        return PiecewiseBezier(pieces).eval(u);
    return single ? single->eval(u) : Point::Zero();
}

int CurveShape::segmentCount() const
{
    if (hermite)
        return hermite->segmentCount();
    if (!pieces.empty())
        return static_cast<int>(pieces.size());
    return single ? 1 : 0;
}

Bezier CurveShape::segment(int i) const
{
    if (hermite)
        return hermite->segment(i);
    if (!pieces.empty())
        return pieces[static_cast<std::size_t>(i)];
    return *single;
}

PiecewiseBezier CurveShape::toPiecewise() const
{
    std::vector<Bezier> segments;
    const int count = segmentCount();
    segments.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        segments.push_back(segment(i));
    return PiecewiseBezier(std::move(segments), closed);
}

bool CurveShape::allFinite() const
{
    const auto finite = [](const auto &points) {
        return std::all_of(points.begin(), points.end(), [](const Point &p) { return p.allFinite(); });
    };
    if (hermite) {
        for (int i = 0; i < hermite->segmentCount(); ++i)
            if (!finite(hermite->segmentControlPoints(i)))
                return false;
        return true;
    }
    for (const Bezier &b : pieces)
        if (!finite(b.controlPoints()))
            return false;
    return !single || finite(single->controlPoints());
}

namespace {

// The slope of each tangent in the function form: the derivative's y over its x (x(u) = u gives x' = 1
// for the tangents this file makes; a typed tangent may have any length).
Result<std::vector<double>> slopesOf(const std::vector<Point> &tangents)
{
    std::vector<double> slopes;
    slopes.reserve(tangents.size());
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        const double slope = tangents[i].y() / tangents[i].x();
        if (!std::isfinite(slope))
            return Error{ErrorCode::InvalidArgument, "a vertical or zero tangent has no slope", static_cast<int>(i)};
        slopes.push_back(slope);
    }
    return slopes;
}

// The plane clamped spline by Török's half-size system, each coordinate solved over the evenly spaced
// parameters s (the function form has its own, uniformClampedSpline).
Result<HermiteSpline> torokClamped(const std::vector<double> &s, const std::vector<Point> &points,
                                   const std::vector<Point> &ends)
{
    const std::size_t n = points.size();
    if (n < 2)
        return Error{ErrorCode::TooFewPoints, "a clamped spline needs at least 2 points", static_cast<int>(n)};
    const double h = (s[n - 1] - s[0]) / static_cast<double>(n - 1);
    for (std::size_t i = 1; i < n; ++i)
        if (std::abs(s[i] - s[i - 1] - h) > 1e-9 * (s[n - 1] - s[0]))
            return Error{ErrorCode::InvalidArgument, "Török's procedure needs evenly spaced knots"};
    std::vector<double> slopes[2];
    for (int c = 0; c < 2; ++c) {
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i)
            v[i] = points[i][c];
        auto d = uniformClampedSlopes(v, h, ends[0][c], ends[1][c], ClampedSolver::Torok);
        if (!d)
            return d.error();
        slopes[c] = std::move(d).value();
    }
    std::vector<Point> tangents(n);
    for (std::size_t i = 0; i < n; ++i)
        tangents[i] = Point(slopes[0][i], slopes[1][i]);
    return HermiteSpline::create(s, points, std::move(tangents), false);
}

} // namespace

Result<CurveShape> buildShape(const CurveParts &parts)
{
    CurveShape shape;
    const std::vector<Point> &points = parts.points;
    const std::size_t expectedEnds = hasEndTangents(parts.kind) ? 2 : hasKnotTangents(parts.kind) ? points.size() : 0;
    if (parts.tangentEnds.size() != expectedEnds && points.size() >= 2)
        return Error{ErrorCode::InvalidArgument, "this kind of curve has " + std::to_string(expectedEnds) +
                                                     " tangent ends, not " + std::to_string(parts.tangentEnds.size())};
    for (const Point &p : parts.tangentEnds)
        if (!p.allFinite())
            return Error{ErrorCode::NonFiniteInput, "a tangent end is not finite"};
    const bool function = isFunctionForm(parts);
    if (function && !traitsOf(parts.kind).functionForm)
        return Error{ErrorCode::InvalidArgument,
                     std::string("a curve of kind \"") + kindId(parts.kind) + "\" has no function form y(x)"};
    if (!parts.knotVector.empty() && !traitsOf(parts.kind).takesOrder)
        return Error{ErrorCode::InvalidArgument, "only a B-spline takes a knot vector"};
    if (parts.solver == ClampedSolver::Torok && parts.kind != CurveKind::ClampedSpline)
        return Error{ErrorCode::InvalidArgument, "Török's procedure solves the clamped spline only"};
    // The function form's x and y.
    std::vector<double> x, y;
    if (function) {
        x.reserve(points.size());
        y.reserve(points.size());
        for (const Point &p : points) {
            x.push_back(p.x());
            y.push_back(p.y());
        }
    }
    // The derivatives the tangent ends stand for, by the knots' parameters `s`; as slopes in the
    // function form.
    const auto tangentsAt = [&parts](const std::vector<double> &s) { return tangentsFromEnds(parts, s); };
    // The kinds kept as Bézier pieces: the built curve's pieces, joined, and the curve itself in
    // `kept` (a member of the shape, for evaluating it by its own parameter), or its error.
    const auto fromPieces = [&shape](auto built, auto &kept) -> Result<CurveShape> {
        if (!built.ok())
            return built.error();
        shape.pieces = joined(built->toPiecewise().segments());
        kept = std::move(built.value());
        return std::move(shape); // a captured local: without the move the whole shape is copied
    };
    // The kinds kept in Hermite form.
    const auto fromHermite = [&shape](auto built) -> Result<CurveShape> {
        if (!built.ok())
            return built.error();
        shape.hermite = std::move(built.value());
        return std::move(shape);
    };

    switch (parts.kind) {
    case CurveKind::Composite:
        return Error{ErrorCode::InvalidArgument, "a composite curve is built from its control vector"};
    case CurveKind::Bezier:
        for (std::size_t i = 0; i < points.size(); ++i)
            if (!points[i].allFinite())
                return Error{ErrorCode::NonFiniteInput, "a control point is not finite", static_cast<int>(i)};
        if (points.size() >= 2)
            shape.single = Bezier(points);
        return shape;
    case CurveKind::Interpolating:
    case CurveKind::LeastSquares: {
        FitOptions options;
        options.alpha = exponentOf(parts.parameterization);
        // Knots dragged onto each other are a normal moment of editing: allowed where the fit can
        // still be made (at least 4 distinct parameters).
        options.allowCoincidentPoints = true;
        auto fit = fitCubic(points, options);
        if (!fit.ok())
            return fit.error();
        shape.single = fit->curve();
        shape.fit = std::move(fit.value());
        return shape;
    }
    case CurveKind::NaturalSpline:
    case CurveKind::NotAKnotSpline:
    case CurveKind::PeriodicSpline:
    case CurveKind::FunctionSpline: {
        const EndCondition end = parts.kind == CurveKind::NotAKnotSpline   ? EndCondition::NotAKnot
                                 : parts.kind == CurveKind::PeriodicSpline ? EndCondition::Periodic
                                                                           : EndCondition::Natural;
        if (function) {
            if (auto ok = checkStrictlyIncreasing(x, "x"); !ok)
                return ok.error();
            return fromHermite(functionSpline(x, y, end));
        }
        shape.closed = traitsOf(parts.kind).closed;
        return fromHermite(cubicSpline(points, end, parts.parameterization));
    }
    case CurveKind::ClampedSpline:
    case CurveKind::HermiteSpline: {
        auto s = knotParameters(parts);
        if (!s.ok())
            return s.error();
        const std::vector<Point> tangents = tangentsAt(*s);
        const bool torok = parts.kind == CurveKind::ClampedSpline && parts.solver == ClampedSolver::Torok;
        if (function) {
            auto slopes = slopesOf(tangents);
            if (!slopes)
                return slopes.error();
            if (torok)
                return fromHermite(uniformClampedSpline(x, y, (*slopes)[0], (*slopes)[1], ClampedSolver::Torok));
            if (parts.kind == CurveKind::ClampedSpline)
                return fromHermite(functionSpline(x, y, EndCondition::Clamped, (*slopes)[0], (*slopes)[1]));
            return fromHermite(HermiteSpline::function(x, y, *slopes));
        }
        if (torok)
            return fromHermite(torokClamped(*s, points, tangents));
        return fromHermite(parts.kind == CurveKind::ClampedSpline
                               ? cubicSpline(*s, points, EndCondition::Clamped, tangents[0], tangents[1])
                               : HermiteSpline::create(*s, points, tangents));
    }
    case CurveKind::CatmullRom: {
        if (!function)
            return fromHermite(hermiteSpline(points, parts.parameterization, TangentRule::CatmullRom));
        auto s = knotParameters(parts);
        if (!s.ok())
            return s.error();
        auto slopes = slopesOf(catmullRomTangents(*s, points, false));
        if (!slopes)
            return slopes.error();
        return fromHermite(HermiteSpline::function(x, y, *slopes));
    }
    case CurveKind::BSpline:
        if (!parts.knotVector.empty())
            return fromPieces(BSpline::create(parts.order, parts.knotVector, points), shape.bspline);
        return fromPieces(BSpline::create(parts.order, KnotKind::OpenUniform, points), shape.bspline);
    case CurveKind::GlobalBSpline: {
        auto s = knotParameters(parts);
        if (!s.ok())
            return s.error();
        const std::vector<Point> tangents = tangentsAt(*s);
        if (function) {
            auto slopes = slopesOf(tangents);
            if (!slopes)
                return slopes.error();
            auto g = globalBSplineFunction(x, y, (*slopes)[0], (*slopes)[1]);
            if (!g)
                return g.error();
            return fromPieces(Result<BSpline>(std::move(g->spline)), shape.bspline);
        }
        return fromPieces(globalBSpline(*s, points, tangents[0], tangents[1]), shape.bspline);
    }
    case CurveKind::Polynomial: {
        return fromPieces(function ? functionPolynomial(x, y) : polynomialInterpolant(points, parts.parameterization),
                          shape.polynomial);
    }
    case CurveKind::Contour: {
        auto pieces = contourPieces(points);
        if (!pieces.ok())
            return pieces.error();
        shape.pieces = std::move(pieces.value());
        return shape;
    }
    }
    return Error{ErrorCode::InvalidArgument, "unknown kind of curve"};
}

} // namespace kontur::geo
