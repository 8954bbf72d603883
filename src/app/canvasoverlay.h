// CanvasOverlay: the base of the painted items over the canvas (the teaching views, the tracing
// tools). It holds the canvas that they map world points through, repaints when the canvas's view
// changes, and has no texture at all while there is nothing to draw: an empty overlay the size of
// the canvas would still cost a blend of every pixel each frame, and a repaint and an upload on
// every pan and zoom step.
#pragma once

#include "app/curvecanvas.h"

#include <QPointer>
#include <QQuickPaintedItem>

namespace kontur {

class CanvasOverlay : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ANONYMOUS
    Q_PROPERTY(kontur::CurveCanvas *canvas READ canvas WRITE setCanvas NOTIFY canvasChanged)

public:
    explicit CanvasOverlay(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(CanvasOverlay)

    [[nodiscard]] CurveCanvas *canvas() const { return m_canvas; }
    void setCanvas(CurveCanvas *canvas);

Q_SIGNALS:
    void canvasChanged();

protected:
    // Whether paint() would draw anything now (read while the GUI thread waits for the sync).
    [[nodiscard]] virtual bool hasContent() const = 0;
    QSGNode *updatePaintNode(QSGNode *oldNode, UpdatePaintNodeData *data) override;

private:
    QPointer<CurveCanvas> m_canvas;
};

} // namespace kontur
