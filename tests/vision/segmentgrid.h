// Line segments in a uniform grid of cells, for the synthetic photos' renderer: which side of a closed
// polyline a point lies on, and whether it lies within a distance of an open one, each touching only
// the segments of one cell.
#pragma once

#include "geometry/bezier.h"
#include "geometry/polyline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace kontur::vision::test {

using Segment = std::pair<geo::Point, geo::Point>;

// Segments in a uniform grid of cells: a point-in-polygon test by parity against the cell's centre
// (whose side is known) and a distance test for strokes, both touching only the segments of one cell.
class SegmentGrid final
{
public:
    SegmentGrid(std::vector<Segment> segs, double margin, double cell)
        : m_segs(std::move(segs))
        , m_cell(cell)
    {
        Eigen::AlignedBox2d box;
        for (const auto &s : m_segs) {
            box.extend(s.first);
            box.extend(s.second);
        }
        m_origin = box.min() - geo::Point::Constant(margin + cell);
        const geo::Point extent = box.max() + geo::Point::Constant(margin + cell) - m_origin;
        m_nx = static_cast<int>(std::ceil(extent.x() / cell));
        m_ny = static_cast<int>(std::ceil(extent.y() / cell));
        m_cells.assign(static_cast<std::size_t>(m_nx) * m_ny, {});
        for (int i = 0; i < static_cast<int>(m_segs.size()); ++i) {
            const auto &[a, b] = m_segs[i];
            const int x0 = cellX(std::min(a.x(), b.x()) - margin), x1 = cellX(std::max(a.x(), b.x()) + margin);
            const int y0 = cellY(std::min(a.y(), b.y()) - margin), y1 = cellY(std::max(a.y(), b.y()) + margin);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    m_cells[static_cast<std::size_t>(y) * m_nx + x].push_back(i);
        }
    }

    // For closed polygons: which cell centres lie inside, by crossings of each centre row.
    void classifyCentres()
    {
        m_inside.assign(m_cells.size(), 0);
        std::vector<double> xs;
        for (int y = 0; y < m_ny; ++y) {
            const double cy = m_origin.y() + (y + 0.5) * m_cell;
            xs.clear();
            for (const auto &[a, b] : m_segs)
                if ((a.y() <= cy) != (b.y() <= cy))
                    xs.push_back(a.x() + (cy - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
            std::sort(xs.begin(), xs.end());
            for (int x = 0; x < m_nx; ++x) {
                const double cx = m_origin.x() + (x + 0.5) * m_cell;
                const auto n = std::lower_bound(xs.begin(), xs.end(), cx) - xs.begin();
                m_inside[static_cast<std::size_t>(y) * m_nx + x] = n % 2;
            }
        }
    }

    [[nodiscard]] bool inside(double px, double py) const
    {
        const int x = cellX(px), y = cellY(py);
        if (x < 0 || y < 0 || x >= m_nx || y >= m_ny)
            return false;
        const std::size_t c = static_cast<std::size_t>(y) * m_nx + x;
        bool in = m_inside[c];
        const geo::Point q(px, py), centre = m_origin + geo::Point((x + 0.5) * m_cell, (y + 0.5) * m_cell);
        for (const int i : m_cells[c])
            if (crosses(q, centre, m_segs[i].first, m_segs[i].second))
                in = !in;
        return in;
    }

    [[nodiscard]] bool near(double px, double py, double r) const
    {
        const int x = cellX(px), y = cellY(py);
        if (x < 0 || y < 0 || x >= m_nx || y >= m_ny)
            return false;
        const geo::Point q(px, py);
        for (const int i : m_cells[static_cast<std::size_t>(y) * m_nx + x]) {
            const auto &[a, b] = m_segs[i];
            if ((geo::nearestOnSegment(q, a, b) - q).squaredNorm() <= r * r)
                return true;
        }
        return false;
    }

private:
    [[nodiscard]] int cellX(double x) const { return static_cast<int>(std::floor((x - m_origin.x()) / m_cell)); }
    [[nodiscard]] int cellY(double y) const { return static_cast<int>(std::floor((y - m_origin.y()) / m_cell)); }
    static double cross(const geo::Point &a, const geo::Point &b) { return a.x() * b.y() - a.y() * b.x(); }
    static bool crosses(const geo::Point &p, const geo::Point &q, const geo::Point &a, const geo::Point &b)
    {
        const double d1 = cross(q - p, a - p), d2 = cross(q - p, b - p);
        const double d3 = cross(b - a, p - a), d4 = cross(b - a, q - a);
        return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
    }

    std::vector<Segment> m_segs;
    double m_cell;
    geo::Point m_origin;
    int m_nx = 0, m_ny = 0;
    std::vector<std::vector<int>> m_cells;
    std::vector<std::uint8_t> m_inside;
};

inline std::vector<Segment> polylineSegments(const std::vector<geo::Point> &pts, bool closed)
{
    std::vector<Segment> out;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        out.emplace_back(pts[i], pts[i + 1]);
    if (closed && pts.size() > 2)
        out.emplace_back(pts.back(), pts.front());
    return out;
}

} // namespace kontur::vision::test
