// Unnormalised spline parameters and input checks (see knots.h).
#include "geometry/splines/knots.h"

#include "geometry/largevector.h"
#include "geometry/parameterization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kontur::geo {

namespace {

// The checks after the pass that sums the steps s (zeroStep: some step was 0; increasing: every sum
// grew): the error that names the culprit, or s.
Result<std::vector<double>> finishParameters(std::span<const Point> points, Parameterization p, bool closed,
                                             std::vector<double> s, bool zeroStep, bool increasing)
{
    const std::size_t n = points.size();
    const std::size_t steps = closed ? n : n - 1;
    if (!std::isfinite(s[steps]) || !points[0].allFinite()) {
        // The normalised parameterization names the culprit (a non-finite point, or an overflow).
        auto normalised = parameterize(points, p);
        if (!normalised)
            return normalised.error();
        return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    if (zeroStep) {
        auto normalised = parameterize(points, p);
        if (!normalised)
            return normalised.error(); // all points equal, or coincident (chord, centripetal)
        for (std::size_t i = 1; i <= steps; ++i) {
            const std::size_t j = i == n ? 0 : i;
            if (points[j] == points[i - 1])
                return Error{ErrorCode::CoincidentPoints,
                             "points " + std::to_string(i - 1) + " and " + std::to_string(j) + " coincide",
                             static_cast<int>(j)};
        }
    }
    if (!increasing)
        return checkStrictlyIncreasing(s, "parameter").error();
    return s;
}

} // namespace

Result<std::vector<double>> splineParameters(std::span<const Point> points, Parameterization p, bool closed)
{
    return splineParameters(points, p, closed, scaleExponent(points));
}

Result<std::vector<double>> splineParameters(std::span<const Point> points, Parameterization p, bool closed, int k)
{
    const std::size_t n = points.size();
    const std::size_t need = closed ? 3 : 2;
    if (n < need)
        return Error{ErrorCode::TooFewPoints, "at least " + std::to_string(need) + " points are needed",
                     static_cast<int>(n)};
    const double alpha = exponentOf(p);
    std::vector<double> s = largeVector<double>(closed ? n + 1 : n);
    s[0] = 0.0;
    const std::size_t steps = closed ? n : n - 1;
    // One pass: each step |Δp|^α (std::pow only for uncommon exponents: it would dominate a
    // million-point spline) added to the running sum. The sum is a chain of dependent additions;
    // the distances beside it are independent work that the processor overlaps with it, which two
    // passes (steps, then sums) could not. Same sums, in the same order, as two passes.
    // (The closing step of a closed curve, i = n, wraps to the first point.)
    // Distances on the points scaled to unit size by 2^-k (exact; no squares overflow at 1e160 or
    // underflow at 1e-170), then scaled back: chord steps by 2^k, centripetal ones by 2^(k/2).
    const double unit = std::ldexp(1.0, -k);
    const double back = std::ldexp(1.0, k);
    const double backRoot = std::ldexp((k & 1) != 0 ? std::sqrt(2.0) : 1.0, (k - (k & 1)) / 2); // 2^(k/2)
    std::size_t zeroSteps = 0;
    bool increasing = true;
    auto run = [&](auto stepOf) {
        double sum = 0.0;
        for (std::size_t i = 1; i <= steps; ++i) {
            const double d = unitDistance(points[i - 1], points[i == n ? 0 : i], unit);
            zeroSteps += d == 0.0 ? 1 : 0;
            const double next = stepOf(d) + sum;
            increasing = increasing && next > sum;
            s[i] = next;
            sum = next;
        }
    };
    // One loop per common exponent, so that the step is not a branch in it.
    if (alpha == 1.0)
        run([&](double d) { return d * back; });
    else if (alpha == 0.5)
        run([&](double d) { return std::sqrt(d) * backRoot; });
    else
        run([&](double d) {
            return alpha == 0.0 ? (d - d) + 1.0 : std::pow(d * back, alpha);
        }); // (d - d) + 1: NaN for a non-finite d
    return finishParameters(points, p, closed, std::move(s), zeroSteps > 0, increasing);
}

Result<std::vector<double>> chordParameters(std::span<const Point> points, bool closed, int &exponent)
{
    auto twoPasses = [&] {
        exponent = scaleExponent(points);
        return splineParameters(points, Parameterization::ChordLength, closed, exponent);
    };
    const std::size_t n = points.size();
    if (n < (closed ? 3u : 2u))
        return twoPasses();
    // The pass of splineParameters with the points as they are (2^-k = 1), finding beside it what
    // scaleExponent finds (the largest coordinate) and the smallest coordinate and coordinate
    // difference that are not 0. Scaling by a power of two is exact while every value stays normal,
    // and a correctly rounded square root halves an even power of two exactly: when, for that k,
    //   every coordinate c != 0 has |c| 2^-k >= 2^-1022 (c 2^-k is exact),
    //   every difference δ != 0 has |δ| >= 2^(max(k, 0) - 500) (δ² and (δ 2^-k)² are normal), and
    //   |k| <= 200 (no coordinate reaches 2^201, so no square overflows),
    // each step here is the scaled step times 2^k bit for bit, so the sums are the same. Otherwise
    // (huge, tiny or uneven coordinates, or not finite) the two passes as before.
    const double inf = std::numeric_limits<double>::infinity();
    auto nonzero = [inf](double a) { return a > 0.0 ? a : inf; };
    std::vector<double> s = largeVector<double>(closed ? n + 1 : n);
    s[0] = 0.0;
    const std::size_t steps = closed ? n : n - 1;
    double biggest = std::max(std::abs(points[0].x()), std::abs(points[0].y()));
    double smallest = std::min(nonzero(std::abs(points[0].x())), nonzero(std::abs(points[0].y())));
    double smallestStep = inf;
    std::size_t zeroSteps = 0;
    bool increasing = true;
    double sum = 0.0;
    for (std::size_t i = 1; i <= steps; ++i) {
        const Point &a = points[i - 1], &b = points[i == n ? 0 : i];
        const double bx = std::abs(b.x()), by = std::abs(b.y());
        biggest = std::max(biggest, std::max(bx, by));
        smallest = std::min(smallest, std::min(nonzero(bx), nonzero(by)));
        smallestStep =
            std::min(smallestStep, std::min(nonzero(std::abs(b.x() - a.x())), nonzero(std::abs(b.y() - a.y()))));
        const double d = unitDistance(a, b, 1.0);
        zeroSteps += d == 0.0 ? 1 : 0;
        const double next = d + sum;
        increasing = increasing && next > sum;
        s[i] = next;
        sum = next;
    }
    exponent = 0;
    if (biggest > 0.0 && std::isfinite(biggest)) {
        std::frexp(biggest, &exponent);
        exponent = std::clamp(exponent - 1, -1000, 1023); // as scaleExponent
    }
    const int k = exponent;
    const bool exact = std::isfinite(biggest) && std::isfinite(sum) && std::abs(k) <= 200 &&
                       (smallest == inf || smallest >= std::ldexp(1.0, k - 1022)) &&
                       (smallestStep == inf || smallestStep >= std::ldexp(1.0, std::max(k, 0) - 500));
    if (!exact)
        return twoPasses();
    return finishParameters(points, Parameterization::ChordLength, closed, std::move(s), zeroSteps > 0, increasing);
}

Result<Ok> checkStrictlyIncreasing(std::span<const double> values, const char *what)
{
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i]))
            return Error{ErrorCode::NonFiniteInput, std::string(what) + " " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
        if (i > 0 && !(values[i] > values[i - 1]))
            return Error{ErrorCode::InvalidArgument,
                         std::string(what) + " values must increase strictly (" + std::to_string(i - 1) + " and " +
                             std::to_string(i) + ")",
                         static_cast<int>(i)};
    }
    return Ok{};
}

namespace {

// Within 2^±200 every product the spline builders form (up to cubes of coordinates and parameter
// steps) stays far inside doubles: such input is computed as it is, with no copy scaled down and
// back (that pass cost a million-point natural spline 6 times its time). Only beyond it the input is
// scaled to unit size, which is exact (powers of two).
constexpr int kDirectExponent = 200;

UnitScale directWhereSafe(UnitScale u)
{
    if (std::abs(u.exponent) <= kDirectExponent && std::abs(u.paramExponent) <= kDirectExponent)
        return {};
    return u;
}

} // namespace

UnitScale unitScale(std::span<const Point> points, Parameterization p)
{
    return unitScale(scaleExponent(points), p);
}

UnitScale unitScale(int exponent, Parameterization p)
{
    UnitScale u;
    u.exponent = exponent & ~1; // even (rounded towards -inf), still within doubles
    const double alpha = exponentOf(p);
    u.paramExponent = alpha == 1.0 ? u.exponent : alpha == 0.5 ? u.exponent / 2 : 0;
    return directWhereSafe(u);
}

UnitScale unitScale(std::span<const Point> points, std::span<const double> parameters)
{
    UnitScale u;
    u.exponent = scaleExponent(points);
    double m = 0.0;
    for (double v : parameters)
        m = std::max(m, std::abs(v));
    if (m > 0.0 && std::isfinite(m)) {
        int e = 0;
        std::frexp(m, &e);
        u.paramExponent = std::clamp(e - 1, -1000, 1023);
    }
    return directWhereSafe(u);
}

std::vector<double> downParameters(std::span<const double> parameters, const UnitScale &scale)
{
    std::vector<double> out(parameters.begin(), parameters.end());
    for (double &v : out)
        v = std::ldexp(v, -scale.paramExponent);
    return out;
}

std::vector<Point> UnitScale::down(std::span<const Point> points) const
{
    std::vector<Point> out(points.begin(), points.end());
    const double f = std::ldexp(1.0, -exponent);
    for (Point &p : out)
        p *= f;
    return out;
}

Result<Ok> scaleBack(std::span<Point> values, int e)
{
    for (Point &v : values) {
        v = Point(std::ldexp(v.x(), e), std::ldexp(v.y(), e));
        if (!v.allFinite())
            return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    return Ok{};
}

Result<Ok> scaleBack(std::span<double> values, int e)
{
    for (double &v : values) {
        v = std::ldexp(v, e);
        if (!std::isfinite(v))
            return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    return Ok{};
}

Result<Ok> checkFinite(std::span<const Point> points)
{
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()))
            return Error{ErrorCode::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
    return Ok{};
}

Result<Ok> checkParametersAndPoints(std::span<const double> parameters, std::span<const Point> points)
{
    if (auto ok = checkStrictlyIncreasing(parameters, "parameter"); !ok)
        return ok;
    return checkFinite(points);
}

} // namespace kontur::geo
