// FlatCache: the canvas's world flattenings of the document's curves.
#include "app/flatcache.h"

#include "app/parallel.h"
#include "app/strokenode.h"
#include "models/document/curve.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace kontur {

void FlatCache::resize(std::size_t count)
{
    m_entries.resize(count);
}

void FlatCache::insertRow(int row)
{
    if (row >= 0 && static_cast<std::size_t>(row) <= m_entries.size())
        m_entries.insert(m_entries.begin() + row, Entry{});
}

void FlatCache::removeRow(int row)
{
    if (row >= 0 && static_cast<std::size_t>(row) < m_entries.size())
        m_entries.erase(m_entries.begin() + row);
}

void FlatCache::moveRow(int from, int to)
{
    const auto n = static_cast<int>(m_entries.size());
    if (from < 0 || to < 0 || from >= n || to >= n || from == to)
        return;
    Entry moved = std::move(m_entries[static_cast<std::size_t>(from)]);
    m_entries.erase(m_entries.begin() + from);
    m_entries.insert(m_entries.begin() + to, std::move(moved));
}

FlatCache::Entry &FlatCache::entryFor(std::size_t index, const Curve &curve)
{
    Entry &entry = m_entries[index];
    if (entry.curve != curve.id()) {
        entry = Entry{};
        entry.curve = curve.id();
    }
    return entry;
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
    Entry &entry = entryFor(index, curve);
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

namespace {

// Flattened in world units to an eighth of a pixel at `zoom`.
std::shared_ptr<std::vector<geo::Point>> flattened(const Curve &curve, double zoom)
{
    auto world = std::make_shared<std::vector<geo::Point>>();
    for (int s = 0; s < curve.segmentCount(); ++s)
        flattenWithin(curve.segment(s), 0.125 / zoom, *world);
    return world;
}

// Below this many segments to flatten, one thread: starting others would cost more.
constexpr std::size_t kSegmentsPerThread = 5000;

} // namespace

bool FlatCache::stale(std::size_t index, const Curve &curve, double zoom) const
{
    // Flattened to an eighth of a pixel at the zoom it was made for, and reused while the zoom
    // stays below twice that (error at most a quarter pixel) and not far above it (no needless
    // points): pans and zoom steps within the band change no vertex.
    const Entry &entry = m_entries[index];
    return entry.curve != curve.id() ||
           !(entry.valid && entry.world && zoom <= 2.0 * entry.zoom && zoom >= entry.zoom / 4.0);
}

std::size_t FlatCache::ensureMany(const std::vector<std::size_t> &indices, const std::vector<Curve> &curves,
                                  double zoom)
{
    std::vector<std::size_t> todo;
    std::size_t segments = 0;
    for (const std::size_t index : indices)
        if (stale(index, curves[index], zoom)) {
            todo.push_back(index);
            segments += static_cast<std::size_t>(std::max(curves[index].segmentCount(), 0));
        }
    // The curves are flattened in parallel (each is read only), their entries written after.
    std::vector<std::shared_ptr<std::vector<geo::Point>>> made(todo.size());
    std::atomic<std::size_t> next{0};
    onThreads(threadsFor(segments, kSegmentsPerThread), [&] {
        for (std::size_t k; (k = next.fetch_add(1)) < todo.size();)
            made[k] = flattened(curves[todo[k]], zoom);
    });
    for (std::size_t k = 0; k < todo.size(); ++k) {
        entryFor(todo[k], curves[todo[k]]);
        store(todo[k], std::move(made[k]), zoom);
    }
    return todo.size();
}

void FlatCache::store(std::size_t index, Polyline world, double zoom)
{
    Entry &entry = m_entries[index];
    entry.world = std::move(world);
    entry.zoom = zoom;
    entry.valid = true;
    entry.version = ++m_version;
}

bool FlatCache::ensure(std::size_t index, const Curve &curve, double zoom)
{
    if (!stale(index, curve, zoom))
        return false;
    entryFor(index, curve);
    store(index, flattened(curve, zoom), zoom);
    return true;
}

} // namespace kontur
