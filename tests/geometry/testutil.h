// Helpers shared by the geometry tests: random curves, a relative-error check, printing points.
#pragma once

#include "geometry/bezier.h"

#include <QString>

#include <random>
#include <vector>

namespace kontur::test {

inline std::vector<geo::Point> randomPoints(std::mt19937_64 &rng, int count, double lo = -100.0, double hi = 100.0)
{
    std::uniform_real_distribution<double> coord(lo, hi);
    std::vector<geo::Point> pts(static_cast<std::size_t>(count));
    for (auto &p : pts)
        p = geo::Point(coord(rng), coord(rng));
    return pts;
}

// The size of a control polygon, the scale "relative" errors are measured against.
inline double polygonScale(const std::vector<geo::Point> &pts)
{
    double m = 0.0;
    for (const auto &p : pts)
        m = std::max(m, p.cwiseAbs().maxCoeff());
    return std::max(m, 1e-300);
}

inline QString str(const geo::Point &p)
{
    return QStringLiteral("(%1, %2)").arg(p.x(), 0, 'g', 17).arg(p.y(), 0, 'g', 17);
}

} // namespace kontur::test
