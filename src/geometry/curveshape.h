// The kinds of curve Kontur knows and the one way from a curve's defining parts to the Bézier
// segments that draw it. The app's document (models/curve) and the headless file layer (src/io,
// kontur-cli) both build shapes here, so a record draws the same everywhere and a new kind is added
// in one place.
#pragma once

#include "geometry/bezier.h"
#include "geometry/fit.h"
#include "geometry/parameterization.h"
#include "geometry/piecewise.h"
#include "geometry/result.h"
#include "geometry/splines/hermite.h"

#include <optional>
#include <string_view>
#include <vector>

namespace kontur::geo {

// The kinds of curve (docs/requirements.md 1.2 with the seed's names in comments, and the spline families of
// docs/requirements.md 2 and 4). Files store a kind by its id (kindId), never by number.
enum class CurveKind {
    Bezier,         // <4 cPoints>, generalised: control points of any degree
    Interpolating,  // <4 pPoints>: the cubic through exactly 4 knots
    LeastSquares,   // <Least Squares>: the cubic closest to n >= 4 knots
    Composite,      // <Composite>: one cubic per pair of knots, tangent continuous (G1)
    NaturalSpline,  // C² through the knots, zero second derivative at the ends
    ClampedSpline,  // C² with given end tangents (guide vectors, seed 003; d_0, d_{k-1}, seed 001)
    NotAKnotSpline, // C² with a continuous third derivative at the second and last-but-one knots
    PeriodicSpline, // closed, C² everywhere
    CatmullRom,     // C¹ Hermite spline with Catmull–Rom tangents
    HermiteSpline,  // C¹ with a tangent at every knot, each editable (seed 001 H-spline)
    BSpline,        // B-spline of order k over the control polygon, open uniform knots (seed 003 KG-205)
    GlobalBSpline,  // the interpolating cubic B-spline with end derivatives (seed 001 §1.2)
    Polynomial,     // the interpolating polynomial, for the Runge comparison (seed 001)
    FunctionSpline, // natural spline y(x) over increasing x (seed 001's function splines)
    Contour,        // Bézier pieces joined at the midpoints of point pairs (seed 004)
};
inline constexpr int kKindCount = static_cast<int>(CurveKind::Contour) + 1;

// "bezier", "interpolating", "least-squares", "composite", "natural", … as written in files and
// taken by kontur-cli.
[[nodiscard]] const char *kindId(CurveKind kind);
[[nodiscard]] std::optional<CurveKind> kindFromId(std::string_view id);

// The two kinds whose control points follow from a cubic fit of the knots.
[[nodiscard]] bool isFittedKind(CurveKind kind);
// The kinds with a tangent end at the first and the last knot (guide vectors).
[[nodiscard]] bool hasEndTangents(CurveKind kind);
// The kinds with one tangent end per knot.
[[nodiscard]] bool hasKnotTangents(CurveKind kind);
// A B-spline's order when none is given: cubic, or as high as the control points allow.
[[nodiscard]] int defaultOrder(std::size_t controlPoints);

// Everything but a composite curve (CompositeCurve holds its own parts): the placed points (control
// points or knots), the tangent ends of the kinds with tangents, the B-spline order and the
// parameterization of the kinds that use one.
struct CurveParts
{
    CurveKind kind = CurveKind::Bezier;
    std::vector<Point> points;
    std::vector<Point> tangentEnds;
    int order = 4;
    Parameterization parameterization = Parameterization::Uniform;
};

// The tangent ends a new curve of `kind` starts with: for the clamped kinds the end chords' thirds
// (seed 003's guide vectors), for the Hermite spline each knot's Catmull–Rom tangent as the Bézier
// handle it gives; none for the other kinds.
[[nodiscard]] std::vector<Point> defaultTangentEnds(CurveKind kind, const std::vector<Point> &points,
                                                    Parameterization parameterization);

// The derivatives by the spline parameter `s` that the tangent ends stand for. A tangent end is the
// Bézier handle its tangent gives: E = P + h·m/3 over the parameter step h next to the knot, so
// m = 3 (E − P) / h.
[[nodiscard]] std::vector<Point> tangentsFromEnds(const CurveParts &parts, const std::vector<double> &s);

// What a curve's parts give: the segments, and what the kind keeps besides them (the fit of the
// fitted kinds, the Hermite form of the Hermite-form splines, for editing and the basis plot).
struct CurveShape
{
    std::optional<Bezier> single;         // Bézier and the fitted kinds: one segment
    std::optional<HermiteSpline> hermite; // natural, clamped, not-a-knot, periodic, Catmull–Rom, Hermite, y(x)
    std::vector<Bezier> pieces;           // B-spline, global B-spline, polynomial, contour
    std::optional<CubicFit> fit;          // interpolating and least-squares
    bool closed = false;                  // the periodic spline

    [[nodiscard]] int segmentCount() const;
    [[nodiscard]] Bezier segment(int i) const;
    [[nodiscard]] PiecewiseBezier toPiecewise() const;
    // Every control point of every segment is finite (checked in place, no segment is built: this
    // runs on every drag step).
    [[nodiscard]] bool allFinite() const;
};

// Builds the shape of a curve that is not composite. A Bézier curve with fewer than 2 control points
// has no segment (an empty shape, not an error: it is being placed). Errors: the kind's geometry
// refuses the points (too few, coincident, non-finite, …), a composite kind (InvalidArgument), tangent
// ends that do not match the kind.
[[nodiscard]] Result<CurveShape> buildShape(const CurveParts &parts);

} // namespace kontur::geo
