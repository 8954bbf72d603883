// Parameterizations of point sequences (see parameterization.h).
#include "geometry/parameterization.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace kontur::geo {

double exponentOf(Parameterization p)
{
    switch (p) {
    case Parameterization::Uniform:
        return 0.0;
    case Parameterization::ChordLength:
        return 1.0;
    case Parameterization::Centripetal:
        return 0.5;
    }
    return 1.0;
}

bool parseParameterization(std::string_view name, Parameterization &out)
{
    if (name == "uniform")
        out = Parameterization::Uniform;
    else if (name == "chord" || name == "chord-length")
        out = Parameterization::ChordLength;
    else if (name == "centripetal")
        out = Parameterization::Centripetal;
    else
        return false;
    return true;
}

const char *nameOf(Parameterization p)
{
    switch (p) {
    case Parameterization::Uniform:
        return "uniform";
    case Parameterization::ChordLength:
        return "chord";
    case Parameterization::Centripetal:
        return "centripetal";
    }
    return "chord";
}

int scaleExponent(std::span<const Point> points)
{
    // Four independent maxima: one chain would wait on each comparison's latency (a million-point
    // spline or fit spent 5-10 % of its time here). std::max ignores a NaN as before.
    double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
    std::size_t i = 0;
    for (; i + 2 <= points.size(); i += 2) {
        m0 = std::max(m0, std::abs(points[i].x()));
        m1 = std::max(m1, std::abs(points[i].y()));
        m2 = std::max(m2, std::abs(points[i + 1].x()));
        m3 = std::max(m3, std::abs(points[i + 1].y()));
    }
    for (; i < points.size(); ++i) {
        m0 = std::max(m0, std::abs(points[i].x()));
        m1 = std::max(m1, std::abs(points[i].y()));
    }
    const double m = std::max({m0, m1, m2, m3});
    if (!(m > 0.0) || !std::isfinite(m))
        return 0;
    int e = 0;
    std::frexp(m, &e); // m = f 2^e, f in [0.5, 1)
    return std::clamp(e - 1, -1000, 1023);
}

Result<std::vector<double>> parameterize(std::span<const Point> points, double alpha)
{
    return parameterize(points, alpha, scaleExponent(points));
}

Result<std::vector<double>> parameterize(std::span<const Point> points, double alpha, int exponent)
{
    const std::size_t n = points.size();
    if (n < 2)
        return Error{ErrorCode::TooFewPoints, "at least 2 points are needed", static_cast<int>(n)};
    if (!(alpha >= 0.0 && alpha <= 1.0))
        return Error{ErrorCode::InvalidArgument, "the parameterization exponent must lie in [0, 1]", -1};
    std::vector<double> s(n);
    s[0] = 0.0;
    // Pass 1, one step per point with no dependency between iterations so it vectorises: the
    // distance (for the checks) and the step |Δp|^α (the common exponents avoid std::pow, which
    // would be the whole cost of a million-point fit).
    // The steps are ratios to their sum, so the points may be scaled first: by a power of two
    // (exact) to unit size. Coincidence is exact equality, not a distance that underflowed.
    const double unit = std::ldexp(1.0, -exponent);
    std::size_t zeroSteps = 0;
    for (std::size_t i = 1; i < n; ++i) {
        zeroSteps += points[i] == points[i - 1] ? 1 : 0;
        if (alpha == 0.0) {
            // Uniform needs no distance: 1 for finite points, NaN otherwise (found below).
            const double f = (points[i].x() - points[i].x()) + (points[i].y() - points[i].y());
            s[i] = f + 1.0;
            continue;
        }
        const double d = unitDistance(points[i - 1], points[i], unit);
        s[i] = alpha == 1.0 ? d : alpha == 0.5 ? std::sqrt(d) : std::pow(d, alpha);
    }
    // Pass 2, the running sum. A NaN or infinite coordinate poisons it (a uniform step is
    // (d - d) + 1: 1 for a finite distance, NaN otherwise); only then look for the culprit.
    for (std::size_t i = 1; i < n; ++i)
        s[i] += s[i - 1];
    if (!std::isfinite(s[n - 1]) || !points[0].allFinite()) {
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()))
                return Error{ErrorCode::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                             static_cast<int>(i)};
        return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    if (zeroSteps == n - 1)
        return Error{ErrorCode::AllPointsEqual, "all points are equal", -1};
    int coincident = -1;
    if (zeroSteps > 0) {
        for (std::size_t i = 1; i < n && coincident < 0; ++i)
            if (points[i] == points[i - 1])
                coincident = static_cast<int>(i);
    }
    if (alpha > 0.0 && coincident >= 0)
        return Error{ErrorCode::CoincidentPoints,
                     "points " + std::to_string(coincident - 1) + " and " + std::to_string(coincident) + " coincide",
                     coincident};
    const double inv = 1.0 / s[n - 1];
    for (std::size_t i = 1; i + 1 < n; ++i)
        s[i] *= inv;
    s[n - 1] = 1.0;
    return s;
}

Result<std::vector<double>> parameterize(std::span<const Point> points, Parameterization p)
{
    return parameterize(points, exponentOf(p));
}

} // namespace kontur::geo
