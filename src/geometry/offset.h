// Offset curves (a pattern maker's seam allowance): the curve at a constant distance from a curve of
// Bézier pieces, on one side, approximated by cubic pieces within a tolerance, with the corners joined
// (miter up to a length, bevel, or round) and the loops that a tight curve's offset makes cut away.
#pragma once

#include "geometry/piecewise.h"
#include "geometry/result.h"

#include <atomic>
#include <cstdint>
#include <string_view>
#include <vector>

namespace kontur::geo {

// Which side the offset lies on. Left and Right are seen along the curve's direction. Outside is away
// from the enclosed area whatever the orientation; for an open curve the area is the one its chord
// closes (the side the curve bulges to is Outside); Inside is the other side.
enum class OffsetSide { Outside, Inside, Left, Right };
enum class OffsetJoin { Miter, Bevel, Round };

[[nodiscard]] const char *offsetSideId(OffsetSide side); // "outside", "inside", "left", "right"
[[nodiscard]] const char *offsetJoinId(OffsetJoin join); // "miter", "bevel", "round"
[[nodiscard]] bool offsetSideFromId(std::string_view id, OffsetSide &side);
[[nodiscard]] bool offsetJoinFromId(std::string_view id, OffsetJoin &join);

struct OffsetOptions
{
    double distance = 1.0; // > 0, in the curve's units
    OffsetSide side = OffsetSide::Outside;
    OffsetJoin join = OffsetJoin::Miter;
    // A miter corner whose tip lies farther than this from the source corner is bevelled instead.
    double miterLimit = 3.0;
    // Every point of the result lies within this of the true offset (checked by sampling), > 0; one
    // below resolvableOffsetTolerance is raised to it (OffsetResult::tolerance says which was used).
    double tolerance = 0.005;
    // A seam allowance per seam (issue #44): the distance for each of the source's segments, in order,
    // each >= 0 and finite (0: the offset follows that segment itself, as at a fold); empty: `distance`
    // everywhere. `distance` stays the piece's own width: the size check uses the largest of them, and
    // the miter limit grows with the wider of a corner's two widths (miterLimit · max(dA, dB) /
    // distance), so that a 1 cm side meeting a 3 cm hem is mitred under the limit a 1 cm allowance has.
    // Where two widths differ at a corner the join is a miter (or a bevel), never round: the two
    // offsets are extended or trimmed to meet.
    std::vector<double> segmentDistances;
    // Hems (with segmentDistances; one flag per segment, or empty): where a hem segment meets one that
    // is no hem at a convex corner, the corner is turned back: the neighbour's allowance runs on to
    // the hem line and from there mirrored about it out to the hem's allowance edge, so that the hem,
    // turned up along its seam, lies flat under the neighbour's allowance (a flared side's allowance
    // narrows below the hem line). The hem's allowance is cut short where that mirrored edge crosses
    // it. Under the miter limit, as a miter; beyond it the corner is the join's.
    std::vector<bool> hems;
};

struct OffsetResult
{
    PiecewiseBezier curve;  // cubic pieces, closed when the source is (the longest part when it splits)
    int partsDropped = 0;   // parts of the offset that fell apart from the kept one (a pinched inside)
    int loopsRemoved = 0;   // self-intersections of the raw offset that were cut
    double tolerance = 0.0; // the tolerance used: the one asked, or the resolvable one when that was finer
};

// The finest tolerance an offset of `source` at `distance` can honestly be asked: its points are sums
// of numbers as large as max|coordinate| + distance, each known only to its rounding (a few ε of it),
// and the error check subtracts two of them.
[[nodiscard]] double resolvableOffsetTolerance(const PiecewiseBezier &source, double distance);

// Work is bounded whatever the input: at most kOffsetBudget steps (an offset point evaluated, a vertex
// of the polylines that look for self-intersections, 16 pairs of their edges compared, a nearest-point
// query), else the error WorkBudget; and a distance more than kOffsetMaxRatio times the source's size
// (its bounding box's larger side) is refused as OutOfProportion: such an offset is a circle around a
// dot, not a seam allowance, and its exact form would need ever more pieces.
inline constexpr std::uint64_t kOffsetBudget = 1'000'000;
inline constexpr double kOffsetMaxRatio = 1000.0;

// Lets another thread follow a long offset and stop it (the app computes allowances off its GUI
// thread). The offset checks `cancelled` wherever it checks its work budget — after every few
// evaluations, every polyline vertex and edge pair, every nearest-point query — and then answers
// ErrorCode::Cancelled; `work` and `progress` are published every kOffsetPublishSteps steps.
struct OffsetControl
{
    std::atomic<bool> cancelled{false};
    std::atomic<std::uint64_t> work{0}; // steps spent so far (as counted against kOffsetBudget)
    // 0..1, an estimate by stage: fitting the pieces, finding the crossings, trimming the loops.
    std::atomic<double> progress{0.0};

    void cancel() { cancelled.store(true, std::memory_order_relaxed); }
};
inline constexpr std::uint64_t kOffsetPublishSteps = 256;

// +1 when the offset on `side` lies on the curve's left (the left normal (-y', x')), -1 on its right.
[[nodiscard]] int offsetSign(const PiecewiseBezier &source, OffsetSide side);

// The offset of `source` (any degree, the pieces joined end to end). Each piece is approximated by
// cubic Hermite pieces through the exact offset points with the exact offset derivatives
// O'(t) = B'(t)(1 − s·d·κ(t)), subdivided until sampled errors are below tolerance / 2 (the
// interpolation scheme of Klass 1983 with the subdivision error control of Tiller & Hanson 1984,
// "Offsets of two-dimensional profiles", IEEE CG&A 4(9); compared in Elber, Lee & Kim 1997,
// "Comparing offset curve approximation methods", IEEE CG&A 17(3)). Corners get the join; the raw
// offset is then split at its self-intersections and every part closer to the source than the
// distance is dropped (the loops and swallowtails where the radius of curvature is below the
// distance; Elber & Cohen 1991, "Error bounded variable distance offset operator for free form
// curves and surfaces"). Errors: no piece, non-finite points, a distance or tolerance not positive
// and finite, nothing left (an inside offset wider than the curve), a closed curve whose kept arcs
// do not close into one (InvalidArgument; see docs/geometry.md), a distance out of proportion,
// the work budget spent (see kOffsetBudget), cancelled through `control` (may be null). With
// segmentDistances, each segment is offset by its own distance, and a part of the raw offset is
// dropped when it lies nearer than its width to a segment of any width (the loops at a concave corner
// where the widths differ); segmentDistances of the wrong size or with a negative or non-finite
// entry is an InvalidArgument.
[[nodiscard]] Result<OffsetResult> offsetCurve(const PiecewiseBezier &source, const OffsetOptions &options,
                                               OffsetControl *control = nullptr);

namespace detail {
// Work steps (as counted against kOffsetBudget) spent by offsetCurve on this thread since the last
// reset: lets tests assert bounded work without timing anything.
[[nodiscard]] std::uint64_t offsetWork();
void resetOffsetWork();
} // namespace detail

} // namespace kontur::geo
