// Cubic Bézier curves through or near points (seed 000 §3.1.3–3.1.7, docs/requirements.md 1.2): the cubic through
// exactly 4 knots and the least-squares ("closest") cubic through n >= 4 knots.
#pragma once

#include "geometry/bezier.h"
#include "geometry/parameterization.h"
#include "geometry/result.h"

#include <array>
#include <span>
#include <vector>

namespace kontur::geo {

struct FitOptions
{
    // Exponent of the parameterization (0 uniform, 0.5 centripetal, 1 chord length).
    double alpha = 1.0;
    // Rounds of parameter correction after the seed's fit (Hoschek 1988): each point's parameter is
    // moved by Newton steps to its foot point on the current curve, then the curve is refitted;
    // a round is kept only when it lowers the RMS. 0, the default, reproduces the seed exactly.
    int reparameterizeIterations = 0;
    // The seed's UI treats coincident consecutive knots as an input error; long traced or scanned
    // point lists may repeat points harmlessly, so a caller can allow them (they share a parameter).
    bool allowCoincidentPoints = false;
};

struct CubicFit
{
    std::array<Point, 4> control;
    std::vector<double> params; // s_i, one per input point
    double rms = 0.0;           // sqrt(Σ |B(s_i) - p_i|² / n)
    double maxError = 0.0;      // max |B(s_i) - p_i|: distances at the fitted parameters
    int iterations = 0;         // parameter-correction rounds that were kept

    [[nodiscard]] Bezier curve() const { return Bezier({control.begin(), control.end()}); }
};

// The least-squares cubic: C minimises Σ |B(s_i) - p_i|² (docs/requirements.md 1.2; the seed's
// C = M⁻¹ (SᵀS)⁻¹ SᵀP). Solved directly in the Bernstein basis (rows B_j(s_i), which equal S·M), and
// a million points need no n×4 matrix in memory: by the corrected semi-normal equations (the 4×4
// Gram matrix of the Bernstein columns from one pass, Cholesky, and one step of refinement on the
// residuals where the condition of B calls for it; Björck 1987), and for an ill-conditioned B by a
// streaming Householder QR of the n×6 matrix [B | x | y] (a tall-skinny QR), whose error grows only
// with the conditioning of B, not of BᵀB (see fit.cpp).
// Errors: fewer than 4 points, non-finite input, all points equal, coincident consecutive points
// (unless allowed), fewer than 4 distinct parameters, or a numerically rank-deficient system.
[[nodiscard]] Result<CubicFit> fitCubic(std::span<const Point> points, const FitOptions &options = {});
[[nodiscard]] Result<CubicFit> fitCubic(std::span<const Point> points, Parameterization p);

// The least-squares cubic for given parameters (any order, need not start at 0 or end at 1).
[[nodiscard]] Result<CubicFit> fitCubicWithParams(std::span<const Point> points, std::vector<double> params);

// The cubic through exactly 4 knots (docs/requirements.md 1.2, `<4 pPoints>`): the same solver, residual 0.
[[nodiscard]] Result<CubicFit> interpolateCubic(std::span<const Point> points, Parameterization p);
[[nodiscard]] Result<CubicFit> interpolateCubic(std::span<const Point> points, double alpha);

namespace detail {
// fitCubicWithParams by the streaming QR alone: the reference the faster solver is tested against.
[[nodiscard]] Result<CubicFit> fitCubicWithParamsQr(std::span<const Point> points, std::vector<double> params);
} // namespace detail

} // namespace kontur::geo
