// PieceEdits: see pieceedits.h.
#include "models/controllers/pieceedits.h"

#include "geometry/compositeedit.h"
#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/text/numbers.h"

#include <QCoreApplication>

#include <cmath>
#include <limits>

namespace kontur {

namespace {

// A curve may take part in these edits: composite, with its own points (not a seam allowance,
// which follows its source), not locked.
bool shapeable(const Curve *c)
{
    return c && c->kind() == CurveKind::Composite && !c->locked && !c->seam;
}

bool isOpenShapeable(const Curve *c)
{
    return shapeable(c) && !c->isClosed() && c->composite().knotCount() >= 2;
}

// `made` with the style (name, colour, visibility, lock) of `like`, and its piece's marks while it
// stays closed (a simplified or straightened piece is the same piece).
Curve styledLike(geo::CompositeCurve made, const Curve &like)
{
    Curve curve = *Curve::makeComposite(std::move(made));
    curve.copyStyleFrom(like);
    if (curve.isClosed())
        curve.piece = like.piece;
    return curve;
}

// Where a curve meets another at its ends: which end of each, and how far apart.
struct EndMatch
{
    const Curve *other = nullptr;
    bool atOwnStart = false;   // the own curve's first knot (else its last)
    bool atOtherStart = false; // the other curve's first knot (else its last)
    double distance = std::numeric_limits<double>::infinity();
};

void consider(EndMatch &best, const Curve *other, const geo::CompositeCurve &own, const geo::CompositeCurve &theirs)
{
    const geo::Point ownEnds[2] = {own.knot(0), own.knot(own.knotCount() - 1)};
    const geo::Point otherEnds[2] = {theirs.knot(0), theirs.knot(theirs.knotCount() - 1)};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            const double d = (ownEnds[i] - otherEnds[j]).norm();
            if (d < best.distance)
                best = {other, i == 0, j == 0, d};
        }
}

// `own` and `other` as one curve, `own` unchanged: joined at the ends a match names, `own` first
// in its own direction (then reversed back where `other` comes before it).
geo::Result<geo::CompositeCurve> joinAt(const geo::CompositeCurve &own, const geo::CompositeCurve &other,
                                        bool atOwnStart, bool atOtherStart, double mergeDistance)
{
    const geo::JoinOptions options{mergeDistance, PieceEdits::cornerAngle};
    auto first = atOwnStart ? geo::reversed(own) : geo::Result<geo::CompositeCurve>(own);
    if (!first)
        return first;
    // The other curve must leave the joint: its start there, else reversed.
    auto second = atOtherStart ? geo::Result<geo::CompositeCurve>(other) : geo::reversed(other);
    if (!second)
        return second;
    auto joined = geo::joinComposites(*first, *second, options);
    if (!joined || !atOwnStart)
        return joined;
    return geo::reversed(*joined);
}

} // namespace

PieceEdits::PieceEdits(QObject *parent)
    : QObject(parent)
{
}

void PieceEdits::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor) {
        disconnect(m_editor->selection(), nullptr, this, nullptr);
        disconnect(m_editor->document(), nullptr, this, nullptr);
    }
    m_editor = editor;
    if (m_editor) {
        const auto changed = [this] { Q_EMIT stateChanged(); };
        connect(m_editor->selection(), &Selection::curveChanged, this, changed);
        connect(m_editor->selection(), &Selection::pointChanged, this, changed);
        connect(m_editor->document(), &Document::curveChanged, this, changed);
        connect(m_editor->document(), &Document::curveCountChanged, this, changed);
    }
    Q_EMIT editorChanged();
    Q_EMIT stateChanged();
}

// --- state ---

bool PieceEdits::canEditKnot() const
{
    if (!m_editor)
        return false;
    const Selection *selection = m_editor->selection();
    return shapeable(selection->curve()) && selection->point() >= 0;
}

bool PieceEdits::canDeleteKnot() const
{
    if (!canEditKnot())
        return false;
    const Curve *c = m_editor->selection()->curve();
    return c->placedCount() > c->minimumPoints();
}

bool PieceEdits::canMakeLine() const
{
    return canEditKnot() && selectedSegment() >= 0;
}

bool PieceEdits::canClose() const
{
    if (!m_editor)
        return false;
    const Curve *c = m_editor->selection()->curve();
    return isOpenShapeable(c) && c->composite().knotCount() >= 3;
}

bool PieceEdits::canJoin() const
{
    if (!m_editor || !isOpenShapeable(m_editor->selection()->curve()))
        return false;
    const Document *document = m_editor->document();
    for (int i = 0; i < document->curveCount(); ++i) {
        const Curve &c = document->curve(i);
        if (c.id() != m_editor->selection()->curve()->id() && isOpenShapeable(&c))
            return true;
    }
    return false;
}

bool PieceEdits::canSimplify() const
{
    if (!m_editor)
        return false;
    const Curve *c = m_editor->selection()->curve();
    return shapeable(c) && c->composite().knotCount() > (c->isClosed() ? 3 : 2);
}

const Curve *PieceEdits::editableComposite(int curveId, bool open)
{
    if (!m_editor)
        return nullptr;
    const Curve *c = m_editor->document()->find(static_cast<CurveId>(curveId));
    if (c && c->locked) {
        m_editor->showMessage(Message::CurveLocked, {c->name});
        return nullptr;
    }
    if (!(open ? isOpenShapeable(c) : shapeable(c))) {
        m_message.show(Message::NotComposite);
        return nullptr;
    }
    m_message.clear();
    return c;
}

// --- knots and segments ---

int PieceEdits::selectedSegment() const
{
    if (!m_editor)
        return -1;
    const Selection *selection = m_editor->selection();
    const Curve *c = selection->curve();
    const int row = selection->point();
    if (!shapeable(c) || row < 0)
        return -1;
    const geo::CompositeCurve &composite = c->composite();
    const int segments = composite.segmentCount();
    if (segments == 0)
        return -1;
    // Rows are the control vector: knot k at 3k, its handles at 3k - 1 (segment k - 1) and 3k + 1.
    if (row % 3 == 1)
        return row / 3;
    if (row % 3 == 2)
        return row / 3;
    const int knot = row / 3;
    return knot < segments ? knot : segments - 1;
}

bool PieceEdits::makeLine(int curveId, int segment)
{
    const Curve *before = editableComposite(curveId, false);
    if (!before)
        return false;
    auto line = geo::makeSegmentLine(before->composite(), segment);
    if (!line) {
        m_editor->sayError(*before, line.error());
        return false;
    }
    if (*line == before->composite())
        return true;
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before, styledLike(*line, *before),
                                           tr("Make line")));
    return true;
}

bool PieceEdits::makeSelectedLine()
{
    const int segment = selectedSegment();
    return segment >= 0 && makeLine(m_editor->selection()->curveIdValue(), segment);
}

bool PieceEdits::deleteSelectedKnot()
{
    if (!canEditKnot())
        return false;
    // The knot of the selected handle goes too: what the user sees selected is that knot's.
    const Selection *selection = m_editor->selection();
    return m_editor->commands()->removePoint(selection->curveIdValue(), selection->knot());
}

bool PieceEdits::setSelectedNodeType(int type)
{
    if (!canEditKnot())
        return false;
    const Selection *selection = m_editor->selection();
    return m_editor->commands()->setNodeType(selection->curveIdValue(), selection->knot(), type);
}

// --- whole curves ---

bool PieceEdits::closeCurve(int curveId, double mergeDistance)
{
    const Curve *before = editableComposite(curveId, true);
    if (!before)
        return false;
    const double merge = std::isfinite(mergeDistance) ? std::max(0.0, mergeDistance) : 0.0;
    auto closed = geo::closeJoined(before->composite(), {merge, cornerAngle});
    if (!closed) {
        m_editor->sayError(*before, closed.error());
        return false;
    }
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before,
                                           styledLike(std::move(*closed), *before),
                                           QCoreApplication::translate("kontur", "Close curve")));
    return true;
}

bool PieceEdits::closeSelected(double mergeDistance)
{
    return m_editor && closeCurve(m_editor->selection()->curveIdValue(), mergeDistance);
}

bool PieceEdits::joinCurves(int firstId, int secondId, double mergeDistance)
{
    if (firstId == secondId)
        return false;
    const Curve *own = editableComposite(firstId, true);
    if (!own)
        return false;
    const Curve *other = editableComposite(secondId, true);
    if (!other)
        return false;
    EndMatch match;
    consider(match, other, own->composite(), other->composite());
    const double merge = std::isfinite(mergeDistance) ? std::max(0.0, mergeDistance) : 0.0;
    auto joined = joinAt(own->composite(), other->composite(), match.atOwnStart, match.atOtherStart, merge);
    if (!joined) {
        m_editor->sayError(*own, joined.error());
        return false;
    }
    Document *document = m_editor->document();
    const QString text = tr("Join curves");
    auto *join = new QUndoCommand(text);
    new ReplaceCurveCommand(document, own->id(), *own, styledLike(std::move(*joined), *own), text, join);
    CurvePresenceCommand::remove(document, other->id(), join);
    const CurveId kept = own->id();
    m_editor->push(join);
    m_editor->selection()->select(kept);
    return true;
}

bool PieceEdits::joinSelected(double mergeDistance)
{
    if (!m_editor)
        return false;
    const Curve *own = editableComposite(m_editor->selection()->curveIdValue(), true);
    if (!own)
        return false;
    EndMatch best;
    const Document *document = m_editor->document();
    for (int i = 0; i < document->curveCount(); ++i) {
        const Curve &c = document->curve(i);
        if (c.id() != own->id() && isOpenShapeable(&c))
            consider(best, &c, own->composite(), c.composite());
    }
    if (!best.other) {
        m_message.show(Message::NothingToJoin);
        return false;
    }
    return joinCurves(static_cast<int>(own->id()), static_cast<int>(best.other->id()), mergeDistance);
}

bool PieceEdits::simplify(int curveId, double tolerance)
{
    const Curve *before = editableComposite(curveId, false);
    if (!before)
        return false;
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
        m_message.show(Message::BadTolerance);
        return false;
    }
    auto simpler = geo::simplifyComposite(before->composite(), tolerance);
    if (!simpler) {
        m_message.show(Message::NotSimpler);
        return false;
    }
    m_editor->push(new ReplaceCurveCommand(m_editor->document(), before->id(), *before,
                                           styledLike(std::move(simpler->curve), *before), tr("Simplify curve")));
    return true;
}

bool PieceEdits::simplifyText(int curveId, const QString &tolerance)
{
    double value = 0.0;
    if (parseNumber(tolerance, value) != Parsed::Number || !(value > 0.0)) {
        m_message.show(Message::BadTolerance);
        return false;
    }
    return simplify(curveId, value);
}

QString PieceEdits::suggestedToleranceText() const
{
    if (!m_editor || !m_editor->selection()->curve())
        return {};
    const geo::Box box = m_editor->selection()->curve()->bounds();
    const double size = box.sizes().maxCoeff();
    if (!(size > 0.0))
        return {};
    // One significant digit: a round number the user can read and change.
    const double step = std::pow(10.0, std::floor(std::log10(size / 1000.0)));
    return displayNumber(std::round(size / 1000.0 / step) * step, 12);
}

CurveId PieceEdits::addOrExtend(EditController *editor, Curve curve, double radius, const QString &addText)
{
    if (curve.kind() == CurveKind::Composite && !curve.isClosed() && curve.composite().knotCount() >= 2 &&
        radius > 0.0) {
        EndMatch best;
        const Document *document = editor->document();
        for (int i = 0; i < document->curveCount(); ++i) {
            const Curve &c = document->curve(i);
            if (isOpenShapeable(&c) && c.visible)
                consider(best, &c, c.composite(), curve.composite());
        }
        // `consider` measured from the existing curve's ends: "own" is the existing curve here.
        if (best.other && best.distance <= radius) {
            auto joined =
                joinAt(best.other->composite(), curve.composite(), best.atOwnStart, best.atOtherStart, radius);
            if (joined) {
                const CurveId id = best.other->id();
                editor->push(new ReplaceCurveCommand(editor->document(), id, *best.other,
                                                     styledLike(std::move(*joined), *best.other), tr("Extend curve")));
                editor->selection()->select(id);
                return id;
            }
        }
    }
    return editor->commands()->appendCurve(std::move(curve), addText);
}

} // namespace kontur
