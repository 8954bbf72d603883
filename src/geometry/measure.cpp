// Seam lengths and curve-to-curve deviation; see measure.h.
#include "geometry/measure.h"

#include "geometry/arclength.h"
#include "geometry/parameterization.h"

#include <algorithm>
#include <cmath>

namespace kontur::geo {

Result<double> lengthBetween(const PiecewiseBezier &curve, int first, int last, double accuracy)
{
    const int n = curve.segmentCount();
    if (first < 0 || last < 0 || first > n || last > n)
        return Error{ErrorCode::IndexOutOfRange, "no such joint", first < 0 || first > n ? first : last};
    int count = last - first;
    if (count < 0) {
        if (!curve.isClosed())
            std::swap(first, last), count = -count;
        else
            count += n;
    }
    if (count == 0)
        return 0.0;
    const double each = (accuracy > 0.0 && std::isfinite(accuracy) ? accuracy : 1e-9) / count;
    double sum = 0.0;
    for (int k = 0; k < count; ++k)
        sum += arcLength(curve.segments()[static_cast<std::size_t>((first + k) % n)], each);
    return sum;
}

namespace {

struct OneSided
{
    double maximum = -1.0;
    int segment = 0;
    double t = 0.0;
    double weighted = 0.0; // ∫ d ds
    double length = 0.0;   // ∫ ds
    int samples = 0;
};

OneSided oneSided(const PiecewiseBezier &from, const PiecewiseBezier &to, int m)
{
    OneSided r;
    for (int s = 0; s < from.segmentCount(); ++s) {
        const Bezier &seg = from.segments()[static_cast<std::size_t>(s)];
        const Bezier hodograph = seg.derivativeCurve(1);
        double wd = 0.0, wl = 0.0;
        for (int k = 0; k <= m; ++k) {
            const double t = double(k) / m;
            const double d = to.nearest(seg.eval(t)).distance;
            const double speed = hodograph.isEmpty() ? hodograph.startPoint().norm() : hodograph.eval(t).norm();
            // Simpson's weights 1, 4, 2, 4, …, 4, 1.
            const double w = (k == 0 || k == m) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
            wd += w * d * speed;
            wl += w * speed;
            if (d > r.maximum) {
                r.maximum = d;
                r.segment = s;
                r.t = t;
            }
        }
        r.weighted += wd / (3.0 * m);
        r.length += wl / (3.0 * m);
        r.samples += m + 1;
    }
    // Golden-section search for the largest distance between the neighbours of the best sample.
    const Bezier &seg = from.segments()[static_cast<std::size_t>(r.segment)];
    auto dist = [&](double t) { return to.nearest(seg.eval(t)).distance; };
    double lo = std::max(0.0, r.t - 1.0 / m), hi = std::min(1.0, r.t + 1.0 / m);
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = dist(x1), f2 = dist(x2);
    for (int it = 0; it < 40; ++it) {
        if (f1 > f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - g * (hi - lo), f1 = dist(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + g * (hi - lo), f2 = dist(x2);
        }
        r.samples += 1;
    }
    const double tBest = f1 > f2 ? x1 : x2;
    const double fBest = std::max(f1, f2);
    if (fBest > r.maximum) {
        r.maximum = fBest;
        r.t = tBest;
    }
    return r;
}

} // namespace

namespace {

Result<Deviation> unitDeviation(const PiecewiseBezier &a, const PiecewiseBezier &b, int samplesPerSegment);

PiecewiseBezier scaled(const PiecewiseBezier &c, int e)
{
    std::vector<Bezier> segments;
    segments.reserve(c.segments().size());
    for (const Bezier &s : c.segments()) {
        std::vector<Point> pts = s.controlPoints();
        for (Point &p : pts)
            p = Point(std::ldexp(p.x(), e), std::ldexp(p.y(), e));
        segments.emplace_back(std::move(pts));
    }
    return PiecewiseBezier(std::move(segments), c.isClosed());
}

} // namespace

// Distances times speeds (the weighted mean) underflow at 1e-170 and overflow at 1e160: both curves
// are measured scaled to unit size by a common power of two (exact) and the distances scaled back.
Result<Deviation> deviation(const PiecewiseBezier &a, const PiecewiseBezier &b, int samplesPerSegment)
{
    if (a.isEmpty() || b.isEmpty())
        return Error{ErrorCode::TooFewPoints, "a curve to compare is empty"};
    std::vector<Point> all;
    for (const PiecewiseBezier *c : {&a, &b})
        for (const Bezier &s : c->segments())
            all.insert(all.end(), s.controlPoints().begin(), s.controlPoints().end());
    const int k = scaleExponent(all);
    if (k == 0)
        return unitDeviation(a, b, samplesPerSegment);
    auto r = unitDeviation(scaled(a, -k), scaled(b, -k), samplesPerSegment);
    if (!r)
        return r;
    for (double *v : {&r->maximum, &r->mean, &r->meanAB, &r->meanBA})
        *v = std::ldexp(*v, k);
    for (Point *p : {&r->maximumAt, &r->maximumOther})
        *p = Point(std::ldexp(p->x(), k), std::ldexp(p->y(), k));
    return r;
}

namespace {

Result<Deviation> unitDeviation(const PiecewiseBezier &a, const PiecewiseBezier &b, int samplesPerSegment)
{
    int m = std::max(8, samplesPerSegment);
    m += m % 2; // Simpson needs an even count of intervals
    const OneSided ab = oneSided(a, b, m);
    const OneSided ba = oneSided(b, a, m);
    Deviation d;
    d.maximumOnA = ab.maximum >= ba.maximum;
    const OneSided &worst = d.maximumOnA ? ab : ba;
    const PiecewiseBezier &on = d.maximumOnA ? a : b;
    const PiecewiseBezier &other = d.maximumOnA ? b : a;
    d.maximum = worst.maximum;
    d.maximumAt = on.segments()[static_cast<std::size_t>(worst.segment)].eval(worst.t);
    d.maximumOther = other.nearest(d.maximumAt).point;
    d.meanAB = ab.length > 0.0 ? ab.weighted / ab.length : 0.0;
    d.meanBA = ba.length > 0.0 ? ba.weighted / ba.length : 0.0;
    const double total = ab.length + ba.length;
    d.mean = total > 0.0 ? (ab.weighted + ba.weighted) / total : 0.0;
    d.samples = ab.samples + ba.samples;
    return d;
}

} // namespace

} // namespace kontur::geo
