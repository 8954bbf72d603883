// Global nearest point on a Bézier curve (see nearest.h).
#include "geometry/nearest.h"

#include "geometry/bernstein.h"

#include <array>

namespace kontur::geo {

Nearest nearest(const Bezier &curve, const Point &query)
{
    const std::vector<Point> &c = curve.controlPoints();
    Nearest best;
    if (c.empty()) {
        best.distance = query.norm();
        return best;
    }
    auto consider = [&](double t, const Point &p) {
        const double d = (p - query).norm();
        if (d < best.distance || (d == best.distance && t < best.t)) {
            best.t = t;
            best.point = p;
            best.distance = d;
        }
    };
    best.t = 0.0;
    best.point = c.front();
    best.distance = (c.front() - query).norm();
    if (c.size() == 1)
        return best;
    consider(1.0, c.back());

    // f(t) = (B(t) - q)·B'(t) in the Bernstein basis of degree 2n - 1: the product rule per axis.
    const int n = static_cast<int>(c.size()) - 1;
    std::vector<double> f(static_cast<std::size_t>(2 * n), 0.0);
    for (int i = 0; i <= n; ++i) {
        const Point a = c[i] - query;
        const double wi = binomial(n, i);
        for (int j = 0; j < n; ++j) {
            const Point d = n * (c[j + 1] - c[j]);
            f[i + j] += wi * binomial(n - 1, j) * a.dot(d);
        }
    }
    for (int k = 0; k < 2 * n; ++k)
        f[k] /= binomial(2 * n - 1, k);
    std::vector<double> roots;
    bernsteinRoots(f, roots, true);
    for (double t : roots)
        if (t > 0.0 && t < 1.0)
            consider(t, curve.eval(t));
    return best;
}

} // namespace kontur::geo
