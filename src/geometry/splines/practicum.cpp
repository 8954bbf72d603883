// Seed 003's spline segments and multi-segment spline (see practicum.h).
#include "geometry/splines/practicum.h"

#include "geometry/splines/knots.h"
#include "geometry/splines/tridiagonal.h"

#include <cmath>
#include <string>
#include <utility>

namespace kontur::geo {

namespace {

bool finite(const Point &p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// Formulas (5)–(7): the guide vector divided by its length.
Result<Point> unitGuide(const Point &g, const char *which)
{
    if (!finite(g))
        return Error{ErrorCode::NonFiniteInput, std::string("the ") + which + " guide vector is not finite", -1};
    const double d = g.norm();
    if (!(d > 0.0))
        return Error{ErrorCode::InvalidArgument, std::string("the ") + which + " guide vector has zero length", -1};
    return Point(g / d);
}

// Both guide vectors of a curve, at its start and its end, scaled to unit length.
Result<std::pair<Point, Point>> unitGuides(const Point &start, const Point &end)
{
    auto k0 = unitGuide(start, "start");
    if (!k0)
        return k0.error();
    auto k1 = unitGuide(end, "end");
    if (!k1)
        return k1.error();
    return std::pair{*k0, *k1};
}

} // namespace

Bezier PracticumFunctionSegment::toBezier() const
{
    const double y1 = value(t);
    return Bezier({Point(x0, y0), Point(x0 + t / 3.0, y0 + k0 * t / 3.0), Point(x0 + 2.0 * t / 3.0, y1 - k1 * t / 3.0),
                   Point(x0 + t, y1)});
}

Result<PracticumFunctionSegment> practicumFunctionSegment(const Point &p0, const Point &p1, const Point &guide0,
                                                          const Point &guide1)
{
    if (!finite(p0) || !finite(p1) || !finite(guide0) || !finite(guide1))
        return Error{ErrorCode::NonFiniteInput, "a point or guide vector is not finite", -1};
    const double t = p1.x() - p0.x();
    if (t == 0.0)
        return Error{ErrorCode::InvalidArgument, "the end points have the same x: no function segment", 1};
    if (guide0.x() == 0.0 || guide1.x() == 0.0)
        return Error{ErrorCode::InvalidArgument, "a vertical or zero guide vector has no slope dy/dx",
                     guide0.x() == 0.0 ? 0 : 1};
    PracticumFunctionSegment s;
    s.x0 = p0.x();
    s.y0 = p0.y();
    s.t = t;
    s.k0 = guide0.y() / guide0.x();
    s.k1 = guide1.y() / guide1.x();
    const double y1 = p1.y();
    s.a3 = 3.0 * (y1 - s.y0) / (t * t) - (2.0 * s.k0 + s.k1) / t;     // (2)
    s.a4 = 2.0 * (s.y0 - y1) / (t * t * t) + (s.k0 + s.k1) / (t * t); // (3)
    return s;
}

Bezier PracticumParametricSegment::toBezier() const
{
    const Point p1 = value(t2);
    return Bezier({p0, p0 + k0 * t2 / 3.0, p1 - k1 * t2 / 3.0, p1});
}

Result<PracticumParametricSegment> practicumParametricSegment(const Point &p0, const Point &p1, const Point &guide0,
                                                              const Point &guide1)
{
    if (!finite(p0) || !finite(p1))
        return Error{ErrorCode::NonFiniteInput, "an end point is not finite", -1};
    const auto guides = unitGuides(guide0, guide1);
    if (!guides)
        return guides.error();
    const auto &[k0, k1] = *guides;
    const double t2 = (p1 - p0).norm();
    if (!(t2 > 0.0))
        return Error{ErrorCode::CoincidentPoints, "the end points coincide", 1};
    PracticumParametricSegment s;
    s.p0 = p0;
    s.k0 = k0;
    s.k1 = k1;
    s.t2 = t2;
    s.a3 = 3.0 * (p1 - p0) / (t2 * t2) - (2.0 * s.k0 + s.k1) / t2;       // (11), (12)
    s.a4 = 2.0 * (p0 - p1) / (t2 * t2 * t2) + (s.k0 + s.k1) / (t2 * t2); // (13), (14)
    return s;
}

Result<PracticumSpline> practicumSpline(std::span<const Point> points, const Point &guideStart, const Point &guideEnd)
{
    const std::size_t m = points.size();
    if (m < 2)
        return Error{ErrorCode::TooFewPoints, "the spline needs at least 2 points", static_cast<int>(m)};
    if (auto ok = checkFinite(points); !ok)
        return ok.error();
    const auto guides = unitGuides(guideStart, guideEnd);
    if (!guides)
        return guides.error();
    const auto &[k0, kn] = *guides;
    const std::size_t n = m - 1;
    PracticumSpline r;
    r.T.assign(n + 1, 0.0);
    r.B.assign(n + 1, Point::Zero());
    r.K.assign(n + 1, Point::Zero());
    for (std::size_t j = 1; j <= n; ++j) {
        r.T[j] = (points[j] - points[j - 1]).norm();
        if (!(r.T[j] > 0.0))
            return Error{ErrorCode::CoincidentPoints,
                         "points " + std::to_string(j - 1) + " and " + std::to_string(j) + " coincide",
                         static_cast<int>(j)};
    }
    r.K[0] = k0;
    r.K[n] = kn;
    if (n >= 2) {
        // Rows i = 1..n-1: T_{i+1} K_{i-1} + 2 (T_i + T_{i+1}) K_i + T_i K_{i+1} = B_i, with
        // B_i = 3 [(P_{i+1} - P_i) T_i / T_{i+1} + (P_i - P_{i-1}) T_{i+1} / T_i] (17), (18).
        const std::size_t rows = n - 1;
        std::vector<double> a(rows), b(rows), c(rows);
        std::vector<Point> rhs(rows);
        for (std::size_t i = 1; i < n; ++i) {
            const double ti = r.T[i], tn = r.T[i + 1];
            r.B[i] = 3.0 * ((points[i + 1] - points[i]) * ti / tn + (points[i] - points[i - 1]) * tn / ti);
            a[i - 1] = tn;
            b[i - 1] = 2.0 * (ti + tn);
            c[i - 1] = ti;
            rhs[i - 1] = r.B[i];
        }
        // The known end tangents move to the right-hand side of the first and last rows.
        rhs[0] -= r.T[2] * r.K[0];
        rhs[rows - 1] -= r.T[n - 1] * r.K[n];
        if (!solveTridiagonal<Point>(a, b, c, rhs)) // the sweep (solve_tds)
            return Error{ErrorCode::IllConditioned, "the spline system is singular", -1};
        for (std::size_t i = 1; i < n; ++i)
            r.K[i] = rhs[i - 1];
    }
    std::vector<double> s(m, 0.0);
    for (std::size_t j = 1; j <= n; ++j)
        s[j] = s[j - 1] + r.T[j];
    auto spline = HermiteSpline::create(std::move(s), std::vector<Point>(points.begin(), points.end()), r.K, false);
    if (!spline)
        return spline.error();
    r.spline = std::move(spline).value();
    return r;
}

} // namespace kontur::geo
