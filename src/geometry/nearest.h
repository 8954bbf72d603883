// The point of a Bézier curve nearest to a query point: global over t in [0, 1], for hit testing,
// snapping and fit errors.
#pragma once

#include "geometry/bezier.h"

namespace kontur::geo {

struct Nearest
{
    double t = 0.0;
    Point point = Point::Zero();
    double distance = 0.0;
};

// Every local minimum of |B(t) - q|² inside (0, 1) is a rising root of (B(t) - q)·B'(t), a
// Bernstein polynomial of degree 2n - 1; all of them are found by the root finder of bernstein.h
// (not a Newton step from a guess, which can converge to the wrong branch), and compared with the
// two end points. Ties go to the smaller t. An empty curve answers its only point (or the origin).
// For cubics the roots are looked for only where the curve can be nearer than the best found so far
// (see nearest.cpp); the answer is the same.
[[nodiscard]] Nearest nearest(const Bezier &curve, const Point &query);

namespace detail {
// Every rising root of (B(t) - q)·B'(t) for every degree: the reference the cubic path is tested
// against, and its fallback.
[[nodiscard]] Nearest nearestByRoots(const Bezier &curve, const Point &query);
} // namespace detail

} // namespace kontur::geo
