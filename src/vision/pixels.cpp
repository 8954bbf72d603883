#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>

namespace kontur::vision {

cv::Mat toGray(const cv::Mat &photo)
{
    cv::Mat gray;
    if (photo.empty() || photo.depth() != CV_8U)
        return gray;
    switch (photo.channels()) {
    case 1:
        return photo;
    case 3:
        cv::cvtColor(photo, gray, cv::COLOR_BGR2GRAY);
        return gray;
    case 4:
        cv::cvtColor(photo, gray, cv::COLOR_BGRA2GRAY);
        return gray;
    default:
        return gray;
    }
}

namespace {

template <typename T>
double bilinear(const cv::Mat &image, double x, double y)
{
    x = std::clamp(x, 0.0, image.cols - 1.0);
    y = std::clamp(y, 0.0, image.rows - 1.0);
    const int x0 = std::min(static_cast<int>(x), std::max(0, image.cols - 2));
    const int y0 = std::min(static_cast<int>(y), std::max(0, image.rows - 2));
    const int x1 = std::min(x0 + 1, image.cols - 1), y1 = std::min(y0 + 1, image.rows - 1);
    const double fx = x - x0, fy = y - y0;
    const T *r0 = image.ptr<T>(y0);
    const T *r1 = image.ptr<T>(y1);
    const double top = r0[x0] + fx * (static_cast<double>(r0[x1]) - r0[x0]);
    const double bottom = r1[x0] + fx * (static_cast<double>(r1[x1]) - r1[x0]);
    return top + fy * (bottom - top);
}

} // namespace

double sampleBilinear(const cv::Mat &image, double x, double y)
{
    if (image.empty() || image.channels() != 1)
        return 0.0;
    switch (image.depth()) {
    case CV_8U:
        return bilinear<std::uint8_t>(image, x, y);
    case CV_32F:
        return bilinear<float>(image, x, y);
    default:
        return 0.0;
    }
}

} // namespace kontur::vision
