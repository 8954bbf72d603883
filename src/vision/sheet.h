// The reference sheet (a white rectangle of known size) found in a photo: its four corners to
// sub-pixel accuracy, each where two fitted edge lines meet, the homography from the photo to the
// sheet's plane in mm, and the calibration error that the edge fits imply.
//
// Calibration error (docs/vision.md): each edge line has two independent parameters, its angle θ
// about the centroid of its edge points and its offset δ along its normal at that centroid, with
// var θ = σ² / Σ tᵢ² and var δ = σ² / n (σ² = Σ rᵢ² / (n − 2) from the residuals rᵢ, tᵢ the edge
// points' positions along the line; Hartley & Zisserman 2nd ed., 5.2 and A5.1 for the propagation).
// The four corners, the homography H and so the world point X = H(p) of a fixed photo point p are
// functions of these eight parameters; with J = ∂X/∂(θ, δ) (central differences), the covariance of
// X is J diag(var) Jᵀ, and the error reported at X is its RMS radius sqrt(trace) in mm (one sigma).
#pragma once

#include "edgefit.h"
#include "homography.h"
#include "visionresult.h"

#include <opencv2/core.hpp>

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace kontur::vision {

struct SheetOptions
{
    geo::Point sizeMm{210.0, 297.0}; // the sheet's two side lengths; which one is seen along the top edge
                                     // is decided from the photo
    // Four approximate corners in any order (for example placed by a finger): the search starts from
    // them instead of finding the sheet's outline.
    std::optional<std::array<geo::Point, 4>> cornerHints;
    // One point near one corner of the wanted sheet: chooses among bright quadrilaterals.
    std::optional<geo::Point> cornerHint;
    double hintRadiusPx = 40; // how far the true edges may be from the hinted corners' outline
};

struct Sheet
{
    std::array<geo::Point, 4> corners; // TL, TR, BR, BL as seen (photo px, y down)
    std::array<EdgeLine, 4> edges;     // top (TL-TR), right, bottom, left
    geo::Point sizeMm;                 // along TL→TR, along TL→BL
    Homography photoToSheet;           // photo px → sheet mm, TL at (0, 0), x towards TR, y towards BL
    Homography sheetToPhoto;           // its inverse
    int hintedCorner = -1;             // the corner nearest SheetOptions::cornerHint, if given
};

// Paper sizes by name: "a4", "a3", "letter", or "WxH" with an optional unit mm (default), cm or in.
[[nodiscard]] Result<geo::Point> parseSheetSize(std::string_view text);

// Finds the sheet in an 8-bit gray, BGR or BGRA photo.
[[nodiscard]] Result<Sheet> findSheet(const cv::Mat &photo, const SheetOptions &options = {});

// The corner where two straight bright/dark edges meet within `searchRadiusPx` of `approx` (a mark
// dragged near a corner snaps there).
[[nodiscard]] Result<geo::Point> snapCorner(const cv::Mat &photo, const geo::Point &approx, double searchRadiusPx = 15);

// The one-sigma RMS error in mm of the mapping photo → sheet at each world point (mm in the sheet's
// frame); see the header comment. Points beyond the horizon get +infinity.
[[nodiscard]] std::vector<double> calibrationErrorMm(const Sheet &sheet, std::span<const geo::Point> worldMm);

// The largest of calibrationErrorMm over the photo's four corners (the far side of what was photographed).
[[nodiscard]] double calibrationErrorAtPhotoCornersMm(const Sheet &sheet, cv::Size photoSize);

namespace detail {
// The corners TL, TR, BR, BL as seen: clockwise on screen, starting from the one nearest the top left.
[[nodiscard]] std::array<geo::Point, 4> orderCorners(std::array<geo::Point, 4> corners);
// 8-bit single-channel copy (or view) of an 8-bit gray/BGR/BGRA image; empty for other types.
[[nodiscard]] cv::Mat toGray(const cv::Mat &photo);
// The sheet's corners, lines, size assignment and homographies from four fitted edges.
[[nodiscard]] Result<Sheet> sheetFromEdges(const std::array<EdgeLine, 4> &edges, geo::Point sizeMm, cv::Size photo);
} // namespace detail

} // namespace kontur::vision
