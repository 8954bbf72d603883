// Undo commands: every change to the document is one of these on the controller's QUndoStack.
// Each stores exactly what it needs to restore the state before it, so undo is exact.
#pragma once

#include "models/curve.h"
#include "models/document.h"

#include <QUndoCommand>

namespace kontur {

// Adds a curve (or, with `remove`, removes the curve at `index`).
class CurvePresenceCommand final : public QUndoCommand
{
public:
    static CurvePresenceCommand *add(Document *document, int index, Curve curve);
    static CurvePresenceCommand *remove(Document *document, int index);
    void redo() override;
    void undo() override;

private:
    CurvePresenceCommand(Document *document, int index, Curve curve, bool adding);
    Document *m_document;
    int m_index;
    Curve m_curve; // the curve while it is not in the document
    bool m_adding;
};

class MoveCurveCommand final : public QUndoCommand
{
public:
    MoveCurveCommand(Document *document, int from, int to);
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    int m_from;
    int m_to;
};

// Moving points: the changes a move made (already applied when the command is pushed). The
// steps of one drag share a drag serial and merge, so one undo takes the whole drag back.
class MovePointsCommand final : public QUndoCommand
{
public:
    MovePointsCommand(Document *document, int curve, std::vector<PointChange> changes, int dragSerial);
    void redo() override;
    void undo() override;
    [[nodiscard]] int id() const override { return 1; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    Document *m_document;
    int m_curve;
    std::vector<PointChange> m_changes;
    int m_dragSerial;
    bool m_applied = true;
};

// Any other change to one curve (settings, style, structure): the curve before and after.
class ReplaceCurveCommand final : public QUndoCommand
{
public:
    ReplaceCurveCommand(Document *document, int index, Curve before, Curve after, const QString &text);
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    int m_index;
    Curve m_before;
    Curve m_after;
};

class BackgroundCommand final : public QUndoCommand
{
public:
    BackgroundCommand(Document *document, Background before, Background after);
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    Background m_before;
    Background m_after;
};

} // namespace kontur
