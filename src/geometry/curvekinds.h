// The kinds of curve Kontur knows and the one table of their geometric facts: how many points
// define one, what the points are, which tangents and settings it takes, its id in files and
// kontur-cli. Everything that asks "which kinds …?" reads the table; the translated names are in
// models/document/kindnames.cpp, the shapes in curveshape.cpp (see docs/architecture.md, "Adding
// a curve kind").
#pragma once

#include "geometry/splines/polynomial.h"

#include <array>
#include <optional>
#include <string_view>

namespace kontur::geo {

// The kinds of curve (docs/requirements.md 1.2 with the seed's names in comments, and the spline families of
// docs/requirements.md 2 and 4). Files store a kind by its id (KindTraits::id), never by number.
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
// The last kind: a new kind goes after it, and this names the new one.
inline constexpr CurveKind kLastKind = CurveKind::Contour;
inline constexpr int kKindCount = static_cast<int>(kLastKind) + 1;

// The most defining points of a kind that has no limit of its own (as many as a file holds of one
// curve, io::kMaxCurvePoints).
inline constexpr int kManyPoints = 1'000'000;

// Which tangents a kind takes besides its points, each as a tangent end (the Bézier handle it gives).
enum class KindTangents {
    None,
    AtEnds,      // at the first and the last knot (guide vectors)
    AtEveryKnot, // one per knot, each editable
};

// What is true of every curve of a kind. Each entry names its fields (designated initialisers); a
// field left out is false, or None.
struct KindTraits
{
    CurveKind kind;
    const char *id;     // as written in files and taken by kontur-cli: "bezier", "least-squares", …
    int minPoints;      // fewest defining points (a composite curve's knots)
    int maxPoints;      // most defining points (documented in README)
    int placementCount; // points that finish a placement by themselves; 0: open-ended ("Done")
    // The points are control points the curve follows (drawn as its control polygon); else knots
    // (a composite curve has knots and handles of its own).
    bool controlPolygon = false;
    bool usesParameterization = false; // the spline parameter of the points follows a parameterization
    bool fitted = false;               // a cubic fitted to the knots, its control points derived (not editable)
    KindTangents tangents = KindTangents::None;
    bool closed = false;         // closed by its kind, the closing segment from the last knot to the first
    bool functionForm = false;   // may be read as the graph of y(x) (CurveParts::function)
    bool knotParameters = false; // each point has a parameter of the curve (knotParameters); else the
                                 // curve has its own (a knot vector, one per piece, 0 and 1)
    bool takesOrder = false;     // a B-spline order k and a knot vector
    bool knotToKnot = false;     // one segment between each two consecutive knots (seam lengths)
    bool hermiteForm = false;    // the segments are cubic Hermite pieces (the basis plot's Hermite bases)
};

// clang-format off: one kind per entry, its facts on the lines that follow
inline constexpr std::array<KindTraits, kKindCount> kKinds{{
    // Degree up to 100, as far as seed 002's demonstration elevates; 4 points place a cubic.
    {.kind = CurveKind::Bezier,
     .id = "bezier",
     .minPoints = 2,
     .maxPoints = 101,
     .placementCount = 4,
     .controlPolygon = true},
    {.kind = CurveKind::Interpolating,
     .id = "interpolating",
     .minPoints = 4,
     .maxPoints = 4,
     .placementCount = 4,
     .usesParameterization = true,
     .fitted = true},
    {.kind = CurveKind::LeastSquares,
     .id = "least-squares",
     .minPoints = 4,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .fitted = true},
    {.kind = CurveKind::Composite,
     .id = "composite",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .knotToKnot = true},
    {.kind = CurveKind::NaturalSpline,
     .id = "natural",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::ClampedSpline,
     .id = "clamped",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .tangents = KindTangents::AtEnds,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::NotAKnotSpline,
     .id = "not-a-knot",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::PeriodicSpline,
     .id = "periodic",
     .minPoints = 3,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .closed = true,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::CatmullRom,
     .id = "catmull-rom",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::HermiteSpline,
     .id = "hermite",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .tangents = KindTangents::AtEveryKnot,
     .functionForm = true,
     .knotParameters = true,
     .knotToKnot = true,
     .hermiteForm = true},
    {.kind = CurveKind::BSpline,
     .id = "bspline",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .controlPolygon = true,
     .takesOrder = true},
    {.kind = CurveKind::GlobalBSpline,
     .id = "global-bspline",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .tangents = KindTangents::AtEnds,
     .functionForm = true,
     .knotParameters = true},
    {.kind = CurveKind::Polynomial,
     .id = "polynomial",
     .minPoints = 2,
     .maxPoints = kMaxPolynomialPoints,
     .placementCount = 0,
     .usesParameterization = true,
     .functionForm = true,
     .knotParameters = true},
    // The natural spline read as y(x): its parameter is x, so no parameterization applies.
    {.kind = CurveKind::FunctionSpline,
     .id = "function-spline",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .functionForm = true,
     .knotParameters = true,
     .hermiteForm = true},
    {.kind = CurveKind::Contour,
     .id = "contour",
     .minPoints = 2,
     .maxPoints = kManyPoints,
     .placementCount = 0,
     .controlPolygon = true},
}};
// clang-format on

// The table covers every kind, each in its place.
static_assert(kKinds.size() == kKindCount);
static_assert(
    [] {
        for (int k = 0; k < kKindCount; ++k) {
            const KindTraits &t = kKinds[static_cast<std::size_t>(k)];
            if (static_cast<int>(t.kind) != k || t.id == nullptr || t.id[0] == '\0' || t.minPoints < 2 ||
                t.maxPoints < t.minPoints || (t.placementCount != 0 && t.placementCount < t.minPoints) ||
                t.placementCount > t.maxPoints)
                return false;
        }
        return true;
    }(),
    "every kind has its entry, in the enum's order, with an id and minPoints <= maxPoints");

[[nodiscard]] constexpr const KindTraits &traitsOf(CurveKind kind)
{
    return kKinds[static_cast<std::size_t>(kind)];
}

// "bezier", "interpolating", "least-squares", "composite", "natural", … as written in files and
// taken by kontur-cli.
[[nodiscard]] constexpr const char *kindId(CurveKind kind)
{
    return traitsOf(kind).id;
}
[[nodiscard]] std::optional<CurveKind> kindFromId(std::string_view id);

// The two kinds whose control points follow from a cubic fit of the knots.
[[nodiscard]] constexpr bool isFittedKind(CurveKind kind)
{
    return traitsOf(kind).fitted;
}
// The kinds with a tangent end at the first and the last knot (guide vectors).
[[nodiscard]] constexpr bool hasEndTangents(CurveKind kind)
{
    return traitsOf(kind).tangents == KindTangents::AtEnds;
}
// The kinds with one tangent end per knot.
[[nodiscard]] constexpr bool hasKnotTangents(CurveKind kind)
{
    return traitsOf(kind).tangents == KindTangents::AtEveryKnot;
}

} // namespace kontur::geo
