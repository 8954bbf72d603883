// CurveCanvas: view transform, gesture routing and scene-graph drawing on both backends.
#include "app/curvecanvas.h"

#include "app/markernode.h"
#include "app/strokenode.h"

#include "models/document.h"
#include "models/editcontroller.h"

#include <QElapsedTimer>
#include <QImageReader>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QQuickWindow>
#include <QSGGeometryNode>
#include <QSGImageNode>
#include <QSGOpacityNode>
#include <QSGRenderNode>
#include <QSGRendererInterface>
#include <QSGVertexColorMaterial>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace kontur {

namespace {

QColor withAlpha(QColor color, double alpha)
{
    color.setAlphaF(static_cast<float>(alpha));
    return color;
}

// The world → item mapping of one view.
struct ViewState
{
    double zoom = 1.0;
    QPointF center;
    QSizeF size;

    [[nodiscard]] QPointF toScreen(const geo::Point &p) const
    {
        return {size.width() / 2.0 + (p.x() - center.x()) * zoom, size.height() / 2.0 - (p.y() - center.y()) * zoom};
    }
    [[nodiscard]] geo::Point toWorld(QPointF s) const
    {
        return {center.x() + (s.x() - size.width() / 2.0) / zoom, center.y() - (s.y() - size.height() / 2.0) / zoom};
    }
    bool operator==(const ViewState &) const = default;
};

// A curve drawn into the software layer.
struct LayerCurve
{
    std::shared_ptr<const std::vector<geo::Point>> world;
    QColor color;
    bool closed = false;
};

// World points on screen, leaving out points closer than a quarter pixel to the last one kept
// (zoomed out, most of them): the drawn line moves by less than that.
void toScreenPolyline(const std::vector<geo::Point> &world, const ViewState &view, std::vector<QPointF> &line)
{
    line.clear();
    line.reserve(world.size());
    for (std::size_t i = 0; i < world.size(); ++i) {
        const QPointF p = view.toScreen(world[i]);
        if (!line.empty() && i + 1 != world.size()) {
            const QPointF d = p - line.back();
            if (d.x() * d.x() + d.y() * d.y() < 0.0625)
                continue;
        }
        line.push_back(p);
    }
}

// Paints the curves of a layer at `view` (its size without the margin) into a picture that has
// `margin` item pixels around the view, at `scale` picture pixels per item pixel.
void paintLayerCurves(QPainter &painter, const std::vector<LayerCurve> &curves, const ViewState &view, double margin,
                      double scale, float curveWidth)
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Device pixels: the fast stroke's one-pixel lines are device pixels.
    std::vector<QPointF> line;
    for (const LayerCurve &curve : curves) {
        if (!curve.world)
            continue;
        toScreenPolyline(*curve.world, view, line);
        if (line.size() < 2)
            continue;
        for (QPointF &point : line)
            point = (point + QPointF(margin, margin)) * scale;
        paintFastStroke(line, curve.color, curveWidth * scale, curve.closed, painter);
    }
}

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

    void render(const RenderState *state) override
    {
        auto *painter = static_cast<QPainter *>(
            m_window->rendererInterface()->getResource(m_window, QSGRendererInterface::PainterResource));
        if (!painter)
            return;
        QElapsedTimer clock;
        clock.start();
        painter->save();
        if (const QRegion *clip = state->clipRegion(); clip && !clip->isEmpty())
            painter->setClipRegion(*clip, Qt::ReplaceClip);
        painter->setTransform(matrix()->toTransform());
        painter->setOpacity(inheritedOpacity());
        paint(grid, *painter);
        const double gridMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
        const bool repainted = drawLayer(*painter);
        const double layerMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
        paint(live, *painter);
        const double liveMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
        paint(top, *painter);
        painter->restore();
        static const bool profiling = qEnvironmentVariableIsSet("KONTUR_PROFILE");
        if (profiling)
            qInfo("software paint: %.2f ms (grid %.2f, layer %.2f %s with %zu curves, selected curve %.2f, "
                  "points %.2f)",
                  static_cast<double>(clock.nsecsElapsed()) / 1e6, gridMs, layerMs - gridMs,
                  repainted ? "painted" : "reused", layerCurves.size(), liveMs - layerMs,
                  static_cast<double>(clock.nsecsElapsed()) / 1e6 - liveMs);
    }
    [[nodiscard]] StateFlags changedStates() const override { return {}; }
    [[nodiscard]] RenderingFlags flags() const override { return BoundedRectRendering; }
    [[nodiscard]] QRectF rect() const override { return bounds; }

    DisplayList grid, live, top;
    QRectF bounds;
    // What the layer shows, described anew every frame; it is only painted when needed.
    std::vector<LayerCurve> layerCurves;
    float curveWidth = 2.0F;
    std::uint64_t version = 0;
    ViewState view;
    bool settled = true;
    double margin = 0.0; // item pixels painted around the view

private:
    // Draws the layer, painting it first when needed; true when it was painted.
    bool drawLayer(QPainter &painter)
    {
        const QTransform device = painter.combinedTransform();
        const double scale = std::sqrt(std::abs(device.determinant())) * painter.device()->devicePixelRatioF();
        const bool sameContent = !m_layer.isNull() && m_version == version && m_view.size == view.size &&
                                 std::abs(m_scale - scale) < 1e-9 && m_margin == margin;
        bool painted = false;
        if (!sameContent || (!(m_view == view) && (settled || !covers()))) {
            paintLayer(scale);
            painted = true;
        }
        painter.save();
        painter.setTransform(layerToItem(), true);
        if (!(m_view == view))
            painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
        painter.drawImage(QPointF(0, 0), m_layer);
        painter.restore();
        return painted;
    }

    // Layer pixels → item coordinates at the current view.
    [[nodiscard]] QTransform layerToItem() const
    {
        const double w = view.size.width(), h = view.size.height();
        const double s = view.zoom / m_view.zoom;
        QTransform t;
        t.translate(w / 2.0 + (m_view.center.x() - view.center.x()) * view.zoom,
                    h / 2.0 - (m_view.center.y() - view.center.y()) * view.zoom);
        t.scale(s, s);
        t.translate(-w / 2.0 - m_margin, -h / 2.0 - m_margin);
        t.scale(1.0 / m_scale, 1.0 / m_scale);
        return t;
    }

    // Whether the layer, transformed, still covers the whole view without much blur.
    [[nodiscard]] bool covers() const
    {
        const double s = view.zoom / m_view.zoom;
        if (!(s >= 0.5 && s <= 2.0))
            return false;
        bool invertible = false;
        const QTransform back = layerToItem().inverted(&invertible);
        if (!invertible)
            return false;
        const QRectF needed = back.mapRect(QRectF(QPointF(0, 0), view.size));
        return QRectF(m_layer.rect()).adjusted(-1, -1, 1, 1).contains(needed);
    }

    void paintLayer(double scale)
    {
        m_view = view;
        m_version = version;
        m_scale = scale;
        m_margin = margin;
        const QSize pixels(static_cast<int>(std::ceil((view.size.width() + 2 * margin) * scale)),
                           static_cast<int>(std::ceil((view.size.height() + 2 * margin) * scale)));
        if (m_layer.size() != pixels)
            m_layer = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
        m_layer.fill(Qt::transparent);
        QPainter p(&m_layer);
        paintLayerCurves(p, layerCurves, view, margin, scale, curveWidth);
    }

    QQuickWindow *m_window;
    QImage m_layer;
    ViewState m_view;
    std::uint64_t m_version = 0;
    double m_scale = 0.0;
    double m_margin = 0.0;
};

} // namespace

// A child item that draws one part of the canvas's picture on GPU backends, over the canvas's
// own nodes: the layer (the curves other than the selected one) or the live part (the selected
// curve and the points). It takes no input: that goes to the canvas.
class CanvasPart final : public QQuickItem
{
public:
    enum class Role { Layer, Live };

    CanvasPart(CurveCanvas *canvas, Role role)
        : QQuickItem(canvas)
        , m_canvas(canvas)
        , m_role(role)
    {
        setFlag(ItemHasContents, true);
        setTransformOrigin(TopLeft);
        setObjectName(role == Role::Layer ? QStringLiteral("canvasLayer") : QStringLiteral("canvasLive"));
    }

protected:
    QSGNode *updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *) override
    {
        return m_role == Role::Layer ? m_canvas->updateLayerNode(oldNode) : m_canvas->updateLiveNode(oldNode);
    }

private:
    CurveCanvas *m_canvas;
    Role m_role;
};

CurveCanvas::CurveCanvas(QQuickItem *parent)
    : QQuickItem(parent)
    , m_layerPart(new CanvasPart(this, CanvasPart::Role::Layer))
    , m_livePart(new CanvasPart(this, CanvasPart::Role::Live))
{
    setFlag(ItemHasContents, true);
    connect(this, &CurveCanvas::styleChanged, this, [this] {
        layerChanged();
        repaint();
    });
    // The layer is drawn sharp again once a gesture pauses this long.
    m_settleTimer.setSingleShot(true);
    m_settleTimer.setInterval(150);
    connect(&m_settleTimer, &QTimer::timeout, this, [this] {
        m_viewSettled = true;
        freezeLayerView();
        repaint();
    });
}

void CurveCanvas::repaint()
{
    // The layer's texture is only worth drawing when it has curves: some other than the selected one.
    const std::size_t curves = m_controller ? m_controller->document()->curves().size() : 0;
    // A layer painted as a picture also carries the grid.
    m_layerPart->setVisible(m_gpu && (curves > 1 || (curves == 1 && m_controller->selectedCurve() != 0) ||
                                      (imageLayerActive() && m_showGrid)));
    update();
    m_layerPart->update();
    m_livePart->update();
}

void CurveCanvas::setLayered(bool layered)
{
    if (layered == m_layered)
        return;
    m_layered = layered;
    applyLayered();
    Q_EMIT layeredChanged();
}

void CurveCanvas::applyLayered()
{
    if (m_layer)
        m_layer->setProperty("enabled", m_gpu && m_layered && !m_imageLayer);
    freezeLayerView();
    repaint();
}

QString CurveCanvas::layerKind() const
{
    if (!window())
        return {};
    if (!m_gpu)
        return QStringLiteral("painter");
    if (!m_rasterizerKnown)
        return {}; // decided at the first frame
    return m_imageLayer ? QStringLiteral("picture") : QStringLiteral("texture");
}

QRectF CurveCanvas::layerWorld() const
{
    // The world the layer shows (the view and the margin around it), and a little more.
    const QPointF half((width() / 2.0 + m_layerMargin + 50.0) / m_layerZoom,
                       (height() / 2.0 + m_layerMargin + 50.0) / m_layerZoom);
    return {m_layerCenter - half, m_layerCenter + half};
}

bool CurveCanvas::isSoftware() const
{
    return window() && window()->rendererInterface()->graphicsApi() == QSGRendererInterface::Software;
}

void CurveCanvas::freezeLayerView()
{
    m_layerZoom = m_zoom;
    m_layerCenter = m_center;
    // The layer covers the view and a margin, so that pans and zooming out show no empty border.
    m_layerMargin = std::ceil(0.25 * std::max(width(), height()));
    m_layerPart->setSize(QSizeF(width() + 2.0 * m_layerMargin, height() + 2.0 * m_layerMargin));
    m_livePart->setSize(size());
    placeLayer();
    m_layerPart->update();
}

void CurveCanvas::placeLayer()
{
    // A world point p is at m + (p - c')·z' in the layer (m: the layer's centre, c' and z' its
    // view) and at h + (p - c)·z on the canvas (h: the canvas's centre), y flipped in both: the
    // layer is scaled by z / z' about its top-left corner and moved so that the two agree.
    const double k = m_zoom / m_layerZoom;
    const double mx = width() / 2.0 + m_layerMargin, my = height() / 2.0 + m_layerMargin;
    // Texels go to pixels one to one while the view is the layer's (nearest is exact and cheaper
    // for a software rasterizer); a scaled layer is filtered.
    if (m_layer)
        m_layer->setProperty("smooth", k != 1.0);
    m_layerPart->setScale(k);
    m_layerPart->setPosition(QPointF(width() / 2.0 + (m_layerCenter.x() - m_center.x()) * m_zoom - mx * k,
                                     height() / 2.0 - (m_layerCenter.y() - m_center.y()) * m_zoom - my * k));
}

void CurveCanvas::setController(EditController *controller)
{
    if (controller == m_controller)
        return;
    if (m_controller) {
        disconnect(m_controller, nullptr, this, nullptr);
        disconnect(m_controller->document(), nullptr, this, nullptr);
    }
    m_controller = controller;
    if (m_controller) {
        connect(m_controller->document(), &Document::changed, this, &CurveCanvas::repaint);
        connect(m_controller->document(), &Document::backgroundChanged, this, &CurveCanvas::reloadBackground);
        // Only what changed is flattened again.
        connect(m_controller->document(), &Document::rowsChanged, this,
                [this](int curve, int, int) { invalidateFlat(curve); });
        connect(m_controller->document(), &Document::curveChanged, this, &CurveCanvas::invalidateFlat);
        for (auto signal : {&Document::curveInserted, &Document::curveRemoved})
            connect(m_controller->document(), signal, this, [this](int) { invalidateAllFlat(); });
        connect(m_controller->document(), &Document::curveMoved, this, [this](int, int) { invalidateAllFlat(); });
        connect(m_controller, &EditController::pendingChanged, this, &CurveCanvas::repaint);
        connect(m_controller, &EditController::hoverChanged, this, &CurveCanvas::repaint);
        connect(m_controller, &EditController::selectionChanged, this, &CurveCanvas::repaint);
        connect(m_controller, &EditController::modeChanged, this, &CurveCanvas::repaint);
    }
    reloadBackground();
    Q_EMIT controllerChanged();
    repaint();
}

void CurveCanvas::setHitRadius(double radius)
{
    if (!(radius > 0.0) || radius == m_hitRadius)
        return;
    m_hitRadius = radius;
    Q_EMIT styleChanged();
}

void CurveCanvas::invalidateFlat(int curve)
{
    if (curve >= 0 && static_cast<std::size_t>(curve) < m_flat.size()) {
        m_flat[static_cast<std::size_t>(curve)].valid = false;
        m_flat[static_cast<std::size_t>(curve)].boundsValid = false;
    }
    // Only a change to a curve in the software layer paints the layer again (a dragged curve is
    // the selected one, drawn live over it).
    if (curve != m_layerExcluded)
        layerChanged();
}

void CurveCanvas::invalidateAllFlat()
{
    m_flat.clear();
    layerChanged();
}

QString CurveCanvas::graphicsApi() const
{
    if (!window() || !window()->rendererInterface())
        return {};
    switch (window()->rendererInterface()->graphicsApi()) {
    case QSGRendererInterface::Software:
        return QStringLiteral("software");
    case QSGRendererInterface::OpenGL:
        return QStringLiteral("opengl");
    case QSGRendererInterface::Vulkan:
        return QStringLiteral("vulkan");
    default:
        return QStringLiteral("other");
    }
}

QPointF CurveCanvas::toWorld(QPointF screen) const
{
    return {m_center.x() + (screen.x() - width() / 2.0) / m_zoom,
            m_center.y() - (screen.y() - height() / 2.0) / m_zoom};
}

QPointF CurveCanvas::toScreen(QPointF world) const
{
    return {width() / 2.0 + (world.x() - m_center.x()) * m_zoom, height() / 2.0 - (world.y() - m_center.y()) * m_zoom};
}

void CurveCanvas::setView(double zoom, QPointF center, bool gesture)
{
    zoom = std::clamp(zoom, minimumZoom(), maximumZoom());
    if (!std::isfinite(zoom) || !std::isfinite(center.x()) || !std::isfinite(center.y()))
        return;
    if (zoom == m_zoom && center == m_center)
        return;
    m_zoom = zoom;
    m_center = center;
    // A drawing small enough to be drawn again at every step of a gesture stays sharp throughout;
    // a large one shows its cached layer moved and scaled until the view rests. Without the
    // layer's texture the curves are drawn at the current view at once anyway.
    const bool cached = gesture && m_layered && segmentTotal() > kSharpGestureSegments;
    m_viewSettled = !cached;
    if (cached) {
        m_settleTimer.start();
        placeLayer();
    } else {
        freezeLayerView();
    }
    Q_EMIT viewChanged();
    repaint();
}

std::size_t CurveCanvas::segmentTotal() const
{
    std::size_t total = 0;
    if (m_controller)
        for (const Curve &curve : m_controller->document()->curves())
            total += static_cast<std::size_t>(std::max(curve.segmentCount(), 0));
    return total;
}

void CurveCanvas::keepAt(QPointF world, QPointF screen, bool gesture)
{
    // Solve toScreen(world) == screen for the centre at the current zoom.
    setView(
        m_zoom,
        QPointF(world.x() - (screen.x() - width() / 2.0) / m_zoom, world.y() + (screen.y() - height() / 2.0) / m_zoom),
        gesture);
}

void CurveCanvas::zoomBy(double factor, QPointF anchor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    // A step of a continuous zoom (the wheel): on large drawings the cached layer is shown scaled
    // until it settles.
    const QPointF world = toWorld(anchor);
    setView(m_zoom * factor, m_center, true);
    keepAt(world, anchor, true);
}

void CurveCanvas::zoomIn()
{
    const QPointF anchor(width() / 2.0, height() / 2.0);
    const QPointF world = toWorld(anchor);
    setView(m_zoom * 1.25, m_center);
    keepAt(world, anchor, false);
}

void CurveCanvas::zoomOut()
{
    const QPointF anchor(width() / 2.0, height() / 2.0);
    const QPointF world = toWorld(anchor);
    setView(m_zoom / 1.25, m_center);
    keepAt(world, anchor, false);
}

void CurveCanvas::panBy(QPointF delta)
{
    setView(m_zoom, QPointF(m_center.x() - delta.x() / m_zoom, m_center.y() + delta.y() / m_zoom), true);
}

void CurveCanvas::resetView()
{
    setView(1.0, QPointF());
}

void CurveCanvas::fitToView()
{
    double minX = std::numeric_limits<double>::infinity(), minY = minX;
    double maxX = -minX, maxY = -minX;
    auto include = [&](const geo::Point &p) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    };
    if (m_controller) {
        for (const Curve &curve : m_controller->document()->curves()) {
            if (!curve.visible)
                continue;
            for (int r = 0; r < curve.rowCount(); ++r)
                include(curve.row(r).position);
        }
        std::for_each(m_controller->pendingPoints().begin(), m_controller->pendingPoints().end(), include);
    }
    if (!(minX <= maxX)) {
        resetView();
        return;
    }
    // Leave a margin of a touch target around the drawing so every point stays reachable.
    const double margin = 2.0 * m_hitRadius;
    const double w = std::max(width() - 2.0 * margin, 1.0);
    const double h = std::max(height() - 2.0 * margin, 1.0);
    const double spanX = maxX - minX, spanY = maxY - minY;
    double zoom = m_zoom;
    if (spanX > 0.0 || spanY > 0.0)
        zoom = std::min(spanX > 0.0 ? w / spanX : maximumZoom(), spanY > 0.0 ? h / spanY : maximumZoom());
    setView(zoom, QPointF((minX + maxX) / 2.0, (minY + maxY) / 2.0));
}

void CurveCanvas::tapAt(QPointF position)
{
    if (m_controller)
        m_controller->tap(toWorld(position), hitRadiusWorld());
}

void CurveCanvas::dragStarted(QPointF pressPosition, bool constrained)
{
    if (!m_controller)
        return;
    if (m_controller->beginDrag(toWorld(pressPosition), hitRadiusWorld(), constrained)) {
        m_draggingPoint = true;
        return;
    }
    // One finger or the left button on empty canvas pans, except while placing points.
    if (m_controller->mode() == EditController::Mode::Select) {
        m_anchorWorld = toWorld(pressPosition);
        m_panning = true;
        Q_EMIT panningChanged();
    }
}

void CurveCanvas::dragMoved(QPointF position)
{
    if (m_draggingPoint && m_controller)
        m_controller->dragTo(toWorld(position));
    else if (m_panning)
        keepAt(m_anchorWorld, position);
}

void CurveCanvas::dragEnded()
{
    if (m_draggingPoint && m_controller)
        m_controller->endDrag();
    m_draggingPoint = false;
    if (m_panning) {
        m_panning = false;
        Q_EMIT panningChanged();
    }
}

void CurveCanvas::hoverAt(QPointF position)
{
    if (m_controller)
        m_controller->hover(toWorld(position));
}

void CurveCanvas::hoverEnded()
{
    if (m_controller)
        m_controller->clearHover();
}

void CurveCanvas::pinchStarted(QPointF centroid)
{
    // A second finger ends a one-finger gesture: the pinch owns the view now.
    dragEnded();
    m_pinchStartZoom = m_zoom;
    m_anchorWorld = toWorld(centroid);
}

void CurveCanvas::pinchUpdated(double scale, QPointF centroid)
{
    // Zoom about the fingers' centroid and follow it: the world point first under the centroid
    // stays under it, which is pan and zoom in one.
    if (!(scale > 0.0) || !std::isfinite(scale))
        return;
    setView(m_pinchStartZoom * scale, m_center, true);
    keepAt(m_anchorWorld, centroid, true);
}

void CurveCanvas::pinchEnded() {}

void CurveCanvas::wheelAt(QPointF position, double angleDeltaY)
{
    // One notch (120 eighths of a degree) zooms by 20 %; touchpads send smaller steps.
    zoomBy(std::pow(1.2, angleDeltaY / 120.0), position);
}

void CurveCanvas::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickItem::geometryChange(newGeometry, oldGeometry);
    if (newGeometry.size() != oldGeometry.size())
        freezeLayerView();
    repaint();
}

void CurveCanvas::itemChange(ItemChange change, const ItemChangeData &value)
{
    QQuickItem::itemChange(change, value);
    if (change == ItemSceneChange && value.window) {
        connect(value.window, &QQuickWindow::sceneGraphInitialized, this, &CurveCanvas::graphicsApiChanged,
                Qt::UniqueConnection);
        // Emitted on the render thread while the GUI thread waits: counts the syncs, so that the
        // screen lists are built once per frame for the canvas and its parts.
        connect(
            value.window, &QQuickWindow::beforeSynchronizing, this, [this] { ++m_syncSerial; }, Qt::DirectConnection);
        // GPU backends draw the layer part into a texture of its own (Qt Quick's item layer, set
        // through its meta-object: QQuickItemLayer is not public API).
        m_gpu = !isSoftware();
        m_layer = qvariant_cast<QObject *>(m_layerPart->property("layer"));
        applyLayered();
        Q_EMIT graphicsApiChanged();
        Q_EMIT layerKindChanged();
    }
}

double CurveCanvas::gridStep() const
{
    return gridStepAt(m_zoom);
}

double CurveCanvas::gridStepAt(double zoom)
{
    // The smallest of 1, 2, 5 × 10^k world units that is at least 40 px on screen.
    const double minimum = 40.0 / zoom;
    const double power = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * power >= minimum)
            return factor * power;
    return 10.0 * power;
}

void CurveCanvas::addGrid(DisplayList &list, double zoom, QPointF center, QSizeF size) const
{
    // World lines x = k·step and y = k·step across the visible area, and the axes through the
    // world origin (y up, SPEC.md 2); the background picture stays visible under them.
    const double step = gridStepAt(zoom);
    const double width = size.width(), height = size.height();
    const ViewState view{zoom, center, size};
    const geo::Point topLeft = view.toWorld(QPointF(0, 0));
    const geo::Point bottomRight = view.toWorld(QPointF(width, height));
    const double x0 = std::floor(topLeft.x() / step) * step, x1 = bottomRight.x();
    const double y0 = std::floor(bottomRight.y() / step) * step, y1 = topLeft.y();
    for (double x = x0; x <= x1; x += step) {
        const double sx = view.toScreen(geo::Point(x, 0.0)).x();
        list.strokes.push_back({{QPointF(sx, 0), QPointF(sx, height)}, m_gridColor, 1.0F, false});
    }
    for (double y = y0; y <= y1; y += step) {
        const double sy = view.toScreen(geo::Point(0.0, y)).y();
        list.strokes.push_back({{QPointF(0, sy), QPointF(width, sy)}, m_gridColor, 1.0F, false});
    }
    const QPointF origin = view.toScreen(geo::Point(0.0, 0.0));
    if (origin.x() >= 0 && origin.x() <= width)
        list.strokes.push_back({{QPointF(origin.x(), 0), QPointF(origin.x(), height)}, m_axisColor, 1.0F, false});
    if (origin.y() >= 0 && origin.y() <= height)
        list.strokes.push_back({{QPointF(0, origin.y()), QPointF(width, origin.y())}, m_axisColor, 1.0F, false});
}

QRectF CurveCanvas::visibleWorld(double margin) const
{
    const QPointF a = toWorld(QPointF(-margin, -margin));
    const QPointF b = toWorld(QPointF(width() + margin, height() + margin));
    return QRectF(QPointF(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                  QPointF(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
}

bool CurveCanvas::curveMeets(std::size_t c, const QRectF &worldRect)
{
    FlatCache &cache = m_flat[c];
    if (!cache.boundsValid) {
        // The curve lies in the hull of its segments' control points.
        const Curve &curve = m_controller->document()->curves()[c];
        double minX = std::numeric_limits<double>::infinity(), minY = minX;
        double maxX = -minX, maxY = -minX;
        for (int s = 0; s < curve.segmentCount(); ++s) {
            const geo::Bezier segment = curve.segment(s);
            for (const geo::Point &p : segment.controlPoints()) {
                minX = std::min(minX, p.x());
                maxX = std::max(maxX, p.x());
                minY = std::min(minY, p.y());
                maxY = std::max(maxY, p.y());
            }
        }
        cache.bounds = minX <= maxX ? QRectF(QPointF(minX, minY), QPointF(maxX, maxY)) : QRectF();
        cache.boundsValid = true;
    }
    const QRectF &b = cache.bounds;
    return !b.isNull() && b.left() <= worldRect.right() && b.right() >= worldRect.left() &&
           b.top() <= worldRect.bottom() && b.bottom() >= worldRect.top();
}

bool CurveCanvas::ensureFlat(std::size_t c, double zoom)
{
    // Flattened in world units to an eighth of a pixel at the zoom it was made for, and reused
    // while the zoom stays below twice that (error at most a quarter pixel) and not far above
    // it (no needless points): pans and zoom steps within the band change no vertex.
    FlatCache &cache = m_flat[c];
    if (cache.valid && cache.world && zoom <= 2.0 * cache.zoom && zoom >= cache.zoom / 4.0)
        return false;
    const Curve &curve = m_controller->document()->curves()[c];
    auto world = std::make_shared<std::vector<geo::Point>>();
    for (int s = 0; s < curve.segmentCount(); ++s)
        flattenWithin(curve.segment(s), 0.125 / zoom, *world);
    cache.world = std::move(world);
    cache.zoom = zoom;
    cache.valid = true;
    cache.version = ++m_flatVersion;
    return true;
}

const CurveCanvas::ScreenLists &CurveCanvas::screenLists(bool software)
{
    if (m_listsSerial == m_syncSerial && m_syncSerial != 0)
        return m_lists;
    m_listsSerial = m_syncSerial;
    const std::size_t count = m_controller ? m_controller->document()->curves().size() : 0;
    if (m_flat.size() != count)
        m_flat.assign(count, FlatCache{});
    buildScreenLists(m_lists, software);
    return m_lists;
}

void CurveCanvas::buildScreenLists(ScreenLists &lists, bool software)
{
    lists.grid.clear();
    lists.guides.clear();
    lists.top.clear();
    lists.live.clear();
    if (m_showGrid && width() > 0 && height() > 0)
        addGrid(lists.grid, m_zoom, m_center, size());
    if (!m_controller)
        return;
    const auto screen = [this](const geo::Point &p) { return toScreen(QPointF(p.x(), p.y())); };
    const QRectF visible = boundingRect().adjusted(-50, -50, 50, 50);
    const auto &curves = m_controller->document()->curves();
    const int selected = m_controller->selectedCurve();
    const auto ringWidth = static_cast<float>(std::max(1.5, m_curveWidth * 0.75));
    const auto radius = static_cast<float>(m_pointRadius);
    const ViewState view{m_zoom, m_center, size()};

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
    const double cell = std::max(2.0, m_pointRadius * 0.75);
    const double reach = 2.0 * m_pointRadius + 4.0;
    const QRectF markerArea = boundingRect().adjusted(-reach, -reach, reach, reach);
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
            top.discs.push_back({at, radius + 4.0F, m_accentColor});
        if (role == PointRole::Knot) {
            top.discs.push_back({at, radius, m_curveColor});
            return;
        }
        if (role == PointRole::TangentEnd) {
            // Tangent ends are diamonds, so that shape and not only colour tells them apart.
            const double r = m_pointRadius * 1.3;
            const std::vector<QPointF> diamond{at + QPointF(0, -r), at + QPointF(r, 0), at + QPointF(0, r),
                                               at + QPointF(-r, 0)};
            top.discs.push_back({at, radius * 0.8F, QColor(Qt::white)});
            top.overlay.push_back({diamond, m_tangentColor, ringWidth, true});
            return;
        }
        top.discs.push_back({at, radius, QColor(Qt::white)});
        top.rings.push_back(
            {at, radius, ringWidth, editable ? m_controlPointColor : withAlpha(m_controlPointColor, 0.45)});
    };

    // Points of every curve while there are few; on large documents only those of the selected curve,
    // which keeps big drawings fast and readable.
    std::size_t totalRows = 0;
    for (const Curve &curve : curves)
        if (curve.visible)
            totalRows += static_cast<std::size_t>(curve.rowCount());
    const bool showAllPoints = totalRows <= kAllPointsLimit;

    // Software: the selected curve is drawn live over the cached layer, with its halo under the guides.
    if (software && selected >= 0 && static_cast<std::size_t>(selected) < curves.size()) {
        const auto c = static_cast<std::size_t>(selected);
        const Curve &curve = curves[c];
        if (curve.visible && curve.rowCount() > 0 && curveMeets(c, visibleWorld(50))) {
            ensureFlat(c, m_zoom);
            std::vector<QPointF> line;
            toScreenPolyline(*m_flat[c].world, view, line);
            if (line.size() >= 2) {
                lists.live.strokes.push_back(
                    {line, withAlpha(m_accentColor, 0.3), static_cast<float>(m_curveWidth + 6.0), false});
            }
        }
    }

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
        int last = -1;
        for (const auto &[from, to] : curve.guides()) {
            const QPointF &end = rows[static_cast<std::size_t>(to)];
            if (from == last)
                guides.back().points.push_back(end);
            else
                guides.push_back({{rows[static_cast<std::size_t>(from)], end}, m_polygonColor, 1.0F, false});
            last = to;
        }
        for (int r = 0; r < curve.rowCount(); ++r) {
            const PointRow row = curve.row(r);
            marker(rows[static_cast<std::size_t>(r)], row.role, row.editable,
                   isSelectedCurve && r == m_controller->selectedPoint());
        }
    }

    // Software: the selected curve's line over its guides.
    if (software && selected >= 0 && static_cast<std::size_t>(selected) < curves.size()) {
        const auto c = static_cast<std::size_t>(selected);
        const Curve &curve = curves[c];
        if (curve.visible && curve.rowCount() > 0 && m_flat[c].world && curveMeets(c, visibleWorld(50))) {
            std::vector<QPointF> line;
            toScreenPolyline(*m_flat[c].world, view, line);
            if (line.size() >= 2)
                lists.live.strokes.push_back(
                    {std::move(line), curve.color, static_cast<float>(m_curveWidth), curve.isClosed()});
        }
    }

    // The curve being placed: its points, the preview the kind allows, and the seed's dashed
    // rubber band from the last point to the pointer.
    const auto &pending = m_controller->pendingPoints();
    if (!pending.empty()) {
        const auto kind = static_cast<CurveKind>(m_controller->placementKind());
        const PointRole role = kind == CurveKind::Bezier ? PointRole::ControlPoint : PointRole::Knot;
        std::vector<QPointF> polygon;
        for (const geo::Point &p : pending)
            polygon.push_back(screen(p));
        if (kind == CurveKind::Bezier)
            top.strokes.push_back({polygon, m_polygonColor, 1.0F, false});
        flat.clear();
        for (const geo::Bezier &segment : m_controller->pendingSegments())
            flattenOnScreen(segment);
        if (flat.size() >= 2)
            top.strokes.push_back({polyline(), m_curveColor, static_cast<float>(m_curveWidth), false});
        for (const QPointF &at : polygon)
            marker(at, role, true, false);
        if (m_controller->hasHover()) {
            const std::vector<QPointF> band{polygon.back(), screen(m_controller->hoverPoint())};
            for (auto &dash : dashed(band, 6.0, 4.0))
                top.strokes.push_back({std::move(dash), m_polygonColor.darker(130), 1.0F, false});
        }
    }
}

namespace {

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

    // Software rasterizers: the layer as a painted picture instead of the chunks.
    QSGImageNode *image = nullptr;
    QImage picture;
    // What the picture shows, to tell when it must be painted again.
    struct Painted
    {
        std::vector<ShownCurve> curves;
        ViewState view;
        double margin = 0.0;
        qreal pixelRatio = 0.0;
        bool grid = false;
        QRgb gridColor = 0, axisColor = 0;
        bool operator==(const Painted &) const = default;
    } painted;
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

} // namespace

void CurveCanvas::reloadBackground()
{
    const QString file = m_controller ? m_controller->document()->background().file : QString();
    if (file == m_backgroundFile)
        return;
    m_backgroundFile = file;
    m_backgroundImage = QImage();
    if (!file.isEmpty()) {
        QImageReader reader(file);
        QImageReader::setAllocationLimit(512); // MiB: a hostile file cannot exhaust memory
        reader.setAutoTransform(true);
        m_backgroundImage = reader.read();
    }
    m_backgroundDirty = true;
    repaint();
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
            const QPointF topLeft = toScreen(background->origin);
            const QPointF size(m_backgroundImage.width() * background->scale * m_zoom,
                               m_backgroundImage.height() * background->scale * m_zoom);
            root->background->setRect(QRectF(topLeft, QSizeF(size.x(), size.y())));
            // Turned about its top-left corner, counter-clockwise in the world (clockwise angles on
            // the screen, whose y points down).
            QMatrix4x4 turn;
            turn.translate(float(topLeft.x()), float(topLeft.y()));
            turn.rotate(float(-background->rotation), 0.0F, 0.0F, 1.0F);
            turn.translate(float(-topLeft.x()), float(-topLeft.y()));
            root->backgroundTurn->setMatrix(turn);
        }
    }

    const int selected = m_controller ? m_controller->selectedCurve() : -1;
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
            for (std::size_t c = 0; c < curves.size(); ++c) {
                const Curve &curve = curves[c];
                if (static_cast<int>(c) == selected || !curve.visible || curve.rowCount() == 0 || !curveMeets(c, area))
                    continue;
                reflattened += ensureFlat(c, m_zoom) ? 1 : 0;
                node->layerCurves.push_back({m_flat[c].world, curve.color, curve.isClosed()});
            }
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
    if (curveMeets(c, area) && ensureFlat(c, zoom) && reflattened)
        ++*reflattened;
    if (!m_flat[c].world)
        return {};
    return {m_flat[c].version, color.rgba(), strokeWidth, curve.isClosed()};
}

ShownCurve CurveCanvas::shownSelected()
{
    const int selected = m_controller ? m_controller->selectedCurve() : -1;
    if (selected < 0 || static_cast<std::size_t>(selected) >= m_flat.size())
        return {};
    const auto c = static_cast<std::size_t>(selected);
    return shownCurve(c, m_controller->document()->curves()[c].color, static_cast<float>(m_curveWidth), m_zoom,
                      visibleWorld(50.0), nullptr);
}

StrokePath CurveCanvas::strokePath(std::size_t c, const ShownCurve &shown) const
{
    return {m_flat[c].world.get(), shown.closed, QColor::fromRgba(shown.color), shown.width};
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
        root->painted = {};
    }
    const QSizeF size(width() + 2.0 * m_layerMargin, height() + 2.0 * m_layerMargin);
    const bool viewChanged =
        root->view.zoom != m_layerZoom || root->view.center != m_layerCenter || root->view.size != size;
    root->view = {m_layerZoom, m_layerCenter, size};
    const QRectF area = layerWorld();

    const auto &curves = m_controller->document()->curves();
    const std::size_t curveCount = curves.size();
    const int selected = m_controller->selectedCurve();
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
    std::size_t reflattened = 0, uploaded = 0, vertices = 0;
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

    // What the picture would show now: the grid and the curves other than the selected one, at
    // the layer's view.
    LayerRootNode::Painted now;
    now.view = {m_layerZoom, m_layerCenter, size()};
    now.margin = m_layerMargin;
    now.pixelRatio = window()->effectiveDevicePixelRatio();
    now.grid = m_showGrid;
    now.gridColor = m_gridColor.rgba();
    now.axisColor = m_axisColor.rgba();
    const auto &curves = m_controller->document()->curves();
    const int selected = m_controller->selectedCurve();
    const auto width = static_cast<float>(m_curveWidth);
    const QSizeF size(this->width() + 2.0 * m_layerMargin, height() + 2.0 * m_layerMargin);
    const QRectF area = layerWorld();
    std::size_t reflattened = 0;
    now.curves.reserve(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c)
        now.curves.push_back(static_cast<int>(c) == selected
                                 ? ShownCurve{}
                                 : shownCurve(c, curves[c].color, width, m_layerZoom, area, &reflattened));

    const bool repaint = !root->image || !(now == root->painted);
    if (repaint) {
        const QSize pixels(static_cast<int>(std::ceil(size.width() * now.pixelRatio)),
                           static_cast<int>(std::ceil(size.height() * now.pixelRatio)));
        if (root->picture.size() != pixels)
            root->picture = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
        root->picture.fill(Qt::transparent);
        QPainter painter(&root->picture);
        if (now.grid) {
            DisplayList grid;
            addGrid(grid, m_layerZoom, m_layerCenter, size);
            painter.save();
            painter.scale(now.pixelRatio, now.pixelRatio);
            paint(grid, painter);
            painter.restore();
        }
        std::vector<LayerCurve> shown;
        for (std::size_t c = 0; c < curves.size(); ++c)
            if (now.curves[c].version != 0)
                shown.push_back({m_flat[c].world, curves[c].color, curves[c].isClosed()});
        paintLayerCurves(painter, shown, now.view, m_layerMargin, now.pixelRatio, width);
        painter.end();
        if (!root->image) {
            root->image = window()->createImageNode();
            root->image->setOwnsTexture(true);
            root->appendChildNode(root->image);
        }
        root->image->setTexture(window()->createTextureFromImage(root->picture));
        root->image->setRect(QRectF(QPointF(0, 0), size));
        root->painted = std::move(now);
    }
    // Pixel for pixel while the view is the layer's (a copy); filtered while it is scaled.
    root->image->setFiltering(m_zoom == m_layerZoom ? QSGTexture::Nearest : QSGTexture::Linear);
    if (profiling)
        qInfo("sync: layer picture %.2f ms, %zu curves re-flattened%s",
              static_cast<double>(profile.nsecsElapsed()) / 1e6, reflattened, repaint ? ", painted" : "");
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
        const auto c = static_cast<std::size_t>(m_controller->selectedCurve());
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
