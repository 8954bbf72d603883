// The nearest point on straight pieces: see polyline.h.
#include "geometry/polyline.h"

#include <limits>

namespace kontur::geo {

PolylinePoint nearestOnPolyline(const std::vector<Point> &points, const Point &p, bool closed)
{
    const std::size_t n = points.size();
    if (n == 0)
        return {};
    PolylinePoint best{points.front(), 0};
    double bestD = std::numeric_limits<double>::infinity();
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const Point q = nearestOnSegment(p, points[i], points[(i + 1) % n]);
        const double d = (q - p).squaredNorm();
        if (d < bestD)
            bestD = d, best = {q, i};
    }
    return best;
}

} // namespace kontur::geo
