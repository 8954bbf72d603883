// QImage → cv::Mat; see photomat.h.
#include "picture/photomat.h"

#include <cstring>

namespace kontur {

namespace {

cv::Mat copyRows(const QImage &image, int type, int bytesPerPixel)
{
    cv::Mat out(image.height(), image.width(), type);
    for (int y = 0; y < image.height(); ++y)
        std::memcpy(out.ptr(y), image.constScanLine(y), static_cast<std::size_t>(image.width()) * bytesPerPixel);
    return out;
}

} // namespace

cv::Mat grayMat(const QImage &image)
{
    if (image.isNull())
        return {};
    return copyRows(image.convertToFormat(QImage::Format_Grayscale8), CV_8UC1, 1);
}

cv::Mat bgrMat(const QImage &image)
{
    if (image.isNull())
        return {};
    // Format_BGR888 stores blue, green, red in that order: OpenCV's layout.
    return copyRows(image.convertToFormat(QImage::Format_BGR888), CV_8UC3, 3);
}

} // namespace kontur
