// Cutting the raw offset's loops (offset.cpp's stages 2 and 3): the raw offset's pieces, their
// crossings (found on polylines, refined by Newton's method), the arcs between crossings, and the
// kept arcs chained into parts. Internal to offset.cpp; split from it along the stages it names.
#pragma once

#include "geometry/bezier.h"
#include "geometry/offset.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace kontur::geo::offsetdetail {

// The steps offsetCurve calls have spent on this thread (detail::offsetWork).
inline thread_local std::uint64_t t_work = 0;

// The steps one offsetCurve call has spent (see kOffsetBudget). Every adaptive loop checks over()
// and stops refining once the budget is spent or the caller cancelled (OffsetControl); the call
// then reports WorkBudget or Cancelled.
struct Work
{
    OffsetControl *control = nullptr;
    std::uint64_t used = 0;
    std::uint64_t published = 0;
    void add(std::uint64_t n)
    {
        used += n;
        t_work += n;
        if (control && used - published >= kOffsetPublishSteps) {
            control->work.store(used, std::memory_order_relaxed);
            published = used;
        }
    }
    // A relaxed load per check: the flag orders nothing else, and a plain load costs no more than
    // the comparison beside it, so Cancel is seen within a few evaluations.
    [[nodiscard]] bool cancelled() const { return control && control->cancelled.load(std::memory_order_relaxed); }
    [[nodiscard]] bool over() const { return used > kOffsetBudget || cancelled(); }
    void progress(double p) const
    {
        if (control)
            control->progress.store(p, std::memory_order_relaxed);
    }
    void finish() const
    {
        if (control)
            control->work.store(used, std::memory_order_relaxed);
    }
};

inline double cross(const Point &a, const Point &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

struct RawPiece
{
    Bezier curve;
    bool turnedBack = false;     // a turned-back hem corner's line: nearer the source than the width by design
    double error = 0.0;          // the largest sampled gap to the exact offset (0 for a line's offset)
    std::optional<Point> corner; // a miter's or bevel's corner: only nearer another part than it counts
};

// A polyline of a piece with the parameter of each vertex, within `tol` of the piece.
struct Polyline
{
    std::vector<double> t;
    std::vector<Point> p;
};

struct Crossing
{
    double ga = 0.0, gb = 0.0; // chain parameters (piece index + t), ga < gb
    Point point;
};

// A stretch of the raw offset between two split points, as portions of pieces.
struct Arc
{
    double g0 = 0.0, g1 = 0.0; // chain parameters; g1 may pass the piece count on a closed curve
    int startId = -1, endId = -1;
    Point startPoint, endPoint;
    bool kept = true;
};

// The portion of a piece an arc covers: the piece's index and the parameters it runs between.
struct Portion
{
    int piece;
    double t0, t1;
};

// The kept arcs chained through their shared crossings into parts, and whether each part closes.
struct Parts
{
    std::vector<std::vector<std::size_t>> arcs;
    std::vector<bool> closed;
};

// Each piece as a polyline within `tol`, with its parameters; empty once the work budget is spent.
// The pieces join exactly, so a closed chain's polylines make one closed polygon.
std::vector<Polyline> flattenPieces(const std::vector<RawPiece> &pieces, double tol, Work &work);

// The crossings of the pieces, found on their polylines (`lines`, flattened within `tol`) and refined
// by Newton's method. Stops early (with what it found) once the work budget is spent; the caller
// checks work.over().
std::vector<Crossing> selfIntersections(const std::vector<RawPiece> &pieces, const std::vector<Polyline> &lines,
                                        bool closed, double tol, Work &work);

// The portions of the `n` pieces `arc` covers, in order (a closed chain's arc may wrap past its end).
std::vector<Portion> portionsOf(const Arc &arc, int n);

// Stage 2: the raw offset (a chain of pieces) split at its crossings into arcs, all kept so far.
std::vector<Arc> arcsBetween(const std::vector<Crossing> &crossings, const std::vector<RawPiece> &raw, bool closed);

// The kept arcs chained through their shared crossings into parts, and whether each part closes.
Parts chainArcs(const std::vector<Arc> &arcs);

// The longest of the parts (by the chords of their pieces' portions): the offset kept.
std::size_t longestPart(const Parts &parts, const std::vector<Arc> &arcs, const std::vector<RawPiece> &raw);

} // namespace kontur::geo::offsetdetail
