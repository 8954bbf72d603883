// Freehand tracing (issue #10): a stroke drawn with a finger or stylus along a contour is fitted with
// a composite curve of as few cubic segments as needed to stay within a tolerance, with corners kept
// as corner nodes and smooth (G1) joins elsewhere. After P. J. Schneider, "An Algorithm for
// Automatically Fitting Digitized Curves", Graphics Gems I (1990), with corner detection first.
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"

#include <span>
#include <vector>

namespace kontur::geo {

struct StrokeFitOptions
{
    // Largest allowed distance from a stroke point to the fitted curve, in document units (> 0).
    double tolerance = 1.0;
    // A point is a corner where the stroke turns by more than this (degrees) between the chords to
    // the points `cornerWindow` before and after it (along the stroke), and turns most there.
    double cornerAngle = 60.0;
    // The window of the corner test, in document units; <= 0: 4 × tolerance or 3 × the median
    // spacing of the samples, whichever is longer. Longer windows ignore more hand jitter but miss
    // corners closer together than the window.
    double cornerWindow = 0.0;
    // Newton reparameterization rounds per span before it is split, stopping early when a round gains
    // less than 5 % (Schneider uses 4 rounds; hand strokes drawn at varying speed need more).
    int reparameterizeIterations = 12;
};

struct StrokeFit
{
    // 3n + 1 control points of n cubic segments: c_{3i} are the knots, as in CompositeCurve.
    std::vector<Point> control;
    // One flag per knot: true where a corner was detected (the handles are independent there).
    std::vector<bool> corner;
    // The largest distance, over the (deduplicated) stroke points, from each point to the curve at
    // its parameter; an upper bound of the distance to the curve itself.
    double maxError = 0.0;
    int pointsUsed = 0; // stroke points after dropping duplicates

    [[nodiscard]] int segmentCount() const { return control.empty() ? 0 : (static_cast<int>(control.size()) - 1) / 3; }
    [[nodiscard]] Bezier segment(int i) const;
};

// Fits the stroke. Duplicate consecutive points (closer than 1e-9 × the stroke's size) are dropped.
// Errors: fewer than 2 distinct points, non-finite coordinates, tolerance not positive and finite.
// A stroke of 2 distinct points gives one straight cubic.
[[nodiscard]] Result<StrokeFit> fitStroke(std::span<const Point> stroke, const StrokeFitOptions &options = {});

// The indices (into `points`, already free of duplicates) of the corners the fit would keep;
// exposed for tests and for showing them while drawing.
[[nodiscard]] std::vector<int> detectCorners(std::span<const Point> points, double angleDegrees, double window);

} // namespace kontur::geo
