// B-splines of order k (degree k - 1, 2 <= k <= 10) over a knot vector (seed 003 KG-205, seed 001
// §1.1; docs/requirements.md 2, 4): open uniform, uniform or user knots; basis functions by Cox–de Boor with
// half-open intervals (the seeds' closed base case counts an interior knot twice), evaluation by de
// Boor's algorithm, knot insertion (Boehm), exact conversion to Bézier pieces (blossoming), and seed
// 001's scaled "bell" functions Bs^{n,p}. Notation: n control points P_0..P_{n-1}, knots t_0..t_{n+k-1},
// the curve lives on [t_{k-1}, t_n] (de Boor, "A Practical Guide to Splines"; Piegl & Tiller, "The
// NURBS Book", ch. 2–5).
#pragma once

#include "geometry/bezier.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"

#include <span>
#include <string_view>
#include <vector>

namespace kontur::geo {

inline constexpr int kMinBSplineOrder = 2;
inline constexpr int kMaxBSplineOrder = 10;

// Checks a knot vector for n control points of order k: n + k finite values, nondecreasing, no value
// repeated more than k times, and a domain [t_{k-1}, t_n] of positive length. Errors name the knot.
[[nodiscard]] Result<Ok> checkKnotVector(std::span<const double> knots, int order, int controlPointCount);

// Seed 003 KG-205: k zeros, 1, 2, …, then k copies of t_max = n - k + 1 (m = 8 points, k = 4:
// 0000 1 2 3 4 5555). Clamped ends: the curve starts and ends at the end control points.
[[nodiscard]] Result<std::vector<double>> openUniformKnots(int controlPointCount, int order);
// Uniform (seed 001's bells): start, start + step, …, n + k values; the curve does not reach the ends.
[[nodiscard]] Result<std::vector<double>> uniformKnots(int controlPointCount, int order, double start = 0.0,
                                                       double step = 1.0);

enum class KnotKind { OpenUniform, Uniform };
[[nodiscard]] const char *nameOf(KnotKind k);

// N_{i,k}(t) by the Cox–de Boor recursion with half-open base intervals [t_j, t_{j+1}); at the last
// knot the last nonempty interval is closed, so the basis is a partition of unity on the whole
// domain. 0 for an index out of range.
[[nodiscard]] double basisFunction(std::span<const double> knots, int i, int order, double t);

// The p + 1 = order nonzero basis functions N_{span-p..span} at t, for the knot span `span`
// (Piegl & Tiller A2.2). Outside [t_span, t_{span+1}] these are the same polynomial pieces, extended.
void nonzeroBasis(std::span<const double> knots, int span, int order, double t, std::span<double> out);
// The same values and their first derivatives from one triangle: the last level's ratios
// N_{i,p-1}/(t_{i+p} - t_i) give N'_{i,p} = p (ratio_i - ratio_{i+1}) (de Boor).
void nonzeroBasisWithDerivatives(std::span<const double> knots, int span, int order, double t, std::span<double> values,
                                 std::span<double> derivatives);

class BSpline final
{
public:
    BSpline() = default;
    // Errors: order outside 2..10, fewer control points than the order, a bad knot vector
    // (checkKnotVector), non-finite control points.
    [[nodiscard]] static Result<BSpline> create(int order, std::vector<double> knots, std::vector<Point> controlPoints);
    // The B-spline with the control polygon `points` over open uniform or uniform knots.
    [[nodiscard]] static Result<BSpline> create(int order, KnotKind kind, std::vector<Point> controlPoints);

    [[nodiscard]] int order() const { return m_order; }
    [[nodiscard]] int degree() const { return m_order - 1; }
    [[nodiscard]] int controlPointCount() const { return static_cast<int>(m_points.size()); }
    [[nodiscard]] const std::vector<double> &knots() const { return m_knots; }
    [[nodiscard]] const std::vector<Point> &controlPoints() const { return m_points; }
    [[nodiscard]] double startParameter() const;
    [[nodiscard]] double endParameter() const;

    // The knot span μ (k - 1 <= μ <= n - 1, t_μ <= t < t_{μ+1}, nonempty) used for t; t is clamped
    // to the domain, and the domain end belongs to the last nonempty span.
    [[nodiscard]] int spanOf(double t) const;
    // C(t) by de Boor's algorithm (t clamped to the domain).
    [[nodiscard]] Point eval(double t) const;
    // The r-th derivative (r > degree gives zero), from the derivative B-spline's control points.
    [[nodiscard]] Point derivative(double t, int r = 1) const;
    // The derivative as a B-spline of order k - 1 on the knots without the first and last (k >= 3).
    [[nodiscard]] Result<BSpline> derivativeCurve() const;
    // All n basis values N_{i,k}(t), i = 0..n-1, for plotting (Cox–de Boor; t anywhere in the knots).
    [[nodiscard]] std::vector<double> basisValues(double t) const;

    // The same curve with the knot t inserted `times` times (Boehm's algorithm), as long as its
    // multiplicity stays <= order - 1 and t lies inside the domain.
    [[nodiscard]] Result<BSpline> withKnotInserted(double t, int times = 1) const;

    // The Bézier piece of degree k - 1 on each nonempty knot span of the domain, by blossoming:
    // b_j = P[t_μ (p - j times), t_{μ+1} (j times)] (Ramshaw; de Boor's algorithm with varying
    // arguments). Piece j runs over [t_μ, t_{μ+1}]; `spanParameters` gets those bounds when given.
    [[nodiscard]] std::vector<Bezier> bezierPieces(std::vector<double> *spanParameters = nullptr) const;
    [[nodiscard]] PiecewiseBezier toPiecewise() const;

private:
    int m_order = 0;
    std::vector<double> m_knots;
    std::vector<Point> m_points;
};

// --- seed 001: "bell" functions and the function B-spline over knots v_0..v_{K-1} ---

// The scale prod_{m=j+1}^{j+n} (v_{j+n+1} - v_m) (docs/requirements.md 2; 6 for unit-spaced cubic knots).
[[nodiscard]] double bellScale(std::span<const double> v, int j, int degree);
// Bs^{n,p}_{v_j..v_{j+n+1}}(x): the piece of the normalised B-spline N_{j,n+1} (degree n) on
// [v_{j+n+1-p}, v_{j+n+2-p}], scaled by bellScale (the consistent reading of the seed's (1.2),
// docs/requirements.md 2). 1 <= p <= n + 1; x outside that interval extends the piece's polynomial.
[[nodiscard]] Result<double> bell(std::span<const double> v, int j, int degree, int p, double x);
// The seed's function B-spline P(x) = Σ c_i Bs_i(x) (scaled bells, degree n) over strictly
// increasing knots v, as a 2D BSpline whose control points are (Greville abscissa, c_i · scale_i):
// x(t) = t exactly, so the curve is the graph of P over [v_n, v_{K-1-n}]. Needs K = c.size() + n + 1.
[[nodiscard]] Result<BSpline> bellSpline(std::span<const double> v, std::span<const double> c, int degree = 3);

} // namespace kontur::geo
