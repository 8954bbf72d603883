// CurveCommands: the edit rules for existing curves, each edit one undo command.
#include "models/controllers/curvecommands.h"

#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/text/numbers.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

// The fewest knots of a closed composite curve (CompositeCurve::close).
constexpr int kMinClosedKnots = 3;

geo::Point toPoint(QPointF p)
{
    return {p.x(), p.y()};
}

} // namespace

CurveCommands::CurveCommands(EditController *editor)
    : QObject(editor)
    , m_editor(editor)
    , m_document(editor->document())
{
}

const Curve *CurveCommands::find(int curveId) const
{
    return m_document->find(static_cast<CurveId>(curveId));
}

const Curve *CurveCommands::editable(int curveId)
{
    const Curve *c = find(curveId);
    if (c && c->locked) {
        m_editor->showMessage(Message::CurveLocked, {c->name});
        return nullptr;
    }
    return c;
}

template <typename Edit>
bool CurveCommands::editCurve(int curveId, const QString &text, Edit edit, AllowancesFollow follow)
{
    const Curve *before = editable(curveId);
    if (!before)
        return false;
    Curve after = *before;
    const geo::Result<geo::Ok> result = edit(after);
    if (!result.ok()) {
        m_editor->sayError(*before, result.error());
        return false;
    }
    if (!after.isFinite()) {
        // Finite input whose result is not (a point moved near the largest double carries a handle
        // past it): refused, so that no model and no canvas ever holds infinity or NaN.
        m_editor->showMessage(Message::OutOfRange);
        return false;
    }
    if (after.sameState(*before))
        return true;
    m_editor->push(new ReplaceCurveCommand(m_document, before->id(), *before, std::move(after), text, nullptr, follow));
    return true;
}

bool CurveCommands::replaceStyle(int curveId, Curve after, const QString &text)
{
    const Curve *before = find(curveId);
    m_editor->push(new ReplaceCurveCommand(m_document, before->id(), *before, std::move(after), text));
    return true;
}

bool CurveCommands::deleteCurve(int curveId)
{
    const Curve *c = editable(curveId);
    if (!c)
        return false;
    m_editor->push(CurvePresenceCommand::remove(m_document, c->id()));
    return true;
}

bool CurveCommands::moveCurve(int curveId, int toRow)
{
    const int from = m_document->indexOf(static_cast<CurveId>(curveId));
    if (from < 0 || toRow < 0 || toRow >= m_document->curveCount() || from == toRow)
        return false;
    m_editor->push(new MoveCurveCommand(m_document, static_cast<CurveId>(curveId), toRow));
    return true;
}

bool CurveCommands::moveCurveBy(int curveId, int steps)
{
    const int from = m_document->indexOf(static_cast<CurveId>(curveId));
    return from >= 0 && moveCurve(curveId, from + steps);
}

bool CurveCommands::setCurveParameterization(int curveId, int parameterization)
{
    const Curve *c = find(curveId);
    if (!c || parameterization < static_cast<int>(geo::Parameterization::Uniform) ||
        parameterization > static_cast<int>(geo::Parameterization::Centripetal))
        return false;
    if (!traitsOf(c->kind()).usesParameterization) {
        m_editor->showMessage(Message::NoParameterization, {static_cast<int>(c->kind())});
        return false;
    }
    return editCurve(curveId, QCoreApplication::translate("kontur", "Change parameterization"), [&](Curve &edited) {
        edited.setParameterization(static_cast<geo::Parameterization>(parameterization));
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool CurveCommands::setCurveName(int curveId, const QString &name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty())
        return false;
    return editCurve(curveId, QCoreApplication::translate("kontur", "Rename curve"), [&](Curve &edited) {
        edited.name = trimmed;
        edited.nameGenerated = false;
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool CurveCommands::setCurveColor(int curveId, const QColor &color)
{
    if (!color.isValid())
        return false;
    return editCurve(curveId, QCoreApplication::translate("kontur", "Change colour"), [&](Curve &edited) {
        edited.color = color;
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool CurveCommands::setCurveVisible(int curveId, bool visible)
{
    // Hiding and showing work on locked curves too: a lock protects the shape, not the view.
    const Curve *c = find(curveId);
    if (!c || c->visible == visible)
        return false;
    Curve after = *c;
    after.visible = visible;
    return replaceStyle(curveId, std::move(after),
                        visible ? QCoreApplication::translate("kontur", "Show curve")
                                : QCoreApplication::translate("kontur", "Hide curve"));
}

bool CurveCommands::setCurveLocked(int curveId, bool locked)
{
    const Curve *c = find(curveId);
    if (!c || c->locked == locked)
        return false;
    Curve after = *c;
    after.locked = locked;
    return replaceStyle(curveId, std::move(after),
                        locked ? QCoreApplication::translate("kontur", "Lock curve")
                               : QCoreApplication::translate("kontur", "Unlock curve"));
}

bool CurveCommands::setNodeType(int curveId, int knot, int type)
{
    if (type < static_cast<int>(geo::NodeType::Smooth) || type > static_cast<int>(geo::NodeType::Corner))
        return false;
    return editCurve(curveId, QCoreApplication::translate("kontur", "Change node type"),
                     [&](Curve &edited) { return edited.setNodeType(knot, static_cast<geo::NodeType>(type)); });
}

bool CurveCommands::insertPoint(int curveId, int index, QPointF position)
{
    const Curve *c = find(curveId);
    if (!c)
        return false;
    const KindTraits traits = traitsOf(c->kind());
    const int count = c->placedCount();
    if (count >= traits.maxPoints) {
        m_editor->showMessage(Message::TooManyPoints, {traits.maxPoints});
        return false;
    }
    if (!toPoint(position).allFinite()) {
        // The table's "Add row" beyond a last point near the largest double.
        m_editor->showMessage(Message::OutOfRange);
        return false;
    }
    // Closing merges a last knot equal to the first (geo::CompositeCurve::close): such a knot adds nothing.
    if (c->kind() == CurveKind::Composite && c->isClosed() && index == count &&
        toPoint(position) == c->composite().knot(0)) {
        m_editor->showMessage(Message::KnotOnFirstKnot);
        return false;
    }
    return editCurve(curveId, QCoreApplication::translate("kontur", "Add point"),
                     [&](Curve &edited) { return edited.insertPoint(index, toPoint(position)); });
}

bool CurveCommands::removePoint(int curveId, int index)
{
    const Curve *c = find(curveId);
    if (!c)
        return false;
    if (c->placedCount() <= c->minimumPoints()) {
        m_editor->showMessage(Message::TooFewPoints, {static_cast<int>(c->kind()), c->minimumPoints()});
        return false;
    }
    return editCurve(curveId, QCoreApplication::translate("kontur", "Delete point"),
                     [&](Curve &edited) { return edited.removePoint(index); });
}

bool CurveCommands::setCurveOrder(int curveId, int order)
{
    return editCurve(curveId, QCoreApplication::translate("kontur", "Change order"),
                     [&](Curve &edited) { return edited.setOrder(order); });
}

bool CurveCommands::insertKnotOnSegment(int curveId, int segment, double t)
{
    return editCurve(curveId, QCoreApplication::translate("kontur", "Insert knot"),
                     [&](Curve &edited) { return edited.insertKnotOnSegment(segment, t); });
}

bool CurveCommands::closeCurve(int curveId)
{
    // A closed composite curve needs 3 knots (two would be one segment there and back): said with
    // that number, not the 2 an open one needs.
    if (const Curve *c = find(curveId);
        c && !c->locked && c->kind() == CurveKind::Composite && !c->isClosed() && c->placedCount() < kMinClosedKnots) {
        m_editor->showMessage(Message::TooFewPoints, {static_cast<int>(CurveKind::Composite), kMinClosedKnots});
        return false;
    }
    return editCurve(curveId, QCoreApplication::translate("kontur", "Close curve"),
                     [&](Curve &edited) { return edited.close(); });
}

bool CurveCommands::setControlPoints(CurveId curveId, const std::vector<geo::Point> &points, const QString &text)
{
    const Curve *c = m_document->find(curveId);
    if (!c || c->kind() != CurveKind::Bezier)
        return false;
    const KindTraits traits = traitsOf(CurveKind::Bezier);
    const int count = static_cast<int>(points.size());
    if (count < traits.minPoints || count > traits.maxPoints)
        return false;
    return editCurve(static_cast<int>(curveId), text, [&](Curve &edited) -> geo::Result<geo::Ok> {
        Curve made = Curve::make(CurveKind::Bezier, points);
        if (made.problem())
            return *made.problem();
        made.copyStyleFrom(edited);
        edited = std::move(made);
        return geo::Ok{};
    });
}

bool CurveCommands::splitBezier(CurveId curveId, double t)
{
    const Curve *before = editable(static_cast<int>(curveId));
    if (!before || before->kind() != CurveKind::Bezier || !(t > 0.0 && t < 1.0))
        return false;
    const auto [left, right] = before->segment(0).split(t);
    Curve first = Curve::make(CurveKind::Bezier, left.controlPoints());
    Curve second = Curve::make(CurveKind::Bezier, right.controlPoints());
    if (!first.isFinite() || !second.isFinite()) {
        m_editor->showMessage(Message::OutOfRange);
        return false;
    }
    first.copyStyleFrom(*before);
    second.copyStyleFrom(*before);
    second.name = m_editor->newCurveName(CurveKind::Bezier);
    const int index = m_document->indexOf(curveId);
    auto *split = new QUndoCommand(QCoreApplication::translate("kontur", "Split curve"));
    new ReplaceCurveCommand(m_document, curveId, *before, std::move(first),
                            QCoreApplication::translate("kontur", "Split curve"), split);
    CurvePresenceCommand::add(m_document, index + 1, std::move(second), split);
    m_editor->push(split);
    return true;
}

bool CurveCommands::splitCurve(CurveId curveId, double u)
{
    const Curve *before = editable(static_cast<int>(curveId));
    if (!before || !(u > 0.0 && u < 1.0))
        return false;
    if (before->kind() == CurveKind::Bezier)
        return splitBezier(curveId, u);
    const geo::PiecewiseBezier whole = before->toPiecewise();
    const std::vector<geo::Bezier> &pieces = whole.segments();
    const int m = static_cast<int>(pieces.size());
    if (m == 0)
        return false;
    const bool closed = before->isClosed();
    // The pieces before and after u; at a joint no piece is cut.
    const double x = u * m;
    const int s = std::clamp(static_cast<int>(std::floor(x)), 0, m - 1);
    const double local = x - s;
    std::vector<geo::Bezier> left(pieces.begin(), pieces.begin() + s);
    std::vector<geo::Bezier> right;
    if (local > 0.0) {
        auto [a, b] = pieces[static_cast<std::size_t>(s)].split(local);
        left.push_back(std::move(a));
        right.push_back(std::move(b));
    } else {
        right.push_back(pieces[static_cast<std::size_t>(s)]);
    }
    right.insert(right.end(), pieces.begin() + s + 1, pieces.end());
    // Each part as its exact composite curve. A composite curve's own knots keep their types: knot k
    // of a part begins its piece k, which is the source's piece (firstPiece + k) mod m.
    std::vector<std::pair<std::vector<geo::Bezier>, int>> halves;
    if (closed) { // one open curve from u round to u
        std::vector<geo::Bezier> round = right;
        round.insert(round.end(), left.begin(), left.end());
        halves.emplace_back(std::move(round), s);
    } else {
        halves.emplace_back(std::move(left), 0);
        halves.emplace_back(std::move(right), s);
    }
    std::vector<Curve> parts;
    for (auto &[half, firstPiece] : halves) {
        auto composite = geo::compositeFromPieces(half, false);
        if (!composite) {
            m_editor->showMessage(Message::NotPossibleForKind, {static_cast<int>(before->kind())});
            return false;
        }
        if (before->kind() == CurveKind::Composite)
            for (int k = 1; k + 1 < composite->knotCount(); ++k)
                composite->setNodeTypeOnly(k, before->composite().nodeType((firstPiece + k) % m));
        parts.push_back(*Curve::makeComposite(std::move(composite).value()));
    }
    for (Curve &part : parts) {
        if (!part.isFinite()) {
            m_editor->showMessage(Message::OutOfRange);
            return false;
        }
        part.copyStyleFrom(*before);
    }
    const QString text = QCoreApplication::translate("kontur", "Split curve");
    auto *split = new QUndoCommand(text);
    if (parts.size() == 2)
        parts[1].name = m_editor->newCurveName(CurveKind::Composite);
    const int index = m_document->indexOf(curveId);
    new ReplaceCurveCommand(m_document, curveId, *before, std::move(parts[0]), text, split);
    if (parts.size() == 2)
        CurvePresenceCommand::add(m_document, index + 1, std::move(parts[1]), split);
    m_editor->push(split);
    return true;
}

bool CurveCommands::applyCoordinates(int curveId, const QVariantList &rows)
{
    const Curve *c = find(curveId);
    if (!c)
        return false;
    std::vector<geo::Point> points;
    if (!m_editor->accepted(parsePoints(rows, points)))
        return false;
    if (static_cast<int>(points.size()) != c->definingCount()) {
        // Rows are added and deleted with insertPoint / removePoint; here they are only edited.
        m_editor->showMessage(Message::FillAllValues);
        return false;
    }
    // Only the rows the user changed are applied, in order; a composite knot that moves carries its
    // handles, which then are not "changed" rows even though their typed values are the old ones.
    std::vector<RowEdit> moves;
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        const geo::Point &p = points[static_cast<std::size_t>(i)];
        if (c->definingPoint(i) != p)
            moves.push_back({i, p.x(), p.y()});
    }
    return moveRows(curveId, moves, QCoreApplication::translate("kontur", "Edit coordinates"));
}

bool CurveCommands::moveRows(int curveId, const std::vector<RowEdit> &moves, const QString &text,
                             AllowancesFollow follow)
{
    const geo::HandleMove mode = m_editor->handleMoveMode();
    // Knots first: a knot carries its handles (and nothing else moves with a handle), so a handle or
    // tangent end typed in the same OK ends where it was typed, not shifted by its knot's move.
    std::vector<RowEdit> ordered = moves;
    if (const Curve *c = find(curveId)) {
        std::stable_partition(ordered.begin(), ordered.end(), [&](const RowEdit &m) {
            return m.row >= 0 && m.row < c->rowCount() && c->row(m.row).role == PointRole::Knot;
        });
    }
    const auto edit = [&](Curve &edited) {
        for (const RowEdit &move : ordered) {
            // An axis not given keeps the double the row holds now, after the rows before it moved
            // (a knot carries its handles): never the rounded text the table shows.
            geo::Point position = edited.row(move.row).position;
            if (move.x)
                position.x() = *move.x;
            if (move.y)
                position.y() = *move.y;
            // Composite handles keep the mode's rule, as if dragged there (docs/requirements.md 1.4).
            const auto moved = edited.move(move.row, position, mode);
            if (!moved.ok())
                return geo::Result<geo::Ok>(moved.error());
        }
        return geo::Result<geo::Ok>(geo::Ok{});
    };
    return editCurve(curveId, text, edit, follow);
}

bool CurveCommands::applyEdits(int curveId, const QVariantList &edits)
{
    const Curve *c = find(curveId);
    if (!c)
        return false;
    std::vector<RowEdit> moves;
    for (const QVariant &item : edits) {
        const QVariantMap edit = item.toMap();
        const int row = edit.value(QStringLiteral("row"), -1).toInt();
        if (row < 0 || row >= c->rowCount())
            return false;
        RowEdit move{row, {}, {}};
        for (const auto &[key, axis] :
             {std::pair{QStringLiteral("x"), &move.x}, std::pair{QStringLiteral("y"), &move.y}}) {
            if (!edit.contains(key))
                continue; // not typed: the stored double stays
            double value = 0.0;
            if (!m_editor->accepted(parseNumber(edit.value(key), value)))
                return false;
            *axis = value;
        }
        if (!move.x && !move.y)
            continue;
        if (!c->row(row).editable) {
            m_editor->showMessage(Message::ControlPointsNotMovable, {static_cast<int>(c->kind())});
            return false;
        }
        moves.push_back(move);
    }
    if (moves.empty())
        return true;
    return moveRows(curveId, moves, QCoreApplication::translate("kontur", "Edit coordinates"));
}

bool CurveCommands::nudgeSelected(QPointF delta)
{
    const Selection *selection = m_editor->selection();
    const Curve *c = selection->curve();
    const int row = selection->point();
    if (!c || row < 0 || !std::isfinite(delta.x()) || !std::isfinite(delta.y()))
        return false;
    if (!c->row(row).editable) {
        m_editor->showMessage(Message::ControlPointsNotMovable, {static_cast<int>(c->kind())});
        return false;
    }
    const geo::Point target = c->row(row).position + toPoint(delta);
    if (!target.allFinite()) {
        m_editor->showMessage(Message::OutOfRange);
        return false;
    }
    return moveRows(selection->curveIdValue(), {{row, target.x(), target.y()}},
                    QCoreApplication::translate("kontur", "Move point"), AllowancesFollow::Later);
}

bool CurveCommands::deleteSelection()
{
    const Selection *selection = m_editor->selection();
    const Curve *c = selection->curve();
    if (!c)
        return false;
    const int curve = selection->curveIdValue();
    if (c->isKnotRow(selection->point()) && c->placedCount() > c->minimumPoints())
        return removePoint(curve, selection->knot());
    return deleteCurve(curve);
}

bool CurveCommands::addRowAfterSelection()
{
    Selection *selection = m_editor->selection();
    const Curve *c = selection->curve();
    if (!c)
        return false;
    const int curve = selection->curveIdValue();
    const int count = c->placedCount();
    int after = c->isKnotRow(selection->point()) ? selection->knot() : -1;
    if (after < 0)
        after = count - 1;
    const auto placed = [&](int i) { return c->definingPoint(c->rowOfKnot(i)); };
    geo::Point position = placed(after);
    if (after + 1 < count)
        position = 0.5 * (placed(after) + placed(after + 1));
    else if (after > 0)
        position = placed(after) + (placed(after) - placed(after - 1));
    else
        position += geo::Point(10, 0);
    if (!insertPoint(curve, after + 1, QPointF(position.x(), position.y())))
        return false;
    const Curve *changed = selection->curve();
    selection->select(changed->id(), changed->rowOfKnot(after + 1));
    return true;
}

bool CurveCommands::deleteSelectedRow()
{
    const Selection *selection = m_editor->selection();
    const Curve *c = selection->curve();
    if (!c || !c->isKnotRow(selection->point()))
        return false;
    return removePoint(selection->curveIdValue(), selection->knot());
}

QString CurveCommands::coordinatesText(int curveId) const
{
    const Curve *c = find(curveId);
    if (!c)
        return {};
    // Every digit the double has, and no group separators, which spreadsheets would take for the
    // end of the number.
    QString text;
    for (int r = 0; r < c->rowCount(); ++r) {
        const PointRow row = c->row(r);
        text += pointLabel(row.role, row.number) + QLatin1Char('\t') + exactNumber(row.position.x()) +
                QLatin1Char('\t') + exactNumber(row.position.y()) + QLatin1Char('\n');
    }
    return text;
}

QVariantList CurveCommands::jointReport(int curveId, int limit) const
{
    QVariantList list;
    const Curve *c = find(curveId);
    if (!c)
        return list;
    const int segments = c->segmentCount();
    const int joints = c->isClosed() ? segments : segments - 1;
    for (int j = 0; j < joints && j < limit; ++j) {
        const auto report = geo::jointContinuity(c->segment(j), c->segment((j + 1) % segments));
        list << QVariantMap{{QStringLiteral("joint"), j + 1},
                            {QStringLiteral("level"), QString::fromLatin1(geo::nameOf(report.level))},
                            {QStringLiteral("angle"), report.angle * 180.0 / M_PI},
                            {QStringLiteral("c1Jump"), report.c1Jump}};
    }
    return list;
}

int CurveCommands::degreeOf(int curveId) const
{
    const Curve *c = find(curveId);
    return c && c->segmentCount() > 0 ? c->segment(0).degree() : -1;
}

void CurveCommands::addCurves(std::vector<Curve> curves, const QString &text)
{
    if (curves.empty())
        return;
    auto *add = new QUndoCommand(text);
    CurvePresenceCommand *last = nullptr;
    for (Curve &curve : curves) {
        if (curve.name.isEmpty())
            curve.name = m_editor->newCurveName(curve.kind());
        last =
            CurvePresenceCommand::add(m_document, m_document->curveCount() + add->childCount(), std::move(curve), add);
    }
    m_editor->push(add);
    m_editor->selection()->select(last->curveId());
    Q_EMIT m_editor->documentReplaced();
}

CurveId CurveCommands::appendCurve(Curve curve, const QString &text)
{
    auto *add = CurvePresenceCommand::add(m_document, m_document->curveCount(), std::move(curve));
    if (!text.isEmpty())
        add->setText(text);
    m_editor->push(add);
    m_editor->selection()->select(add->curveId());
    return add->curveId();
}

void CurveCommands::resetAll()
{
    m_editor->placement()->cancel();
    m_editor->endDrag();
    if (m_document->curveCount() == 0 && m_document->background() == Background{})
        return;
    auto *reset = new QUndoCommand(QCoreApplication::translate("kontur", "Reset all"));
    for (int c = m_document->curveCount() - 1; c >= 0; --c)
        CurvePresenceCommand::remove(m_document, m_document->idAt(c), reset);
    if (!(m_document->background() == Background{}))
        new BackgroundCommand(m_document, m_document->background(), Background{}, reset);
    m_editor->push(reset);
    m_editor->clearMessage();
}

} // namespace kontur
