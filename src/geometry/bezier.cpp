// Bézier curves of any degree: de Casteljau evaluation, derivatives, subdivision, elevation and
// reduction, bounds, curvature, inflections and flattening (see bezier.h).
#include "geometry/bezier.h"

#include "geometry/bernstein.h"
#include "geometry/polyline.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur::geo {

Bezier::Bezier(std::vector<Point> controlPoints)
    : m_points(std::move(controlPoints))
{
}

namespace {

// de Casteljau on a copy of `pts`, with a small fixed buffer for the common degrees.
Point deCasteljauPoint(const std::vector<Point> &pts, double t)
{
    if (pts.empty())
        return Point::Zero();
    constexpr std::size_t kInline = 16;
    const std::size_t n = pts.size();
    std::array<Point, kInline> local;
    std::vector<Point> heap;
    Point *work = local.data();
    if (n > kInline) {
        heap.assign(pts.begin(), pts.end());
        work = heap.data();
    } else {
        std::copy(pts.begin(), pts.end(), work);
    }
    const double s = 1.0 - t;
    for (std::size_t level = n - 1; level > 0; --level)
        for (std::size_t i = 0; i < level; ++i)
            work[i] = s * work[i] + t * work[i + 1];
    return work[0];
}

} // namespace

Point Bezier::eval(double t) const
{
    return deCasteljauPoint(m_points, t);
}

Point Bezier::derivative(double t, int order) const
{
    if (order <= 0)
        return eval(t);
    if (order > degree())
        return Point::Zero();
    return deCasteljauPoint(derivativeCurve(order).m_points, t);
}

Bezier Bezier::derivativeCurve(int order) const
{
    std::vector<Point> d = m_points;
    for (int k = 0; k < order && !d.empty(); ++k) {
        const double n = static_cast<double>(d.size() - 1);
        for (std::size_t i = 0; i + 1 < d.size(); ++i)
            d[i] = n * (d[i + 1] - d[i]);
        d.pop_back();
    }
    if (d.empty() && !m_points.empty())
        d.push_back(Point::Zero());
    return Bezier(std::move(d));
}

std::vector<std::vector<Point>> Bezier::deCasteljau(double t) const
{
    std::vector<std::vector<Point>> levels;
    if (m_points.empty())
        return levels;
    levels.push_back(m_points);
    const double s = 1.0 - t;
    while (levels.back().size() > 1) {
        const std::vector<Point> &prev = levels.back();
        std::vector<Point> next(prev.size() - 1);
        for (std::size_t i = 0; i < next.size(); ++i)
            next[i] = s * prev[i] + t * prev[i + 1];
        levels.push_back(std::move(next));
    }
    return levels;
}

std::pair<Bezier, Bezier> Bezier::split(double t) const
{
    const std::size_t n = m_points.size();
    std::vector<Point> work = m_points;
    std::vector<Point> left(n), right(n);
    const double s = 1.0 - t;
    for (std::size_t level = 0; level < n; ++level) {
        left[level] = work[0];
        right[n - 1 - level] = work[n - 1 - level];
        for (std::size_t i = 0; i + level + 1 < n; ++i)
            work[i] = s * work[i] + t * work[i + 1];
    }
    return {Bezier(std::move(left)), Bezier(std::move(right))};
}

Bezier Bezier::subCurve(double t0, double t1) const
{
    if (t0 > t1)
        return subCurve(t1, t0).reversed();
    if (m_points.empty())
        return {};
    // Cut at the farther end first so the second cut's parameter is a ratio with a nonzero denominator.
    if (t1 > 0.0) {
        const Bezier head = split(t1).first;
        return head.split(t0 / t1).second;
    }
    return Bezier(std::vector<Point>(m_points.size(), eval(t0)));
}

Bezier Bezier::elevated(int r) const
{
    if (r <= 0 || m_points.empty())
        return *this;
    const int n = degree();
    const int m = n + r;
    std::vector<Point> out(static_cast<std::size_t>(m) + 1, Point::Zero());
    // b_i^(r) = Σ_j w_ij b_j with w_ij = C(n,j) C(r,i-j) / C(n+r,i): for each i the weights are a
    // hypergeometric distribution over j, nonnegative and summing to 1. Exact binomials while they
    // fit a double (C(1000, 500) ≈ 2.7e299); beyond, the binomials themselves overflow (issue #17:
    // degree 1100 gave NaN), so the weights come from their logarithms, relative to the largest,
    // and are normalised by their sum: O((n + r)(n + 1)) for any degree, no large number formed.
    std::vector<double> w(static_cast<std::size_t>(n) + 1);
    const bool exact = m <= 1000;
    for (int i = 0; i <= m; ++i) {
        const int lo = std::max(0, i - r), hi = std::min(n, i);
        double top = -std::numeric_limits<double>::infinity();
        for (int j = lo; j <= hi; ++j) {
            const std::size_t k = static_cast<std::size_t>(j - lo);
            if (exact) {
                w[k] = binomial(n, j) * binomial(r, i - j) / binomial(m, i);
            } else {
                w[k] = std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0) + std::lgamma(r + 1.0) -
                       std::lgamma(i - j + 1.0) - std::lgamma(r - i + j + 1.0);
                top = std::max(top, w[k]);
            }
        }
        double sum = 0.0;
        if (!exact) {
            for (int j = lo; j <= hi; ++j) {
                double &x = w[static_cast<std::size_t>(j - lo)];
                x = std::exp(x - top);
                sum += x;
            }
        }
        Point acc = Point::Zero();
        for (int j = lo; j <= hi; ++j)
            acc += w[static_cast<std::size_t>(j - lo)] * m_points[static_cast<std::size_t>(j)];
        out[static_cast<std::size_t>(i)] = exact ? acc : Point(acc / sum);
    }
    // The end points are interpolated exactly; keep them bit-identical.
    out.front() = m_points.front();
    out.back() = m_points.back();
    return Bezier(std::move(out));
}

Bezier Bezier::reduced() const
{
    const int n = degree();
    if (n <= 1)
        return *this;
    // E maps the degree n-1 polygon to its elevation: row i = (i/n) c'_{i-1} + (1 - i/n) c'_i.
    Eigen::MatrixXd e = Eigen::MatrixXd::Zero(n + 1, n);
    Eigen::MatrixXd rhs(n + 1, 2);
    for (int i = 0; i <= n; ++i) {
        const double a = static_cast<double>(i) / n;
        if (i > 0)
            e(i, i - 1) = a;
        if (i < n)
            e(i, i) = 1.0 - a;
        rhs(i, 0) = m_points[i].x();
        rhs(i, 1) = m_points[i].y();
    }
    const Eigen::MatrixXd sol = e.householderQr().solve(rhs);
    std::vector<Point> out(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        out[i] = Point(sol(i, 0), sol(i, 1));
    return Bezier(std::move(out));
}

Bezier Bezier::reversed() const
{
    return Bezier(std::vector<Point>(m_points.rbegin(), m_points.rend()));
}

Bezier Bezier::transformed(const Eigen::Matrix2d &linear, const Point &translation) const
{
    std::vector<Point> out(m_points.size());
    for (std::size_t i = 0; i < m_points.size(); ++i)
        out[i] = linear * m_points[i] + translation;
    return Bezier(std::move(out));
}

Bezier Bezier::transformed(const Eigen::Affine2d &map) const
{
    return transformed(map.linear(), map.translation());
}

Box Bezier::boundingBox() const
{
    Box box;
    if (m_points.empty())
        return box;
    box.extend(m_points.front());
    box.extend(m_points.back());
    if (m_points.size() < 3)
        return box;
    std::vector<double> coeff(m_points.size());
    std::vector<double> roots;
    for (int axis = 0; axis < 2; ++axis) {
        for (std::size_t i = 0; i < m_points.size(); ++i)
            coeff[i] = m_points[i][axis];
        // Interior points whose coordinate lies inside the end points' range cannot widen the box.
        const auto [lo, hi] = std::minmax_element(coeff.begin(), coeff.end());
        if (*lo >= box.min()[axis] && *hi <= box.max()[axis])
            continue;
        roots.clear();
        bernsteinRoots(bernsteinDerivative(coeff), roots);
        for (double t : roots)
            box.extend(eval(t));
    }
    return box;
}

double Bezier::curvature(double t) const
{
    if (degree() < 2)
        return 0.0;
    Point d1 = derivative(t, 1);
    Point d2 = derivative(t, 2);
    // Scaled by a power of two to unit size first: |B'|³ overflows above ~1e102 and underflows
    // below ~1e-102; κ has the unit 1/length, so the scale comes back once.
    const double m = std::max(d1.cwiseAbs().maxCoeff(), d2.cwiseAbs().maxCoeff());
    if (!(m > 0.0) || !std::isfinite(m))
        return 0.0;
    int e = 0;
    std::frexp(m, &e);
    d1 = ldexpPoint(d1, -e);
    d2 = ldexpPoint(d2, -e);
    const double speed = std::hypot(d1.x(), d1.y());
    const double cube = speed * speed * speed;
    if (!(cube > 0.0))
        return 0.0;
    const double k = std::ldexp((d1.x() * d2.y() - d1.y() * d2.x()) / cube, -e);
    return std::isfinite(k) ? k : 0.0;
}

std::vector<double> Bezier::inflections() const
{
    std::vector<double> result;
    if (degree() < 2)
        return result;
    // The parameters do not depend on the scale; the products x'y'' do (overflow above ~1e154,
    // underflow below ~1e-162), so work on the curve scaled to unit size by a power of two.
    double mag = 0.0;
    for (const Point &p : m_points)
        mag = std::max(mag, p.cwiseAbs().maxCoeff());
    if (!(mag > 0.0) || !std::isfinite(mag))
        return result;
    int e = 0;
    std::frexp(mag, &e);
    std::vector<Point> unit(m_points);
    for (Point &p : unit)
        p = ldexpPoint(p, -e);
    const Bezier scaled(std::move(unit));
    const Bezier d1 = scaled.derivativeCurve(1);
    const Bezier d2 = scaled.derivativeCurve(2);
    auto coords = [](const Bezier &c, int axis) {
        std::vector<double> v(c.controlPoints().size());
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] = c.controlPoints()[i][axis];
        return v;
    };
    const std::vector<double> a = bernsteinProduct(coords(d1, 0), coords(d2, 1));
    const std::vector<double> b = bernsteinProduct(coords(d1, 1), coords(d2, 0));
    std::vector<double> cross(a.size());
    double scale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        cross[i] = a[i] - b[i];
        scale = std::max({scale, std::abs(a[i]), std::abs(b[i])});
    }
    // A straight curve leaves only rounding noise: treat it as identically zero.
    bool flat = true;
    for (double &c : cross) {
        if (std::abs(c) <= 1e-13 * scale)
            c = 0.0;
        flat = flat && c == 0.0;
    }
    if (flat)
        return result;
    std::vector<double> roots;
    bernsteinRoots(cross, roots);
    for (double t : roots) {
        if (t <= 0.0 || t >= 1.0)
            continue;
        // Only sign changes are inflections; a touching zero is not.
        const double h = 1e-7;
        const double before = bernsteinEval(cross, std::max(0.0, t - h));
        const double after = bernsteinEval(cross, std::min(1.0, t + h));
        if ((before < 0.0) != (after < 0.0) || before == 0.0 || after == 0.0)
            result.push_back(t);
    }
    return result;
}

Point evalCubicMatrix(const std::array<Point, 4> &c, double t)
{
    // T·M, then times C: the Bernstein weights written through the power basis.
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double w0 = 1.0 - 3.0 * t + 3.0 * t2 - t3;
    const double w1 = 3.0 * t - 6.0 * t2 + 3.0 * t3;
    const double w2 = 3.0 * t2 - 3.0 * t3;
    const double w3 = t3;
    return w0 * c[0] + w1 * c[1] + w2 * c[2] + w3 * c[3];
}

Bezier straightCubic(const Point &a, const Point &b)
{
    return Bezier({a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
}

Bezier quadraticToCubic(const Point &p0, const Point &p1, const Point &p2)
{
    return Bezier({p0, p0 + 2.0 / 3.0 * (p1 - p0), p2 + 2.0 / 3.0 * (p1 - p2), p2});
}

namespace {

template <typename Span> bool flatEnough(const Span &pts, std::size_t n, double tol2)
{
    const Point &a = pts[0];
    const Point &b = pts[n - 1];
    for (std::size_t i = 1; i + 1 < n; ++i)
        if ((pts[i] - nearestOnSegment(pts[i], a, b)).squaredNorm() > tol2)
            return false;
    return true;
}

// At most 2^20 pieces per curve, whatever the tolerance: bounded work (issue #17). 20 halvings reach
// spans of 1e-6 of the parameter range, where a piece deviates from its chord by ~1e-13 of the
// curve's size: finer than any tolerance above the floor in flatten() needs for ordinary curves.
constexpr int kMaxDepth = 20;

// Degree <= 15 without any allocation: an explicit stack of polygons, left halves first.
void flattenSmall(const std::vector<Point> &control, double tol2, std::vector<Point> &out)
{
    constexpr std::size_t kMax = 16;
    struct Item
    {
        std::array<Point, kMax> p;
        int depth;
    };
    const std::size_t n = control.size();
    std::array<Item, kMaxDepth + 2> stack;
    int top = 0;
    std::copy(control.begin(), control.end(), stack[0].p.begin());
    stack[0].depth = 0;
    top = 1;
    while (top > 0) {
        Item &item = stack[top - 1];
        if (item.depth >= kMaxDepth || flatEnough(item.p, n, tol2)) {
            out.push_back(item.p[n - 1]);
            --top;
            continue;
        }
        // Split in place: the right half replaces this item, the left half is pushed above it.
        Item &left = stack[top];
        std::array<Point, kMax> work = item.p;
        for (std::size_t level = 0; level < n; ++level) {
            left.p[level] = work[0];
            item.p[n - 1 - level] = work[n - 1 - level];
            for (std::size_t i = 0; i + level + 1 < n; ++i)
                work[i] = 0.5 * (work[i] + work[i + 1]);
        }
        left.depth = ++item.depth;
        ++top;
    }
}

void flattenRecursive(const Bezier &curve, double tol2, int depth, std::vector<Point> &out)
{
    const auto &pts = curve.controlPoints();
    if (depth >= kMaxDepth || flatEnough(pts, pts.size(), tol2)) {
        out.push_back(pts.back());
        return;
    }
    const auto [left, right] = curve.split(0.5);
    flattenRecursive(left, tol2, depth + 1, out);
    flattenRecursive(right, tol2, depth + 1, out);
}

} // namespace

void flatten(const Bezier &curve, double tolerance, std::vector<Point> &out)
{
    if (curve.isEmpty())
        return;
    const Point &start = curve.controlPoints().front();
    if (out.empty() || out.back() != start)
        out.push_back(start);
    double tol = tolerance > 0.0 && std::isfinite(tolerance) ? tolerance : 0.25;
    // Distances to the chord are computed from coordinates rounded to ~ε·max|coordinate| and from
    // de Casteljau halvings that add a few ε each: a tolerance below 16 ε·max|coordinate| cannot be
    // told apart from rounding and is raised to it.
    double mag = 0.0;
    for (const Point &p : curve.controlPoints())
        mag = std::max(mag, p.cwiseAbs().maxCoeff());
    tol = std::max(tol, 16.0 * std::numeric_limits<double>::epsilon() * mag);
    // Squared distances overflow above ~1e154 and underflow below ~1e-154: outside a safe range the
    // curve is flattened scaled to unit size by a power of two (exact) and the points scaled back.
    if (!(mag > 0.0) || !std::isfinite(mag) || (mag > 0x1p-400 && mag < 0x1p400)) {
        if (curve.controlPoints().size() <= 16)
            flattenSmall(curve.controlPoints(), tol * tol, out);
        else
            flattenRecursive(curve, tol * tol, 0, out);
        return;
    }
    int e = 0;
    std::frexp(mag, &e);
    std::vector<Point> unit(curve.controlPoints());
    for (Point &p : unit)
        p = ldexpPoint(p, -e);
    const double unitTol = std::ldexp(tol, -e);
    const std::size_t first = out.size();
    if (unit.size() <= 16)
        flattenSmall(unit, unitTol * unitTol, out);
    else
        flattenRecursive(Bezier(std::move(unit)), unitTol * unitTol, 0, out);
    for (std::size_t i = first; i < out.size(); ++i)
        out[i] = ldexpPoint(out[i], e);
}

} // namespace kontur::geo
