// SVG path data (the "d" attribute, SVG 1.1 §8.3 / SVG 2 §9.3): M L H V C S Q T A Z, absolute and
// relative, implicit repeated commands, the compact number syntax ("1e-3", ".5.5", "-1-2", arc flags
// without separators). Lines stay degree 1 and quadratics degree 2 (exact); elliptical arcs become
// cubics within a stated tolerance. Each subpath is one PiecewiseBezier, closed after Z.
#pragma once

#include "geometry/piecewise.h"
#include "io/error.h"

#include <string_view>
#include <vector>

namespace kontur::io {

struct SvgPathOptions
{
    // Largest distance between an arc and its cubic approximation, in the path's user units
    // (before any transform). The bound used is Goldapp's: for an arc of radius r and angle θ per
    // cubic, r · (4/27) sin⁶(θ/4) / cos²(θ/4), taken with the larger radius of the ellipse.
    double arcTolerance = 1e-6;
    // Most segments in one path's data (a guard against hostile files).
    qint64 maxSegments = 2'000'000;
};

// The subpaths of `d`, in the path's own coordinates (no transform, SVG's y axis pointing down).
// Subpaths that draw nothing (a lone M) are left out. Errors are PathSyntax (or TooManyPoints) with
// `column` = the character in `d`, 1-based, where the problem is.
[[nodiscard]] Result<std::vector<geo::PiecewiseBezier>> parseSvgPathData(std::string_view d,
                                                                         const SvgPathOptions &options = {});

// The cubics approximating the arc of the ellipse (center, radii, x-axis rotation phi in radians) from
// angle theta1 over dtheta (radians, signed), within `tolerance` (see SvgPathOptions::arcTolerance).
[[nodiscard]] std::vector<geo::Bezier> arcToCubics(const geo::Point &center, double rx, double ry, double phi,
                                                   double theta1, double dtheta, double tolerance);

} // namespace kontur::io
