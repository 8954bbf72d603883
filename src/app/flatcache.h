// FlatCache: the document's curves flattened in world units, one entry per curve, each made for a
// band of zooms and redone only when its curve changed or the zoom left the band. The entries follow
// the document's rows as curves are inserted, removed and moved, and each remembers the id of the
// curve it was made for: adding one curve to a large drawing flattens that curve only. The GPU nodes
// keep the vertices in world units too, so pans and zoom steps within the band change no vertex.
#pragma once

#include "geometry/bezier.h"
#include "models/document/curve.h"

#include <QRectF>

#include <cstdint>
#include <memory>
#include <vector>

namespace kontur {

class FlatCache
{
public:
    using Polyline = std::shared_ptr<const std::vector<geo::Point>>;

    // One entry per curve: entries past `count` are dropped, new ones are empty.
    void resize(std::size_t count);
    // The document's rows changed: an empty entry at `row`, the entry at `row` gone, or moved.
    void insertRow(int row);
    void removeRow(int row);
    void moveRow(int from, int to);
    [[nodiscard]] std::size_t size() const { return m_entries.size(); }
    // The curve changed: flattened and measured anew when next asked.
    void invalidate(int curve);
    void clear() { m_entries.clear(); }

    // Brings the curve's flattening up to the zoom band of `zoom` over the world rectangle `area`
    // (what is seen, with a margin); true when it was redone. Only the parts of the curve that may
    // meet the area (their control points' box meets a larger one around it) are flattened; the
    // others are single chords, which lie in their boxes and so out of sight too. A curve far bigger
    // than the view (a circle of radius 1e150 around it) is then a few hundred points, not millions.
    bool ensure(std::size_t index, const Curve &curve, double zoom, const QRectF &area);
    // Whether ensure() would flatten the curve anew.
    [[nodiscard]] bool stale(std::size_t index, const Curve &curve, double zoom, const QRectF &area) const;
    // ensure() for each of `indices` (distinct) with `curves[index]`, on the machine's cores when
    // there are many; returns how many were redone. The versions increase in the order given.
    std::size_t ensureMany(const std::vector<std::size_t> &indices, const std::vector<Curve> &curves, double zoom,
                           const QRectF &area);
    // Points made by all flattenings so far (lets tests assert bounded work without timing).
    [[nodiscard]] std::uint64_t pointsMade() const { return m_pointsMade; }
    // How many flattenings were made since the cache was created (for tests and benchmarks).
    [[nodiscard]] std::uint64_t flattenings() const { return m_version; }
    // Whether the hull of the curve's control points meets the world rectangle.
    bool meets(std::size_t index, const Curve &curve, const QRectF &worldRect);

    // The last flattening (null before the first) and its version, which increases with every
    // new flattening (the GPU nodes compare it).
    [[nodiscard]] const Polyline &world(std::size_t index) const { return m_entries[index].world; }
    [[nodiscard]] std::uint64_t version(std::size_t index) const { return m_entries[index].version; }

private:
    struct Entry
    {
        Polyline world;
        double zoom = 0.0;    // the zoom it was flattened for
        bool clipped = false; // parts out of `area` were left out (chords)
        QRectF area;          // the world rectangle it was made for
        CurveId curve{};      // the curve the entry was made for
        bool valid = false;
        std::uint64_t version = 0;
        QRectF bounds; // world hull of the control points
        bool boundsValid = false;
    };
    // Makes `world` the curve's flattening for `zoom`, with a new version.
    // The entry at `index`, emptied first when it was made for another curve than `curve`.
    Entry &entryFor(std::size_t index, const Curve &curve);
    void store(std::size_t index, Polyline world, double zoom, bool clipped, const QRectF &area);

    std::vector<Entry> m_entries;
    std::uint64_t m_version = 0;
    std::uint64_t m_pointsMade = 0;
};

} // namespace kontur
