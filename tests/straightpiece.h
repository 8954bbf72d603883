// Pattern pieces with straight sides for the tests of pieces, marks and seams: a closed composite curve
// through its corners, each side a cubic with its handles at thirds (a straight line), every knot a
// corner. Seam k is the side from corner k to the next one.
#pragma once

#include "geometry/composite.h"
#include "models/document/curve.h"

#include <optional>
#include <vector>

namespace kontur::test {

// The closed outline through `corners` (the first not repeated at the end), named `name`; nullopt when
// they make no curve (fewer than two, or two in a row at the same place).
inline std::optional<Curve> straightOutline(const std::vector<geo::Point> &corners, const QString &name)
{
    if (corners.size() < 2)
        return std::nullopt;
    std::vector<geo::Point> control{corners.front()};
    for (std::size_t k = 1; k <= corners.size(); ++k) {
        const geo::Point a = control.back();
        const geo::Point b = corners[k % corners.size()];
        control.insert(control.end(), {(2.0 * a + b) / 3.0, (a + 2.0 * b) / 3.0, b});
    }
    auto made = geo::CompositeCurve::fromParts(control,
                                               std::vector<geo::NodeType>(corners.size(), geo::NodeType::Corner), true);
    if (!made)
        return std::nullopt;
    made->finish();
    geo::Result<Curve> outline = Curve::makeComposite(std::move(*made));
    if (!outline)
        return std::nullopt;
    outline->name = name;
    return std::move(*outline);
}

// A 200 × 300 mm rectangle, counter-clockwise from the origin: seam 0 the bottom (the hem), 1 the
// right side, 2 the top, 3 the left side.
inline std::optional<Curve> rectangleOutline(const QString &name)
{
    return straightOutline({geo::Point(0, 0), geo::Point(200, 0), geo::Point(200, 300), geo::Point(0, 300)}, name);
}

} // namespace kontur::test
