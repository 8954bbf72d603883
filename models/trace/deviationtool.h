// DeviationTool: two curves tapped in turn, and the largest and mean distance of the first from the
// second (geo::deviation); compared again when they change, dropped when one goes.
#pragma once

#include "geometry/measure.h"
#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

class DeviationTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    Q_PROPERTY(bool hasResult READ hasResult NOTIFY resultChanged)
    Q_PROPERTY(int curves READ curves NOTIFY resultChanged)
    Q_PROPERTY(double maximum READ maximum NOTIFY resultChanged)
    Q_PROPERTY(double mean READ mean NOTIFY resultChanged)
    Q_PROPERTY(QString maximumText READ maximumText NOTIFY textsChanged)
    Q_PROPERTY(QString meanText READ meanText NOTIFY textsChanged)

public:
    explicit DeviationTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(DeviationTool)

    [[nodiscard]] bool hasResult() const { return m_has; }
    [[nodiscard]] int curves() const { return static_cast<int>(m_pick.size()); }
    [[nodiscard]] const geo::Deviation &deviation() const { return m_deviation; }
    [[nodiscard]] double maximum() const { return m_has ? m_deviation.maximum : 0.0; }
    [[nodiscard]] double mean() const { return m_has ? m_deviation.mean : 0.0; }
    [[nodiscard]] QString maximumText() const;
    [[nodiscard]] QString meanText() const;
    // Compares the two curves (by id); sets the result.
    Q_INVOKABLE bool compare(int firstId, int secondId);
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    Q_INVOKABLE void clear();
    [[nodiscard]] bool hasLabel() const { return m_has; }
    [[nodiscard]] QPointF labelAnchor() const;
    void documentChanged();

Q_SIGNALS:
    void resultChanged();
    void textsChanged();
    void overlayChanged();

private:
    TraceContext *m_context;
    std::vector<CurveId> m_pick;
    geo::Deviation m_deviation;
    bool m_has = false;
};

} // namespace kontur
