// The plane-to-plane projective map from four point pairs as the matrix the sheet finder and rectify
// work with, and applying it to points. The map itself is geo::Projective2D's (src/geometry/projective.h:
// Hartley & Zisserman's normalised direct linear transform), the project's one homography.
#pragma once

#include "geometry/bezier.h"

#include <Eigen/Core>

#include <array>
#include <optional>

namespace kontur::vision {

using Homography = Eigen::Matrix3d;

// H with H·from[i] ~ to[i] (homogeneous), normalised so that H(2,2) = 1 when that is possible.
// Empty when three of either set of points are (nearly) collinear.
[[nodiscard]] std::optional<Homography> homographyFrom4(const std::array<geo::Point, 4> &from,
                                                        const std::array<geo::Point, 4> &to);

// H applied to p (divides by the third coordinate; the caller keeps points in front of the camera).
[[nodiscard]] inline geo::Point apply(const Homography &h, const geo::Point &p)
{
    const Eigen::Vector3d q = h * Eigen::Vector3d(p.x(), p.y(), 1.0);
    return q.head<2>() / q.z();
}

// The sign of the third homogeneous coordinate of H·p: points whose sign differs from the sheet's
// lie beyond the horizon.
[[nodiscard]] inline double homogeneousW(const Homography &h, const geo::Point &p)
{
    return (h * Eigen::Vector3d(p.x(), p.y(), 1.0)).z();
}

} // namespace kontur::vision
