// PlotLabelPlacer: labels clear of curves, axes and each other on a grid of taken cells (see plotlabels.h).
#include "app/plotlabels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

PlotLabelPlacer::PlotLabelPlacer(const QRectF &plot, double cell)
    : m_plot(plot)
    , m_cell(std::max(1.0, cell))
    , m_columns(std::max(1, static_cast<int>(std::ceil(plot.width() / m_cell))))
    , m_rows(std::max(1, static_cast<int>(std::ceil(plot.height() / m_cell))))
    , m_taken(static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(m_rows), 0)
{
}

void PlotLabelPlacer::mark(QPointF p, double radius)
{
    // Every cell that a disc of `radius` around p reaches, and one cell more: the label keeps a gap.
    const double r = radius + m_cell;
    const int c0 = static_cast<int>(std::floor((p.x() - r - m_plot.left()) / m_cell));
    const int c1 = static_cast<int>(std::floor((p.x() + r - m_plot.left()) / m_cell));
    const int r0 = static_cast<int>(std::floor((p.y() - r - m_plot.top()) / m_cell));
    const int r1 = static_cast<int>(std::floor((p.y() + r - m_plot.top()) / m_cell));
    for (int row = std::max(0, r0); row <= std::min(m_rows - 1, r1); ++row)
        for (int column = std::max(0, c0); column <= std::min(m_columns - 1, c1); ++column)
            m_taken[static_cast<std::size_t>(row) * static_cast<std::size_t>(m_columns) +
                    static_cast<std::size_t>(column)] = 1;
}

void PlotLabelPlacer::addLine(const QLineF &line, double width)
{
    if (!std::isfinite(line.length()))
        return;
    // Points at most half a cell apart: every cell the line crosses is marked.
    const int steps = std::max(1, static_cast<int>(std::ceil(line.length() / (m_cell / 2))));
    if (steps > 100000)
        return;
    for (int i = 0; i <= steps; ++i)
        mark(line.pointAt(static_cast<double>(i) / steps), width / 2);
}

void PlotLabelPlacer::addCurve(const QPolygonF &curve, double width)
{
    for (qsizetype i = 1; i < curve.size(); ++i)
        addLine(QLineF(curve[i - 1], curve[i]), width);
    if (curve.size() == 1)
        mark(curve.front(), width / 2);
}

void PlotLabelPlacer::markRect(const QRectF &rect)
{
    const int c0 = static_cast<int>(std::floor((rect.left() - m_plot.left()) / m_cell));
    const int c1 = static_cast<int>(std::floor((rect.right() - m_plot.left()) / m_cell));
    const int r0 = static_cast<int>(std::floor((rect.top() - m_plot.top()) / m_cell));
    const int r1 = static_cast<int>(std::floor((rect.bottom() - m_plot.top()) / m_cell));
    for (int row = std::max(0, r0); row <= std::min(m_rows - 1, r1); ++row)
        for (int column = std::max(0, c0); column <= std::min(m_columns - 1, c1); ++column)
            m_taken[static_cast<std::size_t>(row) * static_cast<std::size_t>(m_columns) +
                    static_cast<std::size_t>(column)] = 1;
}

void PlotLabelPlacer::addRect(const QRectF &rect)
{
    markRect(rect);
}

bool PlotLabelPlacer::isFree(const QRectF &box) const
{
    if (!m_plot.adjusted(2, 2, -2, -2).contains(box))
        return false;
    const int c0 = static_cast<int>(std::floor((box.left() - m_plot.left()) / m_cell));
    const int c1 = static_cast<int>(std::floor((box.right() - m_plot.left()) / m_cell));
    const int r0 = static_cast<int>(std::floor((box.top() - m_plot.top()) / m_cell));
    const int r1 = static_cast<int>(std::floor((box.bottom() - m_plot.top()) / m_cell));
    for (int row = std::max(0, r0); row <= std::min(m_rows - 1, r1); ++row)
        for (int column = std::max(0, c0); column <= std::min(m_columns - 1, c1); ++column)
            if (m_taken[static_cast<std::size_t>(row) * static_cast<std::size_t>(m_columns) +
                        static_cast<std::size_t>(column)])
                return false;
    return true;
}

QRectF PlotLabelPlacer::place(const QPolygonF &curve, QSizeF size)
{
    if (curve.isEmpty())
        return {};
    const double w = size.width(), h = size.height();
    // Up to 32 points along the curve, the highest on screen first.
    std::vector<QPointF> anchors;
    const qsizetype step = std::max<qsizetype>(1, curve.size() / 32);
    for (qsizetype i = 0; i < curve.size(); i += step)
        anchors.push_back(curve[i]);
    anchors.push_back(curve.back());
    const auto peak = std::min_element(curve.begin(), curve.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
    anchors.insert(anchors.begin(), *peak);
    std::stable_sort(anchors.begin() + 1, anchors.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });

    QRectF chosen;
    for (const double gap : {4.0, 10.0, 20.0}) {
        for (const QPointF &p : anchors) {
            // Above, below, right, left, then the four corners.
            const QRectF candidates[] = {
                {p.x() - w / 2, p.y() - gap - h, w, h}, {p.x() - w / 2, p.y() + gap, w, h},
                {p.x() + gap, p.y() - h / 2, w, h},     {p.x() - gap - w, p.y() - h / 2, w, h},
                {p.x() + gap, p.y() - gap - h, w, h},   {p.x() - gap - w, p.y() - gap - h, w, h},
                {p.x() + gap, p.y() + gap, w, h},       {p.x() - gap - w, p.y() + gap, w, h},
            };
            for (const QRectF &c : candidates)
                if (isFree(c)) {
                    chosen = c;
                    break;
                }
            if (!chosen.isNull())
                break;
        }
        if (!chosen.isNull())
            break;
    }
    if (chosen.isNull()) {
        // Anywhere free, the nearest to the highest point.
        double best = std::numeric_limits<double>::infinity();
        for (double y = m_plot.top() + 2; y + h <= m_plot.bottom() - 2; y += 2 * m_cell)
            for (double x = m_plot.left() + 2; x + w <= m_plot.right() - 2; x += 2 * m_cell) {
                const QRectF c(x, y, w, h);
                const QPointF d = c.center() - *peak;
                const double distance = std::hypot(d.x(), d.y());
                if (distance < best && isFree(c)) {
                    best = distance;
                    chosen = c;
                }
            }
    }
    if (chosen.isNull()) {
        chosen = QRectF(peak->x() - w / 2, peak->y() - 4 - h, w, h);
        chosen.moveLeft(std::clamp(chosen.left(), m_plot.left() + 2, std::max(m_plot.left() + 2, m_plot.right() - w - 2)));
        chosen.moveTop(std::clamp(chosen.top(), m_plot.top() + 2, std::max(m_plot.top() + 2, m_plot.bottom() - h - 2)));
    }
    markRect(chosen);
    return chosen;
}

} // namespace kontur
