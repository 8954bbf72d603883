// Bézier curves of any degree: de Casteljau evaluation, subdivision and flattening.
#include "geometry/bezier.h"

#include <algorithm>
#include <cmath>

namespace kontur::geo {

Bezier::Bezier(std::vector<Point> controlPoints)
    : m_points(std::move(controlPoints))
{
}

Point Bezier::eval(double t) const
{
    if (m_points.empty())
        return Point::Zero();
    // Small fixed buffer for the common degrees; the heap only for degree > 15.
    constexpr std::size_t kInline = 16;
    const std::size_t n = m_points.size();
    std::array<Point, kInline> local;
    std::vector<Point> heap;
    Point *work = local.data();
    if (n > kInline) {
        heap.assign(m_points.begin(), m_points.end());
        work = heap.data();
    } else {
        std::copy(m_points.begin(), m_points.end(), work);
    }
    const double s = 1.0 - t;
    for (std::size_t level = n - 1; level > 0; --level)
        for (std::size_t i = 0; i < level; ++i)
            work[i] = s * work[i] + t * work[i + 1];
    return work[0];
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

namespace {

// Distance from p to the segment a–b (to a when the segment is a single point).
double distanceToSegment(const Point &p, const Point &a, const Point &b)
{
    const Point ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 == 0.0)
        return (p - a).norm();
    const double u = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
    return (p - (a + u * ab)).norm();
}

bool flatEnough(const std::vector<Point> &pts, double tolerance)
{
    const Point &a = pts.front();
    const Point &b = pts.back();
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
        if (distanceToSegment(pts[i], a, b) > tolerance)
            return false;
    return true;
}

void flattenRecursive(const Bezier &curve, double tolerance, int depth, std::vector<Point> &out)
{
    // 40 halvings reach spans of 1e-12 of the parameter range: deeper cannot change the picture.
    if (depth >= 40 || flatEnough(curve.controlPoints(), tolerance)) {
        out.push_back(curve.controlPoints().back());
        return;
    }
    const auto [left, right] = curve.split(0.5);
    flattenRecursive(left, tolerance, depth + 1, out);
    flattenRecursive(right, tolerance, depth + 1, out);
}

} // namespace

void flatten(const Bezier &curve, double tolerance, std::vector<Point> &out)
{
    if (curve.isEmpty())
        return;
    const Point &start = curve.controlPoints().front();
    if (out.empty() || out.back() != start)
        out.push_back(start);
    const double tol = tolerance > 0.0 && std::isfinite(tolerance) ? tolerance : 0.25;
    flattenRecursive(curve, tol, 0, out);
}

} // namespace kontur::geo
