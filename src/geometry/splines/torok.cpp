// Seed 001's uniform clamped spline and Török's half-size procedure (see torok.h).
#include "geometry/splines/torok.h"

#include "geometry/splines/knots.h"
#include "geometry/splines/tridiagonal.h"

#include <cmath>
#include <string>

namespace kontur::geo {

namespace {

std::vector<double> classical(std::span<const double> y, double h, double d0, double dLast)
{
    const std::size_t k = y.size();
    std::vector<double> d(k);
    d[0] = d0;
    d[k - 1] = dLast;
    if (k <= 2)
        return d;
    const std::size_t m = k - 2;
    std::vector<double> a(m, 1.0), b(m, 4.0), c(m, 1.0), r(m);
    for (std::size_t i = 1; i + 1 < k; ++i)
        r[i - 1] = 3.0 * (y[i + 1] - y[i - 1]) / h;
    r[0] -= d0;
    r[m - 1] -= dLast;
    (void)solveTridiagonal<double>(a, b, c, r); // diagonally dominant: never fails
    for (std::size_t i = 0; i < m; ++i)
        d[i + 1] = r[i];
    return d;
}

std::vector<double> torok(std::span<const double> y, double h, double d0, double dLast)
{
    const std::size_t k = y.size();
    std::vector<double> d(k);
    d[0] = d0;
    d[k - 1] = dLast;
    if (k == 2)
        return d;
    if (k == 3) {
        d[1] = cdn(h, y[0], y[2], d0, dLast);
        return d;
    }
    // The even unknowns d_2, d_4, …, d_K: K = k - 2 when k is even, k - 3 when odd.
    const bool even = k % 2 == 0;
    const std::size_t last = even ? k - 2 : k - 3;
    const std::size_t m = last / 2;
    std::vector<double> a(m, -0.5), b(m, 7.0), c(m, -0.5), r(m);
    for (std::size_t row = 0; row < m; ++row) {
        const std::size_t i = 2 * (row + 1);
        if (even && i == last) {
            b[row] = 7.5;
            r[row] = (3.0 * (y[i - 2] - y[i]) + 12.0 * (y[i + 1] - y[i - 1])) / (2.0 * h) - 2.0 * dLast;
        } else {
            r[row] = (3.0 * (y[i - 2] - y[i + 2]) - 12.0 * (y[i - 1] - y[i + 1])) / (2.0 * h);
            if (i + 2 == k - 1)
                r[row] += dLast / 2.0; // odd k: d_{k-1} is known
        }
        if (i == 2)
            r[row] += d0 / 2.0; // d_0 is known
    }
    (void)solveTridiagonal<double>(a, b, c, r); // diagonally dominant: never fails
    for (std::size_t row = 0; row < m; ++row)
        d[2 * (row + 1)] = r[row];
    for (std::size_t i = 1; i + 1 < k; i += 2)
        d[i] = cdn(h, y[i - 1], y[i + 1], d[i - 1], d[i + 1]);
    return d;
}

} // namespace

Result<std::vector<double>> uniformClampedSlopes(std::span<const double> y, double h, double d0, double dLast,
                                                 ClampedSolver solver)
{
    if (y.size() < 2)
        return Error{ErrorCode::TooFewPoints, "a clamped spline needs at least 2 values", static_cast<int>(y.size())};
    if (!(h > 0.0) || !std::isfinite(h))
        return Error{ErrorCode::InvalidArgument, "the knot spacing must be positive and finite", -1};
    for (std::size_t i = 0; i < y.size(); ++i)
        if (!std::isfinite(y[i]))
            return Error{ErrorCode::NonFiniteInput, "value " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
    if (!std::isfinite(d0) || !std::isfinite(dLast))
        return Error{ErrorCode::NonFiniteInput, "an end derivative is not finite", -1};
    return solver == ClampedSolver::Torok ? torok(y, h, d0, dLast) : classical(y, h, d0, dLast);
}

Result<HermiteSpline> uniformClampedSpline(std::span<const double> x, std::span<const double> y, double d0,
                                           double dLast, ClampedSolver solver)
{
    const std::size_t k = x.size();
    if (y.size() != k)
        return Error{ErrorCode::InvalidArgument, "one value per knot is needed", -1};
    if (k < 2)
        return Error{ErrorCode::TooFewPoints, "a clamped spline needs at least 2 knots", static_cast<int>(k)};
    if (auto ok = checkStrictlyIncreasing(x, "x"); !ok)
        return ok.error();
    const double range = x[k - 1] - x[0];
    const double h = range / static_cast<double>(k - 1); // docs/requirements.md 2: the seed's h divides by k
    for (std::size_t i = 1; i + 1 < k; ++i)
        if (std::abs(x[i] - (x[0] + h * static_cast<double>(i))) > 1e-9 * range)
            return Error{ErrorCode::InvalidArgument,
                         "the knots are not uniform (knot " + std::to_string(i) + "); use the general clamped spline",
                         static_cast<int>(i)};
    auto d = uniformClampedSlopes(y, h, d0, dLast, solver);
    if (!d)
        return d.error();
    return HermiteSpline::function(x, y, *d);
}

} // namespace kontur::geo
