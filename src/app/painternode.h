// PainterNode: the canvas on Qt Quick's software backend, painted with QPainter, and the cached
// layer picture of the curves other than the selected one (also used, as a texture, where OpenGL
// rasterizes on the processor).
#pragma once

#include "app/displaylist.h"
#include "app/layerpicture.h"
#include "app/viewstate.h"

#include <QColor>
#include <QImage>
#include <QSGRenderNode>

#include <cstdint>
#include <memory>
#include <vector>

class QQuickWindow;

namespace kontur {

// The software backend draws no geometry nodes with materials, so there the canvas paints
// with the QPainter the renderer hands out (QSGRendererInterface::PainterResource). Curves other
// than the selected one live in a cached layer picture (with a margin around the view): it is
// shown transformed while a gesture goes on and painted again when the view settles or what it
// shows changed, so a drag or a pinch frame costs a picture copy, not every curve.
class PainterNode final : public QSGRenderNode
{
public:
    explicit PainterNode(QQuickWindow *window)
        : m_window(window)
    {
    }

    void render(const RenderState *state) override;
    [[nodiscard]] StateFlags changedStates() const override { return {}; }
    [[nodiscard]] RenderingFlags flags() const override { return BoundedRectRendering; }
    [[nodiscard]] QRectF rect() const override { return bounds; }

    DisplayList grid, live, top;
    QRectF bounds;
    // What the layer shows (sorted by key), described anew every frame; it is only painted when
    // needed, and then only the curves that changed where they are few.
    std::vector<LayerCurve> layerCurves;
    float curveWidth = 2.0F;
    std::uint64_t version = 0;
    ViewState view;
    bool settled = true;
    double margin = 0.0; // item pixels painted around the view

private:
    // Draws the layer, painting it first when needed; true when it was painted.
    bool drawLayer(QPainter &painter);

    // Layer pixels → item coordinates at the current view.
    [[nodiscard]] QTransform layerToItem() const;

    // Whether the layer, transformed, still covers the whole view without much blur.
    [[nodiscard]] bool covers() const;

    void paintLayer(double scale);

    QQuickWindow *m_window;
    LayerPicture m_layer;
    ViewState m_view;
    std::uint64_t m_version = 0;
    double m_scale = 0.0;
    double m_margin = 0.0;
};

} // namespace kontur
