// The homography of four point pairs: geo::Projective2D's, refused here for (nearly) collinear points.
#include "homography.h"

#include "geometry/projective.h"

#include <Eigen/Dense>

#include <cmath>

namespace kontur::vision {
namespace {

bool nearlyCollinear(const std::array<geo::Point, 4> &p)
{
    double scale = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            scale = std::max(scale, (p[i] - p[j]).norm());
    if (!(scale > 0) || !std::isfinite(scale))
        return true;
    for (int i = 0; i < 4; ++i) {
        const geo::Point a = p[(i + 1) % 4] - p[i], b = p[(i + 2) % 4] - p[i];
        if (std::abs(a.x() * b.y() - a.y() * b.x()) < 1e-9 * scale * scale)
            return true;
    }
    return false;
}

} // namespace

std::optional<Homography> homographyFrom4(const std::array<geo::Point, 4> &from, const std::array<geo::Point, 4> &to)
{
    if (nearlyCollinear(from) || nearlyCollinear(to))
        return std::nullopt;
    // The one homography of the project (geo::Projective2D: the normalised DLT), as a matrix.
    const auto h = geo::Projective2D::fromPointPairs(from, to);
    if (!h)
        return std::nullopt;
    Homography out = h->matrix();
    if (std::abs(out(2, 2)) > 1e-300)
        out /= out(2, 2);
    if (!out.allFinite())
        return std::nullopt;
    return out;
}

} // namespace kontur::vision
