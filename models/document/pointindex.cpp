// PointIndex: a spatial hash of points for hit testing.
#include "models/document/pointindex.h"

#include "models/document/document.h"

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {
std::int64_t cellCoordinate(double v, double cell)
{
    // Clamped so that far-away points cannot overflow the key.
    const double c = std::floor(v / cell);
    return static_cast<std::int64_t>(std::clamp(c, -2.0e9, 2.0e9));
}
} // namespace

std::uint64_t PointIndex::keyOf(const geo::Point &p) const
{
    const auto ix = static_cast<std::uint32_t>(cellCoordinate(p.x(), m_cell));
    const auto iy = static_cast<std::uint32_t>(cellCoordinate(p.y(), m_cell));
    return (static_cast<std::uint64_t>(ix) << 32) | iy;
}

double PointIndex::cellFor(double radius) const
{
    const double cell = std::max(radius, m_minCell);
    return cell > 0.0 && std::isfinite(cell) ? cell : 1.0;
}

void PointIndex::rebuild(const Document &document, double radius)
{
    const auto curves = static_cast<std::size_t>(document.curveCount());
    m_positions.assign(curves, {});
    m_boxes.assign(curves, geo::Box());
    // The spacing of most points along their curves (the median over points of their curve's box
    // diagonal over its rows): cells of kPointsPerCell spacings hold a few points of each curve
    // crossing them. Cells the size of a tiny radius (a press zoomed far in, or an exact one) held
    // one point each: a hash node and a vector per point, 60 ms to build for 300,000 points, where a
    // query in bigger cells still looks at only a handful of points. A median, so that a few long
    // curves of few points do not make the cells of many dense ones large.
    std::vector<std::pair<double, std::size_t>> spacings; // per visible curve: spacing, rows
    std::size_t points = 0;
    for (std::size_t c = 0; c < curves; ++c) {
        const Curve &curve = document.curve(static_cast<int>(c));
        auto &positions = m_positions[c];
        positions.resize(static_cast<std::size_t>(curve.rowCount()));
        for (int r = 0; r < curve.rowCount(); ++r) {
            const geo::Point p = curve.row(r).position;
            positions[static_cast<std::size_t>(r)] = p;
            m_boxes[c].extend(p);
        }
        const double diagonal = positions.empty() ? 0.0 : m_boxes[c].diagonal().norm();
        if (curve.visible && positions.size() > 1 && std::isfinite(diagonal)) {
            spacings.emplace_back(diagonal / static_cast<double>(positions.size()), positions.size());
            points += positions.size();
        }
    }
    std::sort(spacings.begin(), spacings.end());
    double median = 0.0;
    for (std::size_t k = 0, seen = 0; k < spacings.size() && 2 * seen < points; ++k) {
        median = spacings[k].first;
        seen += spacings[k].second;
    }
    constexpr double kPointsPerCell = 8.0;
    m_minCell = kPointsPerCell * median;
    m_cell = cellFor(radius);
    m_cells.clear();
    for (std::size_t c = 0; c < curves; ++c) {
        if (!document.curve(static_cast<int>(c)).visible)
            continue;
        const auto &positions = m_positions[c];
        for (std::size_t r = 0; r < positions.size(); ++r) {
            auto &cell = m_cells[keyOf(positions[r])];
            if (cell.empty()) // room for half the points a cell holds about: fewer allocations
                cell.reserve(static_cast<std::size_t>(kPointsPerCell) / 2);
            cell.push_back({static_cast<int>(c), static_cast<int>(r), positions[r]});
        }
    }
    m_valid = true;
}

void PointIndex::insert(int curve, int row, const geo::Point &p)
{
    m_cells[keyOf(p)].push_back({curve, row, p});
}

void PointIndex::erase(int curve, int row, const geo::Point &p)
{
    auto it = m_cells.find(keyOf(p));
    if (it == m_cells.end())
        return;
    auto &entries = it->second;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (entries[i].curve == curve && entries[i].row == row) {
            entries[i] = entries.back();
            entries.pop_back();
            break;
        }
    }
    if (entries.empty())
        m_cells.erase(it);
}

void PointIndex::update(const Document &document, int curve, int first, int last)
{
    if (!m_valid)
        return;
    if (curve < 0 || curve >= static_cast<int>(m_positions.size())) {
        m_valid = false;
        return;
    }
    const Curve &c = document.curve(curve);
    auto &positions = m_positions[static_cast<std::size_t>(curve)];
    if (static_cast<int>(positions.size()) != c.rowCount()) {
        m_valid = false; // rows came or went (a fit that failed or recovered)
        return;
    }
    for (int r = std::max(first, 0); r <= last && r < c.rowCount(); ++r) {
        const geo::Point p = c.row(r).position;
        geo::Point &old = positions[static_cast<std::size_t>(r)];
        if (p == old)
            continue;
        if (c.visible) {
            erase(curve, r, old);
            insert(curve, r, p);
        }
        old = p;
        m_boxes[static_cast<std::size_t>(curve)].extend(p);
    }
}

PointHit PointIndex::nearest(const Document &document, const geo::Point &q, double radius,
                             const std::function<bool(int curve, int row)> &accept)
{
    PointHit best;
    if (!(radius > 0.0) || !q.allFinite())
        return best;
    // Cells about the size of the radius (or of a few points' spacing, when larger) keep a query to
    // at most 5 × 5 cells.
    const double cell = cellFor(radius);
    if (!m_valid || cell < m_cell / 4.0 || cell > 2.0 * m_cell)
        rebuild(document, radius);
    const std::int64_t x0 = cellCoordinate(q.x() - radius, m_cell), x1 = cellCoordinate(q.x() + radius, m_cell);
    const std::int64_t y0 = cellCoordinate(q.y() - radius, m_cell), y1 = cellCoordinate(q.y() + radius, m_cell);
    double bestDistance = radius;
    for (std::int64_t ix = x0; ix <= x1; ++ix) {
        for (std::int64_t iy = y0; iy <= y1; ++iy) {
            const std::uint64_t key =
                (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) | static_cast<std::uint32_t>(iy);
            const auto it = m_cells.find(key);
            if (it == m_cells.end())
                continue;
            for (const Entry &e : it->second) {
                const double d = (e.position - q).norm();
                if (d > bestDistance || (accept && !accept(e.curve, e.row)))
                    continue;
                const bool later = e.curve > best.curve || (e.curve == best.curve && e.row > best.row);
                if (d < bestDistance || (d == bestDistance && later && best.isValid()) ||
                    (d == bestDistance && !best.isValid())) {
                    bestDistance = d;
                    best = {e.curve, e.row, d};
                }
            }
        }
    }
    return best;
}

const geo::Box &PointIndex::curveBox(const Document &document, int curve, double radius)
{
    if (!m_valid)
        rebuild(document, radius);
    return m_boxes.at(static_cast<std::size_t>(curve));
}

} // namespace kontur
