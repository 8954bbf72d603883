// Finding the sheet: a coarse bright quadrilateral on a reduced copy of the photo (Otsu 1979
// threshold, Suzuki & Abe 1985 contours, Douglas & Peucker 1973 polygon), then its four edges
// measured at full resolution (edgefit.h) in three passes of narrowing search radius, each
// pass starting from the corners where the previous pass's lines meet.
#include "sheet.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace kontur::vision {
namespace {

struct Quad
{
    std::array<geo::Point, 4> corners;
    double score = 0;
};

double minInteriorAngle(const std::vector<cv::Point> &poly)
{
    double smallest = M_PI;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const cv::Point a = poly[(i + poly.size() - 1) % poly.size()], b = poly[i], c = poly[(i + 1) % poly.size()];
        const geo::Point u(a.x - b.x, a.y - b.y), v(c.x - b.x, c.y - b.y);
        const double cosine = u.dot(v) / std::max(1e-12, u.norm() * v.norm());
        smallest = std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)));
    }
    return smallest;
}

// Bright convex quadrilaterals in the reduced photo that fill their outline (a sheet, not a piece
// with curved sides), in full-resolution pixel coordinates.
std::vector<Quad> coarseQuads(const cv::Mat &gray, double &scale)
{
    scale = std::max(1.0, std::max(gray.cols, gray.rows) / 1000.0);
    cv::Mat small;
    if (scale > 1.0)
        cv::resize(gray, small, cv::Size(), 1.0 / scale, 1.0 / scale, cv::INTER_AREA);
    else
        small = gray;
    scale = static_cast<double>(gray.cols) / small.cols;
    cv::GaussianBlur(small, small, cv::Size(5, 5), 0);
    cv::Mat bin;
    const double otsu = cv::threshold(small, bin, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    // Higher levels, halfway and three quarters from Otsu's level to the 95th percentile: for light
    // tables, and to part a sheet from a white piece lying so close that the blurred gap between them
    // stays above Otsu's level.
    std::vector<uchar> values(small.begin<uchar>(), small.end<uchar>());
    std::nth_element(values.begin(), values.begin() + values.size() * 95 / 100, values.end());
    const double p95 = values[values.size() * 95 / 100];

    std::vector<Quad> quads;
    const double minArea = 0.005 * small.total();
    for (const double level : {otsu, 0.5 * (otsu + p95), 0.25 * otsu + 0.75 * p95}) {
        cv::threshold(small, bin, level, 255, cv::THRESH_BINARY);
        cv::morphologyEx(bin, bin, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5}));
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(bin, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
        for (const auto &contour : contours) {
            const double area = cv::contourArea(contour);
            if (area < minArea)
                continue;
            std::vector<cv::Point> poly;
            cv::approxPolyDP(contour, poly, 0.02 * cv::arcLength(contour, true), true);
            if (poly.size() != 4) {
                std::vector<cv::Point> hull;
                cv::convexHull(contour, hull);
                cv::approxPolyDP(hull, poly, 0.02 * cv::arcLength(hull, true), true);
            }
            if (poly.size() != 4 || !cv::isContourConvex(poly) || minInteriorAngle(poly) < 0.5)
                continue;
            const double fill = area / cv::contourArea(poly);
            if (fill < 0.93 || fill > 1.07)
                continue;
            Quad q;
            for (int i = 0; i < 4; ++i)
                q.corners[i] = geo::Point((poly[i].x + 0.5) * scale - 0.5, (poly[i].y + 0.5) * scale - 0.5);
            q.score = area * (1.0 - std::abs(1.0 - fill));
            quads.push_back(q);
        }
    }
    return quads;
}

// One pass over the four sides between the current corners; `radius` is how far the true edge may be.
Result<std::array<EdgeLine, 4>> measureSides(const cv::Mat &gray, const std::array<geo::Point, 4> &c, double radius)
{
    std::array<EdgeLine, 4> lines;
    const geo::Point centre = (c[0] + c[1] + c[2] + c[3]) / 4.0;
    for (int i = 0; i < 4; ++i) {
        const geo::Point a = c[i], b = c[(i + 1) % 4];
        const double length = (b - a).norm();
        // Leave out the ends, where the profile would cross the neighbouring edge.
        const double margin = std::max(0.05 * length, 1.5 * radius + 6.0);
        if (length < 2 * margin + 20)
            return Error{ErrorCode::NoSheetFound, "the sheet is too small in the photo"};
        const geo::Point dir = (b - a) / length;
        EdgeSearch s;
        s.from = a + margin * dir;
        s.to = b - margin * dir;
        s.outward = (0.5 * (a + b) - centre).normalized();
        s.radiusPx = radius;
        s.stepPx = std::clamp(length / 600.0, 1.0, 3.0);
        auto line = fitEdge(gray, s);
        if (!line)
            return line.error();
        lines[i] = *line;
    }
    return lines;
}

Result<std::array<geo::Point, 4>> cornersOf(const std::array<EdgeLine, 4> &lines)
{
    std::array<geo::Point, 4> out;
    for (int i = 0; i < 4; ++i) {
        // Corner i is where side i-1 (ending there) meets side i (starting there).
        auto p = intersect(lines[(i + 3) % 4], lines[i]);
        if (!p)
            return Error{ErrorCode::Degenerate, "two adjacent edges are parallel"};
        out[i] = *p;
    }
    return out;
}

// The three passes from coarse corners to the fitted edges, and the checks that make it a sheet.
Result<Sheet> refine(const cv::Mat &gray, std::array<geo::Point, 4> corners, double radius, const SheetOptions &options)
{
    std::array<EdgeLine, 4> lines;
    for (const double r : {radius, 5.0, 5.0}) {
        auto measured = measureSides(gray, corners, r);
        if (!measured)
            return measured.error();
        lines = *measured;
        auto next = cornersOf(lines);
        if (!next)
            return next.error();
        corners = *next;
    }
    for (int i = 0; i < 4; ++i) {
        // Straight within a pixel, or within 0.3 % of the side on a large, soft image (a rectified one).
        const EdgeLine &line = lines[i];
        const double side = (corners[(i + 1) % 4] - corners[i]).norm();
        if (line.rms > std::max(1.0, 0.003 * side) || line.count < 0.5 * line.sampled || line.contrast < 4.0)
            return Error{ErrorCode::NoSheetFound, "the sheet's edges are not straight or not clear enough"};
    }
    return detail::sheetFromEdges(lines, options.sizeMm, gray.size());
}

} // namespace

Result<Sheet> findSheet(const cv::Mat &photo, const SheetOptions &options)
{
    const cv::Mat gray = detail::toGray(photo);
    if (gray.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty or not an 8-bit gray or colour image"};
    if (!(options.sizeMm.x() > 0) || !(options.sizeMm.y() > 0) ||
        !std::isfinite(options.sizeMm.x() + options.sizeMm.y()))
        return Error{ErrorCode::InvalidArgument, "the sheet's size must be positive"};

    std::optional<Result<Sheet>> found;
    if (options.cornerHints) {
        found = refine(gray, detail::orderCorners(*options.cornerHints), std::max(2.0, options.hintRadiusPx), options);
    } else {
        double scale = 1;
        std::vector<Quad> quads = coarseQuads(gray, scale);
        if (quads.empty())
            return Error{ErrorCode::NoSheetFound, "no sheet found in the photo"};
        const auto nearest = [&](const Quad &q) {
            double d = INFINITY;
            for (const auto &p : q.corners)
                d = std::min(d, (p - *options.cornerHint).norm());
            return d;
        };
        std::stable_sort(quads.begin(), quads.end(), [&](const Quad &a, const Quad &b) {
            return options.cornerHint ? nearest(a) < nearest(b) : a.score > b.score;
        });
        // The best candidates in turn, until one has four straight edges.
        for (std::size_t i = 0; i < std::min<std::size_t>(quads.size(), 6); ++i) {
            auto sheet = refine(gray, detail::orderCorners(quads[i].corners), 4.0 * scale + 4.0, options);
            const bool ok = sheet.ok();
            if (ok || !found)
                found = std::move(sheet);
            if (ok)
                break;
        }
    }
    if (!found->ok())
        return *found;
    Sheet sheet = std::move(*found).value();
    if (options.cornerHint) {
        double best = INFINITY;
        for (int i = 0; i < 4; ++i) {
            const double d = (sheet.corners[i] - *options.cornerHint).norm();
            if (d < best) {
                best = d;
                sheet.hintedCorner = i;
            }
        }
    }
    return sheet;
}

} // namespace kontur::vision
