// The photo warped into the sheet's plane at a known scale: what the outline tracer works on.
#pragma once

#include "homography.h"
#include "visionresult.h"

#include <opencv2/core.hpp>

#include <Eigen/Core>

namespace kontur::vision {

struct RectifyRequest
{
    Homography sheetToPhoto;                    // sheet mm → photo px (Sheet::sheetToPhoto)
    double pxPerMm = 10;                        // the rectified image's scale
    geo::Point worldMinMm = geo::Point::Zero(); // the world rectangle to cover, in sheet mm
    geo::Point worldMaxMm{210, 297};
};

struct Rectified
{
    cv::Mat image;                         // same type as the photo
    Eigen::Matrix<double, 2, 3> pixelToMm; // rectified pixel centre (x, y, 1) → sheet mm (exact, affine)
    Homography rectifiedToPhoto;           // rectified px → photo px
};

// Each rectified pixel (i, j) is the photo sampled (bilinear) at sheetToPhoto(pixelToMm · (i, j, 1)).
// Fails on a non-positive scale, an empty rectangle or one wider than 20000 px.
[[nodiscard]] Result<Rectified> rectify(const cv::Mat &photo, const RectifyRequest &request);

// The affine map of rectified pixel centres to mm: x_mm = min.x + (i + 0.5) / pxPerMm, likewise y.
[[nodiscard]] Eigen::Matrix<double, 2, 3> rectifiedPixelToMm(const RectifyRequest &request);

} // namespace kontur::vision
