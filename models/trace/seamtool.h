// SeamTool: two knots of one curve, and the length along the curve between them (geo::lengthBetween);
// measured again when the curve changes, dropped when it goes.
#pragma once

#include "geometry/bezier.h"
#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

class SeamTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    // -1 until two knots are chosen.
    Q_PROPERTY(double length READ length NOTIFY resultChanged)
    Q_PROPERTY(int knots READ knots NOTIFY resultChanged)
    Q_PROPERTY(QString lengthText READ lengthText NOTIFY textsChanged)

public:
    // The accuracy of every length shown (absolute, document units).
    static constexpr double kLengthAccuracy = 1e-6;

    explicit SeamTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(SeamTool)

    [[nodiscard]] double length() const { return m_length; }
    [[nodiscard]] int knots() const { return static_cast<int>(m_knots.size()); }
    [[nodiscard]] QString lengthText() const;
    // The length along the curve with id `curveId` from knot `a` to knot `b` (placed points of
    // composite and spline kinds); false with a message when the kind has no knots.
    Q_INVOKABLE bool measure(int curveId, int knotA, int knotB);
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    Q_INVOKABLE void clear();
    // The seam as Bézier segments (world), for drawing it, and its knots.
    [[nodiscard]] std::vector<geo::Bezier> segments() const;
    [[nodiscard]] std::vector<geo::Point> marks() const;
    [[nodiscard]] bool hasLabel() const { return m_length >= 0.0 && m_knots.size() == 2; }
    [[nodiscard]] QPointF labelAnchor() const;
    // The document changed: measured again, or dropped.
    void documentChanged();

Q_SIGNALS:
    void resultChanged();
    void textsChanged();
    void overlayChanged();

private:
    TraceContext *m_context;
    CurveId m_curve = CurveId::None;
    std::vector<int> m_knots;
    double m_length = -1.0;
};

} // namespace kontur
