// Global nearest point on a Bézier curve (see nearest.h).
#include "geometry/nearest.h"

#include "geometry/bernstein.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kontur::geo {

Nearest nearest(const Bezier &curve, const Point &query)
{
    const std::vector<Point> &c = curve.controlPoints();
    Nearest best;
    if (c.empty()) {
        best.distance = std::hypot(query.x(), query.y());
        return best;
    }
    // |p - q| without squaring (hypot) and without overflowing the difference at ±1e308.
    auto distance = [&](const Point &p) {
        const double d = std::hypot(p.x() - query.x(), p.y() - query.y());
        return std::isfinite(d) ? d : 2.0 * std::hypot(0.5 * p.x() - 0.5 * query.x(), 0.5 * p.y() - 0.5 * query.y());
    };
    auto consider = [&](double t, const Point &p) {
        const double d = distance(p);
        if (d < best.distance || (d == best.distance && t < best.t)) {
            best.t = t;
            best.point = p;
            best.distance = d;
        }
    };
    best.t = 0.0;
    best.point = c.front();
    best.distance = distance(c.front());
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

} // namespace kontur::geo
