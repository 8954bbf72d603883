// From a curve's defining parts to its shape, for every kind (see curveshape.h).
#include "geometry/curveshape.h"

#include "geometry/splines/bspline.h"
#include "geometry/splines/contour.h"
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/polynomial.h"

#include <algorithm>
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

const char *kindId(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Bezier:
        return "bezier";
    case CurveKind::Interpolating:
        return "interpolating";
    case CurveKind::LeastSquares:
        return "least-squares";
    case CurveKind::Composite:
        return "composite";
    case CurveKind::NaturalSpline:
        return "natural";
    case CurveKind::ClampedSpline:
        return "clamped";
    case CurveKind::NotAKnotSpline:
        return "not-a-knot";
    case CurveKind::PeriodicSpline:
        return "periodic";
    case CurveKind::CatmullRom:
        return "catmull-rom";
    case CurveKind::HermiteSpline:
        return "hermite";
    case CurveKind::BSpline:
        return "bspline";
    case CurveKind::GlobalBSpline:
        return "global-bspline";
    case CurveKind::Polynomial:
        return "polynomial";
    case CurveKind::FunctionSpline:
        return "function-spline";
    case CurveKind::Contour:
        return "contour";
    }
    return "";
}

std::optional<CurveKind> kindFromId(std::string_view id)
{
    for (int k = 0; k < kKindCount; ++k)
        if (id == kindId(static_cast<CurveKind>(k)))
            return static_cast<CurveKind>(k);
    return std::nullopt;
}

bool isFittedKind(CurveKind kind)
{
    return kind == CurveKind::Interpolating || kind == CurveKind::LeastSquares;
}

bool hasEndTangents(CurveKind kind)
{
    return kind == CurveKind::ClampedSpline || kind == CurveKind::GlobalBSpline;
}

bool hasKnotTangents(CurveKind kind)
{
    return kind == CurveKind::HermiteSpline;
}

int defaultOrder(std::size_t controlPoints)
{
    return static_cast<int>(std::clamp<std::size_t>(controlPoints, 2, 4));
}

std::vector<Point> defaultTangentEnds(CurveKind kind, const std::vector<Point> &points,
                                      Parameterization parameterization)
{
    const std::size_t n = points.size();
    if (n < 2)
        return {};
    if (hasEndTangents(kind)) {
        // Guide vectors along the end chords (seed 003), drawn a third of the chord long.
        return {points[0] + (points[1] - points[0]) / 3.0, points[n - 1] + (points[n - 1] - points[n - 2]) / 3.0};
    }
    if (!hasKnotTangents(kind))
        return {};
    std::vector<Point> ends(n);
    const auto s = splineParameters(points, parameterization);
    if (!s.ok()) {
        // Knots the spline cannot take yet (coincident while being placed): any handle will do, the
        // curve is not drawn until the knots are valid.
        for (std::size_t k = 0; k < n; ++k)
            ends[k] = points[k] + Point(1, 0);
        return ends;
    }
    const std::vector<Point> tangents = catmullRomTangents(*s, points, false);
    for (std::size_t k = 0; k < n; ++k) {
        const double h = k + 1 < n ? (*s)[k + 1] - (*s)[k] : (*s)[k] - (*s)[k - 1];
        ends[k] = points[k] + tangents[k] * (h / 3.0);
    }
    return ends;
}

std::vector<Point> tangentsFromEnds(const CurveParts &parts, const std::vector<double> &s)
{
    const std::size_t n = parts.points.size();
    const auto step = [&](std::size_t i) { return i + 1 < n ? s[i + 1] - s[i] : s[i] - s[i - 1]; };
    std::vector<Point> tangents;
    if (hasEndTangents(parts.kind)) {
        tangents.push_back(3.0 * (parts.tangentEnds[0] - parts.points[0]) / step(0));
        tangents.push_back(3.0 * (parts.tangentEnds[1] - parts.points[n - 1]) / step(n - 1));
    } else {
        for (std::size_t i = 0; i < n; ++i)
            tangents.push_back(3.0 * (parts.tangentEnds[i] - parts.points[i]) / step(i));
    }
    return tangents;
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
    // The kinds kept as Bézier pieces: the built curve's pieces, joined, or its error.
    const auto fromPieces = [&shape](const auto &built) -> Result<CurveShape> {
        if (!built.ok())
            return built.error();
        shape.pieces = joined(built->toPiecewise().segments());
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
    case CurveKind::PeriodicSpline: {
        const EndCondition end = parts.kind == CurveKind::NaturalSpline    ? EndCondition::Natural
                                 : parts.kind == CurveKind::NotAKnotSpline ? EndCondition::NotAKnot
                                                                           : EndCondition::Periodic;
        shape.closed = end == EndCondition::Periodic;
        return fromHermite(cubicSpline(points, end, parts.parameterization));
    }
    case CurveKind::ClampedSpline:
    case CurveKind::HermiteSpline: {
        auto s = splineParameters(points, parts.parameterization);
        if (!s.ok())
            return s.error();
        const std::vector<Point> tangents = tangentsFromEnds(parts, *s);
        return fromHermite(parts.kind == CurveKind::ClampedSpline
                               ? cubicSpline(*s, points, EndCondition::Clamped, tangents[0], tangents[1])
                               : HermiteSpline::create(*s, points, tangents));
    }
    case CurveKind::CatmullRom:
        return fromHermite(hermiteSpline(points, parts.parameterization, TangentRule::CatmullRom));
    case CurveKind::FunctionSpline: {
        std::vector<double> x, y;
        x.reserve(points.size());
        y.reserve(points.size());
        for (const Point &p : points) {
            x.push_back(p.x());
            y.push_back(p.y());
        }
        return fromHermite(functionSpline(x, y, EndCondition::Natural));
    }
    case CurveKind::BSpline:
        return fromPieces(BSpline::create(parts.order, KnotKind::OpenUniform, points));
    case CurveKind::GlobalBSpline: {
        auto s = splineParameters(points, parts.parameterization);
        if (!s.ok())
            return s.error();
        const std::vector<Point> tangents = tangentsFromEnds(parts, *s);
        return fromPieces(globalBSpline(*s, points, tangents[0], tangents[1]));
    }
    case CurveKind::Polynomial:
        return fromPieces(polynomialInterpolant(points, parts.parameterization));
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
