// OutlineTool: "Trace outline". A tap inside (or beside) a pattern piece on the background picture
// finds the piece's outline in the picture (vision::traceOutlineAt on the picture warped into the
// world's plane, about 8 px/mm) and adds it as one closed composite curve, one undo step: corners as
// Corner knots, straight seams as exact lines. It works through Background::imageToWorld(), so a
// perspective calibration, a two-point calibration or none at all place the outline alike.
#pragma once

#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class OutlineTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    // The knots of the last outline traced (0: none yet).
    Q_PROPERTY(int lastKnotCount READ lastKnotCount NOTIFY traced)

public:
    explicit OutlineTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(OutlineTool)

    // The rectified picture's scale (px per mm in the world) and its largest side.
    static constexpr double pxPerMm = 8.0;
    static constexpr int maxSidePx = 4000;

    // Traces the piece at `world` and adds its outline, saying so on the message line (traced()
    // follows: the tool's controller then leaves it, as a drawing tool leaves when its curve is
    // done); false (with a note) when there is no picture or no piece there.
    Q_INVOKABLE bool traceAt(QPointF world);
    [[nodiscard]] int lastKnotCount() const { return m_lastKnots; }

Q_SIGNALS:
    void traced();

private:
    TraceContext *m_context;
    int m_lastKnots = 0;
};

} // namespace kontur
