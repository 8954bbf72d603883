// Undo commands of the tracing tools (issue #10): a calibration changes the background's placement
// and the document's units together, so that one undo takes both back; a background drag is one
// command that its steps merge into.
#pragma once

#include "models/document.h"

#include <QUndoCommand>

#include <functional>
#include <memory>
#include <vector>

namespace kontur {

class CalibrationCommand final : public QUndoCommand
{
public:
    // The world is mapped by p ↦ scale · R(radians) p; `mapped` is told of it on every redo and of
    // the inverse on every undo, so that the view can keep the picture where it was on the screen.
    using Mapped = std::function<void(double scale, double radians)>;
    CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore, QString unitsAfter,
                       double scale = 1.0, double radians = 0.0, Mapped mapped = {});
    void redo() override;
    void undo() override;

private:
    double m_scale;
    double m_radians;
    Mapped m_mapped;
    Document *m_document;
    Background m_before;
    Background m_after;
    QString m_unitsBefore;
    QString m_unitsAfter;
};

// One step of a background drag: redo() moves the picture. The steps of one drag (the same `drag`
// serial) merge into the first, which keeps its "before": the whole drag is one undo step, and a drag
// that ends where it began leaves none (obsolete).
class BackgroundMoveCommand final : public QUndoCommand
{
public:
    BackgroundMoveCommand(Document *document, Background before, Background after, int drag);
    [[nodiscard]] int id() const override;
    bool mergeWith(const QUndoCommand *other) override;
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    Background m_before;
    Background m_after;
    int m_drag;
};

// Several commands made first and pushed as one undo step: redo() runs them in order, undo()
// backwards (as a QUndoStack macro, without opening one on the shared stack).
class CommandGroup final : public QUndoCommand
{
public:
    explicit CommandGroup(const QString &text);
    void add(QUndoCommand *command); // owned from now on
    void redo() override;
    void undo() override;

private:
    std::vector<std::unique_ptr<QUndoCommand>> m_parts;
};

} // namespace kontur
