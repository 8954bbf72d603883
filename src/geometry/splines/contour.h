// Seed 004's contour curve (§8.1, the listing of its program): Bézier pieces joined at the midpoints
// of pairs of placed points. After P0 P1 P2 the midpoint M23 of P2 and P3 is inserted as a joint,
// then after every two further points the next midpoint, so the pieces are
//   (P0, P1, P2, M23), (M23, P3, P4, M45), (M45, P5, P6, M67), …
// The listing cuts the joint-and-point list into groups of four and draws the points left over
// (always 2 or 3 of them when there are at least 5 points) as one last piece of lower degree:
// (M, P_{n-2}, P_{n-1}), a quadratic, when n is odd; (M, P_{n-1}), a line, when n is even. With 4
// points or fewer there is no joint: one Bézier curve of degree n - 1 (the listing draws more than 4
// points only; this is what its Bezier2D gives for the others).
// Continuity: a joint M = (P_a + P_b)/2 between two cubics lies halfway between the handles around
// it, so B'(1) = 3 (M - P_a) = 3 (P_b - M) = B'(0) next: C1 on unit parameter intervals. The last
// piece of lower degree leaves M along the same direction, so the joint to it is G1; its derivative is
// 2 (P_{n-2} - M) = 2/3 of the cubic's (a quadratic) or P_{n-1} - M = 1/3 of it (a line), i.e. C1 when
// that piece is given a parameter interval of 2/3 or 1/3.
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"

#include <span>
#include <vector>

namespace kontur::geo {

// The pieces in order. Errors: fewer than 2 points, a point that is not finite.
[[nodiscard]] Result<std::vector<Bezier>> contourPieces(std::span<const Point> points);

// The inserted joints M23, M45, … (empty for 4 points or fewer), in order along the curve.
[[nodiscard]] std::vector<Point> contourJoints(std::span<const Point> points);

} // namespace kontur::geo
