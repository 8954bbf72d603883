// Arc length by adaptive Gauss–Kronrod quadrature (see arclength.h).
//
// Work is bounded: the accuracy is raised to what doubles resolve for the curve (resolvableAccuracy)
// and the refinement is globally adaptive under a budget of rules (see adaptive), on the hodograph
// scaled to unit size by a power of two, so its cost does not depend on the curve's magnitude.
// Method: the speed |B'(t)| is integrated with the 7-point Gauss / 15-point Kronrod pair (QUADPACK
// qk15, Piessens et al. 1983), |K15 - G7| taken as each piece's error (conservative: K15 is far more
// accurate than G7 on smooth integrands); the piece with the largest estimate is halved until the
// estimates add up to at most the accuracy asked (QUADPACK qag's global strategy).
// The error estimate can be fooled where the speed is not smooth on the scale of a piece: at a cusp
// (a kink like |t - t0|) and where the speed merely dips (its square root has branch points near the
// real axis). For a cubic these branch points are known exactly (branchPointCuts), and the interval
// is first cut at them and graded away from them so that every rule sees an integrand analytic well
// beyond its piece. For other degrees, when the hodograph's control points do not lie strictly on one
// side of a line through the origin (so the speed may get close to zero), the interval is cut at
// the minima of the speed (rising roots of B'·B'') and graded away from sharp ones (gradedCuts).
#include "geometry/arclength.h"

#include "geometry/bernstein.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <span>

namespace kontur::geo {

namespace {

thread_local std::uint64_t t_evaluations = 0;

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
    double acceleration(double t, const std::vector<Point> &hodograph) const
    {
        std::vector<Point> d(hodograph.size() - 1);
        for (std::size_t i = 0; i + 1 < hodograph.size(); ++i)
            d[i] = static_cast<double>(d.size()) * (hodograph[i + 1] - hodograph[i]);
        return d.empty() ? 0.0 : Bezier(d).eval(t).norm();
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
    t_evaluations += 15;
    error = std::abs((kronrod - gauss) * half);
    return kronrod * half;
}

struct Piece
{
    double lo, hi, value, error;
    bool operator<(const Piece &o) const { return error < o.error; } // max-heap on the error
};

struct Integral
{
    double value = 0.0;
    double error = 0.0;
};

// Globally adaptive quadrature (QUADPACK qag): the piece with the largest error estimate is halved
// until the estimates add up to at most `accuracy` or `budget` rules have been spent. Unlike a local
// recursion that halves every piece to its own share, the work cannot run away when the accuracy is
// near the rounding of the integrand: the budget bounds it, and the sum of the estimates says what
// was reached. A piece too short to halve in doubles keeps its estimate.
template <typename F> Integral adaptive(const F &f, std::span<const double> cuts, double accuracy, int &budget)
{
    Integral total;
    // The first rules on the stack: most lengths are done after them (no allocation then).
    constexpr std::size_t kInline = 8;
    std::array<Piece, kInline> first;
    std::vector<Piece> heap;
    const std::size_t count = cuts.size() - 1;
    Piece *pieces = first.data();
    if (count > kInline) {
        heap.resize(count);
        pieces = heap.data();
    }
    for (std::size_t i = 0; i < count; ++i) {
        double error = 0.0;
        const double value = gk15(f, cuts[i], cuts[i + 1], error);
        --budget;
        pieces[i] = {cuts[i], cuts[i + 1], value, error};
        total.error += error;
        total.value += value;
    }
    if (total.error <= accuracy || budget < 2)
        return total;
    if (count <= kInline)
        heap.assign(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(count));
    std::make_heap(heap.begin(), heap.end());
    double settled = 0.0, settledError = 0.0; // pieces that cannot be halved any more
    while (total.error > accuracy && budget >= 2 && !heap.empty()) {
        std::pop_heap(heap.begin(), heap.end());
        const Piece p = heap.back();
        heap.pop_back();
        const double mid = 0.5 * (p.lo + p.hi);
        if (!(mid > p.lo && mid < p.hi)) {
            settled += p.value;
            settledError += p.error;
            continue;
        }
        double el = 0.0, er = 0.0;
        const double vl = gk15(f, p.lo, mid, el);
        const double vr = gk15(f, mid, p.hi, er);
        budget -= 2;
        heap.push_back({p.lo, mid, vl, el});
        std::push_heap(heap.begin(), heap.end());
        heap.push_back({mid, p.hi, vr, er});
        std::push_heap(heap.begin(), heap.end());
        // Recomputed, not updated by differences, so rounding cannot drift the stopping test.
        total.error = settledError;
        for (const Piece &q : heap)
            total.error += q.error;
    }
    total.value = settled;
    for (const Piece &q : heap)
        total.value += q.value;
    return total;
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

// Cuts graded towards a sharp minimum of the speed at `tm`. Near it the speed is
// √(m² + k²(t − tm)²) to second order (m the minimum, k = |B''(tm)|, as B'·B'' = 0 there): a kink
// rounded over a width w = m/k. A rule over a piece much longer than w samples the rounding with its
// two nodes nearest tm at most, and where both miss it |K15 − G7| misses it too (seen: errors
// 340 times the estimate on random cubics). Pieces [tm ± w·4ʲ, tm ± w·4ʲ⁺¹] see the rounding at
// their own scale, where the integrand is analytic in a region proportional to the piece, so the
// estimate holds again (graded meshes for a near-singularity: Davis & Rabinowitz, Methods of
// Numerical Integration, 2nd ed. 1984, §2.12). A true cusp (m = 0) needs none: the speed is smooth
// on each side of it.
template <typename F>
void gradedCuts(const F &f, const std::vector<Point> &h, double tm, double lo, double hi, std::vector<double> &pts)
{
    const double m = f.speed(tm);
    const double k = f.acceleration(tm, h);
    if (!(m > 0.0) || !(k > 0.0))
        return;
    const double w = m / k;
    for (double step = w; tm - step > lo && step < 0.25 * (tm - lo); step *= 4.0)
        pts.push_back(tm - step);
    for (double step = w; tm + step < hi && step < 0.25 * (hi - tm); step *= 4.0)
        pts.push_back(tm + step);
}

// Cuts for a cubic from the singularities of its speed. With the hodograph in power form
// H(t) = a t² + b t + c, |H|² = (Hx + i Hy)(Hx − i Hy), so the speed's only singularities in the
// complex plane are the roots of the complex quadratic P(t) = (ax + i ay) t² + (bx + i by) t +
// (cx + i cy) and their conjugates (branch points of the square root; a real root is a cusp). A
// Gauss rule on a piece converges like ρ^(−2n), ρ the sum of the semi-axes of the largest ellipse
// with foci at the piece's ends free of singularities (Trefethen, "Is Gauss quadrature better than
// Clenshaw–Curtis?", SIAM Review 50 (2008), Theorem 4.5). When ρ is small, G7 and K15 err alike and
// |K15 − G7| can be far below the true error (seen: 340 times on random cubics whose speed merely
// dips). Every piece is therefore made to have ρ ≥ about 3 before the rules start: at the branch
// point's nearest parameter p, and graded away from it at distances s·4ʲ (s its distance from p),
// where each piece sees the singularity at its own scale.
// ρ = α + √(α² − 1) with α = (|ζ − 1| + |ζ + 1|)/2 the semi-major axis of the ellipse with foci ±1
// through ζ = (z − mid)/half (the same value as |ζ ± √(ζ² − 1)|, without a complex square root).
// Squares, not hypot (a library call, a fifth of a length's time): z is a root of a unit-sized
// hodograph, and a square that overflows (|ζ| beyond 1e154) gives ρ = ∞, which is what such a far
// root means here.
double ellipseRho(std::complex<double> z, double lo, double hi)
{
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    const double x = (z.real() - mid) / half, y = z.imag() / half;
    const double alpha = 0.5 * (std::sqrt((x - 1.0) * (x - 1.0) + y * y) + std::sqrt((x + 1.0) * (x + 1.0) + y * y));
    return alpha + std::sqrt(std::max(0.0, alpha * alpha - 1.0));
}

bool isZero(std::complex<double> z)
{
    return z.real() == 0.0 && z.imag() == 0.0;
}

void branchPointCuts(const CubicSpeed &f, double t0, double t1, double accuracy, std::vector<double> &pts)
{
    using C = std::complex<double>;
    const C a(f.a.x(), f.a.y()), b(f.b.x(), f.b.y()), c(f.c.x(), f.c.y());
    std::array<C, 2> roots;
    std::size_t count = 0;
    if (!isZero(a)) {
        // The stable quadratic formula: q = −(b + σ√(b² − 4ac))/2 with σ making |q| largest.
        const C d = detail::principalSqrt(b * b - 4.0 * a * c); // (std::sqrt calls hypot)
        const C q = -0.5 * (std::real(std::conj(b) * d) >= 0.0 ? b + d : b - d);
        roots[count++] = q / a;
        if (!isZero(q))
            roots[count++] = c / q;
    } else if (!isZero(b)) {
        roots[count++] = -c / b;
    }
    constexpr double kRho = 3.0;
    for (std::size_t i = 0; i < count; ++i) {
        const C z = roots[i];
        if (!std::isfinite(z.real()) || !std::isfinite(z.imag()) || ellipseRho(z, t0, t1) >= kRho)
            continue;
        // No slivers: a cut within 1e-9 of the interval from its end, or a graded cut nearer the end
        // than half its distance from p, is left out (the piece beside it is extended instead), so
        // that rounding (a curve scaled by 1e-6, say) cannot add a rule or take one away.
        const double sliver = 1e-9 * (t1 - t0);
        const double p = std::clamp(z.real(), t0, t1);
        const double s = std::sqrt(std::norm(z - p)); // (no hypot: see ellipseRho)
        if (p - t0 > sliver && t1 - p > sliver)
            pts.push_back(p);
        // A cusp (s = 0): the speed is |t − p| times a smooth function, smooth on each side of p.
        // Rounding moves a cusp's branch point off the axis (by ~√ε where the two roots nearly meet),
        // so a tiny s is taken as a cusp when that cannot be seen: the speed k√(s² + u²) (u = t − p,
        // k = |H'(p)|) exceeds k|u| by k s²/(√(s² + u²) + |u|), whose integral over the interval is
        // below k s² (ln(2(t1 − t0)/s) + 1) on each side, and so is what a rule misses of it.
        const double k = (2.0 * f.a * p + f.b).norm();
        if (!(s > 0.0) || 2.0 * k * s * s * (std::log(2.0 * (t1 - t0) / s) + 1.0) <= 0.01 * accuracy)
            continue;
        for (double d = s; t1 - (p + d) > 0.5 * d; d *= 4.0)
            pts.push_back(p + d);
        for (double d = s; (p - d) - t0 > 0.5 * d; d *= 4.0)
            pts.push_back(p - d);
    }
    std::sort(pts.begin(), pts.end());
}

Integral integrate(const CubicSpeed &f, const std::vector<Point> &, double t0, double t1, double accuracy, int &budget)
{
    // The cuts' storage is kept between calls (a length is a fraction of a microsecond, of which an
    // allocation and its release were a tenth); nothing here calls back into integrate.
    thread_local std::vector<double> pts;
    pts.assign(1, t0);
    branchPointCuts(f, t0, t1, accuracy, pts);
    pts.push_back(t1);
    // Cuts from the two roots at one point (a real quadratic times a direction has conjugate roots)
    // differ by rounding: one cut, and none within a sliver of the end.
    const double sliver = 1e-9 * (t1 - t0);
    std::size_t kept = 1;
    for (std::size_t i = 1; i < pts.size(); ++i) {
        if (pts[i] - pts[kept - 1] <= sliver) {
            if (i + 1 == pts.size())
                pts[kept - 1] = pts[i]; // t1 stays the last point
            continue;
        }
        pts[kept++] = pts[i];
    }
    pts.resize(kept);
    if (pts.size() < 2)
        pts = {t0, t1};
    return adaptive(f, pts, accuracy, budget);
}

template <typename F>
Integral integrate(const F &f, const std::vector<Point> &h, double t0, double t1, double accuracy, int &budget)
{
    std::vector<double> pts{t0};
    if (!speedBoundedAway(h)) {
        // Cut at the minima of the speed: rising roots of (|B'|²)'/2 = B'·B''.
        const std::vector<double> g = speedSquaredSlope(f, h);
        std::vector<double> cuts;
        bernsteinRoots(g, cuts, true);
        for (double c : cuts)
            if (c > t0 && c < t1)
                pts.push_back(c);
        const std::size_t minima = pts.size();
        for (std::size_t i = 1; i < minima; ++i)
            gradedCuts(f, h, pts[i], pts[i - 1], i + 1 < minima ? pts[i + 1] : t1, pts);
        std::sort(pts.begin(), pts.end());
    }
    pts.push_back(t1);
    return adaptive(f, pts, accuracy, budget);
}

// The hodograph scaled to unit size: speeds of the curve are ldexp(speed of this, exponent). The
// scaling is by powers of two, so it is exact, and it keeps |B'|² from overflowing above ~1e154
// and underflowing below ~1e-162 (a curve at 1e160 or 1e-170 measures like one at 1).
struct ScaledHodograph
{
    std::vector<Point> h;
    int exponent = 0;
    double floor = 0.0; // resolvableAccuracy, in the curve's units
    bool zero = true;   // every control point equal (or the curve empty)
};

int exponentOf(double magnitude)
{
    int e = 0;
    std::frexp(magnitude, &e); // magnitude = m 2^e with m in [0.5, 1)
    return e;
}

ScaledHodograph scaledHodograph(const Bezier &curve)
{
    ScaledHodograph r;
    const std::vector<Point> &c = curve.controlPoints();
    if (c.size() < 2)
        return r;
    double m = 0.0;
    for (const Point &p : c)
        m = std::max({m, std::abs(p.x()), std::abs(p.y())});
    if (!(m > 0.0) || !std::isfinite(m))
        return r;
    const int e1 = exponentOf(m);
    const std::size_t n = c.size() - 1;
    r.h.resize(n);
    double hm = 0.0, polygon = 0.0;
    // Scaling by 2^-e1: a multiplication where that power is a normal double (the same correctly
    // rounded result as ldexp, which is a library call per coordinate), ldexp beyond.
    const bool multiply = std::abs(e1) < 1000;
    const double down = multiply ? std::ldexp(1.0, -e1) : 0.0;
    auto unit = [&](const Point &p) { return multiply ? Point(p * down) : ldexpPoint(p, -e1); };
    for (std::size_t i = 0; i < n; ++i) {
        const Point d = unit(c[i + 1]) - unit(c[i]);
        // |d| <= 2 after scaling: the squares cannot overflow, and an underflowing one only
        // lowers the floor's polygon term by less than 1e-300.
        polygon += std::sqrt(d.x() * d.x() + d.y() * d.y());
        r.h[i] = static_cast<double>(n) * d;
        hm = std::max({hm, std::abs(r.h[i].x()), std::abs(r.h[i].y())});
    }
    // The floor, derived: each control point is a double, known to within half an ulp of the largest
    // coordinate, ε·m/2; moving control points by δ moves B' by at most 2nδ, so the length itself
    // is uncertain by n·ε·m. Evaluating the speed and summing 15-point rules adds rounding of a few
    // ε relative to the length, which the polygon length bounds. Eight times both keeps the
    // adaptive error estimates, themselves differences of rounded sums, clear of that noise.
    constexpr double eps = std::numeric_limits<double>::epsilon();
    const double mScaled = std::ldexp(m, -e1);
    r.floor = std::ldexp(8.0 * eps * (static_cast<double>(n) * mScaled + polygon), e1);
    if (!(hm > 0.0))
        return r;
    const int e2 = exponentOf(hm);
    for (Point &p : r.h)
        p = ldexpPoint(p, -e2);
    r.exponent = e1 + e2;
    r.zero = false;
    return r;
}

// ∫ speed over [t0, t1] (0 <= t0 < t1 <= 1) in the scaled units of `s`, to a scaled accuracy.
Integral integrateScaled(const ScaledHodograph &s, double t0, double t1, double accuracy, int &budget)
{
    if (s.h.size() == 1) {
        --budget;
        ++t_evaluations;
        return {std::hypot(s.h[0].x(), s.h[0].y()) * (t1 - t0), 0.0};
    }
    if (s.h.size() == 3) {
        // H(t) = (1-t)² h0 + 2(1-t)t h1 + t² h2 = c + b t + a t² (power form: 2 multiply-adds per axis).
        const std::vector<Point> &h = s.h;
        const CubicSpeed f{h[0] - 2.0 * h[1] + h[2], 2.0 * (h[1] - h[0]), h[0]};
        return integrate(f, h, t0, t1, accuracy, budget);
    }
    return integrate(Hodograph{s.h}, s.h, t0, t1, accuracy, budget);
}

double polygonLength(const Bezier &curve)
{
    double len = 0.0;
    const auto &c = curve.controlPoints();
    for (std::size_t i = 0; i + 1 < c.size(); ++i)
        len += std::hypot(c[i + 1].x() - c[i].x(), c[i + 1].y() - c[i].y());
    return len;
}

// The accuracy to aim for, in the curve's units: the asked one (a default for a meaningless one),
// never below the floor.
double target(const ScaledHodograph &s, const Bezier &curve, double accuracy)
{
    if (!(accuracy > 0.0) || !std::isfinite(accuracy))
        accuracy = 1e-9 * std::max(polygonLength(curve), std::numeric_limits<double>::min());
    return std::max(accuracy, s.floor);
}

LengthEstimate estimate(const ScaledHodograph &s, double t0, double t1, double accuracy)
{
    int budget = kArcLengthBudget;
    const Integral r = integrateScaled(s, t0, t1, std::ldexp(accuracy, -s.exponent), budget);
    const double reached = std::ldexp(r.error, s.exponent);
    return {std::ldexp(r.value, s.exponent), std::max(accuracy, reached)};
}

} // namespace

double resolvableAccuracy(const Bezier &curve)
{
    const ScaledHodograph s = scaledHodograph(curve);
    return s.floor > 0.0 ? s.floor : std::numeric_limits<double>::min();
}

LengthEstimate arcLengthEstimate(const Bezier &curve, double t0, double t1, double accuracy)
{
    if (curve.isEmpty() || t0 == t1)
        return {0.0, std::max(accuracy, 0.0)};
    if (t1 < t0) {
        LengthEstimate r = arcLengthEstimate(curve, t1, t0, accuracy);
        r.length = -r.length;
        return r;
    }
    const ScaledHodograph s = scaledHodograph(curve);
    const double goal = target(s, curve, accuracy);
    if (s.zero)
        return {0.0, goal};
    return estimate(s, t0, t1, goal);
}

double arcLength(const Bezier &curve, double t0, double t1, double accuracy)
{
    return arcLengthEstimate(curve, t0, t1, accuracy).length;
}

double arcLength(const Bezier &curve, double accuracy)
{
    return arcLength(curve, 0.0, 1.0, accuracy);
}

double parameterAtLength(const Bezier &curve, double length, double accuracy)
{
    if (curve.isEmpty() || length <= 0.0)
        return 0.0;
    const ScaledHodograph s = scaledHodograph(curve);
    if (s.zero)
        return 1.0; // a positive length is past the end of a curve of length 0
    // The floor applies to each partial integral below, so the whole target is 64 of them.
    accuracy = std::max(target(s, curve, accuracy), 64.0 * s.floor);
    // Each partial integral gets 1/64 of the accuracy; at most 32 of them are summed, so the
    // accumulated length is within accuracy/2, and iteration stops within the other half.
    const double piece = accuracy / 64.0;
    const double total = estimate(s, 0.0, 1.0, piece).length;
    if (length >= total)
        return 1.0;
    double lo = 0.0, hi = 1.0;
    double t = length / total; // the guess for constant speed
    double at = estimate(s, 0.0, t, piece).length;
    const Bezier hodograph(s.h);
    for (int iter = 0; iter < 31; ++iter) {
        const double diff = at - length;
        if (std::abs(diff) <= 0.5 * accuracy)
            break;
        if (diff > 0.0)
            hi = t;
        else
            lo = t;
        // Newton on L(t) - length, with L'(t) = |B'(t)|, kept inside the bracket by bisection.
        const Point v = hodograph.eval(t);
        const double speed = std::ldexp(std::hypot(v.x(), v.y()), s.exponent);
        double next = speed > 0.0 ? t - diff / speed : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        at += next > t ? estimate(s, t, next, piece).length : -estimate(s, next, t, piece).length;
        t = next;
    }
    return t;
}

namespace detail {

std::uint64_t speedEvaluations()
{
    return t_evaluations;
}

void resetSpeedEvaluations()
{
    t_evaluations = 0;
}

// With the std::abs tests it replaced (isZero), std::sqrt's hypot was a tenth of a length's time.
// A w whose squares underflow (below 1e-308) is a double root, where 0 serves as well.
std::complex<double> principalSqrt(std::complex<double> w)
{
    const double u = w.real(), v = w.imag();
    const double r = std::sqrt(u * u + v * v);
    if (!(r > 0.0))
        return 0.0;
    const double s = std::sqrt(0.5 * (r + std::abs(u))); // > 0: r >= |u| and r > 0
    const double t = 0.5 * v / s;
    return u >= 0.0 ? std::complex<double>(s, t) : std::complex<double>(std::abs(t), std::copysign(s, v));
}

} // namespace detail

} // namespace kontur::geo
