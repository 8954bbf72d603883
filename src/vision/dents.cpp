// Notches cut into the edge: see dents.h.
#include "vision/dents.h"

#include "geometry/polyline.h"
#include "vision/loop.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace kontur::vision::detail {

using geo::Point;

namespace {

// A point in the frame of a chord: x along it from its start, y square to it into the piece.
struct Frame
{
    Point origin, along, inward;
    [[nodiscard]] Point local(const Point &p) const { return {(p - origin).dot(along), (p - origin).dot(inward)}; }
    [[nodiscard]] Point global(const Point &q) const { return origin + q.x() * along + q.y() * inward; }
};

// y = c0 + c1·x + c2·x², least squares.
struct Parabola
{
    double c0 = 0, c1 = 0, c2 = 0;
    [[nodiscard]] double operator()(double x) const { return c0 + x * (c1 + x * c2); }
    [[nodiscard]] double slope(double x) const { return c1 + 2.0 * c2 * x; }
};

std::optional<Parabola> fitParabola(const std::vector<Point> &pts)
{
    if (pts.size() < 6)
        return std::nullopt;
    Eigen::MatrixXd a(static_cast<Eigen::Index>(pts.size()), 3);
    Eigen::VectorXd b(static_cast<Eigen::Index>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        a(r, 0) = 1.0, a(r, 1) = pts[i].x(), a(r, 2) = pts[i].x() * pts[i].x();
        b(r) = pts[i].y();
    }
    const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
    if (!c.allFinite())
        return std::nullopt;
    return Parabola{c(0), c(1), c(2)};
}

// The dent about window [m, k] of the loop (whose chord dips into the piece), measured against the
// edge either side of it; nothing when it is no dent. `from`/`to`: the points to take out.
struct Found
{
    Dent dent;
    std::size_t from = 0, to = 0; // loop indices (counting on over the laps), from <= to
};

std::optional<Found> measure(const Loop &u, std::size_t m, std::size_t k, double sign, const DentLimits &lim)
{
    const Point chord = u.point(k) - u.point(m);
    if (chord.norm() <= 0.0)
        return std::nullopt;
    Frame f;
    f.origin = u.point(m);
    f.along = chord.normalized();
    f.inward = sign * Point(-f.along.y(), f.along.x());
    // The deepest point against the chord, and the stretch about it deeper than a third of that.
    std::size_t deepest = m;
    for (std::size_t q = m; q <= k; ++q)
        if (f.local(u.point(q)).y() > f.local(u.point(deepest)).y())
            deepest = q;
    const double chordDepth = f.local(u.point(deepest)).y();
    if (chordDepth < lim.minDepth)
        return std::nullopt;
    std::size_t a = deepest, b = deepest;
    while (a > m && f.local(u.point(a - 1)).y() > chordDepth / 3)
        --a;
    while (b < k && f.local(u.point(b + 1)).y() > chordDepth / 3)
        ++b;
    // The edge either side: a parabola through the points within the widest mouth of the stretch
    // [a, b], a pixel clear of it; refitted as the stretch grows to every point deeper than 1/8 of the
    // shallowest notch against it.
    const double reach = lim.maxWidth;
    std::optional<Parabola> edge;
    double scatter = 0.0;
    const auto depthOf = [&](std::size_t q) {
        const Point p = f.local(u.point(q));
        return p.y() - (*edge)(p.x());
    };
    std::size_t tip = deepest;
    for (int round = 0; round < 4; ++round) {
        std::vector<Point> flanks;
        std::size_t before = 0, after = 0;
        for (std::size_t q = a; q > 0 && u.arc(a) - u.arc(q - 1) < reach && q - 1 + u.size() > b; --q)
            if (u.arc(a) - u.arc(q - 1) > 1.0)
                flanks.push_back(f.local(u.point(q - 1))), ++before;
        for (std::size_t q = b + 1; u.arc(q) - u.arc(b) < reach && q < a + u.size(); ++q)
            if (u.arc(q) - u.arc(b) > 1.0)
                flanks.push_back(f.local(u.point(q))), ++after;
        if (before < 6 || after < 6)
            return std::nullopt;
        edge = fitParabola(flanks);
        if (!edge)
            return std::nullopt;
        scatter = 0.0;
        for (const Point &p : flanks)
            scatter = std::max(scatter, std::abs(p.y() - (*edge)(p.x())));
        for (std::size_t q = a; q <= b; ++q)
            if (depthOf(q) > depthOf(tip))
                tip = q;
        const double floor = 0.125 * lim.minDepth;
        std::size_t from = tip, to = tip;
        while (from > 0 && u.arc(tip) - u.arc(from - 1) < reach + lim.maxDepth && depthOf(from - 1) > floor)
            --from;
        while (u.arc(to + 1) - u.arc(tip) < reach + lim.maxDepth && depthOf(to + 1) > floor)
            ++to;
        if (from == a && to == b)
            break;
        a = from, b = to;
    }
    const double depth = depthOf(tip);
    if (depth < lim.minDepth || depth > lim.maxDepth || scatter > std::max(0.25 * depth, 0.4 * lim.minDepth))
        return std::nullopt;
    const std::size_t from = a, to = b;
    const double x0 = f.local(u.point(from)).x(), x1 = f.local(u.point(to)).x();
    const double width = std::abs(x1 - x0);
    if (width > lim.maxWidth)
        return std::nullopt;
    // The edge runs on across the mouth as it came (within 30°: a concave corner turns).
    const double slopeLimit = std::tan(std::numbers::pi / 6.0);
    if (std::abs(edge->slope(x0)) > slopeLimit || std::abs(edge->slope(x1)) > slopeLimit)
        return std::nullopt;
    // The notch's axis, in the frame where the edge is straight (x along it, the depth r into the
    // piece): each side a line x = c + m·r through its points between a fifth and nine tenths of the
    // depth (clear of the blurred mouth and of a tip the photo's blur or the segmentation's closing has
    // flattened, which may keep more of one side than of the other); the axis halves the angle between
    // the two sides, its foot halfway between where they meet the edge. A castle's sides go straight in:
    // at half its depth it is nearly as wide as at its mouth.
    const auto side = [&](std::size_t first, std::size_t last) -> std::optional<std::pair<double, double>> {
        double n = 0, sr = 0, sx = 0, srr = 0, srx = 0;
        for (std::size_t q = first; q <= last; ++q) {
            const double r = depthOf(q);
            if (r < 0.2 * depth || r > 0.9 * depth)
                continue;
            const double x = f.local(u.point(q)).x();
            n += 1, sr += r, sx += x, srr += r * r, srx += r * x;
        }
        const double det = n * srr - sr * sr;
        if (n < 4 || !(det > 1e-9 * n * n))
            return std::nullopt;
        const double m = (n * srx - sr * sx) / det;
        return std::pair{(sx - m * sr) / n, m};
    };
    const auto sideA = side(from, tip), sideB = side(tip, to);
    double halfLo = 1e300, halfHi = -1e300;
    for (std::size_t q = from; q <= to; ++q)
        if (depthOf(q) > 0.5 * depth) {
            halfLo = std::min(halfLo, f.local(u.point(q)).x());
            halfHi = std::max(halfHi, f.local(u.point(q)).x());
        }
    double footX = (x0 + x1) / 2;
    Point axis(0.0, 1.0); // (x, r)
    if (sideA && sideB) {
        footX = (sideA->first + sideB->first) / 2;
        axis = Point(sideA->second, 1.0).normalized() + Point(sideB->second, 1.0).normalized();
    }
    const Point tipLocal = Point(footX, 0.0) + axis * (depth / axis.y());
    Found out;
    out.dent.foot = f.global(Point(footX, (*edge)(footX)));
    out.dent.tip = f.global(Point(tipLocal.x(), (*edge)(tipLocal.x()) + tipLocal.y()));
    out.dent.width = width;
    out.dent.depth = depth;
    out.dent.square = halfHi - halfLo >= 0.9 * width;
    out.from = from;
    out.to = to;
    // Also the blurred mouth, where the edge bends into the cut: a pixel more either side.
    while (out.from > 0 && u.arc(from) - u.arc(out.from - 1) < 1.5)
        --out.from;
    while (u.arc(out.to + 1) - u.arc(to) < 1.5)
        ++out.to;
    if (out.to - out.from + 1 >= u.size() / 2)
        return std::nullopt;
    return out;
}

} // namespace

std::vector<Dent> takeOutDents(std::vector<Point> &loop, const DentLimits &lim)
{
    const std::size_t n = loop.size();
    if (n < 64 || !(lim.minDepth > 0.0) || !(lim.maxWidth > 0.0) || !(lim.maxDepth >= lim.minDepth))
        return {};
    double area = 0.0;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++)
        area += loop[j].x() * loop[i].y() - loop[i].x() * loop[j].y();
    const double sign = area > 0.0 ? 1.0 : -1.0; // the piece lies to the left of the loop's way
    const Loop u(loop);
    // A window long enough to span the largest notch's two sides.
    const double window = lim.maxWidth + 2.0 * lim.maxDepth;
    if (u.total() < 4.0 * window)
        return {};
    // Candidates: the window's ends are closer than the arc between them and its points dip into
    // the piece. Each run of them is one dent at most, measured at its window of greatest excess.
    std::vector<double> excess(n, 0.0);
    for (std::size_t m = 0; m < n; ++m) {
        const std::size_t k = u.ahead(m, window);
        const Point chord = u.point(k) - u.point(m);
        const double len = chord.norm();
        if (len > lim.maxWidth + 2.0 * window / 3.0 || len <= 0.0)
            continue;
        const double e = (u.arc(k) - u.arc(m)) - len;
        if (e < 0.25 * lim.minDepth)
            continue;
        const Point in = sign * Point(-chord.y(), chord.x()) / len;
        double dip = 0.0;
        for (std::size_t q = m; q <= k; q += 2)
            dip = std::max(dip, (u.point(q) - u.point(m)).dot(in));
        if (dip >= lim.minDepth)
            excess[m] = e;
    }
    // Start at a point that is no candidate, so that no run wraps.
    std::size_t start = 0;
    while (start < n && excess[start] > 0.0)
        ++start;
    if (start == n)
        return {};
    std::vector<Found> found;
    for (std::size_t m = start; m < start + n;) {
        if (excess[m % n] <= 0.0) {
            ++m;
            continue;
        }
        std::size_t best = m;
        for (; m < start + n && excess[m % n] > 0.0; ++m)
            if (excess[m % n] > excess[best % n])
                best = m;
        // Measured on the second lap, so that the edge before it can be looked at.
        const std::size_t b = best % n + n;
        if (auto d = measure(u, b, u.ahead(b, window), sign, lim)) {
            const bool again = std::any_of(found.begin(), found.end(), [&](const Found &o) {
                return (o.dent.tip - d->dent.tip).norm() < lim.maxWidth;
            });
            if (!again)
                found.push_back(*d);
        }
    }
    if (found.empty())
        return {};
    std::vector<bool> drop(n, false);
    std::vector<Dent> dents;
    for (const Found &d : found) {
        for (std::size_t q = d.from; q <= d.to; ++q)
            drop[q % n] = true;
        dents.push_back(d.dent);
    }
    std::vector<Point> kept;
    kept.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (!drop[i])
            kept.push_back(loop[i]);
    loop = std::move(kept);
    return dents;
}

void dropInDents(std::vector<Point> &points, const std::vector<Dent> &dents)
{
    const auto toAxis = [](const Point &q, const Dent &d) {
        return (geo::nearestOnSegment(q, d.foot, d.tip) - q).norm();
    };
    std::erase_if(points, [&](const Point &q) {
        return std::any_of(dents.begin(), dents.end(), [&](const Dent &d) { return toAxis(q, d) < d.width / 2 + 1.0; });
    });
}

} // namespace kontur::vision::detail
