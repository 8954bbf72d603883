// Bézier curves of any degree n >= 1 as a small value type: evaluation by de Casteljau, the
// matrix form of the cubic (docs/requirements.md 1.2), derivatives, subdivision, degree elevation (seed 002,
// docs/requirements.md 3) and reduction, reversal, affine maps, tight bounds, curvature, inflections and
// adaptive flattening into a polyline. Arc length and nearest point live in arclength.h / nearest.h.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace kontur::geo {

using Point = Eigen::Vector2d;
using Box = Eigen::AlignedBox2d;

// p · 2^e, each coordinate by std::ldexp: exact, and unlike multiplying by ldexp(1.0, e) it has no
// factor that overflows (2^1075 is needed to bring a subnormal coordinate of 1e-310 to unit size).
[[nodiscard]] inline Point ldexpPoint(const Point &p, int e)
{
    return Point(std::ldexp(p.x(), e), std::ldexp(p.y(), e));
}

class Bezier final
{
public:
    Bezier() = default;
    // A curve needs at least two control points (degree >= 1); fewer give an empty curve.
    explicit Bezier(std::vector<Point> controlPoints);

    [[nodiscard]] bool isEmpty() const { return m_points.size() < 2; }
    [[nodiscard]] int degree() const { return static_cast<int>(m_points.size()) - 1; }
    [[nodiscard]] const std::vector<Point> &controlPoints() const { return m_points; }
    [[nodiscard]] Point startPoint() const { return m_points.empty() ? Point::Zero() : m_points.front(); }
    [[nodiscard]] Point endPoint() const { return m_points.empty() ? Point::Zero() : m_points.back(); }

    // B(t) by de Casteljau's algorithm: repeated linear interpolation of the control polygon,
    // numerically stable for any degree (Farin, "Curves and Surfaces for CAGD", ch. 4).
    [[nodiscard]] Point eval(double t) const;

    // The k-th derivative B^(k)(t) (k = 0 is B itself); zero once k exceeds the degree.
    [[nodiscard]] Point derivative(double t, int order = 1) const;

    // The k-th hodograph: the derivative as a Bézier curve of degree n - k, with control points
    // n(n-1)…(n-k+1) Δ^k c_i (seed 004: end tangents n(P1 - P0)). A single point when k = n.
    [[nodiscard]] Bezier derivativeCurve(int order = 1) const;

    // All levels of the de Casteljau construction at t: level 0 is the control polygon, level k
    // has n + 1 - k points, the last level is the single point B(t) (for the teaching view, seed 004).
    [[nodiscard]] std::vector<std::vector<Point>> deCasteljau(double t) const;

    // The two halves of the curve at t, from the sides of the de Casteljau triangle.
    [[nodiscard]] std::pair<Bezier, Bezier> split(double t) const;

    // The part of the curve over [t0, t1], reparameterized to [0, 1]; reversed when t0 > t1.
    [[nodiscard]] Bezier subCurve(double t0, double t1) const;

    // The same curve with degree n + r (seed 002, corrected in docs/requirements.md 3):
    // b_i^(r) = Σ_j C(n,j) C(r,i-j) / C(n+r,i) · b_j, which equals r single elevations.
    [[nodiscard]] Bezier elevated(int r = 1) const;

    // The curve of degree n - 1 whose once-elevated polygon is closest to this polygon in the least
    // squares sense (Farin ch. 6.9), solved by Householder QR. Exact for a curve that was elevated.
    [[nodiscard]] Bezier reduced() const;

    // The same curve traversed from the end to the start (symmetry of the Bernstein basis).
    [[nodiscard]] Bezier reversed() const;

    // The image under x ↦ A x + b; Bézier curves are affinely invariant, so mapping the control
    // points maps the curve (seed 004).
    [[nodiscard]] Bezier transformed(const Eigen::Matrix2d &linear, const Point &translation) const;
    [[nodiscard]] Bezier transformed(const Eigen::Affine2d &map) const;

    // The tight axis-aligned bounding box: the end points and the curve at every root of x'(t) and
    // y'(t) in (0, 1), found by the Bernstein root finder (never the looser control-polygon box).
    [[nodiscard]] Box boundingBox() const;

    // Signed curvature κ(t) = (x'y'' - y'x'') / |B'|³ (positive turning left). Where the speed is
    // zero (a cusp or a handle on its knot) κ is undefined; 0 is returned rather than NaN.
    [[nodiscard]] double curvature(double t) const;

    // Parameters in (0, 1) where the curvature changes sign: the roots of x'y'' - y'x'', a Bernstein
    // polynomial of degree 2n - 3. A straight curve has none.
    [[nodiscard]] std::vector<double> inflections() const;

private:
    std::vector<Point> m_points;
};

// The cubic in matrix form B(t) = T·M·C with T = (1, t, t², t³) and the corrected
// M = [[1,0,0,0],[-3,3,0,0],[3,-6,3,0],[-1,3,-3,1]] (docs/requirements.md 1.2; the seed misprints rows 3 and 4).
[[nodiscard]] Point evalCubicMatrix(const std::array<Point, 4> &c, double t);

// The straight segment from `a` to `b` as a cubic: its handles at a third and two thirds of the way,
// so that its parameter runs at a constant speed (t is the fraction of the length). A traced line, an
// offset's straight join, a segment made straight by an edit.
[[nodiscard]] Bezier straightCubic(const Point &a, const Point &b);

// Quadratic → cubic (seed 004): (P0, P0 + 2/3 (P1 - P0), P2 + 2/3 (P1 - P2), P2), the same curve.
[[nodiscard]] Bezier quadraticToCubic(const Point &p0, const Point &p1, const Point &p2);

// Appends to `out` a polyline that stays within `tolerance` of the curve (same units as the
// control points), starting with the curve's first point unless `out` already ends there.
// Subdivides at t = 1/2 until every interior control point lies within `tolerance` of the chord;
// since the curve lies in the convex hull of its control polygon, that bounds its distance to the chord.
// A tolerance that is not positive and finite falls back to 0.25 (a quarter pixel).
void flatten(const Bezier &curve, double tolerance, std::vector<Point> &out);

} // namespace kontur::geo
