// The affine map from a rectified photo's pixels to millimetres in the sheet's plane. Pixel
// coordinates follow OpenCV: (u, v) = (column, row), the centre of pixel (u, v) is at (u, v), v grows
// downwards. The output frame is whatever the map makes it: a map with y up (negative determinant)
// gives outlines in a y-up world, one with y down keeps the image's orientation.
#pragma once

#include "geometry/bezier.h"

#include <Eigen/Dense>

#include <cmath>

namespace kontur::vision {

struct PixelMapping
{
    // mm = linear · (u, v) + offset.
    Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
    geo::Point offset = geo::Point::Zero();

    // A uniform scale: pixel (0, 0) lands on `originMm`; yUp flips v so that the world's y grows
    // upwards (the app's convention).
    [[nodiscard]] static PixelMapping uniform(double mmPerPixel, const geo::Point &originMm, bool yUp = false)
    {
        PixelMapping m;
        m.linear << mmPerPixel, 0.0, 0.0, yUp ? -mmPerPixel : mmPerPixel;
        m.offset = originMm;
        return m;
    }

    [[nodiscard]] geo::Point toMm(const geo::Point &px) const { return linear * px + offset; }
    [[nodiscard]] geo::Point toPixel(const geo::Point &mm) const { return linear.inverse() * (mm - offset); }
    // The mean scale, sqrt |det|: millimetres per pixel for lengths (exact for a similarity).
    [[nodiscard]] double mmPerPixel() const { return std::sqrt(std::abs(linear.determinant())); }
    // A usable map is finite and invertible.
    [[nodiscard]] bool valid() const
    {
        return linear.allFinite() && offset.allFinite() && std::abs(linear.determinant()) > 1e-300;
    }
};

} // namespace kontur::vision
