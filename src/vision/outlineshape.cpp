// What makes an Outline a composite curve the document takes: its segments, exact lines where the fit
// is straight, and at least three knots when closed. Shared by the outline tracer and the snapped
// stroke (see edges.h).
#include "vision/edges.h"
#include "vision/outline.h"

#include <cmath>

namespace kontur::vision {

using geo::Point;

geo::Bezier Outline::segment(int i) const
{
    const auto at = static_cast<std::size_t>(3 * i);
    return geo::Bezier({control[at], control[at + 1], control[at + 2], control[at + 3]});
}

namespace detail {

void markStraightSegments(Outline &outline, double tolerance)
{
    outline.line.assign(static_cast<std::size_t>(outline.segmentCount()), false);
    for (int i = 0; i < outline.segmentCount(); ++i) {
        const auto at = static_cast<std::size_t>(3 * i);
        const Point a = outline.control[at], b = outline.control[at + 3];
        const Point d = b - a;
        const double len = d.norm();
        if (len == 0.0)
            continue;
        const Point u = d / len;
        bool straight = true;
        for (std::size_t k = 1; k <= 2 && straight; ++k) {
            const Point r = outline.control[at + k] - a;
            const double along = r.dot(u);
            straight =
                std::abs(u.x() * r.y() - u.y() * r.x()) <= tolerance && along >= -tolerance && along <= len + tolerance;
        }
        if (!straight)
            continue;
        const geo::Bezier line = geo::straightCubic(a, b);
        outline.control[at + 1] = line.controlPoints()[1];
        outline.control[at + 2] = line.controlPoints()[2];
        outline.line[static_cast<std::size_t>(i)] = true;
    }
}

// The longest segment halved, its control points by de Casteljau at t = ½, until there are three.
void atLeastThreeSegments(Outline &out)
{
    while (out.closed && out.segmentCount() > 0 && out.segmentCount() < 3) {
        int longest = 0;
        double best = -1.0;
        for (int i = 0; i < out.segmentCount(); ++i) {
            const auto at = static_cast<std::size_t>(3 * i);
            double polygon = 0.0;
            for (std::size_t k = 0; k < 3; ++k)
                polygon += (out.control[at + k + 1] - out.control[at + k]).norm();
            if (polygon > best)
                best = polygon, longest = i;
        }
        const auto at = static_cast<std::size_t>(3 * longest);
        const Point p0 = out.control[at], p1 = out.control[at + 1], p2 = out.control[at + 2], p3 = out.control[at + 3];
        const Point q1 = 0.5 * (p0 + p1), q2 = 0.25 * (p0 + 2.0 * p1 + p2), m = 0.125 * (p0 + 3.0 * p1 + 3.0 * p2 + p3);
        const Point r1 = 0.25 * (p1 + 2.0 * p2 + p3), r2 = 0.5 * (p2 + p3);
        out.control[at + 1] = q1;
        out.control[at + 2] = q2;
        out.control.insert(out.control.begin() + static_cast<std::ptrdiff_t>(at + 3), {m, r1, r2});
        out.corner.insert(out.corner.begin() + longest + 1, false);
        if (static_cast<std::size_t>(longest) < out.line.size())
            out.line.insert(out.line.begin() + longest, out.line[static_cast<std::size_t>(longest)]);
    }
}

} // namespace detail

} // namespace kontur::vision
