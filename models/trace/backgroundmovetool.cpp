// BackgroundMoveTool: see backgroundmovetool.h.
#include "models/trace/backgroundmovetool.h"

#include "models/document/commands.h"

namespace kontur {

BackgroundMoveTool::BackgroundMoveTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
}

bool BackgroundMoveTool::begin()
{
    m_moving = false;
    const Background *bg = m_context->pictureOrSay();
    if (!bg)
        return false;
    if (bg->locked) {
        m_context->say(Message::LockedMove);
        return false;
    }
    m_context->say(Message::None);
    m_moving = true;
    ++m_serial;
    return true;
}

void BackgroundMoveTool::moveBy(QPointF worldDelta)
{
    EditController *editor = m_context->editor();
    if (!m_moving || !editor || worldDelta.isNull())
        return;
    // Each step is a command whose redo() moves the picture; the stack merges the steps of one drag
    // into its first command, so the whole drag is one undo step.
    Document *doc = editor->document();
    Background after = doc->background();
    after.origin += worldDelta;
    if (after.perspective)
        after.rectOrigin += worldDelta;
    editor->push(new BackgroundCommand(doc, doc->background(), after, nullptr, m_serial));
}

void BackgroundMoveTool::end()
{
    m_moving = false;
}

} // namespace kontur
