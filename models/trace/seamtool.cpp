// SeamTool: see seamtool.h.
#include "models/trace/seamtool.h"

#include "geometry/measure.h"
#include "models/text/units.h"

#include <algorithm>

namespace kontur {

using namespace tracepoints;

SeamTool::SeamTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &SeamTool::resultChanged, this, &SeamTool::textsChanged);
    connect(this, &SeamTool::resultChanged, this, &SeamTool::overlayChanged);
}

QString SeamTool::lengthText() const
{
    return formatLength(std::max(m_length, 0.0), m_context->units());
}

bool SeamTool::measure(int curveId, int knotA, int knotB)
{
    Document *doc = m_context->document();
    const Curve *found = doc ? doc->find(static_cast<CurveId>(curveId)) : nullptr;
    if (!found)
        return false;
    const Curve &curve = *found;
    const geo::PiecewiseBezier pw = curve.toPiecewise();
    const int knots = curve.placedCount();
    const int expected = curve.isClosed() ? knots : knots - 1;
    if (!traitsOf(curve.kind()).knotToKnot || pw.segmentCount() != expected) {
        m_context->say(Message::NoKnots);
        return false;
    }
    const auto length = geo::lengthBetween(pw, knotA, knotB, kLengthAccuracy);
    if (!length) {
        m_context->say(Message::TapKnot);
        return false;
    }
    m_curve = curve.id();
    m_knots = {knotA, knotB};
    m_length = *length;
    Q_EMIT resultChanged();
    return true;
}

void SeamTool::tap(QPointF world, double hitRadius)
{
    EditController *editor = m_context->editor();
    const Document *doc = m_context->document();
    if (!editor || !doc)
        return;
    const PointRef hit = editor->hitTest(toPoint(world), hitRadius);
    if (!hit.isValid() || doc->find(hit.curve)->row(hit.point).role != PointRole::Knot) {
        m_context->say(Message::TapKnot);
        return;
    }
    const int knot = doc->find(hit.curve)->knotOfRow(hit.point);
    if (m_knots.size() != 1 || m_curve != hit.curve) {
        m_knots = {knot};
        m_curve = hit.curve;
        m_length = -1.0;
        Q_EMIT resultChanged();
    } else {
        measure(static_cast<int>(hit.curve), m_knots[0], knot);
    }
}

void SeamTool::clear()
{
    m_curve = CurveId::None;
    m_knots.clear();
    m_length = -1.0;
    Q_EMIT resultChanged();
}

void SeamTool::documentChanged()
{
    // Measured again on the changed curve (cheap: a few segments), or dropped when it is gone.
    if (m_knots.size() == 2 && !measure(static_cast<int>(m_curve), m_knots[0], m_knots[1]))
        clear();
}

std::vector<geo::Bezier> SeamTool::segments() const
{
    std::vector<geo::Bezier> out;
    const Document *doc = m_context->document();
    const Curve *curve = doc ? doc->find(m_curve) : nullptr;
    if (!curve || m_knots.size() != 2)
        return out;
    const geo::PiecewiseBezier pw = curve->toPiecewise();
    const int n = pw.segmentCount();
    int first = m_knots[0], last = m_knots[1];
    if (last < first && !pw.isClosed())
        std::swap(first, last);
    const int count = last >= first ? last - first : last - first + n;
    for (int k = 0; k < count && n > 0; ++k)
        out.push_back(pw.segments()[static_cast<std::size_t>((first + k) % n)]);
    return out;
}

std::vector<geo::Point> SeamTool::marks() const
{
    std::vector<geo::Point> out;
    const Document *doc = m_context->document();
    const Curve *curve = doc ? doc->find(m_curve) : nullptr;
    if (!curve)
        return out;
    for (int k : m_knots) {
        const int row = curve->rowOfKnot(k);
        if (row >= 0)
            out.push_back(curve->row(row).position);
    }
    return out;
}

QPointF SeamTool::labelAnchor() const
{
    const std::vector<geo::Point> m = marks();
    return m.empty() ? QPointF() : toQPoint(m.back());
}

} // namespace kontur
