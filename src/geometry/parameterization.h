// Parameter values s_i for points that a curve should pass through or near (seed 000 §3.1.3–3.1.5,
// docs/requirements.md 1.3): uniform, chord length, centripetal, and the general exponent α in between.
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"

#include <cmath>
#include <span>
#include <string_view>
#include <vector>

namespace kontur::geo {

enum class Parameterization { Uniform, ChordLength, Centripetal };

// The exponent α of |p_i - p_{i-1}|^α: uniform 0, centripetal 1/2, chord length 1.
[[nodiscard]] double exponentOf(Parameterization p);
// "uniform", "chord", "centripetal" (the CLI and file format names); nullopt-like: false when unknown.
[[nodiscard]] bool parseParameterization(std::string_view name, Parameterization &out);
[[nodiscard]] const char *nameOf(Parameterization p);

// s_0 = 0, s_i = s_{i-1} + |p_i - p_{i-1}|^α / L with L the sum of all steps, so s_{n-1} = 1
// (docs/requirements.md 1.3; α = 0 gives s_i = i/(n-1)). α must lie in [0, 1].
// Errors: fewer than 2 points, a non-finite coordinate, all points equal, and — for α > 0, where a
// zero step repeats a parameter — coincident consecutive points (with the index of the second one).
// Distances are measured on the points scaled to unit size by a power of two (scaleExponent), so
// they neither overflow above ~1e154 nor underflow below ~1e-162; uniform needs no distances.
[[nodiscard]] Result<std::vector<double>> parameterize(std::span<const Point> points, double alpha);
[[nodiscard]] Result<std::vector<double>> parameterize(std::span<const Point> points, Parameterization p);
// The same when scaleExponent(points) is known (it is a pass over the points).
[[nodiscard]] Result<std::vector<double>> parameterize(std::span<const Point> points, double alpha, int exponent);

// k with max |coordinate| · 2^-k in [0.5, 2) (clamped to [-1000, 1023], so 2^±k is a double):
// multiplying by 2^-k is exact and brings the points to unit size. 0 for no or only zero points.
[[nodiscard]] int scaleExponent(std::span<const Point> points);
// |b - a| · 2^-k, for points scaled by scaleExponent: no overflow or underflow of the squares.
// Inline: it is the inner step of every parameterization of a million points.
[[nodiscard]] inline double unitDistance(const Point &a, const Point &b, double unitFactor)
{
    const double dx = unitFactor * b.x() - unitFactor * a.x();
    const double dy = unitFactor * b.y() - unitFactor * a.y();
    const double d = std::sqrt(dx * dx + dy * dy);
    // Squares below ~1e-308 are lost; hypot keeps a step that small relative to the points.
    return d > 0.0 || (dx == 0.0 && dy == 0.0) ? d : std::hypot(dx, dy);
}

} // namespace kontur::geo
