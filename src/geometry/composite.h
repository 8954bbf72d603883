// The composite curve of seed 000 (§3.1.6, §3.1.8; docs/requirements.md 1.2 and 1.4): one cubic segment per pair
// of consecutive knots with handles from the knots' neighbours, built incrementally as knots are
// added, edited by free / constrained handle moves and knot moves, with node types, knot insertion
// and deletion, and closing. Every edit rewrites only the control points of the segments it touches.
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"

#include <array>
#include <span>
#include <vector>

namespace kontur::geo {

class PiecewiseBezier;

// Beyond the seed (docs/requirements.md 6), as in vector editors. The seed's own behaviour is Smooth.
enum class NodeType {
    Smooth,    // a free move turns the opposite handle to stay collinear, keeping its length
    Symmetric, // the opposite handle is the mirror image of the moved one
    Corner,    // the handles are independent
};

enum class HandleMove {
    Free,        // the handle follows the pointer (seed: left button)
    Constrained, // only the handle's distance to its knot changes (seed: right button)
};

// The segments an edit changed: first, first + 1, … (count of them), modulo segmentCount() on a
// closed curve. Insertions and deletions also renumber the segments after these.
struct SegmentRange
{
    int first = 0;
    int count = 0;
};

class CompositeCurve final
{
public:
    CompositeCurve() = default;
    // The finished curve through `knots` (docs/requirements.md 1.2), open.
    explicit CompositeCurve(std::span<const Point> knots);

    // --- building, as in the seed: segments appear from the 3rd knot on, "Done" finishes ---
    // Appends a knot and recomputes the handles that depend on it (the previous knot's, and the
    // mirrored end handles): O(1). Not allowed on a closed curve.
    Result<SegmentRange> appendKnot(const Point &knot);
    void finish() { m_finished = true; }
    [[nodiscard]] bool isFinished() const { return m_finished; }
    // Segments the seed shows while building: all once finished, otherwise all but the last.
    [[nodiscard]] int visibleSegmentCount() const;

    // --- structure ---
    [[nodiscard]] int knotCount() const { return static_cast<int>(m_types.size()); }
    [[nodiscard]] int segmentCount() const;
    [[nodiscard]] bool isClosed() const { return m_closed; }
    // 3n - 2 points for an open curve (c_{3i} = p_i), 3n + 1 for a closed one (the last repeats the first).
    [[nodiscard]] const std::vector<Point> &controlPoints() const { return m_control; }
    [[nodiscard]] Point knot(int i) const { return m_control[3 * static_cast<std::size_t>(i)]; }
    [[nodiscard]] std::vector<Point> knots() const;
    [[nodiscard]] Bezier segment(int i) const;
    [[nodiscard]] std::array<Point, 4> segmentPoints(int i) const;
    [[nodiscard]] PiecewiseBezier toPiecewise() const;

    // Control-point index helpers: the knot a control point belongs to, whether it is the knot
    // itself, and the index of the knot's incoming / outgoing handle (-1 where there is none).
    [[nodiscard]] int knotOfControl(int controlIndex) const;
    [[nodiscard]] static bool isKnotIndex(int controlIndex) { return controlIndex % 3 == 0; }
    [[nodiscard]] int inHandleIndex(int knotIndex) const;
    [[nodiscard]] int outHandleIndex(int knotIndex) const;

    [[nodiscard]] NodeType nodeType(int knotIndex) const { return m_types[static_cast<std::size_t>(knotIndex)]; }
    // Smooth makes the handles collinear (keeping their lengths), Symmetric also equalises their
    // lengths (to the mean), Corner changes nothing.
    Result<SegmentRange> setNodeType(int knotIndex, NodeType type);

    // --- edits (docs/requirements.md 1.4) ---
    // A handle move in the given mode, honouring the knot's node type. First and last handles of an
    // open curve have no opposite handle and move freely (the seed leaves them undefined).
    //  Free:        handle := pointer; Smooth: opposite := knot + (knot - pointer)/|knot - pointer| ·
    //               |opposite - knot| (unchanged when the pointer is on the knot); Symmetric:
    //               opposite := 2 knot - pointer; Corner: opposite unchanged.
    //  Constrained: handle := knot + u · |pointer - knot| with u the unit vector (knot - opposite)
    //               (for a Corner, the handle's own direction); the opposite handle does not move,
    //               except at a Symmetric node where it stays the mirror image.
    Result<SegmentRange> moveHandle(int controlIndex, const Point &pointer, HandleMove mode);
    // The knot moves; its two handles translate with it, so only its two segments change.
    Result<SegmentRange> moveKnot(int knotIndex, const Point &position);
    // Dispatches on the kind of control point (knot or handle); for typed coordinates too.
    Result<SegmentRange> moveControlPoint(int controlIndex, const Point &position, HandleMove mode);
    // Splits segment `segment` at t in (0, 1) by de Casteljau: a new Smooth knot, the shape unchanged.
    Result<SegmentRange> insertKnot(int segment, double t);
    // Removes a knot; its two segments merge, keeping the outer handles. An open curve keeps at least
    // 2 knots (seed message 9), a closed one at least 3.
    Result<SegmentRange> deleteKnot(int knotIndex);
    // Adds the segment from the last knot back to the first; the end knots get interior handles by
    // the construction rule with wrapped neighbours. Needs at least 3 knots. A last knot equal to the
    // first is merged into it (the closing segment then ends there); 3 distinct knots are still needed.
    Result<SegmentRange> close();

    // --- raw state, for undo and for documents: no construction rule is applied ---
    // Sets one control point (a closed curve's repeated first knot follows).
    void setControlPoint(int controlIndex, const Point &p);
    // Sets a knot's node type without touching its handles.
    void setNodeTypeOnly(int knotIndex, NodeType type);
    // A curve from its stored parts: 3n - 2 control points open (3n + 1 closed, last = first) and
    // one node type per knot. Errors when the sizes do not fit together or a point is not finite.
    [[nodiscard]] static Result<CompositeCurve> fromParts(std::vector<Point> control, std::vector<NodeType> types,
                                                          bool closed);

    friend bool operator==(const CompositeCurve &, const CompositeCurve &) = default;

private:
    void setKnotPosition(int knotIndex, const Point &p);
    void setControl(int controlIndex, const Point &p);
    int oppositeHandle(int controlIndex) const;
    int segmentOfControl(int controlIndex) const;
    SegmentRange segmentsOfKnot(int knotIndex) const;
    void constructInterior(int knotIndex, const Point &prev, const Point &next);
    void constructEnds();

    std::vector<Point> m_control;
    std::vector<NodeType> m_types; // one per knot
    bool m_closed = false;
    bool m_finished = false;
};

// docs/requirements.md 1.2 construction rules, exposed for tests and for other curve kinds.
// Interior handles at p with neighbours prev and next: {incoming, outgoing}; both at p when
// |p - prev| + |next - p| = 0.
[[nodiscard]] std::pair<Point, Point> interiorHandles(const Point &prev, const Point &p, const Point &next);
// The mirror image of `handle` across the perpendicular bisector of near–far, where `handle` belongs
// to `near`: c = h + v (1 - 2 v·w / |v|²), v = far - near, w = h - near. `far` itself if near = far.
[[nodiscard]] Point mirrorHandle(const Point &handle, const Point &near, const Point &far);
// The two-knot rule: c1 = p0 + R(60°)(m - p0), c2 = p1 + R(60°)(m - p1), m the midpoint.
[[nodiscard]] std::array<Point, 4> twoKnotCurve(const Point &p0, const Point &p1);

// Exact Bézier pieces as a composite curve (a spline or any other kind made editable knot by knot, or
// split): pieces of degree 1 and 2 are elevated to cubics, the same curve; each joint's node type is
// its continuity (C1: symmetric, G1: smooth, else a corner; the ends are smooth). A closed curve's
// last piece ends where the first begins. Errors: no piece, a piece of degree above 3 (no cubic is
// the same curve), pieces that do not meet, a closed curve of fewer than 3 pieces.
[[nodiscard]] Result<CompositeCurve> compositeFromPieces(std::span<const Bezier> pieces, bool closed);

} // namespace kontur::geo
