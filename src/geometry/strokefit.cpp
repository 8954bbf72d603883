// The multi-segment stroke fit: corners first, then Schneider's recursive fit of each span between
// corners (Graphics Gems I, 1990): chord-length parameters, a cubic with the end tangents fixed by
// least squares, Newton reparameterization, and a split at the point of largest error with one
// tangent shared by both sides (G1), then neighbours merged again where fewer segments fit. Over 600
// lines because the corner test, the fitter's split and merge passes and their shared tangent and
// parameter estimates work on one polyline and belong together; detectCorners is public for tests.
#include "geometry/strokefit.h"

#include "geometry/parameterization.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::geo {

Bezier StrokeFit::segment(int i) const
{
    const auto first = control.begin() + 3 * i;
    return Bezier(std::vector<Point>(first, first + 4));
}

namespace {

// Points along the stroke with their cumulative chord length.
struct Polyline
{
    std::span<const Point> p;
    std::vector<double> s;

    // The point at arc length `at` (clamped to the stroke), interpolated along the polyline,
    // searching forward from index `hint` (updated), so that monotone queries cost O(1) each.
    Point at(double length, int &hint) const
    {
        const int last = static_cast<int>(p.size()) - 1;
        length = std::clamp(length, 0.0, s.back());
        hint = std::clamp(hint, 0, last);
        while (hint > 0 && s[static_cast<std::size_t>(hint)] > length)
            --hint;
        while (hint < last && s[static_cast<std::size_t>(hint) + 1] < length)
            ++hint;
        if (hint == last)
            return p[static_cast<std::size_t>(last)];
        const double a = s[static_cast<std::size_t>(hint)];
        const double b = s[static_cast<std::size_t>(hint) + 1];
        const double f = b > a ? (length - a) / (b - a) : 0.0;
        return p[static_cast<std::size_t>(hint)] +
               f * (p[static_cast<std::size_t>(hint) + 1] - p[static_cast<std::size_t>(hint)]);
    }
};

std::vector<double> cumulativeLength(std::span<const Point> p)
{
    std::vector<double> s(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i)
        s[i] = s[i - 1] + (p[i] - p[i - 1]).norm();
    return s;
}

// Chord-length parameters of a hand-drawn stroke: when the samples are about as far apart as the hand
// jitters, the raw polyline zigzags and its length runs ahead unevenly. The chord lengths are taken
// along the stroke smoothed by a moving average over ±h (arc length) instead; only the parameters
// and tangents use it, the errors are measured against the points as drawn.
std::vector<double> parameterLength(std::span<const Point> p, double h)
{
    const std::size_t n = p.size();
    if (n == 0)
        return {};
    const std::vector<double> raw = cumulativeLength(p);
    std::vector<Point> prefix(n + 1, Point::Zero());
    for (std::size_t i = 0; i < n; ++i)
        prefix[i + 1] = prefix[i] + p[i];
    std::vector<double> s(n, 0.0);
    std::size_t lo = 0, hi = 0;
    Point prev = Point::Zero();
    for (std::size_t i = 0; i < n; ++i) {
        while (raw[lo] < raw[i] - h)
            ++lo;
        hi = std::max(hi, i);
        while (hi + 1 < n && raw[hi + 1] <= raw[i] + h)
            ++hi;
        const Point q = (prefix[hi + 1] - prefix[lo]) / static_cast<double>(hi - lo + 1);
        if (i > 0)
            s[i] = s[i - 1] + (q - prev).norm();
        prev = q;
    }
    return s;
}

// The tangent direction at p[i] looking one way (step +1 forward, -1 backward, the result pointing
// that way), from the stroke inside [lo, hi]: the derivative of the parabola through p[i] and the
// points about `window` and 2 × `window` away (at least the next two), by chord length. A second-order
// estimate (Schneider takes the chord to the neighbour, first order) over a window that keeps hand
// jitter out of the tangent.
Point sideDirection(const Polyline &line, int i, int lo, int hi, double window, int step)
{
    const auto at = [&](int j) { return static_cast<std::size_t>(j); };
    int j = i + step;
    if (j < lo || j > hi)
        return Point::Zero();
    while (j + step >= lo && j + step <= hi && std::abs(line.s[at(j)] - line.s[at(i)]) < window)
        j += step;
    int k = j + step;
    while (k + step >= lo && k + step <= hi && std::abs(line.s[at(k)] - line.s[at(i)]) < 2.0 * window)
        k += step;
    const Point p0 = line.p[at(i)], pj = line.p[at(j)];
    const double h1 = std::abs(line.s[at(j)] - line.s[at(i)]);
    if (k < lo || k > hi || !(h1 > 0.0))
        return pj - p0;
    const Point pk = line.p[at(k)];
    const double h2 = std::abs(line.s[at(k)] - line.s[at(i)]);
    if (!(h2 > h1))
        return pj - p0;
    const Point d = (pj - p0) * (h2 / (h1 * (h2 - h1))) - (pk - p0) * (h1 / (h2 * (h2 - h1)));
    // A parabola on very uneven points can point backwards; the chord cannot.
    return d.dot(pj - p0) > 0.0 ? d : Point(pj - p0);
}

Point unitOr(const Point &v, const Point &fallback)
{
    const double n = v.norm();
    return n > 0.0 && std::isfinite(n) ? Point(v / n) : fallback;
}

class Fitter
{
public:
    Fitter(const Polyline &line, double tolerance, double tangentWindow, int iterations)
        : m_line(line)
        , m_tol(tolerance)
        , m_window(tangentWindow)
        , m_iterations(iterations)
    {
    }

    // Fits points first..last (inclusive) with tangents t1 (at the start, pointing into the span)
    // and t2 (at the end, pointing back into the span); appends c1, c2, c3 of each segment to `out`.
    // At the span's own ends (a corner or an end of the stroke) nothing has to join smoothly, so the
    // handles there are free (the tangents are only a fallback); joins made by splitting share one
    // tangent direction.
    void fitSpan(int first, int last, Point t1, Point t2, std::vector<Point> &out, std::vector<bool> &corner)
    {
        struct Job
        {
            int first, last;
            Point t1, t2;
            bool free1, free2;
        };
        std::vector<Job> stack{{first, last, t1, t2, true, true}};
        // The segments in order along the span, each with the stroke points it covers.
        struct Segment
        {
            Job job;
            std::array<Point, 4> c;
            double err;
        };
        std::vector<Segment> segments;
        while (!stack.empty()) {
            const Job job = stack.back();
            stack.pop_back();
            std::array<Point, 4> c;
            int split = -1;
            if (fitOne(job.first, job.last, job.t1, job.t2, job.free1, job.free2, c, split)) {
                segments.push_back({job, c, m_lastSquared});
                continue;
            }
            // Split at the worst point, with one tangent for both sides: a smooth (G1) join.
            const Point center = joinTangent(split, job.first, job.last);
            stack.push_back({split, job.last, center, job.t2, false, job.free2});
            stack.push_back({job.first, split, job.t1, -center, job.free1, false});
        }
        // Splitting at the worst point of the whole span fixes where the pieces join; two neighbours
        // often fit within the tolerance as one cubic after all (the split that made them served a
        // part further on). Merge such pairs, keeping the outer joints' tangents (G1 stays), until
        // none is left: fewer segments for the same tolerance.
        // A pair that did not fit stays apart until one of its two segments changes (`tried`).
        const auto mergePairs = [&] {
            std::vector<bool> tried(segments.size(), false); // tried[i]: segments i and i + 1
            for (bool merged = true; merged;) {
                merged = false;
                for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
                    if (tried[i])
                        continue;
                    const Job &a = segments[i].job, &b = segments[i + 1].job;
                    const Job both{a.first, b.last, a.t1, b.t2, a.free1, b.free2};
                    std::array<Point, 4> c;
                    int split = -1;
                    if (fitOne(both.first, both.last, both.t1, both.t2, both.free1, both.free2, c, split)) {
                        segments[i] = {both, c, m_lastSquared};
                        segments.erase(segments.begin() + static_cast<std::ptrdiff_t>(i) + 1);
                        tried.erase(tried.begin() + static_cast<std::ptrdiff_t>(i) + 1);
                        tried[i] = false;
                        if (i > 0)
                            tried[i - 1] = false;
                        merged = true;
                    } else {
                        tried[i] = true;
                    }
                }
            }
        };
        // Three neighbours often fit as two once their joins move (noisy points put the worst point,
        // where a span was split, away from where the shape changes). The one join is tried at
        // evenly spaced points of the three; the first where both halves fit replaces them.
        const auto mergeTriple = [&] {
            constexpr int tries = 48;
            for (std::size_t i = 0; i + 2 < segments.size(); ++i) {
                const Job &a = segments[i].job, &b = segments[i + 2].job;
                for (int q = 1; q < tries; ++q) {
                    const int split = a.first + (b.last - a.first) * q / tries;
                    if (split - a.first < 2 || b.last - split < 2)
                        continue;
                    const Point center = joinTangent(split, a.first, b.last);
                    const Job left{a.first, split, a.t1, -center, a.free1, false};
                    const Job right{split, b.last, center, b.t2, false, b.free2};
                    std::array<Point, 4> cl, cr;
                    int unused = -1;
                    if (!fitOne(left.first, left.last, left.t1, left.t2, left.free1, left.free2, cl, unused))
                        continue;
                    const double leftErr = m_lastSquared;
                    if (!fitOne(right.first, right.last, right.t1, right.t2, right.free1, right.free2, cr, unused))
                        continue;
                    segments[i] = {left, cl, leftErr};
                    segments[i + 1] = {right, cr, m_lastSquared};
                    segments.erase(segments.begin() + static_cast<std::ptrdiff_t>(i) + 2);
                    return true;
                }
            }
            return false;
        };
        do
            mergePairs();
        while (mergeTriple());
        for (const Segment &segment : segments) {
            out.push_back(segment.c[1]);
            out.push_back(segment.c[2]);
            out.push_back(segment.c[3]);
            corner.push_back(false);
            m_maxSquared = std::max(m_maxSquared, segment.err);
        }
    }

    double maxError() const { return std::sqrt(m_maxSquared); }

private:
    // The one tangent of a smooth join at point `split` of the span first..last, pointing forward:
    // the mean of the directions looking either way (the neighbours' chord when they cancel).
    Point joinTangent(int split, int first, int last) const
    {
        const Point fwd = unitOr(sideDirection(m_line, split, first, last, m_window, +1), Point::Zero());
        const Point bwd = unitOr(sideDirection(m_line, split, first, last, m_window, -1), Point::Zero());
        const auto us = static_cast<std::size_t>(split);
        return unitOr(fwd - bwd, unitOr(m_line.p[us + 1] - m_line.p[us - 1], Point(1, 0)));
    }

    // One cubic for the span; true when it is within tolerance (then `c` holds it), otherwise
    // `split` is the interior point to split at.
    bool fitOne(int first, int last, const Point &t1, const Point &t2, bool free1, bool free2, std::array<Point, 4> &c,
                int &split)
    {
        const Point p0 = m_line.p[static_cast<std::size_t>(first)];
        const Point p3 = m_line.p[static_cast<std::size_t>(last)];
        const double chord = (p3 - p0).norm();
        if (last - first == 1) {
            // Two points: a straight cubic along the chord (Schneider's heuristic handles at 1/3).
            c = {p0, p0 + t1 * chord / 3.0, p3 + t2 * chord / 3.0, p3};
            m_lastSquared = 0.0;
            return true;
        }
        const std::size_t n = static_cast<std::size_t>(last - first + 1);
        m_u.resize(n);
        const double s0 = m_line.s[static_cast<std::size_t>(first)];
        const double len = m_line.s[static_cast<std::size_t>(last)] - s0;
        for (std::size_t k = 0; k < n; ++k)
            m_u[k] = len > 0.0 ? (m_line.s[static_cast<std::size_t>(first) + k] - s0) / len : double(k) / double(n - 1);

        generate(first, last, t1, t2, free1, free2, len, c);
        int worst = 0;
        double err = maxSquaredError(first, c, worst);
        // Schneider reparameterizes only when the error is within 4 × the tolerance; chord-length
        // parameters of a stroke drawn at varying speed are often worse than that although one cubic
        // fits, so up to 30 × the parameters are improved first while that keeps paying off (each
        // round is O(points); beyond that the span clearly needs a split).
        if (err > m_tol * m_tol && err < 900.0 * m_tol * m_tol) {
            std::array<Point, 4> best = c;
            double bestErr = err;
            int bestWorst = worst;
            for (int it = 0; it < m_iterations && bestErr > m_tol * m_tol; ++it) {
                reparameterize(first, c);
                generate(first, last, t1, t2, free1, free2, len, c);
                err = maxSquaredError(first, c, worst);
                if (err > 0.95 * bestErr)
                    break; // stalled: split instead
                if (err < bestErr) {
                    best = c;
                    bestErr = err;
                    bestWorst = worst;
                }
            }
            c = best;
            err = bestErr;
            worst = bestWorst;
        }
        if (err <= m_tol * m_tol) {
            m_lastSquared = err;
            return true;
        }
        split = std::clamp(first + worst, first + 1, last - 1);
        return false;
    }

    // The least-squares cubic through the span's end points. With both tangent directions fixed
    // only the two handle lengths are unknown, a 2×2 system (Schneider's GenerateBezier); a free
    // handle adds its two coordinates instead (at most 4 unknowns, normal equations by LDLT).
    void generate(int first, int last, const Point &t1, const Point &t2, bool free1, bool free2, double arc,
                  std::array<Point, 4> &c) const
    {
        const Point p0 = m_line.p[static_cast<std::size_t>(first)];
        const Point p3 = m_line.p[static_cast<std::size_t>(last)];
        // c1 = p0 + A1 z1, c2 = p3 + A2 z2 with A = I (free) or the tangent (a length along it).
        const int n1 = free1 ? 2 : 1, n2 = free2 ? 2 : 1, m = n1 + n2;
        Eigen::Matrix<double, 2, 4> a1 = Eigen::Matrix<double, 2, 4>::Zero(), a2 = Eigen::Matrix<double, 2, 4>::Zero();
        if (free1)
            a1.leftCols<2>().setIdentity();
        else
            a1.col(0) = t1;
        if (free2)
            a2.block<2, 2>(0, n1).setIdentity();
        else
            a2.col(n1) = t2;
        Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
        Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
        for (std::size_t k = 0; k < m_u.size(); ++k) {
            const double u = m_u[k], v = 1.0 - u;
            const double b0 = v * v * v, b1 = 3 * u * v * v, b2 = 3 * u * u * v, b3 = u * u * u;
            const Eigen::Matrix<double, 2, 4> j = b1 * a1 + b2 * a2;
            const Point r = m_line.p[static_cast<std::size_t>(first) + k] - (p0 * (b0 + b1) + p3 * (b2 + b3));
            normal.noalias() += j.transpose() * j;
            rhs.noalias() += j.transpose() * r;
        }
        const double chord = (p3 - p0).norm();
        const double eps = 1e-6 * std::max(chord, arc);
        Eigen::Vector4d z = Eigen::Vector4d::Zero();
        bool good = false;
        if (m_u.size() >= 3) {
            const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal.topLeftCorner(m, m));
            if (ldlt.info() == Eigen::Success && ldlt.isPositive()) {
                z.head(m) = ldlt.solve(rhs.head(m));
                good = z.allFinite();
            }
        }
        Point h1 = a1 * z, h2 = a2 * z;
        // Negative, tiny or runaway handles (longer than the span itself): Schneider's 1/3 heuristic
        // along the estimated tangents.
        const auto bad = [&](const Point &h, bool free, const Point &t) {
            return !(h.norm() > eps && h.norm() <= arc && (free || h.dot(t) > 0.0));
        };
        if (!good || bad(h1, free1, t1) || bad(h2, free2, t2)) {
            h1 = t1 * chord / 3.0;
            h2 = t2 * chord / 3.0;
        }
        c = {p0, p0 + h1, p3 + h2, p3};
    }

    double maxSquaredError(int first, const std::array<Point, 4> &c, int &worst) const
    {
        double maxErr = 0.0;
        worst = static_cast<int>(m_u.size()) / 2;
        for (std::size_t k = 1; k + 1 < m_u.size(); ++k) {
            const double e = (evalCubic(c, m_u[k]) - m_line.p[static_cast<std::size_t>(first) + k]).squaredNorm();
            if (e > maxErr) {
                maxErr = e;
                worst = static_cast<int>(k);
            }
        }
        return maxErr;
    }

    // One Newton step per point towards its foot point on the cubic: u -= f/f', with
    // f = (Q(u) - p)·Q'(u) (Schneider's NewtonRaphsonRootFind).
    void reparameterize(int first, const std::array<Point, 4> &c)
    {
        const std::array<Point, 3> d1 = {3 * (c[1] - c[0]), 3 * (c[2] - c[1]), 3 * (c[3] - c[2])};
        const std::array<Point, 2> d2 = {2 * (d1[1] - d1[0]), 2 * (d1[2] - d1[1])};
        for (std::size_t k = 1; k + 1 < m_u.size(); ++k) {
            const double u = m_u[k], v = 1.0 - u;
            const Point q = evalCubic(c, u);
            const Point q1 = v * v * d1[0] + 2 * u * v * d1[1] + u * u * d1[2];
            const Point q2 = v * d2[0] + u * d2[1];
            const Point diff = q - m_line.p[static_cast<std::size_t>(first) + k];
            const double num = diff.dot(q1);
            const double den = q1.dot(q1) + diff.dot(q2);
            if (den != 0.0 && std::isfinite(num / den))
                m_u[k] = std::clamp(u - num / den, 0.0, 1.0);
        }
    }

    static Point evalCubic(const std::array<Point, 4> &c, double u)
    {
        const double v = 1.0 - u;
        return v * v * v * c[0] + 3 * u * v * v * c[1] + 3 * u * u * v * c[2] + u * u * u * c[3];
    }

    const Polyline &m_line;
    double m_tol;
    double m_window;
    int m_iterations;
    std::vector<double> m_u;
    double m_maxSquared = 0.0;
    double m_lastSquared = 0.0; // the squared error of the last cubic fitOne accepted
};

} // namespace

std::vector<int> detectCorners(std::span<const Point> points, double angleDegrees, double window)
{
    std::vector<int> corners;
    const int n = static_cast<int>(points.size());
    if (n < 3 || !(window > 0.0))
        return corners;
    const Polyline line{points, cumulativeLength(points)};
    const double total = line.s.back();
    const double threshold = angleDegrees * std::numbers::pi / 180.0;
    int backHint = 0, fwdHint = 0;
    int runBest = -1;
    double runAngle = 0.0;
    for (int i = 1; i + 1 < n; ++i) {
        const double si = line.s[static_cast<std::size_t>(i)];
        double angle = 0.0;
        // Near the ends a corner needs at least half a window of stroke on both sides.
        if (si >= 0.5 * window && total - si >= 0.5 * window) {
            const Point back = line.at(si - window, backHint);
            const Point fwd = line.at(si + window, fwdHint);
            const Point a = points[static_cast<std::size_t>(i)] - back;
            const Point b = fwd - points[static_cast<std::size_t>(i)];
            const double na = a.norm(), nb = b.norm();
            if (na > 0.0 && nb > 0.0)
                angle = std::acos(std::clamp(a.dot(b) / (na * nb), -1.0, 1.0));
        }
        // Non-maximum suppression: one corner per run of points above the threshold, where the
        // stroke turns most.
        if (angle > threshold) {
            if (runBest < 0 || angle > runAngle) {
                runBest = i;
                runAngle = angle;
            }
        } else if (runBest >= 0) {
            corners.push_back(runBest);
            runBest = -1;
        }
    }
    if (runBest >= 0)
        corners.push_back(runBest);
    return corners;
}

namespace {
Result<StrokeFit> unitFitStroke(std::span<const Point> stroke, const StrokeFitOptions &options);
} // namespace

// The fit is exact under scaling but squares distances throughout: it runs on the stroke scaled to
// unit size by a power of two (exact, with the tolerance and window), and the curve is scaled back.
Result<StrokeFit> fitStroke(std::span<const Point> stroke, const StrokeFitOptions &options)
{
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
        return Error{ErrorCode::InvalidArgument, "the tolerance must be positive and finite"};
    const int k = scaleExponent(stroke);
    if (k == 0)
        return unitFitStroke(stroke, options);
    std::vector<Point> unit(stroke.begin(), stroke.end());
    for (Point &p : unit)
        p = Point(std::ldexp(p.x(), -k), std::ldexp(p.y(), -k));
    StrokeFitOptions scaled = options;
    scaled.tolerance = std::ldexp(options.tolerance, -k);
    scaled.cornerWindow = std::ldexp(options.cornerWindow, -k);
    if (!(scaled.tolerance > 0.0) || !std::isfinite(scaled.tolerance))
        return Error{ErrorCode::InvalidArgument, "the tolerance must be positive and finite"};
    auto r = unitFitStroke(unit, scaled);
    if (!r)
        return r;
    for (Point &c : r->control) {
        c = Point(std::ldexp(c.x(), k), std::ldexp(c.y(), k));
        if (!c.allFinite())
            return Error{ErrorCode::NonFiniteInput, "the points are too far apart to measure", -1};
    }
    r->maxError = std::ldexp(r->maxError, k);
    return r;
}

namespace {

Result<StrokeFit> unitFitStroke(std::span<const Point> stroke, const StrokeFitOptions &options)
{
    Box box;
    for (std::size_t i = 0; i < stroke.size(); ++i) {
        if (!stroke[i].allFinite())
            return Error{ErrorCode::NonFiniteInput, "a stroke point is not finite", static_cast<int>(i)};
        box.extend(stroke[i]);
    }
    // Drop repeated samples (a resting stylus reports the same place many times).
    std::vector<Point> pts;
    pts.reserve(stroke.size());
    const double size = stroke.empty() ? 0.0 : box.sizes().maxCoeff();
    const double dupe = 1e-9 * std::max(size, 1e-300);
    for (const Point &p : stroke)
        if (pts.empty() || (p - pts.back()).norm() > dupe)
            pts.push_back(p);
    if (pts.size() < 2)
        return Error{pts.empty() ? ErrorCode::TooFewPoints : ErrorCode::AllPointsEqual,
                     "a stroke needs at least 2 distinct points"};

    // The default corner window: 4 × the tolerance, but at least 3 × the median sample spacing. A
    // device that delivers few samples (fast strokes, coalesced touch events) cuts a corner with a
    // short diagonal, two turns of half the angle each; seen over a few samples it is one turn again.
    double cornerWindow = options.cornerWindow;
    if (!(cornerWindow > 0.0)) {
        std::vector<double> spacing;
        for (std::size_t i = 1; i < pts.size(); ++i)
            spacing.push_back((pts[i] - pts[i - 1]).norm());
        const auto mid = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
        std::nth_element(spacing.begin(), mid, spacing.end());
        cornerWindow = std::max(4.0 * options.tolerance, 3.0 * *mid);
    }
    std::vector<int> breaks{0};
    {
        // A corner cut by a diagonal between two samples (a fast stroke) is put back where the two
        // sides meet: the point X where the line coming in through sample c meets the line going
        // out through sample c + 1 (or c - 1 and c) is added to the stroke as the corner.
        // Corners are looked for on the stroke thinned to one sample per tolerance: samples much
        // denser than the hand's jitter (a fast stylus) zigzag, and their raw arc length, which the
        // corner window is measured in, runs far ahead of the distance actually travelled.
        std::vector<Point> thin;
        std::vector<int> thinIndex;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (thin.empty() || i + 1 == pts.size() || (pts[i] - thin.back()).norm() >= options.tolerance) {
                thin.push_back(pts[i]);
                thinIndex.push_back(static_cast<int>(i));
            }
        }
        std::vector<int> corners = detectCorners(thin, options.cornerAngle, cornerWindow);
        for (int &c : corners)
            c = thinIndex[static_cast<std::size_t>(c)];
        const Polyline raw{pts, cumulativeLength(pts)};
        std::vector<std::pair<int, Point>> inserts; // X goes in before this index
        std::vector<int> insertedAt(corners.size(), -1);
        for (std::size_t ci = 0; ci < corners.size(); ++ci) {
            const int c = corners[ci];
            for (int first : {c, c - 1}) {
                const int second = first + 1;
                if (first < 1 || second + 1 >= static_cast<int>(pts.size()))
                    continue;
                int hint = 0;
                const Point p1 = pts[static_cast<std::size_t>(first)], p2 = pts[static_cast<std::size_t>(second)];
                const Point d1 =
                    unitOr(p1 - raw.at(raw.s[static_cast<std::size_t>(first)] - cornerWindow, hint), Point::Zero());
                const Point d2 =
                    unitOr(raw.at(raw.s[static_cast<std::size_t>(second)] + cornerWindow, hint) - p2, Point::Zero());
                const Point cut = unitOr(p2 - p1, Point::Zero());
                const double cross = d1.x() * d2.y() - d1.y() * d2.x();
                // Both ends of the cut must turn (by more than 10°), and the sides must meet ahead.
                if (d1.dot(cut) > std::cos(0.17) || cut.dot(d2) > std::cos(0.17) || std::abs(cross) < 1e-3)
                    continue;
                const Point r = p2 - p1;
                const double t = (r.x() * d2.y() - r.y() * d2.x()) / cross;
                const double u = (d1.x() * r.y() - d1.y() * r.x()) / cross; // t d1 + u d2 = r
                if (!(t > 0.0 && u > 0.0 && t < 2.0 * r.norm() && u < 2.0 * r.norm()))
                    continue;
                if (!inserts.empty() && inserts.back().first >= second)
                    continue; // two corners on one cut: keep the first
                inserts.emplace_back(second, p1 + t * d1);
                insertedAt[ci] = second;
                break;
            }
        }
        if (!inserts.empty()) {
            std::vector<Point> withCorners;
            withCorners.reserve(pts.size() + inserts.size());
            std::size_t k = 0;
            for (std::size_t i = 0; i < pts.size(); ++i) {
                while (k < inserts.size() && inserts[k].first == static_cast<int>(i))
                    withCorners.push_back(inserts[k++].second);
                withCorners.push_back(pts[i]);
            }
            pts = std::move(withCorners);
            // New indices: an inserted corner lands at its position plus the insertions before it; a
            // sample moves on by the insertions at or before it.
            for (std::size_t ci = 0; ci < corners.size(); ++ci) {
                const bool inserted = insertedAt[ci] >= 0;
                const int at = inserted ? insertedAt[ci] : corners[ci];
                int shift = 0;
                for (const auto &ins : inserts)
                    if (ins.first < at || (!inserted && ins.first == at))
                        ++shift;
                corners[ci] = at + shift;
            }
        }
        for (int c : corners)
            breaks.push_back(c);
    }
    breaks.push_back(static_cast<int>(pts.size()) - 1);
    const Polyline line{pts, parameterLength(pts, 0.5 * options.tolerance)};

    StrokeFit result;
    result.pointsUsed = static_cast<int>(pts.size());
    result.control.push_back(pts.front());
    result.corner.push_back(false);
    // Tangents at splits over 8 × the tolerance: over 2 × (Schneider: the neighbour) a hand's jitter of a
    // third of the tolerance turned them by up to 17°, and pieces that could have been one split again.
    const double tangentWindow = 8.0 * options.tolerance;
    Fitter fitter(line, options.tolerance, tangentWindow, std::max(0, options.reparameterizeIterations));
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
        const int first = breaks[b], last = breaks[b + 1];
        const double spanLength = line.s[static_cast<std::size_t>(last)] - line.s[static_cast<std::size_t>(first)];
        // End tangents from at most a third of the span, so that short spans keep their own direction.
        const double w = std::min(tangentWindow, spanLength / 3.0);
        const Point chord =
            unitOr(pts[static_cast<std::size_t>(last)] - pts[static_cast<std::size_t>(first)], Point(1, 0));
        const Point t1 = unitOr(sideDirection(line, first, first, last, w, +1), chord);
        const Point t2 = unitOr(sideDirection(line, last, first, last, w, -1), -chord);
        if (b > 0)
            result.corner.back() = true;
        fitter.fitSpan(first, last, t1, t2, result.control, result.corner);
    }
    result.maxError = fitter.maxError();
    return result;
}

} // namespace

} // namespace kontur::geo
