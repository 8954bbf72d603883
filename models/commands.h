// Undo commands: every change to the document is one of these on the controller's QUndoStack.
#pragma once

#include "models/curve.h"

#include <QUndoCommand>

namespace kontur {

class Document;

class AddCurveCommand final : public QUndoCommand
{
public:
    AddCurveCommand(Document *document, int index, Curve curve);
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    int m_index;
    Curve m_curve;
};

// Moving one point. The steps of one drag share a drag serial and merge into one command,
// so a single undo takes the whole drag back.
class MovePointCommand final : public QUndoCommand
{
public:
    MovePointCommand(Document *document, int curve, int point, geo::Point from, geo::Point to, int dragSerial);
    void redo() override;
    void undo() override;
    [[nodiscard]] int id() const override { return 1; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    Document *m_document;
    int m_curve;
    int m_point;
    geo::Point m_from;
    geo::Point m_to;
    int m_dragSerial;
};

} // namespace kontur
