// The canvas's scene-graph nodes: its own root (the background picture, then on GPU backends the
// grid, the selected curve's halo and the guides, on the software backend the painter node), the
// layer part's curves (GPU: stroke-node chunks, or a painted picture on software rasterizers) and
// the live part (the selected curve and the point markers). CurveCanvas fills them each frame in
// canvasnodes.cpp.
#pragma once

#include "app/displaylist.h"
#include "app/layerpicture.h"
#include "app/markernode.h"
#include "app/painternode.h"
#include "app/strokenode.h"
#include "app/viewstate.h"

#include <QImage>
#include <QSGGeometryNode>
#include <QSGImageNode>
#include <QSGOpacityNode>
#include <QSGTransformNode>

#include <vector>

class QQuickWindow;

namespace kontur {

// Whether the OpenGL implementation rasterizes on the processor (Mesa's llvmpipe and softpipe,
// SwiftShader): the canvas's layer is then best a painted picture (CurveCanvas::m_imageLayer).
// KONTUR_CANVAS_LAYER=picture or texture decides instead. Render thread, context current.
bool softwareRasterizer(QQuickWindow *window);

// A screen-space part of the picture on the GPU: triangles with per-vertex colours.
QSGGeometryNode *newMeshNode();
// Sets the node's triangles to the strokes' (tessellated into `mesh`); returns the vertex count.
std::size_t setMesh(QSGGeometryNode *node, const std::vector<Stroke> &strokes, TriangleMesh &mesh);

// Curves per stroke node: few draw calls, and a changed curve re-uploads only its chunk.
constexpr std::size_t kChunkCurves = 64;

// The canvas's own node tree: the background picture (under an opacity node), then on GPU
// backends the grid, the selected curve's halo and the guides; on the software backend one
// painter node that draws everything.
class CanvasRootNode final : public QSGNode
{
public:
    QSGOpacityNode *backgroundOpacity = nullptr;
    QSGImageNode *background = nullptr;
    QSGTransformNode *backgroundTurn = nullptr; // the picture's rotation (issue 10: calibration)
    QSGNode *firstContent = nullptr;            // the background goes before this

    StrokeView view; // read by the halo's shader
    QSGGeometryNode *grid = nullptr;
    StrokeNode *halo = nullptr;
    ShownCurve haloShown;
    QSGGeometryNode *guides = nullptr;

    PainterNode *painter = nullptr;
};

// The layer part (GPU): the curves other than the selected one in chunks of consecutive ones, a
// draw call each, at the layer's view.
class LayerRootNode final : public QSGNode
{
public:
    StrokeView view;
    std::vector<StrokeNode *> chunks;
    std::vector<std::vector<ShownCurve>> chunkShown;

    // Software rasterizers: the layer as a painted picture instead of the chunks, with the grid.
    QSGImageNode *image = nullptr;
    LayerPicture layer;
    struct Grid
    {
        bool shown = false;
        QRgb color = 0, axisColor = 0;
        bool operator==(const Grid &) const = default;
    } grid;
};

// The live part (GPU): the selected curve, then the placement preview, discs, tangent-end
// diamonds and rings, at the current view.
class LiveRootNode final : public QSGNode
{
public:
    LiveRootNode()
        : selectedCurve(new StrokeNode(&view))
        , topStrokes(newMeshNode())
        , discs(new MarkerNode)
        , overlay(newMeshNode())
        , rings(new MarkerNode)
    {
        for (QSGNode *node : std::initializer_list<QSGNode *>{selectedCurve, topStrokes, discs, overlay, rings})
            appendChildNode(node);
    }

    StrokeView view;
    StrokeNode *selectedCurve;
    ShownCurve selectedShown;
    QSGGeometryNode *topStrokes;
    MarkerNode *discs;
    QSGGeometryNode *overlay;
    MarkerNode *rings;
};

} // namespace kontur
