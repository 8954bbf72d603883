// The document's mutators and their notifications.
#include "models/document.h"

namespace kontur {

Document::Document(QObject *parent)
    : QObject(parent)
{
}

bool Document::isValidPoint(int curve, int point) const
{
    return curve >= 0 && curve < curveCount() && point >= 0 &&
           point < static_cast<int>(m_curves[static_cast<std::size_t>(curve)].points.size());
}

void Document::insertCurve(int index, Curve curve)
{
    index = std::clamp(index, 0, curveCount());
    Q_EMIT curveAboutToBeInserted(index);
    m_curves.insert(m_curves.begin() + index, std::move(curve));
    Q_EMIT curveInserted(index);
    Q_EMIT curveCountChanged();
    Q_EMIT changed();
}

Curve Document::takeCurve(int index)
{
    Q_ASSERT(index >= 0 && index < curveCount());
    Q_EMIT curveAboutToBeRemoved(index);
    Curve taken = std::move(m_curves[static_cast<std::size_t>(index)]);
    m_curves.erase(m_curves.begin() + index);
    Q_EMIT curveRemoved(index);
    Q_EMIT curveCountChanged();
    Q_EMIT changed();
    return taken;
}

void Document::setPoint(int curve, int point, const geo::Point &position)
{
    if (!isValidPoint(curve, point))
        return;
    geo::Point &p = m_curves[static_cast<std::size_t>(curve)].points[static_cast<std::size_t>(point)];
    if (p == position)
        return;
    p = position;
    Q_EMIT pointMoved(curve, point);
    Q_EMIT changed();
}

} // namespace kontur
