// Seed 004's contour curve (see contour.h).
#include "geometry/splines/contour.h"

namespace kontur::geo {

std::vector<Point> contourJoints(std::span<const Point> points)
{
    std::vector<Point> joints;
    const std::size_t n = points.size();
    if (n <= 4)
        return joints;
    // The listing's counter reaches 4 at P3, P5, P7, …: a joint before each of them.
    for (std::size_t j = 3; j < n; j += 2)
        joints.push_back((points[j - 1] + points[j]) / 2.0);
    return joints;
}

Result<std::vector<Bezier>> contourPieces(std::span<const Point> points)
{
    const std::size_t n = points.size();
    if (n < 2)
        return Error{ErrorCode::TooFewPoints, "a contour curve needs at least 2 points"};
    for (std::size_t i = 0; i < n; ++i)
        if (!points[i].allFinite())
            return Error{ErrorCode::NonFiniteInput, "a point is not finite", static_cast<int>(i)};
    if (n <= 4)
        return std::vector<Bezier>{Bezier(std::vector<Point>(points.begin(), points.end()))};

    // The listing's list: P0 P1 P2 M23 | M23 P3 P4 M45 | M45 P5 P6 M67 | … then the rest.
    std::vector<Bezier> pieces;
    std::vector<Point> piece{points[0], points[1], points[2]};
    std::size_t next = 3;
    while (next < n) {
        const Point joint = (points[next - 1] + points[next]) / 2.0;
        piece.push_back(joint);
        pieces.emplace_back(std::move(piece));
        piece = {joint, points[next]};
        if (next + 1 < n)
            piece.push_back(points[next + 1]);
        next += 2;
    }
    pieces.emplace_back(std::move(piece)); // 2 or 3 points: a line or a quadratic
    return pieces;
}

} // namespace kontur::geo
