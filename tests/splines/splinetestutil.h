// Helpers shared by the spline tests: random input, relative comparisons, and the check that a
// family's Bézier pieces evaluate like the family itself (random points and printing: testutil.h).
#pragma once

#include "../geometry/testutil.h"
#include "geometry/bezier.h"
#include "geometry/piecewise.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace kontur::test {

// Strictly increasing values x_0 = start, steps in [minStep, maxStep].
inline std::vector<double> randomIncreasing(std::mt19937_64 &rng, int count, double start = 0.0, double minStep = 0.2,
                                            double maxStep = 3.0)
{
    std::uniform_real_distribution<double> step(minStep, maxStep);
    std::vector<double> x(static_cast<std::size_t>(count));
    double v = start;
    for (auto &e : x) {
        e = v;
        v += step(rng);
    }
    return x;
}

inline std::vector<double> randomValues(std::mt19937_64 &rng, int count, double lo = -10.0, double hi = 10.0)
{
    std::uniform_real_distribution<double> d(lo, hi);
    std::vector<double> y(static_cast<std::size_t>(count));
    for (auto &e : y)
        e = d(rng);
    return y;
}

inline double scaleOf(const std::vector<geo::Point> &pts)
{
    double m = 1.0;
    for (const auto &p : pts)
        m = std::max(m, p.cwiseAbs().maxCoeff());
    return m;
}

inline bool near(const geo::Point &a, const geo::Point &b, double tol)
{
    return (a - b).norm() <= tol;
}

inline bool near(double a, double b, double tol)
{
    return std::abs(a - b) <= tol;
}

// The global parameter u in [bounds[i], bounds[i+1]] → the piecewise curve at segment i, local t.
inline geo::Point evalPieces(const geo::PiecewiseBezier &pw, const std::vector<double> &bounds, double u)
{
    const auto it = std::upper_bound(bounds.begin(), bounds.end(), u);
    const int i = std::clamp(static_cast<int>(it - bounds.begin()) - 1, 0, pw.segmentCount() - 1);
    const auto k = static_cast<std::size_t>(i);
    return pw.segments()[k].eval((u - bounds[k]) / (bounds[k + 1] - bounds[k]));
}

} // namespace kontur::test
