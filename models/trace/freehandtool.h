// FreehandTool: a one-finger, stylus or mouse stroke becomes a composite curve fitted within a
// tolerance (geo::fitStroke), one undo step per stroke. The stroke is the only input of the fit
// (curveFromStroke), so that a stroke that follows the photo's edges can take its place later.
#pragma once

#include "models/document/curve.h"
#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

namespace kontur {

class FreehandTool final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("A tracing tool belongs to a TraceController.")
    Q_PROPERTY(double tolerance READ tolerance WRITE setTolerance NOTIFY toleranceChanged)
    // The world length of one screen pixel at the view's zoom (0: not known), kept by the canvas.
    Q_PROPERTY(double pixelSize READ pixelSize WRITE setPixelSize NOTIFY effectiveToleranceChanged)
    // The tolerance a stroke drawn now is fitted with: the user's, or the input's own precision at
    // this zoom (inputPrecision screen pixels) where that is coarser.
    Q_PROPERTY(double effectiveTolerance READ effectiveTolerance NOTIFY effectiveToleranceChanged)
    Q_PROPERTY(bool drawing READ isDrawing NOTIFY strokeChanged)
    Q_PROPERTY(int lastSegmentCount READ lastSegmentCount NOTIFY lastSegmentCountChanged)
    // The stroke only says where to look: the curve follows the picture's edge near it
    // (vision::snapStrokeToEdges); off by default.
    Q_PROPERTY(bool snapToEdges READ snapToEdges WRITE setSnapToEdges NOTIFY snapToEdgesChanged)

public:
    explicit FreehandTool(TraceContext *context, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(FreehandTool)

    [[nodiscard]] double tolerance() const { return m_tolerance; }
    void setTolerance(double tolerance);
    [[nodiscard]] double pixelSize() const { return m_pixelSize; }
    void setPixelSize(double size);
    // A pointer moves in steps of about a screen pixel: a tolerance below ~1.5 of them makes the fit
    // follow those steps (a smooth stroke along three cubics became 35 segments at 256 %).
    static constexpr double inputPrecision = 1.5;
    [[nodiscard]] double effectiveTolerance() const;
    // A sensible fitting tolerance in `units` (about half a millimetre; one pixel).
    [[nodiscard]] static double defaultTolerance(const QString &units);
    // The tolerance as the user types it, in the UI language's number format; false (and a message)
    // when it is not a positive number.
    Q_INVOKABLE bool setToleranceText(const QString &text);

    [[nodiscard]] bool isDrawing() const { return m_drawing; }
    [[nodiscard]] const std::vector<geo::Point> &stroke() const { return m_stroke; }
    Q_INVOKABLE void beginStroke(QPointF world, double snapRadius);
    Q_INVOKABLE void extendStroke(QPointF world);
    // Fits the stroke and adds the composite curve (one undo step), or appends it to an open curve
    // whose end is within snapRadius of one of its ends (PieceEdits::addOrExtend); false for a stroke
    // too short.
    Q_INVOKABLE bool endStroke(double snapRadius);
    Q_INVOKABLE void cancelStroke();
    // The fit itself, for tests and the command line: a composite curve within `tolerance`.
    [[nodiscard]] static geo::Result<Curve> curveFromStroke(const std::vector<geo::Point> &stroke, double tolerance);
    [[nodiscard]] int lastSegmentCount() const { return m_lastSegments; }
    [[nodiscard]] bool snapToEdges() const { return m_snapToEdges; }
    void setSnapToEdges(bool on);
    // How far from the stroke the edge is looked for, in mm (or, without a unit of length, in
    // screen pixels' worth of the world at the zoom the stroke was drawn at).
    static constexpr double edgeSearchMm = 4.0;

Q_SIGNALS:
    void toleranceChanged();
    void effectiveToleranceChanged();
    void strokeChanged();
    void lastSegmentCountChanged();
    void snapToEdgesChanged();
    // The stroke drawn over the canvas changed.
    void overlayChanged();

private:
    TraceContext *m_context;
    double m_tolerance = 1.0;
    double m_pixelSize = 0.0;
    double m_strokeTolerance = 1.0; // effectiveTolerance() when the stroke began
    bool m_drawing = false;
    std::vector<geo::Point> m_stroke;
    int m_lastSegments = 0;
    bool m_snapToEdges = false;

    // The stroke moved onto the picture's edge near it; nothing when there is no such edge.
    [[nodiscard]] std::optional<Curve> snappedCurve(const std::vector<geo::Point> &stroke);
};

} // namespace kontur
