// Undo commands of the tracing tools; see tracecommands.h.
#include "models/trace/tracecommands.h"

#include <QCoreApplication>

namespace kontur {

CalibrationCommand::CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore,
                                       QString unitsAfter, double scale, double radians, Mapped mapped,
                                       QUndoCommand *parent)
    : DocumentCommand(document, parent)
    , m_scale(scale)
    , m_radians(radians)
    , m_mapped(std::move(mapped))
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_unitsBefore(std::move(unitsBefore))
    , m_unitsAfter(std::move(unitsAfter))
{
    setText(QCoreApplication::translate("kontur::TraceController", "Calibrate background"));
}

void CalibrationCommand::redo()
{
    m_document->setBackground(key(), m_after);
    m_document->setUnits(key(), m_unitsAfter);
    if (m_mapped)
        m_mapped(m_scale, m_radians);
}

void CalibrationCommand::undo()
{
    m_document->setBackground(key(), m_before);
    m_document->setUnits(key(), m_unitsBefore);
    if (m_mapped)
        m_mapped(1.0 / m_scale, -m_radians);
}

} // namespace kontur
