// CurveListModel: rows follow the document's insertions, removals and moves; point moves notify
// only the derived roles of that curve's row; nothing resets the model.
#include "models/itemmodels/curvelistmodel.h"

#include "models/document/document.h"

namespace kontur {

CurveListModel::CurveListModel(Document *document, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(document, &Document::curveAboutToBeInserted, this,
            [this](int index) { beginInsertRows({}, index, index); });
    connect(document, &Document::curveInserted, this, [this](int) { endInsertRows(); });
    connect(document, &Document::curveAboutToBeRemoved, this, [this](int index) { beginRemoveRows({}, index, index); });
    connect(document, &Document::curveRemoved, this, [this](int) { endRemoveRows(); });
    connect(document, &Document::curveAboutToBeMoved, this, [this](int from, int to) {
        // Qt's destination row is the row before which the moved one lands (in the old numbering).
        beginMoveRows({}, from, from, {}, to > from ? to + 1 : to);
    });
    connect(document, &Document::curveMoved, this, [this](int, int) { endMoveRows(); });
    connect(document, &Document::rowsChanged, this, [this](int curve, int, int) {
        const QModelIndex i = index(curve);
        Q_EMIT dataChanged(i, i,
                           {PointCountRole, LengthRole, FitRmsRole, FitMaxErrorRole, ContinuityRole, ProblemRole});
    });
    connect(document, &Document::curveChanged, this, [this](int curve) {
        const QModelIndex i = index(curve);
        Q_EMIT dataChanged(i, i);
    });
}

int CurveListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_document->curveCount();
}

QVariant CurveListModel::data(const QModelIndex &index, int role) const
{
    // Views and bindings may ask with an invalid index (nothing selected): no data, no warning.
    if (!index.isValid() || index.parent().isValid() || index.row() >= rowCount())
        return {};
    const Curve &curve = m_document->curve(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case NameRole:
        return curve.name;
    case KindRole:
        return static_cast<int>(curve.kind());
    case KindNameRole:
        return kindName(curve.kind());
    case ColorRole:
        return curve.color;
    case VisibleRole:
        return curve.visible;
    case LockedRole:
        return curve.locked;
    case ParameterizationRole:
        return traitsOf(curve.kind()).usesParameterization ? static_cast<int>(curve.parameterization()) : -1;
    case PointCountRole:
        // What the user placed: knots of a composite curve (its handles follow from them).
        return curve.placedCount();
    case LengthRole:
        // Relative to the curve's size (Curve::length with no absolute accuracy: 1e-9 of it), so
        // that a curve far from the origin or of any size is measured in bounded time.
        return curve.length(0.0);
    case FitRmsRole:
        return curve.fit() ? curve.fit()->rms : -1.0;
    case FitMaxErrorRole:
        return curve.fit() ? curve.fit()->maxError : -1.0;
    case ContinuityRole: {
        const ContinuitySummary summary = curve.continuity();
        return summary.joints > 0 ? QString::fromLatin1(geo::nameOf(summary.weakest)) : QString();
    }
    case ProblemRole:
        return curve.problem().has_value();
    case SelectedRole:
        return m_selected != CurveId::None && curve.id() == m_selected;
    case CurveIdRole:
        return static_cast<int>(curve.id());
    case DegreeRole:
        return curve.segmentCount() > 0 ? curve.segment(0).degree() : -1;
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
        {VisibleRole, "curveVisible"},
        {LockedRole, "locked"},
        {ParameterizationRole, "parameterization"},
        {PointCountRole, "pointCount"},
        {LengthRole, "length"},
        {FitRmsRole, "fitRms"},
        {FitMaxErrorRole, "fitMaxError"},
        {ContinuityRole, "continuity"},
        {ProblemRole, "problem"},
        {SelectedRole, "selected"},
        {CurveIdRole, "curveId"},
        {DegreeRole, "degree"},
    };
}

void CurveListModel::setSelected(CurveId curve)
{
    if (curve == m_selected)
        return;
    const int old = m_document->indexOf(m_selected);
    m_selected = curve;
    const int row = m_document->indexOf(curve);
    if (old >= 0)
        Q_EMIT dataChanged(index(old), index(old), {SelectedRole});
    if (row >= 0)
        Q_EMIT dataChanged(index(row), index(row), {SelectedRole});
}

void CurveListModel::retranslate()
{
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0), index(rowCount() - 1), {KindNameRole});
}

} // namespace kontur
