// Arc length of Bézier curves to a requested absolute accuracy, and its inverse (the parameter at a
// given length), for the length readout (SPEC.md 1.1 item 9, §6) and even spacing along curves.
#pragma once

#include "geometry/bezier.h"

namespace kontur::geo {

// ∫₀¹ |B'(t)| dt with |result - exact| <= accuracy (absolute, in the curve's units) for every curve
// whose speed is smooth between its minima; see arclength.cpp for the method. A non-positive or
// non-finite accuracy is replaced by 1e-9 times the control polygon's length.
[[nodiscard]] double arcLength(const Bezier &curve, double accuracy);

// The length of the part of the curve over [t0, t1] (negative when t1 < t0), same accuracy contract.
[[nodiscard]] double arcLength(const Bezier &curve, double t0, double t1, double accuracy);

// The parameter t with arcLength(curve, 0, t) = length to within `accuracy` (in length units);
// lengths outside [0, total] give 0 or 1.
[[nodiscard]] double parameterAtLength(const Bezier &curve, double length, double accuracy);

} // namespace kontur::geo
