// The sheet's frame (which side is which, the homographies), its calibration error, paper sizes and
// the snapping of a dragged corner mark to where two edges meet.
#include "sheet.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace kontur::vision {
namespace detail {

std::array<geo::Point, 4> orderCorners(std::array<geo::Point, 4> c)
{
    const geo::Point centre = (c[0] + c[1] + c[2] + c[3]) / 4.0;
    // atan2 grows clockwise on screen (y down).
    std::sort(c.begin(), c.end(), [&](const geo::Point &a, const geo::Point &b) {
        return std::atan2(a.y() - centre.y(), a.x() - centre.x()) < std::atan2(b.y() - centre.y(), b.x() - centre.x());
    });
    const auto first = std::min_element(
        c.begin(), c.end(), [](const geo::Point &a, const geo::Point &b) { return a.x() + a.y() < b.x() + b.y(); });
    std::rotate(c.begin(), first, c.end());
    return c;
}

namespace {

// The images of a rectangle's two axes through K⁻¹ for a pinhole camera with square pixels, the
// principal point at the photo's centre and focal length f: K⁻¹h₁ and K⁻¹h₂ must be orthogonal, and
// their lengths' ratio is the ratio of the rectangle's sides to the lengths it was mapped from (Zhang
// 2000; Hartley & Zisserman 2nd ed. §8.8). Calls `visit(f, a, b)` over focal lengths 0.25–6 × the
// photo's diagonal, geometrically spaced (a phone's ultra-wide to a zoomed telephoto).
template <typename Visit>
void overFocalLengths(const Homography &rectToPhoto, cv::Size photo, Visit visit, double lowFactor = 0.25,
                      double highFactor = 6.0)
{
    Eigen::Matrix3d centre = Eigen::Matrix3d::Identity();
    centre(0, 2) = -0.5 * (photo.width - 1);
    centre(1, 2) = -0.5 * (photo.height - 1);
    const Eigen::Matrix3d h = centre * rectToPhoto;
    const double diag = std::hypot(photo.width, photo.height);
    for (int k = 0; k <= 80; ++k) {
        const double f = diag * lowFactor * std::pow(highFactor / lowFactor, k / 80.0);
        Eigen::Vector3d a = h.col(0), b = h.col(1);
        a.head<2>() /= f;
        b.head<2>() /= f;
        visit(f, a, b);
    }
}

// How far the homography sheet → photo is from one of a pinhole camera (above), for the best focal
// length: |ln(|a| / |b|)| (the sides' proportions) plus |cos ∠(a, b)| (their angle). Only the right
// assignment of the sheet's sides can make both small.
double pinholeInconsistency(const Homography &sheetToPhoto, cv::Size photo)
{
    double best = INFINITY;
    overFocalLengths(sheetToPhoto, photo, [&](double, const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
        const double score = std::abs(std::log(a.norm() / b.norm())) + std::abs(a.dot(b)) / (a.norm() * b.norm());
        best = std::min(best, score);
    });
    return best;
}

} // namespace

Result<Sheet> sheetFromEdges(const std::array<EdgeLine, 4> &edges, geo::Point sizeMm, cv::Size photo,
                             bool checkProportions, double knownFocalPx)
{
    Sheet sheet;
    sheet.edges = edges;
    for (int i = 0; i < 4; ++i) {
        auto p = intersect(edges[(i + 3) % 4], edges[i]);
        if (!p)
            return Error{ErrorCode::Degenerate, "two adjacent edges of the sheet are parallel"};
        sheet.corners[i] = *p;
    }
    std::vector<cv::Point2f> poly;
    for (const auto &p : sheet.corners)
        poly.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    if (!cv::isContourConvex(poly))
        return Error{ErrorCode::Degenerate, "the sheet's corners do not form a convex quadrilateral"};
    for (const auto &p : sheet.corners)
        if (p.x() < -0.5 || p.y() < -0.5 || p.x() > photo.width - 0.5 || p.y() > photo.height - 0.5)
            return Error{ErrorCode::NoSheetFound, "a corner of the sheet lies outside the photo"};

    std::optional<Homography> best;
    double bestScore = INFINITY;
    for (const geo::Point &size : {sizeMm, geo::Point(sizeMm.y(), sizeMm.x())}) {
        const std::array<geo::Point, 4> rect{geo::Point(0, 0), geo::Point(size.x(), 0), size, geo::Point(0, size.y())};
        auto h = homographyFrom4(rect, sheet.corners);
        if (!h)
            continue;
        const double score = pinholeInconsistency(*h, photo);
        if (score < bestScore) {
            bestScore = score;
            best = h;
            sheet.sizeMm = size;
        }
    }
    if (!best)
        return Error{ErrorCode::Degenerate, "no homography from the sheet's corners"};
    const SeenRectangle seen = seenRectangle(sheet.corners, photo, knownFocalPx);
    const double wanted = std::max(sizeMm.x(), sizeMm.y()) / std::min(sizeMm.x(), sizeMm.y());
    const double off = wanted < seen.aspectLow    ? std::log(seen.aspectLow / wanted)
                       : wanted > seen.aspectHigh ? std::log(wanted / seen.aspectHigh)
                                                  : 0.0;
    if (checkProportions && (!(off <= kMaxProportionMismatch) || !(seen.skew <= kMaxRectangleSkew))) {
        Error error{ErrorCode::WrongProportions, "a rectangle of other proportions than the sheet's"};
        error.seenAspect = seen.aspect;
        return error;
    }
    sheet.sheetToPhoto = *best;
    sheet.photoToSheet = best->inverse();
    sheet.photoToSheet /= sheet.photoToSheet(2, 2);
    return sheet;
}

} // namespace detail

SeenRectangle seenRectangle(const std::array<geo::Point, 4> &corners, cv::Size photo, double knownFocalPx)
{
    SeenRectangle seen;
    const std::array<geo::Point, 4> unit{geo::Point(0, 0), geo::Point(1, 0), geo::Point(1, 1), geo::Point(0, 1)};
    const auto h = homographyFrom4(unit, corners);
    if (!h)
        return seen;
    struct Candidate
    {
        double focal, skew, aspect;
    };
    std::vector<Candidate> candidates;
    const auto visit = [&](double f, const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
        const double skew = std::abs(a.dot(b)) / (a.norm() * b.norm());
        const double aspect = std::max(a.norm(), b.norm()) / std::min(a.norm(), b.norm());
        candidates.push_back({f, skew, aspect});
    };
    detail::overFocalLengths(*h, photo, visit);
    // Finely about a known focal length: the proportions of a sheet seen without yaw change by about
    // as much as the focal length does.
    const double diag = std::hypot(photo.width, photo.height);
    if (knownFocalPx > 0.0 && std::isfinite(knownFocalPx) && diag > 0.0)
        detail::overFocalLengths(*h, photo, visit, knownFocalPx / kFocalSlack / diag, knownFocalPx * kFocalSlack / diag);
    const auto pick = [&](auto &&allowed) {
        seen.skew = INFINITY;
        for (const Candidate &c : candidates)
            if (allowed(c) && c.skew < seen.skew)
                seen.skew = c.skew, seen.focalPx = c.focal, seen.aspect = c.aspect;
        // Where the angle hardly tells the focal length (a sheet seen nearly square on), every focal
        // length as good as the best leaves its own proportions: all of them are what the photo shows.
        seen.aspectLow = seen.aspectHigh = seen.aspect;
        for (const Candidate &c : candidates)
            if (allowed(c) && c.skew <= seen.skew + kSkewSlack) {
                seen.aspectLow = std::min(seen.aspectLow, c.aspect);
                seen.aspectHigh = std::max(seen.aspectHigh, c.aspect);
            }
    };
    pick([](const Candidate &) { return true; });
    if (knownFocalPx > 0.0 && std::isfinite(knownFocalPx)) {
        const SeenRectangle any = seen;
        const auto near = [&](const Candidate &c) {
            return c.focal >= knownFocalPx / kFocalSlack && c.focal <= knownFocalPx * kFocalSlack;
        };
        pick(near);
        seen.focalUsed = seen.skew <= any.skew + kSkewSlack;
        if (!seen.focalUsed)
            seen = any;
    }
    return seen;
}

Result<geo::Point> parseSheetSize(std::string_view text)
{
    std::string t(text);
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (t == "a4")
        return geo::Point(210, 297);
    if (t == "a3")
        return geo::Point(297, 420);
    if (t == "letter")
        return geo::Point(215.9, 279.4);
    double factor = 1;
    for (const auto &[suffix, f] : {std::pair{"mm", 1.0}, std::pair{"cm", 10.0}, std::pair{"in", 25.4}}) {
        const std::string s(suffix);
        if (t.size() > s.size() && t.compare(t.size() - s.size(), s.size(), s) == 0) {
            factor = f;
            t.resize(t.size() - s.size());
            break;
        }
    }
    const auto x = t.find('x');
    double w = 0, h = 0;
    const char *end = t.data() + t.size();
    if (x == std::string::npos || std::from_chars(t.data(), t.data() + x, w).ptr != t.data() + x ||
        std::from_chars(t.data() + x + 1, end, h).ptr != end || !(w > 0) || !(h > 0) || !std::isfinite(w * h))
        return Error{ErrorCode::InvalidArgument, "sheet size must be a4, a3, letter or WxH[mm|cm|in]"};
    return geo::Point(w * factor, h * factor);
}

std::vector<double> calibrationErrorMm(const Sheet &sheet, std::span<const geo::Point> worldMm)
{
    const std::array<geo::Point, 4> rect{geo::Point(0, 0), geo::Point(sheet.sizeMm.x(), 0), sheet.sizeMm,
                                         geo::Point(0, sheet.sizeMm.y())};
    const double w0 = homogeneousW(sheet.sheetToPhoto, rect[0] + 0.5 * (rect[2] - rect[0]));
    // The world point of a fixed photo point under the sheet whose eight line parameters are moved by `delta`.
    const auto mapped = [&](const geo::Point &photoPoint, int param, double delta) -> std::optional<geo::Point> {
        std::array<EdgeLine, 4> lines = sheet.edges;
        if (param >= 0) {
            EdgeLine &l = lines[param / 2];
            if (param % 2 == 0) {
                const double c = std::cos(delta), s = std::sin(delta);
                l.direction =
                    geo::Point(c * l.direction.x() - s * l.direction.y(), s * l.direction.x() + c * l.direction.y());
            } else {
                l.point += delta * l.outward;
            }
        }
        std::array<geo::Point, 4> corners;
        for (int i = 0; i < 4; ++i) {
            auto p = intersect(lines[(i + 3) % 4], lines[i], 1e-6);
            if (!p)
                return std::nullopt;
            corners[i] = *p;
        }
        auto h = homographyFrom4(corners, rect);
        if (!h)
            return std::nullopt;
        return apply(*h, photoPoint);
    };
    std::vector<double> out;
    for (const auto &x : worldMm) {
        if (homogeneousW(sheet.sheetToPhoto, x) * w0 <= 0) {
            out.push_back(INFINITY);
            continue;
        }
        const geo::Point p = apply(sheet.sheetToPhoto, x);
        Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
        for (int k = 0; k < 8; ++k) {
            const EdgeLine &l = sheet.edges[k / 2];
            const double sd = std::sqrt(k % 2 == 0 ? l.angleVariance : l.offsetVariance);
            if (!(sd > 0))
                continue;
            const double step = 0.5 * sd;
            const auto plus = mapped(p, k, step), minus = mapped(p, k, -step);
            if (!plus || !minus) {
                cov = Eigen::Matrix2d::Constant(INFINITY);
                break;
            }
            const geo::Point j = (*plus - *minus) / (2 * step);
            cov += (j * j.transpose()) * (sd * sd);
        }
        out.push_back(std::sqrt(cov.trace()));
    }
    return out;
}

double calibrationErrorAtPhotoCornersMm(const Sheet &sheet, cv::Size photoSize)
{
    std::vector<geo::Point> world;
    for (const auto &p :
         {geo::Point(0, 0), geo::Point(photoSize.width - 1.0, 0),
          geo::Point(photoSize.width - 1.0, photoSize.height - 1.0), geo::Point(0, photoSize.height - 1.0)})
        world.push_back(apply(sheet.photoToSheet, p));
    double worst = 0;
    const std::vector<double> errors = calibrationErrorMm(sheet, world);
    for (const double e : errors)
        worst = std::max(worst, e);
    return worst;
}

} // namespace kontur::vision
