// The global B-spline of seed 001 §1.2 (docs/requirements.md 2): the cubic B-spline that interpolates values at
// knots v_0..v_{k-1} with given end derivatives, on the auxiliary knots u_i = v_0 - (3 - i) h (i <= 2),
// u_i = v_{i-3} (3 <= i <= k + 2), u_i = v_{k-1} + (i - k - 2) h after, h = (v_{k-1} - v_0)/(k - 1).
// Its system L b = (c_0..c_{k-1}, d_left, d_right) has three nonzeros per row; eliminating b_0 and
// b_{k+1} with the two derivative rows leaves a tridiagonal system in b_1..b_k, solved in O(k) (the
// seed claims O(k³)).
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/result.h"
#include "geometry/splines/bspline.h"

#include <span>
#include <vector>

namespace kontur::geo {

// u_0..u_{k+5} for knots v_0..v_{k-1} (Example 1.20: (2, 15/4, 5) → (−5/2, −1, 1/2, 2, 15/4, 5, 13/2, 8, 19/2)).
[[nodiscard]] std::vector<double> globalBSplineKnots(std::span<const double> v);

struct GlobalBSplineFunction
{
    std::vector<double> knots;        // u_0..u_{k+5}
    std::vector<double> coefficients; // b_0..b_{k+1} for the seed's scaled bells Bs (Example 1.23)
    BSpline spline;                   // the same function as a 2D curve (x(t) = t, see bellSpline)
};

// The seed's function form over strictly increasing v (k >= 2 knots).
[[nodiscard]] Result<GlobalBSplineFunction> globalBSplineFunction(std::span<const double> v, std::span<const double> c,
                                                                  double dLeft, double dRight);

// The parametric form through points: knots from the parameterization (unnormalised), the control
// points b_0..b_{k+1} of the plain (unscaled) basis, with end derivatives with respect to the parameter.
[[nodiscard]] Result<BSpline> globalBSpline(std::span<const Point> points, Parameterization param,
                                            const Point &startTangent, const Point &endTangent);
// The same over given strictly increasing parameters.
[[nodiscard]] Result<BSpline> globalBSpline(std::span<const double> parameters, std::span<const Point> points,
                                            const Point &startTangent, const Point &endTangent);

} // namespace kontur::geo
