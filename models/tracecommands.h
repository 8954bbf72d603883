// Undo commands of the tracing tools (issue #10): a calibration changes the background's placement
// and the document's units together, so that one undo takes both back.
#pragma once

#include "models/document.h"

#include <QUndoCommand>

namespace kontur {

class CalibrationCommand final : public QUndoCommand
{
public:
    CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore,
                       QString unitsAfter);
    void redo() override;
    void undo() override;

private:
    Document *m_document;
    Background m_before;
    Background m_after;
    QString m_unitsBefore;
    QString m_unitsAfter;
};

} // namespace kontur
