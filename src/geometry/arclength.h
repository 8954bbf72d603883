// Arc length of Bézier curves to a requested absolute accuracy, and its inverse (the parameter at a
// given length), for the length readout (docs/requirements.md 1.1 item 9, §6) and even spacing along curves.
#pragma once

#include "geometry/bezier.h"

#include <complex>
#include <cstdint>

namespace kontur::geo {

// A length and the absolute error bound it was computed to. `accuracy` is the one asked, or more
// when the asked one was below what doubles resolve for the curve (resolvableAccuracy) or the
// evaluation budget ran out first; nothing is silently worse than reported.
struct LengthEstimate
{
    double length = 0.0;
    double accuracy = 0.0;
};

// ∫₀¹ |B'(t)| dt with |result - exact| <= accuracy (absolute, in the curve's units) for every curve
// whose speed is smooth between its minima; see arclength.cpp for the method. A non-positive or
// non-finite accuracy is replaced by 1e-9 times the control polygon's length; one below
// resolvableAccuracy(curve) is raised to it. The work is bounded (see arcLengthEstimate).
[[nodiscard]] double arcLength(const Bezier &curve, double accuracy);

// The length of the part of the curve over [t0, t1] (negative when t1 < t0), same accuracy contract.
[[nodiscard]] double arcLength(const Bezier &curve, double t0, double t1, double accuracy);

// The same with the accuracy reached. At most kArcLengthBudget Gauss–Kronrod rules (15 speed
// evaluations each) are spent; if the error estimate is not within the accuracy by then, the
// estimate reached is reported.
[[nodiscard]] LengthEstimate arcLengthEstimate(const Bezier &curve, double t0, double t1, double accuracy);
inline constexpr int kArcLengthBudget = 2000;

// The smallest absolute accuracy a length of this curve can honestly be asked to: the control
// points are known only to their rounding, ~ε·max|coordinate| each, and the quadrature sums speeds
// with rounding ~ε·length (see arclength.cpp). Positive for a non-empty curve with a nonzero point.
[[nodiscard]] double resolvableAccuracy(const Bezier &curve);

// The parameter t with arcLength(curve, 0, t) = length to within `accuracy` (in length units);
// lengths outside [0, total] give 0 or 1.
[[nodiscard]] double parameterAtLength(const Bezier &curve, double length, double accuracy);

namespace detail {
// Speed evaluations made by the arc length routines on this thread since the last reset: lets tests
// assert bounded work without timing anything.
[[nodiscard]] std::uint64_t speedEvaluations();
void resetSpeedEvaluations();
// The principal square root of a complex number of moderate size (|w| within 1e±150) by real
// square roots, as the branch points of a quadratic hodograph are found (std::sqrt calls hypot).
[[nodiscard]] std::complex<double> principalSqrt(std::complex<double> w);
} // namespace detail

} // namespace kontur::geo
