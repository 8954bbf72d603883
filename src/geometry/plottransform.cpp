// World ↔ plot transform (seed 001 §3.2.1).
#include "geometry/plottransform.h"

#include <cmath>

namespace kontur::geo {

PlotTransform::PlotTransform(const Box &world, double plotWidth, double plotHeight)
{
    const Point size = world.sizes();
    const bool valid = !world.isEmpty() && size.x() > 0.0 && size.y() > 0.0 && std::isfinite(size.x())
                       && std::isfinite(size.y()) && plotWidth > 0.0 && plotHeight > 0.0 && std::isfinite(plotWidth)
                       && std::isfinite(plotHeight);
    if (!valid)
        return;
    m_min = world.min();
    m_maxY = world.max().y();
    m_sx = plotWidth / size.x();
    m_sy = plotHeight / size.y();
}

Point PlotTransform::toPlot(const Point &world) const
{
    // x grows to the right in both; y is flipped about the world's top edge.
    return {(world.x() - m_min.x()) * m_sx, (m_maxY - world.y()) * m_sy};
}

Point PlotTransform::toWorld(const Point &plot) const
{
    return {m_min.x() + plot.x() / m_sx, m_maxY - plot.y() / m_sy};
}

} // namespace kontur::geo
