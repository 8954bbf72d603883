// A piece's marks on the canvas and their touch editing (see piecepainter.h).
#include "app/piecepainter.h"

#include "app/curvecanvas.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"

#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QStyleHints>
#include <QTouchEvent>

#include <cmath>

namespace kontur {

namespace {

QPointF unit(QPointF v)
{
    const double n = std::hypot(v.x(), v.y());
    return n > 0 ? v / n : QPointF(1, 0);
}

} // namespace

PiecePainter::PiecePainter(QQuickItem *parent)
    : CanvasOverlay(parent)
{
    updateInput();
}

void PiecePainter::setMarks(PieceMarkEdits *marks)
{
    if (m_marks == marks)
        return;
    if (m_marks)
        disconnect(m_marks, nullptr, this, nullptr);
    m_marks = marks;
    if (m_marks) {
        connect(m_marks, &PieceMarkEdits::stateChanged, this, [this] { update(); });
        connect(m_marks, &PieceMarkEdits::editorChanged, this, [this] {
            if (m_marks->editor())
                connect(m_marks->editor()->document(), &Document::changed, this, [this] { update(); });
        });
        if (m_marks->editor())
            connect(m_marks->editor()->document(), &Document::changed, this, [this] { update(); });
    }
    Q_EMIT marksChanged();
    update();
}

void PiecePainter::setSeams(SeamWidths *seams)
{
    if (m_seams == seams)
        return;
    if (m_seams)
        disconnect(m_seams, nullptr, this, nullptr);
    m_seams = seams;
    if (m_seams)
        connect(m_seams, &SeamWidths::stateChanged, this, [this] { update(); });
    Q_EMIT marksChanged();
    update();
}

void PiecePainter::setTool(Tool tool)
{
    if (m_tool == tool)
        return;
    m_tool = tool;
    if (m_first) {
        m_first.reset();
        Q_EMIT pendingChanged();
    }
    updateInput();
    Q_EMIT toolChanged();
    update();
}

void PiecePainter::updateInput()
{
    const bool on = m_tool != Tool::None;
    setAcceptedMouseButtons(on ? Qt::LeftButton : Qt::NoButton);
    setAcceptTouchEvents(on);
    if (!on)
        m_down = false;
}

QPointF PiecePainter::world(QPointF item) const
{
    return canvas() ? canvas()->toWorld(item) : item;
}

double PiecePainter::hitRadius() const
{
    return canvas() ? canvas()->hitRadiusWorld() : 10.0;
}

bool PiecePainter::hasContent() const
{
    if (!m_marks || !m_marks->editor())
        return false;
    if (m_first || (m_seams && m_seams->seam() >= 0))
        return true;
    for (const Curve &c : m_marks->editor()->document()->curves())
        if (c.visible && c.piece)
            return true;
    return false;
}

void PiecePainter::paint(QPainter *painter)
{
    if (!m_marks || !m_marks->editor() || !canvas())
        return;
    painter->setRenderHint(QPainter::Antialiasing);
    paintSeam(painter);
    for (const Curve &c : m_marks->editor()->document()->curves())
        if (c.visible && c.piece)
            paintPiece(painter, c);
    if (m_first) {
        const QPointF p = canvas()->toScreen(*m_first);
        painter->setPen(QPen(m_markColor, m_lineWidth));
        painter->setBrush(Qt::NoBrush);
        painter->drawEllipse(p, 3 * m_lineWidth, 3 * m_lineWidth);
    }
}

void PiecePainter::paintPiece(QPainter *painter, const Curve &curve) const
{
    const io::PieceMarks &m = *curve.piece;
    const auto screen = [this](const geo::Point &p) { return canvas()->toScreen(QPointF(p.x(), p.y())); };
    const double w = m_lineWidth;
    QPainterPath path;
    const geo::PiecewiseBezier shape = curve.toPiecewise();
    for (const io::Notch &n : m.notches) {
        const io::CurvePlace place = io::placeAtLength(shape, n.position);
        const geo::Point d = io::notchDirection(shape, place, n.angle);
        const QPointF at = screen(place.point);
        // The screen's y runs down: a world direction maps with y negated.
        const QPointF in = unit(QPointF(d.x(), -d.y())) * (6 * w), along = QPointF(-in.y(), in.x()) / 3;
        switch (n.kind) {
        case io::NotchKind::Slit:
            path.moveTo(at - in);
            path.lineTo(at + in);
            break;
        case io::NotchKind::V:
            path.moveTo(at - in / 2 + along);
            path.lineTo(at + in);
            path.lineTo(at - in / 2 - along);
            break;
        case io::NotchKind::Castle:
            path.moveTo(at - in / 2 + along);
            path.lineTo(at + in + along);
            path.lineTo(at + in - along);
            path.lineTo(at - in / 2 - along);
            break;
        }
    }
    if (m.grainline) {
        const QPointF a = screen(m.grainline->a), b = screen(m.grainline->b);
        path.moveTo(a);
        path.lineTo(b);
        for (const auto &[tip, back] : {std::pair{a, b}, std::pair{b, a}}) {
            const QPointF d = unit(back - tip) * (5 * w), side(-d.y() / 2, d.x() / 2);
            path.moveTo(tip + d + side);
            path.lineTo(tip);
            path.lineTo(tip + d - side);
        }
    }
    for (const geo::Point &h : m.drillHoles) {
        const QPointF p = screen(h);
        path.addEllipse(p, 2.5 * w, 2.5 * w);
        path.moveTo(p - QPointF(4 * w, 0));
        path.lineTo(p + QPointF(4 * w, 0));
        path.moveTo(p - QPointF(0, 4 * w));
        path.lineTo(p + QPointF(0, 4 * w));
    }
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(m_markColor, w, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter->drawPath(path);
    if (m.fold) {
        painter->setPen(QPen(m_markColor, w, Qt::DashDotLine, Qt::RoundCap));
        painter->drawLine(screen(m.fold->a), screen(m.fold->b));
    }
}

// The seam chosen for its own allowance width, wide and translucent under the marks.
void PiecePainter::paintSeam(QPainter *painter) const
{
    const auto shape = m_seams ? m_seams->seamShape() : std::nullopt;
    if (!shape)
        return;
    std::vector<geo::Point> points;
    shape->flatten(0.25 / std::max(canvas()->zoom(), 1e-300), points);
    QPolygonF line;
    for (const geo::Point &p : points)
        line << canvas()->toScreen(QPointF(p.x(), p.y()));
    QColor colour = m_seamColor;
    colour.setAlphaF(0.6f);
    painter->setPen(QPen(colour, 4 * m_lineWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter->setBrush(Qt::NoBrush);
    painter->drawPolyline(line);
}

// --- input: one pointer ---

void PiecePainter::pressed(QPointF position)
{
    m_press = position;
    m_down = true;
    m_moved = false;
    m_dragNotch = -1;
    if (m_tool == Tool::Notch && m_marks) {
        int index = -1;
        if (m_marks->markAt(geo::Point(world(position).x(), world(position).y()), hitRadius(), index) ==
            PieceMarkEdits::Mark::Notch) {
            m_dragNotch = index;
            m_dragSerial = m_marks->beginDrag();
        }
    }
}

void PiecePainter::moved(QPointF position)
{
    if (!m_down)
        return;
    const double threshold = QGuiApplication::styleHints()->startDragDistance();
    if (!m_moved && QLineF(m_press, position).length() < threshold)
        return;
    // A drag that holds no notch pans the view.
    if (m_dragNotch >= 0 && m_marks) {
        const QPointF w = world(position);
        m_marks->moveNotch(m_dragNotch, w.x(), w.y(), m_dragSerial);
    } else if (canvas()) {
        canvas()->panBy(position - (m_moved ? m_last : m_press));
    }
    m_moved = true;
    m_last = position;
}

void PiecePainter::released(QPointF position)
{
    if (!m_down)
        return;
    m_down = false;
    if (!m_moved)
        tapped(position);
    m_dragNotch = -1;
}

void PiecePainter::tapped(QPointF position)
{
    if (!m_marks)
        return;
    const QPointF w = world(position);
    switch (m_tool) {
    case Tool::None:
        return;
    case Tool::Grainline:
    case Tool::Fold:
        if (!m_first) {
            m_first = w;
            Q_EMIT pendingChanged();
            update();
            return;
        }
        if (m_tool == Tool::Grainline)
            m_marks->setGrainline(m_first->x(), m_first->y(), w.x(), w.y(), hitRadius());
        else
            m_marks->setFold(m_first->x(), m_first->y(), w.x(), w.y(), hitRadius());
        m_first.reset();
        Q_EMIT pendingChanged();
        update();
        return;
    case Tool::Notch: {
        // Only on the seam: within the touch radius of the piece's curve.
        const Curve *c = m_marks->editor() ? m_marks->editor()->selection()->curve() : nullptr;
        if (c && c->piece && c->toPiecewise().nearest(geo::Point(w.x(), w.y())).distance <= hitRadius())
            m_marks->addNotch(w.x(), w.y(), m_notchKind);
        return;
    }
    case Tool::DrillHole:
        m_marks->addDrillHole(w.x(), w.y());
        return;
    case Tool::Delete:
        m_marks->deleteMarkAt(w.x(), w.y(), hitRadius());
        return;
    case Tool::Seam:
        if (m_seams)
            m_seams->selectSeamAt(w.x(), w.y(), hitRadius());
        return;
    }
}

void PiecePainter::mousePressEvent(QMouseEvent *event)
{
    if (m_tool == Tool::None || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    // The canvas's DragHandler would take the pointer over once it moves past the drag threshold.
    setKeepMouseGrab(true);
    pressed(event->position());
    event->accept();
}

void PiecePainter::mouseMoveEvent(QMouseEvent *event)
{
    moved(event->position());
}

void PiecePainter::mouseReleaseEvent(QMouseEvent *event)
{
    setKeepMouseGrab(false);
    released(event->position());
}

void PiecePainter::touchEvent(QTouchEvent *event)
{
    const QList<QEventPoint> &points = event->points();
    if (m_tool == Tool::None || event->type() == QEvent::TouchCancel) {
        m_down = false;
        m_touching = false;
        event->ignore();
        return;
    }
    // Two fingers zoom and pan: left to the canvas's PinchHandler.
    if (points.size() > 1) {
        m_down = false;
        m_touching = false;
        setKeepTouchGrab(false);
        ungrabTouchPoints();
        event->ignore();
        return;
    }
    event->accept();
    const QEventPoint &p = points.first();
    if (p.state() == QEventPoint::Pressed) {
        m_touching = true;
        setKeepTouchGrab(true);
        pressed(p.position());
    } else if (m_touching && p.state() == QEventPoint::Released) {
        m_touching = false;
        setKeepTouchGrab(false);
        released(p.position());
    } else if (m_touching) {
        moved(p.position());
    }
}

} // namespace kontur
