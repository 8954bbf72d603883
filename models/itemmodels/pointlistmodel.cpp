// PointListModel: follows point moves of its curve with dataChanged on the moved rows only.
#include "models/itemmodels/pointlistmodel.h"

#include "models/document/document.h"
#include "models/text/numbers.h"

namespace kontur {

namespace {

// What a point move changes: its coordinates and their texts (one list, made once: a drag step
// announces it).
const QList<int> &movedRoles()
{
    static const QList<int> roles{PointListModel::XRole,     PointListModel::YRole,      PointListModel::XTextRole,
                                  PointListModel::YTextRole, PointListModel::XExactRole, PointListModel::YExactRole};
    return roles;
}

// What another curve changes in a row: every role the row has.
const QList<int> &allRoles()
{
    static const QList<int> roles{Qt::DisplayRole,
                                  PointListModel::XRole,
                                  PointListModel::YRole,
                                  PointListModel::PointRoleRole,
                                  PointListModel::LabelRole,
                                  PointListModel::EditableRole,
                                  PointListModel::NodeTypeRole,
                                  PointListModel::XTextRole,
                                  PointListModel::YTextRole,
                                  PointListModel::XExactRole,
                                  PointListModel::YExactRole};
    return roles;
}

} // namespace

PointListModel::PointListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(document, &Document::rowsChanged, this, [this](int curve, int first, int last) {
        if (m_curve == CurveId::None || m_document->idAt(curve) != m_curve)
            return;
        syncRowCount();
        last = std::min(last, m_rows - 1);
        if (first <= last)
            Q_EMIT dataChanged(index(first), index(last), movedRoles());
    });
    connect(document, &Document::curveChanged, this, [this](int curve) {
        if (m_curve == CurveId::None || m_document->idAt(curve) != m_curve)
            return;
        syncRowCount();
        if (m_rows > 0)
            Q_EMIT dataChanged(index(0), index(m_rows - 1));
    });
    // Show nothing when the curve goes; it is held by id, so curves before it coming, going or
    // moving change nothing here.
    connect(document, &Document::curveAboutToBeRemoved, this, [this](int index) {
        if (m_curve != CurveId::None && m_document->idAt(index) == m_curve)
            setCurve(CurveId::None);
    });
}

const Curve *PointListModel::shown() const
{
    return m_document->find(m_curve);
}

void PointListModel::setCurve(CurveId curve)
{
    if (!m_document->contains(curve))
        curve = CurveId::None;
    if (curve == m_curve)
        return;
    // Not a reset: a view keeps the delegates of the rows both curves have and only announces
    // their new data (a reset made the coordinates table create all of them again, most of a
    // selection change's time on the GUI thread). The surplus rows go while the old curve is
    // still shown, the missing ones come once the new one is.
    const Curve *next = m_document->find(curve);
    const int rows = next ? next->rowCount() : 0;
    if (rows < m_rows) {
        beginRemoveRows({}, rows, m_rows - 1);
        m_rows = rows;
        endRemoveRows();
    }
    m_curve = curve;
    if (m_rows > 0)
        Q_EMIT dataChanged(index(0), index(m_rows - 1), allRoles());
    syncRowCount();
    Q_EMIT curveChanged();
}

void PointListModel::retranslate()
{
    if (m_rows > 0)
        Q_EMIT dataChanged(index(0), index(m_rows - 1), {LabelRole, XTextRole, YTextRole, XExactRole, YExactRole});
}

void PointListModel::syncRowCount()
{
    const Curve *c = shown();
    const int rows = c ? c->rowCount() : 0;
    if (rows > m_rows) {
        beginInsertRows({}, m_rows, rows - 1);
        m_rows = rows;
        endInsertRows();
    } else if (rows < m_rows) {
        beginRemoveRows({}, rows, m_rows - 1);
        m_rows = rows;
        endRemoveRows();
    }
}

int PointListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

QVariant PointListModel::data(const QModelIndex &index, int role) const
{
    // Views and bindings may ask with an invalid index (nothing selected): no data, no warning.
    if (!index.isValid() || index.parent().isValid() || index.row() >= rowCount())
        return {};
    const Curve *shownCurve = shown();
    if (!shownCurve || index.row() >= shownCurve->rowCount())
        return {};
    const Curve &curve = *shownCurve;
    if (index.row() >= curve.rowCount())
        return {};
    const PointRow row = curve.row(index.row());
    switch (role) {
    case XRole:
        return row.position.x();
    case YRole:
        return row.position.y();
    case PointRoleRole:
        return static_cast<int>(row.role);
    case Qt::DisplayRole:
    case LabelRole:
        return pointLabel(row.role, row.number);
    case EditableRole:
        return row.editable && !curve.locked;
    case XTextRole:
        return displayNumber(row.position.x(), 3);
    case YTextRole:
        return displayNumber(row.position.y(), 3);
    case XExactRole:
        return exactNumber(row.position.x());
    case YExactRole:
        return exactNumber(row.position.y());
    case NodeTypeRole:
        return curve.kind() == CurveKind::Composite && row.role == PointRole::Knot ? static_cast<int>(row.nodeType)
                                                                                   : -1;
    }
    return {};
}

QHash<int, QByteArray> PointListModel::roleNames() const
{
    return {
        {XRole, "x"},
        {YRole, "y"},
        {PointRoleRole, "pointRole"},
        {LabelRole, "label"},
        {EditableRole, "editable"},
        {NodeTypeRole, "nodeType"},
        {XTextRole, "xText"},
        {YTextRole, "yText"},
        {XExactRole, "xExact"},
        {YExactRole, "yExact"},
    };
}

} // namespace kontur
