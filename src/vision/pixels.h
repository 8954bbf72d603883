// Reading a photo's pixels: its 8-bit gray, and the intensity between pixel centres. One sampler for
// the sheet finder (8-bit gray) and the outline tracer (its smoothed float field).
#pragma once

#include <opencv2/core/mat.hpp>

namespace kontur::vision {

// 8-bit single-channel copy (or view) of an 8-bit gray, BGR or BGRA image; empty for other types.
[[nodiscard]] cv::Mat toGray(const cv::Mat &photo);

// Bilinear intensity of a single-channel 8-bit or 32-bit float image at (x, y), pixel centres at
// integers (OpenCV's convention), the point clamped to the image; 0 for an empty image or another type.
[[nodiscard]] double sampleBilinear(const cv::Mat &image, double x, double y);

} // namespace kontur::vision
