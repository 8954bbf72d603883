// A curve made of Bézier segments joined end to end: the common form every curve kind converts to
// (composite curves now, splines later), with length, bounds, nearest point, flattening and a
// continuity report per joint (G0, G1, C1, G2, C2 and the measured jumps; docs/requirements.md 1.2, §6).
#pragma once

#include "geometry/arclength.h"
#include "geometry/bezier.h"

#include <utility>
#include <vector>

namespace kontur::geo {

enum class Continuity { None, G0, G1, C1, G2, C2 };
[[nodiscard]] const char *nameOf(Continuity c);

// One joint between segment `left` (at t = 1) and segment `right` (at t = 0). Derivatives are with
// respect to each segment's own parameter in [0, 1] (the usual convention for piecewise Bézier).
struct JointContinuity
{
    int left = 0;
    int right = 0;
    double gap = 0.0;           // |B_left(1) - B_right(0)|
    double angle = 0.0;         // radians between the one-sided tangent directions (π if one is undefined)
    double c1Jump = 0.0;        // |B'_left(1) - B'_right(0)|
    double curvatureJump = 0.0; // |κ_left(1) - κ_right(0)| (signed curvatures)
    double c2Jump = 0.0;        // |B''_left(1) - B''_right(0)|
    // C1 and C2 imply G1 here: equal derivatives that vanish (handles on their knots) do not make a
    // kink smooth, so they count only where the tangent directions agree.
    bool g0 = false, g1 = false, c1 = false, g2 = false, c2 = false;
    // The strongest property that holds, in the order None < G0 < G1 < C1 < G2 < C2 (the flags say
    // which of the two incomparable ones, C1 and G2, hold when the level is G2).
    Continuity level = Continuity::None;
};

struct PiecewiseNearest
{
    int segment = 0;
    double t = 0.0;
    Point point = Point::Zero();
    double distance = 0.0;
};

class PiecewiseBezier final
{
public:
    PiecewiseBezier() = default;
    explicit PiecewiseBezier(std::vector<Bezier> segments, bool closed = false);

    [[nodiscard]] const std::vector<Bezier> &segments() const { return m_segments; }
    [[nodiscard]] int segmentCount() const { return static_cast<int>(m_segments.size()); }
    [[nodiscard]] bool isEmpty() const { return m_segments.empty(); }
    [[nodiscard]] bool isClosed() const { return m_closed; }

    // The curve at u in [0, segmentCount()]: segment floor(u) at its local parameter.
    [[nodiscard]] Point eval(double u) const;
    // Total length; `accuracy` (absolute) is shared among the segments.
    [[nodiscard]] double length(double accuracy) const;
    // The same with the accuracy reached: the sum of the segments' (each raised to what its
    // magnitude resolves when asked below it, see arcLengthEstimate).
    [[nodiscard]] LengthEstimate lengthEstimate(double accuracy) const;
    [[nodiscard]] Box boundingBox() const;
    // Global nearest point; segments whose control-polygon box is farther than the best so far are
    // skipped (a curve lies in its control polygon's hull). The segment and t are always found; the
    // distance is +inf only where it is beyond the largest double (a query 1e308 from the curve).
    [[nodiscard]] PiecewiseNearest nearest(const Point &query) const;
    // Appends a polyline within `tolerance` of the whole curve (see flatten in bezier.h).
    void flatten(double tolerance, std::vector<Point> &out) const;

    // One report per interior joint, plus the joint from the last segment to the first when closed.
    // `tolerance` is relative: positions to the segments' size, derivatives to their magnitude,
    // angles in radians.
    [[nodiscard]] std::vector<JointContinuity> continuity(double tolerance = 1e-9) const;

private:
    std::vector<Bezier> m_segments;
    bool m_closed = false;
};

// Any curve of Bézier segments (segmentCount(), segment(i)) as a piecewise curve.
template <class Curve> [[nodiscard]] PiecewiseBezier piecewiseOf(const Curve &curve, bool closed)
{
    std::vector<Bezier> segments;
    segments.reserve(static_cast<std::size_t>(curve.segmentCount()));
    for (int i = 0; i < curve.segmentCount(); ++i)
        segments.push_back(curve.segment(i));
    return PiecewiseBezier(std::move(segments), closed);
}

// The continuity of one joint (the end of `left` against the start of `right`).
[[nodiscard]] JointContinuity jointContinuity(const Bezier &left, const Bezier &right, double tolerance = 1e-9);

} // namespace kontur::geo
