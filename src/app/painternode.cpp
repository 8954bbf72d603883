// PainterNode: the canvas's software-backend node and its cached layer picture.
#include "app/painternode.h"

#include <QElapsedTimer>
#include <QPainter>
#include <QQuickWindow>
#include <QSGRendererInterface>

#include <cmath>

namespace kontur {

void PainterNode::render(const RenderState *state)
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

bool PainterNode::drawLayer(QPainter &painter)
{
    const QTransform device = painter.combinedTransform();
    const double scale = std::sqrt(std::abs(device.determinant())) * painter.device()->devicePixelRatioF();
    const bool sameContent = !m_layer.image().isNull() && m_version == version && m_view.size == view.size &&
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
    painter.drawImage(QPointF(0, 0), m_layer.image());
    painter.restore();
    return painted;
}

QTransform PainterNode::layerToItem() const
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

bool PainterNode::covers() const
{
    const double s = view.zoom / m_view.zoom;
    if (!(s >= 0.5 && s <= 2.0))
        return false;
    bool invertible = false;
    const QTransform back = layerToItem().inverted(&invertible);
    if (!invertible)
        return false;
    const QRectF needed = back.mapRect(QRectF(QPointF(0, 0), view.size));
    return QRectF(m_layer.image().rect()).adjusted(-1, -1, 1, 1).contains(needed);
}

void PainterNode::paintLayer(double scale)
{
    m_view = view;
    m_version = version;
    m_scale = scale;
    m_margin = margin;
    m_layer.update(layerCurves, {view, margin, scale, curveWidth}, {}, false);
}

} // namespace kontur
