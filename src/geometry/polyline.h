// The nearest point on straight pieces: on a segment, and on a polyline, open or closed. Lengths and
// points are in the caller's units (px or mm); nothing here scales them.
#pragma once

#include "geometry/bezier.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace kontur::geo {

// The parameter t in [0, 1] of the point a + t·(b − a) of segment a–b nearest to p: the projection of p
// onto the segment's line, clamped to its ends; 0 when a = b.
[[nodiscard]] inline double nearestSegmentParameter(const Point &p, const Point &a, const Point &b)
{
    const Point ab = b - a;
    const double len2 = ab.squaredNorm();
    return len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
}

// The point of segment a–b nearest to p (a when a = b).
[[nodiscard]] inline Point nearestOnSegment(const Point &p, const Point &a, const Point &b)
{
    return a + nearestSegmentParameter(p, a, b) * (b - a);
}

struct PolylinePoint
{
    Point point = Point::Zero(); // the nearest point
    std::size_t segment = 0;     // it lies on the segment from points[segment] to points[segment + 1]
};

// The point of a polyline nearest to p. Segment i runs from points[i] to points[i + 1]; a closed
// polyline has one more, from its last point back to its first (i = size − 1). Ties go to the lowest
// segment. A single point is its own nearest (segment 0); no points answer the origin (segment 0).
[[nodiscard]] PolylinePoint nearestOnPolyline(const std::vector<Point> &points, const Point &p, bool closed);

} // namespace kontur::geo
