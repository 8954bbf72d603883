// MeasureTool: two taps (snapped while snapping is on) and the straight distance between them.
#pragma once

#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

class MeasureTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    Q_PROPERTY(int points READ points NOTIFY resultChanged)
    Q_PROPERTY(double distance READ distance NOTIFY resultChanged)
    // In the UI language's number format with the document's unit (units.h).
    Q_PROPERTY(QString distanceText READ distanceText NOTIFY textsChanged)

public:
    explicit MeasureTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(MeasureTool)

    [[nodiscard]] int points() const { return static_cast<int>(m_marks.size()); }
    [[nodiscard]] const std::vector<geo::Point> &marks() const { return m_marks; }
    [[nodiscard]] double distance() const;
    [[nodiscard]] QString distanceText() const;
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    Q_INVOKABLE void clear();
    [[nodiscard]] bool hasLabel() const { return m_marks.size() == 2; }
    [[nodiscard]] QPointF labelAnchor() const;

Q_SIGNALS:
    void resultChanged();
    void textsChanged();
    void overlayChanged();

private:
    TraceContext *m_context;
    std::vector<geo::Point> m_marks;
};

} // namespace kontur
