// The coarse search for the sheet (sheet.h, detail::sheetCandidates): bright quadrilaterals on a copy of
// the photo reduced to at most 1000 px, from many segmentations, each judged by its edges.
//
// Real phone photos showed why one threshold is not enough (docs/vision.md, "Real photos"): a white
// sheet on light wood is barely brighter than the wood in grey, but far brighter in the darkest of its
// three channels, min(R, G, B) — paper is white, wood, tiles and cloth are coloured; a box lying on the
// sheet, or a shadow, cuts the bright region so that its outline is no longer four-sided, yet its convex
// hull still is; and on a white desk no threshold parts sheet and desk, while the sheet's edges are still
// there for an edge detector. So the candidates come from:
// - thresholds of the grey and the min(R, G, B) images at five levels between Otsu's (Otsu 1979) and the
//   99th percentile, opened by 5×5;
// - the regions that Canny's edges (Canny 1986) enclose, at two sensitivities;
// each region's outer contour (Suzuki & Abe 1985), its convex hull, the hull simplified to 1 % of its
// perimeter (Douglas & Peucker 1973), and from that polygon the quadrilateral of its four longest sides
// (their lines meeting at the corners, so a corner cut off by an object is restored). A candidate is kept
// when each of its sides is an edge from bright inside to darker outside along at least 40 % of it (60 %
// on average), the "support"; candidates are ranked by area × support, near-duplicates merged.
#include "sheet.h"

#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace kontur::vision::detail {
namespace {

using Quad = std::array<cv::Point2d, 4>;

constexpr double kMaxSearchSidePx = 1000.0; // the reduced copy's longest side
constexpr int kSupportSamples = 40;         // points per side where the edge is looked for
constexpr double kMinStep = 10.0;           // grey levels from inside to outside that count as an edge
constexpr double kMinSideSupport = 0.4;     // every side an edge along this share of it
constexpr double kMinMeanSupport = 0.6;     // and the four sides on average
constexpr double kMinAngle = 0.5;           // rad (29°): no interior angle sharper than this
constexpr double kMinAreaShare = 0.004;     // of the reduced photo

double cross(const cv::Point2d &a, const cv::Point2d &b)
{
    return a.x * b.y - a.y * b.x;
}

double quadArea(const Quad &q)
{
    double a = 0;
    for (int i = 0; i < 4; ++i)
        a += cross(q[i], q[(i + 1) % 4]);
    return 0.5 * std::abs(a);
}

bool convexWithSaneAngles(const Quad &q)
{
    double sign = 0;
    for (int i = 0; i < 4; ++i) {
        const cv::Point2d a = q[(i + 3) % 4], b = q[i], c = q[(i + 1) % 4];
        const cv::Point2d u = a - b, v = c - b;
        const double z = cross(c - b, a - b);
        if (z == 0 || (sign != 0 && (z > 0) != (sign > 0)))
            return false;
        sign = z;
        const double cosine = u.dot(v) / std::max(1e-12, std::hypot(u.x, u.y) * std::hypot(v.x, v.y));
        if (std::acos(std::clamp(cosine, -1.0, 1.0)) < kMinAngle)
            return false;
    }
    return true;
}

// The quadrilateral a region spans: its convex hull simplified to 1 % of the perimeter, then the lines
// of the polygon's four longest sides (in their order round it) meeting at the corners. Nothing when the
// four sides cover less than 75 % of the hull's perimeter (a rounded or many-sided shape).
std::optional<Quad> quadOfRegion(const std::vector<cv::Point> &contour)
{
    std::vector<cv::Point> hull, poly;
    cv::convexHull(contour, hull);
    const double perimeter = cv::arcLength(hull, true);
    cv::approxPolyDP(hull, poly, 0.01 * perimeter, true);
    const int n = static_cast<int>(poly.size());
    if (n < 4)
        return std::nullopt;
    std::vector<int> order(static_cast<std::size_t>(n));
    std::vector<double> length(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        order[static_cast<std::size_t>(i)] = i;
        const cv::Point d = poly[static_cast<std::size_t>((i + 1) % n)] - poly[static_cast<std::size_t>(i)];
        length[static_cast<std::size_t>(i)] = std::hypot(d.x, d.y);
    }
    std::partial_sort(order.begin(), order.begin() + 4, order.end(), [&](int a, int b) {
        return length[static_cast<std::size_t>(a)] > length[static_cast<std::size_t>(b)];
    });
    std::sort(order.begin(), order.begin() + 4);
    double covered = 0;
    for (int k = 0; k < 4; ++k)
        covered += length[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
    if (covered < 0.75 * cv::arcLength(poly, true))
        return std::nullopt;
    Quad q;
    for (int k = 0; k < 4; ++k) {
        // Corner k: where the side before it meets the side after it.
        const int s0 = order[static_cast<std::size_t>((k + 3) % 4)], s1 = order[static_cast<std::size_t>(k)];
        const cv::Point2d a0 = poly[static_cast<std::size_t>(s0)], a1 = poly[static_cast<std::size_t>((s0 + 1) % n)];
        const cv::Point2d b0 = poly[static_cast<std::size_t>(s1)], b1 = poly[static_cast<std::size_t>((s1 + 1) % n)];
        const cv::Point2d da = a1 - a0, db = b1 - b0;
        const double den = cross(da, db);
        if (std::abs(den) < 1e-9 * std::hypot(da.x, da.y) * std::hypot(db.x, db.y))
            return std::nullopt;
        q[static_cast<std::size_t>(k)] = a0 + da * (cross(b0 - a0, db) / den);
    }
    if (!convexWithSaneAngles(q))
        return std::nullopt;
    return q;
}

double sample(const cv::Mat &img, const cv::Point2d &p)
{
    return sampleBilinear(img, p.x, p.y);
}

// The share of each side along which some channel steps down by kMinStep from inside to outside within
// `reach` px of the side (the middle 84 % of the side; its ends meet the neighbouring sides).
std::array<double, 4> sideSupport(const std::vector<cv::Mat> &channels, const Quad &q, double reach)
{
    cv::Point2d centre(0, 0);
    for (const auto &p : q)
        centre += 0.25 * p;
    std::array<double, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const cv::Point2d a = q[static_cast<std::size_t>(i)], b = q[static_cast<std::size_t>((i + 1) % 4)];
        const cv::Point2d d = b - a;
        const double len = std::hypot(d.x, d.y);
        if (len < 8)
            return {};
        cv::Point2d n(d.y / len, -d.x / len);
        if (n.dot(0.5 * (a + b) - centre) < 0)
            n = -n;
        int hits = 0;
        for (int k = 0; k < kSupportSamples; ++k) {
            const double t = 0.08 + 0.84 * (k + 0.5) / kSupportSamples;
            const cv::Point2d p = a + t * d;
            bool hit = false;
            for (const cv::Mat &c : channels) {
                for (double o = -reach; o <= reach && !hit; o += 1.0)
                    hit = sample(c, p + (o - 2.0) * n) - sample(c, p + (o + 2.0) * n) >= kMinStep;
                if (hit)
                    break;
            }
            hits += hit ? 1 : 0;
        }
        out[static_cast<std::size_t>(i)] = static_cast<double>(hits) / kSupportSamples;
    }
    return out;
}

bool sameQuad(const Quad &a, const Quad &b, double tolerance)
{
    // Corners in the same cyclic order, starting anywhere.
    for (int shift = 0; shift < 4; ++shift) {
        bool same = true;
        for (int i = 0; i < 4 && same; ++i) {
            const cv::Point2d d = a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>((i + shift) % 4)];
            same = std::hypot(d.x, d.y) < tolerance;
        }
        if (same)
            return true;
    }
    return false;
}

} // namespace

cv::Mat whiteness(const cv::Mat &photo)
{
    if (photo.empty() || photo.depth() != CV_8U || photo.channels() < 3)
        return {};
    std::vector<cv::Mat> planes;
    cv::split(photo, planes);
    cv::Mat out;
    cv::min(planes[0], planes[1], out);
    cv::min(out, planes[2], out);
    return out;
}

std::vector<SheetCandidate> sheetCandidates(const cv::Mat &gray, const cv::Mat &white)
{
    const double scale = std::max(1.0, std::max(gray.cols, gray.rows) / kMaxSearchSidePx);
    const auto reduce = [&](const cv::Mat &m) {
        cv::Mat small;
        if (scale > 1.0)
            cv::resize(m, small, cv::Size(cvRound(m.cols / scale), cvRound(m.rows / scale)), 0, 0, cv::INTER_AREA);
        else
            small = m.clone();
        cv::GaussianBlur(small, small, cv::Size(5, 5), 0);
        return small;
    };
    std::vector<cv::Mat> channels{reduce(gray)};
    if (!white.empty())
        channels.push_back(reduce(white));
    const cv::Size small = channels.front().size();
    const double sx = static_cast<double>(gray.cols) / small.width, sy = static_cast<double>(gray.rows) / small.height;
    const double minArea = kMinAreaShare * small.area();

    std::vector<std::vector<cv::Point>> regions;
    const auto addContours = [&](const cv::Mat &bin, int mode) {
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(bin, contours, mode, cv::CHAIN_APPROX_SIMPLE);
        for (auto &c : contours)
            if (c.size() >= 4 && cv::contourArea(c) >= minArea)
                regions.push_back(std::move(c));
    };
    const cv::Mat open5 = cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5});
    for (const cv::Mat &c : channels) {
        cv::Mat bin;
        const double otsu = cv::threshold(c, bin, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
        std::vector<uchar> values(c.begin<uchar>(), c.end<uchar>());
        const auto p99 = values.begin() + static_cast<std::ptrdiff_t>(values.size() * 99 / 100);
        std::nth_element(values.begin(), p99, values.end());
        const double top = *p99;
        for (const double f : {0.0, 0.25, 0.5, 0.7, 0.85}) {
            cv::threshold(c, bin, (1 - f) * otsu + f * top, 255, cv::THRESH_BINARY);
            cv::morphologyEx(bin, bin, cv::MORPH_OPEN, open5);
            addContours(bin, cv::RETR_LIST);
        }
        // Regions enclosed by edges: the complement of the dilated edge map.
        for (const auto &[low, high] : {std::pair{15.0, 45.0}, std::pair{30.0, 90.0}}) {
            cv::Mat edges;
            cv::Canny(c, edges, low, high, 3, true);
            cv::dilate(edges, edges, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
            cv::bitwise_not(edges, edges);
            addContours(edges, cv::RETR_LIST);
        }
    }

    std::vector<SheetCandidate> out;
    const double mergeTolerance = std::max(4.0, 0.01 * std::hypot(small.width, small.height));
    for (const auto &region : regions) {
        const auto quad = quadOfRegion(region);
        if (!quad || quadArea(*quad) < minArea)
            continue;
        const std::array<double, 4> support = sideSupport(channels, *quad, 3.0);
        const double least = *std::min_element(support.begin(), support.end());
        const double mean = 0.25 * (support[0] + support[1] + support[2] + support[3]);
        if (least < kMinSideSupport || mean < kMinMeanSupport)
            continue;
        const double score = quadArea(*quad) * mean;
        SheetCandidate candidate;
        for (int i = 0; i < 4; ++i) {
            const cv::Point2d &p = (*quad)[static_cast<std::size_t>(i)];
            candidate.corners[static_cast<std::size_t>(i)] = geo::Point((p.x + 0.5) * sx - 0.5, (p.y + 0.5) * sy - 0.5);
        }
        candidate.support = mean;
        candidate.score = score;
        candidate.reductionPx = 0.5 * (sx + sy);
        const auto same = std::find_if(out.begin(), out.end(), [&](const SheetCandidate &o) {
            Quad a, b;
            for (int i = 0; i < 4; ++i) {
                a[static_cast<std::size_t>(i)] = cv::Point2d(o.corners[static_cast<std::size_t>(i)].x() / sx,
                                                             o.corners[static_cast<std::size_t>(i)].y() / sy);
                b[static_cast<std::size_t>(i)] = (*quad)[static_cast<std::size_t>(i)];
            }
            return sameQuad(a, b, mergeTolerance);
        });
        if (same == out.end())
            out.push_back(candidate);
        else if (candidate.score > same->score)
            *same = candidate;
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const SheetCandidate &a, const SheetCandidate &b) { return a.score > b.score; });
    return out;
}

} // namespace kontur::vision::detail
