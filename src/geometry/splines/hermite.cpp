// Cubic Hermite splines and the default tangent rules (see hermite.h).
#include "geometry/splines/hermite.h"

#include "geometry/splines/knots.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace kontur::geo {

Result<HermiteSpline> HermiteSpline::create(std::vector<double> parameters, std::vector<Point> points,
                                            std::vector<Point> tangents, bool closed)
{
    const std::size_t n = points.size();
    const std::size_t need = closed ? 3 : 2;
    if (n < need)
        return Error{ErrorCode::TooFewPoints, "a Hermite spline needs at least " + std::to_string(need) + " points",
                     static_cast<int>(n)};
    if (tangents.size() != n || parameters.size() != (closed ? n + 1 : n))
        return Error{ErrorCode::InvalidArgument, "one tangent and one parameter per point are needed", -1};
    if (auto ok = checkParametersAndPoints(parameters, points); !ok)
        return ok.error();
    if (auto ok = checkFinite(tangents); !ok)
        return Error{ErrorCode::NonFiniteInput, "tangent " + std::to_string(ok.error().index) + " is not finite",
                     ok.error().index};
    return fromChecked(std::move(parameters), std::move(points), std::move(tangents), closed);
}

HermiteSpline HermiteSpline::fromChecked(std::vector<double> parameters, std::vector<Point> points,
                                         std::vector<Point> tangents, bool closed)
{
    HermiteSpline s;
    s.m_params = std::move(parameters);
    s.m_points = std::move(points);
    s.m_tangents = std::move(tangents);
    s.m_closed = closed;
    return s;
}

Result<HermiteSpline> HermiteSpline::function(std::span<const double> x, std::span<const double> y,
                                              std::span<const double> slopes)
{
    if (x.size() != y.size() || x.size() != slopes.size())
        return Error{ErrorCode::InvalidArgument, "one value and one slope per x are needed", -1};
    std::vector<Point> pts(x.size()), tan(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        pts[i] = Point(x[i], y[i]);
        tan[i] = Point(1.0, slopes[i]);
    }
    return create(std::vector<double>(x.begin(), x.end()), std::move(pts), std::move(tan), false);
}

int HermiteSpline::segmentCount() const
{
    if (m_points.size() < 2)
        return 0;
    return static_cast<int>(m_closed ? m_points.size() : m_points.size() - 1);
}

namespace {

// Sets entry `index` of a hermite spline's points or tangents to a finite `value`.
Result<Ok> setFinite(std::vector<Point> &entries, int index, const Point &value, const char *what)
{
    if (index < 0 || static_cast<std::size_t>(index) >= entries.size())
        return Error{ErrorCode::IndexOutOfRange, "no point " + std::to_string(index), index};
    if (!std::isfinite(value.x()) || !std::isfinite(value.y()))
        return Error{ErrorCode::NonFiniteInput, std::string("the ") + what + " is not finite", index};
    entries[static_cast<std::size_t>(index)] = value;
    return Ok{};
}

} // namespace

Result<Ok> HermiteSpline::setTangent(int index, const Point &tangent)
{
    return setFinite(m_tangents, index, tangent, "tangent");
}

Result<Ok> HermiteSpline::setPoint(int index, const Point &point)
{
    return setFinite(m_points, index, point, "point");
}

SplineLocation HermiteSpline::locate(double u) const
{
    const int segs = segmentCount();
    if (segs == 0)
        return {};
    if (!(u > m_params.front()))
        return {0, 0.0};
    if (!(u < m_params.back()))
        return {segs - 1, 1.0};
    // The last s_i <= u: segment i covers [s_i, s_{i+1}) (half-open; the end belongs to the last).
    const auto it = std::upper_bound(m_params.begin(), m_params.end(), u);
    const int i = std::clamp(static_cast<int>(it - m_params.begin()) - 1, 0, segs - 1);
    const auto k = static_cast<std::size_t>(i);
    return {i, (u - m_params[k]) / (m_params[k + 1] - m_params[k])};
}

std::array<Point, 4> HermiteSpline::segmentControlPoints(int segment) const
{
    const auto i = static_cast<std::size_t>(segment);
    const std::size_t j = i + 1 == m_points.size() ? 0 : i + 1;
    const double h3 = (m_params[i + 1] - m_params[i]) / 3.0;
    return {m_points[i], m_points[i] + h3 * m_tangents[i], m_points[j] - h3 * m_tangents[j], m_points[j]};
}

namespace {

// The cubic Hermite form on one segment: values and derivatives with respect to the local t,
// p(t) = h00 p0 + h10 m0 + h01 p1 + h11 m1 with m scaled by the segment length.
Point hermiteAt(const Point &p0, const Point &m0, const Point &p1, const Point &m1, double t, int order)
{
    const double t2 = t * t, t3 = t2 * t;
    switch (order) {
    case 0:
        return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1;
    case 1:
        return (6 * t2 - 6 * t) * p0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * p1 + (3 * t2 - 2 * t) * m1;
    case 2:
        return (12 * t - 6) * p0 + (6 * t - 4) * m0 + (-12 * t + 6) * p1 + (6 * t - 2) * m1;
    case 3:
        return 12.0 * p0 + 6.0 * m0 - 12.0 * p1 + 6.0 * m1;
    default:
        return Point::Zero();
    }
}

} // namespace

Point HermiteSpline::eval(double u) const
{
    return derivative(u, 0);
}

Point HermiteSpline::derivative(double u, int order) const
{
    if (segmentCount() == 0 || order < 0)
        return Point::Zero();
    const SplineLocation loc = locate(u);
    const auto i = static_cast<std::size_t>(loc.segment);
    const std::size_t j = i + 1 == m_points.size() ? 0 : i + 1;
    const double h = m_params[i + 1] - m_params[i];
    const Point d = hermiteAt(m_points[i], h * m_tangents[i], m_points[j], h * m_tangents[j], loc.t, order);
    return order == 0 ? d : Point(d / std::pow(h, order));
}

namespace {

// The segment of every parameter of a sorted chunk: a merge of two sorted sequences, whose
// one-step-at-a-time chain (compare, advance) would dominate the evaluation, so it runs as kLanes
// independent merges over the chunk's quarters, interleaved (each lane starts from a binary search).
void segmentsOfSorted(const std::vector<double> &params, std::size_t last, std::span<const double> u,
                      std::uint32_t *segOf)
{
    constexpr std::size_t kLanes = 4;
    const double lo = params.front(), hi = params.back();
    const std::size_t m = u.size();
    std::size_t k[kLanes], kEnd[kLanes], seg[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l) {
        k[l] = m * l / kLanes;
        kEnd[l] = m * (l + 1) / kLanes;
        const double x = k[l] < m ? std::clamp(u[k[l]], lo, hi) : hi;
        const auto it = std::upper_bound(params.begin(), params.end(), x);
        seg[l] = std::min(last, static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - params.begin() - 1, 0)));
    }
    for (bool active = true; active;) {
        active = false;
        for (std::size_t l = 0; l < kLanes; ++l) {
            if (k[l] >= kEnd[l])
                continue;
            active = true;
            const double x = std::clamp(u[k[l]], lo, hi);
            const bool advance = seg[l] < last && x >= params[seg[l] + 1];
            segOf[k[l]] = static_cast<std::uint32_t>(seg[l]);
            seg[l] += advance;
            k[l] += !advance;
        }
    }
}

} // namespace

void HermiteSpline::evalSorted(std::span<const double> u, std::span<Point> out) const
{
    const int segs = segmentCount();
    if (segs == 0) {
        std::fill(out.begin(), out.end(), Point::Zero());
        return;
    }
    const double lo = m_params.front(), hi = m_params.back();
    const auto last = static_cast<std::size_t>(segs - 1);
    const std::size_t n = m_points.size();
    // Per chunk: the segments first (segmentsOfSorted), then the evaluation, with no dependency
    // between points.
    constexpr std::size_t kChunk = 4096;
    std::vector<std::uint32_t> segOf(std::min(kChunk, u.size()));
    for (std::size_t base = 0; base < u.size(); base += kChunk) {
        const std::size_t count = std::min(kChunk, u.size() - base);
        segmentsOfSorted(m_params, last, u.subspan(base, count), segOf.data());
        for (std::size_t q = 0; q < count; ++q) {
            const double x = std::clamp(u[base + q], lo, hi);
            std::size_t i = segOf[q];
            if (x < m_params[i] || x > m_params[i + 1]) // unsorted input
                i = static_cast<std::size_t>(locate(x).segment);
            const std::size_t j = i + 1 == n ? 0 : i + 1;
            const double h = m_params[i + 1] - m_params[i];
            const double t = (x - m_params[i]) / h, t2 = t * t, t3 = t2 * t;
            // Cubic Hermite basis, the tangents scaled to the segment.
            const double h00 = 2 * t3 - 3 * t2 + 1, h10 = (t3 - 2 * t2 + t) * h;
            const double h01 = 3 * t2 - 2 * t3, h11 = (t3 - t2) * h;
            const Point &p0 = m_points[i], &p1 = m_points[j], &m0 = m_tangents[i], &m1 = m_tangents[j];
            out[base + q] = Point(h00 * p0.x() + h10 * m0.x() + h01 * p1.x() + h11 * m1.x(),
                                  h00 * p0.y() + h10 * m0.y() + h01 * p1.y() + h11 * m1.y());
        }
    }
}

Bezier HermiteSpline::segment(int segment) const
{
    const auto c = segmentControlPoints(segment);
    return Bezier(std::vector<Point>(c.begin(), c.end()));
}

std::vector<Point> HermiteSpline::bezierControlPoints() const
{
    const int segs = segmentCount();
    if (segs == 0)
        return {};
    std::vector<Point> out(3 * static_cast<std::size_t>(segs) + 1);
    for (int k = 0; k < segs; ++k) {
        const auto c = segmentControlPoints(k);
        const auto b = 3 * static_cast<std::size_t>(k);
        out[b] = c[0];
        out[b + 1] = c[1];
        out[b + 2] = c[2];
    }
    out.back() = m_closed ? m_points.front() : m_points.back();
    return out;
}

PiecewiseBezier HermiteSpline::toPiecewise() const
{
    return piecewiseOf(*this, m_closed);
}

// --- tangent rules ---

namespace {

// Neighbour access for open and closed point lists: the step h_i = s_{i+1} - s_i and the chord
// slope δ_i = (p_{i+1} - p_i) / h_i of segment i (i modulo the segment count when closed).
struct Steps
{
    std::span<const double> s;
    std::span<const Point> p;
    bool closed;
    [[nodiscard]] std::size_t segments() const { return closed ? p.size() : p.size() - 1; }
    [[nodiscard]] double h(std::size_t i) const { return s[i + 1] - s[i]; }
    [[nodiscard]] Point delta(std::size_t i) const
    {
        const std::size_t j = i + 1 == p.size() ? 0 : i + 1;
        return (p[j] - p[i]) / h(i);
    }
    // The segment before point i (the closing one before point 0 of a closed list).
    [[nodiscard]] std::size_t before(std::size_t i) const { return i == 0 ? segments() - 1 : i - 1; }
};

// The tangent at every point: `at(i)` wherever point i has a segment on both sides (every point of a
// closed list, the inner ones of an open list), `atEnds(m)` sets the two ends of an open list. Fewer
// than two points have zero tangents.
template <class At, class AtEnds> std::vector<Point> tangents(const Steps &st, At at, AtEnds atEnds)
{
    const std::size_t n = st.p.size();
    std::vector<Point> m(n, Point::Zero());
    if (n < 2)
        return m;
    for (std::size_t i = st.closed ? 0 : 1; i < (st.closed ? n : n - 1); ++i)
        m[i] = at(i);
    if (!st.closed)
        atEnds(m);
    return m;
}

} // namespace

std::vector<Point> catmullRomTangents(std::span<const double> s, std::span<const Point> p, bool closed)
{
    const Steps st{s, p, closed};
    const auto at = [&](std::size_t i) {
        const std::size_t b = st.before(i);
        const double h0 = st.h(b), h1 = st.h(i);
        return Point((h1 * st.delta(b) + h0 * st.delta(i)) / (h0 + h1));
    };
    return tangents(st, at, [&](std::vector<Point> &m) {
        const std::size_t n = m.size();
        if (n == 2) {
            m[0] = m[1] = st.delta(0);
            return;
        }
        // The derivative of the parabola through the first (last) three points at its end.
        const double h0 = st.h(0), h1 = st.h(1);
        m[0] = st.delta(0) - h0 * (st.delta(1) - st.delta(0)) / (h0 + h1);
        const double ha = st.h(n - 3), hb = st.h(n - 2);
        m[n - 1] = st.delta(n - 2) + hb * (st.delta(n - 2) - st.delta(n - 3)) / (ha + hb);
    });
}

std::vector<Point> cardinalTangents(std::span<const double> s, std::span<const Point> p, double tension, bool closed)
{
    const double f = 1.0 - tension;
    const Steps st{s, p, closed};
    const std::size_t n = p.size();
    // The chord from the point before to the point after, over its parameter span; before point 0 of a
    // closed list lies point n - 1, one period earlier.
    const auto at = [&](std::size_t i) {
        const std::size_t next = i + 1 == n ? 0 : i + 1, prev = i == 0 ? n - 1 : i - 1;
        const double sPrev = i == 0 ? s[n - 1] - (s[n] - s[0]) : s[i - 1];
        return Point(f * (p[next] - p[prev]) / (s[i + 1] - sPrev));
    };
    return tangents(st, at, [&](std::vector<Point> &m) {
        m[0] = f * st.delta(0);
        m[n - 1] = f * st.delta(n - 2);
    });
}

std::vector<Point> finiteDifferenceTangents(std::span<const double> s, std::span<const Point> p, bool closed)
{
    const Steps st{s, p, closed};
    const auto at = [&](std::size_t i) { return Point(0.5 * (st.delta(st.before(i)) + st.delta(i))); };
    return tangents(st, at, [&](std::vector<Point> &m) {
        m[0] = st.delta(0);
        m[m.size() - 1] = st.delta(m.size() - 2);
    });
}

namespace {

Result<HermiteSpline> unitHermite(std::span<const Point> points, Parameterization param, TangentRule rule,
                                  double tension, bool closed)
{
    if (!(tension >= 0.0 && tension <= 1.0))
        return Error{ErrorCode::InvalidArgument, "the tension must lie in [0, 1]", -1};
    auto s = splineParameters(points, param, closed);
    if (!s)
        return s.error();
    std::vector<Point> m;
    switch (rule) {
    case TangentRule::CatmullRom:
        m = catmullRomTangents(*s, points, closed);
        break;
    case TangentRule::Cardinal:
        m = cardinalTangents(*s, points, tension, closed);
        break;
    case TangentRule::FiniteDifference:
        m = finiteDifferenceTangents(*s, points, closed);
        break;
    }
    return HermiteSpline::create(std::move(s).value(), std::vector<Point>(points.begin(), points.end()), std::move(m),
                                 closed);
}

Result<HermiteSpline> unitHermite(std::span<const Point> points, std::span<const Point> tangents,
                                  Parameterization param, bool closed)
{
    for (std::size_t i = 0; i < tangents.size(); ++i)
        if (tangents[i].x() == 0.0 && tangents[i].y() == 0.0) // not squared: 1e-170 is not zero
            return Error{ErrorCode::InvalidArgument, "tangent " + std::to_string(i) + " has zero length",
                         static_cast<int>(i)};
    auto s = splineParameters(points, param, closed);
    if (!s)
        return s.error();
    return HermiteSpline::create(std::move(s).value(), std::vector<Point>(points.begin(), points.end()),
                                 std::vector<Point>(tangents.begin(), tangents.end()), closed);
}

} // namespace

Result<HermiteSpline> scaledBack(const HermiteSpline &unit, const UnitScale &scale, std::span<const Point> points)
{
    std::vector<double> params = unit.parameters();
    std::vector<Point> tangents = unit.tangents();
    if (auto ok = scaleBack(params, scale.paramExponent); !ok)
        return ok.error();
    if (auto ok = scaleBack(tangents, scale.tangentExponent()); !ok)
        return ok.error();
    // Finite points and tangents can still have Bézier handles p ± h m / 3 beyond the largest double.
    std::vector<Point> handles = unit.bezierControlPoints();
    if (auto ok = scaleBack(handles, scale.exponent); !ok)
        return ok.error();
    return HermiteSpline::fromChecked(std::move(params), std::vector<Point>(points.begin(), points.end()),
                                      std::move(tangents), unit.isClosed());
}

// Built on the points scaled to unit size (see UnitScale in knots.h), then scaled back.
Result<HermiteSpline> hermiteSpline(std::span<const Point> points, Parameterization param, TangentRule rule,
                                    double tension, bool closed)
{
    const UnitScale scale = unitScale(points, param);
    if (scale.identity())
        return unitHermite(points, param, rule, tension, closed);
    const std::vector<Point> unitPoints = scale.down(points);
    auto r = unitHermite(unitPoints, param, rule, tension, closed);
    if (!r)
        return r;
    return scaledBack(*r, scale, points);
}

Result<HermiteSpline> hermiteSpline(std::span<const Point> points, std::span<const Point> tangents,
                                    Parameterization param, bool closed)
{
    if (tangents.size() != points.size())
        return Error{ErrorCode::InvalidArgument, "one tangent per point is needed", -1};
    const UnitScale scale = unitScale(points, param);
    if (scale.identity())
        return unitHermite(points, tangents, param, closed);
    const std::vector<Point> unitPoints = scale.down(points);
    std::vector<Point> unitTangents(tangents.begin(), tangents.end());
    for (Point &t : unitTangents)
        t = Point(std::ldexp(t.x(), -scale.tangentExponent()), std::ldexp(t.y(), -scale.tangentExponent()));
    auto r = unitHermite(unitPoints, unitTangents, param, closed);
    if (!r)
        return r;
    return scaledBack(*r, scale, points);
}

} // namespace kontur::geo
