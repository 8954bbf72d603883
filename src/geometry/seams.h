// The seams of a garment piece (issue #44): its closed outline between two consecutive corner knots,
// each with a seam allowance width of its own. A corner is a joint of the outline's segments where the
// tangent turns by more than kSeamCornerDegrees; an outline without one is a single seam. Seams are
// numbered from the first corner at or after the outline's start, in the outline's direction; the
// last one runs on through the start to the first corner.
#pragma once

#include "geometry/piecewise.h"

#include <optional>
#include <vector>

namespace kontur::geo {

inline constexpr double kSeamCornerDegrees = 15.0;

// Segments first, first + 1, … first + count − 1 (modulo the outline's segment count).
struct SeamSpan
{
    int first = 0;
    int count = 0;
    friend bool operator==(const SeamSpan &, const SeamSpan &) = default;
};

// The seams of a closed outline (an open one is one seam of all its segments; none when empty).
[[nodiscard]] std::vector<SeamSpan> seamSpans(const PiecewiseBezier &outline);
// The seam that segment `segment` belongs to (-1 when out of range).
[[nodiscard]] int seamOfSegment(const std::vector<SeamSpan> &seams, int segmentCount, int segment);
// Each segment's offset distance (OffsetOptions::segmentDistances) from the seams' widths: seam k's
// width is widths[k] when that is given, else `fallback` (the piece's own width).
[[nodiscard]] std::vector<double> segmentDistancesOf(const PiecewiseBezier &outline,
                                                     const std::vector<std::optional<double>> &widths, double fallback);
// The same for an outline of `segmentCount` segments whose seams (seamSpans) are known already.
[[nodiscard]] std::vector<double> segmentDistancesOf(int segmentCount, const std::vector<SeamSpan> &seams,
                                                     const std::vector<std::optional<double>> &widths, double fallback);

// Each segment's hem flag (OffsetOptions::hems): those of the seams numbered in `hemSeams`.
[[nodiscard]] std::vector<bool> segmentHemsOf(const PiecewiseBezier &outline, const std::vector<int> &hemSeams);
// The same for an outline of `segmentCount` segments whose seams (seamSpans) are known already.
[[nodiscard]] std::vector<bool> segmentHemsOf(int segmentCount, const std::vector<SeamSpan> &seams,
                                              const std::vector<int> &hemSeams);

} // namespace kontur::geo
