// The scene builder: a pure function from the document's curves, the view and the style to the
// canvas's screen-space display lists (grid, guide lines, point markers, the placement preview;
// on the software backend also the selected curve). No window, no scene graph: the canvas hands
// the lists to its nodes, and tests read them directly.
#pragma once

#include "app/displaylist.h"
#include "app/viewstate.h"
#include "geometry/curveshape.h"

#include <QColor>

#include <optional>
#include <vector>

namespace kontur {

class Curve;

// Colours and sizes, set from the QML Theme through the canvas's properties.
struct SceneStyle
{
    QColor curve{0, 0, 0};
    QColor polygon{200, 200, 200};
    QColor controlPoint{220, 0, 0};
    QColor accent{33, 118, 210};
    QColor tangent{90, 100, 112};
    QColor grid{236, 239, 243};
    QColor axis{160, 168, 178};
    bool showGrid = true;
    double curveWidth = 2.0;
    double pointRadius = 4.5;
};

// What the scene shows besides the curves: the selection and the curve being placed.
struct SceneInput
{
    const std::vector<Curve> *curves = nullptr; // null: only the grid
    ViewState view;
    int selectedCurve = -1;
    int selectedPoint = -1;
    // Software backend: the selected curve is drawn with the lists (halo and line), from this
    // world flattening; null when it is out of sight. GPU backends draw it in a stroke node.
    bool software = false;
    const std::vector<geo::Point> *selectedFlat = nullptr;
    // The curve being placed: its points so far, the segments of its preview, its kind, and the
    // pointer the rubber band goes to, if any.
    const std::vector<geo::Point> *pendingPoints = nullptr;
    std::vector<geo::Bezier> pendingSegments;
    geo::CurveKind placementKind = geo::CurveKind::Bezier;
    std::optional<geo::Point> hover;
};

// The screen-space parts of the picture: grid (under everything), guides (control polygons,
// under the curves) and top (placement preview, point markers). With `software`, `live` gets
// the selected curve's halo, then the guides instead of `guides`, then the selected curve's line
// (the cached layer has every other curve).
struct ScreenLists
{
    DisplayList grid, guides, top, live;
};

// Point markers of every curve while the visible curves have at most this many rows together;
// above it only those of the selected curve, which keeps big drawings fast and readable.
inline constexpr std::size_t kAllPointsLimit = 4000;

// Replaces the lists' content with the scene (the lists keep their memory between frames).
void buildScene(const SceneInput &input, const SceneStyle &style, ScreenLists &lists);

// The world distance between grid lines at `zoom`: the smallest of 1, 2, 5 × 10^k world units
// that is at least 40 px on screen.
[[nodiscard]] double gridStepAt(double zoom);
// The grid lines and the axes across the view.
void addGrid(DisplayList &list, const ViewState &view, const QColor &gridColor, const QColor &axisColor);

} // namespace kontur
