// Natural, clamped, not-a-knot and periodic cubic splines (see cubicspline.h).
#include "geometry/splines/cubicspline.h"

#include "geometry/largevector.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/tridiagonal.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>

namespace kontur::geo {

const char *nameOf(EndCondition c)
{
    switch (c) {
    case EndCondition::Natural:
        return "natural";
    case EndCondition::Clamped:
        return "clamped";
    case EndCondition::NotAKnot:
        return "not-a-knot";
    case EndCondition::Periodic:
        return "periodic";
    }
    return "natural";
}

bool parseEndCondition(std::string_view name, EndCondition &out)
{
    if (name == "natural")
        out = EndCondition::Natural;
    else if (name == "clamped")
        out = EndCondition::Clamped;
    else if (name == "not-a-knot")
        out = EndCondition::NotAKnot;
    else if (name == "periodic")
        out = EndCondition::Periodic;
    else
        return false;
    return true;
}

namespace {

// Runs `a` here and `b` on a new thread at once; false, having run neither, when no thread can be
// made (the caller then runs both itself).
template <typename A, typename B> bool onTwoThreads(A &a, B &b)
{
    std::thread other;
    try {
        other = std::thread([&b] { b(); });
    } catch (const std::system_error &) {
        return false;
    }
    a();
    other.join();
    return true;
}

template <typename T> T zeroValue()
{
    if constexpr (std::is_same_v<T, double>)
        return 0.0;
    else
        return T::Zero();
}

// Work a caller may hand to the open-end sweep, which is bound by the latency of its dependency
// chains and so has room for independent work beside them: copying the values (the spline's own
// copy of its points) as they are read, and checking that the solution is finite as it is formed,
// instead of two more passes over a million points.
template <typename T> struct CopyAndCheck
{
    T *copy = nullptr;    // receives v[i] for every i
    bool checked = false; // set when the sweep did both
    bool finite = true;   // every m[i] finite (valid when checked)
};

template <typename T>
bool derivatives(std::span<const double> s, std::span<const T> v, EndCondition end, const T &d0, const T &dn,
                 std::span<T> m, CopyAndCheck<T> *extra = nullptr)
{
    const std::size_t n = v.size();
    if (n < 2)
        return false;
    auto value = [&](std::size_t i) -> const T & { return v[i == n ? 0 : i]; };
    auto h = [&](std::size_t i) { return s[i + 1] - s[i]; };
    auto delta = [&](std::size_t i) -> T { return (value(i + 1) - value(i)) / h(i); };

    if (end == EndCondition::Periodic) {
        if (n < 3)
            return false;
        std::vector<double> a(n), b(n), c(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t prev = i == 0 ? n - 1 : i - 1; // segment before knot i
            const double hp = h(prev), hi = h(i);
            a[i] = hi;
            b[i] = 2.0 * (hp + hi);
            c[i] = hp;
            m[i] = 3.0 * (hi * delta(prev) + hp * delta(i));
        }
        return solveCyclicTridiagonal<T>(a, b, c, m);
    }

    if (end == EndCondition::NotAKnot && n <= 3) {
        // Too few knots for two distinct not-a-knot conditions: the line (n = 2) or the parabola through
        // the three points (n = 3), the unique C³ interpolant.
        if (n == 2) {
            m[0] = m[1] = delta(0);
            return true;
        }
        const double h0 = h(0), h1 = h(1);
        const T q = (delta(1) - delta(0)) / (h0 + h1);
        m[0] = delta(0) - h0 * q;
        m[1] = (h1 * delta(0) + h0 * delta(1)) / (h0 + h1);
        m[2] = delta(1) + h1 * q;
        return true;
    }

    // Open ends: rows 1..n-2 are the C² conditions, rows 0 and n-1 the end conditions. No matrix is
    // stored: row(i) builds a_i, b_i, c_i and r_i on demand. Solved by the two-ended ("twisted")
    // sweep: Thomas from the top and from the bottom at once, meeting in the middle (Hegland, "On
    // the parallel solution of tridiagonal systems by wrap-around partitioning", 1991). The two
    // recurrences are independent, so the processor runs both dependency chains side by side.
    struct Row
    {
        double a, b, c;
        T r;
    };
    auto row = [&](std::size_t i) -> Row {
        if (i == 0) {
            switch (end) {
            case EndCondition::Natural: // 2 m_0 + m_1 = 3 δ_0
                return {0.0, 2.0, 1.0, T(3.0 * delta(0))};
            case EndCondition::NotAKnot: { // de Boor (MATLAB spline.m)
                const double h0 = h(0), h1 = h(1);
                return {0.0, h1, h0 + h1, T(((h0 + 2.0 * (h0 + h1)) * h1 * delta(0) + h0 * h0 * delta(1)) / (h0 + h1))};
            }
            default: // clamped: m_0 = d0
                return {0.0, 1.0, 0.0, d0};
            }
        }
        if (i == n - 1) {
            switch (end) {
            case EndCondition::Natural: // m_{n-2} + 2 m_{n-1} = 3 δ_{n-2}
                return {1.0, 2.0, 0.0, T(3.0 * delta(n - 2))};
            case EndCondition::NotAKnot: {
                const double ha = h(n - 3), hb = h(n - 2), xn = ha + hb;
                return {xn, ha, 0.0, T((hb * hb * delta(n - 3) + (2.0 * xn + hb) * ha * delta(n - 2)) / xn)};
            }
            default:
                return {0.0, 1.0, 0.0, dn};
            }
        }
        const double hp = s[i] - s[i - 1], hi = s[i + 1] - s[i];
        const T dp = (v[i] - v[i - 1]) / hp, di = (v[i + 1] - v[i]) / hi;
        return {hi, 2.0 * (hp + hi), hp, T(3.0 * (hi * dp + hp * di))};
    };
    // Scratch for the eliminated off-diagonal, kept between calls (a dragged spline is rebuilt many
    // times a second; reusing it spares the page faults of a fresh allocation).
    thread_local std::vector<double> scratch;
    if (scratch.size() < n)
        scratch.resize(n);
    double *w = scratch.data();
    // Rows 0..k-1 from the top (x_i + w_i x_{i+1} = m_i), rows n-1..k+1 from the bottom
    // (x_i + w_i x_{i-1} = m_i), then row k joins them.
    const std::size_t k = n / 2;
    const T zero = zeroValue<T>();
    T *const copy = extra != nullptr ? extra->copy : nullptr;
    // What a sweep carries from row to row. Besides the eliminated off-diagonal and right-hand side,
    // the step and the divided difference it shares with the next row (a C² row needs the segments
    // on both sides of its knot): one division of the points per row instead of two, the same values
    // (the same expressions, s[i] - s[i-1] and (v[i] - v[i-1]) / h, either way). Each sweep runs on a
    // copy local to its thread (two threads writing to one cache line would stall each other).
    struct Sweep
    {
        std::size_t i; // the next row
        double h;      // the step it shares with the row before
        T d;           // the divided difference over that step
        double w;      // the row before's eliminated off-diagonal
        T g;           // and right-hand side
        bool finite;   // every pivot so far is not 0
    };
    // One elimination step, from the top (the row's a is the eliminated neighbour, c the next) or from
    // the bottom (the mirror: c eliminated, a next).
    auto eliminate = [&](Sweep &z, const Row &q, bool fromTop) {
        const std::size_t i = z.i;
        if (copy != nullptr)
            copy[i] = v[i];
        const double eliminated = fromTop ? q.a : q.c, next = fromTop ? q.c : q.a;
        const double pivot = q.b - eliminated * z.w;
        z.finite = z.finite && std::abs(pivot) > 0.0;
        const double inv = 1.0 / pivot;
        z.w = next * inv;
        z.g = (q.r - eliminated * z.g) * inv;
        w[i] = z.w;
        m[i] = z.g;
    };
    // The top sweep starts at row 0 and never reaches row n - 1; the bottom sweep the mirror.
    auto stepTop = [&](Sweep &z) {
        const std::size_t i = z.i;
        if (i == 0) {
            eliminate(z, row(i), true);
        } else {
            const double hp = z.h, hi = s[i + 1] - s[i];
            const T di = (v[i + 1] - v[i]) / hi;
            const Row q{hi, 2.0 * (hp + hi), hp, T(3.0 * (hi * z.d + hp * di))};
            z.h = hi;
            z.d = di;
            eliminate(z, q, true);
        }
        ++z.i;
    };
    auto stepBottom = [&](Sweep &z) {
        const std::size_t i = z.i;
        if (i == n - 1) {
            eliminate(z, row(i), false);
        } else {
            const double hp = s[i] - s[i - 1], hi = z.h;
            const T dp = (v[i] - v[i - 1]) / hp;
            const Row q{hi, 2.0 * (hp + hi), hp, T(3.0 * (hi * dp + hp * z.d))};
            z.h = hp;
            z.d = dp;
            eliminate(z, q, false);
        }
        --z.i;
    };
    const double h0 = s[1] - s[0], hn = s[n - 1] - s[n - 2]; // n >= 2 here
    Sweep top{0, h0, T((v[1] - v[0]) / h0), 0.0, zero, true};
    Sweep bottom{n - 1, hn, T((v[n - 1] - v[n - 2]) / hn), 0.0, zero, true};
    // The two halves share nothing until row k: on two threads for a large system (each half's
    // steps in the same order as on one, so the same bits), else interleaved on this one, one row
    // from each end per iteration, two independent dependency chains side by side.
    const bool twoThreads = n >= kSplineTwoThreadRows;
    auto sweepTop = [&] {
        Sweep z = top;
        while (z.i < k)
            stepTop(z);
        top = z;
    };
    auto sweepBottom = [&] {
        Sweep z = bottom;
        while (z.i > k)
            stepBottom(z);
        bottom = z;
    };
    if (!twoThreads || !onTwoThreads(sweepTop, sweepBottom)) {
        Sweep a = top, b = bottom;
        while (a.i < k && b.i > k) {
            stepTop(a);
            stepBottom(b);
        }
        top = a;
        bottom = b;
        sweepTop();
        sweepBottom();
    }
    {
        const Row q = row(k);
        const double wl = k > 0 ? w[k - 1] : 0.0, wr = k + 1 < n ? w[k + 1] : 0.0;
        const T gl = k > 0 ? T(m[k - 1]) : zero, gr = k + 1 < n ? T(m[k + 1]) : zero;
        const double pivot = q.b - q.a * wl - q.c * wr;
        if (!top.finite || !bottom.finite || !(std::abs(pivot) > 0.0))
            return false;
        m[k] = (q.r - q.a * gl - q.c * gr) / pivot;
        if (copy != nullptr)
            copy[k] = v[k];
    }
    // Back substitution outwards from row k, again both halves at once. 0·m is 0 for a finite m and
    // NaN otherwise: the probes (one per half, so neither waits on the other) find a non-finite one.
    T probeUp = m[k] * 0.0, probeDown = zero;
    std::size_t up = k, down = k;
    auto substituteUp = [&] {
        T probe = probeUp;
        for (std::size_t i = up; i-- > 0;) {
            m[i] = m[i] - w[i] * m[i + 1];
            probe += m[i] * 0.0;
        }
        up = 0;
        probeUp = probe;
    };
    auto substituteDown = [&] {
        T probe = probeDown;
        for (std::size_t i = down + 1; i < n; ++i) {
            m[i] = m[i] - w[i] * m[i - 1];
            probe += m[i] * 0.0;
        }
        down = n - 1;
        probeDown = probe;
    };
    if (!twoThreads || !onTwoThreads(substituteUp, substituteDown)) {
        T pu = probeUp, pd = probeDown;
        while (up > 0 && down + 1 < n) {
            --up;
            ++down;
            m[up] = m[up] - w[up] * m[up + 1];
            m[down] = m[down] - w[down] * m[down - 1];
            pu += m[up] * 0.0;
            pd += m[down] * 0.0;
        }
        probeUp = pu;
        probeDown = pd;
        substituteUp();
        substituteDown();
    }
    if (extra != nullptr) {
        extra->checked = copy != nullptr;
        extra->finite = probeUp + probeDown == zero;
    }
    return true;
}

} // namespace

bool cubicSplineDerivatives(std::span<const double> s, std::span<const Point> v, EndCondition end, const Point &d0,
                            const Point &dn, std::span<Point> m)
{
    return derivatives<Point>(s, v, end, d0, dn, m);
}

bool cubicSplineDerivatives(std::span<const double> s, std::span<const double> v, EndCondition end, double d0,
                            double dn, std::span<double> m)
{
    return derivatives<double>(s, v, end, d0, dn, m);
}

namespace {

// The parametric spline once parameters and points are known to be valid (the tangents are not).
Result<HermiteSpline> build(std::vector<double> parameters, std::span<const Point> points, EndCondition end,
                            const Point &startTangent, const Point &endTangent)
{
    const bool closed = end == EndCondition::Periodic;
    const std::size_t n = points.size();
    if (end == EndCondition::Clamped) {
        // A zero end derivative is valid (the curve leaves its end at speed zero, as the function
        // form's zero slope); only a non-finite one is refused.
        if (!startTangent.allFinite() || !endTangent.allFinite())
            return Error{ErrorCode::NonFiniteInput, "an end tangent is not finite", -1};
    }
    std::vector<Point> m = largeVector<Point>(n);
    // The spline's copy of the points, written by the sweep as it reads them (or copied after).
    std::vector<Point> copy = largeVector<Point>(n);
    CopyAndCheck<Point> extra{copy.data()};
    if (!derivatives<Point>(parameters, points, end, startTangent, endTangent, m, &extra))
        return Error{ErrorCode::IllConditioned, "the spline system is singular", -1};
    if (!extra.checked) {
        std::copy(points.begin(), points.end(), copy.begin());
        double sum = 0.0;
        for (const Point &t : m)
            sum += t.x() * 0.0 + t.y() * 0.0; // NaN exactly when some tangent is not finite
        extra.finite = sum == 0.0;
    }
    // Finite input can still overflow (coordinates near the largest double).
    if (!extra.finite)
        return Error{ErrorCode::NonFiniteInput, "the spline overflows: the coordinates are too large", -1};
    return HermiteSpline::fromChecked(std::move(parameters), std::move(copy), std::move(m), closed);
}

} // namespace

Result<HermiteSpline> cubicSpline(std::span<const Point> points, EndCondition end, Parameterization param,
                                  const Point &startTangent, const Point &endTangent)
{
    const bool closed = end == EndCondition::Periodic;
    if (closed && points.size() >= 2 && points.front() == points.back())
        points = points.first(points.size() - 1);
    // Built on the points scaled to unit size and scaled back (UnitScale, knots.h): the systems
    // square parameter steps, which would overflow at 1e160 and underflow at 1e-170.
    // Chord-length parameters come with the exponent from one pass over the points (knots.h).
    int exponent = 0;
    std::optional<Result<std::vector<double>>> chord;
    if (param == Parameterization::ChordLength)
        chord.emplace(chordParameters(points, closed, exponent));
    else
        exponent = scaleExponent(points);
    const UnitScale scale = unitScale(exponent, param);
    const std::vector<Point> unitPoints = scale.identity() ? std::vector<Point>() : scale.down(points);
    const std::span<const Point> work = scale.identity() ? points : std::span<const Point>(unitPoints);
    // Checks the points and the parameters (with the exponent known, one pass less).
    auto s = !scale.identity() ? splineParameters(work, param, closed)
             : chord           ? std::move(*chord)
                               : splineParameters(work, param, closed, exponent);
    if (!s)
        return s.error();
    const int te = -scale.tangentExponent();
    const Point t0(std::ldexp(startTangent.x(), te), std::ldexp(startTangent.y(), te));
    const Point t1(std::ldexp(endTangent.x(), te), std::ldexp(endTangent.y(), te));
    auto r = build(std::move(s).value(), work, end, t0, t1);
    if (!r || scale.identity())
        return r;
    return scaledBack(*r, scale, points);
}

Result<HermiteSpline> cubicSpline(std::vector<double> parameters, std::span<const Point> points, EndCondition end,
                                  const Point &startTangent, const Point &endTangent)
{
    const bool closed = end == EndCondition::Periodic;
    const std::size_t n = points.size();
    if (n < (closed ? 3u : 2u))
        return Error{ErrorCode::TooFewPoints,
                     closed ? "a periodic spline needs at least 3 points" : "a spline needs at least 2 points",
                     static_cast<int>(n)};
    if (parameters.size() != (closed ? n + 1 : n))
        return Error{ErrorCode::InvalidArgument, "one parameter per point is needed (one more when periodic)", -1};
    if (auto ok = checkParametersAndPoints(parameters, points); !ok)
        return ok.error();
    // On points and parameters scaled to unit size by powers of two, then scaled back (knots.h).
    const UnitScale scale = unitScale(points, parameters);
    if (scale.identity())
        return build(std::move(parameters), points, end, startTangent, endTangent);
    const std::vector<Point> unitPoints = scale.down(points);
    const int te = -scale.tangentExponent();
    auto r = build(downParameters(parameters, scale), unitPoints, end,
                   Point(std::ldexp(startTangent.x(), te), std::ldexp(startTangent.y(), te)),
                   Point(std::ldexp(endTangent.x(), te), std::ldexp(endTangent.y(), te)));
    if (!r)
        return r;
    return scaledBack(*r, scale, points);
}

Result<std::vector<double>> functionSplineSlopes(std::span<const double> x, std::span<const double> y, EndCondition end,
                                                 double startSlope, double endSlope)
{
    const std::size_t n = x.size();
    if (y.size() != n)
        return Error{ErrorCode::InvalidArgument, "one y per x is needed", -1};
    const std::size_t need = end == EndCondition::Periodic ? 4 : 2; // periodic: 3 distinct knots
    if (n < need)
        return Error{ErrorCode::TooFewPoints, "a function spline needs at least " + std::to_string(need) + " points",
                     static_cast<int>(n)};
    if (auto ok = checkStrictlyIncreasing(x, "x"); !ok)
        return ok.error();
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(y[i]))
            return Error{ErrorCode::NonFiniteInput, "y " + std::to_string(i) + " is not finite", static_cast<int>(i)};
    if (!std::isfinite(startSlope) || !std::isfinite(endSlope))
        return Error{ErrorCode::NonFiniteInput, "an end slope is not finite", -1};
    std::vector<double> m(n);
    bool ok = false;
    if (end == EndCondition::Periodic) {
        if (y[0] != y[n - 1])
            return Error{ErrorCode::InvalidArgument, "a periodic function spline needs y_0 = y_{n-1}",
                         static_cast<int>(n - 1)};
        // The knots x_0..x_{n-1} close onto themselves: n - 1 distinct values over one period.
        ok = cubicSplineDerivatives(x, y.first(n - 1), end, 0.0, 0.0, std::span<double>(m).first(n - 1));
        m[n - 1] = m[0];
    } else {
        ok = cubicSplineDerivatives(x, y, end, startSlope, endSlope, m);
    }
    if (!ok)
        return Error{ErrorCode::IllConditioned, "the spline system is singular", -1};
    return m;
}

Result<HermiteSpline> functionSpline(std::span<const double> x, std::span<const double> y, EndCondition end,
                                     double startSlope, double endSlope)
{
    auto m = functionSplineSlopes(x, y, end, startSlope, endSlope);
    if (!m)
        return m.error();
    return HermiteSpline::function(x, y, *m);
}

} // namespace kontur::geo
