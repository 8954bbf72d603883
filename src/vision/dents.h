// Notches cut into a piece's edge (a V, or a "castle" cut square), found on the loop of its sub-pixel
// edge points before the outline is fitted: the edge dips into the piece and comes back out in the
// direction it went in. Their points are taken out of the loop, so the outline bridges the cut as the
// pattern's seam line does, and each becomes a notch. Internal to kontur_vision; docs/vision.md,
// "Marks on a piece".
#pragma once

#include "geometry/bezier.h"

#include <vector>

namespace kontur::vision::detail {

struct Dent
{
    geo::Point foot;     // px: where the notch's axis meets the edge the cut left out
    geo::Point tip;      // px: its deepest point
    double width = 0;    // px: its mouth along the edge
    double depth = 0;    // px: from the edge to the tip
    bool square = false; // a castle (its sides square to the edge) rather than a V
};

// Sizes in px of the cuts that are notches: at least `minDepth` and at most `maxDepth` deep, at most
// `maxWidth` across the mouth. A dart (wider and deeper) is a seam, not a notch.
struct DentLimits
{
    double minDepth = 0;
    double maxDepth = 0;
    double maxWidth = 0;
};

// The dents of a closed loop of edge points (px, in order, about a pixel apart; either orientation),
// and the loop without their points. A dent: a stretch the edge leaves by going into the piece (towards
// the side the loop's enclosed area lies on), whose chord is at most maxWidth, whose points all lie on
// the inner side of the edge fitted by a parabola to the stretches either side of it, and where the
// edge's direction before and after it agrees with that chord within 30° (a concave corner turns).
[[nodiscard]] std::vector<Dent> takeOutDents(std::vector<geo::Point> &loop, const DentLimits &limits);

// Drops the points (px) within half a dent's mouth (and a pixel) of its axis, the segment from its
// foot to its tip: edge points found again along an outline's normals where it bridges the dent.
void dropInDents(std::vector<geo::Point> &points, const std::vector<Dent> &dents);

} // namespace kontur::vision::detail
