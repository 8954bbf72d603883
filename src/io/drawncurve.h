// DrawnCurve: a curve as the vector exports (SVG, DXF) write it, and the one rule of which curves an
// export writes, shared by the app's File menu and kontur-cli.
#pragma once

#include "geometry/piecewise.h"

#include <QString>

namespace kontur::io {

struct DrawnCurve
{
    QString name;               // SVG: the path's <title>; DXF: the entities' layer and the writer's messages
    QString color;              // "#rrggbb": the stroke; black in SVG, no true colour in DXF when empty or invalid
    geo::PiecewiseBezier curve; // closed curves end where they start
};

} // namespace kontur::io
