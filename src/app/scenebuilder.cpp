// The scene builder: the canvas's display lists from the curves, the view and the style.
#include "app/scenebuilder.h"

#include "models/document/curve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>

namespace kontur {
namespace {

// The part of the segment a–b inside `area` (Liang & Barsky 1984), or nothing. A rubber band from a
// point zoomed far out of view can be 10^12 px long: dashed whole, it made that many dashes and froze
// the window (the random-input run found it); only what can be seen is dashed.
std::optional<std::pair<QPointF, QPointF>> clipped(QPointF a, QPointF b, const QRectF &area)
{
    const QPointF d = b - a;
    double t0 = 0.0, t1 = 1.0;
    const auto edge = [&](double p, double q) { // p t <= q
        if (p == 0.0)
            return q >= 0.0;
        const double t = q / p;
        if (p < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        return t0 <= t1;
    };
    if (!std::isfinite(d.x()) || !std::isfinite(d.y()) || !edge(-d.x(), a.x() - area.left()) ||
        !edge(d.x(), area.right() - a.x()) || !edge(-d.y(), a.y() - area.top()) || !edge(d.y(), area.bottom() - a.y()))
        return std::nullopt;
    return std::pair{a + t0 * d, a + t1 * d};
}

} // namespace

double gridStepAt(double zoom)
{
    const double minimum = 40.0 / zoom;
    const double power = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * power >= minimum)
            return factor * power;
    return 10.0 * power;
}

void addGrid(DisplayList &list, const ViewState &view, const QColor &gridColor, const QColor &axisColor)
{
    // World lines x = k·step and y = k·step across the visible area, and the axes through the
    // world origin (y up, docs/requirements.md 2); the background picture stays visible under them.
    const double step = gridStepAt(view.zoom);
    const double width = view.size.width(), height = view.size.height();
    const geo::Point topLeft = view.toWorld(QPointF(0, 0));
    const geo::Point bottomRight = view.toWorld(QPointF(width, height));
    const double x0 = std::floor(topLeft.x() / step) * step, x1 = bottomRight.x();
    const double y0 = std::floor(bottomRight.y() / step) * step, y1 = topLeft.y();
    // Lines counted, not stepped by adding: far from the origin (a view centred at 1e150) a step
    // below the coordinates' resolution would never advance x and the loop would never end.
    const int columns = static_cast<int>(std::min(width / 40.0 + 2.0, 1e4));
    const int rows = static_cast<int>(std::min(height / 40.0 + 2.0, 1e4));
    for (int k = 0; k <= columns && x0 + k * step <= x1; ++k) {
        const double sx = view.toScreen(geo::Point(x0 + k * step, 0.0)).x();
        list.strokes.push_back({{QPointF(sx, 0), QPointF(sx, height)}, gridColor, 1.0F, false});
    }
    for (int k = 0; k <= rows && y0 + k * step <= y1; ++k) {
        const double sy = view.toScreen(geo::Point(0.0, y0 + k * step)).y();
        list.strokes.push_back({{QPointF(0, sy), QPointF(width, sy)}, gridColor, 1.0F, false});
    }
    const QPointF origin = view.toScreen(geo::Point(0.0, 0.0));
    if (origin.x() >= 0 && origin.x() <= width)
        list.strokes.push_back({{QPointF(origin.x(), 0), QPointF(origin.x(), height)}, axisColor, 1.0F, false});
    if (origin.y() >= 0 && origin.y() <= height)
        list.strokes.push_back({{QPointF(0, origin.y()), QPointF(width, origin.y())}, axisColor, 1.0F, false});
}

void buildScene(const SceneInput &input, const SceneStyle &style, ScreenLists &lists)
{
    lists.grid.clear();
    lists.guides.clear();
    lists.top.clear();
    lists.live.clear();
    const ViewState &view = input.view;
    if (style.showGrid && view.size.width() > 0 && view.size.height() > 0)
        addGrid(lists.grid, view, style.grid, style.axis);
    if (!input.curves)
        return;
    const auto screen = [&view](const geo::Point &p) { return view.toScreen(p); };
    const QRectF itemRect(QPointF(0, 0), view.size);
    const QRectF visible = itemRect.adjusted(-50, -50, 50, 50);
    const auto &curves = *input.curves;
    const int selected = input.selectedCurve;
    const bool software = input.software;
    const auto ringWidth = static_cast<float>(std::max(1.5, style.curveWidth * 0.75));
    const auto radius = static_cast<float>(style.pointRadius);

    // Flattens segments in screen space, so the curve stays sharp at any zoom (0.25 px tolerance).
    std::vector<geo::Point> flat;
    const auto flattenOnScreen = [&](const geo::Bezier &segment) {
        std::vector<geo::Point> screenControl;
        screenControl.reserve(segment.controlPoints().size());
        for (const geo::Point &p : segment.controlPoints()) {
            const QPointF s = screen(p);
            screenControl.emplace_back(s.x(), s.y());
        }
        geo::flatten(geo::Bezier(std::move(screenControl)), 0.25, flat);
    };
    const auto polyline = [&]() {
        std::vector<QPointF> line;
        line.reserve(flat.size());
        for (const geo::Point &p : flat)
            line.emplace_back(p.x(), p.y());
        return line;
    };
    // Knots are filled dots; control points and handles are rings on a white disc; points that
    // cannot be moved (derived ones) are fainter rings.
    DisplayList &top = lists.top;
    // Markers closer on screen than a fraction of their size cannot be told apart, nor picked
    // apart by a finger (44 px targets): of the markers of one look, only the first in each cell
    // of a small grid is drawn, and none off the canvas. A curve of hundreds of points seen whole
    // draws a few dozen markers instead of hundreds stacked on each other, which on a software
    // rasterizer cost a millisecond a frame. The selected point is always drawn.
    const double cell = std::max(2.0, style.pointRadius * 0.75);
    const double reach = 2.0 * style.pointRadius + 4.0;
    const QRectF markerArea = itemRect.adjusted(-reach, -reach, reach, reach);
    std::unordered_set<std::uint64_t> occupied;
    const auto shown = [&](QPointF at, PointRole role, bool editable) {
        if (!markerArea.contains(at))
            return false;
        // Cells within the area fit in 24 bits each way; the look takes the bits above.
        const auto cx = static_cast<std::uint64_t>((at.x() - markerArea.left()) / cell) & 0xFFFFFFU;
        const auto cy = static_cast<std::uint64_t>((at.y() - markerArea.top()) / cell) & 0xFFFFFFU;
        const auto look = static_cast<std::uint64_t>(role) * 2U + (editable ? 1U : 0U);
        return occupied.insert(look << 48U | cx << 24U | cy).second;
    };
    const auto marker = [&](QPointF at, PointRole role, bool editable, bool isSelected) {
        if (!shown(at, role, editable) && !isSelected)
            return;
        if (isSelected)
            top.discs.push_back({at, radius + 4.0F, style.accent});
        if (role == PointRole::Knot) {
            top.discs.push_back({at, radius, style.curve});
            return;
        }
        if (role == PointRole::TangentEnd) {
            // Tangent ends are diamonds, so that shape and not only colour tells them apart.
            const double r = style.pointRadius * 1.3;
            const std::vector<QPointF> diamond{at + QPointF(0, -r), at + QPointF(r, 0), at + QPointF(0, r),
                                               at + QPointF(-r, 0)};
            top.discs.push_back({at, radius * 0.8F, QColor(Qt::white)});
            top.overlay.push_back({diamond, style.tangent, ringWidth, true});
            return;
        }
        top.discs.push_back({at, radius, QColor(Qt::white)});
        top.rings.push_back(
            {at, radius, ringWidth, editable ? style.controlPoint : withAlpha(style.controlPoint, 0.45)});
    };

    // Points of every curve while there are few; on large documents only those of the selected curve,
    // which keeps big drawings fast and readable.
    std::size_t totalRows = 0;
    for (const Curve &curve : curves)
        if (curve.visible)
            totalRows += static_cast<std::size_t>(curve.rowCount());
    const bool showAllPoints = totalRows <= kAllPointsLimit;

    // Software: the selected curve is drawn live over the cached layer, with its halo under the guides.
    std::vector<QPointF> selectedLine;
    if (software && input.selectedFlat)
        toScreenPolyline(*input.selectedFlat, view, selectedLine);
    if (selectedLine.size() >= 2)
        lists.live.strokes.push_back(
            {selectedLine, withAlpha(style.accent, 0.3), static_cast<float>(style.curveWidth + 6.0), false});

    std::vector<Stroke> &guides = software ? lists.live.strokes : lists.guides.strokes;
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const bool isSelectedCurve = static_cast<int>(c) == selected;
        if (!showAllPoints && !isSelectedCurve)
            continue;
        const Curve &curve = curves[c];
        if (!curve.visible || curve.rowCount() == 0)
            continue;
        std::vector<QPointF> rows;
        rows.reserve(static_cast<std::size_t>(curve.rowCount()));
        QRectF bounds;
        for (int r = 0; r < curve.rowCount(); ++r) {
            rows.push_back(screen(curve.row(r).position));
            bounds = bounds.united(QRectF(rows.back(), QSizeF(1e-9, 1e-9)));
        }
        if (!bounds.intersects(visible))
            continue;
        // The light grey guides (Curve::guides()); a pair that continues the one before extends
        // its polyline, so that a control polygon is drawn with joins.
        // Handles away from the selected knot are hidden (Curve::isRowShown), with their guides.
        const int selectedRow = isSelectedCurve ? input.selectedPoint : -1;
        int last = -1;
        for (const auto &[from, to] : curve.guides()) {
            if (!curve.isRowShown(from, selectedRow) || !curve.isRowShown(to, selectedRow)) {
                last = -1;
                continue;
            }
            const QPointF &end = rows[static_cast<std::size_t>(to)];
            if (from == last)
                guides.back().points.push_back(end);
            else
                guides.push_back({{rows[static_cast<std::size_t>(from)], end}, style.polygon, 1.0F, false});
            last = to;
        }
        for (int r = 0; r < curve.rowCount(); ++r) {
            if (!curve.isRowShown(r, selectedRow))
                continue;
            const PointRow row = curve.row(r);
            marker(rows[static_cast<std::size_t>(r)], row.role, row.editable,
                   isSelectedCurve && r == input.selectedPoint);
        }
    }

    // Software: the selected curve's line over its guides.
    if (selectedLine.size() >= 2) {
        const Curve &curve = curves[static_cast<std::size_t>(selected)];
        lists.live.strokes.push_back(
            {std::move(selectedLine), curve.color, static_cast<float>(style.curveWidth), curve.isClosed()});
    }

    // The curve being placed: its points, the preview the kind allows, and the seed's dashed
    // rubber band from the last point to the pointer.
    if (input.pendingPoints && !input.pendingPoints->empty()) {
        const auto &pending = *input.pendingPoints;
        const CurveKind kind = input.placementKind;
        // The kinds whose points steer the curve show their control polygon while being placed.
        const bool controlled = kind == CurveKind::Bezier || kind == CurveKind::Contour;
        const PointRole role = controlled ? PointRole::ControlPoint : PointRole::Knot;
        std::vector<QPointF> polygon;
        for (const geo::Point &p : pending)
            polygon.push_back(screen(p));
        if (controlled)
            top.strokes.push_back({polygon, style.polygon, 1.0F, false});
        flat.clear();
        for (const geo::Bezier &segment : input.pendingSegments)
            flattenOnScreen(segment);
        if (flat.size() >= 2)
            top.strokes.push_back({polyline(), style.curve, static_cast<float>(style.curveWidth), false});
        for (const QPointF &at : polygon)
            marker(at, role, true, false);
        if (input.hover) {
            if (const auto band = clipped(polygon.back(), screen(*input.hover), visible))
                for (auto &dash : dashed({band->first, band->second}, 6.0, 4.0))
                    top.strokes.push_back({std::move(dash), style.polygon.darker(130), 1.0F, false});
        }
    }
}

} // namespace kontur
