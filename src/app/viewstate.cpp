// ViewState: the canvas's world → item mapping.
#include "app/viewstate.h"

#include <algorithm>

namespace kontur {

QRectF ViewState::visibleWorld(double margin) const
{
    const geo::Point a = toWorld(QPointF(-margin, -margin));
    const geo::Point b = toWorld(QPointF(size.width() + margin, size.height() + margin));
    return QRectF(QPointF(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                  QPointF(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
}

void toScreenPolyline(const std::vector<geo::Point> &world, const ViewState &view, std::vector<QPointF> &line)
{
    line.clear();
    line.reserve(world.size());
    for (std::size_t i = 0; i < world.size(); ++i) {
        const QPointF p = view.toScreen(world[i]);
        if (!line.empty() && i + 1 != world.size()) {
            const QPointF d = p - line.back();
            if (d.x() * d.x() + d.y() * d.y() < 0.0625)
                continue;
        }
        line.push_back(p);
    }
}

} // namespace kontur
