// StrokeNode: polylines in world units as a scene-graph node, drawn by StrokeMaterial's shaders
// as anti-aliased strokes of a fixed width in pixels. The view (zoom and centre) is shared by all
// stroke nodes of a canvas and read by the shader each frame, so panning and zooming change no
// vertex: only a node with a curve whose shape changed (or whose flattening no longer meets the
// tolerance at the new zoom) gets new geometry.
#pragma once

#include "geometry/bezier.h"

#include <QColor>
#include <QPointF>
#include <QSGGeometryNode>
#include <QSGMaterial>
#include <QSizeF>

#include <cstdint>
#include <vector>

namespace kontur {

// Appends a polyline within `tolerance` of the Bézier curve (world units), with as few points as
// geo::flatten gives for that: its test bounds the control points' distance to the chord, and the
// curve's distance is at most 1 - 2^(1-n) of that for degree n (3/4 for a cubic), since the
// distance to a segment is convex and the interior Bernstein weights sum to 1 - t^n - (1-t)^n.
void flattenWithin(const geo::Bezier &curve, double tolerance, std::vector<geo::Point> &out);

// The canvas's view as the render side sees it: written while the canvas synchronises.
struct StrokeView
{
    double zoom = 1.0;
    QPointF center; // world point at the item's centre
    QSizeF size;    // the item's size in pixels
};

// One polyline of a stroke node and how it is drawn.
struct StrokePath
{
    const std::vector<geo::Point> *world = nullptr; // world units, y up
    bool closed = false;
    QColor color;
    float width = 1.0F; // device-independent pixels
};

// What a stroke node shows of a curve, to tell when it must be built again: the flattening's
// version (0: nothing) and the style.
struct ShownCurve
{
    std::uint64_t version = 0;
    QRgb color = 0;
    float width = 0.0F;
    bool closed = false;
    bool operator==(const ShownCurve &) const = default;
};

class StrokeMaterial final : public QSGMaterial
{
public:
    explicit StrokeMaterial(const StrokeView *view);
    [[nodiscard]] QSGMaterialType *type() const override;
    [[nodiscard]] QSGMaterialShader *createShader(QSGRendererInterface::RenderMode renderMode) const override;

    const StrokeView *view;
};

// Any number of polylines, each with its own colour and width, in one triangle strip (joined by
// degenerate triangles): one draw call for many curves. The vertices hold world positions split
// into a float and the float rest of the double, and so does the view's centre in the shader, so
// the difference keeps double precision at any zoom and however far apart the curves are.
class StrokeNode final : public QSGGeometryNode
{
public:
    explicit StrokeNode(const StrokeView *view);

    // Replaces the polylines. Repeated points are dropped.
    void setPaths(const std::vector<StrokePath> &paths);
    [[nodiscard]] int vertexCount() const { return geometry()->vertexCount(); }

private:
    StrokeMaterial m_material;
    QSGGeometry m_geometry;
};

} // namespace kontur
