// Marks on a piece: see marks.h.
#include "vision/marks.h"

#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::vision {

using geo::Point;

namespace {

// The outline as a closed polygon in px, about a pixel apart.
std::vector<Point> outlinePolygon(const Outline &outline, const PixelMapping &mapping)
{
    std::vector<Point> px;
    for (int i = 0; i < outline.segmentCount(); ++i) {
        const geo::Bezier b = outline.segment(i);
        double len = 0.0;
        for (std::size_t k = 0; k + 1 < b.controlPoints().size(); ++k)
            len += (mapping.toPixel(b.controlPoints()[k + 1]) - mapping.toPixel(b.controlPoints()[k])).norm();
        const int steps = std::max(2, static_cast<int>(std::ceil(len)));
        for (int k = 0; k < steps; ++k)
            px.push_back(mapping.toPixel(b.eval(static_cast<double>(k) / steps)));
    }
    return px;
}

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

// The line through a blob's pixels (Huber-weighted, OpenCV's fitLine): a point on it and its direction.
std::pair<Point, Point> lineOf(const std::vector<Point> &px)
{
    std::vector<cv::Point2f> pts;
    pts.reserve(px.size());
    for (const Point &p : px)
        pts.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    cv::Vec4f l;
    cv::fitLine(pts, l, cv::DIST_HUBER, 0, 0.01, 0.01);
    return {Point(l[2], l[3]), Point(l[0], l[1]).normalized()};
}

// A grainline in a blob, if it is one: the straight core of at least `minLength` px, the pixels
// within the core's half-width of its line (1.5 times the line's own, from the median distance of the
// blob's pixels to it, at least `minCore`, at most `maxCore`) making up two thirds of it or more; its
// ends (px) and whether each has an arrowhead (pixels off the core within `headLength` of the end, on
// both sides of the line).
struct Grain
{
    Point a, b;
    bool headA = false, headB = false;
};

std::optional<Grain> grainIn(const Blob &blob, double minLength, double minCore, double maxCore, double headLength)
{
    if (blob.hi - blob.lo < minLength)
        return std::nullopt;
    const auto [on, dir] = lineOf(blob.px);
    const Point normal(-dir.y(), dir.x());
    std::vector<double> across;
    across.reserve(blob.px.size());
    for (const Point &p : blob.px)
        across.push_back(std::abs((p - on).dot(normal)));
    std::nth_element(across.begin(), across.begin() + static_cast<std::ptrdiff_t>(across.size() / 2), across.end());
    // Half a band's width is twice the median distance of its pixels from its middle.
    const double coreWidth = std::clamp(1.5 * 2.0 * across[across.size() / 2], minCore, maxCore);
    double lo = 1e300, hi = -1e300;
    std::size_t core = 0;
    for (const Point &p : blob.px)
        if (std::abs((p - on).dot(normal)) <= coreWidth) {
            const double t = (p - on).dot(dir);
            lo = std::min(lo, t), hi = std::max(hi, t);
            ++core;
        }
    if (core < 2 * blob.px.size() / 3 || hi - lo < minLength)
        return std::nullopt;
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

// The point of a closed polygon nearest to p.
std::pair<Point, std::size_t> nearestOn(const std::vector<Point> &polygon, const Point &p)
{
    Point best = polygon.front();
    std::size_t at = 0;
    double bestD = 1e300;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
        const Point ab = b - a;
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        const Point q = a + t * ab;
        const double d = (q - p).squaredNorm();
        if (d < bestD)
            bestD = d, best = q, at = i;
    }
    return {best, at};
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

    // The grainline: the longest straight line away from the edge.
    std::optional<Grain> grain;
    for (const Blob &b : blobs)
        if (b.meanEdge >= options.grainFromEdge * mm)
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
        const auto [p1, i1] = nearestOn(polygon, end1);
        const auto [p2, i2] = nearestOn(polygon, end2);
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
        const auto [at, unused] = nearestOn(polygon, outer + t * into);
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
