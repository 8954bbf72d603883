// The document's mutators and their notifications.
#include "models/document/document.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace kontur {

namespace {

// After a move whose changes are `changes`: are the curve's rows and segments still finite? A
// composite curve's segments are its rows (the control vector), so its changed rows tell; every
// other kind may derive any row or segment from the moved one (a spline's whole shape).
bool finiteAfter(const Curve &curve, const std::vector<PointChange> &changes)
{
    if (!std::all_of(changes.begin(), changes.end(), [](const PointChange &c) { return c.after.allFinite(); }))
        return false;
    return curve.kind() == CurveKind::Composite || curve.isFinite();
}

} // namespace

Document::Document(QObject *parent)
    : QObject(parent)
{
    // Connected first, so the seams of a changed curve are forgotten before anyone else is told.
    connect(this, &Document::curveChanged, this, &Document::forgetSeams);
    connect(this, &Document::rowsChanged, this, [this](int curve, int, int) { forgetSeams(curve); });
    connect(this, &Document::curveInserted, this, &Document::forgetSeams);
    connect(this, &Document::curveAboutToBeRemoved, this, &Document::forgetSeams);
}

int Document::indexOf(CurveId id) const
{
    if (id == CurveId::None)
        return -1;
    // The row asked last: a drag asks for the same curve several times a step. Ids are unique, so a
    // curve with this id at that row is the answer, whatever moved since.
    if (m_lastRow < curveCount() && m_curves[static_cast<std::size_t>(m_lastRow)].m_id == id)
        return m_lastRow;
    if (m_rowsStale) {
        m_rowOfId.clear();
        m_rowOfId.reserve(curveCount());
        for (int i = 0; i < curveCount(); ++i)
            m_rowOfId.insert(static_cast<int>(curve(i).id()), i);
        m_rowsStale = false;
    }
    const int row = m_rowOfId.value(static_cast<int>(id), -1);
    if (row >= 0)
        m_lastRow = row;
    return row;
}

const Curve *Document::find(CurveId id) const
{
    const int index = indexOf(id);
    return index >= 0 ? &curve(index) : nullptr;
}

CurveId Document::insertCurve(EditKey, int index, Curve curve)
{
    index = std::clamp(index, 0, curveCount());
    if (curve.m_id == CurveId::None || contains(curve.m_id))
        curve.m_id = static_cast<CurveId>(++m_lastId);
    else
        m_lastId = std::max(m_lastId, static_cast<int>(curve.m_id));
    const CurveId id = curve.m_id;
    Q_EMIT curveAboutToBeInserted(index);
    m_curves.insert(m_curves.begin() + index, std::move(curve));
    if (index == curveCount() - 1 && !m_rowsStale)
        m_rowOfId.insert(static_cast<int>(id), index); // appending keeps every other row
    else
        m_rowsStale = true;
    Q_EMIT curveInserted(index);
    Q_EMIT curveCountChanged();
    Q_EMIT changed();
    if (m_curves[static_cast<std::size_t>(index)].seam)
        refreshAllowance(index);
    allowancesFollow(id);
    return id;
}

Curve Document::takeCurve(EditKey, int index)
{
    Q_ASSERT(index >= 0 && index < curveCount());
    Q_EMIT curveAboutToBeRemoved(index);
    Curve taken = std::move(m_curves[static_cast<std::size_t>(index)]);
    m_curves.erase(m_curves.begin() + index);
    dropStale(taken.m_id); // an undo brings it back computed anew
    m_rowsStale = true;
    Q_EMIT curveRemoved(index);
    Q_EMIT curveCountChanged();
    Q_EMIT changed();
    return taken;
}

void Document::moveCurve(EditKey, int from, int to)
{
    if (from == to || from < 0 || to < 0 || from >= curveCount() || to >= curveCount())
        return;
    Q_EMIT curveAboutToBeMoved(from, to);
    Curve moving = std::move(m_curves[static_cast<std::size_t>(from)]);
    m_curves.erase(m_curves.begin() + from);
    m_curves.insert(m_curves.begin() + to, std::move(moving));
    m_rowsStale = true;
    Q_EMIT curveMoved(from, to);
    Q_EMIT changed();
}

void Document::replaceCurve(EditKey, int index, Curve curve)
{
    if (index < 0 || index >= curveCount())
        return;
    curve.m_id = m_curves[static_cast<std::size_t>(index)].m_id;
    dropStale(curve.m_id); // replaced as a whole: a job of its old link is of no use
    m_curves[static_cast<std::size_t>(index)] = std::move(curve);
    Q_EMIT curveChanged(index);
    Q_EMIT changed();
    if (m_curves[static_cast<std::size_t>(index)].seam)
        refreshAllowance(index);
    allowancesFollow(m_curves[static_cast<std::size_t>(index)].m_id);
}

void Document::setPiece(EditKey, int index, const std::optional<io::PieceMarks> &piece)
{
    if (index < 0 || index >= curveCount())
        return;
    // The seams' widths shape the piece's allowance.
    const auto widthsOf = [](const std::optional<io::PieceMarks> &p) {
        return p ? std::pair(p->seamWidths, p->hems)
                 : std::pair<std::vector<std::optional<double>>, std::vector<int>>{};
    };
    Curve &curve = m_curves[static_cast<std::size_t>(index)];
    const bool widthsChanged = widthsOf(curve.piece) != widthsOf(piece);
    curve.piece = piece;
    Q_EMIT curveChanged(index);
    Q_EMIT changed();
    if (widthsChanged)
        allowancesFollow(curve.m_id);
}

std::vector<int> Document::resolveSeamLinks(EditKey, int first)
{
    for (int row = std::max(first, 0); row < curveCount(); ++row) {
        Curve &c = m_curves[static_cast<std::size_t>(row)];
        if (!c.seam || c.seam->fileIndex < 0)
            continue;
        const int source = first + c.seam->fileIndex;
        if (source == row || source >= curveCount()) {
            c.seam.reset();
        } else {
            c.seam->source = curve(source).m_id;
            c.seam->fileIndex = -1;
        }
        Q_EMIT curveChanged(row);
    }
    std::vector<int> failed;
    for (int row = std::max(first, 0); row < curveCount(); ++row)
        if (m_curves[static_cast<std::size_t>(row)].seam && !recomputeAllowance(row))
            failed.push_back(row);
    return failed;
}

void Document::announceRows(int curve, const std::vector<PointChange> &changes)
{
    const Curve &c = m_curves[static_cast<std::size_t>(curve)];
    if (geo::isFittedKind(c.kind())) {
        // A moved knot moves the fitted control points too: they are the rows after the knots.
        int first = c.rowCount();
        for (const PointChange &change : changes)
            first = std::min(first, change.row);
        Q_EMIT rowsChanged(curve, first, std::max(first, c.rowCount() - 1));
    } else if (!changes.empty()) {
        int first = changes.front().row, last = first;
        for (const PointChange &change : changes) {
            first = std::min(first, change.row);
            last = std::max(last, change.row);
        }
        Q_EMIT rowsChanged(curve, first, last);
    }
    Q_EMIT changed();
}

void Document::setPoints(EditKey, int curve, const std::vector<PointChange> &changes, bool useAfter)
{
    if (curve < 0 || curve >= curveCount() || changes.empty())
        return;
    m_curves[static_cast<std::size_t>(curve)].setPoints(changes, useAfter);
    announceRows(curve, changes);
    allowancesFollow(m_curves[static_cast<std::size_t>(curve)].m_id);
}

geo::Result<std::vector<PointChange>> Document::movePoint(EditKey, int curve, int row, const geo::Point &target,
                                                          geo::HandleMove mode)
{
    if (curve < 0 || curve >= curveCount())
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no curve " + std::to_string(curve), curve};
    if (!target.allFinite())
        return geo::Error{geo::ErrorCode::NonFiniteInput, "the target is not a finite point", row};
    Curve &moved = m_curves[static_cast<std::size_t>(curve)];
    auto changes = moved.move(row, target, mode);
    if (!changes.ok() || changes->empty())
        return changes;
    if (!finiteAfter(moved, *changes)) {
        // Taken back before anyone is told: nobody ever sees the overflowed state.
        moved.setPoints(*changes, false);
        return geo::Error{geo::ErrorCode::NonFiniteInput, "the move would take points past the largest number", row};
    }
    announceRows(curve, *changes);
    allowancesFollow(moved.m_id);
    return changes;
}

void Document::setBackground(EditKey, const Background &background)
{
    if (background == m_background)
        return;
    m_background = background;
    Q_EMIT backgroundChanged();
    Q_EMIT changed();
}

void Document::setUnits(EditKey, const QString &units)
{
    if (units == m_units)
        return;
    m_units = units;
    Q_EMIT unitsChanged();
}

} // namespace kontur
