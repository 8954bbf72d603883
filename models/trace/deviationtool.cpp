// DeviationTool: see deviationtool.h.
#include "models/trace/deviationtool.h"

#include "models/text/units.h"

namespace kontur {

using namespace tracepoints;

DeviationTool::DeviationTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &DeviationTool::resultChanged, this, &DeviationTool::textsChanged);
    connect(this, &DeviationTool::resultChanged, this, &DeviationTool::overlayChanged);
}

QString DeviationTool::maximumText() const
{
    return formatLength(maximum(), m_context->units());
}

QString DeviationTool::meanText() const
{
    return formatLength(mean(), m_context->units());
}

bool DeviationTool::compare(int firstId, int secondId)
{
    const Document *doc = m_context->document();
    const Curve *first = doc ? doc->find(static_cast<CurveId>(firstId)) : nullptr;
    const Curve *second = doc ? doc->find(static_cast<CurveId>(secondId)) : nullptr;
    if (!first || !second || firstId == secondId)
        return false;
    const auto d = geo::deviation(first->toPiecewise(), second->toPiecewise());
    if (!d) {
        m_context->say(Message::NotComparable);
        return false;
    }
    m_pick = {first->id(), second->id()};
    m_deviation = *d;
    m_has = true;
    Q_EMIT resultChanged();
    return true;
}

void DeviationTool::tap(QPointF world, double hitRadius)
{
    EditController *editor = m_context->editor();
    if (!editor)
        return;
    const CurveHit hit = editor->curveAt(toPoint(world), hitRadius);
    if (!hit.isValid()) {
        m_context->say(Message::TapCurve);
        return;
    }
    if (m_pick.size() != 1) {
        m_pick = {hit.curve};
        m_has = false;
        Q_EMIT resultChanged();
    } else if (m_pick[0] == hit.curve) {
        m_context->say(Message::TapOtherCurve);
    } else {
        compare(static_cast<int>(m_pick[0]), static_cast<int>(hit.curve));
    }
}

void DeviationTool::clear()
{
    m_pick.clear();
    m_has = false;
    Q_EMIT resultChanged();
}

void DeviationTool::documentChanged()
{
    if (m_has && m_pick.size() == 2 && !compare(static_cast<int>(m_pick[0]), static_cast<int>(m_pick[1])))
        clear();
}

QPointF DeviationTool::labelAnchor() const
{
    return m_has ? toQPoint(m_deviation.maximumAt) : QPointF();
}

} // namespace kontur
