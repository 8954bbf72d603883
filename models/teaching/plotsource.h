// PlotSource: what a teaching plot shows (basis functions, a function spline y(x), the Runge
// comparison, seed 003's segments), as plain world-coordinate data for the PlotView item to draw.
// The source decides everything (ranges, colours, which points may be dragged and what a drag
// means); the view only maps world to screen, draws and reports pointer gestures back.
#pragma once

#include <QColor>
#include <QObject>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

namespace kontur {

struct PlotSeries
{
    QPolygonF points; // world coordinates, drawn as a polyline
    QColor color;
    double width = 2.0; // in device-independent pixels
    bool dashed = false;
    bool asDots = false; // drawn as separate dots (seed 003: "by points" instead of by lines)
    QString label;       // written beside the curve's highest point; empty: none
    int id = -1;         // reported back by hoverSeries (the basis function's index)
};

struct PlotDot
{
    enum Shape { Disc, Ring, Square };
    QPointF position;
    QColor color;
    Shape shape = Disc;
    double radius = 4.0; // visible radius in pixels; the touch target is larger
    bool draggable = false;
    std::optional<QPointF> anchor; // a line is drawn from here to the dot (derivative handles)
};

// Everything one plot shows.
struct PlotData
{
    QRectF world; // x, y, width, height with y up: the range to show
    std::vector<PlotSeries> series;
    std::vector<PlotDot> dots;
    std::vector<double> xMarks;   // short marks on the x axis (the knots of a B-spline)
    std::optional<double> marker; // a vertical line at this x (the parameter t), draggable
    QString xLabel;
    QString yLabel;
};

// Not final: the concrete sources derive from it. Uncreatable in QML; only its subclasses are made.
class PlotSource : public QObject
{
    Q_OBJECT
    QML_ANONYMOUS

public:
    explicit PlotSource(QObject *parent = nullptr)
        : QObject(parent)
    {
    }
    Q_DISABLE_COPY_MOVE(PlotSource)

    [[nodiscard]] virtual PlotData plotData() const = 0;
    // A draggable dot moved to `world`; `finished` on release (the source records one undo step).
    virtual void dragDot(int index, QPointF world, bool finished)
    {
        Q_UNUSED(index)
        Q_UNUSED(world)
        Q_UNUSED(finished)
    }
    // The marker was dragged to x.
    virtual void dragMarker(double x) { Q_UNUSED(x) }
    // The pointer is over the series with this id (-1: none), for highlighting.
    virtual void hoverSeries(int id) { Q_UNUSED(id) }

    // The size of the plot area in pixels (the view without its axis margins): sources that place
    // things at a fixed screen length (derivative handles) need it. The view sets it on resize.
    void setPlotArea(QSizeF size)
    {
        if (size == m_area)
            return;
        m_area = size;
        Q_EMIT plotChanged();
    }
    [[nodiscard]] QSizeF plotArea() const { return m_area; }

Q_SIGNALS:
    // Anything shown changed: the view repaints.
    void plotChanged();

private:
    QSizeF m_area{400.0, 200.0};
};

} // namespace kontur
