// The composite curve of seed 000 (see composite.h).
#include "geometry/composite.h"

#include "geometry/parameterization.h"
#include "geometry/piecewise.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace kontur::geo {

namespace {

// |v| without overflowing or underflowing the squares (Eigen's norm() squares: NaN-free only
// between ~1e-154 and ~1e154).
double length(const Point &v)
{
    return std::hypot(v.x(), v.y());
}

Point direction(const Point &v)
{
    const double m = v.cwiseAbs().maxCoeff();
    if (!(m > 0.0))
        return Point::Zero();
    const Point u = v / m;
    return u / length(u);
}

} // namespace

std::pair<Point, Point> interiorHandles(const Point &prev, const Point &p, const Point &next)
{
    // docs/requirements.md 1.2: c_{3i-1} = p_i + ½ l1/(l1+l2) (p_{i-1} - p_{i+1}),
    //              c_{3i+1} = p_i + ½ l2/(l1+l2) (p_{i+1} - p_{i-1}).
    // Only the ratios l1/(l1+l2) matter: measured on the three points scaled to unit size by a power
    // of two (exact), so the squares in |·| neither overflow (NaN handles at 1e160) nor underflow
    // (handles collapsed onto their knots at 1e-170). Halves keep next - prev finite at ±1e308.
    const std::array<Point, 3> three = {prev, p, next};
    const double unit = std::ldexp(1.0, -scaleExponent(three));
    const double l1 = unitDistance(prev, p, unit);
    const double l2 = unitDistance(p, next, unit);
    const double sum = l1 + l2;
    if (!(sum > 0.0))
        return {p, p};
    const Point half = 0.5 * next - 0.5 * prev;
    return {p - (l1 / sum) * half, p + (l2 / sum) * half};
}

Point mirrorHandle(const Point &handle, const Point &near, const Point &far)
{
    // Reflection across the perpendicular bisector of near–far (docs/requirements.md 1.2, the first/last handle).
    // The factor 1 - 2 v·w/|v|² does not depend on the scale: computed on the points scaled to unit
    // size by a power of two, so v·w and |v|² neither overflow nor underflow.
    if (near == far)
        return far;
    const std::array<Point, 3> three = {handle, near, far};
    const double unit = std::ldexp(1.0, -scaleExponent(three));
    const Point v = unit * far - unit * near;
    const Point w = unit * handle - unit * near;
    const double v2 = v.squaredNorm();
    if (!(v2 > 0.0))
        return far;
    const double factor = 1.0 - 2.0 * v.dot(w) / v2;
    return handle + (0.5 * far - 0.5 * near) * (2.0 * factor);
}

std::array<Point, 4> twoKnotCurve(const Point &p0, const Point &p1)
{
    // docs/requirements.md 1.2: rotating both half-chords by +60° puts the handles on opposite sides: an S.
    const double c = 0.5;
    const double s = std::sqrt(3.0) / 2.0;
    auto rot = [&](const Point &v) { return Point(c * v.x() - s * v.y(), s * v.x() + c * v.y()); };
    const Point m = 0.5 * (p0 + p1);
    return {p0, p0 + rot(m - p0), p1 + rot(m - p1), p1};
}

CompositeCurve::CompositeCurve(std::span<const Point> knots)
    : m_types(knots.size(), NodeType::Smooth)
    , m_finished(true)
{
    const std::size_t n = knots.size();
    if (n == 0)
        return;
    if (n == 1) {
        m_control = {knots[0]};
        return;
    }
    if (n == 2) {
        const auto c = twoKnotCurve(knots[0], knots[1]);
        m_control.assign(c.begin(), c.end());
        return;
    }
    m_control.resize(3 * n - 2);
    for (std::size_t i = 0; i < n; ++i)
        m_control[3 * i] = knots[i];
    for (std::size_t i = 1; i + 1 < n; ++i)
        constructInterior(static_cast<int>(i), knots[i - 1], knots[i + 1]);
    constructEnds();
}

void CompositeCurve::constructInterior(int k, const Point &prev, const Point &next)
{
    const auto [in, out] = interiorHandles(prev, knot(k), next);
    setControl(inHandleIndex(k), in);
    setControl(outHandleIndex(k), out);
}

void CompositeCurve::constructEnds()
{
    // Open curve with n >= 3: the first and last handles mirror their neighbours (docs/requirements.md 1.2).
    const int n = knotCount();
    m_control[1] = mirrorHandle(m_control[2], knot(1), knot(0));
    const std::size_t last = m_control.size() - 1;
    m_control[last - 1] = mirrorHandle(m_control[last - 2], knot(n - 2), knot(n - 1));
}

Result<SegmentRange> CompositeCurve::appendKnot(const Point &p)
{
    if (m_closed)
        return Error{ErrorCode::InvalidArgument, "a closed curve has no end to add knots to", -1};
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return Error{ErrorCode::NonFiniteInput, "the knot is not finite", knotCount()};
    m_types.push_back(NodeType::Smooth);
    const int n = knotCount();
    if (n == 1) {
        m_control = {p};
        return SegmentRange{0, 0};
    }
    if (n == 2) {
        const auto c = twoKnotCurve(m_control[0], p);
        m_control.assign(c.begin(), c.end());
        return SegmentRange{0, 1};
    }
    m_control.resize(3 * static_cast<std::size_t>(n) - 2);
    m_control.back() = p;
    // The previous last knot becomes interior; the mirrored end handles follow (docs/requirements.md 1.2).
    constructInterior(n - 2, knot(n - 3), p);
    if (n == 3)
        m_control[1] = mirrorHandle(m_control[2], knot(1), knot(0));
    const std::size_t last = m_control.size() - 1;
    m_control[last - 1] = mirrorHandle(m_control[last - 2], knot(n - 2), knot(n - 1));
    return SegmentRange{n - 3, 2};
}

int CompositeCurve::visibleSegmentCount() const
{
    const int count = segmentCount();
    return m_finished ? count : std::max(0, knotCount() - 2);
}

int CompositeCurve::segmentCount() const
{
    const int n = knotCount();
    if (n < 2)
        return 0;
    return m_closed ? n : n - 1;
}

std::vector<Point> CompositeCurve::knots() const
{
    std::vector<Point> k(static_cast<std::size_t>(knotCount()));
    for (int i = 0; i < knotCount(); ++i)
        k[i] = knot(i);
    return k;
}

std::array<Point, 4> CompositeCurve::segmentPoints(int i) const
{
    const std::size_t b = 3 * static_cast<std::size_t>(i);
    return {m_control[b], m_control[b + 1], m_control[b + 2], m_control[b + 3]};
}

Bezier CompositeCurve::segment(int i) const
{
    const auto c = segmentPoints(i);
    return Bezier({c.begin(), c.end()});
}

PiecewiseBezier CompositeCurve::toPiecewise() const
{
    return piecewiseOf(*this, m_closed);
}

int CompositeCurve::knotOfControl(int ci) const
{
    const int n = knotCount();
    int k = ci % 3 == 2 ? (ci + 1) / 3 : ci / 3;
    if (m_closed && k == n)
        k = 0;
    return k;
}

int CompositeCurve::inHandleIndex(int k) const
{
    const int n = knotCount();
    if (n < 2)
        return -1;
    if (k == 0)
        return m_closed ? 3 * n - 1 : -1;
    return 3 * k - 1;
}

int CompositeCurve::outHandleIndex(int k) const
{
    const int n = knotCount();
    if (n < 2)
        return -1;
    if (k == n - 1 && !m_closed)
        return -1;
    return 3 * k + 1;
}

int CompositeCurve::oppositeHandle(int ci) const
{
    const int k = knotOfControl(ci);
    return ci % 3 == 1 ? inHandleIndex(k) : outHandleIndex(k);
}

int CompositeCurve::segmentOfControl(int ci) const
{
    return ci / 3;
}

SegmentRange CompositeCurve::segmentsOfKnot(int k) const
{
    const int n = knotCount();
    const int count = segmentCount();
    if (count == 0)
        return {0, 0};
    if (m_closed)
        return {(k - 1 + n) % n, 2};
    if (k == 0)
        return {0, 1};
    if (k == n - 1)
        return {n - 2, 1};
    return {k - 1, 2};
}

void CompositeCurve::setControl(int ci, const Point &p)
{
    m_control[static_cast<std::size_t>(ci)] = p;
    // A closed curve stores its first knot twice (the end of the closing segment).
    if (m_closed) {
        const std::size_t last = m_control.size() - 1;
        if (ci == 0)
            m_control[last] = p;
        else if (static_cast<std::size_t>(ci) == last)
            m_control[0] = p;
    }
}

void CompositeCurve::setControlPoint(int ci, const Point &p)
{
    if (ci >= 0 && static_cast<std::size_t>(ci) < m_control.size())
        setControl(ci, p);
}

void CompositeCurve::setNodeTypeOnly(int k, NodeType type)
{
    if (k >= 0 && k < knotCount())
        m_types[static_cast<std::size_t>(k)] = type;
}

Result<CompositeCurve> CompositeCurve::fromParts(std::vector<Point> control, std::vector<NodeType> types, bool closed)
{
    const std::size_t n = types.size();
    const std::size_t expected = closed ? 3 * n + 1 : (n == 0 ? 0 : 3 * n - 2);
    if (control.size() != expected || (closed && n < 3))
        return Error{ErrorCode::InvalidArgument, "a composite curve of " + std::to_string(n) + " knots has " +
                                                     std::to_string(expected) + " control points, not " +
                                                     std::to_string(control.size())};
    for (std::size_t i = 0; i < control.size(); ++i)
        if (!control[i].allFinite())
            return Error{ErrorCode::NonFiniteInput, "control point " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
    if (closed && control.front() != control.back())
        return Error{ErrorCode::InvalidArgument, "a closed composite curve ends where it starts"};
    CompositeCurve curve;
    curve.m_control = std::move(control);
    curve.m_types = std::move(types);
    curve.m_closed = closed;
    curve.m_finished = true;
    return curve;
}

void CompositeCurve::setKnotPosition(int k, const Point &p)
{
    const Point delta = p - knot(k);
    setControl(3 * k, p);
    if (const int in = inHandleIndex(k); in >= 0)
        m_control[static_cast<std::size_t>(in)] += delta;
    if (const int out = outHandleIndex(k); out >= 0)
        m_control[static_cast<std::size_t>(out)] += delta;
}

Result<SegmentRange> CompositeCurve::setNodeType(int k, NodeType type)
{
    if (k < 0 || k >= knotCount())
        return Error{ErrorCode::IndexOutOfRange, "no knot " + std::to_string(k), k};
    m_types[static_cast<std::size_t>(k)] = type;
    const int in = inHandleIndex(k);
    const int out = outHandleIndex(k);
    if (type == NodeType::Corner || in < 0 || out < 0)
        return SegmentRange{0, 0};
    const Point K = knot(k);
    const Point a = m_control[static_cast<std::size_t>(in)] - K;
    const Point b = m_control[static_cast<std::size_t>(out)] - K;
    const Point dir = b - a;
    const double len = length(dir);
    if (!(len > 0.0))
        return SegmentRange{0, 0};
    const Point u = direction(dir);
    double la = length(a), lb = length(b);
    if (type == NodeType::Symmetric)
        la = lb = 0.5 * (la + lb);
    setControl(in, K - la * u);
    setControl(out, K + lb * u);
    return segmentsOfKnot(k);
}

Result<SegmentRange> CompositeCurve::moveHandle(int ci, const Point &pointer, HandleMove mode)
{
    if (ci < 0 || static_cast<std::size_t>(ci) >= m_control.size() || isKnotIndex(ci) || segmentCount() == 0)
        return Error{ErrorCode::IndexOutOfRange, "no handle " + std::to_string(ci), ci};
    if (!std::isfinite(pointer.x()) || !std::isfinite(pointer.y()))
        return Error{ErrorCode::NonFiniteInput, "the position is not finite", ci};
    const int k = knotOfControl(ci);
    const Point K = knot(k);
    const int o = oppositeHandle(ci);
    if (o < 0) {
        setControl(ci, pointer);
        return SegmentRange{segmentOfControl(ci), 1};
    }
    const NodeType type = nodeType(k);
    const Point opposite = m_control[static_cast<std::size_t>(o)];
    bool oppositeMoved = false;
    if (mode == HandleMove::Free) {
        setControl(ci, pointer);
        if (type == NodeType::Smooth) {
            // r = knot + (knot - dragged)/|knot - dragged| · |opposite - knot| (docs/requirements.md 1.4);
            // a handle dragged onto its knot has no direction, and the opposite one stays put.
            const Point d = K - pointer;
            const double len = length(d);
            if (len > 0.0) {
                setControl(o, K + direction(d) * length(opposite - K));
                oppositeMoved = true;
            }
        } else if (type == NodeType::Symmetric) {
            setControl(o, 2.0 * K - pointer);
            oppositeMoved = true;
        }
    } else {
        // r = knot + (knot - opposite)/|knot - opposite| · |pointer - knot| (docs/requirements.md 1.4). Where
        // that direction does not exist, fall back to the handle's own, then to its segment's chord.
        const Point own = m_control[static_cast<std::size_t>(ci)] - K;
        Point u = type == NodeType::Corner ? own : Point(K - opposite);
        if (!(u.squaredNorm() > 0.0))
            u = own;
        if (!(u.squaredNorm() > 0.0)) {
            const int s = segmentOfControl(ci);
            const Point other = ci % 3 == 1 ? m_control[3 * static_cast<std::size_t>(s) + 3]
                                            : m_control[3 * static_cast<std::size_t>(s)];
            u = other - K;
        }
        if (!(u.squaredNorm() > 0.0))
            u = Point(1.0, 0.0);
        const Point moved = K + direction(u) * length(pointer - K);
        setControl(ci, moved);
        if (type == NodeType::Symmetric) {
            setControl(o, 2.0 * K - moved);
            oppositeMoved = true;
        }
    }
    return oppositeMoved ? segmentsOfKnot(k) : SegmentRange{segmentOfControl(ci), 1};
}

Result<SegmentRange> CompositeCurve::moveKnot(int k, const Point &position)
{
    if (k < 0 || k >= knotCount())
        return Error{ErrorCode::IndexOutOfRange, "no knot " + std::to_string(k), k};
    if (!std::isfinite(position.x()) || !std::isfinite(position.y()))
        return Error{ErrorCode::NonFiniteInput, "the position is not finite", k};
    setKnotPosition(k, position);
    return segmentsOfKnot(k);
}

Result<SegmentRange> CompositeCurve::moveControlPoint(int ci, const Point &position, HandleMove mode)
{
    if (ci < 0 || static_cast<std::size_t>(ci) >= m_control.size())
        return Error{ErrorCode::IndexOutOfRange, "no control point " + std::to_string(ci), ci};
    if (isKnotIndex(ci))
        return moveKnot(knotOfControl(ci), position);
    return moveHandle(ci, position, mode);
}

Result<SegmentRange> CompositeCurve::insertKnot(int s, double t)
{
    if (s < 0 || s >= segmentCount())
        return Error{ErrorCode::IndexOutOfRange, "no segment " + std::to_string(s), s};
    if (!(t > 0.0 && t < 1.0))
        return Error{ErrorCode::InvalidArgument, "a knot is inserted at t strictly between 0 and 1", s};
    const auto [left, right] = segment(s).split(t);
    const std::size_t b = 3 * static_cast<std::size_t>(s);
    m_control[b + 1] = left.controlPoints()[1];
    m_control[b + 2] = left.controlPoints()[2];
    const std::array<Point, 3> added = {left.controlPoints()[3], right.controlPoints()[1], right.controlPoints()[2]};
    m_control.insert(m_control.begin() + static_cast<std::ptrdiff_t>(b + 3), added.begin(), added.end());
    m_types.insert(m_types.begin() + s + 1, NodeType::Smooth);
    return SegmentRange{s, 2};
}

Result<SegmentRange> CompositeCurve::deleteKnot(int k)
{
    const int n = knotCount();
    if (k < 0 || k >= n)
        return Error{ErrorCode::IndexOutOfRange, "no knot " + std::to_string(k), k};
    if (n <= (m_closed ? 3 : 2))
        return Error{ErrorCode::TooFewPoints,
                     m_closed ? "a closed composite curve needs at least 3 knots"
                              : "composite curves can not have less than 2 knot points",
                     k};
    const auto begin = m_control.begin();
    if (!m_closed && k == 0) {
        m_control.erase(begin, begin + 3);
        m_types.erase(m_types.begin());
        return SegmentRange{0, 0};
    }
    if (!m_closed && k == n - 1) {
        m_control.erase(m_control.end() - 3, m_control.end());
        m_types.pop_back();
        return SegmentRange{0, 0};
    }
    if (m_closed && k == 0) {
        // The closing segment and segment 0 merge; knot 1 becomes the first knot.
        std::vector<Point> next(m_control.begin() + 3, m_control.end() - 2);
        next.push_back(m_control[2]);
        next.push_back(m_control[3]);
        m_control = std::move(next);
        m_types.erase(m_types.begin());
        return SegmentRange{n - 2, 1};
    }
    // Interior: drop the knot and its two handles; segment k-1 now joins knots k-1 and k+1.
    const std::ptrdiff_t first = 3 * static_cast<std::ptrdiff_t>(k) - 1;
    m_control.erase(begin + first, begin + first + 3);
    m_types.erase(m_types.begin() + k);
    return SegmentRange{k - 1, 1};
}

Result<SegmentRange> CompositeCurve::close()
{
    if (m_closed)
        return Error{ErrorCode::InvalidArgument, "the curve is already closed", -1};
    int n = knotCount();
    if (n < 3)
        return Error{ErrorCode::TooFewPoints, "closing needs at least 3 knots", n};
    const Point first = knot(0);
    // A last knot on the first one is that closing already: merged, not joined by a segment of
    // length zero (as the periodic spline drops such a duplicate).
    if (knot(n - 1) == first) {
        if (n <= 3)
            return Error{ErrorCode::TooFewPoints, "closing needs at least 3 knots", n - 1};
        m_control.erase(m_control.end() - 3, m_control.end());
        m_types.pop_back();
        --n;
    }
    m_control.push_back(Point::Zero()); // outgoing handle of the last knot
    m_control.push_back(Point::Zero()); // incoming handle of knot 0
    m_control.push_back(first);
    m_closed = true;
    m_finished = true;
    constructInterior(0, knot(n - 1), knot(1));
    constructInterior(n - 1, knot(n - 2), first);
    m_types.front() = NodeType::Smooth;
    m_types.back() = NodeType::Smooth;
    return SegmentRange{n - 2, 3};
}

Result<CompositeCurve> compositeFromPieces(std::span<const Bezier> pieces, bool closed)
{
    if (pieces.empty())
        return Error{ErrorCode::TooFewPoints, "no piece to make a composite curve of"};
    std::vector<Bezier> cubics;
    cubics.reserve(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const int degree = pieces[i].degree();
        if (degree > 3)
            return Error{ErrorCode::InvalidArgument,
                         "piece " + std::to_string(i) + " has degree " + std::to_string(degree) + ", above 3",
                         static_cast<int>(i)};
        cubics.push_back(degree < 3 ? pieces[i].elevated(3 - degree) : pieces[i]);
    }
    std::vector<Point> control{cubics.front().controlPoints().front()};
    control.reserve(3 * cubics.size() + 1);
    for (std::size_t i = 0; i < cubics.size(); ++i) {
        const std::vector<Point> &c = cubics[i].controlPoints();
        const double size = std::max({1.0, c[0].cwiseAbs().maxCoeff(), c[3].cwiseAbs().maxCoeff()});
        if ((c[0] - control.back()).norm() > 1e-9 * size)
            return Error{ErrorCode::InvalidArgument,
                         "piece " + std::to_string(i) +
                             " does not start where the one "
                             "before it ends",
                         static_cast<int>(i)};
        control.insert(control.end(), c.begin() + 1, c.end());
    }
    const auto typeOf = [](const Bezier &left, const Bezier &right) {
        const JointContinuity j = jointContinuity(left, right);
        return j.c1 ? NodeType::Symmetric : j.g1 ? NodeType::Smooth : NodeType::Corner;
    };
    std::vector<NodeType> types;
    const std::size_t m = cubics.size();
    if (closed) {
        const double size =
            std::max({1.0, control.front().cwiseAbs().maxCoeff(), control.back().cwiseAbs().maxCoeff()});
        if ((control.back() - control.front()).norm() > 1e-9 * size)
            return Error{ErrorCode::InvalidArgument, "a closed curve's last piece does not end where the first begins"};
        control.back() = control.front();
        types.push_back(typeOf(cubics[m - 1], cubics[0]));
        for (std::size_t i = 1; i < m; ++i)
            types.push_back(typeOf(cubics[i - 1], cubics[i]));
    } else {
        types.push_back(NodeType::Smooth);
        for (std::size_t i = 1; i < m; ++i)
            types.push_back(typeOf(cubics[i - 1], cubics[i]));
        types.push_back(NodeType::Smooth);
    }
    return CompositeCurve::fromParts(std::move(control), std::move(types), closed);
}

} // namespace kontur::geo
