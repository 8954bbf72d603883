// Barycentric polynomial interpolation and its Bézier pieces (see polynomial.h).
#include "geometry/splines/polynomial.h"

#include "geometry/parameterization.h"
#include "geometry/splines/knots.h"

#include <cmath>
#include <string>

namespace kontur::geo {

Result<PolynomialInterpolant> PolynomialInterpolant::create(std::vector<double> parameters, std::vector<Point> points)
{
    const std::size_t n = points.size();
    if (n < 2)
        return Error{ErrorCode::TooFewPoints, "polynomial interpolation needs at least 2 points", static_cast<int>(n)};
    if (n > static_cast<std::size_t>(kMaxPolynomialPoints))
        return Error{ErrorCode::InvalidArgument,
                     "polynomial interpolation takes at most " + std::to_string(kMaxPolynomialPoints) + " points",
                     static_cast<int>(n)};
    if (parameters.size() != n)
        return Error{ErrorCode::InvalidArgument, "one parameter per point is needed", -1};
    if (auto ok = checkParametersAndPoints(parameters, points); !ok)
        return ok.error();
    PolynomialInterpolant p;
    p.m_params = std::move(parameters);
    p.m_points = std::move(points);
    // w_j = 1 / prod_{k≠j} (s_j - s_k), computed on the parameters mapped to an interval of length 4
    // (the weights then neither overflow nor underflow for moderate n; a common factor cancels in
    // the barycentric formula).
    const double scale = 4.0 / (p.m_params.back() - p.m_params.front());
    p.m_weights.assign(n, 1.0);
    for (std::size_t j = 0; j < n; ++j) {
        double w = 1.0;
        for (std::size_t k = 0; k < n; ++k)
            if (k != j)
                w *= scale * (p.m_params[j] - p.m_params[k]);
        p.m_weights[j] = 1.0 / w;
    }
    return p;
}

Point PolynomialInterpolant::eval(double u) const
{
    if (m_points.empty())
        return Point::Zero();
    Point num = Point::Zero();
    double den = 0.0;
    for (std::size_t j = 0; j < m_points.size(); ++j) {
        const double diff = u - m_params[j];
        if (diff == 0.0)
            return m_points[j];
        const double c = m_weights[j] / diff;
        num += c * m_points[j];
        den += c;
    }
    return num / den;
}

PiecewiseBezier PolynomialInterpolant::toPiecewise() const
{
    const std::size_t n = m_points.size();
    if (n < 2)
        return {};
    const std::size_t d = n - 1;
    // The Bézier pieces do not depend on an affine change of the parameter, nor (up to scaling back)
    // on a scale of the points, but the divided differences raise both to the n-th power: computed on
    // parameters mapped to unit range and points of unit size, both by powers of two (exact).
    const int kp = scaleExponent(m_points);
    int ks = 0;
    std::frexp(m_params.back() - m_params.front(), &ks);
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i)
        u[i] = std::ldexp(m_params[i] - m_params.front(), -ks);
    // Newton form: divided differences c_j = f[u_0..u_j].
    std::vector<Point> c(n);
    for (std::size_t i = 0; i < n; ++i)
        c[i] = Point(std::ldexp(m_points[i].x(), -kp), std::ldexp(m_points[i].y(), -kp));
    for (std::size_t level = 1; level < n; ++level)
        for (std::size_t i = n - 1; i >= level; --i)
            c[i] = (c[i] - c[i - 1]) / (u[i] - u[i - level]);
    // Binomial coefficients C(d, j) as doubles.
    std::vector<double> binom(d + 1, 1.0);
    for (std::size_t j = 1; j <= d; ++j)
        binom[j] = binom[j - 1] * static_cast<double>(d - j + 1) / static_cast<double>(j);
    std::vector<Bezier> pieces;
    pieces.reserve(d);
    for (std::size_t seg = 0; seg < d; ++seg) {
        const double a = u[seg], h = u[seg + 1] - a;
        // Taylor coefficients at a: shift the Newton form to centre a (Horner with the Newton nodes),
        // then substitute x = a + h t: q_j = h^j p^(j)(a)/j!.
        std::vector<Point> q(n, Point::Zero());
        for (std::size_t k = n; k-- > 0;) {
            // q ← q · (x - s_k) + c_k, with x - s_k = (x - a) + (a - s_k).
            const double shift = a - u[k];
            for (std::size_t j = n - 1; j > 0; --j)
                q[j] = q[j] * shift + q[j - 1];
            q[0] = q[0] * shift + c[k];
        }
        // Now p(x) = Σ q_j (x - a)^j (the first step, k = n - 1, multiplied zero).
        double hp = 1.0;
        for (std::size_t j = 0; j < n; ++j) {
            q[j] *= hp;
            hp *= h;
        }
        // Power (in t) → Bernstein: b_i = Σ_{j<=i} C(i,j)/C(d,j) q_j.
        std::vector<Point> ctrl(n, Point::Zero());
        for (std::size_t i = 0; i <= d; ++i) {
            double cij = 1.0; // C(i, j)
            for (std::size_t j = 0; j <= i; ++j) {
                ctrl[i] += (cij / binom[j]) * q[j];
                cij = cij * static_cast<double>(i - j) / static_cast<double>(j + 1);
            }
        }
        for (Point &p : ctrl)
            p = Point(std::ldexp(p.x(), kp), std::ldexp(p.y(), kp));
        // The first and last points are the knots' own values (exact, whatever the rounding above).
        ctrl.front() = m_points[seg];
        ctrl.back() = m_points[seg + 1];
        pieces.emplace_back(std::move(ctrl));
    }
    return PiecewiseBezier(std::move(pieces), false);
}

Result<PolynomialInterpolant> polynomialInterpolant(std::span<const Point> points, Parameterization param)
{
    if (points.size() > static_cast<std::size_t>(kMaxPolynomialPoints))
        return Error{ErrorCode::InvalidArgument,
                     "polynomial interpolation takes at most " + std::to_string(kMaxPolynomialPoints) + " points",
                     static_cast<int>(points.size())};
    // Parameters measured on the points scaled to unit size (UnitScale, knots.h), then scaled back.
    const UnitScale scale = unitScale(points, param);
    auto s = splineParameters(scale.down(points), param);
    if (!s)
        return s.error();
    if (auto ok = scaleBack(*s, scale.paramExponent); !ok)
        return ok.error();
    return PolynomialInterpolant::create(std::move(s).value(), std::vector<Point>(points.begin(), points.end()));
}

Result<PolynomialInterpolant> functionPolynomial(std::span<const double> x, std::span<const double> y)
{
    if (x.size() != y.size())
        return Error{ErrorCode::InvalidArgument, "one y per x is needed", -1};
    std::vector<Point> pts(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        pts[i] = Point(x[i], y[i]);
    return PolynomialInterpolant::create(std::vector<double>(x.begin(), x.end()), std::move(pts));
}

} // namespace kontur::geo
