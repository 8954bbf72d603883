// Closed loops of points: a piece's edge points with the arc length along them, and an outline
// sampled into such a loop in pixels. Internal to kontur_vision.
#pragma once

#include "geometry/bezier.h"
#include "vision/outline.h"
#include "vision/pixelmapping.h"

#include <cstddef>
#include <vector>

namespace kontur::vision {

namespace detail {

// A closed polyline (at least one point) with the arc length along it, in the points' own units (px
// where the edge points are found, mm where the outline is fitted). Its segments run from each point
// to the next and from the last back to the first, which total() includes. Indices wrap and count on
// over the laps: point(i) is points()[i % size()] at arc(i) = arc(i % size()) + (i / size())·total(),
// so a stretch across the closing point has increasing indices and lengths; arc(0) = 0. Arc lengths
// given to at() and between() wrap too, and may be negative.
class Loop
{
public:
    explicit Loop(std::vector<geo::Point> points);

    [[nodiscard]] std::size_t size() const { return m_points.size(); }
    [[nodiscard]] double total() const { return m_arc.back(); }
    [[nodiscard]] const std::vector<geo::Point> &points() const { return m_points; }
    [[nodiscard]] const geo::Point &point(std::size_t i) const { return m_points[i % m_points.size()]; }
    [[nodiscard]] double arc(std::size_t i) const
    {
        const std::size_t n = m_points.size();
        return m_arc[i % n] + static_cast<double>(i / n) * total();
    }
    // The point at arc length s, between the loop's points.
    [[nodiscard]] geo::Point at(double s) const;
    // The loop's points with arc length in [from, to], in order; from and to may lie up to one lap
    // outside [0, total()] (the points of laps −1, 0 and 1 are looked at).
    [[nodiscard]] std::vector<geo::Point> between(double from, double to) const;
    // The first index k >= i with arc(k) >= arc(i) + length, i + size() at most.
    [[nodiscard]] std::size_t ahead(std::size_t i, double length) const;

private:
    std::vector<geo::Point> m_points;
    std::vector<double> m_arc; // size() + 1: m_arc[i] from point 0 to point i, the last the total
};

} // namespace detail

// A closed outline as a polygon in px (mapping.toPixel of the outline's points in mm): each segment
// sampled at t = k / m, k = 0 .. m − 1, where m is the length of its control polygon in px rounded up
// (2 at least). The control polygon is at least as long as the curve, so the points lie a pixel apart
// or less on average over a segment (closer where the curve moves slowly in t). Segment after segment
// from the outline's first knot, each knot once; the first point is not repeated at the end (the
// polygon closes from the last point back to the first). `segment` and `t`: where each point lies on
// the outline (outline.segment(segment).eval(t) maps to it).
struct OutlineSamples
{
    std::vector<geo::Point> px;
    std::vector<int> segment;
    std::vector<double> t;
};
[[nodiscard]] OutlineSamples sampleOutline(const Outline &outline, const PixelMapping &mapping);

// Only the points of sampleOutline: the outline as a closed polygon in px, about a pixel apart.
[[nodiscard]] std::vector<geo::Point> outlinePolygon(const Outline &outline, const PixelMapping &mapping);

} // namespace kontur::vision
