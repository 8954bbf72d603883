// PointListModel: follows point moves of its curve with dataChanged on the moved rows only.
#include "models/pointlistmodel.h"

#include "models/document.h"

#include <QLocale>

#include <cmath>

namespace kontur {

QString displayNumber(double value, int decimals)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    const QLocale locale;
    const double magnitude = std::abs(value);
    if (value == 0.0)
        return locale.toString(value, 'f', decimals);
    if (magnitude >= std::pow(10.0, -decimals) && magnitude < 1e9) {
        const int integerDigits = std::max(1, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
        return locale.toString(value, 'f', std::clamp(7 - integerDigits, 0, decimals));
    }
    // 3 significant digits and no leading zero in the exponent: -1.23E+150 fits a cell.
    QLocale shown = locale;
    shown.setNumberOptions(shown.numberOptions() | QLocale::OmitLeadingZeroInExponent);
    return shown.toString(value, 'g', 3);
}

QString exactNumber(double value)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'g', QLocale::FloatingPointShortest);
}

PointListModel::PointListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(document, &Document::rowsChanged, this, [this](int curve, int first, int last) {
        if (curve != m_curve)
            return;
        syncRowCount();
        last = std::min(last, m_rows - 1);
        if (first <= last)
            Q_EMIT dataChanged(index(first), index(last), {XRole, YRole});
    });
    connect(document, &Document::curveChanged, this, [this](int curve) {
        if (curve != m_curve)
            return;
        syncRowCount();
        if (m_rows > 0)
            Q_EMIT dataChanged(index(0), index(m_rows - 1));
    });
    // Keep pointing at the same curve when curves before it come, go or move; show nothing when it goes.
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
    connect(document, &Document::curveMoved, this, [this](int from, int to) {
        const int c = indexAfterMove(m_curve, from, to);
        if (c != m_curve) {
            m_curve = c;
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
    m_rows = curve >= 0 ? m_document->curve(curve).rowCount() : 0;
    endResetModel();
    Q_EMIT curveChanged();
}

void PointListModel::syncRowCount()
{
    const int rows = m_curve >= 0 ? m_document->curve(m_curve).rowCount() : 0;
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
    const Curve &curve = m_document->curve(m_curve);
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
    };
}

} // namespace kontur
