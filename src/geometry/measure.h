// Measuring traced curves (issue #10): the length along a curve between two of its joints (a seam),
// and the deviation of one curve from another (a traced curve against a reference pattern): the
// largest distance both ways (Hausdorff), the mean distance, and where the largest one is.
#pragma once

#include "geometry/piecewise.h"
#include "geometry/result.h"

namespace kontur::geo {

// The length of segments first..last - 1 of `curve` (from joint `first` to joint `last`, joints
// numbered 0..segmentCount() like a composite curve's knots) to `accuracy` (absolute, shared among
// the segments). On a closed curve last < first goes on over the closing joint. Errors for joints
// out of range.
[[nodiscard]] Result<double> lengthBetween(const PiecewiseBezier &curve, int first, int last, double accuracy);

struct Deviation
{
    double maximum = 0.0;               // Hausdorff distance: the larger of the two one-sided maxima
    double mean = 0.0;                  // the length-weighted mean distance, both ways together
    double meanAB = 0.0;                // mean distance from points of a to b (weighted by a's arc length)
    double meanBA = 0.0;                // … from b to a
    Point maximumAt = Point::Zero();    // the point (on a or b) where the maximum is reached
    Point maximumOther = Point::Zero(); // its nearest point on the other curve
    bool maximumOnA = true;
    int samples = 0; // distance evaluations made
};

// Samples each segment of each curve at `samplesPerSegment` + 1 parameters (at least 8; the mean is
// Simpson's rule in the arc length), takes the exact nearest point on the other curve for each
// (PiecewiseBezier::nearest), then refines the largest distance by golden-section search between
// the neighbouring samples, so the maximum is accurate to far below the sample spacing.
// Errors: an empty curve.
[[nodiscard]] Result<Deviation> deviation(const PiecewiseBezier &a, const PiecewiseBezier &b,
                                          int samplesPerSegment = 32);

} // namespace kontur::geo
