// The marks a pattern maker draws on a piece or cuts into its edge, found in the photo once the piece's
// outline is known (traceOutlines): the grainline (a long straight line, with or without arrowheads),
// notches (V or castle cuts into the edge, which the tracer bridges and reports; slits and short marks
// drawn across the edge), drill holes (a small dot, circle or cross well inside the piece) and the fold
// (a "place on fold" bracket: a bar along a straight edge, its two legs' arrows pointing at the edge).
// Dark marks are what a morphological black-hat (Soille 2003, §4.5) lifts out of the paper: thinner than
// kMaxMarkWidthMm and darker than the paper around them. docs/vision.md, "Marks on a piece".
#pragma once

#include "geometry/result.h"
#include "vision/outline.h"
#include "vision/pixelmapping.h"

#include <opencv2/core/mat.hpp>

#include <array>
#include <optional>
#include <vector>

namespace kontur::vision {

// Marks are lines at most this wide (mm): a pen's, a pencil's, a marker's; anything wider is paper
// print, a shadow or an object lying on the piece.
inline constexpr double kMaxMarkWidthMm = 2.5;

struct MarkOptions
{
    // One millimetre in the mapping's units (as OutlineOptions::millimetre).
    double millimetre = 1.0;
    // A grainline is a straight line at least this long (mm), on average at least `grainFromEdge` (mm)
    // from the edge (a line along the edge is a seam line drawn on the paper, not a grainline).
    double minGrainline = 30.0;
    double grainFromEdge = 4.0;
    // A "place on fold" bracket's bar is at least this long (mm); its legs reach at least 4 mm from it
    // and end at most 6 mm from the edge.
    double minFoldBar = 30.0;
};

struct FoundNotch
{
    enum class Kind { Slit, V, Castle };
    geo::Point at = geo::Point::Zero(); // on the outline, in the mapping's units
    geo::Point into = geo::Point(1, 0); // unit: the notch's direction into the piece
    Kind kind = Kind::Slit;
};

struct FoundMarks
{
    // The grainline's ends: towards b where only b has an arrowhead; with arrowheads at both ends or
    // none, b is the upper end in the mapping's frame (the right one when it lies level).
    std::optional<std::array<geo::Point, 2>> grainline;
    std::vector<FoundNotch> notches; // the outline's cut notches first, then the drawn ones
    std::vector<geo::Point> drillHoles;
    // The fold a "place on fold" bracket points at: the straight stretch of the outline its legs end
    // at, from corner to corner where it runs into corners.
    std::optional<std::array<geo::Point, 2>> fold;
};

// The marks on or in the piece whose outline is `outline` (in the mapping's units) in `image` (8-bit
// gray, BGR or BGRA, the photo warped into the piece's plane as traceOutlines saw it). Errors: an
// empty image, a map that is not invertible, an outline that is not closed.
[[nodiscard]] geo::Result<FoundMarks> findPieceMarks(const cv::Mat &image, const PixelMapping &mapping,
                                                     const Outline &outline, const MarkOptions &options = {});

} // namespace kontur::vision
