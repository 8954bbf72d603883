// The projective map of the plane: see projective.h.
#include "geometry/projective.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>

namespace kontur::geo {

namespace {

// Scaled so that H(2,2) = 1 when that entry is not negligible, otherwise to unit Frobenius norm (a
// map that sends the origin to infinity).
Eigen::Matrix3d normalised(const Eigen::Matrix3d &m)
{
    const double norm = m.norm();
    if (std::abs(m(2, 2)) > 1e-12 * norm)
        return m / m(2, 2);
    return m / norm;
}

// Hartley's normalisation: the similarity that moves the points' centroid to the origin and their
// mean distance from it to √2.
Eigen::Matrix3d conditioner(const Quad &q)
{
    Point c = Point::Zero();
    for (const Point &p : q)
        c += p / 4.0;
    double mean = 0.0;
    for (const Point &p : q)
        mean += (p - c).norm() / 4.0;
    const double s = std::sqrt(2.0) / mean;
    Eigen::Matrix3d t;
    t << s, 0.0, -s * c.x(), 0.0, s, -s * c.y(), 0.0, 0.0, 1.0;
    return t;
}

// Whether m is far from singular, whatever the scales of its rows and columns (a map from 1e6-sized
// pictures to 1e-6-sized worlds has entries 1e-12 apart): rows and then columns scaled to unit length,
// Hadamard's bound |det| ≤ 1 is then compared with the determinant.
bool regular(const Eigen::Matrix3d &m)
{
    Eigen::Matrix3d e = m;
    for (int r = 0; r < 3; ++r) {
        const double n = e.row(r).norm();
        if (!(n > 0.0) || !std::isfinite(n))
            return false;
        e.row(r) /= n;
    }
    for (int c = 0; c < 3; ++c) {
        const double n = e.col(c).norm();
        if (!(n > 0.0))
            return false;
        e.col(c) /= n;
    }
    return std::abs(e.determinant()) > 1e-13;
}

bool finite(const Quad &q)
{
    for (const Point &p : q)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            return false;
    return true;
}

// Whether no three of the (normalised, so of size about 1) points lie on a line.
bool inGeneralPosition(const std::array<Point, 4> &q)
{
    constexpr double tiny = 1e-10;
    for (int skip = 0; skip < 4; ++skip) {
        Point t[3];
        for (int i = 0, k = 0; i < 4; ++i)
            if (i != skip)
                t[k++] = q[static_cast<std::size_t>(i)];
        const Point u = t[1] - t[0], v = t[2] - t[0];
        if (!(std::abs(u.x() * v.y() - u.y() * v.x()) > tiny))
            return false;
    }
    return true;
}

} // namespace

Projective2D::Projective2D(const Eigen::Matrix3d &m)
    : m_h(normalised(m))
{
}

Result<Projective2D> Projective2D::fromMatrix(const Eigen::Matrix3d &m)
{
    if (!m.allFinite())
        return Error{ErrorCode::NonFiniteInput, "the matrix has a NaN or infinite entry"};
    if (!regular(m))
        return Error{ErrorCode::IllConditioned, "the matrix is singular"};
    return Projective2D(m);
}

Projective2D Projective2D::fromAffine(const Eigen::Matrix2d &linear, const Point &translation)
{
    Projective2D t;
    t.m_h.topLeftCorner<2, 2>() = linear;
    t.m_h.topRightCorner<2, 1>() = translation;
    return t;
}

Result<Projective2D> Projective2D::fromPointPairs(const Quad &from, const Quad &to)
{
    if (!finite(from) || !finite(to))
        return Error{ErrorCode::NonFiniteInput, "a point has a NaN or infinite coordinate"};
    const Eigen::Matrix3d tFrom = conditioner(from), tTo = conditioner(to);
    if (!tFrom.allFinite() || !tTo.allFinite())
        return Error{ErrorCode::AllPointsEqual, "the four points are one point"};
    Quad a, b;
    for (std::size_t i = 0; i < 4; ++i) {
        a[i] = (tFrom * from[i].homogeneous()).head<2>();
        b[i] = (tTo * to[i].homogeneous()).head<2>();
    }
    if (!inGeneralPosition(a) || !inGeneralPosition(b))
        return Error{ErrorCode::IllConditioned, "three of the four points lie on a line"};
    // Two rows per pair from b × (H a) = 0 (Hartley & Zisserman, eq. 4.3).
    Eigen::Matrix<double, 9, 9> system = Eigen::Matrix<double, 9, 9>::Zero();
    for (std::size_t i = 0; i < 4; ++i) {
        const double x = a[i].x(), y = a[i].y(), u = b[i].x(), v = b[i].y();
        const auto r = static_cast<Eigen::Index>(2 * i);
        system.row(r) << 0, 0, 0, -x, -y, -1, v * x, v * y, v;
        system.row(r + 1) << x, y, 1, 0, 0, 0, -u * x, -u * y, -u;
    }
    // The ninth row stays zero: a square matrix gives JacobiSVD the full null space.
    const Eigen::JacobiSVD<Eigen::Matrix<double, 9, 9>> svd(system, Eigen::ComputeFullV);
    const Eigen::Matrix<double, 9, 1> h = svd.matrixV().col(8);
    Eigen::Matrix3d hn;
    hn << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), h(8);
    // Undo the normalisations: H = T_to⁻¹ · Ĥ · T_from.
    const Eigen::Matrix3d m = tTo.inverse() * hn * tFrom;
    return fromMatrix(m);
}

double Projective2D::denominator(const Point &p) const
{
    return m_h(2, 0) * p.x() + m_h(2, 1) * p.y() + m_h(2, 2);
}

Point Projective2D::map(const Point &p) const
{
    const Eigen::Vector3d q = m_h * p.homogeneous();
    if (isAffine() && m_h(2, 2) == 1.0)
        return q.head<2>();
    return q.head<2>() / q.z();
}

Eigen::Matrix2d Projective2D::jacobian(const Point &p) const
{
    const Eigen::Vector3d q = m_h * p.homogeneous();
    const double w = q.z();
    // d(u/w) = (du·w − u·dw) / w², with du, dw the rows of H's first two columns.
    Eigen::Matrix2d j;
    for (int k = 0; k < 2; ++k) {
        j(0, k) = (m_h(0, k) * w - q.x() * m_h(2, k)) / (w * w);
        j(1, k) = (m_h(1, k) * w - q.y() * m_h(2, k)) / (w * w);
    }
    return j;
}

Result<Projective2D> Projective2D::inverse() const
{
    if (!regular(m_h))
        return Error{ErrorCode::IllConditioned, "the map is singular"};
    // The adjugate is H⁻¹ up to scale, and keeps an affine map's last row (0, 0, det) exact.
    Eigen::Matrix3d adj;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            adj(r, c) = m_h(r1, c1) * m_h(r2, c2) - m_h(r1, c2) * m_h(r2, c1);
        }
    return Projective2D(adj);
}

Projective2D Projective2D::then(const Projective2D &next) const
{
    return Projective2D(next.m_h * m_h);
}

} // namespace kontur::geo
