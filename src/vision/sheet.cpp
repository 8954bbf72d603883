// Finding the sheet: coarse bright quadrilaterals on a reduced copy of the photo (sheetsearch.cpp),
// then each one's four edges measured at full resolution (edgefit.h) in three passes of narrowing
// search radius, each pass starting from the corners where the previous pass's lines meet, until one
// has four straight edges and the sheet's proportions.
#include "sheet.h"

#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace kontur::vision {
namespace {

constexpr std::size_t kMaxRefined = 8; // coarse candidates measured at full resolution, best first
// A found sheet's edge may stray from its line (edgeBend) by this much, or this share of the side,
// whichever is more, measured from the line through the whole edge: flat sheets in the labelled real
// photos stay within it but one, curled and creased ones mostly bend more (docs/vision.md, "Real
// photos"); lens distortion, a soft paper edge and a box lying over the edge (synthetic: 5.2 px) are
// within it.
constexpr double kMaxBendPx = 5.5;
constexpr double kMaxBendShare = 0.003;
// An edge that turns bright again just beyond it along more than this share is a printed line (lineShare).
constexpr double kMaxLineShare = 0.5;

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
        // A wide first search takes a soft or slightly wavy edge whole; the later passes narrow it.
        s.inlierPx = std::max(1.0, radius / 10.0);
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

// The three passes from coarse corners to the fitted edges, and the checks that make it a sheet. A sheet
// found by the search must also be flat (`checkBend`); four corners the user gave are taken as bent as
// they are, the calibration error then says what that costs.
Result<Sheet> refine(const cv::Mat &gray, std::array<geo::Point, 4> corners, double radius, const SheetOptions &options,
                     bool checkBend)
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
    const geo::Point centre = (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
    for (int i = 0; i < 4; ++i) {
        const EdgeLine &line = lines[i];
        const geo::Point a = corners[i], b = corners[(i + 1) % 4];
        const double side = (b - a).norm();
        if (line.count < 0.5 * line.sampled || line.contrast < 4.0)
            return Error{ErrorCode::NoSheetFound, "the sheet's edges are not clear enough"};
        // Straight within a pixel, or within 0.3 % of the side on a large, soft image (a rectified one).
        if (line.rms > std::max(1.0, 0.003 * side))
            return Error{ErrorCode::SheetNotFlat, "the sheet's edges are not straight: the sheet is not flat"};
        if (!checkBend)
            continue;
        // A line printed on paper, not the paper's edge: white again just beyond it along most of it.
        const double reach = std::clamp(0.006 * side, 6.0, 30.0);
        const double share =
            lineShare(gray, line, a + 0.1 * (b - a), b - 0.1 * (b - a), reach, std::clamp(side / 100.0, 1.0, 20.0));
        if (share > kMaxLineShare)
            return Error{ErrorCode::NoSheetFound, "a line printed on paper, not the sheet's edge"};
        // How far the edge strays from its line, looked for well beyond the fit's last 5 px.
        EdgeSearch s;
        s.from = a + 0.05 * (b - a);
        s.to = b - 0.05 * (b - a);
        s.outward = (0.5 * (a + b) - centre).normalized();
        s.radiusPx = std::clamp(0.015 * side, 8.0, 60.0);
        s.stepPx = std::clamp(side / 300.0, 1.0, 6.0);
        lines[i].bow = edgeBend(gray, s);
        if (lines[i].bow > std::max(kMaxBendPx, kMaxBendShare * side))
            return Error{ErrorCode::SheetNotFlat, "the sheet's edge bends: the sheet is not flat"};
    }
    return detail::sheetFromEdges(lines, options.sizeMm, gray.size(), options.checkProportions, options.focalPx);
}

} // namespace

Result<Sheet> findSheet(const cv::Mat &photo, const SheetOptions &options)
{
    const cv::Mat gray = toGray(photo);
    if (gray.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty or not an 8-bit gray or colour image"};
    if (!(options.sizeMm.x() > 0) || !(options.sizeMm.y() > 0) ||
        !std::isfinite(options.sizeMm.x() + options.sizeMm.y()))
        return Error{ErrorCode::InvalidArgument, "the sheet's size must be positive"};

    std::optional<Result<Sheet>> found;
    if (options.cornerHints) {
        found = refine(gray, detail::orderCorners(*options.cornerHints), std::max(2.0, options.hintRadiusPx), options,
                       false);
    } else {
        std::vector<detail::SheetCandidate> candidates = detail::sheetCandidates(gray, detail::whiteness(photo));
        if (candidates.empty())
            return Error{ErrorCode::NoSheetFound, "no sheet found in the photo"};
        const auto nearest = [&](const detail::SheetCandidate &q) {
            double d = INFINITY;
            for (const auto &p : q.corners)
                d = std::min(d, (p - *options.cornerHint).norm());
            return d;
        };
        if (options.cornerHint)
            std::stable_sort(candidates.begin(), candidates.end(),
                             [&](const auto &a, const auto &b) { return nearest(a) < nearest(b); });
        // The best candidates in turn, until one has four straight edges and the sheet's proportions.
        // The error said is the best candidate's: what the user most likely meant as the sheet.
        for (std::size_t i = 0; i < std::min<std::size_t>(candidates.size(), kMaxRefined); ++i) {
            const detail::SheetCandidate &c = candidates[i];
            auto sheet = refine(gray, detail::orderCorners(c.corners), 4.0 * c.reductionPx + 4.0, options, true);
            // A shadow or an object over a corner can put the coarse corner tens of pixels off: once more
            // with a search three times as wide.
            if (!sheet && sheet.error().code == ErrorCode::NoSheetFound)
                if (auto wider =
                        refine(gray, detail::orderCorners(c.corners), 12.0 * c.reductionPx + 12.0, options, true))
                    sheet = std::move(wider);
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
