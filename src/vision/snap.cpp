// Snapping a corner mark: the polygon of the bright region in a window around the mark gives the two
// edges' directions near the corner; each edge is then measured (edgefit.h) along an arm leading away
// from the corner, and the mark goes where the two lines meet.
#include "sheet.h"

#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace kontur::vision {

Result<geo::Point> snapCorner(const cv::Mat &photo, const geo::Point &approx, double searchRadiusPx)
{
    const cv::Mat gray = toGray(photo);
    if (gray.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty or not an 8-bit gray or colour image"};
    if (!(searchRadiusPx > 0) || !approx.allFinite())
        return Error{ErrorCode::InvalidArgument, "the search radius must be positive"};
    const auto noCorner = [] { return Error{ErrorCode::NoCornerFound, "no corner where two straight edges meet"}; };

    // A window several radii wide, so each arm is long enough for a good line.
    const double half = std::max(400.0, 16.0 * searchRadiusPx);
    const cv::Rect window =
        cv::Rect(cvFloor(approx.x() - half), cvFloor(approx.y() - half), cvCeil(2 * half), cvCeil(2 * half)) &
        cv::Rect(0, 0, gray.cols, gray.rows);
    if (window.width < 20 || window.height < 20)
        return noCorner();
    cv::Mat local;
    cv::GaussianBlur(gray(window), local, cv::Size(5, 5), 0);
    cv::threshold(local, local, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(local, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);

    // The polygon vertex nearest the mark that is not on the window's border and is a real turn.
    const geo::Point origin(window.x, window.y);
    double bestDistance = 1.5 * searchRadiusPx + 3.0;
    std::optional<std::array<geo::Point, 3>> best; // previous vertex, corner, next vertex
    const auto onBorder = [&](const cv::Point &p) {
        return p.x <= 1 || p.y <= 1 || p.x >= window.width - 2 || p.y >= window.height - 2;
    };
    for (const auto &contour : contours) {
        if (contour.size() < 20)
            continue;
        std::vector<cv::Point> poly;
        cv::approxPolyDP(contour, poly, 3.0, true);
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const cv::Point a = poly[(i + poly.size() - 1) % poly.size()], b = poly[i], c = poly[(i + 1) % poly.size()];
            if (onBorder(b))
                continue;
            const geo::Point pb = origin + geo::Point(b.x, b.y);
            const geo::Point u(a.x - b.x, a.y - b.y), v(c.x - b.x, c.y - b.y);
            const double angle = std::acos(std::clamp(u.dot(v) / std::max(1e-9, u.norm() * v.norm()), -1.0, 1.0));
            if (angle < 0.35 || angle > 2.8 || u.norm() < 12 || v.norm() < 12)
                continue;
            const double d = (pb - approx).norm();
            if (d < bestDistance) {
                bestDistance = d;
                best = std::array<geo::Point, 3>{origin + geo::Point(a.x, a.y), pb, origin + geo::Point(c.x, c.y)};
            }
        }
    }
    if (!best)
        return noCorner();

    std::optional<geo::Point> corner = (*best)[1];
    std::array<geo::Point, 2> dirs{((*best)[0] - (*best)[1]).normalized(), ((*best)[2] - (*best)[1]).normalized()};
    std::array<double, 2> arms{((*best)[0] - (*best)[1]).norm(), ((*best)[2] - (*best)[1]).norm()};
    for (const double radius : {6.0, 4.0}) {
        std::array<EdgeLine, 2> lines;
        for (int k = 0; k < 2; ++k) {
            const double start = 1.5 * radius + 6.0;
            const double end = std::min(arms[k], half);
            if (end < start + 20)
                return noCorner();
            EdgeSearch s;
            s.from = *corner + start * dirs[k];
            s.to = *corner + end * dirs[k];
            // The dark side is away from the other arm (the bright region lies between the arms).
            s.outward = -dirs[1 - k];
            s.radiusPx = radius;
            s.stepPx = 1.0;
            auto line = fitEdge(gray, s);
            if (!line || line->rms > 1.0)
                return noCorner();
            lines[k] = *line;
        }
        corner = intersect(lines[0], lines[1], 0.3);
        if (!corner)
            return noCorner();
        for (int k = 0; k < 2; ++k) {
            dirs[k] = lines[k].direction.dot(dirs[k]) < 0 ? geo::Point(-lines[k].direction) : lines[k].direction;
        }
    }
    if ((*corner - approx).norm() > searchRadiusPx * 1.5 + 3.0)
        return noCorner();
    return *corner;
}

} // namespace kontur::vision
