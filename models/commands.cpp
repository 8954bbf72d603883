// Undo commands on the document.
#include "models/commands.h"

#include <QCoreApplication>

#include <algorithm>

namespace kontur {

CurvePresenceCommand::CurvePresenceCommand(Document *document, int index, Curve curve, bool adding)
    : m_document(document)
    , m_index(index)
    , m_curve(std::move(curve))
    , m_adding(adding)
{
}

CurvePresenceCommand *CurvePresenceCommand::add(Document *document, int index, Curve curve)
{
    auto *command = new CurvePresenceCommand(document, index, std::move(curve), true);
    command->setText(QCoreApplication::translate("kontur", "Add %1").arg(command->m_curve.name));
    return command;
}

CurvePresenceCommand *CurvePresenceCommand::remove(Document *document, int index)
{
    auto *command = new CurvePresenceCommand(document, index, document->curve(index), false);
    command->setText(QCoreApplication::translate("kontur", "Delete %1").arg(command->m_curve.name));
    return command;
}

void CurvePresenceCommand::redo()
{
    if (m_adding)
        m_document->insertCurve(m_index, m_curve);
    else
        m_curve = m_document->takeCurve(m_index);
}

void CurvePresenceCommand::undo()
{
    if (m_adding)
        m_curve = m_document->takeCurve(m_index);
    else
        m_document->insertCurve(m_index, m_curve);
}

MoveCurveCommand::MoveCurveCommand(Document *document, int from, int to)
    : m_document(document)
    , m_from(from)
    , m_to(to)
{
    setText(QCoreApplication::translate("kontur", "Reorder curves"));
}

void MoveCurveCommand::redo()
{
    m_document->moveCurve(m_from, m_to);
}

void MoveCurveCommand::undo()
{
    m_document->moveCurve(m_to, m_from);
}

MovePointsCommand::MovePointsCommand(Document *document, int curve, std::vector<PointChange> changes, int dragSerial)
    : m_document(document)
    , m_curve(curve)
    , m_changes(std::move(changes))
    , m_dragSerial(dragSerial)
{
    setText(QCoreApplication::translate("kontur", "Move point"));
}

void MovePointsCommand::redo()
{
    // The move was made by the rule that produced the changes; only a redo after an undo sets them.
    if (m_applied) {
        m_applied = false;
        return;
    }
    m_document->setPoints(m_curve, m_changes, true);
}

void MovePointsCommand::undo()
{
    m_document->setPoints(m_curve, m_changes, false);
}

bool MovePointsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const MovePointsCommand *>(other);
    if (next->m_dragSerial != m_dragSerial || next->m_curve != m_curve)
        return false;
    // Keep the first "before" of every point and the last "after".
    for (const PointChange &change : next->m_changes) {
        auto it =
            std::find_if(m_changes.begin(), m_changes.end(), [&](const PointChange &c) { return c.row == change.row; });
        if (it == m_changes.end())
            m_changes.push_back(change);
        else
            it->after = change.after;
    }
    return true;
}

ReplaceCurveCommand::ReplaceCurveCommand(Document *document, int index, Curve before, Curve after, const QString &text)
    : m_document(document)
    , m_index(index)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setText(text);
}

void ReplaceCurveCommand::redo()
{
    m_document->replaceCurve(m_index, m_after);
}

void ReplaceCurveCommand::undo()
{
    m_document->replaceCurve(m_index, m_before);
}

BackgroundCommand::BackgroundCommand(Document *document, Background before, Background after)
    : m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setText(QCoreApplication::translate("kontur", "Change background"));
}

void BackgroundCommand::redo()
{
    m_document->setBackground(m_after);
}

void BackgroundCommand::undo()
{
    m_document->setBackground(m_before);
}

} // namespace kontur
