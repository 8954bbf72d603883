// MeasureTool: see measuretool.h.
#include "models/trace/measuretool.h"

#include "models/text/units.h"

namespace kontur {

using namespace tracepoints;

MeasureTool::MeasureTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
    connect(this, &MeasureTool::resultChanged, this, &MeasureTool::textsChanged);
    connect(this, &MeasureTool::resultChanged, this, &MeasureTool::overlayChanged);
}

double MeasureTool::distance() const
{
    return m_marks.size() == 2 ? (m_marks[1] - m_marks[0]).norm() : 0.0;
}

QString MeasureTool::distanceText() const
{
    return formatLength(distance(), m_context->units());
}

void MeasureTool::tap(QPointF world, double hitRadius)
{
    if (m_marks.size() >= 2)
        m_marks.clear();
    m_marks.push_back(toPoint(m_context->snap(world, hitRadius)));
    Q_EMIT resultChanged();
}

void MeasureTool::clear()
{
    m_marks.clear();
    Q_EMIT resultChanged();
}

QPointF MeasureTool::labelAnchor() const
{
    return m_marks.size() == 2 ? toQPoint((m_marks[0] + m_marks[1]) / 2) : QPointF();
}

} // namespace kontur
