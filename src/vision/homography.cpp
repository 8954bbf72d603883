// The direct linear transform for exactly four point pairs, on normalised coordinates.
#include "homography.h"

#include <Eigen/Dense>

#include <cmath>

namespace kontur::vision {
namespace {

// Translates the centroid to the origin and scales the mean distance to sqrt(2) (Hartley's
// normalisation): keeps the 8x8 system well conditioned for pixel coordinates in the thousands.
Eigen::Matrix3d normaliser(const std::array<geo::Point, 4> &pts)
{
    geo::Point c = geo::Point::Zero();
    for (const auto &p : pts)
        c += p;
    c /= 4.0;
    double mean = 0;
    for (const auto &p : pts)
        mean += (p - c).norm();
    mean /= 4.0;
    const double s = mean > 0 ? std::sqrt(2.0) / mean : 1.0;
    Eigen::Matrix3d t;
    t << s, 0, -s * c.x(), 0, s, -s * c.y(), 0, 0, 1;
    return t;
}

bool nearlyCollinear(const std::array<geo::Point, 4> &p)
{
    double scale = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            scale = std::max(scale, (p[i] - p[j]).norm());
    if (!(scale > 0) || !std::isfinite(scale))
        return true;
    for (int i = 0; i < 4; ++i) {
        const geo::Point a = p[(i + 1) % 4] - p[i], b = p[(i + 2) % 4] - p[i];
        if (std::abs(a.x() * b.y() - a.y() * b.x()) < 1e-9 * scale * scale)
            return true;
    }
    return false;
}

} // namespace

std::optional<Homography> homographyFrom4(const std::array<geo::Point, 4> &from, const std::array<geo::Point, 4> &to)
{
    if (nearlyCollinear(from) || nearlyCollinear(to))
        return std::nullopt;
    const Eigen::Matrix3d tf = normaliser(from), tt = normaliser(to);
    Eigen::Matrix<double, 8, 8> a;
    Eigen::Matrix<double, 8, 1> b;
    for (int i = 0; i < 4; ++i) {
        const geo::Point p = (tf * from[i].homogeneous()).head<2>();
        const geo::Point q = (tt * to[i].homogeneous()).head<2>();
        // u = (h0 x + h1 y + h2) / (h6 x + h7 y + 1), v likewise with h3..h5 (h8 = 1).
        a.row(2 * i) << p.x(), p.y(), 1, 0, 0, 0, -q.x() * p.x(), -q.x() * p.y();
        a.row(2 * i + 1) << 0, 0, 0, p.x(), p.y(), 1, -q.y() * p.x(), -q.y() * p.y();
        b(2 * i) = q.x();
        b(2 * i + 1) = q.y();
    }
    const Eigen::Matrix<double, 8, 1> h = a.fullPivLu().solve(b);
    if (!h.allFinite())
        return std::nullopt;
    Eigen::Matrix3d hn;
    hn << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), 1.0;
    Homography out = tt.inverse() * hn * tf;
    if (std::abs(out(2, 2)) > 1e-300)
        out /= out(2, 2);
    if (!out.allFinite())
        return std::nullopt;
    return out;
}

} // namespace kontur::vision
