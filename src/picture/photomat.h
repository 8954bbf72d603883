// A picture as the image library works on it: a QImage copied into an OpenCV matrix that owns its
// pixels (QImage's rows are 4-byte aligned), in grey or in colour (BGR, OpenCV's order). The one place
// these conversions are written, for the app's tools and kontur-cli.
#pragma once

#include <QImage>

#include <opencv2/core.hpp>

namespace kontur {

// 8-bit single-channel: the picture's grey levels. Empty for a null image.
[[nodiscard]] cv::Mat grayMat(const QImage &image);
// 8-bit three-channel BGR (alpha dropped). Empty for a null image.
[[nodiscard]] cv::Mat bgrMat(const QImage &image);

} // namespace kontur
