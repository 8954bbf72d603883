// Whole-curve edits of composite curves: see compositeedit.h.
#include "geometry/compositeedit.h"

#include "geometry/measure.h"
#include "geometry/piecewise.h"
#include "geometry/strokefit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::geo {

namespace {

// The direction a cubic leaves its first point / arrives at its last: the first non-zero of the
// chords to the next control points (a handle on its knot gives no direction; the curve's own
// tangent there is then along the next chord).
Point startTangent(const std::array<Point, 4> &c)
{
    for (int i = 1; i < 4; ++i)
        if (const Point d = c[static_cast<std::size_t>(i)] - c[0]; d.squaredNorm() > 0.0)
            return d;
    return Point::Zero();
}

Point endTangent(const std::array<Point, 4> &c)
{
    for (int i = 2; i >= 0; --i)
        if (const Point d = c[3] - c[static_cast<std::size_t>(i)]; d.squaredNorm() > 0.0)
            return d;
    return Point::Zero();
}

// The turn from direction u to direction v in degrees (0 where either has no direction).
double turnDegrees(const Point &u, const Point &v)
{
    const double lu = u.norm(), lv = v.norm();
    if (!(lu > 0.0) || !(lv > 0.0))
        return 0.0;
    const double cosine = std::clamp(u.dot(v) / (lu * lv), -1.0, 1.0);
    return std::acos(cosine) * 180.0 / std::numbers::pi;
}

std::vector<NodeType> typesOf(const CompositeCurve &curve)
{
    std::vector<NodeType> types;
    types.reserve(static_cast<std::size_t>(curve.knotCount()));
    for (int k = 0; k < curve.knotCount(); ++k)
        types.push_back(curve.nodeType(k));
    return types;
}

Result<CompositeCurve> finished(Result<CompositeCurve> curve)
{
    if (curve)
        curve->finish();
    return curve;
}

Error notOpen(const char *what)
{
    return Error{ErrorCode::InvalidArgument, what, -1};
}

} // namespace

Result<CompositeCurve> reversed(const CompositeCurve &curve)
{
    if (curve.isClosed())
        return notOpen("only an open curve is reversed");
    std::vector<Point> control(curve.controlPoints().rbegin(), curve.controlPoints().rend());
    std::vector<NodeType> types = typesOf(curve);
    std::reverse(types.begin(), types.end());
    return finished(CompositeCurve::fromParts(std::move(control), std::move(types), false));
}

Result<CompositeCurve> joinComposites(const CompositeCurve &a, const CompositeCurve &b, const JoinOptions &options)
{
    if (a.isClosed() || b.isClosed())
        return notOpen("closed curves have no ends to join");
    if (a.knotCount() < 2 || b.knotCount() < 2)
        return Error{ErrorCode::TooFewPoints, "a curve to join needs 2 knots", -1};
    const Point end = a.knot(a.knotCount() - 1);
    const Point start = b.knot(0);
    std::vector<Point> control = a.controlPoints();
    std::vector<NodeType> types = typesOf(a);
    types.pop_back(); // the joint's type is decided below
    const std::vector<Point> &next = b.controlPoints();
    const std::vector<NodeType> nextTypes = typesOf(b);
    if ((start - end).norm() <= options.mergeDistance) {
        // One knot at a's end: b's first knot and its handle move by the gap.
        const Point gap = end - start;
        Point handle = next[1] + gap;
        const Point incoming = endTangent(a.segmentPoints(a.segmentCount() - 1));
        const Point outgoing = startTangent({end, handle, next[2], next[3]});
        const bool corner = turnDegrees(incoming, outgoing) > options.cornerAngle;
        if (!corner && incoming.squaredNorm() > 0.0 && (handle - end).squaredNorm() > 0.0)
            handle = end + incoming.normalized() * (handle - end).norm(); // a stays; b's handle turns
        types.push_back(corner ? NodeType::Corner : NodeType::Smooth);
        control.push_back(handle);
        control.insert(control.end(), next.begin() + 2, next.end());
    } else {
        // A straight segment from a's end to b's start, both its knots corners.
        types.push_back(NodeType::Corner);
        const Bezier straight = straightCubic(end, start);
        control.push_back(straight.controlPoints()[1]);
        control.push_back(straight.controlPoints()[2]);
        control.insert(control.end(), next.begin(), next.end());
        types.push_back(NodeType::Corner);
    }
    types.insert(types.end(), nextTypes.begin() + 1, nextTypes.end());
    return finished(CompositeCurve::fromParts(std::move(control), std::move(types), false));
}

Result<CompositeCurve> closeJoined(const CompositeCurve &curve, const JoinOptions &options)
{
    if (curve.isClosed())
        return notOpen("the curve is already closed");
    const int n = curve.knotCount();
    const Point first = curve.knot(0);
    if (n >= 4 && (curve.knot(n - 1) - first).norm() <= options.mergeDistance) {
        std::vector<Point> control = curve.controlPoints();
        const std::size_t last = control.size() - 1;
        control[last - 1] += first - control[last];
        control[last] = first;
        std::vector<NodeType> types = typesOf(curve);
        types.pop_back();
        const Point incoming = endTangent({control[last - 3], control[last - 2], control[last - 1], first});
        const Point outgoing = startTangent(curve.segmentPoints(0));
        const bool corner = turnDegrees(incoming, outgoing) > options.cornerAngle;
        types.front() = corner ? NodeType::Corner : NodeType::Smooth;
        auto closed = finished(CompositeCurve::fromParts(std::move(control), std::move(types), true));
        if (closed && !corner) {
            // Nearly continuing ends: make the handles collinear (their mean direction).
            if (auto set = closed->setNodeType(0, NodeType::Smooth); !set)
                return set.error();
        }
        return closed;
    }
    CompositeCurve copy = curve;
    if (auto done = copy.close(); !done)
        return done.error();
    return copy;
}

Result<CompositeCurve> makeSegmentLine(const CompositeCurve &curve, int segment)
{
    if (segment < 0 || segment >= curve.segmentCount())
        return Error{ErrorCode::IndexOutOfRange, "no segment " + std::to_string(segment), segment};
    CompositeCurve line = curve;
    const int n = curve.knotCount();
    const int k0 = segment, k1 = (segment + 1) % n;
    const Point p0 = curve.knot(k0), p1 = curve.knot(k1);
    const int base = 3 * segment;
    const Bezier straight = straightCubic(p0, p1);
    line.setControlPoint(base + 1, straight.controlPoints()[1]);
    line.setControlPoint(base + 2, straight.controlPoints()[2]);
    line.setNodeTypeOnly(k0, NodeType::Corner);
    line.setNodeTypeOnly(k1, NodeType::Corner);
    return line;
}

namespace {

// The curve's points from knot `from` to knot `to` (to > from; indices modulo the knot count on a
// closed curve), `perSegment` samples per segment, the knots exact.
std::vector<Point> sampleRun(const CompositeCurve &curve, int from, int to, int perSegment)
{
    const int segments = curve.segmentCount();
    std::vector<Point> points;
    points.reserve(static_cast<std::size_t>((to - from) * perSegment + 1));
    for (int s = from; s < to; ++s) {
        const Bezier segment = curve.segment(s % segments);
        points.push_back(curve.knot(s % curve.knotCount()));
        for (int i = 1; i < perSegment; ++i)
            points.push_back(segment.eval(static_cast<double>(i) / perSegment));
    }
    points.push_back(curve.knot(to % curve.knotCount()));
    return points;
}

Result<CompositeCurve> refit(const CompositeCurve &curve, double fitTolerance)
{
    const int n = curve.knotCount();
    const bool closed = curve.isClosed();
    // The knots that stay: every Corner, and an open curve's ends.
    std::vector<int> breaks;
    for (int k = 0; k < n; ++k)
        if (curve.nodeType(k) == NodeType::Corner || (!closed && (k == 0 || k == n - 1)))
            breaks.push_back(k);
    const bool loop = closed && breaks.empty(); // no corner: one run round from knot 0
    if (loop)
        breaks.push_back(0);
    if (closed)
        breaks.push_back(breaks.front() + n);
    constexpr int perSegment = 32;
    StrokeFitOptions options;
    options.tolerance = fitTolerance;
    std::vector<Point> control;
    std::vector<NodeType> types;
    for (std::size_t r = 0; r + 1 < breaks.size(); ++r) {
        const int from = breaks[r], to = breaks[r + 1];
        const std::vector<Point> samples = sampleRun(curve, from, to, perSegment);
        auto fit = fitStroke(samples, options);
        if (!fit)
            return fit.error();
        std::vector<Point> runControl = std::move(fit->control);
        runControl.front() = samples.front();
        runControl.back() = samples.back();
        // The run's own knots take the fit's corners; its end knots are the original's.
        const std::size_t skip = r == 0 ? 0 : 1;
        control.insert(control.end(), runControl.begin() + static_cast<std::ptrdiff_t>(skip), runControl.end());
        if (r == 0)
            types.push_back(curve.nodeType(from % n));
        for (std::size_t k = 1; k + 1 < fit->corner.size(); ++k)
            types.push_back(fit->corner[k] ? NodeType::Corner : NodeType::Smooth);
        types.push_back(curve.nodeType(to % n));
    }
    if (closed) {
        types.pop_back(); // the first knot again
        control.back() = control.front();
    }
    auto made = finished(CompositeCurve::fromParts(std::move(control), std::move(types), closed));
    if (made && loop) {
        if (auto set = made->setNodeType(0, NodeType::Smooth); !set)
            return set.error();
    }
    return made;
}

} // namespace

Result<Simplified> simplifyComposite(const CompositeCurve &curve, double tolerance)
{
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        return Error{ErrorCode::InvalidArgument, "the tolerance must be a positive number", -1};
    if (curve.segmentCount() == 0)
        return Error{ErrorCode::TooFewPoints, "an empty curve has nothing to simplify", -1};
    const PiecewiseBezier original = curve.toPiecewise();
    // The fit bounds the distance of the samples to the new curve; the new curve's distance back to
    // the old one is measured. Tighter fits first give up knots, then give up.
    for (const double factor : {0.8, 0.5, 0.3}) {
        auto fitted = refit(curve, factor * tolerance);
        if (!fitted)
            return fitted.error();
        if (fitted->knotCount() >= curve.knotCount())
            return Error{ErrorCode::InvalidArgument, "no curve with fewer knots within the tolerance", -1};
        const auto measured = deviation(original, fitted->toPiecewise());
        if (!measured)
            return measured.error();
        if (measured->maximum <= tolerance)
            return Simplified{std::move(*fitted), measured->maximum};
    }
    return Error{ErrorCode::InvalidArgument, "no curve with fewer knots within the tolerance", -1};
}

} // namespace kontur::geo
