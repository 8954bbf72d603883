// CanvasOverlay: see canvasoverlay.h.
#include "app/canvasoverlay.h"

#include <QSGNode>

namespace kontur {

CanvasOverlay::CanvasOverlay(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
}

void CanvasOverlay::setCanvas(CurveCanvas *canvas)
{
    if (m_canvas == canvas)
        return;
    if (m_canvas)
        disconnect(m_canvas, nullptr, this, nullptr);
    m_canvas = canvas;
    if (m_canvas)
        connect(m_canvas, &CurveCanvas::viewChanged, this, [this] { update(); });
    Q_EMIT canvasChanged();
    update();
}

QSGNode *CanvasOverlay::updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *data)
{
    if (!hasContent()) {
        // As QQuickPaintedItem itself does for an empty size: no node, no texture.
        delete oldNode;
        return nullptr;
    }
    return QQuickPaintedItem::updatePaintNode(oldNode, data);
}

} // namespace kontur
