// CurveCanvas: view transform, gesture routing and scene-graph drawing on both backends.
#include "app/curvecanvas.h"

#include "models/document.h"
#include "models/editcontroller.h"

#include <QElapsedTimer>
#include <QImageReader>
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

namespace kontur {

namespace {

// The software backend draws no geometry nodes with materials, so there the canvas paints
// with the QPainter the renderer hands out (QSGRendererInterface::PainterResource).
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
        painter->save();
        if (const QRegion *clip = state->clipRegion(); clip && !clip->isEmpty())
            painter->setClipRegion(*clip, Qt::ReplaceClip);
        painter->setTransform(matrix()->toTransform());
        painter->setOpacity(inheritedOpacity());
        paint(list, *painter);
        painter->restore();
    }
    [[nodiscard]] StateFlags changedStates() const override { return {}; }
    [[nodiscard]] RenderingFlags flags() const override { return BoundedRectRendering; }
    [[nodiscard]] QRectF rect() const override { return bounds; }

    DisplayList list;
    QRectF bounds;

private:
    QQuickWindow *m_window;
};

QColor withAlpha(QColor color, double alpha)
{
    color.setAlphaF(static_cast<float>(alpha));
    return color;
}

} // namespace

CurveCanvas::CurveCanvas(QQuickItem *parent)
    : QQuickItem(parent)
{
    setFlag(ItemHasContents, true);
    connect(this, &CurveCanvas::styleChanged, this, &QQuickItem::update);
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
        connect(m_controller->document(), &Document::changed, this, &QQuickItem::update);
        connect(m_controller->document(), &Document::backgroundChanged, this, &CurveCanvas::reloadBackground);
        // Only what changed is flattened again.
        connect(m_controller->document(), &Document::rowsChanged, this,
                [this](int curve, int, int) { invalidateFlat(curve); });
        connect(m_controller->document(), &Document::curveChanged, this, &CurveCanvas::invalidateFlat);
        for (auto signal : {&Document::curveInserted, &Document::curveRemoved})
            connect(m_controller->document(), signal, this, [this](int) { m_flat.clear(); });
        connect(m_controller->document(), &Document::curveMoved, this, [this](int, int) { m_flat.clear(); });
        connect(m_controller, &EditController::pendingChanged, this, &QQuickItem::update);
        connect(m_controller, &EditController::hoverChanged, this, &QQuickItem::update);
        connect(m_controller, &EditController::selectionChanged, this, &QQuickItem::update);
        connect(m_controller, &EditController::modeChanged, this, &QQuickItem::update);
    }
    reloadBackground();
    Q_EMIT controllerChanged();
    update();
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
    if (curve >= 0 && static_cast<std::size_t>(curve) < m_flat.size())
        m_flat[static_cast<std::size_t>(curve)].valid = false;
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

void CurveCanvas::setView(double zoom, QPointF center)
{
    zoom = std::clamp(zoom, minimumZoom(), maximumZoom());
    if (!std::isfinite(zoom) || !std::isfinite(center.x()) || !std::isfinite(center.y()))
        return;
    if (zoom == m_zoom && center == m_center)
        return;
    m_zoom = zoom;
    m_center = center;
    Q_EMIT viewChanged();
    update();
}

void CurveCanvas::keepAt(QPointF world, QPointF screen)
{
    // Solve toScreen(world) == screen for the centre at the current zoom.
    setView(m_zoom, QPointF(world.x() - (screen.x() - width() / 2.0) / m_zoom,
                            world.y() + (screen.y() - height() / 2.0) / m_zoom));
}

void CurveCanvas::zoomBy(double factor, QPointF anchor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    const QPointF world = toWorld(anchor);
    setView(m_zoom * factor, m_center);
    keepAt(world, anchor);
}

void CurveCanvas::zoomIn()
{
    zoomBy(1.25, QPointF(width() / 2.0, height() / 2.0));
}

void CurveCanvas::zoomOut()
{
    zoomBy(1.0 / 1.25, QPointF(width() / 2.0, height() / 2.0));
}

void CurveCanvas::panBy(QPointF delta)
{
    setView(m_zoom, QPointF(m_center.x() - delta.x() / m_zoom, m_center.y() + delta.y() / m_zoom));
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
    setView(m_pinchStartZoom * scale, m_center);
    keepAt(m_anchorWorld, centroid);
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
    update();
}

void CurveCanvas::itemChange(ItemChange change, const ItemChangeData &value)
{
    QQuickItem::itemChange(change, value);
    if (change == ItemSceneChange && value.window) {
        connect(value.window, &QQuickWindow::sceneGraphInitialized, this, &CurveCanvas::graphicsApiChanged,
                Qt::UniqueConnection);
        Q_EMIT graphicsApiChanged();
    }
}

double CurveCanvas::gridStep() const
{
    // The smallest of 1, 2, 5 × 10^k world units that is at least 40 px on screen.
    const double minimum = 40.0 / m_zoom;
    const double power = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * power >= minimum)
            return factor * power;
    return 10.0 * power;
}

void CurveCanvas::addGrid(DisplayList &list) const
{
    // World lines x = k·step and y = k·step across the visible area, and the axes through the
    // world origin (y up, SPEC.md 2); the background picture stays visible under them.
    const double step = gridStep();
    const QPointF topLeft = toWorld(QPointF(0, 0));
    const QPointF bottomRight = toWorld(QPointF(width(), height()));
    const double x0 = std::floor(topLeft.x() / step) * step, x1 = bottomRight.x();
    const double y0 = std::floor(bottomRight.y() / step) * step, y1 = topLeft.y();
    for (double x = x0; x <= x1; x += step) {
        const double sx = toScreen(QPointF(x, 0)).x();
        list.strokes.push_back({{QPointF(sx, 0), QPointF(sx, height())}, m_gridColor, 1.0F, false});
    }
    for (double y = y0; y <= y1; y += step) {
        const double sy = toScreen(QPointF(0, y)).y();
        list.strokes.push_back({{QPointF(0, sy), QPointF(width(), sy)}, m_gridColor, 1.0F, false});
    }
    const QPointF origin = toScreen(QPointF(0, 0));
    if (origin.x() >= 0 && origin.x() <= width())
        list.strokes.push_back({{QPointF(origin.x(), 0), QPointF(origin.x(), height())}, m_axisColor, 1.0F, false});
    if (origin.y() >= 0 && origin.y() <= height())
        list.strokes.push_back({{QPointF(0, origin.y()), QPointF(width(), origin.y())}, m_axisColor, 1.0F, false});
}

void CurveCanvas::buildDisplayList(DisplayList &list) const
{
    list.clear();
    if (m_showGrid && width() > 0 && height() > 0)
        addGrid(list);
    if (!m_controller)
        return;
    const auto screen = [this](const geo::Point &p) { return toScreen(QPointF(p.x(), p.y())); };
    const QRectF visible = boundingRect().adjusted(-50, -50, 50, 50);
    const auto &curves = m_controller->document()->curves();
    const int selected = m_controller->selectedCurve();
    const auto ringWidth = static_cast<float>(std::max(1.5, m_curveWidth * 0.75));
    const auto radius = static_cast<float>(m_pointRadius);

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
    const auto marker = [&](QPointF at, PointRole role, bool editable, bool isSelected) {
        if (isSelected)
            list.discs.push_back({at, radius + 4.0F, m_accentColor});
        if (role == PointRole::Knot) {
            list.discs.push_back({at, radius, m_curveColor});
            return;
        }
        if (role == PointRole::TangentEnd) {
            // Tangent ends are diamonds, so that shape and not only colour tells them apart.
            const double r = m_pointRadius * 1.3;
            const std::vector<QPointF> diamond{at + QPointF(0, -r), at + QPointF(r, 0), at + QPointF(0, r),
                                               at + QPointF(-r, 0)};
            list.discs.push_back({at, radius * 0.8F, QColor(Qt::white)});
            list.overlay.push_back({diamond, m_tangentColor, ringWidth, true});
            return;
        }
        list.discs.push_back({at, radius, QColor(Qt::white)});
        list.overlay.push_back({circle(at, m_pointRadius),
                                editable ? m_controlPointColor : withAlpha(m_controlPointColor, 0.45), ringWidth,
                                true});
    };

    // Points of every curve while there are few; on large documents only those of the selected curve,
    // which keeps big drawings fast and readable.
    std::size_t totalRows = 0;
    for (const Curve &curve : curves)
        if (curve.visible)
            totalRows += static_cast<std::size_t>(curve.rowCount());
    const bool showAllPoints = totalRows <= kAllPointsLimit;
    if (m_flat.size() != curves.size())
        m_flat.assign(curves.size(), FlatCache{});

    std::vector<Stroke> halos, guides, lines;
    for (std::size_t c = 0; c < curves.size(); ++c) {
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
        // The curve lies in the hull of its points: skip what cannot be seen.
        if (!bounds.intersects(visible))
            continue;
        const bool isSelectedCurve = static_cast<int>(c) == selected;
        const bool showPoints = showAllPoints || isSelectedCurve;

        // Flattened in world units to a quarter pixel at the zoom it was made for, and reused while
        // the zoom stays below twice that (error under half a pixel) and not far above it (no
        // needless points): pans and small zoom steps only transform it.
        FlatCache &cache = m_flat[c];
        if (!cache.valid || m_zoom > 2.0 * cache.zoom || m_zoom < cache.zoom / 8.0) {
            cache.world.clear();
            for (int s = 0; s < curve.segmentCount(); ++s)
                geo::flatten(curve.segment(s), 0.25 / m_zoom, cache.world);
            cache.zoom = m_zoom;
            cache.valid = true;
        }
        // On screen, points closer than half a pixel to the last one kept add nothing visible
        // (the drawn line moves by less than that): zoomed out, most of them go.
        std::vector<QPointF> line;
        line.reserve(cache.world.size());
        for (std::size_t i = 0; i < cache.world.size(); ++i) {
            const QPointF p = screen(cache.world[i]);
            const bool last = i + 1 == cache.world.size();
            if (!line.empty() && !last) {
                const QPointF d = p - line.back();
                if (d.x() * d.x() + d.y() * d.y() < 0.25)
                    continue;
            }
            line.push_back(p);
        }
        if (isSelectedCurve && line.size() >= 2)
            halos.push_back({line, withAlpha(m_accentColor, 0.3), static_cast<float>(m_curveWidth + 6.0), false});

        if (line.size() >= 2)
            lines.push_back({std::move(line), curve.color, static_cast<float>(m_curveWidth), curve.isClosed()});
        if (!showPoints)
            continue;
        // The light grey guides: the control polygon, or the lines from a composite's knots to their handles.
        const int placed = curve.placedCount();
        const auto guide = [&](int from, int to) {
            guides.push_back({{rows[static_cast<std::size_t>(from)], rows[static_cast<std::size_t>(to)]},
                              m_polygonColor,
                              1.0F,
                              false});
        };
        switch (curve.kind()) {
        case CurveKind::Bezier:
        case CurveKind::BSpline:
            guides.push_back({std::vector<QPointF>(rows.begin(), rows.begin() + placed), m_polygonColor, 1.0F, false});
            break;
        case CurveKind::Interpolating:
        case CurveKind::LeastSquares:
            if (curve.fit())
                guides.push_back({std::vector<QPointF>(rows.end() - 4, rows.end()), m_polygonColor, 1.0F, false});
            break;
        case CurveKind::Composite:
            for (int r = 0; r < curve.rowCount(); ++r)
                if (!geo::CompositeCurve::isKnotIndex(r))
                    guide(r, (3 * curve.composite().knotOfControl(r)) % curve.rowCount());
            break;
        case CurveKind::ClampedSpline:
        case CurveKind::GlobalBSpline:
            if (curve.rowCount() >= placed + 2) {
                guide(0, placed);
                guide(placed - 1, placed + 1);
            }
            break;
        case CurveKind::HermiteSpline:
            for (int k = 0; k < placed && placed + k < curve.rowCount(); ++k)
                guide(k, placed + k);
            break;
        default:
            break;
        }
        for (int r = 0; r < curve.rowCount(); ++r) {
            const PointRow row = curve.row(r);
            marker(rows[static_cast<std::size_t>(r)], row.role, row.editable,
                   isSelectedCurve && r == m_controller->selectedPoint());
        }
    }
    list.strokes.insert(list.strokes.end(), halos.begin(), halos.end());
    list.strokes.insert(list.strokes.end(), guides.begin(), guides.end());
    list.strokes.insert(list.strokes.end(), lines.begin(), lines.end());

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
            list.strokes.push_back({polygon, m_polygonColor, 1.0F, false});
        flat.clear();
        for (const geo::Bezier &segment : m_controller->pendingSegments())
            flattenOnScreen(segment);
        if (flat.size() >= 2)
            list.strokes.push_back({polyline(), m_curveColor, static_cast<float>(m_curveWidth), false});
        for (const QPointF &at : polygon)
            marker(at, role, true, false);
        if (m_controller->hasHover()) {
            const std::vector<QPointF> band{polygon.back(), screen(m_controller->hoverPoint())};
            for (auto &dash : dashed(band, 6.0, 4.0))
                list.strokes.push_back({std::move(dash), m_polygonColor.darker(130), 1.0F, false});
        }
    }
}

namespace {

// The canvas's node tree: the background picture (under an opacity node), then the curves.
class CanvasRootNode final : public QSGNode
{
public:
    QSGOpacityNode *backgroundOpacity = nullptr;
    QSGImageNode *background = nullptr;
    QSGNode *curves = nullptr;
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
    update();
}

QSGNode *CurveCanvas::updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *)
{
    QQuickWindow *win = window();
    if (!win)
        return oldNode;
    auto *root = static_cast<CanvasRootNode *>(oldNode);
    if (!root)
        root = new CanvasRootNode;

    // The background: a textured rectangle where the document places the picture (y up in the world).
    const Background *background = m_controller ? &m_controller->document()->background() : nullptr;
    const bool showBackground = background && background->visible && !m_backgroundImage.isNull();
    if (m_backgroundDirty && root->backgroundOpacity) {
        root->removeChildNode(root->backgroundOpacity);
        delete root->backgroundOpacity; // deletes the image node and its texture with it
        root->backgroundOpacity = nullptr;
        root->background = nullptr;
    }
    m_backgroundDirty = false;
    if (showBackground && !root->background) {
        root->backgroundOpacity = new QSGOpacityNode;
        root->backgroundOpacity->setFlag(QSGNode::OwnedByParent);
        root->background = win->createImageNode();
        root->background->setTexture(win->createTextureFromImage(m_backgroundImage));
        root->background->setOwnsTexture(true);
        root->background->setFiltering(QSGTexture::Linear);
        root->backgroundOpacity->appendChildNode(root->background);
        if (root->curves)
            root->insertChildNodeBefore(root->backgroundOpacity, root->curves);
        else
            root->appendChildNode(root->backgroundOpacity);
    }
    if (root->backgroundOpacity) {
        root->backgroundOpacity->setOpacity(showBackground ? background->opacity : 0.0);
        if (showBackground) {
            const QPointF topLeft = toScreen(background->origin);
            const QPointF size(m_backgroundImage.width() * background->scale * m_zoom,
                               m_backgroundImage.height() * background->scale * m_zoom);
            root->background->setRect(QRectF(topLeft, QSizeF(size.x(), size.y())));
        }
    }

    QElapsedTimer profile;
    profile.start();
    buildDisplayList(m_list);
    static const bool profiling = qEnvironmentVariableIsSet("KONTUR_PROFILE");
    if (profiling)
        qInfo("display list: %.2f ms, %zu strokes", profile.nsecsElapsed() / 1e6, m_list.strokes.size());
    if (win->rendererInterface()->graphicsApi() == QSGRendererInterface::Software) {
        auto *node = static_cast<PainterNode *>(root->curves);
        if (!node) {
            node = new PainterNode(win);
            root->curves = node;
            root->appendChildNode(node);
        }
        node->bounds = boundingRect();
        std::swap(node->list, m_list);
        node->markDirty(QSGNode::DirtyMaterial);
        return root;
    }

    auto *node = static_cast<QSGGeometryNode *>(root->curves);
    if (!node) {
        node = new QSGGeometryNode;
        auto *geometry =
            new QSGGeometry(QSGGeometry::defaultAttributes_ColoredPoint2D(), 0, 0, QSGGeometry::UnsignedIntType);
        geometry->setDrawingMode(QSGGeometry::DrawTriangles);
        node->setGeometry(geometry);
        node->setFlag(QSGNode::OwnsGeometry);
        node->setMaterial(new QSGVertexColorMaterial);
        node->setFlag(QSGNode::OwnsMaterial);
        root->curves = node;
        root->appendChildNode(node);
    }
    TriangleMesh mesh;
    profile.restart();
    tessellate(m_list, mesh);
    if (profiling)
        qInfo("tessellation: %.2f ms, %zu vertices", profile.nsecsElapsed() / 1e6, mesh.vertices.size());
    QSGGeometry *geometry = node->geometry();
    geometry->allocate(static_cast<int>(mesh.vertices.size()), static_cast<int>(mesh.indices.size()));
    std::copy(mesh.vertices.begin(), mesh.vertices.end(), geometry->vertexDataAsColoredPoint2D());
    std::copy(mesh.indices.begin(), mesh.indices.end(), geometry->indexDataAsUInt());
    node->markDirty(QSGNode::DirtyGeometry);
    return root;
}

} // namespace kontur
