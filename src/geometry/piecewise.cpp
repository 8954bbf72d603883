// Piecewise Bézier curves and their continuity report (see piecewise.h).
#include "geometry/piecewise.h"

#include "geometry/arclength.h"
#include "geometry/nearest.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::geo {

const char *nameOf(Continuity c)
{
    switch (c) {
    case Continuity::None:
        return "none";
    case Continuity::G0:
        return "G0";
    case Continuity::G1:
        return "G1";
    case Continuity::C1:
        return "C1";
    case Continuity::G2:
        return "G2";
    case Continuity::C2:
        return "C2";
    }
    return "none";
}

namespace {

// |v| by hypot: Eigen's norm() squares, which overflows above ~1e154 and underflows below ~1e-162.
double hypotNorm(const Point &v)
{
    return std::hypot(v.x(), v.y());
}

} // namespace

PiecewiseBezier::PiecewiseBezier(std::vector<Bezier> segments, bool closed)
    : m_segments(std::move(segments))
    , m_closed(closed)
{
}

Point PiecewiseBezier::eval(double u) const
{
    if (m_segments.empty())
        return Point::Zero();
    const double clamped = std::clamp(u, 0.0, static_cast<double>(m_segments.size()));
    const std::size_t i = std::min(static_cast<std::size_t>(clamped), m_segments.size() - 1);
    return m_segments[i].eval(clamped - static_cast<double>(i));
}

double PiecewiseBezier::length(double accuracy) const
{
    return lengthEstimate(accuracy).length;
}

LengthEstimate PiecewiseBezier::lengthEstimate(double accuracy) const
{
    LengthEstimate total;
    if (m_segments.empty())
        return total;
    const double share = accuracy / static_cast<double>(m_segments.size());
    for (const Bezier &b : m_segments) {
        const LengthEstimate e = arcLengthEstimate(b, 0.0, 1.0, share);
        total.length += e.length;
        total.accuracy += e.accuracy;
    }
    return total;
}

Box PiecewiseBezier::boundingBox() const
{
    Box box;
    for (const Bezier &b : m_segments)
        box.extend(b.boundingBox());
    return box;
}

PiecewiseNearest PiecewiseBezier::nearest(const Point &query) const
{
    PiecewiseNearest best;
    best.distance = std::numeric_limits<double>::infinity();
    bool found = false; // a distance beyond the largest double is still an answer: the first segment's
    for (std::size_t i = 0; i < m_segments.size(); ++i) {
        const auto &c = m_segments[i].controlPoints();
        if (c.empty())
            continue;
        Box hull;
        for (const Point &p : c)
            hull.extend(p);
        // Eigen's exteriorDistance squares (infinite above ~1e154, so every segment was skipped).
        const Point outside = (hull.min() - query).cwiseMax(query - hull.max()).cwiseMax(Point::Zero());
        if (found && hypotNorm(outside) >= best.distance)
            continue;
        const Nearest n = geo::nearest(m_segments[i], query);
        if (!found || n.distance < best.distance) {
            best = {static_cast<int>(i), n.t, n.point, n.distance};
            found = true;
        }
    }
    if (!found)
        best.distance = 0.0; // no segment: the empty curve's answer, as before
    return best;
}

void PiecewiseBezier::flatten(double tolerance, std::vector<Point> &out) const
{
    for (const Bezier &b : m_segments)
        geo::flatten(b, tolerance, out);
}

namespace {

// The direction the curve leaves c[0] in: the first nonzero c[k] - c[0] (a handle on its knot
// hands the tangent to the next control point). Zero when every control point coincides.
Point startDirection(const std::vector<Point> &c)
{
    for (std::size_t k = 1; k < c.size(); ++k) {
        const Point d = c[k] - c[0];
        const double m = d.cwiseAbs().maxCoeff();
        if (m > 0.0) {
            const Point u = d / m; // unit size first, so normalising cannot underflow
            return u / hypotNorm(u);
        }
    }
    return Point::Zero();
}

double polygonLength(const std::vector<Point> &c)
{
    double len = 0.0;
    for (std::size_t i = 0; i + 1 < c.size(); ++i)
        len += hypotNorm(c[i + 1] - c[i]);
    return len;
}

} // namespace

JointContinuity jointContinuity(const Bezier &left, const Bezier &right, double tolerance)
{
    JointContinuity j;
    if (left.isEmpty() || right.isEmpty())
        return j;
    const double scale = std::max(polygonLength(left.controlPoints()) + polygonLength(right.controlPoints()),
                                  std::numeric_limits<double>::min());
    j.gap = hypotNorm(left.endPoint() - right.startPoint());

    std::vector<Point> rev(left.controlPoints().rbegin(), left.controlPoints().rend());
    const Point tl = -startDirection(rev); // the direction the left segment arrives in
    const Point tr = startDirection(right.controlPoints());
    if (tl.squaredNorm() > 0.0 && tr.squaredNorm() > 0.0)
        j.angle = std::atan2(std::abs(tl.x() * tr.y() - tl.y() * tr.x()), tl.dot(tr));
    else
        j.angle = std::numbers::pi;

    const Point d1l = left.derivative(1.0, 1), d1r = right.derivative(0.0, 1);
    const Point d2l = left.derivative(1.0, 2), d2r = right.derivative(0.0, 2);
    const double kl = left.curvature(1.0), kr = right.curvature(0.0);
    j.c1Jump = hypotNorm(d1l - d1r);
    j.c2Jump = hypotNorm(d2l - d2r);
    j.curvatureJump = std::abs(kl - kr);

    j.g0 = j.gap <= tolerance * scale;
    // The tangent directions come from the first control point off the joint on each side (the next
    // nonzero derivative where handles lie on their knot), so G1 is about the shape.
    j.g1 = j.g0 && j.angle <= tolerance;
    // Equal derivatives that are both zero (handles on the knot) are not a smooth join: C1 and C2
    // are claimed only where G1 holds too (issue #17: zero-length handles read "C2" at a kink).
    j.c1 = j.g1 && j.c1Jump <= tolerance * std::max({hypotNorm(d1l), hypotNorm(d1r), scale});
    j.g2 = j.g1 && j.curvatureJump <= tolerance * std::max({std::abs(kl), std::abs(kr), 1.0 / scale});
    j.c2 = j.c1 && j.c2Jump <= tolerance * std::max({hypotNorm(d2l), hypotNorm(d2r), scale});
    j.level = j.c2   ? Continuity::C2
              : j.g2 ? Continuity::G2
              : j.c1 ? Continuity::C1
              : j.g1 ? Continuity::G1
              : j.g0 ? Continuity::G0
                     : Continuity::None;
    return j;
}

std::vector<JointContinuity> PiecewiseBezier::continuity(double tolerance) const
{
    std::vector<JointContinuity> out;
    const std::size_t n = m_segments.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        out.push_back(jointContinuity(m_segments[i], m_segments[i + 1], tolerance));
        out.back().left = static_cast<int>(i);
        out.back().right = static_cast<int>(i + 1);
    }
    if (m_closed && n >= 2) {
        out.push_back(jointContinuity(m_segments[n - 1], m_segments[0], tolerance));
        out.back().left = static_cast<int>(n - 1);
        out.back().right = 0;
    }
    return out;
}

} // namespace kontur::geo
