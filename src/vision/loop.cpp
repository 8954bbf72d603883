// Closed loops of points: see loop.h.
#include "vision/loop.h"

#include <algorithm>
#include <cmath>

namespace kontur::vision {

namespace detail {

Loop::Loop(std::vector<geo::Point> points)
    : m_points(std::move(points))
    , m_arc(m_points.size() + 1, 0.0)
{
    const std::size_t n = m_points.size();
    for (std::size_t i = 0; i < n; ++i)
        m_arc[i + 1] = m_arc[i] + (m_points[(i + 1) % n] - m_points[i]).norm();
}

geo::Point Loop::at(double s) const
{
    const double length = total();
    s = std::fmod(s, length);
    if (s < 0.0)
        s += length;
    // Among the points' own arc lengths (not the total): s may round up to the total.
    const auto hi = std::upper_bound(m_arc.begin(), m_arc.end() - 1, s);
    const auto i = static_cast<std::size_t>(hi - m_arc.begin()) - 1;
    const geo::Point &a = m_points[i], &b = m_points[(i + 1) % m_points.size()];
    const double len = m_arc[i + 1] - m_arc[i];
    return len > 0.0 ? geo::Point(a + (b - a) * ((s - m_arc[i]) / len)) : a;
}

std::vector<geo::Point> Loop::between(double from, double to) const
{
    std::vector<geo::Point> out;
    for (int lap = -1; lap < 2; ++lap)
        for (std::size_t i = 0; i < m_points.size(); ++i) {
            const double si = m_arc[i] + lap * total();
            if (si >= from && si <= to)
                out.push_back(m_points[i]);
        }
    return out;
}

std::size_t Loop::ahead(std::size_t i, double length) const
{
    const double want = arc(i) + length;
    std::size_t k = i;
    while (k < i + m_points.size() && arc(k) < want)
        ++k;
    return k;
}

} // namespace detail

OutlineSamples sampleOutline(const Outline &outline, const PixelMapping &mapping)
{
    OutlineSamples out;
    for (int i = 0; i < outline.segmentCount(); ++i) {
        const geo::Bezier b = outline.segment(i);
        const auto &c = b.controlPoints();
        double len = 0.0;
        for (std::size_t k = 0; k + 1 < c.size(); ++k)
            len += (mapping.toPixel(c[k + 1]) - mapping.toPixel(c[k])).norm();
        const int steps = std::max(2, static_cast<int>(std::ceil(len)));
        for (int k = 0; k < steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            out.px.push_back(mapping.toPixel(b.eval(t)));
            out.segment.push_back(i);
            out.t.push_back(t);
        }
    }
    return out;
}

std::vector<geo::Point> outlinePolygon(const Outline &outline, const PixelMapping &mapping)
{
    return sampleOutline(outline, mapping).px;
}

} // namespace kontur::vision
