// FlatCache: the canvas's world flattenings of the document's curves.
#include "app/flatcache.h"

#include "app/strokenode.h"
#include "models/curve.h"

#include <algorithm>
#include <limits>

namespace kontur {

void FlatCache::resize(std::size_t count)
{
    if (m_entries.size() != count)
        m_entries.assign(count, Entry{});
}

void FlatCache::invalidate(int curve)
{
    if (curve >= 0 && static_cast<std::size_t>(curve) < m_entries.size()) {
        m_entries[static_cast<std::size_t>(curve)].valid = false;
        m_entries[static_cast<std::size_t>(curve)].boundsValid = false;
    }
}

bool FlatCache::meets(std::size_t index, const Curve &curve, const QRectF &worldRect)
{
    Entry &entry = m_entries[index];
    if (!entry.boundsValid) {
        // The curve lies in the hull of its segments' control points.
        double minX = std::numeric_limits<double>::infinity(), minY = minX;
        double maxX = -minX, maxY = -minX;
        for (int s = 0; s < curve.segmentCount(); ++s) {
            const geo::Bezier segment = curve.segment(s);
            for (const geo::Point &p : segment.controlPoints()) {
                minX = std::min(minX, p.x());
                maxX = std::max(maxX, p.x());
                minY = std::min(minY, p.y());
                maxY = std::max(maxY, p.y());
            }
        }
        entry.bounds = minX <= maxX ? QRectF(QPointF(minX, minY), QPointF(maxX, maxY)) : QRectF();
        entry.boundsValid = true;
    }
    const QRectF &b = entry.bounds;
    return !b.isNull() && b.left() <= worldRect.right() && b.right() >= worldRect.left() &&
           b.top() <= worldRect.bottom() && b.bottom() >= worldRect.top();
}

bool FlatCache::ensure(std::size_t index, const Curve &curve, double zoom)
{
    // Flattened in world units to an eighth of a pixel at the zoom it was made for, and reused
    // while the zoom stays below twice that (error at most a quarter pixel) and not far above
    // it (no needless points): pans and zoom steps within the band change no vertex.
    Entry &entry = m_entries[index];
    if (entry.valid && entry.world && zoom <= 2.0 * entry.zoom && zoom >= entry.zoom / 4.0)
        return false;
    auto world = std::make_shared<std::vector<geo::Point>>();
    for (int s = 0; s < curve.segmentCount(); ++s)
        flattenWithin(curve.segment(s), 0.125 / zoom, *world);
    entry.world = std::move(world);
    entry.zoom = zoom;
    entry.valid = true;
    entry.version = ++m_version;
    return true;
}

} // namespace kontur
