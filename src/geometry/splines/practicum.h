// The splines of seed 003 (Russian practicum, docs/requirements.md 4), exactly as the practicum computes them:
// KG-202's single cubic segment between two points with end conditions from guide vectors (the
// non-parametric y(x) form, formulas 1–4, and the parametric form over the chord length, 8–16), and
// KG-203's multi-segment parametric spline: chord-length segments T_j, unit guide-vector tangents
// K_0 and K_n, right-hand sides (17)–(18) and the sweep method. (KG-203 is the clamped spline with
// chord-length parameters; the tests check it against cubicSpline(…, Clamped, ChordLength, …).)
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"
#include "geometry/splines/hermite.h"

#include <span>
#include <vector>

namespace kontur::geo {

// KG-202, non-parametric: y = y0 + k0 x + a3 x² + a4 x³ for x in [0, t], t = x1 - x0, drawn at x0 + x;
// k0, k1 = dy/dx of the guide vectors, a3 = 3(y1 - y0)/t² - (2k0 + k1)/t, a4 = 2(y0 - y1)/t³ + (k0 + k1)/t².
struct PracticumFunctionSegment
{
    double x0 = 0, y0 = 0, t = 1, k0 = 0, k1 = 0, a3 = 0, a4 = 0;
    // y at the local x in [0, t] (Horner, formula 4).
    [[nodiscard]] double value(double x) const { return y0 + (k0 + (a3 + a4 * x) * x) * x; }
    // The graph over [x0, x0 + t] as a cubic Bézier (x linear in its parameter).
    [[nodiscard]] Bezier toBezier() const;
};
// Errors: x1 = x0, a vertical or zero guide vector (no slope dy/dx), non-finite input.
[[nodiscard]] Result<PracticumFunctionSegment> practicumFunctionSegment(const Point &p0, const Point &p1,
                                                                        const Point &guide0, const Point &guide1);

// KG-202, parametric: P(t) = P0 + P0' t + a3 t² + a4 t³, t in [0, t2], t2 = |P1 - P0| (the chord),
// P0', P1' the unit guide vectors, a3 = 3(P1 - P0)/t2² - (2P0' + P1')/t2, a4 = 2(P0 - P1)/t2³ + (P0' + P1')/t2².
struct PracticumParametricSegment
{
    Point p0 = Point::Zero(), k0 = Point::Zero(), k1 = Point::Zero(), a3 = Point::Zero(), a4 = Point::Zero();
    double t2 = 1;
    [[nodiscard]] Point value(double t) const { return p0 + (k0 + (a3 + a4 * t) * t) * t; }
    [[nodiscard]] Bezier toBezier() const;
};
// Errors: P0 = P1, a zero guide vector, non-finite input.
[[nodiscard]] Result<PracticumParametricSegment> practicumParametricSegment(const Point &p0, const Point &p1,
                                                                            const Point &guide0, const Point &guide1);

// KG-203 with the practicum's arrays (index 0..n, n = m - 1 segments), for its debug view:
// T[j] = |P_j - P_{j-1}| (T[0] unused, 0), B[i] for i = 1..n-1 (B[0] = B[n] = 0), K[i] the tangents.
struct PracticumSpline
{
    std::vector<double> T;
    std::vector<Point> B;
    std::vector<Point> K;
    HermiteSpline spline; // segment j over the chord parameter: P_j, P_{j+1}, K_j, K_{j+1}, length T_{j+1}
};
// Debug oracle (KG-203 §3.3): 4 points with step (30, 20) and guide vectors along it give
// T = 36.055, B_1 = B_2 = (180, 120), K_0..K_3 = (0.832, 0.554). Errors: fewer than 2 points,
// coincident consecutive points, a zero guide vector.
[[nodiscard]] Result<PracticumSpline> practicumSpline(std::span<const Point> points, const Point &guideStart,
                                                      const Point &guideEnd);

} // namespace kontur::geo
