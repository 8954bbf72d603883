// The cubic Hermite spline: a value and a first derivative at every knot, one cubic per knot
// interval (seed 001 §1.3 with the corrected basis of docs/requirements.md 2; C¹ in general). It is also the
// common form of every interpolating cubic here (natural, clamped, not-a-knot, periodic, the
// practicum's, Catmull–Rom): they differ only in how the derivatives are chosen. Converts exactly to
// PiecewiseBezier: on [s_i, s_{i+1}] with h = s_{i+1} - s_i the control points are
// p_i, p_i + h m_i / 3, p_{i+1} - h m_{i+1} / 3, p_{i+1}.
// A function spline y(x) is the same object with points (x_i, y_i), parameters x_i and tangents
// (1, y'_i): its x(u) is then exactly u, so the 2D curve is the graph.
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"
#include "geometry/splines/knots.h"

#include <array>
#include <span>
#include <vector>

namespace kontur::geo {

// Where a global parameter falls: the segment and the local parameter t in [0, 1] of its Bézier piece.
struct SplineLocation
{
    int segment = 0;
    double t = 0.0;
};

class HermiteSpline final
{
public:
    HermiteSpline() = default;

    // `parameters` strictly increasing, one per point (open) or one more than the points (closed: the
    // last segment runs from the last point back to the first over [s_{n-1}, s_n]). Tangents are
    // derivatives with respect to the parameter. Errors: too few points, mismatched sizes,
    // non-increasing parameters, non-finite values.
    [[nodiscard]] static Result<HermiteSpline> create(std::vector<double> parameters, std::vector<Point> points,
                                                      std::vector<Point> tangents, bool closed = false);
    // The same without the checks, for the builders in this directory whose input is already checked
    // (a million-point spline would otherwise read everything twice more).
    [[nodiscard]] static HermiteSpline fromChecked(std::vector<double> parameters, std::vector<Point> points,
                                                   std::vector<Point> tangents, bool closed);
    // The function spline y(x) with values y_i and slopes d_i at strictly increasing x_i (seed 001).
    [[nodiscard]] static Result<HermiteSpline> function(std::span<const double> x, std::span<const double> y,
                                                        std::span<const double> slopes);

    [[nodiscard]] int pointCount() const { return static_cast<int>(m_points.size()); }
    [[nodiscard]] int segmentCount() const;
    [[nodiscard]] bool isClosed() const { return m_closed; }
    [[nodiscard]] const std::vector<double> &parameters() const { return m_params; }
    [[nodiscard]] const std::vector<Point> &points() const { return m_points; }
    [[nodiscard]] const std::vector<Point> &tangents() const { return m_tangents; }
    [[nodiscard]] double startParameter() const { return m_params.empty() ? 0.0 : m_params.front(); }
    [[nodiscard]] double endParameter() const { return m_params.empty() ? 0.0 : m_params.back(); }

    // Editing (the Hermite family's tangents are editable; the other families rebuild instead).
    Result<Ok> setTangent(int index, const Point &tangent);
    Result<Ok> setPoint(int index, const Point &point);

    // The segment containing u (clamped to the parameter range; binary search) and its local t.
    [[nodiscard]] SplineLocation locate(double u) const;
    // The curve and its derivatives (order 1..3) with respect to the global parameter u.
    [[nodiscard]] Point eval(double u) const;
    [[nodiscard]] Point derivative(double u, int order = 1) const;
    // For a function spline: y(x).
    [[nodiscard]] double functionValue(double x) const { return eval(x).y(); }
    // The curve at nondecreasing parameters `u` (one walk through the segments, O(n + m)); out.size()
    // must equal u.size(). Unsorted input still gives correct values, only slower.
    void evalSorted(std::span<const double> u, std::span<Point> out) const;

    [[nodiscard]] std::array<Point, 4> segmentControlPoints(int segment) const;
    [[nodiscard]] Bezier segment(int segment) const;
    // All Bézier control points in one array: 3·segmentCount() + 1 points, segment i is [3i, 3i + 3].
    [[nodiscard]] std::vector<Point> bezierControlPoints() const;
    [[nodiscard]] PiecewiseBezier toPiecewise() const;

private:
    std::vector<double> m_params;
    std::vector<Point> m_points;
    std::vector<Point> m_tangents;
    bool m_closed = false;
};

// A spline built on points scaled by `scale` (knots.h), scaled back onto the original `points`.
[[nodiscard]] Result<HermiteSpline> scaledBack(const HermiteSpline &unit, const UnitScale &scale,
                                               std::span<const Point> points);

// --- default tangents for a Hermite spline through points (parameters s as from splineParameters) ---

// Catmull–Rom in the Barry–Goldman form for any parameterization: the derivative at p_i of the
// parabola through p_{i-1}, p_i, p_{i+1}, m_i = (h_i δ_{i-1} + h_{i-1} δ_i) / (h_{i-1} + h_i) with
// h_i = s_{i+1} - s_i, δ_i = (p_{i+1} - p_i) / h_i. Uniform s gives the classic (p_{i+1} - p_{i-1}) / 2;
// centripetal s avoids cusps and self-intersections (Yuksel, Schaefer, Keyser 2011). Open ends take
// the derivative of that parabola at its end; closed curves wrap around (`s` has n + 1 values).
[[nodiscard]] std::vector<Point> catmullRomTangents(std::span<const double> s, std::span<const Point> p, bool closed);
// Cardinal spline: m_i = (1 - tension)(p_{i+1} - p_{i-1}) / (s_{i+1} - s_{i-1}); tension 0 is the
// uniform Catmull–Rom, 1 gives zero tangents (a polygon with stops at the knots). Ends one-sided.
[[nodiscard]] std::vector<Point> cardinalTangents(std::span<const double> s, std::span<const Point> p, double tension,
                                                  bool closed);
// Finite differences: m_i = (δ_{i-1} + δ_i) / 2, the ends δ_0 and δ_{n-2}.
[[nodiscard]] std::vector<Point> finiteDifferenceTangents(std::span<const double> s, std::span<const Point> p,
                                                          bool closed);

enum class TangentRule { CatmullRom, Cardinal, FiniteDifference };

// The Hermite spline through `points` with the given parameterization and tangent rule.
// Errors as splineParameters; a tension outside [0, 1] is InvalidArgument.
[[nodiscard]] Result<HermiteSpline> hermiteSpline(std::span<const Point> points, Parameterization param,
                                                  TangentRule rule, double tension = 0.0, bool closed = false);
// The Hermite spline through `points` with user tangents (one per point), parameterized as asked.
// A zero-length tangent is an error (the "zero-length tangents"), named by index.
[[nodiscard]] Result<HermiteSpline> hermiteSpline(std::span<const Point> points, std::span<const Point> tangents,
                                                  Parameterization param, bool closed = false);

} // namespace kontur::geo
