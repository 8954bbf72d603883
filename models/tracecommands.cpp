// Undo commands of the tracing tools; see tracecommands.h.
#include "models/tracecommands.h"

#include <QCoreApplication>

namespace kontur {

CalibrationCommand::CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore,
                                       QString unitsAfter)
    : QUndoCommand(QCoreApplication::translate("kontur::TraceController", "Calibrate background"))
    , m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_unitsBefore(std::move(unitsBefore))
    , m_unitsAfter(std::move(unitsAfter))
{
}

void CalibrationCommand::redo()
{
    m_document->setBackground(m_after);
    m_document->setUnits(m_unitsAfter);
}

void CalibrationCommand::undo()
{
    m_document->setBackground(m_before);
    m_document->setUnits(m_unitsBefore);
}

} // namespace kontur
