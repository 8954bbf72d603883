// The outline tracer: sub-pixel edge points of each segmented piece, corners from the edge's turning,
// straight runs as lines and the rest by the stroke fit, joined into one closed composite curve in mm.
// Over 600 lines because the corner finding, the corners' placement between straight and curved sides
// and the second look beyond a line along the edge all work on one loop of edge points and its spans;
// the image side (segmentation, edge search) is edges.cpp, the shape fixes outlineshape.cpp.
#include "vision/outline.h"

#include "geometry/strokefit.h"
#include "vision/dents.h"
#include "vision/edgefit.h"
#include "vision/edges.h"
#include "vision/loop.h"
#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::vision {

using geo::Point;

namespace {

using detail::Loop;

double turnAngle(const Loop &loop, std::size_t i, double window)
{
    const Point a = loop.point(i) - loop.at(loop.arc(i) - window), b = loop.at(loop.arc(i) + window) - loop.point(i);
    const double na = a.norm(), nb = b.norm();
    return na > 0.0 && nb > 0.0 ? std::acos(std::clamp(a.dot(b) / (na * nb), -1.0, 1.0)) : 0.0;
}

// A corner as a span of the loop, in arc length (from <= to; both may lie past total: the loop wraps):
// where the edge keeps turning about one sharp turn. A blurred tip, a pencil line crossing the edge
// near the corner or the edge lost under a marking there make the span longer; the sides are fitted
// only outside it.
struct CornerSpan
{
    double from = 0.0, to = 0.0;
    std::size_t peak = 0; // where it turns most
};

// The corners: each stretch where the loop turns by more than half the threshold (measured over
// window[i] on either side of point i) and somewhere by more than the threshold, stretches less
// than `minGap` apart joined into one. In order of arc length from a quiet point of the loop.
std::vector<CornerSpan> loopCorners(const Loop &loop, const std::vector<double> &window, double thresholdRad,
                                    double minGap)
{
    const std::size_t n = loop.size();
    std::vector<double> angle(n);
    for (std::size_t i = 0; i < n; ++i)
        angle[i] = turnAngle(loop, i, window[i]);
    const double low = 0.5 * thresholdRad;
    const auto quiet = std::find_if(angle.begin(), angle.end(), [&](double a) { return a <= low; });
    if (quiet == angle.end())
        return {};
    const auto start = static_cast<std::size_t>(quiet - angle.begin());
    // Arc length from before the quiet point, increasing over one lap.
    const auto along = [&](std::size_t i) { return loop.arc(i) + (i <= start ? loop.total() : 0.0); };
    std::vector<CornerSpan> spans;
    std::optional<CornerSpan> open;
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (start + k) % n;
        if (angle[i] > low) {
            if (!open)
                open = CornerSpan{along(i), along(i), i};
            open->to = along(i);
            if (angle[i] > angle[open->peak])
                open->peak = i;
        } else if (open) {
            if (angle[open->peak] > thresholdRad) {
                if (!spans.empty() && open->from - spans.back().to < minGap) {
                    spans.back().to = open->to;
                    if (angle[open->peak] > angle[spans.back().peak])
                        spans.back().peak = open->peak;
                } else {
                    spans.push_back(*open);
                }
            }
            open.reset();
        }
    }
    // The last span may join the first across the quiet point.
    if (spans.size() > 1 && spans.front().from + loop.total() - spans.back().to < minGap) {
        spans.front().from = spans.back().from - loop.total();
        if (angle[spans.back().peak] > angle[spans.front().peak])
            spans.front().peak = spans.back().peak;
        spans.pop_back();
    }
    return spans;
}

// The line through at least three points (fitLineTls): a point on it and its unit direction.
std::optional<std::pair<Point, Point>> fitLine(const std::vector<Point> &pts)
{
    if (pts.size() < 3)
        return std::nullopt;
    return fitLineTls(pts);
}

using Line = std::pair<Point, Point>; // a point on it and its unit direction

// The distance from a point to a line.
double distanceTo(const Point &q, const Line &line)
{
    const Point r = q - line.first;
    return std::abs(line.second.x() * r.y() - line.second.y() * r.x());
}

// The largest distance from the points to a line.
double deviation(const std::vector<Point> &pts, const Line &line)
{
    double dev = 0.0;
    for (const Point &q : pts)
        dev = std::max(dev, distanceTo(q, line));
    return dev;
}

// The run's points without those that lie off the edge (the edge lost under a pencil line crossing
// it, the table's grain against a weak edge): each point's distance from the line fitted to the
// points within `reach` of it along the run; farther than three robust deviations of those distances
// (and than `floor`) is off. The run's ends stay. Also that robust deviation (1.4826 × the median
// distance: σ for a normal scatter).
struct CleanRun
{
    std::vector<Point> points;
    double deviation = 0.0;
};
CleanRun withoutOutliers(const std::vector<Point> &run, double reach, double floor)
{
    const std::size_t n = run.size();
    if (n < 8)
        return {run, 0.0};
    std::vector<double> s(n, 0.0), off(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
        s[i] = s[i - 1] + (run[i] - run[i - 1]).norm();
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 0; i < n; ++i) {
        while (s[i] - s[lo] > reach)
            ++lo;
        while (hi + 1 < n && s[hi + 1] - s[i] <= reach)
            ++hi;
        const std::vector<Point> near(run.begin() + static_cast<std::ptrdiff_t>(lo),
                                      run.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
        if (const auto line = fitLine(near))
            off[i] = distanceTo(run[i], *line);
    }
    std::vector<double> sorted = off;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2), sorted.end());
    const double deviation = 1.4826 * sorted[n / 2];
    const double limit = std::max(floor, 3.0 * deviation);
    std::vector<Point> kept;
    kept.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (i == 0 || i + 1 == n || off[i] <= limit)
            kept.push_back(run[i]);
    return {std::move(kept), deviation};
}

// The line of a straight side: a line through the run's points that all but 2 % of them (the edge
// disturbed near a corner, a mark touching it) lie within the tolerance of, and none farther than
// twice it, refitted to the points within the tolerance. Nothing when the run is no line.
std::optional<Line> straightSide(const std::vector<Point> &run, double tolerance)
{
    auto line = fitLine(run);
    for (int round = 0; line && round < 2; ++round) {
        std::vector<Point> near;
        near.reserve(run.size());
        for (const Point &q : run)
            if (distanceTo(q, *line) <= tolerance)
                near.push_back(q);
        if (near.size() < 3 || double(near.size()) < 0.98 * double(run.size()))
            return std::nullopt;
        line = fitLine(near);
    }
    if (!line || deviation(run, *line) > 2.0 * tolerance)
        return std::nullopt;
    return line;
}

// The tangent line at arc length `at` of the loop, extrapolated from the points between `from` and
// `to` (a side of a corner, outside the corner's blur) by a quadratic in arc length: a curved side
// bends towards its corner, which a chord would miss.
// The quadratic c0 + c1·u + c2·u² in arc length u from `at`, fitted by least squares to the loop's
// points between `from` and `to`; nothing with fewer than six points.
using Quadratic = std::array<Point, 3>;
std::optional<Quadratic> endQuadratic(const Loop &loop, double from, double to, double at)
{
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
    int count = 0;
    for (int lap = 0; lap < 3; ++lap)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const double si = loop.arc(i) + (lap - 1) * loop.total();
            if (si < from || si > to)
                continue;
            const double u = si - at;
            const Eigen::Vector3d b(1.0, u, u * u);
            normal += b * b.transpose();
            rhs += b * loop.point(i).transpose();
            ++count;
        }
    if (count < 6)
        return std::nullopt;
    const Eigen::Matrix<double, 3, 2> coef = normal.ldlt().solve(rhs);
    const Quadratic q{Point(coef.row(0).transpose()), Point(coef.row(1).transpose()), Point(coef.row(2).transpose())};
    if (!q[0].allFinite() || !q[1].allFinite() || !q[2].allFinite() || !(q[1].norm() > 0.0))
        return std::nullopt;
    return q;
}

std::optional<Line> endTangent(const Loop &loop, double from, double to, double at)
{
    const auto q = endQuadratic(loop, from, to, at);
    if (!q)
        return std::nullopt;
    return Line{(*q)[0], (*q)[1].normalized()};
}

// Where a straight side's line crosses a curved side's quadratic (endQuadratic), at the crossing
// nearest the quadratic's u = 0; nothing when they do not cross or cross farther than `within` from
// `here`. Unlike the tangent's meeting point, this does not move along the line by the curve's bend
// between the corner and where its fitted stretch begins.
std::optional<Point> crossing(const Line &line, const Quadratic &q, const Point &here, double within)
{
    const Point n(-line.second.y(), line.second.x());
    const double a = n.dot(q[2]), b = n.dot(q[1]), c = n.dot(q[0] - line.first);
    std::vector<double> roots;
    if (std::abs(a) < 1e-12 * std::max(1.0, std::abs(b))) {
        if (b != 0.0)
            roots.push_back(-c / b);
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc >= 0.0) {
            const double r = std::sqrt(disc);
            roots.push_back((-b + r) / (2 * a));
            roots.push_back((-b - r) / (2 * a));
        }
    }
    std::optional<Point> best;
    double bestU = INFINITY;
    for (const double u : roots)
        if (std::isfinite(u) && std::abs(u) < bestU) {
            const Point x = q[0] + u * q[1] + u * u * q[2];
            if ((x - here).norm() <= within)
                best = x, bestU = std::abs(u);
        }
    return best;
}

// Where the edges on either side of a corner meet, or nothing when they are nearly parallel or meet
// implausibly far from the contour's own corner.
std::optional<Point> meet(const std::optional<Line> &before, const std::optional<Line> &after, const Point &here,
                          double within)
{
    if (!before || !after)
        return std::nullopt;
    const Point d1 = before->second, d2 = after->second, r = after->first - before->first;
    const double cross = d1.x() * d2.y() - d1.y() * d2.x();
    if (std::abs(cross) < 0.2)
        return std::nullopt;
    const double t = (r.x() * d2.y() - r.y() * d2.x()) / cross;
    const Point x = before->first + t * d1;
    return (x - here).norm() <= within ? std::optional<Point>(x) : std::nullopt;
}

void appendFit(Outline &out, const std::vector<Point> &ctrl, std::vector<bool> corners)
{
    if (out.control.empty())
        out.control.push_back(ctrl.front());
    out.control.insert(out.control.end(), ctrl.begin() + 1, ctrl.end());
    corners.erase(corners.begin());
    out.corner.insert(out.corner.end(), corners.begin(), corners.end());
}

// The closed outline through a piece's edge points (px, in order along its edge): corners, straight
// sides as lines, the rest by the stroke fit, in the mapping's units.
geo::Result<Outline> fitEdgePoints(const std::vector<Point> &px, const PixelMapping &mapping,
                                   const OutlineOptions &options)
{
    const double mmpp = mapping.mmPerPixel();
    if (px.size() < 16)
        return geo::Error{geo::ErrorCode::TooFewPoints, "too few edge points along the piece"};
    std::vector<Point> points;
    points.reserve(px.size());
    double area = 0.0;
    for (const auto &q : px)
        points.push_back(mapping.toMm(q));
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++)
        area += points[j].x() * points[i].y() - points[i].x() * points[j].y();
    if (area < 0.0)
        std::reverse(points.begin(), points.end());
    const Loop loop(std::move(points));

    // The corner test looks past the edge's blur and scatter along the edge: 6 pixels of the photo
    // the image was warped from (of the image itself when that is not known), and at least 0.6 mm.
    const double mm = options.millimetre;
    std::vector<double> window(loop.size());
    double widest = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        double pixel = options.sourcePixel ? options.sourcePixel(loop.point(i)) : mmpp;
        if (!(pixel > mmpp) || !std::isfinite(pixel))
            pixel = mmpp;
        window[i] = std::max(6.0 * pixel, 0.6 * mm);
        widest = std::max(widest, window[i]);
    }
    const double threshold = options.cornerAngle * std::numbers::pi / 180.0;
    std::vector<CornerSpan> spans = loopCorners(loop, window, threshold, std::max(2.0 * widest, 3.0 * mm));

    // A turn is a corner when the sides on either side of it, fitted by lines outside its span, meet
    // at more than the threshold: a wobble of the edge points on a straight side (the table's grain
    // against the paper, a smudge) is not.
    const auto direction = [&](double from, double to) -> std::optional<Point> {
        const std::vector<Point> pts = loop.between(from, to);
        const auto line = fitLine(pts);
        if (!line)
            return std::nullopt;
        return line->second.dot(pts.back() - pts.front()) >= 0.0 ? line->second : Point(-line->second);
    };
    std::erase_if(spans, [&](const CornerSpan &c) {
        const double side = std::max(3.0 * mm, 4.0 * window[c.peak]);
        const auto before = direction(c.from - side, c.from), after = direction(c.to, c.to + side);
        return before && after && std::acos(std::clamp(before->dot(*after), -1.0, 1.0)) < threshold;
    });

    geo::StrokeFitOptions fitOptions;
    fitOptions.tolerance = options.tolerance;
    fitOptions.cornerAngle = 180.0; // the runs between corners are smooth
    // Edge points of a strongly bent side (an armhole) lie far from their chord-length parameters;
    // Newton rounds converge there, slowly. A hand stroke's default is 12.
    fitOptions.reparameterizeIterations = 100;
    Outline out;
    if (spans.empty()) {
        // A smooth piece: start where it turns most; the join is made smooth afterwards.
        std::size_t start = 0;
        double best = -1.0;
        for (std::size_t i = 0; i < loop.size(); ++i)
            if (const double a = turnAngle(loop, i, window[i]); a > best)
                best = a, start = i;
        std::vector<Point> run = loop.between(loop.arc(start), loop.arc(start) + loop.total());
        run.push_back(run.front());
        auto fit = geo::fitStroke(run, fitOptions);
        if (!fit)
            return fit.error();
        out.control = fit->control;
        out.corner.assign(static_cast<std::size_t>(fit->segmentCount() + 1), false);
        out.maxError = fit->maxError;
        auto &c = out.control;
        const std::size_t last = c.size() - 1;
        const Point dir = ((c[1] - c[0]).normalized() + (c[last] - c[last - 1]).normalized()).normalized();
        if (dir.allFinite()) {
            c[1] = c[0] + dir * (c[1] - c[0]).norm();
            c[last - 1] = c[0] - dir * (c[last] - c[last - 1]).norm();
        }
    } else {
        // The runs between corners, without the blurred ends near the corners; a run is straight when
        // a line fits all its edge points within the tolerance.
        const std::size_t n = spans.size();
        std::vector<std::vector<Point>> runs(n);
        std::vector<std::optional<Line>> straight(n);
        std::vector<double> runFrom(n), runTo(n), runTolerance(n);
        for (std::size_t k = 0; k < n; ++k) {
            const double from = spans[k].to;
            double to = spans[(k + 1) % n].from;
            while (to <= from)
                to += loop.total();
            // Past the span, a quarter window more: the last of the blur.
            const double w = window[spans[k].peak];
            const double trim = std::min(0.25 * w, 0.25 * (to - from));
            runFrom[k] = from + trim, runTo[k] = to - trim;
            CleanRun clean =
                withoutOutliers(loop.between(runFrom[k], runTo[k]), std::max(1.0 * mm, w), 0.5 * options.tolerance);
            runs[k] = std::move(clean.points);
            runTolerance[k] = std::max(options.tolerance, 6.0 * clean.deviation);
            straight[k] = straightSide(runs[k], runTolerance[k]);
        }
        // Each corner where the edges on its two sides meet: a straight side's own line, or a line
        // tangent at the corner extrapolated from the first (last) 10 mm of a curved side by a
        // quadratic (garment curves bend little over 10 mm; over fewer, the edge disturbed near a
        // corner, by a seam line crossing it, say, tilts the tangent). Where a straight side meets a
        // curved one, the curved side's quadratic is fitted over its first 4 mm only: its position
        // near the corner matters there, not its tangent, and an armhole's end bends too much within
        // 10 mm for one quadratic (docs/vision.md, "A line along the edge": the corner's error with a
        // line along the edge, 0.23–0.83 mm with 10 mm, 0.16–0.43 mm with 4 mm).
        std::vector<Point> at(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t prev = (k + n - 1) % n;
            const double s = 0.5 * (spans[k].from + spans[k].to);
            const double w = window[spans[k].peak];
            double end = runTo[prev];
            while (end > s)
                end -= loop.total();
            const Point here = loop.point(spans[k].peak);
            const double within = 3.0 * w + 0.5 * (spans[k].to - spans[k].from);
            // A straight side meets a curved one where its line crosses the curved side's quadratic.
            // Otherwise the tangents' meeting point, from three stretches of a curved side (0.75, 1 and
            // 1.25 × the reach), the median of the three: one stretch's end falling a point earlier or
            // later (a hair's change in the photo) must not move the corner by the curve's bend there.
            std::vector<Point> meets;
            if (straight[prev] != straight[k]) {
                const double reach = std::max(4.0 * mm, 6.0 * w);
                const auto curve =
                    straight[prev]
                        ? endQuadratic(loop, runFrom[k], std::min(runFrom[k] + reach, runTo[k]), s)
                        : endQuadratic(loop, std::max(end - reach, end - (runTo[prev] - runFrom[prev])), end, s);
                if (curve)
                    if (const auto x = crossing(straight[prev] ? *straight[prev] : *straight[k], *curve, here, within))
                        meets.push_back(*x);
            }
            for (const double f : {0.75, 1.0, 1.25}) {
                if (!meets.empty() && straight[prev] != straight[k])
                    break;
                const double reach = f * std::max(10.0 * mm, 6.0 * w);
                const double endFrom = std::max(end - reach, end - (runTo[prev] - runFrom[prev]));
                const auto before = straight[prev] ? straight[prev] : endTangent(loop, endFrom, end, s);
                const auto after =
                    straight[k] ? straight[k] : endTangent(loop, runFrom[k], std::min(runFrom[k] + reach, runTo[k]), s);
                if (const auto m = meet(before, after, here, within))
                    meets.push_back(*m);
                if (straight[prev] && straight[k])
                    break; // two lines: one meeting point
            }
            if (meets.empty()) {
                at[k] = here;
            } else {
                std::vector<double> xs, ys;
                for (const Point &m : meets)
                    xs.push_back(m.x()), ys.push_back(m.y());
                std::sort(xs.begin(), xs.end());
                std::sort(ys.begin(), ys.end());
                at[k] = Point(xs[xs.size() / 2], ys[ys.size() / 2]);
            }
        }
        out.corner.push_back(true);
        for (std::size_t k = 0; k < n; ++k) {
            const Point a = at[k], b = at[(k + 1) % n];
            if (straight[k] || runs[k].size() < 4) {
                appendFit(out, geo::straightCubic(a, b).controlPoints(), {true, true});
                if (straight[k])
                    out.maxError = std::max(out.maxError, deviation(runs[k], *straight[k]));
                continue;
            }
            std::vector<Point> run{a};
            run.insert(run.end(), runs[k].begin(), runs[k].end());
            run.push_back(b);
            geo::StrokeFitOptions runOptions = fitOptions;
            runOptions.tolerance = runTolerance[k];
            auto fit = geo::fitStroke(run, runOptions);
            if (!fit)
                return fit.error();
            fit->control.front() = a;
            fit->control.back() = b;
            std::vector<bool> flags(static_cast<std::size_t>(fit->segmentCount() + 1), false);
            flags.front() = flags.back() = true;
            appendFit(out, fit->control, flags);
            out.maxError = std::max(out.maxError, fit->maxError);
        }
    }
    detail::markStraightSegments(out, 0.5 * options.tolerance);
    out.closed = true;
    out.edgePoints = static_cast<int>(loop.size());
    if (out.segmentCount() < 1)
        return geo::Error{geo::ErrorCode::InvalidArgument, "the outline has no segment"};
    detail::atLeastThreeSegments(out);
    return out;
}

// The points of an outline's polygon (sampleOutline: px, about a pixel apart) with their outward
// normals (px, unit); none at a corner knot, where the normal is not defined.
void alongOutline(const Outline &outline, const PixelMapping &mapping, std::vector<Point> &p, std::vector<Point> &out)
{
    const Eigen::Matrix2d toPx = mapping.linear.inverse();
    const OutlineSamples samples = sampleOutline(outline, mapping);
    int current = -1;
    geo::Bezier seg;
    for (std::size_t k = 0; k < samples.px.size(); ++k) {
        const int i = samples.segment[k];
        const double t = samples.t[k];
        if (t == 0.0 && outline.corner[static_cast<std::size_t>(i)])
            continue;
        if (i != current)
            seg = outline.segment(i), current = i;
        const Point d = seg.derivative(t);
        if (!(d.norm() > 0.0))
            continue;
        // Counter-clockwise in the output frame: the table lies to the right.
        const Point normalMm(d.y(), -d.x());
        const Point tangentPx = toPx * d;
        Point normalPx = Point(tangentPx.y(), -tangentPx.x()).normalized();
        if ((mapping.linear * normalPx).dot(normalMm) < 0.0)
            normalPx = -normalPx;
        p.push_back(samples.px[k]);
        out.push_back(normalPx);
    }
}

geo::Result<Outline> traceRegion(const detail::EdgeField &field, const detail::Region &region,
                                 const PixelMapping &mapping, const OutlineOptions &options)
{
    const double mmpp = mapping.mmPerPixel();
    const double radius = 4.0; // px: the segmentation's smoothing leaves the edge within a few pixels
    // A line printed or drawn along the paper's edge: up to 1.5 mm wide and 1.5 mm inside it.
    const double lineReach = 3.0 * options.millimetre / mmpp;
    const detail::ContourEdge edge = detail::subpixelContour(field, region, radius, lineReach);
    // Notches cut into the edge are bridged, as the seam line runs across them.
    const double pxPerMm = options.millimetre / mmpp;
    std::vector<Point> points = edge.points;
    const std::vector<detail::Dent> dents = detail::takeOutDents(
        points, {.minDepth = 1.5 * pxPerMm, .maxDepth = 12.0 * pxPerMm, .maxWidth = 10.0 * pxPerMm});
    const auto withNotches = [&](geo::Result<Outline> fitted) {
        if (fitted)
            for (const detail::Dent &d : dents)
                fitted->notches.push_back({.at = mapping.toMm(d.foot),
                                           .tip = mapping.toMm(d.tip),
                                           .width = d.width * mmpp,
                                           .depth = d.depth * mmpp,
                                           .castle = d.square});
        return fitted;
    };
    auto first = fitEdgePoints(points, mapping, options);
    if (!first || !edge.beyondLine)
        return withNotches(std::move(first));
    // The paper's edge beyond a line, a second time along the first outline's own normals. The first
    // look went along the normals of the line's inner side, which never reach the paper's edge within
    // (inset + width) / tan(angle / 2) of a tip (2 mm for a 1.3 mm line at 60°); the outline's do.
    // (Done for every piece, this second look made plain pieces' outlines 0.01–0.04 mm worse.)
    // docs/vision.md, "A line along the edge".
    std::vector<Point> p, out;
    alongOutline(*first, mapping, p, out);
    std::vector<Point> again = detail::paperEdgeAlong(field, p, out, edge, lineReach);
    detail::dropInDents(again, dents); // not into the notches found the first time
    if (2 * again.size() < p.size())
        return withNotches(std::move(first));
    if (auto second = fitEdgePoints(again, mapping, options))
        return withNotches(std::move(second));
    return withNotches(std::move(first));
}

struct Prepared
{
    detail::EdgeField field;
    std::vector<detail::Region> regions;
};

geo::Result<Prepared> prepare(const cv::Mat &image, const PixelMapping &mapping, const OutlineOptions &options)
{
    if (image.empty() || image.rows < 8 || image.cols < 8)
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is empty"};
    if (!mapping.valid())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the pixel-to-mm map is not invertible"};
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
        return geo::Error{geo::ErrorCode::InvalidArgument, "the tolerance must be positive and finite"};
    const cv::Mat gray = toGray(image);
    if (gray.empty())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is not 8-bit gray, BGR or BGRA"};
    std::optional<std::vector<Point>> ignore;
    if (options.ignoreRect)
        ignore = std::vector<Point>{mapping.toPixel(options.ignoreRect->corner(geo::Box::BottomLeft)),
                                    mapping.toPixel(options.ignoreRect->corner(geo::Box::BottomRight)),
                                    mapping.toPixel(options.ignoreRect->corner(geo::Box::TopRight)),
                                    mapping.toPixel(options.ignoreRect->corner(geo::Box::TopLeft))};
    const double mmpp = mapping.mmPerPixel();
    Prepared prep;
    // Pencil and marker lines along an edge, and where two of them meet, are up to about 3 mm wide after
    // the segmentation's blur; concave corners that this fills are found again from the edge points.
    prep.regions =
        detail::segmentPieces(gray, options.minArea / (mmpp * mmpp), 1.5 * options.millimetre / mmpp, ignore);
    // A little smoothing against noise, well below the edge's own blur in a photo (Canny 1986).
    prep.field = detail::edgeField(gray, 1.0);
    return prep;
}

} // namespace

geo::Result<std::vector<Outline>> traceOutlines(const cv::Mat &image, const PixelMapping &mapping,
                                                const OutlineOptions &options)
{
    auto prep = prepare(image, mapping, options);
    if (!prep)
        return prep.error();
    std::vector<Outline> out;
    for (const auto &region : prep->regions)
        if (auto o = traceRegion(prep->field, region, mapping, options))
            out.push_back(std::move(o.value()));
    return out;
}

geo::Result<Outline> traceOutlineAt(const cv::Mat &image, const PixelMapping &mapping, const Point &seedMm,
                                    const OutlineOptions &options)
{
    auto prep = prepare(image, mapping, options);
    if (!prep)
        return prep.error();
    if (prep->regions.empty())
        return geo::Error{geo::ErrorCode::InvalidArgument, "no piece found in the image"};
    const Point seed = mapping.toPixel(seedMm);
    // The regions do not nest (outer contours only): the one with the largest signed distance
    // (positive inside) contains the seed, or else its outline is the nearest.
    const detail::Region *best = nullptr;
    double bestDistance = 0.0;
    for (const auto &r : prep->regions) {
        const double d = cv::pointPolygonTest(r.contour, cv::Point2f(float(seed.x()), float(seed.y())), true);
        if (!best || d > bestDistance)
            best = &r, bestDistance = d;
    }
    return traceRegion(prep->field, *best, mapping, options);
}

} // namespace kontur::vision
