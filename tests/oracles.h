// Comparing computed points with oracles written out to 17 digits, shared by the model and the window
// tests: equal to a relative 1e-9 (of the larger coordinate magnitude, at least 1), and the points
// as text for a failure message.
#pragma once

#include "geometry/bezier.h"

#include <QByteArray>

#include <algorithm>
#include <array>
#include <cmath>

namespace kontur::test {

inline bool near(const geo::Point &actual, const geo::Point &expected)
{
    const double scale = std::max({1.0, std::abs(expected.x()), std::abs(expected.y())});
    return (actual - expected).norm() <= 1e-9 * scale;
}

inline bool near(const std::array<geo::Point, 4> &actual, const std::array<geo::Point, 4> &expected)
{
    return std::equal(actual.begin(), actual.end(), expected.begin(),
                      [](const geo::Point &a, const geo::Point &e) { return near(a, e); });
}

inline QByteArray text(const std::array<geo::Point, 4> &control)
{
    QByteArray out;
    for (const geo::Point &c : control)
        out += QByteArray::number(c.x(), 'g', 17) + ' ' + QByteArray::number(c.y(), 'g', 17) + "; ";
    return out;
}

} // namespace kontur::test
