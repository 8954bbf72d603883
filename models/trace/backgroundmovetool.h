// BackgroundMoveTool: a drag shifts the background picture in the world; the steps of one drag merge
// into one undo step. Refused, with a message, without a picture or while the background is locked.
#pragma once

#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class BackgroundMoveTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")

public:
    explicit BackgroundMoveTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(BackgroundMoveTool)

    Q_INVOKABLE bool begin();
    Q_INVOKABLE void moveBy(QPointF worldDelta);
    Q_INVOKABLE void end();
    [[nodiscard]] bool moving() const { return m_moving; }

private:
    TraceContext *m_context;
    bool m_moving = false;
    int m_serial = 0; // which drag: its steps merge into one undo command
};

} // namespace kontur
