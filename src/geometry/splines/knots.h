// Parameter values for splines through points, unnormalised (issue 4): uniform gives 0, 1, 2, …,
// chord length the cumulative chord length, centripetal the cumulative square roots of the chords.
// The normalised values of SPEC.md 1.3 are geo::parameterize (parameterization.h); these are the
// same sums before the division, which spline derivatives and the CLI report in the input's units.
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/result.h"

#include <span>
#include <vector>

namespace kontur::geo {

// s_0 = 0, s_i = s_{i-1} + |p_i - p_{i-1}|^α. With `closed`, one more value: the step from the last
// point back to the first. Errors: fewer than 2 points (3 when closed), a non-finite coordinate, all
// points equal, and two consecutive points that coincide (a spline through them would need a
// repeated parameter or a stationary point), for every parameterization.
[[nodiscard]] Result<std::vector<double>> splineParameters(std::span<const Point> points, Parameterization p,
                                                           bool closed = false);

// Checks that `values` strictly increase and are finite (knots of a function spline y(x), user
// parameters). `what` names them in the message ("x", "parameter").
[[nodiscard]] Result<Ok> checkStrictlyIncreasing(std::span<const double> values, const char *what);

// Checks that every coordinate is finite.
[[nodiscard]] Result<Ok> checkFinite(std::span<const Point> points);

} // namespace kontur::geo
