// TracePainter: see tracepainter.h.
#include "app/tracepainter.h"

#include "app/curvecanvas.h"
#include "models/trace/perspective.h"

#include "geometry/bezier.h"

#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QStyleHints>
#include <QTouchEvent>

#include <algorithm>
#include <cmath>

namespace kontur {

TracePainter::TracePainter(QQuickItem *parent)
    : CanvasOverlay(parent)
{
    connect(this, &TracePainter::styleChanged, this, [this] { update(); });
    connect(this, &CanvasOverlay::canvasChanged, this, &TracePainter::updateInput);
    connect(this, &CanvasOverlay::canvasChanged, this, [this] {
        if (canvas())
            connect(canvas(), &CurveCanvas::viewChanged, this, &TracePainter::updatePixelSize);
        updatePixelSize();
    });
    updateInput();
}

// The tracing tools learn the size of a screen pixel, under which a freehand fit does not go.
void TracePainter::updatePixelSize()
{
    if (m_trace && canvas() && canvas()->zoom() > 0.0)
        m_trace->freehand()->setPixelSize(1.0 / canvas()->zoom());
}

void TracePainter::setTrace(TraceController *trace)
{
    if (m_trace == trace)
        return;
    if (m_trace)
        disconnect(m_trace, nullptr, this, nullptr);
    m_trace = trace;
    updatePixelSize();
    if (m_trace) {
        connect(m_trace, &TraceController::overlayChanged, this, [this] {
            update();
            Q_EMIT loupeChanged();
        });
        connect(m_trace, &TraceController::toolChanged, this, [this] {
            updateInput();
            update();
        });
    }
    updateInput();
    Q_EMIT traceChanged();
    update();
}

// Only a tool draws: the stroke while drawing freehand, its marks and results otherwise.
bool TracePainter::hasContent() const
{
    return active();
}

bool TracePainter::active() const
{
    return m_trace && canvas() && m_trace->tool() != TraceController::Tool::None;
}

// Outside the tracing tools every press goes through to the canvas underneath.
void TracePainter::updateInput()
{
    const bool on = active();
    setAcceptedMouseButtons(on ? Qt::LeftButton : Qt::NoButton);
    setAcceptTouchEvents(on);
    if (!on) {
        m_pressed = false;
        m_touch = Touch::Idle;
    }
}

QPointF TracePainter::world(QPointF item) const
{
    return canvas() ? canvas()->toWorld(item) : item;
}

double TracePainter::hitRadius() const
{
    return canvas() ? canvas()->hitRadiusWorld() : 0.0;
}

// ---------------------------------------------------------------------------------------------
// Input

void TracePainter::pointerPressed(QPointF position)
{
    m_pressed = true;
    m_panning = false;
    m_press = m_last = position;
    // The canvas's own drag and pinch handlers must not take the pointer over once it moves.
    setKeepMouseGrab(true);
    setKeepTouchGrab(true);
    if (m_trace->tool() == TraceController::Tool::Freehand)
        m_trace->freehand()->beginStroke(world(position), hitRadius());
    else if (m_trace->tool() == TraceController::Tool::MoveBackground)
        m_trace->backgroundMove()->begin();
    else if (m_trace->tool() == TraceController::Tool::Perspective)
        m_trace->perspective()->beginCornerDrag(world(position), hitRadius());
}

void TracePainter::pointerMoved(QPointF position)
{
    if (!m_pressed)
        return;
    if (m_trace->tool() == TraceController::Tool::Freehand) {
        m_trace->freehand()->extendStroke(world(position));
    } else if (m_trace->tool() == TraceController::Tool::MoveBackground) {
        m_trace->backgroundMove()->moveBy(world(position) - world(m_last));
    } else if (m_trace->perspective()->cornerDragging()) {
        m_trace->perspective()->dragCornerTo(world(position));
    } else {
        // The marking tools pan on a drag, as the canvas does.
        if (!m_panning && QLineF(m_press, position).length() >= QGuiApplication::styleHints()->startDragDistance())
            m_panning = true;
        if (m_panning)
            canvas()->panBy(position - m_last);
    }
    m_last = position;
}

void TracePainter::pointerReleased(QPointF position)
{
    if (!m_pressed)
        return;
    m_pressed = false;
    if (m_trace->tool() == TraceController::Tool::Freehand) {
        m_trace->freehand()->extendStroke(world(position));
        m_trace->freehand()->endStroke(hitRadius());
    } else if (m_trace->tool() == TraceController::Tool::MoveBackground) {
        m_trace->backgroundMove()->moveBy(world(position) - world(m_last));
        m_trace->backgroundMove()->end();
    } else if (m_trace->perspective()->cornerDragging()) {
        // A press on a corner that does not move leaves it where it was (no tap: no new mark); any
        // move counts, since refining is a matter of a few pixels.
        if (QLineF(m_press, position).length() >= 1.0) {
            m_trace->perspective()->dragCornerTo(world(position));
            m_trace->perspective()->endCornerDrag();
        } else {
            m_trace->perspective()->cancelCornerDrag();
        }
    } else if (!m_panning) {
        m_trace->tap(world(position), hitRadius());
    }
}

void TracePainter::pointerCancelled()
{
    m_pressed = false;
    if (m_trace) {
        m_trace->freehand()->cancelStroke();
        m_trace->backgroundMove()->end();
        m_trace->perspective()->cancelCornerDrag();
    }
}

void TracePainter::mousePressEvent(QMouseEvent *event)
{
    if (!active() || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    pointerPressed(event->position());
    event->accept();
}

void TracePainter::mouseMoveEvent(QMouseEvent *event)
{
    if (active())
        pointerMoved(event->position());
}

void TracePainter::mouseReleaseEvent(QMouseEvent *event)
{
    if (active())
        pointerReleased(event->position());
}

void TracePainter::mouseUngrabEvent()
{
    if (m_touch == Touch::Idle)
        pointerCancelled();
}

void TracePainter::palm()
{
    if (m_touch == Touch::Single)
        pointerCancelled();
    m_touch = Touch::Ignore;
    ++m_ignoredPalms;
    Q_EMIT ignoredPalmsChanged();
}

void TracePainter::touchEvent(QTouchEvent *event)
{
    if (!active()) {
        event->ignore();
        return;
    }
    const QList<QEventPoint> &points = event->points();
    if (event->type() == QEvent::TouchCancel) {
        if (m_touch == Touch::Single)
            pointerCancelled();
        m_touch = Touch::Idle;
        return;
    }
    // A new sequence: the last one may have ended with the canvas (a pinch), unseen here.
    if (event->type() == QEvent::TouchBegin)
        m_touch = Touch::Idle;
    // Two fingers zoom and pan: the canvas's PinchHandler (CanvasView.qml) does it. A stroke or tap
    // begun with the first finger is dropped, and the points are let go so that it can take them.
    if (m_touch == Touch::Pinch || (m_touch != Touch::Ignore && points.size() == 2 && !palmIn(points))) {
        if (m_touch == Touch::Single)
            pointerCancelled();
        setKeepTouchGrab(false);
        ungrabTouchPoints(); // touchUngrabEvent() sets Idle: the state is set after it
        m_touch = Touch::Pinch;
        event->ignore();
        return;
    }
    event->accept();
    // A palm resting on the screen: a large contact, or a third point. The whole touch sequence is
    // then ignored until every finger is lifted, and a stroke in progress is dropped.
    if (m_touch != Touch::Ignore && (points.size() > 2 || palmIn(points)))
        palm();
    int down = 0;
    for (const QEventPoint &p : points)
        if (p.state() != QEventPoint::Released)
            ++down;
    const bool finished = event->type() == QEvent::TouchEnd || down == 0;
    if (m_touch == Touch::Idle && points.size() == 1 && !finished) {
        m_touch = Touch::Single;
        pointerPressed(points.first().position());
    } else if (m_touch == Touch::Single && points.size() == 1) {
        const QEventPoint &p = points.first();
        if (p.state() == QEventPoint::Released) {
            pointerReleased(p.position());
            m_touch = Touch::Idle;
        } else {
            pointerMoved(p.position());
        }
    }
    if (finished && m_touch != Touch::Single)
        m_touch = Touch::Idle;
}

bool TracePainter::palmIn(const QList<QEventPoint> &points) const
{
    for (const QEventPoint &p : points) {
        const QSizeF d = p.ellipseDiameters();
        if (std::max(d.width(), d.height()) > m_palmDiameter)
            return true;
    }
    return false;
}

void TracePainter::touchUngrabEvent()
{
    if (m_touch == Touch::Single)
        pointerCancelled();
    m_touch = Touch::Idle;
}

// ---------------------------------------------------------------------------------------------
// Painting

namespace {

void cross(QPainter *painter, QPointF at, double size)
{
    painter->drawLine(at - QPointF(size, 0), at + QPointF(size, 0));
    painter->drawLine(at - QPointF(0, size), at + QPointF(0, size));
    painter->drawEllipse(at, size / 2, size / 2);
}

} // namespace

QPointF TracePainter::loupeCentre() const
{
    if (!m_trace || !canvas() || !m_trace->perspective()->cornerDragging())
        return {};
    const QPointF at = canvas()->toScreen(m_trace->perspective()->cornerDragPoint());
    const double radius = m_loupeRadius;
    QPointF centre(at.x(), at.y() - radius - m_palmDiameter);
    if (centre.y() - radius < 0)
        centre.setY(at.y() + radius + m_palmDiameter);
    centre.setX(std::clamp(centre.x(), radius, std::max(radius, width() - radius)));
    return centre;
}

void TracePainter::paintLoupe(QPainter *painter, QPointF at)
{
    // A magnifier over the picture under the finger, shown above it (below it near the top edge) so
    // that the finger does not hide the corner being placed.
    const Document *doc = m_trace->editor() ? m_trace->editor()->document() : nullptr;
    const QImage &image = canvas()->backgroundImage();
    if (!doc || image.isNull())
        return;
    const double radius = m_loupeRadius;
    const QPointF centre = loupeCentre();

    const Background &bg = doc->background();
    // picture → world (the placement) → screen → the loupe: the screen around `at`, enlarged.
    const QPointF o = canvas()->toScreen(QPointF(0, 0));
    const QPointF ex = canvas()->toScreen(QPointF(1, 0)) - o, ey = canvas()->toScreen(QPointF(0, 1)) - o;
    const QTransform worldToScreen(ex.x(), ex.y(), ey.x(), ey.y(), o.x(), o.y());
    const QTransform imageToWorld = perspective::toQTransform(bg.imageToWorld());
    const QRectF drawn = perspective::drawnRect(bg, image.size());
    const QTransform toLoupe = QTransform::fromTranslate(-at.x(), -at.y()) *
                               QTransform::fromScale(m_loupeZoom, m_loupeZoom) *
                               QTransform::fromTranslate(centre.x(), centre.y());

    painter->save();
    QPainterPath disc;
    disc.addEllipse(centre, radius, radius);
    painter->setPen(Qt::NoPen);
    painter->setBrush(QColor(255, 255, 255));
    painter->drawPath(disc);
    painter->setClipPath(disc);
    painter->setRenderHint(QPainter::SmoothPixmapTransform);
    painter->setTransform(imageToWorld * worldToScreen * toLoupe, true);
    painter->drawImage(drawn, image, drawn);
    painter->restore();

    painter->setPen(QPen(m_deviationColor, 1.0));
    painter->drawLine(centre - QPointF(radius, 0), centre + QPointF(radius, 0));
    painter->drawLine(centre - QPointF(0, radius), centre + QPointF(0, radius));
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(QColor(60, 60, 60), 2.0));
    painter->drawEllipse(centre, radius, radius);
}

void TracePainter::paint(QPainter *painter)
{
    if (!m_trace || !canvas())
        return;
    painter->setRenderHint(QPainter::Antialiasing);
    const auto screen = [this](const geo::Point &p) { return canvas()->toScreen(QPointF(p.x(), p.y())); };
    const TraceController::Tool tool = m_trace->tool();

    // The stroke being drawn.
    const std::vector<geo::Point> &stroke = m_trace->freehand()->stroke();
    if (stroke.size() >= 2) {
        QPolygonF line;
        line.reserve(static_cast<qsizetype>(stroke.size()));
        for (const geo::Point &p : stroke)
            line << screen(p);
        painter->setPen(QPen(m_strokeColor, m_lineWidth * 1.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->drawPolyline(line);
    }

    // Calibration: the marks being placed, and those of the current calibration.
    if (tool == TraceController::Tool::Calibrate) {
        const Document *doc = m_trace->editor() ? m_trace->editor()->document() : nullptr;
        if (doc && doc->background().calibrated) {
            const Background &bg = doc->background();
            painter->setPen(QPen(m_markColor.lighter(140), m_lineWidth, Qt::DashLine));
            const QPointF a = screen(bg.toWorld(bg.calibrationA));
            const QPointF b = screen(bg.toWorld(bg.calibrationB));
            painter->drawLine(a, b);
            cross(painter, a, 10);
            cross(painter, b, 10);
        }
        const auto &marks = m_trace->calibration()->marks();
        painter->setPen(QPen(m_markColor, m_lineWidth));
        if (marks.size() == 2)
            painter->drawLine(screen(marks[0]), screen(marks[1]));
        for (const geo::Point &m : marks)
            cross(painter, screen(m), 14);
    }

    // Perspective: the quadrilateral of the marks (or of the calibration's corners), numbered in the
    // order they were tapped; the corner being dragged is drawn at the finger.
    if (tool == TraceController::Tool::Perspective) {
        std::vector<geo::Point> handles = m_trace->perspective()->handles();
        const bool dragging = m_trace->perspective()->cornerDragging();
        perspective::Quad corners;
        for (std::size_t i = 0; i < handles.size() && i < 4; ++i)
            corners[i] = screen(handles[i]);
        painter->setPen(QPen(m_markColor, m_lineWidth));
        // Four marks are joined in the order of their quadrilateral, whatever order they were tapped in.
        if (handles.size() == 4) {
            if (const auto ordered = perspective::orderCorners(corners))
                painter->drawPolygon(QPolygonF(QList<QPointF>(ordered->begin(), ordered->end())));
        }
        for (std::size_t i = 0; i < handles.size() && i < 4; ++i)
            cross(painter, corners[i], 14);
        if (dragging) {
            const QPointF at = canvas()->toScreen(m_trace->perspective()->cornerDragPoint());
            painter->setPen(QPen(m_deviationColor, m_lineWidth));
            cross(painter, at, 18);
            paintLoupe(painter, at);
        }
    }

    if (tool == TraceController::Tool::Measure) {
        const auto &marks = m_trace->measure()->marks();
        painter->setPen(QPen(m_markColor, m_lineWidth));
        if (marks.size() == 2)
            painter->drawLine(screen(marks[0]), screen(marks[1]));
        for (const geo::Point &m : marks)
            cross(painter, screen(m), 10);
    }

    if (tool == TraceController::Tool::Seam) {
        // The seam, flattened in screen space like the canvas's curves (a quarter pixel).
        std::vector<geo::Point> poly;
        for (const geo::Bezier &segment : m_trace->seam()->segments()) {
            std::vector<geo::Point> control;
            for (const geo::Point &p : segment.controlPoints()) {
                const QPointF s = screen(p);
                control.emplace_back(s.x(), s.y());
            }
            geo::flatten(geo::Bezier(std::move(control)), 0.25, poly);
        }
        if (poly.size() >= 2) {
            QPolygonF line;
            for (const geo::Point &p : poly)
                line << QPointF(p.x(), p.y());
            painter->setPen(QPen(m_seamColor, m_lineWidth * 4, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            painter->drawPolyline(line);
        }
        painter->setPen(QPen(m_seamColor.darker(130), m_lineWidth));
        for (const geo::Point &m : m_trace->seam()->marks())
            painter->drawEllipse(screen(m), 9, 9);
    }

    if (tool == TraceController::Tool::Deviation && m_trace->deviation()->hasResult()) {
        const geo::Deviation &d = m_trace->deviation()->deviation();
        const QPointF a = screen(d.maximumAt), b = screen(d.maximumOther);
        painter->setPen(QPen(m_deviationColor, m_lineWidth));
        painter->drawLine(a, b);
        painter->drawEllipse(a, 8, 8);
        painter->drawEllipse(b, 5, 5);
        // A ring that stays visible when the two points are closer than a pixel.
        painter->drawEllipse((a + b) / 2, 16, 16);
    }
}

} // namespace kontur
