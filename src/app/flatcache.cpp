// FlatCache: the canvas's world flattenings of the document's curves.
#include "app/flatcache.h"

#include "app/parallel.h"
#include "app/strokenode.h"
#include "models/document/curve.h"

#include <algorithm>
#include <atomic>
#include <cmath>
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

// Whether the box of the control points meets `area`, and whether it lies inside it.
struct BoxTest
{
    bool meets = false, inside = false;
};
BoxTest testBox(const std::vector<geo::Point> &control, const QRectF &area)
{
    double minX = control.front().x(), maxX = minX, minY = control.front().y(), maxY = minY;
    for (const geo::Point &p : control) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    }
    BoxTest t;
    t.meets = minX <= area.right() && maxX >= area.left() && minY <= area.bottom() && maxY >= area.top();
    t.inside = minX >= area.left() && maxX <= area.right() && minY >= area.top() && maxY <= area.bottom();
    return t;
}

// Whether every control point lies within `tol` of the chord (unit direction first: no squares of
// coordinates near 1e300).
bool nearChord(const std::vector<geo::Point> &control, double tol)
{
    const geo::Point a = control.front(), d = control.back() - a;
    const double len = std::hypot(d.x(), d.y());
    for (const geo::Point &p : control) {
        const geo::Point v = p - a;
        const double dev = len > 0 ? std::abs(d.x() / len * v.y() - d.y() / len * v.x()) : std::hypot(v.x(), v.y());
        if (!(dev <= tol))
            return false;
    }
    return true;
}

// The part of a segment that may be seen: halves whose box lies inside `area` are flattened
// (flattenWithin), halves whose box misses it become their chord, the ones across its edge are
// halved again until flat. Each level halves the pieces across the edge, a few per level (a cubic
// crosses a line at most 3 times), so the work grows with the levels, not with the curve's size.
void flattenSeen(const geo::Bezier &segment, double tol, const QRectF &area, int depth, bool &clipped,
                 std::vector<geo::Point> &out)
{
    const auto &control = segment.controlPoints();
    const BoxTest box = testBox(control, area);
    if (box.inside) {
        flattenWithin(segment, tol, out);
        return;
    }
    if (!box.meets || depth >= 1100 || nearChord(control, tol)) {
        clipped = true;
        if (out.empty() || out.back() != control.front())
            out.push_back(control.front());
        out.push_back(control.back());
        return;
    }
    const auto [left, right] = segment.split(0.5);
    flattenSeen(left, tol, area, depth + 1, clipped, out);
    flattenSeen(right, tol, area, depth + 1, clipped, out);
}

// Flattened in world units to an eighth of a pixel at `zoom` where it may meet `area` (see ensure);
// `clipped` tells whether some part was left out (else the flattening holds everywhere).
std::shared_ptr<std::vector<geo::Point>> flattened(const Curve &curve, double zoom, const QRectF &area, bool &clipped)
{
    auto world = std::make_shared<std::vector<geo::Point>>();
    clipped = false;
    for (int s = 0; s < curve.segmentCount(); ++s)
        flattenSeen(curve.segment(s), 0.125 / zoom, area, 0, clipped, *world);
    return world;
}

// The rectangle flattened for `area`: three times as wide and high, so that pans of up to a view
// change no vertex.
QRectF flatArea(const QRectF &area)
{
    return area.adjusted(-area.width(), -area.height(), area.width(), area.height());
}

// Below this many segments to flatten, one thread: starting others would cost more.
constexpr std::size_t kSegmentsPerThread = 5000;

} // namespace

bool FlatCache::stale(std::size_t index, const Curve &curve, double zoom, const QRectF &area) const
{
    // Flattened to an eighth of a pixel at the zoom it was made for, and reused while the zoom
    // stays below twice that (error at most a quarter pixel) and not far above it (no needless
    // points), and while the area stays within the one it was made for: pans and zoom steps
    // within the band change no vertex.
    const Entry &entry = m_entries[index];
    return entry.curve != curve.id() || !(entry.valid && entry.world && zoom <= 2.0 * entry.zoom &&
                                          zoom >= entry.zoom / 4.0 && (!entry.clipped || entry.area.contains(area)));
}

std::size_t FlatCache::ensureMany(const std::vector<std::size_t> &indices, const std::vector<Curve> &curves,
                                  double zoom, const QRectF &area)
{
    std::vector<std::size_t> todo;
    std::size_t segments = 0;
    for (const std::size_t index : indices)
        if (stale(index, curves[index], zoom, area)) {
            todo.push_back(index);
            segments += static_cast<std::size_t>(std::max(curves[index].segmentCount(), 0));
        }
    // The curves are flattened in parallel (each is read only), their entries written after.
    std::vector<std::shared_ptr<std::vector<geo::Point>>> made(todo.size());
    std::vector<char> clipped(todo.size(), 0);
    std::atomic<std::size_t> next{0};
    const QRectF wide = flatArea(area);
    onThreads(threadsFor(segments, kSegmentsPerThread), [&] {
        for (std::size_t k; (k = next.fetch_add(1)) < todo.size();) {
            bool cut = false;
            made[k] = flattened(curves[todo[k]], zoom, wide, cut);
            clipped[k] = cut;
        }
    });
    for (std::size_t k = 0; k < todo.size(); ++k) {
        entryFor(todo[k], curves[todo[k]]);
        store(todo[k], std::move(made[k]), zoom, clipped[k] != 0, wide);
    }
    return todo.size();
}

void FlatCache::store(std::size_t index, Polyline world, double zoom, bool clipped, const QRectF &area)
{
    Entry &entry = m_entries[index];
    m_pointsMade += world ? world->size() : 0;
    entry.clipped = clipped;
    entry.area = area;
    entry.world = std::move(world);
    entry.zoom = zoom;
    entry.valid = true;
    entry.version = ++m_version;
}

bool FlatCache::ensure(std::size_t index, const Curve &curve, double zoom, const QRectF &area)
{
    if (!stale(index, curve, zoom, area))
        return false;
    entryFor(index, curve);
    const QRectF wide = flatArea(area);
    bool clipped = false;
    auto world = flattened(curve, zoom, wide, clipped);
    store(index, std::move(world), zoom, clipped, wide);
    return true;
}

} // namespace kontur
