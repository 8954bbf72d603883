// The canvas's nodes, and how the canvas fills them each frame: its own root (background, and the
// grid and guides or the software painter node), the layer part's stroke chunks or picture, the
// live part.
#include "app/canvasnodes.h"

#include "app/curvecanvas.h"

#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/trace/perspective.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QSGVertexColorMaterial>

#include <algorithm>
#include <cmath>

namespace kontur {

// Whether the OpenGL implementation rasterizes on the processor (Mesa's llvmpipe and softpipe,
// SwiftShader): the canvas's layer is then best a painted picture (CurveCanvas::m_imageLayer).
// KONTUR_CANVAS_LAYER=picture or texture decides instead. Render thread, context current.
bool softwareRasterizer(QQuickWindow *window)
{
    const QByteArray forced = qgetenv("KONTUR_CANVAS_LAYER");
    if (forced == "picture" || forced == "texture")
        return forced == "picture";
    auto *context = static_cast<QOpenGLContext *>(
        window->rendererInterface()->getResource(window, QSGRendererInterface::OpenGLContextResource));
    if (!context || !context->functions())
        return false; // another graphics API: a GPU
    const QByteArray renderer =
        QByteArray(reinterpret_cast<const char *>(context->functions()->glGetString(GL_RENDERER))).toLower();
    return renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swiftshader") ||
           renderer.contains("software rasterizer");
}

// A screen-space part of the picture on the GPU: triangles with per-vertex colours.
QSGGeometryNode *newMeshNode()
{
    auto *node = new QSGGeometryNode;
    auto *geometry =
        new QSGGeometry(QSGGeometry::defaultAttributes_ColoredPoint2D(), 0, 0, QSGGeometry::UnsignedIntType);
    geometry->setDrawingMode(QSGGeometry::DrawTriangles);
    node->setGeometry(geometry);
    node->setFlag(QSGNode::OwnsGeometry);
    node->setMaterial(new QSGVertexColorMaterial);
    node->setFlag(QSGNode::OwnsMaterial);
    return node;
}

std::size_t setMesh(QSGGeometryNode *node, const std::vector<Stroke> &strokes, TriangleMesh &mesh)
{
    tessellateStrokes(strokes, mesh);
    QSGGeometry *geometry = node->geometry();
    geometry->allocate(static_cast<int>(mesh.vertices.size()), static_cast<int>(mesh.indices.size()));
    std::copy(mesh.vertices.begin(), mesh.vertices.end(), geometry->vertexDataAsColoredPoint2D());
    std::copy(mesh.indices.begin(), mesh.indices.end(), geometry->indexDataAsUInt());
    node->markDirty(QSGNode::DirtyGeometry);
    return mesh.vertices.size();
}

QSGNode *CurveCanvas::updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *)
{
    QQuickWindow *win = window();
    if (!win)
        return oldNode;
    QElapsedTimer profile;
    profile.start();
    static const bool profiling = qEnvironmentVariableIsSet("KONTUR_PROFILE");
    const bool software = win->rendererInterface()->graphicsApi() == QSGRendererInterface::Software;
    auto *root = static_cast<CanvasRootNode *>(oldNode);
    if (!root) {
        root = new CanvasRootNode;
        if (software) {
            root->painter = new PainterNode(win);
            root->appendChildNode(root->painter);
            root->firstContent = root->painter;
        } else {
            root->grid = newMeshNode();
            root->halo = new StrokeNode(&root->view);
            root->guides = newMeshNode();
            for (QSGNode *node : std::initializer_list<QSGNode *>{root->grid, root->halo, root->guides})
                root->appendChildNode(node);
            root->firstContent = root->grid;
        }
    }

    // The background: a textured rectangle where the document places the picture (y up in the world).
    const Background *background = m_controller ? &m_controller->document()->background() : nullptr;
    const bool showBackground = background && background->visible && !m_backgroundImage.isNull();
    if (m_backgroundDirty && root->backgroundOpacity) {
        root->removeChildNode(root->backgroundOpacity);
        delete root->backgroundOpacity; // deletes the image node and its texture with it
        root->backgroundOpacity = nullptr;
        root->background = nullptr;
        root->backgroundTurn = nullptr;
    }
    m_backgroundDirty = false;
    if (showBackground && !root->background) {
        root->backgroundOpacity = new QSGOpacityNode;
        root->backgroundOpacity->setFlag(QSGNode::OwnedByParent);
        root->background = win->createImageNode();
        root->background->setTexture(win->createTextureFromImage(m_backgroundImage));
        root->background->setOwnsTexture(true);
        root->background->setFiltering(QSGTexture::Linear);
        root->backgroundTurn = new QSGTransformNode;
        root->backgroundTurn->appendChildNode(root->background);
        root->backgroundOpacity->appendChildNode(root->backgroundTurn);
        root->insertChildNodeBefore(root->backgroundOpacity, root->firstContent);
    }
    if (root->backgroundOpacity) {
        root->backgroundOpacity->setOpacity(showBackground ? background->opacity : 0.0);
        if (showBackground) {
            const QSizeF imageSize = m_backgroundImage.size();
            if (background->placedInPerspective()) {
                // The picture in its own pixels, mapped to the screen by the one picture → world
                // mapping (Background::imageToWorld, here a homography) and then world → screen; the
                // GPU interpolates the texture in perspective, the software renderer paints it with
                // QPainter's projective transform. Only the part this side of the horizon is drawn
                // (perspective::drawnRect).
                const QRectF drawn = perspective::drawnRect(*background, imageSize);
                root->background->setRect(drawn);
                root->background->setSourceRect(drawn);
                root->backgroundTurn->setMatrix(
                    QMatrix4x4(perspective::toQTransform(background->imageToWorld()) * view().worldToScreen()));
            } else {
                // An affine placement: the picture's rectangle on the screen, turned about its
                // top-left corner; the corner and the scale come from the one mapping.
                const geo::Projective2D toWorld = background->imageToWorld();
                const QPointF topLeft = view().toScreen(toWorld.map(geo::Point(0.0, 0.0)));
                const double scale = toWorld.jacobian(geo::Point(0.0, 0.0)).col(0).norm() * m_zoom;
                root->background->setRect(
                    QRectF(topLeft, QSizeF(imageSize.width() * scale, imageSize.height() * scale)));
                root->background->setSourceRect(QRectF(QPointF(0.0, 0.0), imageSize));
                // Turned counter-clockwise in the world (clockwise angles on the screen, y down).
                QMatrix4x4 turn;
                turn.translate(float(topLeft.x()), float(topLeft.y()));
                turn.rotate(float(-background->rotation), 0.0F, 0.0F, 1.0F);
                turn.translate(float(-topLeft.x()), float(-topLeft.y()));
                root->backgroundTurn->setMatrix(turn);
            }
        }
    }

    const int selected = m_controller ? m_controller->selection()->curveRow() : -1;
    if (software && selected != m_layerExcluded) {
        m_layerExcluded = selected;
        layerChanged();
    }
    screenLists(software);
    const double listMs = static_cast<double>(profile.nsecsElapsed()) / 1e6;

    if (software) {
        std::size_t reflattened = 0;
        PainterNode *node = root->painter;
        node->bounds = boundingRect();
        std::swap(node->grid, m_lists.grid);
        std::swap(node->live, m_lists.live);
        std::swap(node->top, m_lists.top);
        // The layer covers the view and a margin, so that pans and zooming out show no empty border.
        node->margin = std::ceil(0.25 * std::max(width(), height()));
        node->layerCurves.clear();
        if (m_controller) {
            const auto &curves = m_controller->document()->curves();
            const QRectF area = visibleWorld(node->margin + 10.0);
            const std::vector<std::size_t> meeting = curvesMeeting(area, selected);
            reflattened = m_flat.ensureMany(meeting, curves, m_zoom, area);
            for (const std::size_t c : meeting)
                node->layerCurves.push_back({c, m_flat.world(c), curves[c].color, curves[c].isClosed()});
        }
        node->curveWidth = static_cast<float>(m_curveWidth);
        node->version = m_layerVersion;
        node->view = {m_zoom, m_center, size()};
        node->settled = m_viewSettled;
        node->markDirty(QSGNode::DirtyMaterial);
        if (profiling)
            qInfo("sync: %.2f ms (screen lists %.2f ms), %zu curves in the layer, %zu re-flattened",
                  static_cast<double>(profile.nsecsElapsed()) / 1e6, listMs, node->layerCurves.size(), reflattened);
        return root;
    }

    root->view = {m_zoom, m_center, size()};
    TriangleMesh mesh;
    // A layer painted as a picture has the grid in it.
    std::size_t meshVertices =
        setMesh(root->grid, imageLayerActive() ? std::vector<Stroke>{} : m_lists.grid.strokes, mesh);
    meshVertices += setMesh(root->guides, m_lists.guides.strokes, mesh);
    // The selected curve's halo, under the guides.
    const ShownCurve selectedNow = shownSelected();
    const ShownCurve haloNow = selectedNow.version != 0
                                   ? ShownCurve{selectedNow.version, withAlpha(m_accentColor, 0.3).rgba(),
                                                static_cast<float>(m_curveWidth + 6.0), selectedNow.closed}
                                   : ShownCurve{};
    if (haloNow != root->haloShown) {
        root->halo->setPaths(haloNow.version != 0 ? std::vector{strokePath(static_cast<std::size_t>(selected), haloNow)}
                                                  : std::vector<StrokePath>{});
        root->haloShown = haloNow;
    }
    if (profiling)
        qInfo("sync: canvas %.2f ms (screen lists %.2f ms, %zu mesh vertices)",
              static_cast<double>(profile.nsecsElapsed()) / 1e6, listMs, meshVertices);
    return root;
}

ShownCurve CurveCanvas::shownCurve(std::size_t c, QColor color, float strokeWidth, double zoom, const QRectF &area,
                                   std::size_t *reflattened)
{
    const Curve &curve = m_controller->document()->curves()[c];
    if (!curve.visible || curve.rowCount() == 0)
        return {};
    // Curves out of sight keep what they had (the clip hides it); those that come into sight or
    // changed get new vertices.
    if (curveMeets(c, area) && ensureFlat(c, zoom, area) && reflattened)
        ++*reflattened;
    if (!m_flat.world(c))
        return {};
    return {m_flat.version(c), color.rgba(), strokeWidth, curve.isClosed()};
}

ShownCurve CurveCanvas::shownSelected()
{
    const int selected = m_controller ? m_controller->selection()->curveRow() : -1;
    if (selected < 0 || static_cast<std::size_t>(selected) >= m_flat.size())
        return {};
    const auto c = static_cast<std::size_t>(selected);
    return shownCurve(c, m_controller->document()->curves()[c].color, static_cast<float>(m_curveWidth), m_zoom,
                      visibleWorld(50.0), nullptr);
}

StrokePath CurveCanvas::strokePath(std::size_t c, const ShownCurve &shown) const
{
    return {m_flat.world(c).get(), shown.closed, QColor::fromRgba(shown.color), shown.width};
}

QSGNode *CurveCanvas::updateLayerNode(QSGNode *oldNode)
{
    if (!m_gpu || !m_controller) {
        delete oldNode;
        return nullptr;
    }
    if (!m_rasterizerKnown) {
        m_rasterizerKnown = true;
        m_imageLayer = softwareRasterizer(window());
        // The item layer is switched off, and the grid moves into the picture, on the GUI thread.
        QMetaObject::invokeMethod(
            this,
            [this] {
                applyLayered();
                Q_EMIT layerKindChanged();
            },
            Qt::QueuedConnection);
    }
    QElapsedTimer profile;
    profile.start();
    static const bool profiling = qEnvironmentVariableIsSet("KONTUR_PROFILE");
    screenLists(false);
    auto *root = static_cast<LayerRootNode *>(oldNode);
    if (!root)
        root = new LayerRootNode;
    if (imageLayerActive())
        return updateLayerImage(root);
    if (root->image) {
        root->removeChildNode(root->image);
        delete root->image;
        root->image = nullptr;
        root->layer.clear();
    }
    const QSizeF size(width() + 2.0 * m_layerMargin, height() + 2.0 * m_layerMargin);
    const bool viewChanged =
        root->view.zoom != m_layerZoom || root->view.center != m_layerCenter || root->view.size != size;
    root->view = {m_layerZoom, m_layerCenter, size};
    const QRectF area = layerWorld();

    const auto &curves = m_controller->document()->curves();
    const std::size_t curveCount = curves.size();
    const int selected = m_controller->selection()->curveRow();
    const auto width = static_cast<float>(m_curveWidth);
    const std::size_t chunkCount = (curveCount + kChunkCurves - 1) / kChunkCurves;
    while (root->chunks.size() > chunkCount) {
        root->removeChildNode(root->chunks.back());
        delete root->chunks.back();
        root->chunks.pop_back();
    }
    while (root->chunks.size() < chunkCount) {
        root->chunks.push_back(new StrokeNode(&root->view));
        root->appendChildNode(root->chunks.back());
    }
    root->chunkShown.resize(chunkCount);
    std::size_t reflattened = flattenMeeting(area, m_layerZoom, selected), uploaded = 0, vertices = 0;
    std::vector<ShownCurve> now;
    std::vector<StrokePath> paths;
    for (std::size_t k = 0; k < chunkCount; ++k) {
        const std::size_t first = k * kChunkCurves;
        const std::size_t last = std::min(first + kChunkCurves, curveCount);
        now.clear();
        for (std::size_t c = first; c < last; ++c)
            now.push_back(static_cast<int>(c) == selected
                              ? ShownCurve{}
                              : shownCurve(c, curves[c].color, width, m_layerZoom, area, &reflattened));
        if (now != root->chunkShown[k]) {
            paths.clear();
            for (std::size_t c = first; c < last; ++c)
                if (now[c - first].version != 0)
                    paths.push_back(strokePath(c, now[c - first]));
            root->chunks[k]->setPaths(paths);
            root->chunkShown[k] = now;
            ++uploaded;
        } else if (viewChanged) {
            // The shader reads the view: the layer's texture must be drawn again.
            root->chunks[k]->markDirty(QSGNode::DirtyMaterial);
        }
        vertices += static_cast<std::size_t>(root->chunks[k]->vertexCount());
    }
    if (profiling)
        qInfo("sync: layer %.2f ms, %zu curves re-flattened, %zu of %zu chunks uploaded, %zu stroke vertices%s",
              static_cast<double>(profile.nsecsElapsed()) / 1e6, reflattened, uploaded, chunkCount, vertices,
              viewChanged ? ", new view" : "");
    return root;
}

QSGNode *CurveCanvas::updateLayerImage(QSGNode *node)
{
    auto *root = static_cast<LayerRootNode *>(node);
    QElapsedTimer profile;
    profile.start();
    static const bool profiling = qEnvironmentVariableIsSet("KONTUR_PROFILE");
    for (StrokeNode *chunk : root->chunks) {
        root->removeChildNode(chunk);
        delete chunk;
    }
    root->chunks.clear();
    root->chunkShown.clear();

    // What the picture shows now: the grid and the curves other than the selected one, at the
    // layer's view. Only what changed is painted again: a selection change, two curves.
    const auto &curves = m_controller->document()->curves();
    const int selected = m_controller->selection()->curveRow();
    const auto width = static_cast<float>(m_curveWidth);
    const QSizeF size(this->width() + 2.0 * m_layerMargin, height() + 2.0 * m_layerMargin);
    const QRectF area = layerWorld();
    const LayerPicture::Frame frame{
        {m_layerZoom, m_layerCenter, this->size()}, m_layerMargin, window()->effectiveDevicePixelRatio(), width};
    const LayerRootNode::Grid grid{m_showGrid, m_gridColor.rgba(), m_axisColor.rgba()};
    std::size_t reflattened = flattenMeeting(area, m_layerZoom, selected);
    std::vector<LayerCurve> shown;
    shown.reserve(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c)
        if (static_cast<int>(c) != selected &&
            shownCurve(c, curves[c].color, width, m_layerZoom, area, &reflattened).version != 0)
            shown.push_back({c, m_flat.world(c), curves[c].color, curves[c].isClosed()});
    const ViewState layerView{m_layerZoom, m_layerCenter, size};
    const auto background = [&](QPainter &painter) {
        if (!grid.shown)
            return;
        DisplayList lines;
        addGrid(lines, layerView, m_gridColor, m_axisColor);
        painter.save();
        painter.scale(frame.scale, frame.scale);
        paint(lines, painter);
        painter.restore();
    };
    const bool gridChanged = !(grid == root->grid);
    root->grid = grid;
    const LayerPicture::Painted painted = root->layer.update(shown, frame, background, gridChanged || !root->image);
    if (painted != LayerPicture::Painted::Nothing) {
        if (!root->image) {
            root->image = window()->createImageNode();
            root->image->setOwnsTexture(true);
            root->appendChildNode(root->image);
        }
        root->image->setTexture(window()->createTextureFromImage(root->layer.image()));
        root->image->setRect(QRectF(QPointF(0, 0), size));
    }
    // Pixel for pixel while the view is the layer's (a copy); filtered while it is scaled.
    root->image->setFiltering(m_zoom == m_layerZoom ? QSGTexture::Nearest : QSGTexture::Linear);
    if (profiling)
        qInfo("sync: layer picture %.2f ms, %zu curves re-flattened%s",
              static_cast<double>(profile.nsecsElapsed()) / 1e6, reflattened,
              painted == LayerPicture::Painted::Whole  ? ", painted"
              : painted == LayerPicture::Painted::Part ? ", painted in part"
                                                       : "");
    return root;
}

QSGNode *CurveCanvas::updateLiveNode(QSGNode *oldNode)
{
    if (!m_gpu || !m_controller) {
        delete oldNode;
        return nullptr;
    }
    const ScreenLists &lists = screenLists(false);
    auto *root = static_cast<LiveRootNode *>(oldNode);
    if (!root)
        root = new LiveRootNode;
    root->view = {m_zoom, m_center, size()};
    const ShownCurve selectedNow = shownSelected();
    if (selectedNow != root->selectedShown) {
        const auto c = static_cast<std::size_t>(m_controller->selection()->curveRow());
        root->selectedCurve->setPaths(selectedNow.version != 0 ? std::vector{strokePath(c, selectedNow)}
                                                               : std::vector<StrokePath>{});
        root->selectedShown = selectedNow;
    }
    TriangleMesh mesh;
    setMesh(root->topStrokes, lists.top.strokes, mesh);
    root->discs->setMarkers(lists.top.discs, {});
    setMesh(root->overlay, lists.top.overlay, mesh);
    root->rings->setMarkers({}, lists.top.rings);
    return root;
}

} // namespace kontur
