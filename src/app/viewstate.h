// ViewState: the canvas's world → item mapping (zoom, the world point at the item's centre, the
// item's size; world y up, item y down, docs/requirements.md 2), shared by the scene builder and the nodes.
#pragma once

#include "geometry/bezier.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>

#include <vector>

namespace kontur {

struct ViewState
{
    double zoom = 1.0;
    QPointF center;
    QSizeF size;

    [[nodiscard]] QPointF toScreen(const geo::Point &p) const
    {
        return {size.width() / 2.0 + (p.x() - center.x()) * zoom, size.height() / 2.0 - (p.y() - center.y()) * zoom};
    }
    [[nodiscard]] geo::Point toWorld(QPointF s) const
    {
        return {center.x() + (s.x() - size.width() / 2.0) / zoom, center.y() - (s.y() - size.height() / 2.0) / zoom};
    }
    // toScreen for QPainter and the scene graph.
    [[nodiscard]] QTransform worldToScreen() const
    {
        return {zoom, 0.0, 0.0, -zoom, size.width() / 2.0 - center.x() * zoom, size.height() / 2.0 + center.y() * zoom};
    }
    // The world seen through the item and `margin` pixels around it (y up: top < bottom).
    [[nodiscard]] QRectF visibleWorld(double margin) const;
    bool operator==(const ViewState &) const = default;
};

// World points on screen, leaving out points closer than a quarter pixel to the last one kept
// (zoomed out, most of them): the drawn line moves by less than that.
void toScreenPolyline(const std::vector<geo::Point> &world, const ViewState &view, std::vector<QPointF> &line);

} // namespace kontur
