// A long wavy closed piece for the seam allowance tests: `knots` composite knots in millimetres on a
// circle of radius 200 with waves of 30 and 10 (7 and 23 round it). Its inside allowance at 40 mm
// crosses itself often: trimming those loops takes about a second per 6,000 knots on a 2020s laptop
// core, seconds at 20,000.
#pragma once

#include "models/document/curve.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace kontur::test {

inline Curve wavyPiece(int knots)
{
    std::vector<geo::Point> p;
    for (int i = 0; i < knots; ++i) {
        const double t = 2 * std::numbers::pi * i / knots;
        const double r = 200 + 30 * std::sin(7 * t) + 10 * std::sin(23 * t);
        p.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    Curve c = Curve::make(CurveKind::Composite, std::move(p));
    (void)c.close();
    c.name = QStringLiteral("Wave");
    return c;
}

} // namespace kontur::test
