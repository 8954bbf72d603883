// CurveListModel: rows follow the document's insertions and removals; no resets on edits.
#include "models/curvelistmodel.h"

#include "models/document.h"

namespace kontur {

CurveListModel::CurveListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(document, &Document::curveAboutToBeInserted, this,
            [this](int index) { beginInsertRows({}, index, index); });
    connect(document, &Document::curveInserted, this, [this](int index) {
        if (m_selected >= index)
            ++m_selected;
        endInsertRows();
    });
    connect(document, &Document::curveAboutToBeRemoved, this, [this](int index) {
        beginRemoveRows({}, index, index);
        if (m_selected == index)
            m_selected = -1;
        else if (m_selected > index)
            --m_selected;
    });
    connect(document, &Document::curveRemoved, this, [this](int) { endRemoveRows(); });
}

int CurveListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_document->curveCount();
}

QVariant CurveListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Curve &curve = m_document->curve(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case NameRole:
        return curve.name;
    case KindRole:
        return static_cast<int>(curve.kind);
    case KindNameRole:
        return kindName(curve.kind);
    case ColorRole:
        return curve.color;
    case PointCountRole:
        return static_cast<int>(curve.points.size());
    case SelectedRole:
        return index.row() == m_selected;
    }
    return {};
}

QHash<int, QByteArray> CurveListModel::roleNames() const
{
    return {
        {NameRole, "name"},
        {KindRole, "kind"},
        {KindNameRole, "kindName"},
        {ColorRole, "color"},
        {PointCountRole, "pointCount"},
        {SelectedRole, "selected"},
    };
}

void CurveListModel::setSelectedRow(int row)
{
    if (row == m_selected)
        return;
    const int old = m_selected;
    m_selected = row;
    if (old >= 0 && old < rowCount())
        Q_EMIT dataChanged(index(old), index(old), {SelectedRole});
    if (row >= 0 && row < rowCount())
        Q_EMIT dataChanged(index(row), index(row), {SelectedRole});
}

void CurveListModel::retranslate()
{
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0), index(rowCount() - 1), {KindNameRole});
}

} // namespace kontur
