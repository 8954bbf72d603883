// SelectedCurveModel: forwards the selected curve's row of the CurveListModel, by id.
#include "models/itemmodels/selectedcurvemodel.h"

#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"

namespace kontur {

SelectedCurveModel::SelectedCurveModel(CurveListModel *curves, Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_curves(curves)
    , m_document(document)
{
    connect(curves, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &topLeft, const QModelIndex &bottomRight, const QList<int> &roles) {
                if (m_curve == CurveId::None)
                    return;
                const int row = m_document->indexOf(m_curve);
                if (row >= topLeft.row() && row <= bottomRight.row())
                    Q_EMIT dataChanged(index(0), index(0), roles);
            });
}

void SelectedCurveModel::setCurve(CurveId curve)
{
    if (!m_document->contains(curve))
        curve = CurveId::None;
    if (curve == m_curve)
        return;
    const bool had = m_curve != CurveId::None;
    const bool has = curve != CurveId::None;
    if (had && !has) {
        beginRemoveRows({}, 0, 0);
        m_curve = curve;
        endRemoveRows();
    } else if (!had && has) {
        beginInsertRows({}, 0, 0);
        m_curve = curve;
        endInsertRows();
    } else {
        m_curve = curve;
        Q_EMIT dataChanged(index(0), index(0));
    }
}

int SelectedCurveModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || m_curve == CurveId::None ? 0 : 1;
}

QVariant SelectedCurveModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() != 0 || m_curve == CurveId::None)
        return {};
    const int row = m_document->indexOf(m_curve);
    return row >= 0 ? m_curves->data(m_curves->index(row), role) : QVariant();
}

QHash<int, QByteArray> SelectedCurveModel::roleNames() const
{
    return m_curves->roleNames();
}

} // namespace kontur
