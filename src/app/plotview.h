// PlotView: draws a PlotSource (basis functions, function splines, the Runge comparison, seed 003's
// segments) over axes with ticks and labels in the UI language's number format, and turns pointer
// gestures into calls on the source: dragging a draggable dot or the parameter marker, hovering a
// curve. A QQuickPaintedItem, so it draws the same on the GPU and the software backends.
#pragma once

#include "models/teaching/plotsource.h"

#include <QLineF>
#include <QPointer>
#include <QQuickPaintedItem>

#include <vector>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class PlotView : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::PlotSource *source READ source WRITE setSource NOTIFY sourceChanged)
    // The index of the dot being dragged (-1: none), and whether the marker is.
    Q_PROPERTY(int draggedDot READ draggedDot NOTIFY dragChanged)
    Q_PROPERTY(bool draggingMarker READ draggingMarker NOTIFY dragChanged)
    // The pixel size of the tick and curve labels; the margins that hold them grow with it
    // (presentation mode draws larger text for a projector).
    Q_PROPERTY(double fontPixelSize READ fontPixelSize WRITE setFontPixelSize NOTIFY fontPixelSizeChanged)

public:
    // Room for the tick labels left of and under the plot area, at the default font size.
    static constexpr double kFontPixelSize = 11.0;
    static constexpr double kLeftMargin = 56.0;
    static constexpr double kBottomMargin = 28.0;
    static constexpr double kTopMargin = 10.0;
    static constexpr double kRightMargin = 14.0;
    // Half the touch target (44 px) of a dot or the marker.
    static constexpr double kHitRadius = 22.0;

    explicit PlotView(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PlotView)

    [[nodiscard]] PlotSource *source() const { return m_source; }
    void setSource(PlotSource *source);
    [[nodiscard]] int draggedDot() const { return m_dragDot; }
    [[nodiscard]] bool draggingMarker() const { return m_dragMarker; }
    [[nodiscard]] double fontPixelSize() const { return m_fontPixelSize; }
    void setFontPixelSize(double size);

    // World (y up) ↔ item coordinates, for the current data (tests, overlays).
    Q_INVOKABLE QPointF toScreen(QPointF world) const;
    Q_INVOKABLE QPointF toWorld(QPointF item) const;
    // Where the last paint wrote the curves' labels and drew the two axes (item coordinates), for tests.
    [[nodiscard]] const std::vector<QRectF> &labelRects() const { return m_labelRects; }
    [[nodiscard]] const std::vector<QLineF> &axisLines() const { return m_axisLines; }
    // Tick step for a range: 1, 2 or 5 times a power of ten, about `ticks` ticks.
    [[nodiscard]] static double tickStep(double range, int ticks);

    void paint(QPainter *painter) override;

Q_SIGNALS:
    void sourceChanged();
    void dragChanged();
    void fontPixelSizeChanged();

protected:
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseUngrabEvent() override;
    void hoverMoveEvent(QHoverEvent *event) override;
    void hoverLeaveEvent(QHoverEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    bool event(QEvent *event) override;

private:
    void sourceChanged_();
    [[nodiscard]] QRectF plotRect() const;
    // How much larger than the default the text and its margins are.
    [[nodiscard]] double textScale() const { return m_fontPixelSize / kFontPixelSize; }
    void endDrag(QPointF position);

    QPointer<PlotSource> m_source;
    PlotData m_data; // what is drawn, refreshed on plotChanged
    int m_dragDot = -1;
    bool m_dragMarker = false;
    double m_fontPixelSize = kFontPixelSize;
    std::vector<QRectF> m_labelRects;
    std::vector<QLineF> m_axisLines;
};

} // namespace kontur
