// Arc length by adaptive Gauss–Kronrod quadrature (see arclength.h).
//
// Method: the speed |B'(t)| is integrated with the 7-point Gauss / 15-point Kronrod pair (QUADPACK
// qk15, Piessens et al. 1983). The 15-point result is kept when |K15 - G7| is within the interval's
// share of the accuracy (conservative: K15 is far more accurate than G7 on smooth integrands);
// otherwise the interval is halved and the halves share the accuracy (see refine), so the
// accepted error estimates add up to at most the accuracy asked.
// The speed is smooth except near a cusp where it touches zero (a kink like |t - t0|), where a
// quadrature error estimate can be fooled: when the hodograph's control points do not lie strictly
// on one side of a line through the origin (so the speed may get close to zero), the interval is
// first cut at the minima of the speed (rising roots of B'·B''), making every piece smooth.
#include "geometry/arclength.h"

#include "geometry/bernstein.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kontur::geo {

namespace {

// QUADPACK qk15 nodes and weights on [-1, 1] (the positive half; node 7 is 0).
constexpr std::array<double, 8> kXgk = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                        0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> kWgk = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss 7-point weights for the nodes kXgk[1], kXgk[3], kXgk[5], kXgk[7].
constexpr std::array<double, 4> kWg = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// The hodograph with a fixed buffer for degree <= 16; speed(t) = |H(t)| by de Casteljau.
struct Hodograph
{
    std::vector<Point> h;

    double speed(double t) const
    {
        const std::size_t n = h.size();
        std::array<Point, 16> w;
        if (n > w.size())
            return Bezier(h).eval(t).norm();
        std::copy(h.begin(), h.end(), w.begin());
        const double s = 1.0 - t;
        for (std::size_t level = n - 1; level > 0; --level)
            for (std::size_t i = 0; i < level; ++i)
                w[i] = s * w[i] + t * w[i + 1];
        return w[0].norm();
    }
};

// Specialised speed of a cubic: the quadratic hodograph in power form a t² + b t + c.
struct CubicSpeed
{
    Point a, b, c;
    double speed(double t) const { return ((a * t + b) * t + c).norm(); }
};

template <typename F> double gk15(const F &f, double lo, double hi, double &error)
{
    const double centre = 0.5 * (lo + hi);
    const double half = 0.5 * (hi - lo);
    const double fc = f.speed(centre);
    double kronrod = fc * kWgk[7];
    double gauss = fc * kWg[3];
    for (int j = 0; j < 7; ++j) {
        const double dx = half * kXgk[j];
        const double sum = f.speed(centre - dx) + f.speed(centre + dx);
        kronrod += kWgk[j] * sum;
        if (j % 2 == 1)
            gauss += kWg[j / 2] * sum;
    }
    error = std::abs((kronrod - gauss) * half);
    return kronrod * half;
}

// Refines [lo, hi] whose K15 value and error estimate are known until the error is within
// `accuracy`. The budget is shared where it is needed: when one half is already good enough, the
// other half may use what that half left over (the estimates still add up to <= accuracy).
template <typename F>
double refine(const F &f, double lo, double hi, double accuracy, double value, double error, int depth)
{
    // 50 halvings reach intervals of 1e-15: below that the integrand cannot be resolved anyway.
    if (error <= accuracy || depth >= 50)
        return value;
    const double mid = 0.5 * (lo + hi);
    double el = 0.0, er = 0.0;
    const double vl = gk15(f, lo, mid, el);
    const double vr = gk15(f, mid, hi, er);
    if (el + er <= accuracy)
        return vl + vr;
    if (el <= 0.5 * accuracy)
        return vl + refine(f, mid, hi, accuracy - el, vr, er, depth + 1);
    if (er <= 0.5 * accuracy)
        return refine(f, lo, mid, accuracy - er, vl, el, depth + 1) + vr;
    return refine(f, lo, mid, 0.5 * accuracy, vl, el, depth + 1) +
           refine(f, mid, hi, 0.5 * accuracy, vr, er, depth + 1);
}

template <typename F> double adaptive(const F &f, double lo, double hi, double accuracy, int depth)
{
    double error = 0.0;
    const double value = gk15(f, lo, hi, error);
    return refine(f, lo, hi, accuracy, value, error, depth);
}

double segmentDistanceToOrigin(const Point &a, const Point &b)
{
    const Point ab = b - a;
    const double len2 = ab.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp(-a.dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + u * ab).norm();
}

// True when the speed is bounded away from zero, so the integrand is smooth: the hodograph lies in
// the convex hull of its control points, so a hull that keeps a margin from the origin proves it.
// Exact hull distance for a cubic's triangle; for other degrees, a separating line through the
// origin with the mean direction as its normal.
bool speedBoundedAway(const std::vector<Point> &h)
{
    double maxNorm = 0.0;
    for (const Point &p : h)
        maxNorm = std::max(maxNorm, p.norm());
    const double margin = 0.05 * maxNorm;
    if (!(maxNorm > 0.0))
        return false;
    if (h.size() == 3) {
        auto cross = [](const Point &a, const Point &b) { return a.x() * b.y() - a.y() * b.x(); };
        const double c0 = cross(h[0], h[1]), c1 = cross(h[1], h[2]), c2 = cross(h[2], h[0]);
        const bool inside = (c0 >= 0.0 && c1 >= 0.0 && c2 >= 0.0) || (c0 <= 0.0 && c1 <= 0.0 && c2 <= 0.0);
        if (inside)
            return false;
        const double d = std::min({segmentDistanceToOrigin(h[0], h[1]), segmentDistanceToOrigin(h[1], h[2]),
                                   segmentDistanceToOrigin(h[2], h[0])});
        return d > margin;
    }
    Point d = Point::Zero();
    for (const Point &p : h)
        d += p;
    const double dn = d.norm();
    if (dn == 0.0)
        return false;
    for (const Point &p : h)
        if (p.dot(d) <= margin * dn)
            return false;
    return true;
}

// The Bernstein coefficients of B'·B'' = (|B'|²)'/2, whose rising roots are the speed's minima.
std::vector<double> speedSquaredSlope(const CubicSpeed &f, const std::vector<Point> &)
{
    // H = a t² + b t + c, H' = 2a t + b: H·H' = 2|a|² t³ + 3 a·b t² + (|b|² + 2 a·c) t + b·c,
    // converted from the power to the Bernstein basis of degree 3.
    const double p0 = f.b.dot(f.c);
    const double p1 = f.b.squaredNorm() + 2.0 * f.a.dot(f.c);
    const double p2 = 3.0 * f.a.dot(f.b);
    const double p3 = 2.0 * f.a.squaredNorm();
    return {p0, p0 + p1 / 3.0, p0 + 2.0 * p1 / 3.0 + p2 / 3.0, p0 + p1 + p2 + p3};
}

std::vector<double> speedSquaredSlope(const Hodograph &, const std::vector<Point> &h)
{
    std::vector<double> xs(h.size()), ys(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
        xs[i] = h[i].x();
        ys[i] = h[i].y();
    }
    std::vector<double> g = bernsteinProduct(xs, bernsteinDerivative(xs));
    const std::vector<double> gy = bernsteinProduct(ys, bernsteinDerivative(ys));
    for (std::size_t i = 0; i < g.size(); ++i)
        g[i] += gy[i];
    return g;
}

template <typename F> double integrate(const F &f, const std::vector<Point> &h, double t0, double t1, double accuracy)
{
    if (speedBoundedAway(h))
        return adaptive(f, t0, t1, accuracy, 0);
    // Cut at the minima of the speed: rising roots of (|B'|²)'/2 = B'·B''.
    const std::vector<double> g = speedSquaredSlope(f, h);
    std::vector<double> cuts;
    bernsteinRoots(g, cuts, true);
    std::vector<double> pts{t0};
    for (double c : cuts)
        if (c > t0 && c < t1)
            pts.push_back(c);
    pts.push_back(t1);
    const double share = accuracy / static_cast<double>(pts.size() - 1);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        sum += adaptive(f, pts[i], pts[i + 1], share, 0);
    return sum;
}

double polygonLength(const Bezier &curve)
{
    double len = 0.0;
    const auto &c = curve.controlPoints();
    for (std::size_t i = 0; i + 1 < c.size(); ++i)
        len += (c[i + 1] - c[i]).norm();
    return len;
}

} // namespace

double arcLength(const Bezier &curve, double t0, double t1, double accuracy)
{
    if (curve.isEmpty() || t0 == t1)
        return 0.0;
    if (t1 < t0)
        return -arcLength(curve, t1, t0, accuracy);
    if (!(accuracy > 0.0) || !std::isfinite(accuracy))
        accuracy = 1e-9 * std::max(polygonLength(curve), std::numeric_limits<double>::min());
    const std::vector<Point> &c = curve.controlPoints();
    if (c.size() == 2)
        return (c[1] - c[0]).norm() * (t1 - t0);
    const std::vector<Point> h = curve.derivativeCurve(1).controlPoints();
    if (c.size() == 4) {
        // H(t) = (1-t)² h0 + 2(1-t)t h1 + t² h2 = c + b t + a t² (power form: 2 multiply-adds per axis).
        const CubicSpeed f{h[0] - 2.0 * h[1] + h[2], 2.0 * (h[1] - h[0]), h[0]};
        return integrate(f, h, t0, t1, accuracy);
    }
    return integrate(Hodograph{h}, h, t0, t1, accuracy);
}

double arcLength(const Bezier &curve, double accuracy)
{
    return arcLength(curve, 0.0, 1.0, accuracy);
}

double parameterAtLength(const Bezier &curve, double length, double accuracy)
{
    if (curve.isEmpty() || length <= 0.0)
        return 0.0;
    if (!(accuracy > 0.0) || !std::isfinite(accuracy))
        accuracy = 1e-9 * std::max(polygonLength(curve), std::numeric_limits<double>::min());
    // Each partial integral gets 1/64 of the accuracy; at most 32 of them are summed, so the
    // accumulated length is within accuracy/2, and iteration stops within the other half.
    const double piece = accuracy / 64.0;
    const double total = arcLength(curve, 0.0, 1.0, piece);
    if (length >= total)
        return 1.0;
    const Bezier hodograph = curve.derivativeCurve(1);
    double lo = 0.0, hi = 1.0;
    double t = length / total; // the guess for constant speed
    double at = arcLength(curve, 0.0, t, piece);
    for (int iter = 0; iter < 31; ++iter) {
        const double diff = at - length;
        if (std::abs(diff) <= 0.5 * accuracy)
            break;
        if (diff > 0.0)
            hi = t;
        else
            lo = t;
        // Newton on L(t) - length, with L'(t) = |B'(t)|, kept inside the bracket by bisection.
        const double speed = hodograph.eval(t).norm();
        double next = speed > 0.0 ? t - diff / speed : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        at += arcLength(curve, t, next, piece);
        t = next;
    }
    return t;
}

} // namespace kontur::geo
