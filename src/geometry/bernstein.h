// Scalar polynomials in the Bernstein basis on [0, 1]: evaluation, derivative, product and all real
// roots in [0, 1]. Used for tight bounding boxes, inflections and the global nearest point.
#pragma once

#include <span>
#include <vector>

namespace kontur::geo {

// C(n, k) as a double (exact for the degrees Kontur uses, n <= 1000 gives relative error ~1e-15;
// it overflows to infinity near n = 1030: callers of higher degrees work with ratios or logarithms).
[[nodiscard]] double binomial(int n, int k);

// p(t) by de Casteljau; when `derivative` is given, also p'(t).
[[nodiscard]] double bernsteinEval(std::span<const double> b, double t, double *derivative = nullptr);

// Coefficients of p' (degree n - 1) from those of p (degree n).
[[nodiscard]] std::vector<double> bernsteinDerivative(std::span<const double> b);

// Coefficients of p·q (degree n + m).
[[nodiscard]] std::vector<double> bernsteinProduct(std::span<const double> p, std::span<const double> q);

// Appends to `roots` every t in [0, 1] with p(t) = 0, in increasing order, to full double precision.
// Method: the roots of p' split [0, 1] into intervals where p is monotone, found recursively down to
// degree 1; in each interval with a sign change a safeguarded Newton–bisection iteration converges
// (C. Yuksel, "High-Performance Polynomial Root Finding for Graphics", HPG 2022). Unlike a Newton
// step from a guess it cannot miss a root. An identically zero p has no isolated roots and gives none.
// With `risingOnly`, only roots where p goes from negative to positive are reported (the minima of
// an integral of p), which halves the work of a nearest-point query.
void bernsteinRoots(std::span<const double> b, std::vector<double> &roots, bool risingOnly = false);

} // namespace kontur::geo
