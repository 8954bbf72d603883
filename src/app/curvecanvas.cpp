// CurveCanvas: the view, gesture routing, and each frame's nodes on both backends.
// Over 600 lines because it is the one QQuickItem between QML and the painters: 46 short members
// (view transform, gesture routing to the tools, the frame's scene-graph nodes on the software and
// GPU backends) that all read the same view state; the drawing itself lives in the painters and in
// scenebuilder.cpp.
#include "app/curvecanvas.h"

#include "app/canvasnodes.h"

#include "models/controllers/editcontroller.h"
#include "picture/picture.h"
#include "models/document/document.h"
#include "models/trace/perspective.h"

#include <QQuickItemGrabResult>
#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

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
    m_layerPart->setVisible(m_gpu && (curves > 1 || (curves == 1 && m_controller->selection()->curveRow() != 0) ||
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
        // The flattenings follow the rows: an inserted curve is the only one flattened anew.
        connect(m_controller->document(), &Document::curveInserted, this, [this](int row) {
            m_flat.insertRow(row);
            layerChanged();
        });
        connect(m_controller->document(), &Document::curveRemoved, this, [this](int row) {
            m_flat.removeRow(row);
            layerChanged();
        });
        connect(m_controller->document(), &Document::curveMoved, this, [this](int from, int to) {
            m_flat.moveRow(from, to);
            layerChanged();
        });
        connect(m_controller->placement(), &Placement::pendingChanged, this, &CurveCanvas::repaint);
        connect(m_controller->placement(), &Placement::hoverChanged, this, &CurveCanvas::repaint);
        connect(m_controller->selection(), &Selection::changed, this, &CurveCanvas::repaint);
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
    m_flat.invalidate(curve);
    // Only a change to a curve in the software layer paints the layer again (a dragged curve is
    // the selected one, drawn live over it).
    if (curve != m_layerExcluded)
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
    const geo::Point world = view().toWorld(screen);
    return {world.x(), world.y()};
}

QPointF CurveCanvas::toScreen(QPointF world) const
{
    return view().toScreen(geo::Point(world.x(), world.y()));
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

void CurveCanvas::beginPicture(bool wholeDocument)
{
    if (!m_picture)
        m_picture = PictureState{m_layered, wholeDocument, m_zoom, m_center};
    setLayered(false);
    if (wholeDocument)
        fitToView();
}

void CurveCanvas::endPicture()
{
    if (!m_picture)
        return;
    const PictureState state = *m_picture;
    m_picture.reset();
    setLayered(state.layered);
    if (state.wholeDocument)
        setView(state.zoom, state.center);
}

bool CurveCanvas::makePicture(QSize size, bool wholeDocument, std::function<void(const QImage &)> done)
{
    if (size.isEmpty() || !done)
        return false;
    beginPicture(wholeDocument);
    const QSharedPointer<QQuickItemGrabResult> grab = grabToImage(size);
    if (!grab) {
        endPicture();
        return false;
    }
    const QPointer<CurveCanvas> self(this);
    connect(grab.data(), &QQuickItemGrabResult::ready, this, [self, keep = grab, done = std::move(done)]() mutable {
        if (self)
            self->endPicture();
        done(keep->image());
        // The result may not be deleted while it is still emitting: drop it from the event loop.
        QTimer::singleShot(0, [gone = std::move(keep)] {});
    });
    return true;
}

void CurveCanvas::fitToView()
{
    fitToViewWith(QRectF());
}

void CurveCanvas::fitToViewWith(const QRectF &extra)
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
        std::for_each(m_controller->placement()->pendingPoints().begin(),
                      m_controller->placement()->pendingPoints().end(), include);
    }
    if (!extra.isNull()) {
        include(geo::Point(extra.left(), extra.top()));
        include(geo::Point(extra.right(), extra.bottom()));
    }
    // With no curve, the background picture is what there is to see (and to trace).
    const Background *background = m_controller ? &m_controller->document()->background() : nullptr;
    if (!(minX <= maxX) && background && background->visible && !m_backgroundImage.isNull()) {
        const QRectF drawn = perspective::drawnRect(*background, m_backgroundImage.size());
        for (const QPointF &corner : {drawn.topLeft(), drawn.topRight(), drawn.bottomLeft(), drawn.bottomRight()})
            include(background->toWorld(corner));
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
        m_controller->placement()->hover(toWorld(position));
}

void CurveCanvas::hoverEnded()
{
    if (m_controller)
        m_controller->placement()->clearHover();
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
    // A bar opening or closing under the canvas (the trace bar, the teaching bar) changes its height
    // in a window of the same size: the world stays under every pixel (the top edge is held), so that
    // opening a bar moves nothing the user looks at. A window resize keeps the centre, as before.
    const double windowHeight = window() ? window()->height() : 0.0;
    if (newGeometry.height() != oldGeometry.height() && oldGeometry.height() > 0.0 && newGeometry.height() > 0.0 &&
        newGeometry.top() == oldGeometry.top() && windowHeight == m_windowHeight && m_zoom > 0.0) {
        m_center.setY(m_center.y() + (oldGeometry.height() - newGeometry.height()) / (2.0 * m_zoom));
        Q_EMIT viewChanged();
    }
    m_windowHeight = windowHeight;
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
        // GPU backends draw the layer part into a texture of its own: Qt Quick's item layer.
        // property("layer") is the only public way to it in Qt 6.4 (QQuickItemLayer is private API).
        m_gpu = !isSoftware();
        m_layer = qvariant_cast<QObject *>(m_layerPart->property("layer"));
        applyLayered();
        Q_EMIT graphicsApiChanged();
        Q_EMIT layerKindChanged();
    }
}

void CurveCanvas::followWorldMapping(double scale, double radians)
{
    if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(radians))
        return;
    // The centre maps like every world point; the zoom shrinks by the scale, so screen distances stay.
    const double c = std::cos(radians), s = std::sin(radians);
    const QPointF center = m_center;
    setView(m_zoom / scale, scale * QPointF(c * center.x() - s * center.y(), s * center.x() + c * center.y()));
}

double CurveCanvas::gridStep() const
{
    return gridStepAt(m_zoom);
}

const ScreenLists &CurveCanvas::screenLists(bool software)
{
    if (m_listsSerial == m_syncSerial && m_syncSerial != 0)
        return m_lists;
    m_listsSerial = m_syncSerial;
    const std::size_t count = m_controller ? m_controller->document()->curves().size() : 0;
    m_flat.resize(count);
    SceneInput input;
    input.view = view();
    input.software = software;
    if (m_controller) {
        input.curves = &m_controller->document()->curves();
        input.selectedCurve = m_controller->selection()->curveRow();
        input.selectedPoint = m_controller->selection()->point();
        // Software: the selected curve is drawn with the lists, where it can be seen.
        const int selected = input.selectedCurve;
        if (software && selected >= 0 && static_cast<std::size_t>(selected) < count) {
            const auto c = static_cast<std::size_t>(selected);
            const Curve &curve = curveAt(c);
            if (const QRectF seen = visibleWorld(50); curve.visible && curve.rowCount() > 0 && curveMeets(c, seen)) {
                ensureFlat(c, m_zoom, seen);
                input.selectedFlat = m_flat.world(c).get();
            }
        }
        input.pendingPoints = &m_controller->placement()->pendingPoints();
        if (!m_controller->placement()->pendingPoints().empty()) {
            input.pendingSegments = m_controller->placement()->pendingSegments();
            input.placementKind = static_cast<CurveKind>(m_controller->placement()->kind());
            if (m_controller->placement()->hasHover())
                input.hover = m_controller->placement()->hoverPoint();
        }
    }
    buildScene(input, sceneStyle(), m_lists);
    return m_lists;
}

std::vector<std::size_t> CurveCanvas::curvesMeeting(const QRectF &worldRect, int except)
{
    const auto &curves = m_controller->document()->curves();
    std::vector<std::size_t> meeting;
    for (std::size_t c = 0; c < curves.size(); ++c)
        if (static_cast<int>(c) != except && curves[c].visible && curves[c].rowCount() > 0 && curveMeets(c, worldRect))
            meeting.push_back(c);
    return meeting;
}

std::size_t CurveCanvas::flattenMeeting(const QRectF &worldRect, double zoom, int except)
{
    return m_flat.ensureMany(curvesMeeting(worldRect, except), m_controller->document()->curves(), zoom, worldRect);
}

SceneStyle CurveCanvas::sceneStyle() const
{
    return {m_curveColor, m_polygonColor, m_controlPointColor, m_accentColor, m_tangentColor,
            m_gridColor,  m_axisColor,    m_showGrid,          m_curveWidth,  m_pointRadius};
}

void CurveCanvas::reloadBackground()
{
    const QString file = m_controller ? m_controller->document()->background().file : QString();
    if (file == m_backgroundFile)
        return;
    m_backgroundFile = file;
    m_backgroundImage = QImage();
    if (!file.isEmpty())
        m_backgroundImage = readImage(file).image; // null when unreadable: nothing is drawn
    m_backgroundDirty = true;
    repaint();
}

} // namespace kontur
