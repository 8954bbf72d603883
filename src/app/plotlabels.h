// Where a teaching plot writes its curves' labels: beside each labelled curve and clear of every
// curve, both axes, the dots and the labels written before it. (At the curve's highest point, as
// before, the y axis ran through Runge's labels and the basis functions' labels sat on their
// neighbours' curves.) Screen coordinates throughout; the PlotView paints where this says.
#pragma once

#include <QLineF>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>

#include <vector>

namespace kontur {

class PlotLabelPlacer
{
public:
    // `plot`: the area labels stay in. `cell`: the grid's resolution in pixels (a label is kept
    // at least about one cell away from what it must not touch).
    explicit PlotLabelPlacer(const QRectF &plot, double cell = 3.0);

    // What a label must not touch: a curve drawn with a pen `width` wide, a line, a rectangle.
    void addCurve(const QPolygonF &curve, double width);
    void addLine(const QLineF &line, double width);
    void addRect(const QRectF &rect);

    // A box of `size` beside `curve` (its highest point first, then further along it) that touches
    // nothing added or placed before; it is then taken. Where nothing is free, the free box nearest
    // the highest point; where the plot has no free box of that size at all, above the highest point.
    [[nodiscard]] QRectF place(const QPolygonF &curve, QSizeF size);

private:
    [[nodiscard]] bool isFree(const QRectF &box) const;
    void mark(QPointF p, double radius);
    void markRect(const QRectF &rect);

    QRectF m_plot;
    double m_cell;
    int m_columns = 0, m_rows = 0;
    std::vector<unsigned char> m_taken;
};

} // namespace kontur
