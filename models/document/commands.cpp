// Undo commands on the document.
#include "models/document/commands.h"

#include <QCoreApplication>

#include <algorithm>

namespace kontur {

// A command's change inside a step edit when its allowances follow later (Document::beginStepEdit).
class DocumentCommand::StepEdit final
{
public:
    StepEdit(Document *document, AllowancesFollow follow)
        : m_document(follow == AllowancesFollow::Later ? document : nullptr)
    {
        if (m_document)
            m_document->beginStepEdit(key());
    }
    ~StepEdit()
    {
        if (m_document)
            m_document->endStepEdit(key());
    }
    Q_DISABLE_COPY_MOVE(StepEdit)

private:
    Document *m_document;
};

CurvePresenceCommand::CurvePresenceCommand(Document *document, int index, Curve curve, bool adding,
                                           QUndoCommand *parent)
    : DocumentCommand(document, parent)
    , m_index(index)
    , m_curve(std::move(curve))
    , m_id(m_curve.id())
    , m_adding(adding)
{
}

CurvePresenceCommand *CurvePresenceCommand::add(Document *document, int index, Curve curve, QUndoCommand *parent)
{
    auto *command = new CurvePresenceCommand(document, index, std::move(curve), true, parent);
    //: Undo text: %1 is the name of the added curve.
    command->setText(QCoreApplication::translate("kontur", "Add %1").arg(command->m_curve.name));
    return command;
}

CurvePresenceCommand *CurvePresenceCommand::remove(Document *document, CurveId id, QUndoCommand *parent)
{
    const int index = document->indexOf(id);
    Q_ASSERT(index >= 0);
    auto *command = new CurvePresenceCommand(document, index, document->curve(index), false, parent);
    //: Undo text: %1 is the name of the deleted curve.
    command->setText(QCoreApplication::translate("kontur", "Delete %1").arg(command->m_curve.name));
    return command;
}

void CurvePresenceCommand::redo()
{
    if (m_adding) {
        // The first redo gives the curve its id; later ones bring back the same curve with it.
        m_id = m_document->insertCurve(key(), m_index, m_curve);
    } else {
        m_index = indexOf(m_id);
        m_curve = m_document->takeCurve(key(), m_index);
    }
}

void CurvePresenceCommand::undo()
{
    if (m_adding) {
        m_index = indexOf(m_id);
        m_curve = m_document->takeCurve(key(), m_index); // with its id, for the next redo
    } else {
        m_document->insertCurve(key(), m_index, m_curve);
    }
}

MoveCurveCommand::MoveCurveCommand(Document *document, CurveId id, int to)
    : DocumentCommand(document)
    , m_id(id)
    , m_to(to)
{
    setText(QCoreApplication::translate("kontur", "Reorder curves"));
}

void MoveCurveCommand::redo()
{
    m_from = indexOf(m_id);
    m_document->moveCurve(key(), m_from, m_to);
}

void MoveCurveCommand::undo()
{
    m_document->moveCurve(key(), indexOf(m_id), m_from);
}

MovePointCommand::MovePointCommand(Document *document, Move move, int dragSerial, std::optional<geo::Error> *failure)
    : DocumentCommand(document)
    , m_move(move)
    , m_dragSerial(dragSerial)
    , m_failure(failure)
{
    setText(QCoreApplication::translate("kontur", "Move point"));
}

void MovePointCommand::redo()
{
    const int index = indexOf(m_move.curve);
    if (m_done) {
        m_document->setPoints(key(), index, m_changes, true);
        return;
    }
    // The first redo makes the move by the kind's rule; what it changed is what undo restores.
    m_done = true;
    auto changes = m_document->movePoint(key(), index, m_move.row, m_move.target, m_move.mode);
    if (!changes.ok() && m_failure)
        *m_failure = changes.error();
    if (!changes.ok() || changes->empty()) {
        setObsolete(true); // nothing changed: the stack drops the command
        return;
    }
    m_changes = std::move(changes.value());
}

void MovePointCommand::undo()
{
    m_document->setPoints(key(), indexOf(m_move.curve), m_changes, false);
}

bool MovePointCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const MovePointCommand *>(other);
    if (m_dragSerial == 0 || next->m_dragSerial != m_dragSerial || next->m_move.curve != m_move.curve)
        return false;
    // Keep the first "before" of every point and the last "after".
    for (const PointChange &change : next->m_changes) {
        auto it =
            std::find_if(m_changes.begin(), m_changes.end(), [&](const PointChange &c) { return c.row == change.row; });
        if (it == m_changes.end())
            m_changes.push_back(change);
        else
            it->after = change.after;
    }
    return true;
}

// Merge ids: 1 is the point drag's (MovePointCommand).
constexpr int kBackgroundMoveId = 2;
constexpr int kPieceDragId = 3;

ReplaceCurveCommand::ReplaceCurveCommand(Document *document, CurveId id, Curve before, Curve after, const QString &text,
                                         QUndoCommand *parent, AllowancesFollow follow)
    : SnapshotCommand(std::move(before), std::move(after), -1, 0, document, parent)
    , m_id(id)
    , m_follow(follow)
{
    setText(text);
}

void ReplaceCurveCommand::apply(const Curve &curve)
{
    StepEdit step(m_document, m_follow);
    m_document->replaceCurve(key(), indexOf(m_id), curve);
}

PieceCommand::PieceCommand(Document *document, CurveId id, std::optional<io::PieceMarks> before,
                           std::optional<io::PieceMarks> after, const QString &text, int dragSerial,
                           AllowancesFollow follow)
    : SnapshotCommand(std::move(before), std::move(after), kPieceDragId, dragSerial, document)
    , m_id(id)
    , m_follow(follow)
{
    setText(text);
}

void PieceCommand::apply(const std::optional<io::PieceMarks> &piece)
{
    StepEdit step(m_document, m_follow);
    m_document->setPiece(key(), indexOf(m_id), piece);
}

BackgroundCommand::BackgroundCommand(Document *document, Background before, Background after, QUndoCommand *parent,
                                     int moveSerial)
    : SnapshotCommand(std::move(before), std::move(after), kBackgroundMoveId, moveSerial, document, parent)
{
    setText(QCoreApplication::translate("kontur", "Change background"));
}

void BackgroundCommand::apply(const Background &background)
{
    m_document->setBackground(key(), background);
}

} // namespace kontur
