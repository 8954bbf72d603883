// Undo commands of the tracing tools; see tracecommands.h.
#include "models/tracecommands.h"

#include <QCoreApplication>

namespace kontur {

CalibrationCommand::CalibrationCommand(Document *document, Background before, Background after, QString unitsBefore,
                                       QString unitsAfter, double scale, double radians, Mapped mapped)
    : QUndoCommand(QCoreApplication::translate("kontur::TraceController", "Calibrate background"))
    , m_scale(scale)
    , m_radians(radians)
    , m_mapped(std::move(mapped))
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
    if (m_mapped)
        m_mapped(m_scale, m_radians);
}

void CalibrationCommand::undo()
{
    m_document->setBackground(m_before);
    m_document->setUnits(m_unitsBefore);
    if (m_mapped)
        m_mapped(1.0 / m_scale, -m_radians);
}

BackgroundMoveCommand::BackgroundMoveCommand(Document *document, Background before, Background after, int drag)
    : QUndoCommand(QCoreApplication::translate("kontur", "Change background"))
    , m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_drag(drag)
{
}

int BackgroundMoveCommand::id() const
{
    return 0x4b42; // "KB": merges only with its own kind (MovePointsCommand is 1)
}

bool BackgroundMoveCommand::mergeWith(const QUndoCommand *other)
{
    // The same id() is this class (QUndoStack merges only equal ids).
    const auto *next = static_cast<const BackgroundMoveCommand *>(other);
    if (next->m_drag != m_drag)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

void BackgroundMoveCommand::redo()
{
    m_document->setBackground(m_after);
}

void BackgroundMoveCommand::undo()
{
    m_document->setBackground(m_before);
}

CommandGroup::CommandGroup(const QString &text)
    : QUndoCommand(text)
{
}

void CommandGroup::add(QUndoCommand *command)
{
    m_parts.emplace_back(command);
}

void CommandGroup::redo()
{
    for (const auto &part : m_parts)
        part->redo();
}

void CommandGroup::undo()
{
    for (auto it = m_parts.rbegin(); it != m_parts.rend(); ++it)
        (*it)->undo();
}

} // namespace kontur
