// The projective map of the plane (a homography): how a photo's pixels lie in the world when the
// photo was taken at an angle, and the affine placement as its special case. One value type so that
// the canvas, the painters and the tracing tools map the picture the same way.
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"

#include <Eigen/Core>

#include <array>

namespace kontur::geo {

using Quad = std::array<Point, 4>;

// x ↦ (H·(x, y, 1))ₓᵧ / (H·(x, y, 1))_w for a non-singular 3×3 matrix H, kept up to scale with
// H(2,2) = 1 where that is possible (so an affine map has the last row (0, 0, 1) exactly).
class Projective2D final
{
public:
    // The identity.
    Projective2D() = default;

    // Any non-singular matrix (not checked: use fromMatrix for input from outside).
    [[nodiscard]] static Result<Projective2D> fromMatrix(const Eigen::Matrix3d &m);
    // p ↦ linear·p + translation.
    [[nodiscard]] static Projective2D fromAffine(const Eigen::Matrix2d &linear, const Point &translation);
    // The map that takes from[i] to to[i] for the four pairs: the direct linear transform with
    // Hartley's normalisation (Hartley & Zisserman, "Multiple View Geometry", 2nd ed., algorithm 4.2:
    // each set moved to its centroid and scaled to mean distance √2, the 8×9 system's null vector by
    // SVD, then the normalisations undone). Fails with IllConditioned when three points of either set
    // lie on a line (or two coincide), and NonFiniteInput for NaN or infinite coordinates.
    [[nodiscard]] static Result<Projective2D> fromPointPairs(const Quad &from, const Quad &to);

    [[nodiscard]] const Eigen::Matrix3d &matrix() const { return m_h; }
    // The homogeneous denominator w at p: it vanishes on the line that goes to infinity (the picture
    // of the horizon), and has one sign on the side that is drawn.
    [[nodiscard]] double denominator(const Point &p) const;
    // The image of p; not finite where denominator(p) is 0.
    [[nodiscard]] Point map(const Point &p) const;
    // The derivative of map at p (columns: ∂/∂x, ∂/∂y); for an affine map the linear part everywhere.
    [[nodiscard]] Eigen::Matrix2d jacobian(const Point &p) const;
    [[nodiscard]] bool isAffine() const { return m_h(2, 0) == 0.0 && m_h(2, 1) == 0.0; }

    // The inverse map (H⁻¹ by the adjugate, which is exact for the affine case's last row).
    [[nodiscard]] Result<Projective2D> inverse() const;
    // First this map, then `next`: p ↦ next.map(this->map(p)).
    [[nodiscard]] Projective2D then(const Projective2D &next) const;

private:
    explicit Projective2D(const Eigen::Matrix3d &m);

    Eigen::Matrix3d m_h = Eigen::Matrix3d::Identity();
};

} // namespace kontur::geo
