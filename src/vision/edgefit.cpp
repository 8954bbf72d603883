// Sub-pixel edge points along normals and the robust total-least-squares line through them.
#include "edgefit.h"

#include "vision/pixels.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace kontur::vision {

std::optional<std::pair<geo::Point, geo::Point>> fitLineTls(std::span<const geo::Point> pts)
{
    if (pts.size() < 2)
        return std::nullopt;
    geo::Point c = geo::Point::Zero();
    for (const geo::Point &p : pts)
        c += p;
    c /= static_cast<double>(pts.size());
    double sxx = 0, sxy = 0, syy = 0;
    for (const geo::Point &p : pts) {
        const geo::Point d = p - c;
        sxx += d.x() * d.x();
        sxy += d.x() * d.y();
        syy += d.y() * d.y();
    }
    // Major axis of the scatter matrix: the direction minimising the sum of squared normal distances.
    const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
    return std::pair{c, geo::Point(std::cos(angle), std::sin(angle))};
}

std::optional<geo::Point> intersect(const EdgeLine &a, const EdgeLine &b, double minAngleRad)
{
    const double cross = a.direction.x() * b.direction.y() - a.direction.y() * b.direction.x();
    if (std::abs(cross) < std::sin(minAngleRad))
        return std::nullopt;
    // a.point + s a.direction lies on b: (a.point + s a.dir - b.point) x b.dir = 0.
    const geo::Point d = b.point - a.point;
    const double s = (d.x() * b.direction.y() - d.y() * b.direction.x()) / cross;
    return geo::Point(a.point + s * a.direction);
}

namespace {

// The largest bow an edge may have and still be fitted whole: its sagitta as a share of its length.
constexpr double kMaxSagitta = 0.01;

struct Candidate
{
    geo::Point p;
    double strength;
};

// The edge point on one profile: where the intensity falls most towards `outward` over a step of
// ±kStepPx (so a soft, large edge — the paper's against the table — wins over a sharp, small one — wood
// grain, a tile's grout), then the greatest fall per px within ±kStepPx of it, interpolated by a parabola
// through it and its neighbours (half-pixel spacing). Each profile value averages three samples one pixel
// apart along the edge, which smooths noise without blurring across it.
std::optional<Candidate> profileEdge(const cv::Mat &gray, const geo::Point &c, const geo::Point &tangent,
                                     const geo::Point &outward, double radius)
{
    constexpr double h = 0.5;
    constexpr double kStepPx = 4.0;
    constexpr int step = static_cast<int>(kStepPx / h);
    const int n = static_cast<int>(std::ceil(radius / h)) + step + 2;
    std::vector<double> v(2 * n + 1);
    for (int i = -n; i <= n; ++i) {
        const geo::Point q = c + (i * h) * outward;
        double sum = 0;
        for (int k = -1; k <= 1; ++k)
            sum += sampleBilinear(gray, q.x() + k * tangent.x(), q.y() + k * tangent.y());
        v[i + n] = sum / 3.0;
    }
    // Fall per px towards outward, central differences over one pixel: d[i] at offset i*h.
    std::vector<double> d(v.size(), 0.0);
    for (int i = 1; i + 1 < static_cast<int>(v.size()); ++i)
        d[i] = (v[i - 1] - v[i + 1]) / (2 * h);
    const int limit = static_cast<int>(std::floor(radius / h));
    int coarse = -1;
    double coarseValue = 0;
    for (int i = n - limit; i <= n + limit; ++i) {
        const double fall = v[i - step] - v[i + step];
        if (fall > coarseValue) {
            coarseValue = fall;
            coarse = i;
        }
    }
    if (coarse < 0)
        return std::nullopt;
    int best = -1;
    double bestValue = 0;
    for (int i = std::max(n - limit, coarse - step); i <= std::min(n + limit, coarse + step); ++i) {
        if (d[i] > bestValue && d[i] >= d[i - 1] && d[i] >= d[i + 1]) {
            bestValue = d[i];
            best = i;
        }
    }
    if (best < 0)
        return std::nullopt;
    const double dm = d[best - 1], d0 = d[best], dp = d[best + 1];
    const double denom = dm - 2 * d0 + dp;
    const double shift = denom < 0 ? std::clamp(0.5 * (dm - dp) / denom, -0.5, 0.5) : 0.0;
    return Candidate{c + ((best - n + shift) * h) * outward, bestValue};
}

struct LineFit
{
    geo::Point centroid;
    geo::Point direction;
};

LineFit tls(const std::vector<geo::Point> &pts, const std::vector<int> &use)
{
    std::vector<geo::Point> used;
    used.reserve(use.size());
    for (int i : use)
        used.push_back(pts[i]);
    const auto line = fitLineTls(used);
    return line ? LineFit{line->first, line->second} : LineFit{geo::Point::Zero(), geo::Point(1, 0)};
}

} // namespace

double edgeBend(const cv::Mat &gray, const EdgeSearch &s)
{
    constexpr int kStretches = 8;
    const geo::Point span = s.to - s.from;
    const double length = span.norm();
    if (gray.empty() || gray.type() != CV_8UC1 || !(length > 2 * s.stepPx) || !(s.radiusPx > 0))
        return 0.0;
    const geo::Point tangent = span / length;
    geo::Point outward(tangent.y(), -tangent.x());
    if (outward.dot(s.outward) < 0)
        outward = -outward;
    std::array<std::vector<double>, kStretches> offsets;
    const int samples = static_cast<int>(length / s.stepPx) + 1;
    for (int i = 0; i < samples; ++i) {
        const geo::Point c = s.from + (i * s.stepPx) * tangent;
        if (auto e = profileEdge(gray, c, tangent, outward, s.radiusPx))
            offsets[static_cast<std::size_t>(std::min(kStretches - 1, i * kStretches / samples))].push_back(
                (e->p - c).dot(outward));
    }
    double lo = INFINITY, hi = -INFINITY;
    for (auto &o : offsets) {
        if (o.size() < 4)
            continue;
        std::nth_element(o.begin(), o.begin() + static_cast<std::ptrdiff_t>(o.size() / 2), o.end());
        lo = std::min(lo, o[o.size() / 2]);
        hi = std::max(hi, o[o.size() / 2]);
    }
    return hi >= lo ? hi - lo : 0.0;
}

double lineShare(const cv::Mat &gray, const EdgeLine &edge, geo::Point from, geo::Point to, double reachPx,
                 double stepPx)
{
    constexpr double h = 0.5; // px between samples across the edge
    constexpr double kInsidePx = 4.0;
    const geo::Point span = to - from;
    const double length = span.norm();
    if (gray.empty() || gray.type() != CV_8UC1 || !(length > stepPx) || !(stepPx > 0) || !(reachPx > 0))
        return 0.0;
    const int n = static_cast<int>(std::ceil(reachPx / h));
    int profiles = 0, lines = 0;
    for (double t = 0; t <= length; t += stepPx) {
        // The point on the edge's line across from this one on the stretch.
        const geo::Point q = from + (t / length) * span;
        const geo::Point c = q - (q - edge.point).dot(edge.outward) * edge.outward;
        const auto at = [&](double offset) {
            const geo::Point p = c + offset * edge.outward;
            return sampleBilinear(gray, p.x(), p.y());
        };
        const double paper = at(-kInsidePx);
        double dark = at(0), darkAt = 0;
        for (int i = 1; i <= n; ++i)
            if (const double v = at(i * h); v < dark) {
                dark = v;
                darkAt = i * h;
            }
        double bright = dark;
        for (double o = darkAt; o <= reachPx + kInsidePx; o += h)
            bright = std::max(bright, at(o));
        ++profiles;
        if (paper - dark > 0 && bright - dark >= 0.5 * (paper - dark))
            ++lines;
    }
    return profiles > 0 ? static_cast<double>(lines) / profiles : 0.0;
}

Result<EdgeLine> fitEdge(const cv::Mat &gray, const EdgeSearch &s)
{
    if (gray.empty() || gray.type() != CV_8UC1)
        return Error{ErrorCode::InvalidImage, "edge search needs an 8-bit single-channel image"};
    const geo::Point span = s.to - s.from;
    const double length = span.norm();
    if (!(length > 2 * s.stepPx) || !(s.radiusPx > 0))
        return Error{ErrorCode::InvalidArgument, "edge stretch too short"};
    const geo::Point tangent = span / length;
    geo::Point outward(tangent.y(), -tangent.x());
    if (outward.dot(s.outward) < 0)
        outward = -outward;

    std::vector<geo::Point> pts;
    std::vector<double> strength;
    const int samples = static_cast<int>(length / s.stepPx) + 1;
    for (int i = 0; i < samples; ++i) {
        const geo::Point c = s.from + (i * s.stepPx) * tangent;
        if (auto e = profileEdge(gray, c, tangent, outward, s.radiusPx)) {
            pts.push_back(e->p);
            strength.push_back(e->strength);
        }
    }
    const auto failed = [&] { return Error{ErrorCode::NoSheetFound, "no straight edge along the stretch"}; };
    if (pts.size() < 12)
        return failed();

    // Which points lie on the edge: RANSAC (deterministic) on triples spread along the stretch, each
    // giving the quadratic u(t) = a + b t + c t^2 of the offset u across the stretch over the position t
    // along it, inliers within s.inlierPx of it, or within twice that when too few agree (a soft-focus
    // edge scatters its points more). A quadratic, not a line, so that an edge bowed by the lens or
    // the paper (real photos: up to 6 px over a side) keeps its whole length: a line's band would keep
    // only the part of the bow the band covers and give a tangent to it, whose corners lie several
    // pixels along the neighbouring edges from where the whole edge's line meets them. The bow allowed
    // is bounded (sagitta at most kMaxSagitta of the length, at least 8 px): a wider curve is not a
    // sheet's edge. How far an edge may bend to be a flat sheet's is edgeBend's to judge.
    const auto local = [&](const geo::Point &p) {
        const geo::Point d = p - s.from;
        return std::pair{d.dot(tangent), d.dot(outward)};
    };
    std::vector<double> ts(pts.size()), us(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        std::tie(ts[i], us[i]) = local(pts[i]);
    const double half = 0.5 * length;
    const double maxCurvature = std::max(8.0, kMaxSagitta * length) / (half * half); // |c| for that sagitta
    std::vector<int> bestInliers;
    for (const double band : {s.inlierPx, 2.0 * s.inlierPx}) {
        std::mt19937 rng(12345u);
        std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
        for (int iter = 0; iter < 300; ++iter) {
            const std::size_t a = pick(rng), b = pick(rng), c = pick(rng);
            const double ta = ts[a], tb = ts[b], tc = ts[c];
            if (std::abs(ta - tb) < 0.2 * length || std::abs(tb - tc) < 0.2 * length ||
                std::abs(ta - tc) < 0.2 * length)
                continue;
            // Newton's divided differences through the three points.
            const double ab = (us[b] - us[a]) / (tb - ta), bc = (us[c] - us[b]) / (tc - tb);
            const double curvature = (bc - ab) / (tc - ta);
            if (std::abs(curvature) > maxCurvature)
                continue;
            std::vector<int> in;
            for (std::size_t i = 0; i < pts.size(); ++i) {
                const double q = us[a] + ab * (ts[i] - ta) + curvature * (ts[i] - ta) * (ts[i] - tb);
                if (std::abs(us[i] - q) < band)
                    in.push_back(static_cast<int>(i));
            }
            if (in.size() > bestInliers.size())
                bestInliers = std::move(in);
        }
        if (bestInliers.size() >= 0.4 * samples)
            break;
    }
    if (bestInliers.size() < 12 || bestInliers.size() < 0.4 * samples)
        return failed();

    // Least squares of the quadratic on the inliers, then trimming at 3 sigma (at least 0.3 px) of its
    // residuals until stable; the line is the total least squares line through the points kept.
    std::vector<int> use = bestInliers;
    for (int round = 0; round < 4; ++round) {
        Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
        Eigen::Vector3d atb = Eigen::Vector3d::Zero();
        for (int i : use) {
            const double t = ts[i] / half - 1.0; // scaled to [-1, 1] for conditioning
            const Eigen::Vector3d row(1.0, t, t * t);
            ata += row * row.transpose();
            atb += row * us[i];
        }
        const Eigen::Vector3d q = ata.ldlt().solve(atb);
        const auto residual = [&](std::size_t i) {
            const double t = ts[i] / half - 1.0;
            return us[i] - (q[0] + q[1] * t + q[2] * t * t);
        };
        double ss = 0;
        for (int i : use)
            ss += residual(static_cast<std::size_t>(i)) * residual(static_cast<std::size_t>(i));
        const double sigma = std::sqrt(ss / std::max<std::size_t>(1, use.size() - 3));
        const double cut = std::max(3 * sigma, 0.3);
        std::vector<int> next;
        for (std::size_t i = 0; i < pts.size(); ++i)
            if (std::abs(residual(i)) < cut)
                next.push_back(static_cast<int>(i));
        if (next.size() < 12)
            return failed();
        const bool same = next == use;
        use = std::move(next);
        if (same)
            break;
    }
    const LineFit fit = tls(pts, use);
    EdgeLine line;
    line.point = fit.centroid;
    line.direction = fit.direction.dot(tangent) < 0 ? geo::Point(-fit.direction) : fit.direction;
    line.outward = geo::Point(line.direction.y(), -line.direction.x());
    if (line.outward.dot(outward) < 0)
        line.outward = -line.outward;
    double ss = 0, tt = 0;
    std::vector<double> used;
    for (int i : use) {
        const geo::Point d = pts[i] - fit.centroid;
        ss += std::pow(d.dot(line.outward), 2);
        tt += std::pow(d.dot(line.direction), 2);
        used.push_back(strength[i]);
    }
    line.count = static_cast<int>(use.size());
    line.sampled = samples;
    line.rms = std::sqrt(ss / line.count);
    // Neighbouring edge points are not independent when the residuals follow the table's texture or
    // the paper's waviness: the variances grow by (1 + rho) / (1 - rho) for a lag-one correlation rho
    // of the residuals in order along the edge (the AR(1) variance inflation; points come in order).
    double lag = 0;
    for (std::size_t k = 0; k + 1 < use.size(); ++k)
        lag += (pts[use[k]] - fit.centroid).dot(line.outward) * (pts[use[k + 1]] - fit.centroid).dot(line.outward);
    const double rho = ss > 0 ? std::clamp(lag / ss, 0.0, 0.95) : 0.0;
    const double var = ss / std::max(1, line.count - 2) * (1 + rho) / (1 - rho);
    line.offsetVariance = var / line.count;
    line.angleVariance = tt > 0 ? var / tt : 1.0;
    std::nth_element(used.begin(), used.begin() + used.size() / 2, used.end());
    line.contrast = used[used.size() / 2];
    return line;
}

} // namespace kontur::vision
