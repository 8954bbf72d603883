// Whole-curve edits of composite curves for finishing a traced piece: joining two curves end to end
// (extending a curve by a new stroke is the same), closing where the ends meet (merged into one knot,
// a corner where they meet at an angle), straightening a segment, and simplifying a curve to a
// tolerance. Each makes a new curve from the old ones, which stay as they were (undo keeps them).
#pragma once

#include "geometry/composite.h"
#include "geometry/result.h"

namespace kontur::geo {

struct JoinOptions
{
    // Ends closer than this (document units) become one knot; farther ends are joined by a line.
    double mergeDistance = 0.0;
    // Where the tangents on either side of the joint turn by more than this (degrees), the joint is a
    // Corner node with its handles as they were; otherwise it is Smooth.
    double cornerAngle = 30.0;
};

// The same curve run the other way: control points and node types in reverse order. Open curves only.
[[nodiscard]] Result<CompositeCurve> reversed(const CompositeCurve &curve);

// `a` followed by `b`: a's last knot joined to b's first. Ends within mergeDistance become a's end
// knot (b's first knot and its handle move there by the gap); otherwise a straight segment joins
// them, its two knots corners. A Smooth joint turns b's first handle onto a's end tangent (keeping its
// length), so `a` is unchanged in every case. Both curves open, at least 2 knots each.
[[nodiscard]] Result<CompositeCurve> joinComposites(const CompositeCurve &a, const CompositeCurve &b,
                                                    const JoinOptions &options);

// Closes an open curve. A last knot within mergeDistance of the first is merged into it (the last
// segment then ends on the first knot, its end handle moved by the same gap): no segment of nearly
// zero length is added, and the joint is a Corner where the two ends meet at an angle (Smooth, with
// its handles made collinear, where they nearly continue each other). Ends farther apart are closed
// as CompositeCurve::close does (a segment built by the construction rule).
[[nodiscard]] Result<CompositeCurve> closeJoined(const CompositeCurve &curve, const JoinOptions &options);

// Segment `segment` straight: its handles at 1/3 and 2/3 of its chord, both its knots Corner nodes
// so that the neighbouring segments keep their shape.
[[nodiscard]] Result<CompositeCurve> makeSegmentLine(const CompositeCurve &curve, int segment);

struct Simplified
{
    CompositeCurve curve;
    double deviation = 0.0; // Hausdorff distance to the original (geo::deviation)
};

// Fewer knots within `tolerance` (document units, > 0): the curve is sampled densely between its
// Corner knots (and ends), each run refitted by fitStroke, and the runs put together again with the
// corners kept. Errors where the refit has no fewer knots or strays farther than `tolerance`
// (measured as the Hausdorff distance between old and new curve) even with a tighter fit.
[[nodiscard]] Result<Simplified> simplifyComposite(const CompositeCurve &curve, double tolerance);

} // namespace kontur::geo
