// Interpolating cubic splines (C²) through n points with the classical end conditions: natural
// (zero second derivative), clamped (given end derivatives: seed 001's d_0 and d_{k-1}, seed 003's
// guide vectors), not-a-knot (third derivative continuous at the second and last-but-one knot, de
// Boor) and periodic (a closed curve, C² at every joint). The unknowns are the first derivatives m_i
// at the knots (the tangent form of de Boor, "A Practical Guide to Splines", ch. IV):
//   h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i δ_{i-1} + h_{i-1} δ_i),
// h_i = s_{i+1} - s_i, δ_i = (p_{i+1} - p_i) / h_i: tridiagonal (cyclic when periodic), solved in O(n)
// by the sweep (Thomas) or Sherman–Morrison. The result is a HermiteSpline (hermite.h), which
// converts exactly to PiecewiseBezier.
#pragma once

#include "geometry/parameterization.h"
#include "geometry/result.h"
#include "geometry/splines/hermite.h"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace kontur::geo {

enum class EndCondition { Natural, Clamped, NotAKnot, Periodic };
[[nodiscard]] const char *nameOf(EndCondition c);
// "natural", "clamped", "not-a-knot", "periodic"; false when unknown.
[[nodiscard]] bool parseEndCondition(std::string_view name, EndCondition &out);

// From this many knots on, the open-end systems are solved on two threads: the sweep's two halves
// (from the top and from the bottom) share nothing until the middle row, so each runs on its own
// processor with the same steps in the same order, and the same results, as on one.
inline constexpr std::size_t kSplineTwoThreadRows = std::size_t(1) << 17;

// The parametric spline through `points` (parameters from splineParameters, unnormalised).
// `startTangent`/`endTangent` are used only when clamped (derivatives with respect to the parameter;
// a zero-length one is an error). Periodic: the curve closes from the last point back to the first;
// a last point equal to the first is taken as that closing and dropped. Needs 2 points (3 periodic).
[[nodiscard]] Result<HermiteSpline> cubicSpline(std::span<const Point> points, EndCondition end,
                                                Parameterization param = Parameterization::ChordLength,
                                                const Point &startTangent = Point::Zero(),
                                                const Point &endTangent = Point::Zero());
// The same with given strictly increasing parameters (n values; n + 1 when periodic, the last one
// for the closing point).
[[nodiscard]] Result<HermiteSpline> cubicSpline(std::vector<double> parameters, std::span<const Point> points,
                                                EndCondition end, const Point &startTangent = Point::Zero(),
                                                const Point &endTangent = Point::Zero());

// The function spline y(x) over strictly increasing x (seed 001). Clamped takes the end slopes;
// periodic needs y_0 = y_{n-1} (period x_{n-1} - x_0).
[[nodiscard]] Result<HermiteSpline> functionSpline(std::span<const double> x, std::span<const double> y,
                                                   EndCondition end, double startSlope = 0.0, double endSlope = 0.0);
// Only the derivatives y'(x_i) of that spline.
[[nodiscard]] Result<std::vector<double>> functionSplineSlopes(std::span<const double> x, std::span<const double> y,
                                                               EndCondition end, double startSlope = 0.0,
                                                               double endSlope = 0.0);

// The derivatives m_i for values v_i at parameters s_i (n values, n + 1 when periodic: s_n closes
// the curve and v_n = v_0 is implied). The numerical core shared by every form above; s must be
// checked by the caller. Returns false only on a singular system (not for valid input).
[[nodiscard]] bool cubicSplineDerivatives(std::span<const double> s, std::span<const Point> v, EndCondition end,
                                          const Point &d0, const Point &dn, std::span<Point> m);
[[nodiscard]] bool cubicSplineDerivatives(std::span<const double> s, std::span<const double> v, EndCondition end,
                                          double d0, double dn, std::span<double> m);

} // namespace kontur::geo
