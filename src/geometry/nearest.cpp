// Global nearest point on a Bézier curve (see nearest.h).
#include "geometry/nearest.h"

#include "geometry/bernstein.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kontur::geo {

namespace {

// |p - q|, without overflowing the difference at ±1e308. Where the sum of squares is well inside
// doubles (2^±960), sqrt(dx² + dy²) is within an ulp of the exact value like hypot, at a fraction of
// its cost (hypot was a fifth of a query's time): a square lost to underflow is below 2^-1074, under
// the sum's rounding. Outside that range, hypot, which neither overflows nor underflows.
double distanceTo(const Point &p, const Point &query)
{
    const double dx = p.x() - query.x(), dy = p.y() - query.y();
    const double squares = dx * dx + dy * dy;
    if (squares > 0x1p-960 && squares < 0x1p960)
        return std::sqrt(squares);
    const double d = std::hypot(dx, dy);
    return std::isfinite(d) ? d : 2.0 * std::hypot(0.5 * p.x() - 0.5 * query.x(), 0.5 * p.y() - 0.5 * query.y());
}

// D(t) = |B(t) − q|² of a cubic on a parameter interval, in the Bernstein basis of degree 6.
struct Piece
{
    double lo, hi;
    std::array<double, 7> d;
    double lower; // the smallest coefficient: D ≥ lower on the piece (convex hull property)
};

void setLower(Piece &p)
{
    p.lower = *std::min_element(p.d.begin(), p.d.end());
}

// The halves of a piece at its middle (de Casteljau).
void split(const Piece &p, Piece &left, Piece &right)
{
    std::array<double, 7> w = p.d;
    const double mid = 0.5 * (p.lo + p.hi);
    left.lo = p.lo;
    left.hi = mid;
    right.lo = mid;
    right.hi = p.hi;
    left.d[0] = w[0];
    right.d[6] = w[6];
    for (int level = 1; level <= 6; ++level) {
        for (int i = 0; i + level <= 6; ++i)
            w[i] = 0.5 * (w[i] + w[i + 1]);
        left.d[level] = w[0];
        right.d[6 - level] = w[6 - level];
    }
    setLower(left);
    setLower(right);
}

// The scaled cubic relative to the query in power form: X(t) = ((a t + b) t + c) t + d per axis.
struct Power
{
    Point a, b, c, d;
    Point at(double t) const { return ((a * t + b) * t + c) * t + d; }
    Point velocity(double t) const { return (3.0 * a * t + 2.0 * b) * t + c; }
    Point acceleration(double t) const { return 6.0 * a * t + 2.0 * b; }
};

// The minimum of D inside a piece where D is convex and D' changes sign: Newton on
// D'/2 = (B − q)·B' with the global cubic (full precision), kept inside the piece's bracket.
double convexMinimum(const Power &f, double lo, double hi)
{
    double t = 0.5 * (lo + hi);
    for (int iter = 0; iter < 60; ++iter) {
        const Point r = f.at(t), v = f.velocity(t);
        const double g = r.dot(v);
        const double dg = v.squaredNorm() + r.dot(f.acceleration(t));
        if (g == 0.0)
            return t;
        if (g < 0.0)
            lo = t;
        else
            hi = t;
        double next = dg > 0.0 ? t - g / dg : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 2.0 * std::numeric_limits<double>::epsilon() ||
            hi - lo <= 4.0 * std::numeric_limits<double>::epsilon())
            return next;
        t = next;
    }
    return t;
}

} // namespace

namespace detail {

Nearest nearestByRoots(const Bezier &curve, const Point &query)
{
    const std::vector<Point> &c = curve.controlPoints();
    Nearest best;
    if (c.empty()) {
        best.distance = std::hypot(query.x(), query.y());
        return best;
    }
    auto consider = [&](double t, const Point &p) {
        const double d = distanceTo(p, query);
        if (d < best.distance || (d == best.distance && t < best.t)) {
            best.t = t;
            best.point = p;
            best.distance = d;
        }
    };
    best.t = 0.0;
    best.point = c.front();
    best.distance = distanceTo(c.front(), query);
    if (c.size() == 1)
        return best;
    consider(1.0, c.back());

    // f(t) = (B(t) - q)·B'(t) in the Bernstein basis of degree 2n - 1: the product rule per axis.
    // Its roots do not depend on the scale, its products do (overflow above ~1e154, underflow below
    // ~1e-162): the curve is taken relative to the query and scaled to unit size by a power of two.
    double mag = 0.0;
    for (const Point &p : c)
        mag = std::max(mag, (0.5 * p - 0.5 * query).cwiseAbs().maxCoeff());
    if (!(mag > 0.0) || !std::isfinite(mag))
        return best;
    int e = 0;
    std::frexp(mag, &e);
    std::vector<double> xs(c.size()), ys(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
        xs[i] = std::ldexp(0.5 * c[i].x() - 0.5 * query.x(), -e);
        ys[i] = std::ldexp(0.5 * c[i].y() - 0.5 * query.y(), -e);
    }
    std::vector<double> f = bernsteinProduct(xs, bernsteinDerivative(xs));
    const std::vector<double> fy = bernsteinProduct(ys, bernsteinDerivative(ys));
    for (std::size_t k = 0; k < f.size(); ++k)
        f[k] += fy[k];
    std::vector<double> roots;
    bernsteinRoots(f, roots, true);
    for (double t : roots)
        if (t > 0.0 && t < 1.0)
            consider(t, curve.eval(t));
    return best;
}

} // namespace detail

// A cubic (the curves Kontur draws are made of them): branch and bound on D(t) = |B(t) − q|² in
// the Bernstein basis. A piece whose smallest coefficient is not below the best distance found so
// far cannot hold the nearest point and is dropped without finding its roots; a piece where D is
// monotone has its minimum at an end (already a candidate); a piece where D is convex has one
// minimum, found by bracketed Newton; any other piece is halved, its middle becoming a candidate.
// The coefficients tighten quadratically as pieces shrink, so a few halvings settle most queries
// (Bernstein bounds: Farouki & Rajan 1987; subdivision for curve–point distance: Chen et al.,
// "Computing the minimum distance between a point and a cubic Bézier curve", 2007). Rare pieces
// that do not settle (a query at the centre of a circular arc: D nearly constant) fall back to the
// root finder, which is exact for every degree.
Nearest nearest(const Bezier &curve, const Point &query)
{
    const std::vector<Point> &c = curve.controlPoints();
    if (c.size() != 4)
        return detail::nearestByRoots(curve, query);
    double mag = 0.0;
    for (const Point &p : c)
        mag = std::max(mag, (0.5 * p - 0.5 * query).cwiseAbs().maxCoeff());
    if (!(mag > 0.0) || !std::isfinite(mag))
        return detail::nearestByRoots(curve, query);
    int e = 0;
    std::frexp(mag, &e);
    std::array<Point, 4> u;
    for (std::size_t i = 0; i < 4; ++i)
        u[i] =
            Point(std::ldexp(0.5 * c[i].x() - 0.5 * query.x(), -e), std::ldexp(0.5 * c[i].y() - 0.5 * query.y(), -e));
    auto dot = [&](int i, int j) { return u[i].dot(u[j]); };
    Piece whole{0.0, 1.0, {}, 0.0};
    whole.d = {dot(0, 0),
               dot(0, 1),
               (6.0 * dot(0, 2) + 9.0 * dot(1, 1)) / 15.0,
               (2.0 * dot(0, 3) + 18.0 * dot(1, 2)) / 20.0,
               (6.0 * dot(1, 3) + 9.0 * dot(2, 2)) / 15.0,
               dot(2, 3),
               dot(3, 3)};
    setLower(whole);
    const Power f{u[3] - u[0] + 3.0 * (u[1] - u[2]), 3.0 * (u[0] - 2.0 * u[1] + u[2]), 3.0 * (u[1] - u[0]), u[0]};

    // Candidates are compared by their distance computed from the curve itself, as nearestByRoots
    // does, so both agree; the coefficients only decide what need not be looked at.
    Nearest best;
    best.t = 0.0;
    best.point = c.front();
    best.distance = distanceTo(c.front(), query);
    double bestD = whole.d[0];
    auto consider = [&](double t) {
        const Point p = t == 1.0 ? c.back() : curve.eval(t);
        const double d = distanceTo(p, query);
        if (d < best.distance || (d == best.distance && t < best.t)) {
            best = {t, p, d};
        }
        const Point r = f.at(t);
        bestD = std::min(bestD, r.squaredNorm());
    };
    consider(1.0);

    constexpr int kStack = 64, kSteps = 96;
    std::array<Piece, kStack> stack;
    int size = 0;
    stack[size++] = whole;
    for (int steps = 0; size > 0; ++steps) {
        if (steps == kSteps || size + 2 > kStack)
            return detail::nearestByRoots(curve, query);
        const Piece p = stack[--size];
        if (p.lower > bestD)
            continue;
        bool rising = true, falling = true, convex = true;
        for (int i = 0; i < 6; ++i) {
            rising = rising && p.d[i + 1] >= p.d[i];
            falling = falling && p.d[i + 1] <= p.d[i];
            if (i < 5)
                convex = convex && p.d[i + 2] - 2.0 * p.d[i + 1] + p.d[i] >= 0.0;
        }
        if (rising || falling)
            continue; // the minimum over the piece is at an end, a candidate already
        if (convex) {
            consider(convexMinimum(f, p.lo, p.hi));
            continue;
        }
        Piece left, right;
        split(p, left, right);
        // The middle's D is left.d[6]: a middle that cannot be nearer (beyond rounding) is not
        // evaluated (hypot is the dearest step here).
        if (left.d[6] <= bestD * (1.0 + 1e-9))
            consider(left.hi);
        // The piece with the lower bound nearer the best is looked at first.
        if (left.lower < right.lower) {
            stack[size++] = right;
            stack[size++] = left;
        } else {
            stack[size++] = left;
            stack[size++] = right;
        }
    }
    return best;
}

} // namespace kontur::geo
