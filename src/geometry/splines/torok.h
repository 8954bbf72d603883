// Seed 001's clamped spline on uniform knots (§1.4) and Török's "new procedure" (§2), with the
// corrections of docs/requirements.md 2: h = (v_{k-1} - v_0)/(k - 1) (the seed divides by k) and the boundary
// terms the seed omits from the half-size system. Both give the derivatives d_0..d_{k-1} of the
// same C² cubic (then drawn as a Hermite spline); the clamped system is
//   d_{i-1} + 4 d_i + d_{i+1} = 3 (y_{i+1} - y_{i-1}) / h,   i = 1..k-2.
// Török eliminates the odd unknowns with CDN_h(y_l, y_r, d_l, d_r) = (3 (y_r - y_l)/h - d_l - d_r)/4,
// leaving -½ d_{i-2} + 7 d_i - ½ d_{i+2} = (3 (y_{i-2} - y_{i+2}) - 12 (y_{i-1} - y_{i+1})) / (2h) for
// even i; the first row gets +d_0/2 on the right, the last +d_{k-1}/2 when k is odd, and when k is even
// the last row is -½ d_{k-4} + 15/2 d_{k-2} = (3 (y_{k-4} - y_{k-2}) + 12 (y_{k-1} - y_{k-3}))/(2h) - 2 d_{k-1}.
#pragma once

#include "geometry/result.h"
#include "geometry/splines/hermite.h"

#include <span>
#include <vector>

namespace kontur::geo {

enum class ClampedSolver {
    Classical, // the tridiagonal system of seed 001 (1.17), k - 2 unknowns
    Torok,     // the "new procedure": a tridiagonal system in the even derivatives only
};

// CDN_h (seed 001, Definition 2.1).
[[nodiscard]] inline double cdn(double h, double yLeft, double yRight, double dLeft, double dRight)
{
    return (3.0 * (yRight - yLeft) / h - dLeft - dRight) / 4.0;
}

// d_0..d_{k-1} for values y at uniform knots with spacing h > 0 and end derivatives d0, dLast.
// Errors: fewer than 2 values, h not positive, non-finite input.
[[nodiscard]] Result<std::vector<double>> uniformClampedSlopes(std::span<const double> y, double h, double d0,
                                                               double dLast, ClampedSolver solver);

// Seed 001's clamped spline C-Spline over knots x that must be uniform (to 1e-9 of the range;
// otherwise use functionSpline(…, EndCondition::Clamped, …), the general system), as a function
// HermiteSpline.
[[nodiscard]] Result<HermiteSpline> uniformClampedSpline(std::span<const double> x, std::span<const double> y,
                                                         double d0, double dLast,
                                                         ClampedSolver solver = ClampedSolver::Classical);

} // namespace kontur::geo
