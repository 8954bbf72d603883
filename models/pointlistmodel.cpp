// PointListModel: follows point moves of its curve with dataChanged on that row only.
#include "models/pointlistmodel.h"

#include "models/document.h"

namespace kontur {

PointListModel::PointListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(document, &Document::pointMoved, this, [this](int curve, int point) {
        if (curve == m_curve)
            Q_EMIT dataChanged(index(point), index(point), {XRole, YRole});
    });
    // Keep pointing at the same curve when curves before it come and go; show nothing when it goes.
    connect(document, &Document::curveAboutToBeRemoved, this, [this](int index) {
        if (index == m_curve)
            setCurve(-1);
    });
    connect(document, &Document::curveRemoved, this, [this](int index) {
        if (m_curve > index) {
            --m_curve;
            Q_EMIT curveChanged();
        }
    });
    connect(document, &Document::curveInserted, this, [this](int index) {
        if (m_curve >= index) {
            ++m_curve;
            Q_EMIT curveChanged();
        }
    });
}

void PointListModel::setCurve(int curve)
{
    if (curve < -1 || curve >= m_document->curveCount())
        curve = -1;
    if (curve == m_curve)
        return;
    beginResetModel();
    m_curve = curve;
    endResetModel();
    Q_EMIT curveChanged();
}

int PointListModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() || m_curve < 0)
        return 0;
    return static_cast<int>(m_document->curve(m_curve).points.size());
}

QVariant PointListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Curve &curve = m_document->curve(m_curve);
    const geo::Point &p = curve.points[static_cast<std::size_t>(index.row())];
    const PointRole pointRole = curve.roleOf(index.row());
    switch (role) {
    case XRole:
        return p.x();
    case YRole:
        return p.y();
    case PointRoleRole:
        return static_cast<int>(pointRole);
    case Qt::DisplayRole:
    case LabelRole:
        return pointLabel(pointRole, index.row());
    case EditableRole:
        // Control points of a Bézier curve move freely (SPEC.md 1.4).
        return pointRole == PointRole::ControlPoint;
    }
    return {};
}

QHash<int, QByteArray> PointListModel::roleNames() const
{
    return {
        {XRole, "x"}, {YRole, "y"}, {PointRoleRole, "pointRole"}, {LabelRole, "label"}, {EditableRole, "editable"},
    };
}

} // namespace kontur
