// The global B-spline of seed 001 §1.2, solved in O(k) (see globalbspline.h).
#include "geometry/splines/globalbspline.h"

#include "geometry/splines/knots.h"
#include "geometry/splines/tridiagonal.h"

#include <array>
#include <cmath>
#include <string>

namespace kontur::geo {

std::vector<double> globalBSplineKnots(std::span<const double> v)
{
    const std::size_t k = v.size();
    if (k < 2)
        return {};
    const double h = (v[k - 1] - v[0]) / static_cast<double>(k - 1);
    std::vector<double> u(k + 6);
    for (std::size_t i = 0; i < 3; ++i)
        u[i] = v[0] - static_cast<double>(3 - i) * h;
    for (std::size_t i = 0; i < k; ++i)
        u[i + 3] = v[i];
    for (std::size_t i = k + 3; i < k + 6; ++i)
        u[i] = v[k - 1] + static_cast<double>(i - k - 2) * h;
    return u;
}

namespace {

// The three nonzero cubic basis values and first derivatives at t on span μ (N_{μ-3..μ}).
struct CubicBasisAt
{
    std::array<double, 4> n{};
    std::array<double, 4> d{};
};

CubicBasisAt cubicBasis(std::span<const double> u, int mu, double t)
{
    CubicBasisAt b;
    nonzeroBasisWithDerivatives(u, mu, 4, t, b.n, b.d);
    return b;
}

// Solves for the plain-basis control values B_0..B_{k+1} (T = double or Point).
template <typename T>
bool solveGlobal(std::span<const double> v, std::span<const double> u, std::span<const T> c, const T &dl, const T &dr,
                 std::vector<T> &out)
{
    const std::size_t k = v.size();
    out.resize(k + 2); // every entry is assigned below
    // Row i (value at v_i) touches B_i, B_{i+1}, B_{i+2}: span μ = i + 3 (the last knot uses the last
    // span μ = k + 1, where the entries are N_{k-1..k+1}).
    std::vector<double> a(k), b(k), cc(k);
    std::vector<T> rhs(c.begin(), c.end());
    std::array<double, 3> first{}, firstD{}, last{}, lastD{};
    for (std::size_t i = 0; i < k; ++i) {
        const bool end = i + 1 == k;
        const int mu = end ? static_cast<int>(k) + 1 : static_cast<int>(i) + 3;
        const CubicBasisAt nb = cubicBasis(u, mu, v[i]);
        // Entries for B_i, B_{i+1}, B_{i+2}: on span μ = i + 3 they are N_{i..i+2} = nb.n[0..2]
        // (nb.n[3] = N_{i+3}(v_i) = 0); on the last span N_{k-1..k+1} = nb.n[1..3].
        const std::size_t o = end ? 1 : 0;
        const std::array<double, 3> row{nb.n[o], nb.n[o + 1], nb.n[o + 2]};
        if (i == 0) {
            first = row;
            firstD = {nb.d[0], nb.d[1], nb.d[2]};
        }
        if (end) {
            last = row;
            lastD = {nb.d[1], nb.d[2], nb.d[3]};
        }
        // Unknowns x_j = B_{j+1}: row i has x_{i-1}, x_i, x_{i+1}.
        a[i] = row[0];
        b[i] = row[1];
        cc[i] = row[2];
    }
    // Eliminate B_0 from row 0 with the left derivative row, B_{k+1} from row k-1 with the right one.
    if (firstD[0] == 0.0 || lastD[2] == 0.0)
        return false;
    const double f0 = first[0] / firstD[0];
    const double fl = last[2] / lastD[2];
    if (k == 2) {
        // Both rows touch B_1, B_2 only: a 2×2 system.
        const double a00 = first[1] - f0 * firstD[1], a01 = first[2] - f0 * firstD[2];
        const double a10 = last[0] - fl * lastD[0], a11 = last[1] - fl * lastD[1];
        const T r0 = c[0] - f0 * dl, r1 = c[1] - fl * dr;
        const double det = a00 * a11 - a01 * a10;
        if (!(std::abs(det) > 0.0))
            return false;
        out[1] = (a11 * r0 - a01 * r1) / det;
        out[2] = (a00 * r1 - a10 * r0) / det;
    } else {
        b[0] = first[1] - f0 * firstD[1];
        cc[0] = first[2] - f0 * firstD[2];
        rhs[0] = c[0] - f0 * dl;
        a[k - 1] = last[0] - fl * lastD[0];
        b[k - 1] = last[1] - fl * lastD[1];
        rhs[k - 1] = c[k - 1] - fl * dr;
        if (!solveTridiagonal<T>(a, b, cc, rhs))
            return false;
        for (std::size_t j = 0; j < k; ++j)
            out[j + 1] = rhs[j];
    }
    out[0] = (dl - firstD[1] * out[1] - firstD[2] * out[2]) / firstD[0];
    out[k + 1] = (dr - lastD[0] * out[k - 1] - lastD[1] * out[k]) / lastD[2];
    return true;
}

} // namespace

Result<GlobalBSplineFunction> globalBSplineFunction(std::span<const double> v, std::span<const double> c, double dLeft,
                                                    double dRight)
{
    const std::size_t k = v.size();
    if (k < 2)
        return Error{ErrorCode::TooFewPoints, "a global B-spline needs at least 2 knots", static_cast<int>(k)};
    if (c.size() != k)
        return Error{ErrorCode::InvalidArgument, "one value per knot is needed", -1};
    if (auto ok = checkStrictlyIncreasing(v, "x"); !ok)
        return ok.error();
    for (std::size_t i = 0; i < k; ++i)
        if (!std::isfinite(c[i]))
            return Error{ErrorCode::NonFiniteInput, "value " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
    if (!std::isfinite(dLeft) || !std::isfinite(dRight))
        return Error{ErrorCode::NonFiniteInput, "an end derivative is not finite", -1};
    GlobalBSplineFunction g;
    g.knots = globalBSplineKnots(v);
    std::vector<double> plain;
    if (!solveGlobal<double>(v, g.knots, c, dLeft, dRight, plain))
        return Error{ErrorCode::IllConditioned, "the global B-spline system is singular", -1};
    g.coefficients.resize(k + 2);
    for (std::size_t j = 0; j < k + 2; ++j)
        g.coefficients[j] = plain[j] / bellScale(g.knots, static_cast<int>(j), 3);
    auto spline = bellSpline(g.knots, g.coefficients, 3);
    if (!spline)
        return spline.error();
    g.spline = std::move(spline).value();
    return g;
}

namespace {
Result<BSpline> globalUnit(std::span<const double> parameters, std::span<const Point> points, const Point &startTangent,
                           const Point &endTangent);

// A B-spline built on unit-size input, with its knots and control points scaled back (exact: powers of two).
Result<BSpline> scaledBack(Result<BSpline> unit, const UnitScale &scale)
{
    if (!unit)
        return unit;
    std::vector<double> knots = unit->knots();
    std::vector<Point> control = unit->controlPoints();
    if (auto ok = scaleBack(knots, scale.paramExponent); !ok)
        return ok.error();
    if (auto ok = scaleBack(control, scale.exponent); !ok)
        return ok.error();
    return BSpline::create(unit->order(), std::move(knots), std::move(control));
}
} // namespace

Result<BSpline> globalBSpline(std::span<const double> parameters, std::span<const Point> points,
                              const Point &startTangent, const Point &endTangent)
{
    const std::size_t k = points.size();
    if (k < 2)
        return Error{ErrorCode::TooFewPoints, "a global B-spline needs at least 2 points", static_cast<int>(k)};
    if (parameters.size() != k)
        return Error{ErrorCode::InvalidArgument, "one parameter per point is needed", -1};
    if (auto ok = checkParametersAndPoints(parameters, points); !ok)
        return ok.error();
    // Zero end derivatives are valid (as in the function form); only non-finite ones are refused.
    if (!startTangent.allFinite() || !endTangent.allFinite())
        return Error{ErrorCode::NonFiniteInput, "an end tangent is not finite", -1};
    // On points and parameters scaled to unit size by powers of two, then scaled back (knots.h).
    const UnitScale scale = unitScale(points, parameters);
    if (scale.identity())
        return globalUnit(parameters, points, startTangent, endTangent);
    const int te = -scale.tangentExponent();
    return scaledBack(globalUnit(downParameters(parameters, scale), scale.down(points),
                                 Point(std::ldexp(startTangent.x(), te), std::ldexp(startTangent.y(), te)),
                                 Point(std::ldexp(endTangent.x(), te), std::ldexp(endTangent.y(), te))),
                      scale);
}

namespace {

Result<BSpline> globalUnit(std::span<const double> parameters, std::span<const Point> points, const Point &startTangent,
                           const Point &endTangent)
{
    std::vector<double> u = globalBSplineKnots(parameters);
    std::vector<Point> b;
    if (!solveGlobal<Point>(parameters, u, points, startTangent, endTangent, b))
        return Error{ErrorCode::IllConditioned, "the global B-spline system is singular", -1};
    return BSpline::create(4, std::move(u), std::move(b));
}

} // namespace

Result<BSpline> globalBSpline(std::span<const Point> points, Parameterization param, const Point &startTangent,
                              const Point &endTangent)
{
    // Built on the points scaled to unit size and scaled back (UnitScale, knots.h).
    const UnitScale scale = unitScale(points, param);
    if (scale.identity()) {
        auto s = splineParameters(points, param);
        if (!s)
            return s.error();
        return globalBSpline(*s, points, startTangent, endTangent);
    }
    const std::vector<Point> unitPoints = scale.down(points);
    auto s = splineParameters(unitPoints, param);
    if (!s)
        return s.error();
    const int te = -scale.tangentExponent();
    return scaledBack(globalBSpline(*s, unitPoints,
                                    Point(std::ldexp(startTangent.x(), te), std::ldexp(startTangent.y(), te)),
                                    Point(std::ldexp(endTangent.x(), te), std::ldexp(endTangent.y(), te))),
                      scale);
}

} // namespace kontur::geo
