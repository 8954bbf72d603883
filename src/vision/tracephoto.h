// A photo traced into a plane: the picture warped into world coordinates around a region of interest
// (rectifyWorld, shared by the app's tools and the command line), and the whole path of
// `kontur-cli trace` (tracePhoto): the sheet found, the photo rectified at a known scale, every pattern
// piece outlined in millimetres. See docs/vision.md, "From a photo to outlines".
#pragma once

#include "vision/homography.h"
#include "vision/outline.h"
#include "vision/pixelmapping.h"
#include "vision/sheet.h"
#include "vision/visionresult.h"

#include <opencv2/core.hpp>

#include <vector>

namespace kontur::vision {

// A part of the world as a picture: the photo resampled so that its pixels are square in the world.
struct WorldPatch
{
    cv::Mat image;        // same type as the photo
    PixelMapping mapping; // patch px → world
    double pxPerUnit = 0; // the scale used (may be below the one asked for, see rectifyWorld)
};

// The world box [worldMin, worldMax] sampled from the photo through `worldToPhoto` (a homography,
// world → photo px): bilinear, the photo's border repeated outside it. The scale is `pxPerUnit`, or
// less where the box would exceed `maxSidePx` on a side. `yUp`: the world's y grows upwards (the
// app's convention), so the patch's first row is the box's top. Fails on an empty box or scale.
[[nodiscard]] Result<WorldPatch> rectifyWorld(const cv::Mat &photo, const Homography &worldToPhoto,
                                              const geo::Point &worldMin, const geo::Point &worldMax, double pxPerUnit,
                                              bool yUp, int maxSidePx = 4000);

// The bounding box of the photo's visible part in the world (its border mapped through
// `photoToWorld`, the points beyond the horizon left out), limited to `limit`. Empty when nothing of
// the photo lies in front of the camera.
[[nodiscard]] std::optional<geo::Box> photoExtentInWorld(cv::Size photo, const Homography &photoToWorld,
                                                         const geo::Box &limit);

struct PhotoTraceOptions
{
    SheetOptions sheet;     // its size and optional corner hints
    double pxPerMm = 8;     // each piece's rectified scale (less when it would exceed maxSidePx)
    int maxSidePx = 4000;   // a rectified piece's longest side
    double reachMm = 1500;  // how far beyond the sheet the photo is looked at
    OutlineOptions outline; // ignoreRect is set to the sheet
};

struct PhotoTrace
{
    Sheet sheet;
    double calibrationErrorMm = 0; // at the photo's far corners (calibrationErrorAtPhotoCornersMm)
    std::vector<Outline> outlines; // in mm, the sheet's top-left at (0, 0), x along its top, y up
    double pxPerMm = 0;            // the scale the (last) piece was traced at
    cv::Size rectified;            // the (last) piece's rectified image's size
};

// The sheet found (or refined from the hints), the photo rectified into the sheet's plane (at most
// 1500 px a side) and the pieces other than the sheet found in it, then each piece rectified alone at
// pxPerMm and outlined. Errors: no sheet (NoSheetFound), no piece (NoPieceFound).
[[nodiscard]] Result<PhotoTrace> tracePhoto(const cv::Mat &photo, const PhotoTraceOptions &options = {});

// The same after the sheet was found (by findSheet with options.sheet): a caller that wants to report
// the sheet even when no piece is found (NoPieceFound) finds it first.
[[nodiscard]] Result<PhotoTrace> tracePieces(const cv::Mat &photo, const Sheet &sheet,
                                             const PhotoTraceOptions &options = {});

} // namespace kontur::vision
