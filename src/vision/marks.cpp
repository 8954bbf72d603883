// Marks on a piece: see marks.h.
#include "vision/marks.h"

#include "geometry/polyline.h"
#include "vision/edgefit.h"
#include "vision/loop.h"
#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::vision {

using geo::Point;

namespace {

// One dark mark: its pixels (px, relative to the whole image) and their spread.
struct Blob
{
    std::vector<Point> px;
    Point mean = Point::Zero();
    Point major = Point(1, 0); // unit: the direction of greatest spread
    double lo = 0, hi = 0;     // extent along `major`, from `mean`
    double across = 0;         // extent square to it
    double nearEdge = 0;       // px: the least distance of its pixels from the outline
    double meanEdge = 0;       // px: their mean distance from the outline
    cv::Rect box;
};

Blob describe(std::vector<Point> px, const cv::Mat &edgeDistance, cv::Rect box)
{
    Blob b;
    b.px = std::move(px);
    b.box = box;
    for (const Point &p : b.px)
        b.mean += p;
    b.mean /= static_cast<double>(b.px.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Point &p : b.px)
        cov += (p - b.mean) * (p - b.mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    b.major = eig.eigenvectors().col(1);
    const Point minor(-b.major.y(), b.major.x());
    double alo = 1e300, ahi = -1e300;
    b.lo = 1e300, b.hi = -1e300, b.nearEdge = 1e300;
    for (const Point &p : b.px) {
        const double t = (p - b.mean).dot(b.major), s = (p - b.mean).dot(minor);
        b.lo = std::min(b.lo, t), b.hi = std::max(b.hi, t);
        alo = std::min(alo, s), ahi = std::max(ahi, s);
        const double d = edgeDistance.at<float>(static_cast<int>(p.y()), static_cast<int>(p.x()));
        b.nearEdge = std::min(b.nearEdge, d);
        b.meanEdge += d;
    }
    b.meanEdge /= static_cast<double>(b.px.size());
    b.across = ahi - alo + 1.0;
    return b;
}

// The straight line that most of a blob's pixels lie on: the densest band across the blob's major
// axis (a line's pixels pile up there; arrowheads, a bracket's legs and letters spread out), then the
// total least squares line (edgefit.h, fitLineTls) through the pixels within `maxCore` px of that band,
// and again through those within the line's own half-width: three times the median distance of the
// pixels used from it (twice the median is a band's half-width), at least `minCore`, at most `maxCore`.
// The pixels off the line weigh nothing in the fit.
struct CoreLine
{
    Point on = Point::Zero(), dir = Point(1, 0);
    double halfWidth = 0;  // px
    double lo = 0, hi = 0; // the core's extent along `dir`, from `on`
    std::size_t count = 0; // pixels within halfWidth of the line
};

std::optional<CoreLine> coreLineOf(const Blob &blob, double minCore, double maxCore)
{
    const Point minor(-blob.major.y(), blob.major.x());
    const double bin = std::max(0.5, minCore / 2.0);
    std::vector<int> histogram(static_cast<std::size_t>(blob.across / bin) + 3, 0);
    double smin = 1e300;
    for (const Point &p : blob.px)
        smin = std::min(smin, (p - blob.mean).dot(minor));
    for (const Point &p : blob.px)
        ++histogram[std::min(histogram.size() - 1,
                             static_cast<std::size_t>(((p - blob.mean).dot(minor) - smin) / bin))];
    const auto densest = std::max_element(histogram.begin(), histogram.end()) - histogram.begin();
    CoreLine line;
    line.on = blob.mean + (smin + (static_cast<double>(densest) + 0.5) * bin) * minor;
    line.dir = blob.major;
    double within = maxCore;
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<Point> used;
        std::vector<double> off;
        const Point normal(-line.dir.y(), line.dir.x());
        for (const Point &p : blob.px)
            if (const double d = std::abs((p - line.on).dot(normal)); d <= within)
                used.push_back(p), off.push_back(d);
        const auto fit = fitLineTls(used);
        if (!fit)
            return std::nullopt;
        line.on = fit->first, line.dir = fit->second;
        const Point n(-line.dir.y(), line.dir.x());
        for (std::size_t i = 0; i < used.size(); ++i)
            off[i] = std::abs((used[i] - line.on).dot(n));
        std::nth_element(off.begin(), off.begin() + static_cast<std::ptrdiff_t>(off.size() / 2), off.end());
        within = line.halfWidth = std::clamp(3.0 * off[off.size() / 2], minCore, maxCore);
    }
    const Point normal(-line.dir.y(), line.dir.x());
    line.lo = 1e300, line.hi = -1e300;
    for (const Point &p : blob.px)
        if (std::abs((p - line.on).dot(normal)) <= line.halfWidth) {
            const double t = (p - line.on).dot(line.dir);
            line.lo = std::min(line.lo, t), line.hi = std::max(line.hi, t);
            ++line.count;
        }
    if (line.count < 2)
        return std::nullopt;
    return line;
}

// A grainline in a blob, if it is one: a straight core (coreLineOf) of at least `minLength` px, its
// pixels two thirds of the blob's or more, inked along its whole length; its ends (px) and whether
// each has an arrowhead (pixels off the core within `headLength` of the end, on both sides of the line).
struct Grain
{
    Point a, b;
    bool headA = false, headB = false;
};

std::optional<Grain> grainIn(const Blob &blob, double minLength, double minCore, double maxCore, double headLength)
{
    if (blob.hi - blob.lo < minLength)
        return std::nullopt;
    const std::optional<CoreLine> line = coreLineOf(blob, minCore, maxCore);
    if (!line || line->count < 2 * blob.px.size() / 3 || line->hi - line->lo < minLength)
        return std::nullopt;
    const Point on = line->on, dir = line->dir, normal(-dir.y(), dir.x());
    const double lo = line->lo, hi = line->hi, coreWidth = line->halfWidth;
    // Every stretch of the core's length is inked: a curve bent back along a chord is no line.
    std::vector<bool> inked(static_cast<std::size_t>(hi - lo) + 1, false);
    for (const Point &p : blob.px)
        if (std::abs((p - on).dot(normal)) <= coreWidth)
            inked[static_cast<std::size_t>((p - on).dot(dir) - lo)] = true;
    if (std::count(inked.begin(), inked.end(), false) > static_cast<std::ptrdiff_t>(inked.size() / 20))
        return std::nullopt;
    Grain g;
    g.a = on + lo * dir;
    g.b = on + hi * dir;
    // An arrowhead: pixels off the core on both sides near the end.
    int offA[2] = {0, 0}, offB[2] = {0, 0};
    for (const Point &p : blob.px) {
        const double s = (p - on).dot(normal), t = (p - on).dot(dir);
        if (std::abs(s) <= 1.5 * coreWidth)
            continue;
        const int side = s > 0 ? 1 : 0;
        if (t - lo <= headLength)
            ++offA[side];
        else if (hi - t <= headLength)
            ++offB[side];
    }
    const int enough = static_cast<int>(std::ceil(headLength / 4.0));
    g.headA = offA[0] >= enough && offA[1] >= enough;
    g.headB = offB[0] >= enough && offB[1] >= enough;
    return g;
}

// A "place on fold" bracket in a blob, if it is one: a straight bar (coreLineOf) at least `minBar` px
// long with a leg at each end, both on the same side of it, reaching at least `minLeg` px from it
// (an arrowhead at a leg's end is part of the leg), and nothing else off the bar. The legs' far ends
// (px), where they point at the fold.
std::optional<std::array<Point, 2>> bracketIn(const Blob &blob, double minBar, double minLeg, double minCore,
                                              double maxCore)
{
    if (blob.hi - blob.lo < minBar)
        return std::nullopt;
    const std::optional<CoreLine> bar = coreLineOf(blob, minCore, maxCore);
    if (!bar || bar->hi - bar->lo < minBar)
        return std::nullopt;
    const Point normal(-bar->dir.y(), bar->dir.x());
    // The legs: the pixels off the bar within a leg's reach of either end (a quarter of the bar, and
    // at least minLeg for the arrowheads' width).
    const double endZone = std::max(minLeg, 0.25 * (bar->hi - bar->lo));
    // Which end's leg a pixel at `t` along the bar belongs to: 0, 1, or -1 for neither.
    const auto endAt = [&](double t) { return t - bar->lo <= endZone ? 0 : bar->hi - t <= endZone ? 1 : -1; };
    std::array<double, 2> reach{0.0, 0.0};
    std::array<std::size_t, 2> leg{0, 0};
    std::size_t middle = 0, plus = 0, minus = 0;
    for (const Point &p : blob.px) {
        const double s = (p - bar->on).dot(normal), t = (p - bar->on).dot(bar->dir);
        if (std::abs(s) <= 1.5 * bar->halfWidth)
            continue;
        ++(s > 0 ? plus : minus);
        const int end = endAt(t);
        if (end < 0) {
            ++middle;
            continue;
        }
        ++leg[static_cast<std::size_t>(end)];
        reach[static_cast<std::size_t>(end)] = std::max(reach[static_cast<std::size_t>(end)], std::abs(s));
    }
    const std::size_t off = plus + minus;
    if (leg[0] == 0 || leg[1] == 0 || reach[0] < minLeg || reach[1] < minLeg || middle > off / 20 ||
        std::min(plus, minus) > off / 20)
        return std::nullopt;
    // Each leg's far end: the middle of its pixels within a core's width of its farthest.
    const double side = plus > minus ? 1.0 : -1.0;
    std::array<Point, 2> tip{Point::Zero(), Point::Zero()};
    std::array<int, 2> n{0, 0};
    for (const Point &p : blob.px) {
        const double s = side * (p - bar->on).dot(normal), t = (p - bar->on).dot(bar->dir);
        const int end = endAt(t);
        if (end >= 0 && s >= reach[static_cast<std::size_t>(end)] - 2.0 * bar->halfWidth) {
            tip[static_cast<std::size_t>(end)] += p;
            ++n[static_cast<std::size_t>(end)];
        }
    }
    return std::array<Point, 2>{tip[0] / n[0], tip[1] / n[1]};
}

// The fold a bracket points at: the straight run of the outline `polygon` (px) that holds the points
// nearest to both legs' ends, as far as it stays within `tolerance` px of one line (total least
// squares through it); its ends are the outline's `corners` (px) where one lies within `snap` px.
// Nothing when a leg's end lies farther than `reach` px from the outline, or the outline between
// the legs is not straight.
std::optional<std::array<Point, 2>> foldAlong(const std::vector<Point> &polygon, const std::array<Point, 2> &tips,
                                              double tolerance, double reach, const std::vector<Point> &corners,
                                              double snap)
{
    const auto [foot1, at1] = geo::nearestOnPolyline(polygon, tips[0], true);
    const auto [foot2, at2] = geo::nearestOnPolyline(polygon, tips[1], true);
    if ((foot1 - tips[0]).norm() > reach || (foot2 - tips[1]).norm() > reach)
        return std::nullopt;
    // The shorter way round between the feet.
    const std::size_t n = polygon.size();
    std::size_t first = at1 + 1, count = (at2 + n - at1) % n;
    if (count > n / 2)
        first = at2 + 1, count = n - count;
    std::vector<Point> run{foot1, foot2};
    for (std::size_t k = 0; k < count; ++k)
        run.push_back(polygon[(first + k) % n]);
    auto line = fitLineTls(run);
    const auto off = [&](const Point &p) {
        return std::abs((p - line->first).dot(Point(-line->second.y(), line->second.x())));
    };
    if (!line || std::any_of(run.begin(), run.end(), [&](const Point &p) { return off(p) > tolerance; }))
        return std::nullopt;
    // On along the outline both ways while it stays on the line, then the line through all of it.
    std::size_t before = 0, after = 0;
    while (before + count < n && off(polygon[(first + n - 1 - before) % n]) <= tolerance)
        run.push_back(polygon[(first + n - 1 - before++) % n]);
    while (before + count + after < n && off(polygon[(first + count + after) % n]) <= tolerance)
        run.push_back(polygon[(first + count + after++) % n]);
    line = fitLineTls(run);
    double lo = 1e300, hi = -1e300;
    for (const Point &p : run) {
        const double t = (p - line->first).dot(line->second);
        lo = std::min(lo, t), hi = std::max(hi, t);
    }
    std::array<Point, 2> ends{line->first + lo * line->second, line->first + hi * line->second};
    for (Point &end : ends) {
        const auto nearest = std::min_element(corners.begin(), corners.end(), [&](const Point &a, const Point &b) {
            return (a - end).squaredNorm() < (b - end).squaredNorm();
        });
        if (nearest != corners.end() && (*nearest - end).norm() <= snap)
            end = *nearest;
    }
    return ends;
}

} // namespace

geo::Result<FoundMarks> findPieceMarks(const cv::Mat &image, const PixelMapping &mapping, const Outline &outline,
                                       const MarkOptions &options)
{
    if (image.empty())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is empty"};
    if (!mapping.valid())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the pixel-to-mm map is not invertible"};
    if (!outline.closed || outline.segmentCount() < 2)
        return geo::Error{geo::ErrorCode::InvalidArgument, "the outline is not closed"};
    const cv::Mat gray = toGray(image);
    if (gray.empty())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is not 8-bit gray, BGR or BGRA"};
    const double mm = options.millimetre / mapping.mmPerPixel(); // px per mm

    FoundMarks found;
    for (const CutNotch &cut : outline.notches) {
        const Point into = cut.tip - cut.at;
        if (into.norm() > 0.0)
            found.notches.push_back(
                {cut.at, into.normalized(), cut.castle ? FoundNotch::Kind::Castle : FoundNotch::Kind::V});
    }

    // The piece's inside, as far as each pixel lies from the outline; the edge's blur (about half a
    // millimetre) is left out.
    const std::vector<Point> polygon = outlinePolygon(outline, mapping);
    std::vector<cv::Point> fill;
    constexpr int shift = 4;
    for (const Point &p : polygon)
        fill.emplace_back(static_cast<int>(std::lround(p.x() * (1 << shift))),
                          static_cast<int>(std::lround(p.y() * (1 << shift))));
    cv::Mat inside(gray.size(), CV_8U, cv::Scalar(0));
    cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{fill}, cv::Scalar(255), cv::LINE_8, shift);
    const cv::Rect roi = cv::boundingRect(inside) & cv::Rect(0, 0, gray.cols, gray.rows);
    if (roi.area() == 0)
        return found;
    cv::Mat edgeDistance(gray.size(), CV_32F, cv::Scalar(0));
    cv::distanceTransform(inside(roi), edgeDistance(roi), cv::DIST_L2, cv::DIST_MASK_PRECISE);
    const double blurBand = 0.6 * mm;

    // Dark, thin marks: the black-hat lifts what is narrower than the closing's square.
    const int k = 2 * static_cast<int>(std::ceil(kMaxMarkWidthMm * mm / 2)) + 1;
    cv::Mat closed, hat;
    cv::morphologyEx(gray(roi), closed, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {k, k}));
    cv::subtract(closed, gray(roi), hat);
    // The threshold: well above the paper's own texture (five robust deviations of the black-hat on
    // the paper) and an eighth of the paper's level (a faint pencil line on white paper is darker).
    std::vector<uchar> hatOnPaper, paperLevels;
    for (int y = 0; y < roi.height; ++y)
        for (int x = 0; x < roi.width; ++x)
            if (edgeDistance.at<float>(y + roi.y, x + roi.x) > 3.0 * mm) {
                hatOnPaper.push_back(hat.at<uchar>(y, x));
                paperLevels.push_back(closed.at<uchar>(y, x));
            }
    if (hatOnPaper.size() < 100)
        return found;
    const auto median = [](std::vector<uchar> v) {
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return static_cast<double>(v[v.size() / 2]);
    };
    const double hatMedian = median(hatOnPaper);
    std::vector<uchar> deviation(hatOnPaper.size());
    std::transform(hatOnPaper.begin(), hatOnPaper.end(), deviation.begin(),
                   [&](uchar v) { return static_cast<uchar>(std::min(255.0, std::abs(v - hatMedian))); });
    const double threshold =
        std::max(hatMedian + 5.0 * 1.4826 * std::max(1.0, median(deviation)), median(paperLevels) / 8.0);
    cv::Mat ink;
    cv::threshold(hat, ink, threshold, 255, cv::THRESH_BINARY);
    for (int y = 0; y < roi.height; ++y)
        for (int x = 0; x < roi.width; ++x)
            if (edgeDistance.at<float>(y + roi.y, x + roi.x) <= blurBand)
                ink.at<uchar>(y, x) = 0;
    // The table seen through a cut notch, which the outline bridges, is no mark.
    for (const CutNotch &cut : outline.notches) {
        const Point a = mapping.toPixel(cut.at),
                    b = mapping.toPixel(cut.tip) + mm * (mapping.toPixel(cut.tip) - a).normalized();
        cv::line(ink,
                 cv::Point(static_cast<int>(std::lround(a.x())) - roi.x, static_cast<int>(std::lround(a.y())) - roi.y),
                 cv::Point(static_cast<int>(std::lround(b.x())) - roi.x, static_cast<int>(std::lround(b.y())) - roi.y),
                 cv::Scalar(0), static_cast<int>(std::ceil(cut.width / mapping.mmPerPixel() + 2.0 * mm)));
    }

    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(ink, labels, stats, centroids, 8, CV_32S);
    std::vector<std::vector<Point>> pixels(static_cast<std::size_t>(n));
    for (int y = 0; y < roi.height; ++y)
        for (int x = 0; x < roi.width; ++x)
            if (const int l = labels.at<int>(y, x); l > 0)
                pixels[static_cast<std::size_t>(l)].emplace_back(x + roi.x, y + roi.y);
    std::vector<Blob> blobs;
    for (int l = 1; l < n; ++l)
        if (stats.at<int>(l, cv::CC_STAT_AREA) >= std::max(4.0, 0.25 * mm * mm))
            blobs.push_back(
                describe(std::move(pixels[static_cast<std::size_t>(l)]), edgeDistance,
                         cv::Rect(stats.at<int>(l, cv::CC_STAT_LEFT) + roi.x, stats.at<int>(l, cv::CC_STAT_TOP) + roi.y,
                                  stats.at<int>(l, cv::CC_STAT_WIDTH), stats.at<int>(l, cv::CC_STAT_HEIGHT))));

    // The fold: a bracket whose legs point at a straight stretch of the outline; the longest such fold.
    std::vector<Point> corners;
    for (int k = 0; k < outline.knotCount(); ++k)
        if (outline.corner.at(static_cast<std::size_t>(k)))
            corners.push_back(mapping.toPixel(outline.control.at(static_cast<std::size_t>(3 * k))));
    std::vector<bool> bracket(blobs.size(), false);
    for (std::size_t i = 0; i < blobs.size(); ++i) {
        const auto legs = bracketIn(blobs[i], options.minFoldBar * mm, 4.0 * mm, 0.6 * mm, kMaxMarkWidthMm / 2 * mm);
        if (!legs)
            continue;
        bracket[i] = true; // a bracket's bar is no grainline, whether or not its fold is found
        const auto fold = foldAlong(polygon, *legs, 0.25 * mm, 6.0 * mm, corners, 3.0 * mm);
        if (!fold)
            continue;
        const std::array<Point, 2> foldMm{mapping.toMm((*fold)[0]), mapping.toMm((*fold)[1])};
        if (!found.fold || (foldMm[1] - foldMm[0]).norm() > ((*found.fold)[1] - (*found.fold)[0]).norm())
            found.fold = foldMm;
    }

    // The grainline: the longest straight line away from the edge that is no fold's bracket.
    std::optional<Grain> grain;
    for (std::size_t i = 0; i < blobs.size(); ++i)
        if (const Blob &b = blobs[i]; !bracket[i] && b.meanEdge >= options.grainFromEdge * mm)
            if (auto g = grainIn(b, options.minGrainline * mm, 0.6 * mm, kMaxMarkWidthMm / 2 * mm, 10.0 * mm))
                if (!grain || (g->b - g->a).norm() > (grain->b - grain->a).norm())
                    grain = g;
    if (grain) {
        Point a = mapping.toMm(grain->a), b = mapping.toMm(grain->b);
        bool towardsA = grain->headA && !grain->headB;
        if (grain->headA == grain->headB) {
            const Point d = b - a;
            towardsA = std::abs(d.y()) > 0.05 * d.norm() ? d.y() < 0.0 : d.x() < 0.0;
        }
        if (towardsA)
            std::swap(a, b);
        found.grainline = std::array<Point, 2>{a, b};
    }

    // Slits and marks across the edge: short thin lines from the edge inwards, square to it within 45°.
    for (const Blob &b : blobs) {
        const double length = b.hi - b.lo;
        if (b.nearEdge > blurBand + 0.6 * mm || length < 2.0 * mm || length > 12.0 * mm || b.across > 1.2 * mm)
            continue;
        const Point end1 = b.mean + b.lo * b.major, end2 = b.mean + b.hi * b.major;
        const auto [p1, i1] = geo::nearestOnPolyline(polygon, end1, true);
        const auto [p2, i2] = geo::nearestOnPolyline(polygon, end2, true);
        const bool firstOuter = (p1 - end1).norm() < (p2 - end2).norm();
        const Point outer = firstOuter ? end1 : end2, inner = firstOuter ? end2 : end1;
        const Point into = (inner - outer).normalized();
        const std::size_t i = firstOuter ? i1 : i2;
        const Point tangent = (polygon[(i + 1) % polygon.size()] - polygon[i]).normalized();
        if (std::abs(into.dot(tangent)) > std::sin(std::numbers::pi / 4))
            continue;
        // Where the line, carried on outwards, meets the edge.
        const Point normal(-tangent.y(), tangent.x());
        const double t =
            into.dot(normal) != 0.0 ? (firstOuter ? p1 - outer : p2 - outer).dot(normal) / into.dot(normal) : 0.0;
        const auto [at, unused] = geo::nearestOnPolyline(polygon, outer + t * into, true);
        const Point intoMm = mapping.toMm(at + into) - mapping.toMm(at);
        found.notches.push_back({mapping.toMm(at), intoMm.normalized(), FoundNotch::Kind::Slit});
    }

    // Drill holes: small round marks well inside, alone (a letter has neighbours); a dot inside a
    // circle is one hole.
    const auto nested = [](const cv::Rect &inner, const cv::Rect &outer) {
        return (inner & outer) == inner && inner != outer;
    };
    for (std::size_t i = 0; i < blobs.size(); ++i) {
        const Blob &b = blobs[i];
        const double size = b.hi - b.lo + 1.0;
        if (size < 0.6 * mm || size > 7.0 * mm || b.across < 0.6 * size || b.nearEdge < 3.0 * mm)
            continue;
        // Alone: no other mark's pixel within 3 mm of its box, but for a dot inside it. A dot inside a
        // small circle is that circle's.
        const cv::Rect grown(b.box.x - static_cast<int>(3 * mm), b.box.y - static_cast<int>(3 * mm),
                             b.box.width + static_cast<int>(6 * mm), b.box.height + static_cast<int>(6 * mm));
        bool alone = true;
        for (std::size_t j = 0; j < blobs.size() && alone; ++j) {
            const Blob &o = blobs[j];
            if (j == i || nested(o.box, b.box))
                continue;
            if (nested(b.box, o.box) && o.hi - o.lo + 1.0 <= 7.0 * mm) {
                alone = false;
                break;
            }
            if ((grown & o.box).area() == 0)
                continue;
            alone = std::none_of(o.px.begin(), o.px.end(), [&](const Point &p) {
                return grown.contains(cv::Point(static_cast<int>(p.x()), static_cast<int>(p.y())));
            });
        }
        if (!alone)
            continue;
        // Round: its pixels' middle is its box's middle, within a sixth of its size.
        const Point boxMid(b.box.x + (b.box.width - 1) / 2.0, b.box.y + (b.box.height - 1) / 2.0);
        if ((boxMid - b.mean).norm() > size / 6.0)
            continue;
        found.drillHoles.push_back(mapping.toMm(boxMid));
    }
    return found;
}

} // namespace kontur::vision
