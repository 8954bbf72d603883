// Bézier curves of any degree n >= 1 as a small value type: evaluation by de Casteljau, the
// matrix form of the cubic (SPEC.md 1.2), subdivision and adaptive flattening into a polyline.
#pragma once

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

namespace kontur::geo {

using Point = Eigen::Vector2d;

class Bezier final
{
public:
    Bezier() = default;
    // A curve needs at least two control points (degree >= 1); fewer give an empty curve.
    explicit Bezier(std::vector<Point> controlPoints);

    [[nodiscard]] bool isEmpty() const { return m_points.size() < 2; }
    [[nodiscard]] int degree() const { return static_cast<int>(m_points.size()) - 1; }
    [[nodiscard]] const std::vector<Point> &controlPoints() const { return m_points; }

    // B(t) by de Casteljau's algorithm: repeated linear interpolation of the control polygon,
    // numerically stable for any degree (Farin, "Curves and Surfaces for CAGD", ch. 4).
    [[nodiscard]] Point eval(double t) const;

    // The two halves of the curve at t, from the sides of the de Casteljau triangle.
    [[nodiscard]] std::pair<Bezier, Bezier> split(double t) const;

private:
    std::vector<Point> m_points;
};

// The cubic in matrix form B(t) = T·M·C with T = (1, t, t², t³) and the corrected
// M = [[1,0,0,0],[-3,3,0,0],[3,-6,3,0],[-1,3,-3,1]] (SPEC.md 1.2; the seed misprints rows 3 and 4).
[[nodiscard]] Point evalCubicMatrix(const std::array<Point, 4> &c, double t);

// Appends to `out` a polyline that stays within `tolerance` of the curve (same units as the
// control points), starting with the curve's first point unless `out` already ends there.
// Subdivides at t = 1/2 until every interior control point lies within `tolerance` of the chord;
// since the curve lies in the convex hull of its control polygon, that bounds its distance to the chord.
void flatten(const Bezier &curve, double tolerance, std::vector<Point> &out);

} // namespace kontur::geo
