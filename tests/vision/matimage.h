// A synthetic photo (8-bit grey or BGR cv::Mat) as a QImage, to be saved as a picture file for the
// tests that read photos the way the app and kontur-cli do. Header-only: Qt Gui where it is included.
#pragma once

#include <QImage>

#include <opencv2/core.hpp>

#include <cstring>

namespace kontur::vision::test {

[[nodiscard]] inline QImage qImageOf(const cv::Mat &photo)
{
    const bool grey = photo.channels() == 1;
    QImage image(photo.cols, photo.rows, grey ? QImage::Format_Grayscale8 : QImage::Format_BGR888);
    for (int y = 0; y < photo.rows; ++y)
        std::memcpy(image.scanLine(y), photo.ptr(y), static_cast<std::size_t>(photo.cols) * (grey ? 1 : 3));
    return image;
}

} // namespace kontur::vision::test
