// Undo commands of the tracing tools (issue #10): a calibration changes the background's placement
// and the document's units together, so that one undo takes both back.
#pragma once

#include "models/document/commands.h"

#include <QUndoCommand>

#include <functional>

namespace kontur {

class CalibrationCommand final : public DocumentCommand
{
public:
    // The world is mapped by p ↦ scale · R(radians) p; `mapped` is told of it on every redo and of
    // the inverse on every undo, so that the view can keep the picture where it was on the screen.
    using Mapped = std::function<void(double scale, double radians)>;
    CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore, QString unitsAfter,
                       double scale = 1.0, double radians = 0.0, Mapped mapped = {}, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    double m_scale;
    double m_radians;
    Mapped m_mapped;
    Background m_before;
    Background m_after;
    QString m_unitsBefore;
    QString m_unitsAfter;
};

} // namespace kontur
