// PlotView: axes, ticks, curves, dots and gestures of the teaching plots (see plotview.h).
#include "app/plotview.h"

#include "app/plotlabels.h"

#include "geometry/plottransform.h"
#include "models/text/numbers.h"

#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

const QColor kBackground(0xff, 0xff, 0xff);
const QColor kGrid(0xe6, 0xe6, 0xe6);
const QColor kAxis(0x44, 0x44, 0x44);
const QColor kText(0x33, 0x33, 0x33);
const QColor kMarker(0x1f, 0x6f, 0xd1);
const QColor kKnotMark(0x8e, 0x24, 0xaa);

geo::PlotTransform transformFor(const QRectF &world, const QRectF &plot)
{
    geo::Box box(geo::Point(world.left(), world.top()), geo::Point(world.right(), world.bottom()));
    return geo::PlotTransform(box, plot.width(), plot.height());
}

// Distance from p to the segment ab.
double segmentDistance(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF q = a + t * ab - p;
    return std::hypot(q.x(), q.y());
}

} // namespace

PlotView::PlotView(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAcceptedMouseButtons(Qt::LeftButton);
    setAcceptHoverEvents(true);
    setActiveFocusOnTab(true);
    setAntialiasing(true);
}

void PlotView::setSource(PlotSource *source)
{
    if (m_source == source)
        return;
    if (m_source)
        disconnect(m_source, nullptr, this, nullptr);
    m_source = source;
    if (m_source)
        connect(m_source, &PlotSource::plotChanged, this, &PlotView::sourceChanged_);
    const QRectF plot = plotRect();
    if (m_source)
        m_source->setPlotArea(plot.size());
    sourceChanged_();
    Q_EMIT sourceChanged();
}

void PlotView::sourceChanged_()
{
    m_data = m_source ? m_source->plotData() : PlotData{};
    update();
}

void PlotView::setFontPixelSize(double size)
{
    if (size == m_fontPixelSize || !(size > 0))
        return;
    m_fontPixelSize = size;
    if (m_source)
        m_source->setPlotArea(plotRect().size());
    update();
    Q_EMIT fontPixelSizeChanged();
}

QRectF PlotView::plotRect() const
{
    const double s = textScale();
    const double left = kLeftMargin * s;
    const double top = kTopMargin * s;
    return QRectF(left, top, std::max(1.0, width() - left - kRightMargin * s),
                  std::max(1.0, height() - top - kBottomMargin * s));
}

void PlotView::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickPaintedItem::geometryChange(newGeometry, oldGeometry);
    if (m_source)
        m_source->setPlotArea(plotRect().size()); // repaints through plotChanged when it changed
    update();
}

QPointF PlotView::toScreen(QPointF world) const
{
    const QRectF plot = plotRect();
    const geo::Point p = transformFor(m_data.world, plot).toPlot(geo::Point(world.x(), world.y()));
    return QPointF(p.x() + plot.left(), p.y() + plot.top());
}

QPointF PlotView::toWorld(QPointF item) const
{
    const QRectF plot = plotRect();
    const geo::Point p =
        transformFor(m_data.world, plot).toWorld(geo::Point(item.x() - plot.left(), item.y() - plot.top()));
    return QPointF(p.x(), p.y());
}

double PlotView::tickStep(double range, int ticks)
{
    if (!(range > 0) || !std::isfinite(range) || ticks < 1)
        return 1.0;
    const double raw = range / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= raw)
            return m * power;
    return 10.0 * power;
}

void PlotView::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    painter->fillRect(boundingRect(), kBackground);
    const QRectF plot = plotRect();
    if (m_data.world.width() <= 0 || m_data.world.height() <= 0)
        return;

    const QLocale locale; // the UI language's number format
    QFont font = painter->font();
    font.setPixelSize(static_cast<int>(std::lround(m_fontPixelSize)));
    const double s = textScale();
    painter->setFont(font);
    const QFontMetricsF metrics(font);

    // Grid lines and tick labels.
    const QRectF &w = m_data.world;
    const double stepX = tickStep(w.width(), std::max(2, static_cast<int>(plot.width() / (90 * s))));
    const double stepY = tickStep(w.height(), std::max(2, static_cast<int>(plot.height() / (40 * s))));
    auto label = [&](double v, double step) {
        const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 8);
        return fixedNumber(v, decimals, locale);
    };
    painter->setPen(QPen(kGrid, 1));
    for (double x = std::ceil(w.left() / stepX) * stepX; x <= w.right() + stepX * 1e-9; x += stepX) {
        const double sx = toScreen(QPointF(x, 0)).x();
        painter->setPen(QPen(kGrid, 1));
        painter->drawLine(QPointF(sx, plot.top()), QPointF(sx, plot.bottom()));
        painter->setPen(kText);
        const QString text = label(x, stepX);
        painter->drawText(QRectF(sx - 40 * s, plot.bottom() + 4, 80 * s, metrics.height()),
                          Qt::AlignHCenter | Qt::AlignTop, text);
    }
    for (double y = std::ceil(w.top() / stepY) * stepY; y <= w.bottom() + stepY * 1e-9; y += stepY) {
        const double sy = toScreen(QPointF(0, y)).y();
        painter->setPen(QPen(kGrid, 1));
        painter->drawLine(QPointF(plot.left(), sy), QPointF(plot.right(), sy));
        painter->setPen(kText);
        painter->drawText(QRectF(0, sy - metrics.height() / 2, plot.left() - 6, metrics.height()),
                          Qt::AlignRight | Qt::AlignVCenter, label(y, stepY));
    }
    // Axes: through the origin when it is in view, else along the plot's edges.
    painter->setPen(QPen(kAxis, 1.2));
    const double axisY = w.top() <= 0 && 0 <= w.bottom() ? toScreen(QPointF(0, 0)).y() : plot.bottom();
    const double axisX = w.left() <= 0 && 0 <= w.right() ? toScreen(QPointF(0, 0)).x() : plot.left();
    painter->drawLine(QPointF(plot.left(), axisY), QPointF(plot.right(), axisY));
    painter->drawLine(QPointF(axisX, plot.top()), QPointF(axisX, plot.bottom()));
    painter->setPen(kText);
    // Labels already written: a curve's label keeps out of their way.
    std::vector<QRectF> placed;
    if (!m_data.xLabel.isEmpty()) {
        const double w = metrics.horizontalAdvance(m_data.xLabel);
        placed.emplace_back(plot.right() - w - 2, axisY - metrics.height() - 2, w, metrics.height());
        painter->drawText(placed.back(), Qt::AlignRight | Qt::AlignBottom, m_data.xLabel);
    }
    if (!m_data.yLabel.isEmpty()) {
        placed.emplace_back(axisX + 4, plot.top(), metrics.horizontalAdvance(m_data.yLabel), metrics.height());
        painter->drawText(placed.back(), Qt::AlignLeft | Qt::AlignTop, m_data.yLabel);
    }

    painter->save();
    painter->setClipRect(plot.adjusted(-1, -1, 1, 1));

    // Knot marks on the x axis: a repeated knot gets a stack of marks.
    if (!m_data.xMarks.empty()) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(kKnotMark);
        std::size_t i = 0;
        while (i < m_data.xMarks.size()) {
            std::size_t j = i;
            while (j < m_data.xMarks.size() && m_data.xMarks[j] == m_data.xMarks[i])
                ++j;
            const double sx = toScreen(QPointF(m_data.xMarks[i], 0)).x();
            for (std::size_t k = 0; k < j - i; ++k) {
                const double sy = plot.bottom() - 5 - 7.0 * static_cast<double>(k);
                QPolygonF triangle{QPointF(sx, sy - 4), QPointF(sx - 4, sy + 3), QPointF(sx + 4, sy + 3)};
                painter->drawPolygon(triangle);
            }
            i = j;
        }
    }

    // Curves, then their labels beside their highest points.
    for (const PlotSeries &s : m_data.series) {
        QPolygonF screen;
        screen.reserve(s.points.size());
        for (const QPointF &p : s.points)
            screen.append(toScreen(p));
        if (s.asDots) {
            painter->setPen(Qt::NoPen);
            painter->setBrush(s.color);
            for (const QPointF &p : screen)
                painter->drawEllipse(p, s.width, s.width);
            continue;
        }
        // As much thicker as the text is larger: in presentation mode the thin lines could not be told
        // apart from the back of a class.
        QPen pen(s.color, s.width * textScale());
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        if (s.dashed)
            pen.setStyle(Qt::DashLine);
        painter->setPen(pen);
        painter->setBrush(Qt::NoBrush);
        painter->drawPolyline(screen);
    }
    // The labels where they touch no curve, axis, dot or other label (the y axis ran through
    // Runge's labels; the basis functions' labels sat on their neighbours' curves).
    PlotLabelPlacer placer(plot);
    placer.addLine(QLineF(plot.left(), axisY, plot.right(), axisY), 1.2);
    placer.addLine(QLineF(axisX, plot.top(), axisX, plot.bottom()), 1.2);
    for (const QRectF &r : placed)
        placer.addRect(r);
    for (const PlotSeries &s : m_data.series) {
        QPolygonF screen;
        screen.reserve(s.points.size());
        for (const QPointF &p : s.points)
            screen.append(toScreen(p));
        placer.addCurve(screen, s.asDots ? 2 * s.width : s.width * textScale());
    }
    for (const PlotDot &d : m_data.dots) {
        const QPointF c = toScreen(d.position);
        placer.addRect(QRectF(c.x() - d.radius, c.y() - d.radius, 2 * d.radius, 2 * d.radius));
        if (d.anchor)
            placer.addLine(QLineF(toScreen(*d.anchor), c), 1.5);
    }
    m_labelRects.clear();
    for (const PlotSeries &s : m_data.series) {
        if (s.label.isEmpty() || s.points.isEmpty())
            continue;
        QPolygonF screen;
        screen.reserve(s.points.size());
        for (const QPointF &p : s.points)
            screen.append(toScreen(p));
        const QRectF box = placer.place(screen, QSizeF(std::ceil(metrics.horizontalAdvance(s.label)) + 1, metrics.height()));
        m_labelRects.push_back(box);
        QColor color = s.color;
        color.setAlphaF(1.0f);
        painter->setPen(color.darker(120));
        painter->drawText(box, Qt::AlignLeft | Qt::AlignVCenter, s.label);
    }
    m_axisLines = {QLineF(plot.left(), axisY, plot.right(), axisY), QLineF(axisX, plot.top(), axisX, plot.bottom())};

    // The parameter marker, with a grip at the top.
    if (m_data.marker) {
        const double sx = toScreen(QPointF(*m_data.marker, 0)).x();
        painter->setPen(QPen(kMarker, m_dragMarker ? 2.5 : 1.5, Qt::DashLine));
        painter->drawLine(QPointF(sx, plot.top()), QPointF(sx, plot.bottom()));
        painter->setPen(Qt::NoPen);
        painter->setBrush(kMarker);
        painter->drawEllipse(QPointF(sx, plot.top() + 7), 6, 6);
    }

    // Dots: the lines from their anchors first.
    for (const PlotDot &d : m_data.dots)
        if (d.anchor) {
            painter->setPen(QPen(d.color, 1.5));
            painter->drawLine(toScreen(*d.anchor), toScreen(d.position));
        }
    for (std::size_t i = 0; i < m_data.dots.size(); ++i) {
        const PlotDot &d = m_data.dots[i];
        const QPointF c = toScreen(d.position);
        const double r = d.radius * (static_cast<int>(i) == m_dragDot ? 1.4 : 1.0);
        switch (d.shape) {
        case PlotDot::Disc:
            painter->setPen(QPen(Qt::white, 1));
            painter->setBrush(d.color);
            painter->drawEllipse(c, r, r);
            break;
        case PlotDot::Ring:
            painter->setPen(QPen(d.color, 2));
            painter->setBrush(Qt::white);
            painter->drawEllipse(c, r, r);
            break;
        case PlotDot::Square:
            painter->setPen(QPen(Qt::white, 1));
            painter->setBrush(d.color);
            painter->drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
            break;
        }
    }
    painter->restore();
    painter->setPen(QPen(kAxis, 1));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(plot);
}

void PlotView::mousePressEvent(QMouseEvent *event)
{
    if (!m_source) {
        event->ignore();
        return;
    }
    forceActiveFocus(Qt::MouseFocusReason);
    const QPointF pos = event->position();
    // The nearest draggable dot within the touch target; dots drawn later win ties (handles).
    double best = kHitRadius;
    int hit = -1;
    for (std::size_t i = 0; i < m_data.dots.size(); ++i) {
        if (!m_data.dots[i].draggable)
            continue;
        const QPointF d = toScreen(m_data.dots[i].position) - pos;
        const double dist = std::hypot(d.x(), d.y());
        if (dist <= best) {
            best = dist;
            hit = static_cast<int>(i);
        }
    }
    if (hit >= 0) {
        // A flickable or drawer around the view must not take the drag over once it moves.
        setKeepMouseGrab(true);
        m_dragDot = hit;
        Q_EMIT dragChanged();
        event->accept();
        return;
    }
    if (m_data.marker && plotRect().adjusted(0, -kHitRadius, 0, kHitRadius).contains(pos)) {
        // Anywhere on the plot moves the marker there: a tap is as good as a drag for a student.
        setKeepMouseGrab(true);
        m_dragMarker = true;
        m_source->dragMarker(toWorld(pos).x());
        Q_EMIT dragChanged();
        event->accept();
        return;
    }
    event->ignore();
}

void PlotView::mouseMoveEvent(QMouseEvent *event)
{
    if (!m_source)
        return;
    const QPointF pos = event->position();
    if (m_dragDot >= 0)
        m_source->dragDot(m_dragDot, toWorld(pos), false);
    else if (m_dragMarker)
        m_source->dragMarker(toWorld(pos).x());
    event->accept();
}

void PlotView::endDrag(QPointF position)
{
    const int dot = m_dragDot;
    const bool marker = m_dragMarker;
    m_dragDot = -1;
    m_dragMarker = false;
    setKeepMouseGrab(false);
    if (m_source && dot >= 0)
        m_source->dragDot(dot, toWorld(position), true);
    if (dot >= 0 || marker) {
        Q_EMIT dragChanged();
        update();
    }
}

void PlotView::mouseReleaseEvent(QMouseEvent *event)
{
    endDrag(event->position());
    event->accept();
}

void PlotView::mouseUngrabEvent()
{
    // A stolen grab (a flickable, a popup) still ends the drag as one step, where the dot is now.
    if (m_dragDot >= 0 && m_dragDot < static_cast<int>(m_data.dots.size()))
        endDrag(toScreen(m_data.dots[static_cast<std::size_t>(m_dragDot)].position));
    else
        endDrag({});
}

void PlotView::hoverMoveEvent(QHoverEvent *event)
{
    if (!m_source)
        return;
    const QPointF pos = event->position();
    int id = -1;
    double best = 8.0;
    for (const PlotSeries &s : m_data.series) {
        if (s.id < 0)
            continue;
        for (qsizetype i = 1; i < s.points.size(); ++i) {
            const double d = segmentDistance(pos, toScreen(s.points[i - 1]), toScreen(s.points[i]));
            if (d < best) {
                best = d;
                id = s.id;
            }
        }
    }
    m_source->hoverSeries(id);
}

void PlotView::hoverLeaveEvent(QHoverEvent *event)
{
    Q_UNUSED(event)
    if (m_source)
        m_source->hoverSeries(-1);
}

bool PlotView::event(QEvent *event)
{
    // With the focus here, Left and Right move the marker rather than the window's nudge shortcuts.
    if (event->type() == QEvent::ShortcutOverride && m_data.marker) {
        auto *key = static_cast<QKeyEvent *>(event);
        if ((key->key() == Qt::Key_Left || key->key() == Qt::Key_Right) &&
            (key->modifiers() & ~Qt::ShiftModifier & ~Qt::KeypadModifier) == Qt::NoModifier) {
            event->accept();
            return true;
        }
    }
    return QQuickPaintedItem::event(event);
}

void PlotView::keyPressEvent(QKeyEvent *event)
{
    // Left and Right move the marker by a hundredth of the range (Shift: a tenth).
    if (!m_source || !m_data.marker || (event->key() != Qt::Key_Left && event->key() != Qt::Key_Right)) {
        event->ignore();
        return;
    }
    const double step = m_data.world.width() * ((event->modifiers() & Qt::ShiftModifier) ? 0.1 : 0.01);
    m_source->dragMarker(*m_data.marker + (event->key() == Qt::Key_Left ? -step : step));
    event->accept();
}

} // namespace kontur
