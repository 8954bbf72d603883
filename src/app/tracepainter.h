// TracePainter: the tracing tools over the canvas (issue #10). It draws the live freehand stroke,
// the calibration marks, the measured line, the seam and the place of the largest deviation, and
// takes the input of the tracing tools: in freehand mode one finger, a stylus or the left button
// draws (a stylus never pans), two fingers are left to the canvas's PinchHandler (zoom), and palm
// touches (a large contact or more than two points) are ignored; in the other tools a tap marks and
// a drag pans; in the perspective tool a press on a corner drags it, with a magnifier of the picture
// under the finger. Touch is taken raw for the stroke: palms are told by their contact size.
// A QQuickPaintedItem, so it draws on the GPU backends and the software one alike.
#pragma once

#include "app/canvasoverlay.h"
#include "models/trace/tracecontroller.h"

#include <QColor>
#include <QPointer>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class TracePainter : public CanvasOverlay
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::TraceController *trace READ trace WRITE setTrace NOTIFY traceChanged)
    Q_PROPERTY(QColor strokeColor MEMBER m_strokeColor NOTIFY styleChanged)
    Q_PROPERTY(QColor markColor MEMBER m_markColor NOTIFY styleChanged)
    Q_PROPERTY(QColor seamColor MEMBER m_seamColor NOTIFY styleChanged)
    Q_PROPERTY(QColor deviationColor MEMBER m_deviationColor NOTIFY styleChanged)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY styleChanged)
    // A touch whose contact ellipse is larger than this (px) is a palm, not a finger.
    Q_PROPERTY(double palmDiameter MEMBER m_palmDiameter NOTIFY styleChanged)
    // Touches since the tool was chosen that were ignored as palms (for tests and diagnostics).
    Q_PROPERTY(int ignoredPalms READ ignoredPalms NOTIFY ignoredPalmsChanged)
    // The magnifier shown while a perspective corner is dragged: its radius (px), enlargement, and
    // where it was last drawn (item coordinates; for tests).
    Q_PROPERTY(double loupeRadius MEMBER m_loupeRadius NOTIFY styleChanged)
    Q_PROPERTY(double loupeZoom MEMBER m_loupeZoom NOTIFY styleChanged)
    Q_PROPERTY(QPointF loupeCentre READ loupeCentre NOTIFY loupeChanged)

public:
    explicit TracePainter(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(TracePainter)

    [[nodiscard]] TraceController *trace() const { return m_trace; }
    void setTrace(TraceController *trace);
    [[nodiscard]] int ignoredPalms() const { return m_ignoredPalms; }
    [[nodiscard]] QPointF loupeCentre() const;

    void paint(QPainter *painter) override;

Q_SIGNALS:
    void traceChanged();
    void styleChanged();
    void ignoredPalmsChanged();
    void loupeChanged();

protected:
    [[nodiscard]] bool hasContent() const override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseUngrabEvent() override;
    void touchEvent(QTouchEvent *event) override;
    void touchUngrabEvent() override;

private:
    void updateInput();
    void updatePixelSize();
    [[nodiscard]] bool active() const;
    [[nodiscard]] QPointF world(QPointF item) const;
    [[nodiscard]] double hitRadius() const;
    // One pointer (a finger, the stylus or the mouse) pressed, moved, released at `position`.
    void pointerPressed(QPointF position);
    void pointerMoved(QPointF position);
    void pointerReleased(QPointF position);
    void pointerCancelled();
    void palm();
    void paintLoupe(QPainter *painter, QPointF at);
    [[nodiscard]] bool palmIn(const QList<QEventPoint> &points) const;

    // Pinch: two fingers, which the canvas handles; Ignore: a palm, until every finger is lifted.
    enum class Touch { Idle, Single, Pinch, Ignore };

    QPointer<TraceController> m_trace;
    QColor m_strokeColor{31, 111, 209};
    QColor m_markColor{0, 137, 123};
    QColor m_seamColor{239, 108, 0, 160};
    QColor m_deviationColor{198, 40, 40};
    double m_lineWidth = 2.0;
    double m_palmDiameter = 60.0;
    double m_loupeRadius = 70.0;
    double m_loupeZoom = 3.0;
    QPointF m_press;
    QPointF m_last;
    bool m_pressed = false;
    bool m_panning = false;
    Touch m_touch = Touch::Idle;
    int m_ignoredPalms = 0;
};

} // namespace kontur
