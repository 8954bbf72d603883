// The one way from a curve's defining parts to the Bézier segments that draw it, for every kind of
// curve (the kinds and their facts: curvekinds.h). The app's document (models/curve) and the
// headless file layer (src/io, kontur-cli) both build shapes here, so a record draws the same
// everywhere.
#pragma once

#include "geometry/bezier.h"
#include "geometry/curvekinds.h"
#include "geometry/fit.h"
#include "geometry/parameterization.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"
#include "geometry/splines/bspline.h"
#include "geometry/splines/hermite.h"
#include "geometry/splines/polynomial.h"
#include "geometry/splines/torok.h"

#include <optional>
#include <string_view>
#include <vector>

namespace kontur::geo {

// A B-spline's order when none is given: cubic, or as high as the control points allow.
[[nodiscard]] int defaultOrder(std::size_t controlPoints);

// The record of a curve that is not composite (CompositeCurve holds its own parts): everything its
// shape depends on. The app's document, the function-spline view and kontur-cli all describe a curve
// this way and build it with buildShape, so one record draws one curve everywhere.
struct CurveParts
{
    CurveKind kind = CurveKind::Bezier;
    // The placed points: control points or knots.
    std::vector<Point> points;
    // The tangent ends of the kinds with tangents: the Bézier handle each tangent gives (see
    // tangentsFromEnds). Two for the clamped spline and the global B-spline, one per knot for the
    // Hermite spline, none for the other kinds.
    std::vector<Point> tangentEnds;
    // B-spline order k.
    int order = 4;
    Parameterization parameterization = Parameterization::Uniform;
    // The graph of a function y(x) over the points' strictly increasing x (seed 001's function
    // splines): the spline's parameter is x itself, so x(u) = u, and the parameterization is not
    // used. Taken by the interpolating splines and the polynomial (not by the Bézier curve, the
    // fitted cubics, the B-spline or the contour); the FunctionSpline kind is the natural spline so.
    bool function = false;
    // A B-spline's knot vector (points + order values); empty: open uniform, the app's knots.
    std::vector<double> knotVector;
    // How the clamped spline's inner derivatives are solved: Török's half-size system needs evenly
    // spaced parameters (uniform, or evenly spaced x). Both give the same curve to rounding.
    ClampedSolver solver = ClampedSolver::Classical;
};

// The record reads its points as the graph of y(x) (the function flag or the FunctionSpline kind).
[[nodiscard]] bool isFunctionForm(const CurveParts &parts);

// The parameter of each point: its x in the function form, else splineParameters with the record's
// parameterization (for the periodic spline one more, for the closing point; a last point equal to
// the first is that closing, as in cubicSpline).
[[nodiscard]] Result<std::vector<double>> knotParameters(const CurveParts &parts);

// The tangent ends a new curve starts with (parts.tangentEnds is not read): for the clamped kinds
// the end chords' thirds (seed 003's guide vectors), for the Hermite spline each knot's Catmull–Rom
// tangent as the Bézier handle it gives; none for the other kinds.
[[nodiscard]] std::vector<Point> defaultTangentEnds(const CurveParts &parts);
[[nodiscard]] std::vector<Point> defaultTangentEnds(CurveKind kind, const std::vector<Point> &points,
                                                    Parameterization parameterization);

// The tangent ends that stand for derivatives by the spline parameter (the inverse of
// tangentsFromEnds): E = P + h·m/3. `tangents` has two entries (first and last knot) for the kinds with
// end tangents, one per knot for the Hermite spline; `s` as from knotParameters.
[[nodiscard]] std::vector<Point> endsFromTangents(const CurveParts &parts, const std::vector<double> &s,
                                                  const std::vector<Point> &tangents);

// The derivatives by the spline parameter `s` that the tangent ends stand for. A tangent end is the
// Bézier handle its tangent gives: E = P + h·m/3 over the parameter step h next to the knot, so
// m = 3 (E − P) / h.
[[nodiscard]] std::vector<Point> tangentsFromEnds(const CurveParts &parts, const std::vector<double> &s);

// What a curve's parts give: the segments, and what the kind keeps besides them (the fit of the
// fitted kinds, the Hermite form of the Hermite-form splines, for editing and the basis plot; the
// B-spline and the polynomial, for evaluating them by their own parameter).
struct CurveShape
{
    std::optional<Bezier> single;         // Bézier and the fitted kinds: one segment
    std::optional<HermiteSpline> hermite; // natural, clamped, not-a-knot, periodic, Catmull–Rom, Hermite, y(x)
    std::vector<Bezier> pieces;           // B-spline, global B-spline, polynomial, contour
    std::optional<CubicFit> fit;          // interpolating and least-squares
    std::optional<BSpline> bspline;       // B-spline, global B-spline
    std::optional<PolynomialInterpolant> polynomial; // polynomial
    bool closed = false;                             // the periodic spline

    // The values of the curve's own parameter: each knot's (the Hermite form and the polynomial; a
    // closed curve's closing one too), a B-spline's knot vector, 0, 1, …, m over a contour's m pieces,
    // 0 and 1 for a single segment.
    [[nodiscard]] std::vector<double> parameters() const;
    // The point at u of that parameter (outside its range as each form does: a B-spline and the
    // contour clamp u, the Hermite form and the polynomial extend their end pieces).
    [[nodiscard]] Point eval(double u) const;
    [[nodiscard]] int segmentCount() const;
    [[nodiscard]] Bezier segment(int i) const;
    [[nodiscard]] PiecewiseBezier toPiecewise() const;
    // Every control point of every segment is finite (checked in place, no segment is built: this
    // runs on every drag step).
    [[nodiscard]] bool allFinite() const;
};

// Builds the shape of a curve that is not composite: the one place that turns a record into its
// curve, for every kind. A Bézier curve with fewer than 2 control points has no segment (an empty
// shape, not an error: it is being placed). Errors: the kind's geometry refuses the points (too few,
// coincident, non-finite, x not increasing in the function form, …), a composite kind or a kind
// without the asked form (InvalidArgument), tangent ends that do not match the kind, a tangent end
// straight above its knot in the function form (no slope), Török's solver on uneven parameters.
[[nodiscard]] Result<CurveShape> buildShape(const CurveParts &parts);

} // namespace kontur::geo
