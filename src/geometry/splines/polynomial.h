// Polynomial interpolation through the same points as the splines, for the "Runge" comparison of
// seed 001 (docs/requirements.md 2): the polynomial of degree n - 1 through n points, evaluated in the barycentric
// form of the second kind (Berrut & Trefethen, "Barycentric Lagrange Interpolation", SIAM Review
// 2004): stable, O(n) per point after O(n²) weights. Converts to PiecewiseBezier with one Bézier piece
// of degree n - 1 per knot interval (from the Newton form's Taylor coefficients; exact up to rounding).
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"

#include <span>
#include <vector>

namespace kontur::geo {

// A degree this high is useless for drawing (and its Bézier pieces lose all precision).
inline constexpr int kMaxPolynomialPoints = 64;

class PolynomialInterpolant final
{
public:
    PolynomialInterpolant() = default;
    // Errors: fewer than 2 points, more than kMaxPolynomialPoints, sizes differ, parameters not
    // strictly increasing, non-finite input.
    [[nodiscard]] static Result<PolynomialInterpolant> create(std::vector<double> parameters,
                                                              std::vector<Point> points);

    [[nodiscard]] int pointCount() const { return static_cast<int>(m_points.size()); }
    [[nodiscard]] int degree() const { return pointCount() - 1; }
    [[nodiscard]] const std::vector<double> &parameters() const { return m_params; }
    [[nodiscard]] const std::vector<Point> &points() const { return m_points; }
    [[nodiscard]] const std::vector<double> &weights() const { return m_weights; }

    // The polynomial at u (any real u; the knot values exactly at the knots).
    [[nodiscard]] Point eval(double u) const;
    // One Bézier piece of degree n - 1 per interval [s_i, s_{i+1}].
    [[nodiscard]] PiecewiseBezier toPiecewise() const;

private:
    std::vector<double> m_params;
    std::vector<Point> m_points;
    std::vector<double> m_weights;
};

// Through points with the given parameterization (unnormalised, as splineParameters).
[[nodiscard]] Result<PolynomialInterpolant> polynomialInterpolant(std::span<const Point> points,
                                                                  Parameterization param);
// The function y(x) over strictly increasing x, as a curve (x_i, y_i) with parameters x_i: x(u) = u.
[[nodiscard]] Result<PolynomialInterpolant> functionPolynomial(std::span<const double> x, std::span<const double> y);

} // namespace kontur::geo
