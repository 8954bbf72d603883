// CalibrationTool: the background calibrated to real units by two points a known distance apart.
// Two taps mark them on the picture; calibrate() scales (and may turn) the world so that they lie that
// distance apart, with the curves following the picture; one undo step.
#pragma once

#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

class CalibrationTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    Q_PROPERTY(int points READ points NOTIFY marksChanged)
    // The marked distance in picture pixels (0 until two points are marked), and as the UI writes it.
    Q_PROPERTY(double imageDistance READ imageDistance NOTIFY marksChanged)
    Q_PROPERTY(QString imageDistanceText READ imageDistanceText NOTIFY textsChanged)

public:
    enum Align {
        NoAlign,
        Horizontal, // the marked line becomes horizontal (the picture rotates)
        Vertical,
    };
    Q_ENUM(Align)

    explicit CalibrationTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(CalibrationTool)

    [[nodiscard]] int points() const { return static_cast<int>(m_marks.size()); }
    [[nodiscard]] const std::vector<geo::Point> &marks() const { return m_marks; } // world
    [[nodiscard]] double imageDistance() const;
    [[nodiscard]] QString imageDistanceText() const;
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    Q_INVOKABLE void clear();
    // Applies the calibration: `distanceText` in the UI language's format, `unit` one of mm, cm, in,
    // `align` an Align value. The document then works in `unit`. False with a message on bad input.
    Q_INVOKABLE bool calibrate(const QString &distanceText, const QString &unit, int align);
    // The same with the picture points given (image pixels), for tests and files.
    bool calibrateImagePoints(QPointF imageA, QPointF imageB, double distance, const QString &unit, Align align);
    [[nodiscard]] bool hasLabel() const { return m_marks.size() == 2; }
    [[nodiscard]] QPointF labelAnchor() const;

Q_SIGNALS:
    void marksChanged();
    void textsChanged();
    void overlayChanged();

private:
    TraceContext *m_context;
    std::vector<geo::Point> m_marks;
};

} // namespace kontur
