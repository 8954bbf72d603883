// Selection: follows the document by id; announces what changed, once.
#include "models/document/selection.h"

#include "models/document/document.h"

namespace kontur {

Selection::Selection(Document *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
{
    // Rows come, go and move; the selected curve may be deleted (undo of its creation) or lose the
    // selected row (a point deleted). The id stays; what it stands for is looked up again.
    for (auto signal : {&Document::curveInserted, &Document::curveRemoved, &Document::curveChanged})
        connect(document, signal, this, [this](int) { followDocument(); });
    connect(document, &Document::curveMoved, this, [this](int, int) { followDocument(); });
    // Moved points change neither the curve's row nor a knot's type (those come with curveChanged):
    // a drag step only needs the selected row to still exist.
    connect(document, &Document::rowsChanged, this, [this](int curve, int, int) {
        if (curve == m_row && m_point >= m_document->curve(curve).rowCount())
            followDocument();
    });
}

const Curve *Selection::curve() const
{
    return m_document->find(m_curve);
}

int Selection::curveRow() const
{
    return m_document->indexOf(m_curve);
}

int Selection::knot() const
{
    const Curve *c = curve();
    return c && m_point >= 0 ? c->knotOfRow(m_point) : -1;
}

int Selection::nodeType() const
{
    const Curve *c = curve();
    if (!c || c->kind() != CurveKind::Composite || m_point < 0 || m_point >= c->rowCount())
        return -1;
    return static_cast<int>(c->composite().nodeType(c->knotOfRow(m_point)));
}

void Selection::select(CurveId id, int point)
{
    const Curve *c = m_document->find(id);
    if (!c)
        id = CurveId::None;
    if (!c || point < -1 || point >= c->rowCount())
        point = -1;
    const CurveId oldCurve = m_curve;
    const int oldPoint = m_point;
    m_curve = id;
    m_point = point;
    announce(oldCurve, oldPoint, m_row, m_nodeType);
}

void Selection::selectRow(int row)
{
    select(m_document->idAt(row));
}

void Selection::followDocument()
{
    const Curve *c = curve();
    const CurveId oldCurve = m_curve;
    const int oldPoint = m_point;
    if (!c) {
        m_curve = CurveId::None;
        m_point = -1;
    } else if (m_point >= c->rowCount()) {
        m_point = -1;
    }
    announce(oldCurve, oldPoint, m_row, m_nodeType);
}

void Selection::announce(CurveId oldCurve, int oldPoint, int oldRow, int oldNodeType)
{
    m_row = curveRow();
    m_nodeType = nodeType();
    const bool curveChange = oldCurve != m_curve;
    const bool pointChange = curveChange || oldPoint != m_point;
    const bool rowChange = oldRow != m_row;
    const bool nodeTypeChange = oldNodeType != m_nodeType;
    if (curveChange)
        Q_EMIT curveChanged();
    if (rowChange)
        Q_EMIT curveRowChanged();
    if (pointChange)
        Q_EMIT pointChanged();
    if (nodeTypeChange)
        Q_EMIT nodeTypeChanged();
    if (curveChange || rowChange || pointChange || nodeTypeChange)
        Q_EMIT changed();
}

} // namespace kontur
