// B-splines: knot vectors, Cox–de Boor, de Boor, Boehm insertion, Bézier pieces, seed 001's bells
// (see bspline.h).
#include "geometry/splines/bspline.h"

#include "geometry/splines/knots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace kontur::geo {

namespace {

Error orderError(int order)
{
    return Error{ErrorCode::InvalidArgument,
                 "the order must lie in " + std::to_string(kMinBSplineOrder) + ".." + std::to_string(kMaxBSplineOrder) +
                     " (got " + std::to_string(order) + ")",
                 -1};
}

// An order within kMin..kMaxBSplineOrder and at least `order` points (`what` names them).
Result<Ok> checkOrderAndCount(int order, int count, const char *what)
{
    if (order < kMinBSplineOrder || order > kMaxBSplineOrder)
        return orderError(order);
    if (count < order)
        return Error{ErrorCode::TooFewPoints,
                     "order " + std::to_string(order) + " needs at least " + std::to_string(order) + " " + what, count};
    return Ok{};
}

// The last nonempty span [t_j, t_{j+1}) with j <= limit: where the end of a domain belongs.
int lastNonemptySpan(std::span<const double> knots, int limit)
{
    for (int j = limit; j > 0; --j)
        if (knots[static_cast<std::size_t>(j)] < knots[static_cast<std::size_t>(j) + 1])
            return j;
    return 0;
}

// The blossom P[u_1, ..., u_deg] of the degree-deg spline with control points `points` on span mu
// (t_mu <= t < t_{mu+1}): de Boor's algorithm, whose level r takes the argument u_r. With every u_r = t
// it is the point C(t) (de Boor 1972; Piegl & Tiller A3.1); with u_r = a for p - j levels and b after,
// the j-th Bézier control point of the span [a, b] (Ramshaw, "Blossoming", 1987). A zero-length
// knot interval weighs 0, as in Cox–de Boor.
Point deBoor(std::span<const Point> points, std::span<const double> knots, int mu, int deg, std::span<const double> u)
{
    std::array<Point, kMaxBSplineOrder> d;
    for (int j = 0; j <= deg; ++j)
        d[static_cast<std::size_t>(j)] = points[static_cast<std::size_t>(mu - deg + j)];
    for (int r = 1; r <= deg; ++r) {
        const double t = u[static_cast<std::size_t>(r) - 1];
        for (int j = deg; j >= r; --j) {
            const auto i = static_cast<std::size_t>(mu - deg + j);
            const double a = knots[i], b = knots[i + static_cast<std::size_t>(deg - r) + 1];
            const double alpha = b > a ? (t - a) / (b - a) : 0.0;
            d[static_cast<std::size_t>(j)] =
                (1.0 - alpha) * d[static_cast<std::size_t>(j) - 1] + alpha * d[static_cast<std::size_t>(j)];
        }
    }
    return d[static_cast<std::size_t>(deg)];
}

// C(t) on span mu: the blossom with every argument t.
Point deBoor(std::span<const Point> points, std::span<const double> knots, int mu, int deg, double t)
{
    std::array<double, kMaxBSplineOrder> u;
    u.fill(t);
    return deBoor(points, knots, mu, deg, u);
}

// One step of differentiation in place: the degree-deg spline (points, knots) becomes its derivative,
// of degree deg - 1, Q_i = deg (P_{i+1} - P_i) / (t_{i+deg+1} - t_{i+1}) on the knots without their
// first and last (de Boor; Piegl & Tiller eq. 3.10). A zero-length support gives Q_i = 0.
void differentiate(std::vector<Point> &points, std::vector<double> &knots, int deg)
{
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double den = knots[i + static_cast<std::size_t>(deg) + 1] - knots[i + 1];
        points[i] = den > 0.0 ? Point(deg * (points[i + 1] - points[i]) / den) : Point::Zero();
    }
    points.pop_back();
    knots.erase(knots.begin());
    knots.pop_back();
}

} // namespace

Result<Ok> checkKnotVector(std::span<const double> knots, int order, int controlPointCount)
{
    const auto need = static_cast<std::size_t>(controlPointCount + order);
    if (knots.size() != need)
        return Error{ErrorCode::InvalidArgument,
                     "the knot vector needs " + std::to_string(need) + " values (n + k), got " +
                         std::to_string(knots.size()),
                     -1};
    int run = 1;
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i]))
            return Error{ErrorCode::NonFiniteInput, "knot " + std::to_string(i) + " is not finite",
                         static_cast<int>(i)};
        if (i == 0)
            continue;
        if (knots[i] < knots[i - 1])
            return Error{ErrorCode::InvalidArgument, "knot " + std::to_string(i) + " decreases", static_cast<int>(i)};
        run = knots[i] == knots[i - 1] ? run + 1 : 1;
        if (run > order)
            return Error{ErrorCode::InvalidArgument,
                         "knot " + std::to_string(i) + " is repeated more than " + std::to_string(order) + " times",
                         static_cast<int>(i)};
    }
    if (!(knots[static_cast<std::size_t>(controlPointCount)] > knots[static_cast<std::size_t>(order - 1)]))
        return Error{ErrorCode::InvalidArgument, "the knot vector leaves the curve an empty domain", order - 1};
    return Ok{};
}

Result<std::vector<double>> openUniformKnots(int controlPointCount, int order)
{
    if (auto ok = checkOrderAndCount(order, controlPointCount, "points"); !ok)
        return ok.error();
    const int tmax = controlPointCount - order + 1;
    std::vector<double> t(static_cast<std::size_t>(controlPointCount + order));
    for (std::size_t i = 0; i < t.size(); ++i)
        t[i] = std::clamp(static_cast<double>(static_cast<int>(i) - order + 1), 0.0, static_cast<double>(tmax));
    return t;
}

Result<std::vector<double>> uniformKnots(int controlPointCount, int order, double start, double step)
{
    if (auto ok = checkOrderAndCount(order, controlPointCount, "points"); !ok)
        return ok.error();
    if (!(step > 0.0) || !std::isfinite(step) || !std::isfinite(start))
        return Error{ErrorCode::InvalidArgument, "the knot step must be positive and finite", -1};
    std::vector<double> t(static_cast<std::size_t>(controlPointCount + order));
    for (std::size_t i = 0; i < t.size(); ++i)
        t[i] = start + step * static_cast<double>(i);
    return t;
}

const char *nameOf(KnotKind k)
{
    return k == KnotKind::OpenUniform ? "open-uniform" : "uniform";
}

double basisFunction(std::span<const double> knots, int i, int order, double t)
{
    const int m = static_cast<int>(knots.size()) - 1; // last knot index
    if (i < 0 || order < 1 || i + order > m || !(t >= knots.front() && t <= knots.back()))
        return 0.0;
    // The active base interval: half-open, except the very last knot, which belongs to the last
    // nonempty interval (seed 003 KG-205: "treat t = t_max specially").
    int active;
    if (t >= knots.back()) {
        active = lastNonemptySpan(knots, m - 1);
    } else {
        active = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), t) - knots.begin()) - 1;
    }
    // Triangular Cox–de Boor table over the order + 1... base functions N_{i..i+k-1, 1}.
    std::array<double, kMaxBSplineOrder + 1> n{};
    const int k = std::min(order, kMaxBSplineOrder);
    for (int j = 0; j < k; ++j)
        n[static_cast<std::size_t>(j)] = (i + j == active) ? 1.0 : 0.0;
    for (int r = 2; r <= k; ++r) {
        for (int j = 0; j + r <= k; ++j) {
            const auto a = static_cast<std::size_t>(i + j);
            const double left = knots[a + static_cast<std::size_t>(r) - 1] - knots[a];
            const double right = knots[a + static_cast<std::size_t>(r)] - knots[a + 1];
            double v = 0.0;
            // 0/0 := 0: a zero-length support contributes nothing.
            if (left > 0.0)
                v += (t - knots[a]) / left * n[static_cast<std::size_t>(j)];
            if (right > 0.0)
                v += (knots[a + static_cast<std::size_t>(r)] - t) / right * n[static_cast<std::size_t>(j) + 1];
            n[static_cast<std::size_t>(j)] = v;
        }
    }
    return n[0];
}

namespace {

// The order nonzero N_{span-p..span, k}(t) into `values` (Piegl & Tiller A2.2) and, when `ratio` is given,
// the ratios N_{span-p+1+r, k-1} / (t_{span+1+r} - t_{span-p+1+r}) of the last level, r = 0..p-1.
void nonzeroBasisAndRatios(std::span<const double> knots, int span, int order, double t, std::span<double> values,
                           double *ratio)
{
    const int p = order - 1;
    std::array<double, kMaxBSplineOrder + 1> left{}, right{};
    values[0] = 1.0;
    const auto s = static_cast<std::size_t>(span);
    for (int j = 1; j <= p; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        left[uj] = t - knots[s + 1 - uj];
        right[uj] = knots[s + uj] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const auto ur = static_cast<std::size_t>(r);
            const double denom = right[ur + 1] + left[uj - ur];
            const double temp = denom != 0.0 ? values[ur] / denom : 0.0;
            if (ratio && j == p)
                ratio[ur] = temp;
            values[ur] = saved + right[ur + 1] * temp;
            saved = left[uj - ur] * temp;
        }
        values[uj] = saved;
    }
}

} // namespace

void nonzeroBasis(std::span<const double> knots, int span, int order, double t, std::span<double> out)
{
    nonzeroBasisAndRatios(knots, span, order, t, out, nullptr);
}

void nonzeroBasisWithDerivatives(std::span<const double> knots, int span, int order, double t, std::span<double> values,
                                 std::span<double> derivatives)
{
    const int p = order - 1;
    std::array<double, kMaxBSplineOrder + 1> ratio{};
    nonzeroBasisAndRatios(knots, span, order, t, values, ratio.data());
    for (int j = 0; j <= p; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        const double before = j > 0 ? ratio[uj - 1] : 0.0;
        const double after = j < p ? ratio[uj] : 0.0;
        derivatives[uj] = p * (before - after);
    }
}

Result<BSpline> BSpline::create(int order, std::vector<double> knots, std::vector<Point> controlPoints)
{
    const int n = static_cast<int>(controlPoints.size());
    if (auto ok = checkOrderAndCount(order, n, "control points"); !ok)
        return ok.error();
    if (auto ok = checkKnotVector(knots, order, n); !ok)
        return ok.error();
    if (auto ok = checkFinite(controlPoints); !ok)
        return ok.error();
    BSpline b;
    b.m_order = order;
    b.m_knots = std::move(knots);
    b.m_points = std::move(controlPoints);
    return b;
}

Result<BSpline> BSpline::create(int order, KnotKind kind, std::vector<Point> controlPoints)
{
    const int n = static_cast<int>(controlPoints.size());
    auto knots = kind == KnotKind::OpenUniform ? openUniformKnots(n, order) : uniformKnots(n, order);
    if (!knots)
        return knots.error();
    return create(order, std::move(knots).value(), std::move(controlPoints));
}

double BSpline::startParameter() const
{
    return m_knots.empty() ? 0.0 : m_knots[static_cast<std::size_t>(m_order - 1)];
}

double BSpline::endParameter() const
{
    return m_knots.empty() ? 0.0 : m_knots[m_points.size()];
}

int BSpline::spanOf(double t) const
{
    const int n = controlPointCount();
    const int p = degree();
    const double lo = startParameter(), hi = endParameter();
    if (!(t < hi))
        return lastNonemptySpan(m_knots, n - 1);
    if (!(t > lo))
        t = lo;
    // upper_bound in [t_p, t_n]: the last knot <= t.
    const auto first = m_knots.begin() + p, last = m_knots.begin() + n + 1;
    const int mu = static_cast<int>(std::upper_bound(first, last, t) - m_knots.begin()) - 1;
    return std::clamp(mu, p, n - 1);
}

Point BSpline::eval(double t) const
{
    if (m_points.empty())
        return Point::Zero();
    const int p = degree();
    t = std::clamp(t, startParameter(), endParameter());
    return deBoor(m_points, m_knots, spanOf(t), p, t);
}

Result<BSpline> BSpline::derivativeCurve() const
{
    if (m_order < 3)
        return Error{ErrorCode::InvalidArgument, "the derivative of an order-2 B-spline is not continuous", -1};
    BSpline d = *this;
    differentiate(d.m_points, d.m_knots, degree());
    d.m_order = m_order - 1;
    return d;
}

Point BSpline::derivative(double t, int r) const
{
    if (r <= 0)
        return eval(t);
    if (r > degree() || m_points.empty())
        return Point::Zero();
    const int p = degree();
    // Differentiate the control points r times (piecewise constant when r = p).
    std::vector<Point> q = m_points;
    std::vector<double> knots = m_knots;
    for (int level = 0; level < r; ++level)
        differentiate(q, knots, p - level);
    // Evaluate the order-(k - r) spline with the span of the original curve (the same interval).
    return deBoor(q, knots, spanOf(t) - r, p - r, std::clamp(t, startParameter(), endParameter()));
}

std::vector<double> BSpline::basisValues(double t) const
{
    std::vector<double> out(m_points.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = basisFunction(m_knots, static_cast<int>(i), m_order, t);
    return out;
}

Result<BSpline> BSpline::withKnotInserted(double t, int times) const
{
    if (times < 1)
        return Error{ErrorCode::InvalidArgument, "insert a knot at least once", -1};
    if (!(t >= startParameter() && t <= endParameter()))
        return Error{ErrorCode::InvalidArgument, "the knot lies outside the curve's domain", -1};
    const int p = degree();
    const auto mult = static_cast<int>(std::count(m_knots.begin(), m_knots.end(), t));
    if (mult + times > p)
        return Error{ErrorCode::InvalidArgument,
                     "a knot may appear at most " + std::to_string(p) + " times inside the curve", -1};
    BSpline b = *this;
    for (int step = 0; step < times; ++step) {
        // Boehm: Q_i = (1 - α_i) P_{i-1} + α_i P_i for μ-p+1 <= i <= μ, α_i = (t - t_i)/(t_{i+p} - t_i).
        int mu = static_cast<int>(std::upper_bound(b.m_knots.begin(), b.m_knots.end(), t) - b.m_knots.begin()) - 1;
        mu = std::clamp(mu, p, b.controlPointCount() - 1);
        std::vector<Point> q;
        q.reserve(b.m_points.size() + 1);
        for (int i = 0; i <= mu - p; ++i)
            q.push_back(b.m_points[static_cast<std::size_t>(i)]);
        for (int i = mu - p + 1; i <= mu; ++i) {
            const auto ui = static_cast<std::size_t>(i);
            const double den = b.m_knots[ui + static_cast<std::size_t>(p)] - b.m_knots[ui];
            const double alpha = den > 0.0 ? (t - b.m_knots[ui]) / den : 0.0;
            q.push_back((1.0 - alpha) * b.m_points[ui - 1] + alpha * b.m_points[ui]);
        }
        for (int i = mu; i < b.controlPointCount(); ++i)
            q.push_back(b.m_points[static_cast<std::size_t>(i)]);
        b.m_knots.insert(b.m_knots.begin() + mu + 1, t);
        b.m_points = std::move(q);
    }
    return b;
}

std::vector<Bezier> BSpline::bezierPieces(std::vector<double> *spanParameters) const
{
    std::vector<Bezier> out;
    if (spanParameters)
        spanParameters->clear();
    if (m_points.empty())
        return out;
    const int p = degree();
    const int n = controlPointCount();
    for (int mu = p; mu < n; ++mu) {
        const double a = m_knots[static_cast<std::size_t>(mu)], b = m_knots[static_cast<std::size_t>(mu) + 1];
        if (!(b > a))
            continue;
        std::vector<Point> ctrl(static_cast<std::size_t>(p) + 1);
        for (int jb = 0; jb <= p; ++jb) {
            // Blossom P[a^(p-jb), b^jb].
            std::array<double, kMaxBSplineOrder> u;
            std::fill_n(u.begin(), p - jb, a);
            std::fill(u.begin() + (p - jb), u.end(), b);
            ctrl[static_cast<std::size_t>(jb)] = deBoor(m_points, m_knots, mu, p, u);
        }
        out.emplace_back(std::move(ctrl));
        if (spanParameters) {
            if (spanParameters->empty())
                spanParameters->push_back(a);
            spanParameters->push_back(b);
        }
    }
    return out;
}

PiecewiseBezier BSpline::toPiecewise() const
{
    return PiecewiseBezier(bezierPieces(), false);
}

// --- seed 001 ---

double bellScale(std::span<const double> v, int j, int degree)
{
    double s = 1.0;
    const auto top = static_cast<std::size_t>(j + degree + 1);
    for (int m = j + 1; m <= j + degree; ++m)
        s *= v[top] - v[static_cast<std::size_t>(m)];
    return s;
}

Result<double> bell(std::span<const double> v, int j, int degree, int p, double x)
{
    if (degree < 1 || degree + 1 > kMaxBSplineOrder)
        return orderError(degree + 1);
    if (p < 1 || p > degree + 1)
        return Error{ErrorCode::InvalidArgument, "the piece p must lie in 1..n+1", -1};
    if (j < 0 || static_cast<std::size_t>(j + degree + 1) >= v.size())
        return Error{ErrorCode::IndexOutOfRange, "the bell needs knots v_j..v_{j+n+1}", j};
    if (auto ok = checkStrictlyIncreasing(v, "knot"); !ok)
        return ok.error();
    // The piece of N_{j} on span μ = j + n + 1 - p: N_j is entry j - (μ - n) of the nonzero basis there.
    const int mu = j + degree + 1 - p;
    std::array<double, kMaxBSplineOrder + 1> nb{};
    nonzeroBasis(v, mu, degree + 1, x, std::span<double>(nb.data(), static_cast<std::size_t>(degree) + 1));
    return bellScale(v, j, degree) * nb[static_cast<std::size_t>(j - (mu - degree))];
}

Result<BSpline> bellSpline(std::span<const double> v, std::span<const double> c, int degree)
{
    if (degree < 1 || degree + 1 > kMaxBSplineOrder)
        return orderError(degree + 1);
    if (v.size() != c.size() + static_cast<std::size_t>(degree) + 1)
        return Error{ErrorCode::InvalidArgument, "K knots carry K - n - 1 control values", -1};
    if (c.size() < static_cast<std::size_t>(degree) + 1)
        return Error{ErrorCode::TooFewPoints, "a B-spline of degree n needs n + 1 control values",
                     static_cast<int>(c.size())};
    if (auto ok = checkStrictlyIncreasing(v, "knot"); !ok)
        return ok.error();
    std::vector<Point> ctrl(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
        // Greville abscissa: the average of the n interior knots of N_i; with these x(t) = t.
        double g = 0.0;
        for (int m = 1; m <= degree; ++m)
            g += v[i + static_cast<std::size_t>(m)];
        ctrl[i] = Point(g / degree, c[i] * bellScale(v, static_cast<int>(i), degree));
    }
    return BSpline::create(degree + 1, std::vector<double>(v.begin(), v.end()), std::move(ctrl));
}

} // namespace kontur::geo
