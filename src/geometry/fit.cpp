// Least-squares and interpolating cubic fits: corrected semi-normal equations, with the streaming
// (tall-skinny) Householder QR as the reference and the fallback for ill-conditioned systems (see fit.h).
#include "geometry/fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kontur::geo {

namespace {

// Rows are fed in blocks of kBlock; a block is stored by columns so the inner loops vectorise.
constexpr int kBlock = 128;
constexpr int kCols = 6; // B0, B1, B2, B3 | x, y

// R of the QR factorisation of all rows seen so far: rows 0..3 of [R11 | Qᵀ[x y]].
struct StreamingQr
{
    double r[4][kCols] = {};

    // Annihilates a block of rows against R with one Householder reflection per column
    // (LAPACK dlarfg/dlarf on the stacked matrix [R; block]). Rows that are all zero are harmless,
    // which lets the last block be padded instead of having a variable trip count.
    void addBlock(double (&blk)[kCols][kBlock])
    {
        reflect<0>(blk);
        reflect<1>(blk);
        reflect<2>(blk);
        reflect<3>(blk);
    }

    // Column J's reflection. The dot products of all later columns are accumulated in one pass over
    // the rows: independent sums keep the floating-point adders busy (a single running sum would
    // wait for each addition in turn, and may not be reordered without -ffast-math).
    template <int J> void reflect(double (&blk)[kCols][kBlock])
    {
        double sq[4] = {0.0, 0.0, 0.0, 0.0};
        for (int i = 0; i < kBlock; i += 4)
            for (int u = 0; u < 4; ++u)
                sq[u] += blk[J][i + u] * blk[J][i + u];
        const double sigma = (sq[0] + sq[1]) + (sq[2] + sq[3]);
        if (sigma == 0.0)
            return;
        const double alpha = r[J][J];
        const double norm = std::sqrt(alpha * alpha + sigma);
        const double beta = alpha >= 0.0 ? -norm : norm;
        const double tau = (beta - alpha) / beta;
        const double scale = 1.0 / (alpha - beta);
        constexpr int kRest = kCols - J - 1;
        double w[kRest] = {};
        for (int i = 0; i < kBlock; ++i) {
            const double v = blk[J][i] * scale; // v = (1, blk[J] · scale)
            blk[J][i] = v;
            for (int l = 0; l < kRest; ++l)
                w[l] += v * blk[J + 1 + l][i];
        }
        for (int l = 0; l < kRest; ++l) {
            w[l] = tau * (r[J][J + 1 + l] + w[l]);
            r[J][J + 1 + l] -= w[l];
        }
        for (int l = 0; l < kRest; ++l)
            for (int i = 0; i < kBlock; ++i)
                blk[J + 1 + l][i] -= w[l] * blk[J][i];
        r[J][J] = beta;
    }
};

Error tooFewDistinct()
{
    return Error{ErrorCode::TooFewDistinctParameters, "fewer than 4 distinct parameter values", -1};
}

// The cubic for the control points c (rows of [x y]) and its residuals at the parameters: the
// RMS and largest distance of B(s_i) from p_i, evaluated in power form a t³ + b t² + c t + d
// (seed 004).
CubicFit withResiduals(std::span<const Point> points, const std::vector<double> &params, const double (&c)[4][2])
{
    CubicFit fit;
    for (int j = 0; j < 4; ++j)
        fit.control[j] = Point(c[j][0], c[j][1]);
    const Point d0 = fit.control[0];
    const Point c1 = 3.0 * (fit.control[1] - fit.control[0]);
    const Point b2 = 3.0 * (fit.control[2] - fit.control[1]) - c1;
    const Point a3 = fit.control[3] - fit.control[0] - b2 - c1;
    double sum = 0.0;
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const double t = params[k];
        const double x = ((a3.x() * t + b2.x()) * t + c1.x()) * t + d0.x() - points[k].x();
        const double y = ((a3.y() * t + b2.y()) * t + c1.y()) * t + d0.y() - points[k].y();
        const double e2 = x * x + y * y;
        sum += e2;
        worst = std::max(worst, e2);
    }
    fit.rms = std::sqrt(sum / static_cast<double>(points.size()));
    fit.maxError = std::sqrt(worst);
    return fit;
}

// The reference solver: the streaming Householder QR of [B | x | y]. Backward stable, so its
// error grows like κ(B) ε where the normal equations' grows like κ(B)² ε (Björck, "Numerical
// Methods for Least Squares Problems", SIAM 1996, §1.4 and §2.2). Assumes finite points and params.
Result<CubicFit> solveQr(std::span<const Point> points, std::vector<double> params)
{
    const std::size_t n = points.size();
    StreamingQr qr;
    alignas(64) double blk[kCols][kBlock];
    std::size_t i = 0;
    while (i < n) {
        const int rows = static_cast<int>(std::min<std::size_t>(kBlock, n - i));
        for (int k = 0; k < rows; ++k) {
            const double t = params[i + k];
            const double s = 1.0 - t;
            blk[0][k] = s * s * s;
            blk[1][k] = 3.0 * s * s * t;
            blk[2][k] = 3.0 * s * t * t;
            blk[3][k] = t * t * t;
            blk[4][k] = points[i + k].x();
            blk[5][k] = points[i + k].y();
        }
        for (int c = 0; c < kCols; ++c)
            std::fill(blk[c] + rows, blk[c] + kBlock, 0.0);
        qr.addBlock(blk);
        i += static_cast<std::size_t>(rows);
    }
    // Rank check: with 4 distinct parameters the Bernstein matrix has full rank, but parameters
    // crowded into a tiny interval make it numerically singular; refuse rather than answer noise.
    double maxDiag = 0.0;
    for (int j = 0; j < 4; ++j)
        maxDiag = std::max(maxDiag, std::abs(qr.r[j][j]));
    for (int j = 0; j < 4; ++j)
        if (!(std::abs(qr.r[j][j]) > 1e-13 * maxDiag))
            return Error{ErrorCode::IllConditioned, "the points do not determine a cubic (rank deficient)", -1};
    // Back substitution R11 C = Qᵀ[x y].
    double c[4][2];
    for (int j = 3; j >= 0; --j) {
        for (int axis = 0; axis < 2; ++axis) {
            double v = qr.r[j][4 + axis];
            for (int k = j + 1; k < 4; ++k)
                v -= qr.r[j][k] * c[k][axis];
            c[j][axis] = v / qr.r[j][j];
        }
    }
    CubicFit fit = withResiduals(points, params, c);
    fit.params = std::move(params);
    return fit;
}

// The monomials of the cubic Bernstein basis without their binomials, u_j = (1 - t)^(3-j) t^j
// (B_j = C(3,j) u_j).
struct Monomials
{
    double u0, u1, u2, u3;
    explicit Monomials(double t)
    {
        const double s = 1.0 - t;
        const double s2 = s * s, t2 = t * t;
        u0 = s2 * s;
        u1 = s2 * t;
        u2 = s * t2;
        u3 = t2 * t;
    }
};

// Sums over the points of the products the normal equations need. A product of two cubic Bernstein
// polynomials is one of degree 6, B_i B_j = C(3,i) C(3,j) u_i u_j with u_i u_j = (1 - t)^(6-i-j)
// t^(i+j) (Farouki & Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5 (1988), §3), so
// the 4×4 Gram matrix BᵀB needs only the 7 sums g_k = Σ (1 - t)^(6-k) t^k, and the right-hand
// sides Bᵀx, Bᵀy the 8 sums Σ u_j x, Σ u_j y: 15 multiply-adds a point where the QR spends ~60.
// For parameters in [0, 1] (others go to the QR) every term of g_k is non-negative, so each sum is
// accurate to its rounding relative to itself (no cancellation), which is what makes the Gram matrix
// of this basis a good one to form.
struct NormalSums
{
    double g[7] = {};
    double bx[4] = {}, by[4] = {};
};

// Lanes of independent sums (vectorised across points; a single running sum would wait for each
// addition, and may not be reordered without -ffast-math), added up per block of rows so that no
// sum runs over more than kBlock terms before it joins the total.
constexpr int kLanes = 4;

NormalSums normalSums(std::span<const Point> points, const std::vector<double> &params)
{
    NormalSums total;
    const std::size_t n = points.size();
    for (std::size_t start = 0; start < n; start += kBlock) {
        const std::size_t end = std::min(n, start + static_cast<std::size_t>(kBlock));
        double acc[15][kLanes] = {};
        // Point i's terms into lane l.
        const auto add = [&](std::size_t i, int l) {
            const Monomials m(params[i]);
            const double x = points[i].x(), y = points[i].y();
            acc[0][l] += m.u0 * m.u0;
            acc[1][l] += m.u0 * m.u1;
            acc[2][l] += m.u1 * m.u1;
            acc[3][l] += m.u1 * m.u2;
            acc[4][l] += m.u2 * m.u2;
            acc[5][l] += m.u2 * m.u3;
            acc[6][l] += m.u3 * m.u3;
            acc[7][l] += m.u0 * x;
            acc[8][l] += m.u1 * x;
            acc[9][l] += m.u2 * x;
            acc[10][l] += m.u3 * x;
            acc[11][l] += m.u0 * y;
            acc[12][l] += m.u1 * y;
            acc[13][l] += m.u2 * y;
            acc[14][l] += m.u3 * y;
        };
        std::size_t i = start;
        for (; i + kLanes <= end; i += kLanes)
            for (int l = 0; l < kLanes; ++l)
                add(i + l, l);
        for (; i < end; ++i)
            add(i, 0);
        double sums[15];
        for (int k = 0; k < 15; ++k) {
            sums[k] = 0.0;
            for (int l = 0; l < kLanes; ++l)
                sums[k] += acc[k][l];
        }
        for (int k = 0; k < 7; ++k)
            total.g[k] += sums[k];
        for (int j = 0; j < 4; ++j) {
            total.bx[j] += sums[7 + j];
            total.by[j] += sums[11 + j];
        }
    }
    return total;
}

// Bᵀr for the residuals r = [x y] - B c at the control points c (the refinement's right-hand side).
void residualProducts(std::span<const Point> points, const std::vector<double> &params, const double (&c)[4][2],
                      double (&out)[4][2])
{
    double total[4][2] = {};
    const std::size_t n = points.size();
    for (std::size_t start = 0; start < n; start += kBlock) {
        const std::size_t end = std::min(n, start + static_cast<std::size_t>(kBlock));
        double acc[8] = {};
        for (std::size_t i = start; i < end; ++i) {
            const Monomials m(params[i]);
            const double b[4] = {m.u0, 3.0 * m.u1, 3.0 * m.u2, m.u3};
            const double rx = points[i].x() - (b[0] * c[0][0] + b[1] * c[1][0] + b[2] * c[2][0] + b[3] * c[3][0]);
            const double ry = points[i].y() - (b[0] * c[0][1] + b[1] * c[1][1] + b[2] * c[2][1] + b[3] * c[3][1]);
            for (int j = 0; j < 4; ++j) {
                acc[j] += b[j] * rx;
                acc[4 + j] += b[j] * ry;
            }
        }
        for (int j = 0; j < 4; ++j) {
            total[j][0] += acc[j];
            total[j][1] += acc[4 + j];
        }
    }
    for (int j = 0; j < 4; ++j) {
        out[j][0] = total[j][0];
        out[j][1] = total[j][1];
    }
}

// The Cholesky factor R (G = RᵀR, upper triangular) of a 4×4 symmetric matrix; false when G is not
// numerically positive definite.
bool cholesky(const double (&g)[4][4], double (&r)[4][4])
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r[i][j] = 0.0;
    for (int j = 0; j < 4; ++j) {
        double d = g[j][j];
        for (int k = 0; k < j; ++k)
            d -= r[k][j] * r[k][j];
        if (!(d > 0.0))
            return false;
        r[j][j] = std::sqrt(d);
        for (int i = j + 1; i < 4; ++i) {
            double v = g[j][i];
            for (int k = 0; k < j; ++k)
                v -= r[k][j] * r[k][i];
            r[j][i] = v / r[j][j];
        }
    }
    return true;
}

// Solves RᵀR x = b in place for both columns of b.
void choleskySolve(const double (&r)[4][4], double (&b)[4][2])
{
    for (int axis = 0; axis < 2; ++axis) {
        for (int i = 0; i < 4; ++i) { // Rᵀ y = b
            double v = b[i][axis];
            for (int k = 0; k < i; ++k)
                v -= r[k][i] * b[k][axis];
            b[i][axis] = v / r[i][i];
        }
        for (int i = 3; i >= 0; --i) { // R x = y
            double v = b[i][axis];
            for (int k = i + 1; k < 4; ++k)
                v -= r[i][k] * b[k][axis];
            b[i][axis] = v / r[i][i];
        }
    }
}

// κ_F(R) = ‖R‖_F ‖R⁻¹‖_F, an upper bound of κ₂(R) = κ₂(B) within a factor 4 (the norms of a
// 4×4 matrix agree within √4 each), with R⁻¹ formed explicitly (it is 4×4 triangular).
double conditionEstimate(const double (&r)[4][4])
{
    double inv[4][4] = {};
    for (int j = 0; j < 4; ++j) {
        inv[j][j] = 1.0 / r[j][j];
        for (int i = j - 1; i >= 0; --i) {
            double v = 0.0;
            for (int k = i + 1; k <= j; ++k)
                v += r[i][k] * inv[k][j];
            inv[i][j] = -v / r[i][i];
        }
    }
    double nr = 0.0, ni = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = i; j < 4; ++j) {
            nr += r[i][j] * r[i][j];
            ni += inv[i][j] * inv[i][j];
        }
    return std::sqrt(nr) * std::sqrt(ni);
}

// Above this estimate of κ(B) the semi-normal solution is refined (below it its error, ~κ² ε,
// is under 1e-12 relative: within a factor 32 of the QR's κ ε, and a million times below any
// tolerance the application or its tests use).
constexpr double kRefineCondition = 32.0;
// Above this one the QR answers: one step of refinement contracts the error by about κ² ε
// (Björck 1996, §2.5.2), ≤ 2e-8 here, so a single step brings the semi-normal solution (error
// ~κ² ε ≤ 2e-8 relative) to the QR's level; beyond it, and for a system too ill-conditioned to
// factor at all, the QR (which also decides rank deficiency) is used.
constexpr double kQrCondition = 1e4;

// Fits with the given parameters. Assumes finite points and params.
// Corrected semi-normal equations (CSNE; Björck, "Stability analysis of the method of seminormal
// equations for linear least squares problems", Linear Algebra Appl. 88/89 (1987), and Björck 1996,
// §2.5.2): the Gram matrix G = BᵀB of the Bernstein columns (one for both coordinates, which share
// the basis) and Bᵀ[x y] are summed in one pass (normalSums), G = RᵀR by Cholesky, RᵀR c = Bᵀ[x y];
// then, where κ(B) calls for it, one step of refinement RᵀR δ = Bᵀ(p - B c), c += δ, on the
// residuals of a second pass. The pass that reports the residuals of the result is the one every
// solver needs. A condition estimate from R decides, and the QR (solveQr) answers what it should.
Result<CubicFit> solve(std::span<const Point> points, std::vector<double> params)
{
    const NormalSums sums = normalSums(points, params);
    constexpr double kBinomial[4] = {1.0, 3.0, 3.0, 1.0};
    double g[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            g[i][j] = kBinomial[i] * kBinomial[j] * sums.g[i + j];
    double r[4][4];
    if (!cholesky(g, r))
        return solveQr(points, std::move(params));
    const double kappa = conditionEstimate(r);
    if (!(kappa <= kQrCondition))
        return solveQr(points, std::move(params));
    double c[4][2];
    for (int j = 0; j < 4; ++j) {
        c[j][0] = kBinomial[j] * sums.bx[j];
        c[j][1] = kBinomial[j] * sums.by[j];
    }
    choleskySolve(r, c);
    if (kappa > kRefineCondition) {
        double delta[4][2];
        residualProducts(points, params, c, delta);
        choleskySolve(r, delta);
        for (int j = 0; j < 4; ++j)
            for (int axis = 0; axis < 2; ++axis)
                c[j][axis] += delta[j][axis];
    }
    CubicFit fit = withResiduals(points, params, c);
    fit.params = std::move(params);
    return fit;
}

std::size_t countDistinct(const std::vector<double> &params, std::size_t enough)
{
    std::vector<double> seen;
    for (double t : params) {
        if (std::find(seen.begin(), seen.end(), t) == seen.end()) {
            seen.push_back(t);
            if (seen.size() >= enough)
                break;
        }
    }
    return seen.size();
}

// One round of parameter correction: a few Newton steps on (B(s) - p)·B'(s) = 0 per point.
void correctParameters(const Bezier &curve, std::span<const Point> points, std::vector<double> &params)
{
    const Bezier d1 = curve.derivativeCurve(1);
    const Bezier d2 = curve.derivativeCurve(2);
    for (std::size_t k = 0; k < points.size(); ++k) {
        double t = params[k];
        for (int step = 0; step < 3; ++step) {
            const Point diff = curve.eval(t) - points[k];
            const Point v = d1.eval(t);
            const double f = diff.dot(v);
            const double df = v.squaredNorm() + diff.dot(d2.eval(t));
            if (!(df > 0.0))
                break;
            const double next = std::clamp(t - f / df, 0.0, 1.0);
            if (next == t)
                break;
            t = next;
        }
        params[k] = t;
    }
}

using Solver = Result<CubicFit> (*)(std::span<const Point>, std::vector<double>);

Result<CubicFit> unitFit(std::span<const Point> points, std::vector<double> params, int iterations, Solver solver);

// The fit is affinely invariant, but its squares (the residuals, the QR's norms) overflow above
// ~1e154 and underflow below ~1e-162: it runs on the points scaled to unit size by a power of two
// (exact) and the result is scaled back, so a fit at scale s is s times the fit at scale 1.
Result<CubicFit> checkedFit(std::span<const Point> points, std::vector<double> params, int iterations, int k,
                            Solver solver = solve)
{
    // Within 2^±200 the squares stay far inside doubles: fitted as given, without a scaled copy
    // (which cost a million-point fit half its time again). k = scaleExponent(points).
    if (std::abs(k) <= 200)
        return unitFit(points, std::move(params), iterations, solver);
    std::vector<Point> unit(points.begin(), points.end());
    for (Point &p : unit)
        p *= std::ldexp(1.0, -k);
    Result<CubicFit> fit = unitFit(unit, std::move(params), iterations, solver);
    if (!fit)
        return fit;
    const double back = std::ldexp(1.0, k);
    for (Point &c : fit->control)
        c *= back;
    fit->rms *= back;
    fit->maxError *= back;
    for (const Point &c : fit->control)
        if (!c.allFinite())
            return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    return fit;
}

Result<CubicFit> unitFit(std::span<const Point> points, std::vector<double> params, int iterations, Solver solver)
{
    if (countDistinct(params, 4) < 4)
        return tooFewDistinct();
    Result<CubicFit> fit = solver(points, std::move(params));
    if (!fit)
        return fit;
    for (int round = 0; round < iterations; ++round) {
        std::vector<double> next = fit->params;
        correctParameters(fit->curve(), points, next);
        if (countDistinct(next, 4) < 4)
            break;
        Result<CubicFit> better = solver(points, std::move(next));
        if (!better || !(better->rms < fit->rms))
            break;
        better->iterations = fit->iterations + 1;
        fit = std::move(better);
    }
    return fit;
}

} // namespace

Result<CubicFit> fitCubic(std::span<const Point> points, const FitOptions &options)
{
    if (points.size() < 4)
        return Error{ErrorCode::TooFewPoints, "a cubic needs at least 4 points", static_cast<int>(points.size())};
    const int exponent = scaleExponent(points);
    Result<std::vector<double>> params = parameterize(points, options.alpha, exponent);
    if (!params) {
        if (!(params.error().code == ErrorCode::CoincidentPoints && options.allowCoincidentPoints))
            return params.error();
        // Coincident points allowed: recompute with zero steps kept (they share a parameter).
        std::vector<double> s(points.size(), 0.0);
        const double unit = std::ldexp(1.0, -exponent);
        for (std::size_t i = 1; i < points.size(); ++i)
            s[i] = s[i - 1] + std::pow(unitDistance(points[i - 1], points[i], unit), options.alpha);
        for (double &v : s)
            v /= s.back();
        params = std::move(s);
    } else if (!options.allowCoincidentPoints && options.alpha == 0.0) {
        // Uniform parameters stay distinct, but the seed's rule still rejects repeated knots.
        for (std::size_t i = 1; i < points.size(); ++i)
            if (points[i] == points[i - 1])
                return Error{ErrorCode::CoincidentPoints,
                             "points " + std::to_string(i - 1) + " and " + std::to_string(i) + " coincide",
                             static_cast<int>(i)};
    }
    return checkedFit(points, std::move(params).value(), std::max(0, options.reparameterizeIterations), exponent);
}

Result<CubicFit> fitCubic(std::span<const Point> points, Parameterization p)
{
    return fitCubic(points, FitOptions{exponentOf(p), 0, false});
}

namespace {

Result<CubicFit> fitWithParams(std::span<const Point> points, std::vector<double> params, Solver solver)
{
    if (points.size() < 4)
        return Error{ErrorCode::TooFewPoints, "a cubic needs at least 4 points", static_cast<int>(points.size())};
    if (params.size() != points.size())
        return Error{ErrorCode::InvalidArgument, "one parameter per point is needed", -1};
    bool unit = true;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(params[i]))
            return Error{ErrorCode::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
        unit = unit && params[i] >= 0.0 && params[i] <= 1.0;
    }
    // Outside [0, 1] the Bernstein values change sign, the Gram matrix's sums lose the accuracy
    // that non-negative terms give them, and the QR answers.
    return checkedFit(points, std::move(params), 0, scaleExponent(points), unit ? solver : solveQr);
}

} // namespace

Result<CubicFit> fitCubicWithParams(std::span<const Point> points, std::vector<double> params)
{
    return fitWithParams(points, std::move(params), solve);
}

Result<CubicFit> detail::fitCubicWithParamsQr(std::span<const Point> points, std::vector<double> params)
{
    return fitWithParams(points, std::move(params), solveQr);
}

Result<CubicFit> interpolateCubic(std::span<const Point> points, double alpha)
{
    if (points.size() != 4)
        return Error{ErrorCode::InvalidArgument, "the interpolating cubic needs exactly 4 points",
                     static_cast<int>(points.size())};
    return fitCubic(points, FitOptions{alpha, 0, false});
}

Result<CubicFit> interpolateCubic(std::span<const Point> points, Parameterization p)
{
    return interpolateCubic(points, exponentOf(p));
}

} // namespace kontur::geo
