// The marks of a garment piece, edited by touch (see piecemarks.h).
#include "models/controllers/piecemarks.h"

#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/document/selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

namespace {

double distanceToSegment(const geo::Point &p, const io::Segment &s)
{
    const geo::Point d = s.b - s.a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (s.a + t * d)).norm();
}

void sortNotches(io::PieceMarks &marks)
{
    std::stable_sort(marks.notches.begin(), marks.notches.end(),
                     [](const io::Notch &a, const io::Notch &b) { return a.position < b.position; });
}

} // namespace

PieceMarkEdits::PieceMarkEdits(QObject *parent)
    : QObject(parent)
{
}

void PieceMarkEdits::setEditor(EditController *editor)
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
        connect(m_editor->document(), &Document::curveChanged, this, changed);
        connect(m_editor->document(), &Document::curveCountChanged, this, changed);
    }
    Q_EMIT editorChanged();
    Q_EMIT stateChanged();
}

const Curve *PieceMarkEdits::selected() const
{
    return m_editor ? m_editor->selection()->curve() : nullptr;
}

bool PieceMarkEdits::canBePiece() const
{
    const Curve *c = selected();
    return c && c->isClosed() && !c->seam && !c->locked && !c->piece;
}

bool PieceMarkEdits::isPiece() const
{
    const Curve *c = selected();
    return c && c->piece.has_value();
}

std::optional<io::PieceMarks> PieceMarkEdits::marks() const
{
    const Curve *c = selected();
    return c ? c->piece : std::nullopt;
}

QString PieceMarkEdits::size() const
{
    const auto m = marks();
    return m ? m->size : QString();
}

int PieceMarkEdits::quantity() const
{
    const auto m = marks();
    return m ? m->quantity : 0;
}

QString PieceMarkEdits::material() const
{
    const auto m = marks();
    return m ? m->material : QString();
}

bool PieceMarkEdits::hasFold() const
{
    const auto m = marks();
    return m && m->fold;
}

bool PieceMarkEdits::hasGrainline() const
{
    const auto m = marks();
    return m && m->grainline;
}

int PieceMarkEdits::notchCount() const
{
    const auto m = marks();
    return m ? static_cast<int>(m->notches.size()) : 0;
}

int PieceMarkEdits::drillHoleCount() const
{
    const auto m = marks();
    return m ? static_cast<int>(m->drillHoles.size()) : 0;
}

const Curve *PieceMarkEdits::editablePiece()
{
    const Curve *c = selected();
    if (c && c->locked) {
        m_editor->showMessage(Message::CurveLocked, {c->name});
        return nullptr;
    }
    if (!c || !c->piece) {
        m_message.show(Message::SelectPiece);
        return nullptr;
    }
    return c;
}

bool PieceMarkEdits::change(const Curve &curve, std::optional<io::PieceMarks> after, const QString &text,
                            int dragSerial)
{
    if (after == curve.piece && dragSerial == 0)
        return true;
    m_message.clear();
    m_editor->push(new PieceCommand(m_editor->document(), curve.id(), curve.piece, std::move(after), text, dragSerial));
    return true;
}

bool PieceMarkEdits::makePiece()
{
    const Curve *c = selected();
    if (c && c->locked) {
        m_editor->showMessage(Message::CurveLocked, {c->name});
        return false;
    }
    if (!c || !c->isClosed() || c->seam) {
        m_message.show(Message::PieceNotClosed);
        return false;
    }
    if (c->piece)
        return true;
    return change(*c, io::PieceMarks{}, tr("Make a pattern piece"));
}

bool PieceMarkEdits::removePiece()
{
    const Curve *c = editablePiece();
    return c && change(*c, std::nullopt, tr("No longer a pattern piece"));
}

bool PieceMarkEdits::setSize(const QString &size)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    io::PieceMarks m = *c->piece;
    m.size = size.trimmed();
    return change(*c, m, tr("Set the piece's size"));
}

bool PieceMarkEdits::setQuantity(int quantity)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    if (quantity < 1 || quantity > 1000000) {
        m_message.show(Message::BadQuantity);
        return false;
    }
    io::PieceMarks m = *c->piece;
    m.quantity = quantity;
    return change(*c, m, tr("Set how many to cut"));
}

bool PieceMarkEdits::setQuantityText(const QString &text)
{
    bool ok = false;
    const int n = text.trimmed().toInt(&ok);
    if (!ok) {
        m_message.show(Message::BadQuantity);
        return false;
    }
    return setQuantity(n);
}

bool PieceMarkEdits::setMaterial(const QString &material)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    io::PieceMarks m = *c->piece;
    m.material = material.trimmed();
    return change(*c, m, tr("Set the piece's material"));
}

bool PieceMarkEdits::setGrainline(double ax, double ay, double bx, double by, double minimum)
{
    return setLine(&io::PieceMarks::grainline, io::Segment{geo::Point(ax, ay), geo::Point(bx, by)}, minimum,
                   tr("Draw the grainline"));
}

bool PieceMarkEdits::setFold(double ax, double ay, double bx, double by, double minimum)
{
    return setLine(&io::PieceMarks::fold, io::Segment{geo::Point(ax, ay), geo::Point(bx, by)}, minimum,
                   tr("Place on fold"));
}

bool PieceMarkEdits::setLine(std::optional<io::Segment> io::PieceMarks::*line, const io::Segment &s, double minimum,
                             const QString &text)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    if (!((s.b - s.a).norm() > std::max(minimum, 0.0)) || !std::isfinite((s.b - s.a).norm())) {
        m_message.show(Message::MarkPointsTooClose);
        return false;
    }
    io::PieceMarks m = *c->piece;
    m.*line = s;
    return change(*c, m, text);
}

bool PieceMarkEdits::foldAlongSeam(double x, double y)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    const geo::PiecewiseBezier shape = c->toPiecewise();
    if (shape.isEmpty())
        return false;
    const geo::PiecewiseNearest n = shape.nearest(geo::Point(x, y));
    const geo::Bezier &b = shape.segments()[static_cast<std::size_t>(n.segment)];
    return setFold(b.controlPoints().front().x(), b.controlPoints().front().y(), b.controlPoints().back().x(),
                   b.controlPoints().back().y());
}

int PieceMarkEdits::addNotch(double x, double y, int kind)
{
    const Curve *c = editablePiece();
    if (!c)
        return -1;
    io::PieceMarks m = *c->piece;
    io::Notch notch;
    notch.position = io::lengthAtNearest(c->toPiecewise(), geo::Point(x, y));
    notch.kind = static_cast<io::NotchKind>(std::clamp(kind, 0, 2));
    m.notches.push_back(notch);
    sortNotches(m);
    const auto at = std::find(m.notches.begin(), m.notches.end(), notch);
    const int index = static_cast<int>(at - m.notches.begin());
    change(*c, m, tr("Add a notch"));
    return index;
}

bool PieceMarkEdits::moveNotch(int index, double x, double y, int dragSerial)
{
    const Curve *c = editablePiece();
    if (!c || index < 0 || index >= static_cast<int>(c->piece->notches.size()))
        return false;
    io::PieceMarks m = *c->piece;
    m.notches[static_cast<std::size_t>(index)].position = io::lengthAtNearest(c->toPiecewise(), geo::Point(x, y));
    // The order by position is kept only when the drag ends elsewhere: a notch dragged past another
    // keeps its index while the finger holds it.
    if (dragSerial == 0)
        sortNotches(m);
    return change(*c, m, tr("Move a notch"), dragSerial);
}

bool PieceMarkEdits::setNotchKind(int index, int kind)
{
    const Curve *c = editablePiece();
    if (!c || index < 0 || index >= static_cast<int>(c->piece->notches.size()) || kind < 0 || kind > 2)
        return false;
    io::PieceMarks m = *c->piece;
    m.notches[static_cast<std::size_t>(index)].kind = static_cast<io::NotchKind>(kind);
    return change(*c, m, tr("Change a notch"));
}

bool PieceMarkEdits::setNotchAngle(int index, double degrees)
{
    const Curve *c = editablePiece();
    if (!c || index < 0 || index >= static_cast<int>(c->piece->notches.size()) || !(std::abs(degrees) < 90))
        return false;
    io::PieceMarks m = *c->piece;
    m.notches[static_cast<std::size_t>(index)].angle = degrees;
    return change(*c, m, tr("Change a notch"));
}

int PieceMarkEdits::addDrillHole(double x, double y)
{
    const Curve *c = editablePiece();
    if (!c || !std::isfinite(x) || !std::isfinite(y))
        return -1;
    io::PieceMarks m = *c->piece;
    m.drillHoles.emplace_back(x, y);
    change(*c, m, tr("Add a drill hole"));
    return static_cast<int>(m.drillHoles.size()) - 1;
}

bool PieceMarkEdits::moveDrillHole(int index, double x, double y, int dragSerial)
{
    const Curve *c = editablePiece();
    if (!c || index < 0 || index >= static_cast<int>(c->piece->drillHoles.size()) || !std::isfinite(x) ||
        !std::isfinite(y))
        return false;
    io::PieceMarks m = *c->piece;
    m.drillHoles[static_cast<std::size_t>(index)] = geo::Point(x, y);
    return change(*c, m, tr("Move a drill hole"), dragSerial);
}

PieceMarkEdits::Mark PieceMarkEdits::markAt(const geo::Point &p, double radius, int &index) const
{
    index = -1;
    const Curve *c = selected();
    if (!c || !c->piece)
        return Mark::None;
    Mark best = Mark::None;
    double bestDistance = radius;
    const auto consider = [&](Mark mark, int i, double d) {
        if (d <= bestDistance) {
            best = mark;
            index = i;
            bestDistance = d;
        }
    };
    const geo::PiecewiseBezier shape = c->toPiecewise();
    for (std::size_t i = 0; i < c->piece->notches.size(); ++i)
        consider(Mark::Notch, static_cast<int>(i),
                 (io::placeAtLength(shape, c->piece->notches[i].position).point - p).norm());
    for (std::size_t i = 0; i < c->piece->drillHoles.size(); ++i)
        consider(Mark::DrillHole, static_cast<int>(i), (c->piece->drillHoles[i] - p).norm());
    // Lines count a little less than points on them, so a notch on the fold is still reachable.
    if (c->piece->grainline)
        consider(Mark::Grainline, 0, distanceToSegment(p, *c->piece->grainline) * 1.01);
    if (c->piece->fold)
        consider(Mark::Fold, 0, distanceToSegment(p, *c->piece->fold) * 1.01);
    return best;
}

int PieceMarkEdits::markTypeAt(double x, double y, double radius) const
{
    int index = -1;
    return static_cast<int>(markAt(geo::Point(x, y), radius, index));
}

int PieceMarkEdits::markIndexAt(double x, double y, double radius) const
{
    int index = -1;
    (void)markAt(geo::Point(x, y), radius, index);
    return index;
}

bool PieceMarkEdits::deleteMarkAt(double x, double y, double radius)
{
    const Curve *c = editablePiece();
    if (!c)
        return false;
    int index = -1;
    io::PieceMarks m = *c->piece;
    switch (markAt(geo::Point(x, y), radius, index)) {
    case Mark::None:
        m_message.show(Message::NoSuchMark);
        return false;
    case Mark::Grainline:
        m.grainline.reset();
        break;
    case Mark::Fold:
        m.fold.reset();
        break;
    case Mark::Notch:
        m.notches.erase(m.notches.begin() + index);
        break;
    case Mark::DrillHole:
        m.drillHoles.erase(m.drillHoles.begin() + index);
        break;
    }
    return change(*c, m, tr("Delete a mark"));
}

int PieceMarkEdits::beginDrag()
{
    return ++m_dragSerial;
}

} // namespace kontur
