// The world ↔ plot transform of seed 001 §3.2.1 (docs/requirements.md 2): the world rectangle with y up is mapped
// onto a plot area whose origin is its top-left corner with y down. The teaching views draw function
// splines through it; the canvas uses the uniform special case (one zoom for both axes).
#pragma once

#include "geometry/bezier.h"

namespace kontur::geo {

class PlotTransform final
{
public:
    // `world` must have positive width and height and the plot a positive size; otherwise the
    // transform is the identity of a 1×1 square (never a division by zero).
    PlotTransform(const Box &world, double plotWidth, double plotHeight);

    [[nodiscard]] Point toPlot(const Point &world) const;
    [[nodiscard]] Point toWorld(const Point &plot) const;
    [[nodiscard]] double scaleX() const { return m_sx; }
    [[nodiscard]] double scaleY() const { return m_sy; }

private:
    Point m_min = Point::Zero();
    double m_maxY = 1.0;
    double m_sx = 1.0;
    double m_sy = 1.0;
};

} // namespace kontur::geo
