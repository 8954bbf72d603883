// Undo commands on the document.
#include "models/commands.h"

#include "models/document.h"

namespace kontur {

AddCurveCommand::AddCurveCommand(Document *document, int index, Curve curve)
    : m_document(document)
    , m_index(index)
    , m_curve(std::move(curve))
{
    setText(QCoreApplication::translate("kontur", "Add %1").arg(m_curve.name));
}

void AddCurveCommand::redo()
{
    m_document->insertCurve(m_index, m_curve);
}

void AddCurveCommand::undo()
{
    m_curve = m_document->takeCurve(m_index);
}

MovePointCommand::MovePointCommand(Document *document, int curve, int point, geo::Point from, geo::Point to,
                                   int dragSerial)
    : m_document(document)
    , m_curve(curve)
    , m_point(point)
    , m_from(std::move(from))
    , m_to(std::move(to))
    , m_dragSerial(dragSerial)
{
    setText(QCoreApplication::translate("kontur", "Move point"));
}

void MovePointCommand::redo()
{
    m_document->setPoint(m_curve, m_point, m_to);
}

void MovePointCommand::undo()
{
    m_document->setPoint(m_curve, m_point, m_from);
}

bool MovePointCommand::mergeWith(const QUndoCommand *other)
{
    const auto *move = static_cast<const MovePointCommand *>(other);
    if (move->m_dragSerial != m_dragSerial || move->m_curve != m_curve || move->m_point != m_point)
        return false;
    m_to = move->m_to;
    return true;
}

} // namespace kontur
