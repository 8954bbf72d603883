// Undo commands: every change to the document is one of these, pushed on the one undo stack
// (EditController::push). As in Qt's undoframework example, a command's redo() makes the change,
// the first time too, and undo() takes it back; each stores exactly what it needs for that, so undo
// is exact. Commands name curves by id (CurveId), never by row: rows change under undo and redo.
#pragma once

#include "geometry/result.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "models/document/snapshotcommand.h"

#include <QUndoCommand>

#include <optional>

namespace kontur {

// When the seam allowances a command changes are computed, in its redo and its undo alike: at once,
// on this thread, or later, on the Document's worker (Document::beginStepEdit: a repeated fast
// edit, an arrow-key nudge or a seam width's step, issue #45).
enum class AllowancesFollow {
    AtOnce,
    Later,
};

// The base of every command: the only holder of the document's edit key.
class DocumentCommand : public QUndoCommand
{
protected:
    explicit DocumentCommand(Document *document, QUndoCommand *parent = nullptr)
        : QUndoCommand(parent)
        , m_document(document)
    {
    }
    [[nodiscard]] static Document::EditKey key() { return {}; }
    class StepEdit;
    [[nodiscard]] int indexOf(CurveId id) const { return m_document->indexOf(id); }
    Document *m_document;
};

// Adds a curve at a row (or, with `remove`, removes the curve with an id).
class CurvePresenceCommand final : public DocumentCommand
{
public:
    // With a `parent`, the command is one step of its parent (QUndoCommand's own composition).
    static CurvePresenceCommand *add(Document *document, int index, Curve curve, QUndoCommand *parent = nullptr);
    static CurvePresenceCommand *remove(Document *document, CurveId id, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;
    // The added curve's id, known after the first redo.
    [[nodiscard]] CurveId curveId() const { return m_id; }

private:
    CurvePresenceCommand(Document *document, int index, Curve curve, bool adding, QUndoCommand *parent);
    int m_index;
    Curve m_curve; // the curve while it is not in the document
    CurveId m_id = CurveId::None;
    bool m_adding;
};

// Moves a curve to another row (the curve list's order).
class MoveCurveCommand final : public DocumentCommand
{
public:
    MoveCurveCommand(Document *document, CurveId id, int to);
    void redo() override;
    void undo() override;

private:
    CurveId m_id;
    int m_from = -1;
    int m_to;
};

// A point moved by the user with its kind's rule (a drag step, a nudge, a typed coordinate). The
// first redo() makes the move and records what changed; later ones set the recorded positions. The
// steps of one drag share a drag serial and merge, so one undo takes the whole drag back. A move that
// changes nothing or that is refused (a result beyond the largest double) makes the command
// obsolete, so the stack drops it; the refusal is written to `failure` when given.
class MovePointCommand final : public DocumentCommand
{
public:
    struct Move
    {
        CurveId curve;
        int row;
        geo::Point target;
        geo::HandleMove mode;
    };
    MovePointCommand(Document *document, Move move, int dragSerial, std::optional<geo::Error> *failure = nullptr);
    void redo() override;
    void undo() override;
    [[nodiscard]] int id() const override { return 1; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    Move m_move;
    std::vector<PointChange> m_changes;
    int m_dragSerial; // 0: a single move, never merged
    std::optional<geo::Error> *m_failure;
    bool m_done = false;
};

// Any other change to one curve (settings, style, structure): the curve before and after.
class ReplaceCurveCommand final : public SnapshotCommand<Curve, DocumentCommand>
{
public:
    ReplaceCurveCommand(Document *document, CurveId id, Curve before, Curve after, const QString &text,
                        QUndoCommand *parent = nullptr, AllowancesFollow follow = AllowancesFollow::AtOnce);

private:
    void apply(const Curve &curve) override;
    CurveId m_id;
    AllowancesFollow m_follow;
};

// A change of a piece's marks (size, quantity, fold, grainline, a notch, a drill hole), or making a
// curve a piece or no piece. The steps of one drag of a mark share a serial and merge.
class PieceCommand final : public SnapshotCommand<std::optional<io::PieceMarks>, DocumentCommand>
{
public:
    PieceCommand(Document *document, CurveId id, std::optional<io::PieceMarks> before,
                 std::optional<io::PieceMarks> after, const QString &text, int dragSerial = 0,
                 AllowancesFollow follow = AllowancesFollow::AtOnce);

private:
    void apply(const std::optional<io::PieceMarks> &piece) override;
    CurveId m_id;
    AllowancesFollow m_follow;
};

// A change of the background picture. The steps of one move of the picture share a move serial
// and merge (as a point drag does), so one undo takes the whole move back.
class BackgroundCommand final : public SnapshotCommand<Background, DocumentCommand>
{
public:
    BackgroundCommand(Document *document, Background before, Background after, QUndoCommand *parent = nullptr,
                      int moveSerial = 0);

private:
    void apply(const Background &background) override;
};

} // namespace kontur
