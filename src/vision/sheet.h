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
    // Refuse a rectangle of other proportions than sizeMm's (WrongProportions); off where the caller
    // already knows which rectangle is meant and only wants its edges.
    bool checkProportions = true;
    // The camera's focal length in the photo's pixels when known (from the photo's EXIF: picture/exif.h),
    // else 0. A sheet seen without yaw (one pair of its sides parallel in the photo) does not tell the
    // focal length, and without it its proportions span a wide range (a Letter sheet would pass for
    // A4); a known focal length narrows them. Ignored where the sheet's own corners contradict it (a
    // cropped photo).
    double focalPx = 0;
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

// Finds the sheet in an 8-bit gray, BGR or BGRA photo (colour helps: a white sheet on a light, coloured
// table). Errors: NoSheetFound; SheetNotFlat when the best candidate's edges are not straight;
// WrongProportions when the best candidate is a rectangle of other proportions than the sheet's (the
// proportions seen in Error::seenAspect), which also refuses four hinted corners of such a rectangle.
[[nodiscard]] Result<Sheet> findSheet(const cv::Mat &photo, const SheetOptions &options = {});

// The proportions (long side over short side, >= 1) of the rectangle whose image is the quadrilateral
// `corners` (in order round it), seen by a pinhole camera with square pixels, the principal point at the
// photo's centre and the focal length (0.25–6 × the photo's diagonal) that makes its angles most nearly
// right; `skew` is the cosine of its angle that remains (0 for a true rectangle's image). Where other
// focal lengths make the angles right within kSkewSlack too (a sheet seen nearly square on tells its
// camera poorly), their proportions span [aspectLow, aspectHigh]. With a known focal length
// (`knownFocalPx` > 0), only focal lengths within kFocalSlack of it count, unless none of them makes the
// angles as right as the best one does (within kSkewSlack): then the known one is wrong (a cropped
// photo) and is not used (`focalUsed` false).
struct SeenRectangle
{
    double aspect = 0;
    double focalPx = 0;
    double skew = 0;
    double aspectLow = 0, aspectHigh = 0;
    bool focalUsed = false;
};
inline constexpr double kSkewSlack = 0.003;
// A phone's 35 mm equivalent focal length is rounded to a whole mm (26–28 mm for a main camera: ±2 %),
// makers take it from the sensor's diagonal or its width (4 % apart on a 4:3 sensor), and focusing
// near changes it by a few per cent: ±6 %.
inline constexpr double kFocalSlack = 1.06;
[[nodiscard]] SeenRectangle seenRectangle(const std::array<geo::Point, 4> &corners, cv::Size photo,
                                          double knownFocalPx = 0);

// A quadrilateral is taken for the chosen sheet when the sheet's proportions lie within 5 % (|ln|) of
// [aspectLow, aspectHigh] and no plausible camera leaves more skew than kMaxRectangleSkew (3°): A4 and
// Letter (9 % apart) are told apart, a dollar bill (2.35 : 1) is not A4 (1.41 : 1). 5 %, not less: a
// real A4 photo of the benchmark (phminh151/6, resized by an app) reads 1.35 : 1 at its labelled corners.
inline constexpr double kMaxProportionMismatch = 0.05;
inline constexpr double kMaxRectangleSkew = 0.05;

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
// The sheet's corners, lines, size assignment and homographies from four fitted edges; with
// `checkProportions`, WrongProportions when no assignment of the sheet's sides fits a plausible camera
// within kMaxProportionMismatch.
[[nodiscard]] Result<Sheet> sheetFromEdges(const std::array<EdgeLine, 4> &edges, geo::Point sizeMm, cv::Size photo,
                                           bool checkProportions = true, double knownFocalPx = 0);
// min(B, G, R) of an 8-bit colour photo (white paper stays bright, wood, tiles and cloth do not); empty
// for a grey one.
[[nodiscard]] cv::Mat whiteness(const cv::Mat &photo);
// A coarse quadrilateral that may be the sheet (sheetsearch.cpp), in full-resolution px.
struct SheetCandidate
{
    std::array<geo::Point, 4> corners;
    double support = 0;     // the share of its sides that are bright-to-dark edges (0..1)
    double score = 0;       // area × support, in reduced px²: higher first
    double reductionPx = 1; // full-resolution px per px of the copy it was found in
};
// Candidates from the grey photo and its whiteness (may be empty), best first.
[[nodiscard]] std::vector<SheetCandidate> sheetCandidates(const cv::Mat &gray, const cv::Mat &white);
} // namespace detail

} // namespace kontur::vision
