// Least-squares and interpolating cubic fits by a streaming (tall-skinny) Householder QR (see fit.h).
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

// Fits with the given parameters. Assumes finite points and params.
Result<CubicFit> solve(std::span<const Point> points, std::vector<double> params)
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
    CubicFit fit;
    for (int j = 0; j < 4; ++j)
        fit.control[j] = Point(c[j][0], c[j][1]);
    // Residuals at the fitted parameters, evaluated in power form a t³ + b t² + c t + d (seed 004).
    const Point d0 = fit.control[0];
    const Point c1 = 3.0 * (fit.control[1] - fit.control[0]);
    const Point b2 = 3.0 * (fit.control[2] - fit.control[1]) - c1;
    const Point a3 = fit.control[3] - fit.control[0] - b2 - c1;
    double sum = 0.0;
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = params[k];
        const double x = ((a3.x() * t + b2.x()) * t + c1.x()) * t + d0.x() - points[k].x();
        const double y = ((a3.y() * t + b2.y()) * t + c1.y()) * t + d0.y() - points[k].y();
        const double e2 = x * x + y * y;
        sum += e2;
        worst = std::max(worst, e2);
    }
    fit.rms = std::sqrt(sum / static_cast<double>(n));
    fit.maxError = std::sqrt(worst);
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

Result<CubicFit> unitFit(std::span<const Point> points, std::vector<double> params, int iterations);

// The fit is affinely invariant, but its squares (the residuals, the QR's norms) overflow above
// ~1e154 and underflow below ~1e-162: it runs on the points scaled to unit size by a power of two
// (exact) and the result is scaled back, so a fit at scale s is s times the fit at scale 1.
Result<CubicFit> checkedFit(std::span<const Point> points, std::vector<double> params, int iterations)
{
    // Within 2^±200 the squares stay far inside doubles: fitted as given, without a scaled copy
    // (which cost a million-point fit half its time again).
    const int k = scaleExponent(points);
    if (std::abs(k) <= 200)
        return unitFit(points, std::move(params), iterations);
    std::vector<Point> unit(points.begin(), points.end());
    for (Point &p : unit)
        p *= std::ldexp(1.0, -k);
    Result<CubicFit> fit = unitFit(unit, std::move(params), iterations);
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

Result<CubicFit> unitFit(std::span<const Point> points, std::vector<double> params, int iterations)
{
    if (countDistinct(params, 4) < 4)
        return tooFewDistinct();
    Result<CubicFit> fit = solve(points, std::move(params));
    if (!fit)
        return fit;
    for (int round = 0; round < iterations; ++round) {
        std::vector<double> next = fit->params;
        correctParameters(fit->curve(), points, next);
        if (countDistinct(next, 4) < 4)
            break;
        Result<CubicFit> better = solve(points, std::move(next));
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
    Result<std::vector<double>> params = parameterize(points, options.alpha);
    if (!params) {
        if (!(params.error().code == ErrorCode::CoincidentPoints && options.allowCoincidentPoints))
            return params.error();
        // Coincident points allowed: recompute with zero steps kept (they share a parameter).
        std::vector<double> s(points.size(), 0.0);
        const double unit = std::ldexp(1.0, -scaleExponent(points));
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
    return checkedFit(points, std::move(params).value(), std::max(0, options.reparameterizeIterations));
}

Result<CubicFit> fitCubic(std::span<const Point> points, Parameterization p)
{
    return fitCubic(points, FitOptions{exponentOf(p), 0, false});
}

Result<CubicFit> fitCubicWithParams(std::span<const Point> points, std::vector<double> params)
{
    if (points.size() < 4)
        return Error{ErrorCode::TooFewPoints, "a cubic needs at least 4 points", static_cast<int>(points.size())};
    if (params.size() != points.size())
        return Error{ErrorCode::InvalidArgument, "one parameter per point is needed", -1};
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(params[i]))
            return Error{ErrorCode::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
    return checkedFit(points, std::move(params), 0);
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
