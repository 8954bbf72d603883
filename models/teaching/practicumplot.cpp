// PracticumPlot: seed 003's segments and multi-segment spline (see practicumplot.h).
#include "models/teaching/practicumplot.h"

#include "geometry/splines/practicum.h"
#include "models/document/snapshotcommand.h"
#include "models/text/languagewatch.h"
#include "models/text/numbers.h"

#include <QCoreApplication>
#include <QLocale>
#include <QUndoCommand>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

namespace {

const QColor kCurveColor(0x1f, 0x4e, 0x9c);
const QColor kPointColor(0x2e, 0x9d, 0x3a);
const QColor kGuideColor(0x70, 0x70, 0x70);

geo::Point toGeo(QPointF p)
{
    return {p.x(), p.y()};
}

QString number(double v)
{
    return fixedNumber(v, 3, QLocale(), {.grouping = false});
}

QString vec(const geo::Point &p)
{
    return QStringLiteral("(%1; %2)").arg(number(p.x()), number(p.y()));
}

} // namespace

// One change of the practicum's segments.
class PracticumCommand final : public SnapshotCommand<PracticumInput>
{
public:
    PracticumCommand(PracticumPlot *plot, PracticumInput before, PracticumInput after)
        : SnapshotCommand(std::move(before), std::move(after), -1, 0)
        , m_plot(plot)
    {
        setText(QCoreApplication::translate("PracticumPlot", "Change the segments"));
    }

private:
    void apply(const PracticumInput &input) override { m_plot->setState(input); }
    PracticumPlot *m_plot;
};

PracticumPlot::PracticumPlot(QObject *parent)
    : PlotSource(parent)
    , m_in(defaultsFor(FunctionSegment))
{
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &PracticumPlot::undoStateChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &PracticumPlot::undoStateChanged);
    recompute();
    // The details are translated, with numbers in the language's format (the error is a Message,
    // announced again by its ShownMessage).
    new LanguageWatch(this, [this] { recompute(); });
}

PracticumInput PracticumPlot::defaultsFor(int mode)
{
    PracticumInput in;
    in.mode = mode;
    switch (mode) {
    case FunctionSegment:
        in.points = {{0, 1}, {4, 2}};
        in.guideStart = QPointF(1, 2); // slope 1
        in.guideEnd = QPointF(5, 1.5); // slope -1/2
        break;
    case ParametricSegment:
        in.points = {{0, 0}, {4, 1}};
        in.guideStart = QPointF(0, 2); // straight up
        in.guideEnd = QPointF(4, -1);  // arriving downwards: an S
        break;
    default:
        in.points = {{0, 0}, {2, 2}, {4, 1}, {6, 3}, {8, 2}};
        in.guideStart = QPointF(1.5, 0);
        in.guideEnd = QPointF(9.5, 2);
        break;
    }
    return in;
}

void PracticumPlot::setInput(const PracticumInput &input)
{
    if (input == m_in)
        return;
    m_undo.push(new PracticumCommand(this, m_in, input));
}

void PracticumPlot::setState(const PracticumInput &input)
{
    m_in = input;
    recompute();
    Q_EMIT inputChanged();
}

void PracticumPlot::setMode(Mode mode)
{
    if (m_in.mode == mode)
        return;
    PracticumInput next = defaultsFor(mode);
    next.linesPerSegment = m_in.linesPerSegment;
    next.byPoints = m_in.byPoints;
    setInput(next);
}

void PracticumPlot::setLinesPerSegment(int lines)
{
    lines = std::clamp(lines, 1, 200);
    if (m_in.linesPerSegment == lines)
        return;
    PracticumInput next = m_in;
    next.linesPerSegment = lines;
    setInput(next);
}

void PracticumPlot::setByPoints(bool byPoints)
{
    if (m_in.byPoints == byPoints)
        return;
    PracticumInput next = m_in;
    next.byPoints = byPoints;
    setInput(next);
}

void PracticumPlot::loadDebugExample()
{
    PracticumInput next = m_in;
    next.mode = MultiSegment;
    next.points = {{0, 0}, {30, 20}, {60, 40}, {90, 60}};
    next.guideStart = QPointF(15, 10);
    next.guideEnd = QPointF(105, 70);
    setInput(next);
}

void PracticumPlot::loadSegmentExample()
{
    PracticumInput next = m_in;
    if (next.mode == MultiSegment)
        next.mode = FunctionSegment;
    next.points = {{0, 0}, {100, 0}};
    next.guideStart = QPointF(30, 30);
    next.guideEnd = QPointF(130, -30);
    setInput(next);
}

void PracticumPlot::recompute()
{
    m_polyline.clear();
    m_details.clear();
    Message error;
    const int ln = m_in.linesPerSegment;
    const auto &pts = m_in.points;
    if (pts.size() < 2) {
        m_error.clear();
        Q_EMIT plotChanged();
        return;
    }
    const geo::Point g0 = toGeo(m_in.guideStart - pts.front());
    const geo::Point g1 = toGeo(m_in.guideEnd - pts.back());
    switch (m_in.mode) {
    case FunctionSegment: {
        const auto s = geo::practicumFunctionSegment(toGeo(pts[0]), toGeo(pts[1]), g0, g1);
        if (!s) {
            error = Message(s.error().index == 1 ? Message::SegmentSameX : Message::GuideVertical);
            break;
        }
        for (int i = 0; i <= ln; ++i) {
            const double x = s->t * i / ln;
            m_polyline.append(QPointF(s->x0 + x, s->value(x)));
        }
        m_details = tr("t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5")
                        .arg(number(s->t), number(s->k0), number(s->k1), number(s->a3), number(s->a4));
        break;
    }
    case ParametricSegment: {
        const auto s = geo::practicumParametricSegment(toGeo(pts[0]), toGeo(pts[1]), g0, g1);
        if (!s) {
            error = Message(Message::SegmentDegenerate);
            break;
        }
        for (int i = 0; i <= ln; ++i) {
            const geo::Point p = s->value(s->t2 * i / ln);
            m_polyline.append(QPointF(p.x(), p.y()));
        }
        m_details = tr("t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5")
                        .arg(number(s->t2), vec(s->k0), vec(s->k1), vec(s->a3), vec(s->a4));
        break;
    }
    default: {
        std::vector<geo::Point> points;
        for (const QPointF &p : pts)
            points.push_back(toGeo(p));
        const auto s = geo::practicumSpline(points, g0, g1);
        if (!s) {
            error = Message(Message::SplineDegenerate);
            break;
        }
        for (int j = 0; j < s->spline.segmentCount(); ++j) {
            const geo::Bezier segment = s->spline.segment(j);
            for (int i = j == 0 ? 0 : 1; i <= ln; ++i) {
                const geo::Point p = segment.eval(static_cast<double>(i) / ln);
                m_polyline.append(QPointF(p.x(), p.y()));
            }
        }
        QStringList chords, tangents;
        for (std::size_t j = 1; j < s->T.size(); ++j)
            chords.append(number(s->T[j]));
        for (const geo::Point &k : s->K)
            tangents.append(vec(k));
        m_details =
            //: Two lines of figures: %1 the chord lengths T, %2 the tangent lengths K of the segments (numbers).
            tr("Chords T: %1\nTangents K: %2").arg(chords.join(QStringLiteral("  ")), tangents.join(QLatin1Char(' ')));
        break;
    }
    }
    m_error.show(error);
    Q_EMIT plotChanged();
}

PlotData PracticumPlot::plotData() const
{
    PlotData data;
    data.xLabel = QStringLiteral("x");
    data.yLabel = QStringLiteral("y");
    if (m_dragWorld) {
        data.world = *m_dragWorld;
    } else {
        // Everything in view, with one scale for both axes: the guide vectors' directions are true.
        QRectF box;
        auto include = [&box](QPointF p) {
            box = box.isNull() ? QRectF(p, QSizeF(1e-9, 1e-9)) : box.united(QRectF(p, QSizeF(1e-9, 1e-9)));
        };
        for (const QPointF &p : m_in.points)
            include(p);
        include(m_in.guideStart);
        include(m_in.guideEnd);
        for (const QPointF &p : m_polyline)
            include(p);
        const double pad = 0.12 * std::max({box.width(), box.height(), 1e-6});
        box.adjust(-pad, -pad, pad, pad);
        const QSizeF area = plotArea();
        const double aspect = area.width() / std::max(1.0, area.height());
        if (box.width() / box.height() < aspect) {
            const double w = box.height() * aspect;
            box.adjust(-(w - box.width()) / 2, 0, (w - box.width()) / 2, 0);
        } else {
            const double h = box.width() / aspect;
            box.adjust(0, -(h - box.height()) / 2, 0, (h - box.height()) / 2);
        }
        data.world = box;
    }
    PlotSeries curve;
    curve.points = m_polyline;
    curve.color = kCurveColor;
    curve.width = m_in.byPoints ? 2.5 : 2.0;
    curve.asDots = m_in.byPoints;
    data.series.push_back(curve);
    for (const QPointF &p : m_in.points) {
        PlotDot dot;
        dot.position = p;
        dot.color = kPointColor;
        dot.radius = 5.5;
        dot.draggable = true;
        data.dots.push_back(dot);
    }
    for (int g = 0; g < 2 && !m_in.points.empty(); ++g) {
        PlotDot grip;
        grip.position = g == 0 ? m_in.guideStart : m_in.guideEnd;
        grip.anchor = g == 0 ? m_in.points.front() : m_in.points.back();
        grip.color = kGuideColor;
        grip.shape = PlotDot::Square;
        grip.radius = 5.0;
        grip.draggable = true;
        data.dots.push_back(grip);
    }
    return data;
}

void PracticumPlot::dragDot(int index, QPointF world, bool finished)
{
    const int n = static_cast<int>(m_in.points.size());
    if (index < 0 || index >= n + 2)
        return;
    if (!m_dragStart) {
        m_dragStart = m_in;
        m_dragWorld = plotData().world;
    }
    PracticumInput next = m_in;
    if (index < n) {
        // A point carries its guide vector along.
        const QPointF delta = world - next.points[static_cast<std::size_t>(index)];
        next.points[static_cast<std::size_t>(index)] = world;
        if (index == 0)
            next.guideStart += delta;
        if (index == n - 1)
            next.guideEnd += delta;
    } else if (index == n) {
        next.guideStart = world;
    } else {
        next.guideEnd = world;
    }
    if (!finished) {
        setState(next);
        return;
    }
    const PracticumInput before = *m_dragStart;
    m_dragStart.reset();
    m_dragWorld.reset();
    m_in = before;
    if (next == before)
        setState(before);
    else
        setInput(next);
}

} // namespace kontur
