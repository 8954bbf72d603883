// Parameter values for splines through points, unnormalised (issue 4): uniform gives 0, 1, 2, …,
// chord length the cumulative chord length, centripetal the cumulative square roots of the chords.
// The normalised values of docs/requirements.md 1.3 are geo::parameterize (parameterization.h); these are the
// same sums before the division, which spline derivatives and the CLI report in the input's units.
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/result.h"

#include <span>
#include <vector>

namespace kontur::geo {

// s_0 = 0, s_i = s_{i-1} + |p_i - p_{i-1}|^α. With `closed`, one more value: the step from the last
// point back to the first. Errors: fewer than 2 points (3 when closed), a non-finite coordinate, all
// points equal, and two consecutive points that coincide (a spline through them would need a
// repeated parameter or a stationary point), for every parameterization.
[[nodiscard]] Result<std::vector<double>> splineParameters(std::span<const Point> points, Parameterization p,
                                                           bool closed = false);
// The same when scaleExponent(points) is known (it is a pass over the points).
[[nodiscard]] Result<std::vector<double>> splineParameters(std::span<const Point> points, Parameterization p,
                                                           bool closed, int exponent);
// Chord-length parameters as splineParameters(points, ChordLength, closed), bit for bit, and
// scaleExponent(points) in `exponent`, in one pass over the points where that is exact (coordinates
// within 2^±200, the spline's direct range; else the two passes).
[[nodiscard]] Result<std::vector<double>> chordParameters(std::span<const Point> points, bool closed, int &exponent);

// Checks that `values` strictly increase and are finite (knots of a function spline y(x), user
// parameters). `what` names them in the message ("x", "parameter").
[[nodiscard]] Result<Ok> checkStrictlyIncreasing(std::span<const double> values, const char *what);

// The spline builders are exact under scaling, but their systems square parameter steps (overflow
// above ~1e154, underflow below ~1e-162): they run on the points scaled to unit size by 2^-exponent
// and scale the result back. The exponent is even, so that every parameterization's parameters
// scale by an exact power of two: 2^paramExponent (chord: the exponent, centripetal: half of it,
// uniform: 0); derivatives with respect to them by 2^(exponent - paramExponent).
struct UnitScale
{
    int exponent = 0;
    int paramExponent = 0;
    [[nodiscard]] int tangentExponent() const { return exponent - paramExponent; }
    [[nodiscard]] bool identity() const { return exponent == 0 && paramExponent == 0; }
    // The points times 2^-exponent.
    [[nodiscard]] std::vector<Point> down(std::span<const Point> points) const;
};
[[nodiscard]] UnitScale unitScale(std::span<const Point> points, Parameterization p);
// The same from scaleExponent(points).
[[nodiscard]] UnitScale unitScale(int exponent, Parameterization p);
// For given parameters: the points and the parameters each scaled to unit size, independently.
[[nodiscard]] UnitScale unitScale(std::span<const Point> points, std::span<const double> parameters);
// The parameters times 2^-paramExponent.
[[nodiscard]] std::vector<double> downParameters(std::span<const double> parameters, const UnitScale &scale);
// Values times 2^e; NonFiniteInput when one is too large for doubles (a result not representable).
[[nodiscard]] Result<Ok> scaleBack(std::span<Point> values, int e);
[[nodiscard]] Result<Ok> scaleBack(std::span<double> values, int e);

// Checks that every coordinate is finite.
[[nodiscard]] Result<Ok> checkFinite(std::span<const Point> points);

// The inputs of an interpolant through points at given parameters: the parameters strictly increase
// and are finite (checkStrictlyIncreasing), then the points are finite (checkFinite).
[[nodiscard]] Result<Ok> checkParametersAndPoints(std::span<const double> parameters, std::span<const Point> points);

} // namespace kontur::geo
