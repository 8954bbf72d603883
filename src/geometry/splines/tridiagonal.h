// O(n) solvers for the tridiagonal and cyclic tridiagonal systems every interpolating cubic spline
// leads to: the Thomas algorithm ("прогонка", the sweep method of seed 003 KG-203) and, for closed
// curves, the cyclic system reduced to two tridiagonal ones by the Sherman–Morrison formula.
// Templates over the right-hand side type so one sweep solves for x and y together (T = Point).
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace kontur::geo {

// Solves a_i x_{i-1} + b_i x_i + c_i x_{i+1} = d_i, i = 0..n-1 (a_0 and c_{n-1} are ignored), in
// place: `d` holds the solution afterwards. `work` is scratch space of n doubles. No pivoting: meant
// for the diagonally dominant spline systems; a zero (or non-finite) pivot returns false and leaves
// `d` unspecified.
template <typename T>
[[nodiscard]] bool solveTridiagonal(std::span<const double> a, std::span<const double> b, std::span<const double> c,
                                    std::span<T> d, std::span<double> work)
{
    const std::size_t n = d.size();
    if (n == 0)
        return true;
    double pivot = b[0];
    if (!(std::abs(pivot) > 0.0) || !std::isfinite(pivot))
        return false;
    work[0] = c.size() > 0 && n > 1 ? c[0] / pivot : 0.0;
    d[0] = d[0] / pivot;
    for (std::size_t i = 1; i < n; ++i) {
        pivot = b[i] - a[i] * work[i - 1];
        if (!(std::abs(pivot) > 0.0) || !std::isfinite(pivot))
            return false;
        const double inv = 1.0 / pivot;
        work[i] = i + 1 < n ? c[i] * inv : 0.0;
        d[i] = (d[i] - a[i] * d[i - 1]) * inv;
    }
    for (std::size_t i = n - 1; i-- > 0;)
        d[i] = d[i] - work[i] * d[i + 1];
    return true;
}

template <typename T>
[[nodiscard]] bool solveTridiagonal(std::span<const double> a, std::span<const double> b, std::span<const double> c,
                                    std::span<T> d)
{
    std::vector<double> work(d.size());
    return solveTridiagonal(a, b, c, d, std::span<double>(work));
}

// Solves the cyclic system a_i x_{i-1} + b_i x_i + c_i x_{i+1} = d_i with indices modulo n (a_0
// couples x_0 to x_{n-1}, c_{n-1} couples x_{n-1} to x_0), n >= 3, in place. Sherman–Morrison
// (Press et al., "Numerical Recipes" §2.7): A = T + u vᵀ with u = (γ, 0, …, 0, c_{n-1}),
// v = (1, 0, …, 0, a_0/γ), γ = -b_0; x = y - (vᵀy)/(1 + vᵀz) z where T y = d and T z = u.
template <typename T>
[[nodiscard]] bool solveCyclicTridiagonal(std::span<const double> a, std::span<const double> b,
                                          std::span<const double> c, std::span<T> d)
{
    const std::size_t n = d.size();
    if (n < 3)
        return false;
    const double gamma = -b[0];
    if (!(std::abs(gamma) > 0.0))
        return false;
    std::vector<double> bb(b.begin(), b.end());
    bb[0] = b[0] - gamma;
    bb[n - 1] = b[n - 1] - c[n - 1] * a[0] / gamma;
    std::vector<double> work(n);
    if (!solveTridiagonal(a, std::span<const double>(bb), c, d, std::span<double>(work)))
        return false;
    std::vector<double> z(n, 0.0);
    z[0] = gamma;
    z[n - 1] = c[n - 1];
    if (!solveTridiagonal(a, std::span<const double>(bb), c, std::span<double>(z), std::span<double>(work)))
        return false;
    const double denom = 1.0 + z[0] + a[0] * z[n - 1] / gamma;
    if (!(std::abs(denom) > 0.0) || !std::isfinite(denom))
        return false;
    const T vy = d[0] + (a[0] / gamma) * d[n - 1];
    const T factor = vy / denom;
    for (std::size_t i = 0; i < n; ++i)
        d[i] = d[i] - z[i] * factor;
    return true;
}

} // namespace kontur::geo
