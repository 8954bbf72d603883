// The background picture's placement: the one picture → world mapping, by the perspective
// calibration's homography or by origin, scale and rotation. A value type: nothing is kept between
// calls (the four-point solve is an SVD, about 30 µs: bench_models background-map; a caller that maps
// many points takes the map once with imageToWorld() and maps through it).
#include "models/document/document.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace kontur {

std::optional<geo::Projective2D> Background::homography(const std::array<QPointF, 4> &ordered, double width,
                                                        double height, QPointF topLeft)
{
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height))
        return std::nullopt;
    const geo::Point tl(topLeft.x(), topLeft.y());
    const geo::Quad to{tl, tl + geo::Point(width, 0.0), tl + geo::Point(width, -height), tl + geo::Point(0.0, -height)};
    geo::Quad from;
    for (std::size_t i = 0; i < 4; ++i)
        from[i] = geo::Point(ordered[i].x(), ordered[i].y());
    const auto t = geo::Projective2D::fromPointPairs(from, to);
    if (!t)
        return std::nullopt;
    for (const geo::Point &p : from)
        if (!(std::abs(t->denominator(p)) > 0.0))
            return std::nullopt;
    return *t;
}

std::optional<geo::Projective2D> Background::perspectiveMap() const
{
    if (!perspective)
        return std::nullopt;
    return homography(corners, rectWidth, rectHeight, rectOrigin);
}

bool Background::placedInPerspective() const
{
    return perspectiveMap().has_value();
}

geo::Projective2D Background::imageToWorld() const
{
    if (const auto map = perspectiveMap())
        return *map;
    // The picture's x runs right and its y down from its top-left corner at `origin`; the world's y
    // runs up; the picture is turned by `rotation` (counter-clockwise) about its origin.
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(rotation * std::numbers::pi / 180.0).toRotationMatrix();
    const Eigen::Matrix2d flip = Eigen::Vector2d(1.0, -1.0).asDiagonal();
    return geo::Projective2D::fromAffine(scale * turn * flip, geo::Point(origin.x(), origin.y()));
}

geo::Projective2D Background::worldToImage() const
{
    if (const auto inverse = imageToWorld().inverse())
        return *inverse;
    // A zero scale (never stored by the controllers) maps as scale 1 backwards, as before.
    Background unit = *this;
    unit.perspective = false;
    unit.scale = 1.0;
    return *unit.imageToWorld().inverse();
}

QPointF Background::toImage(const geo::Point &world) const
{
    const geo::Point p = worldToImage().map(world);
    return {p.x(), p.y()};
}

} // namespace kontur
