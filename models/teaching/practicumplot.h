// PracticumPlot: seed 003's cubic segments for the teaching view (issue 9 part B, docs/requirements.md 4): the
// non-parametric segment y(x) and the parametric segment between two points with end conditions
// from draggable guide vectors (KG-202), and the multi-segment parametric spline through several
// points (KG-203), drawn with 'lines per segment' either by lines or by points (KG-201). The
// practicum's intermediate numbers (k0, k1, a3, a4; the chords T and tangents K) are shown beside.
// Drags are steps of the view's own undo stack.
#pragma once

#include "models/teaching/plotsource.h"
#include "models/text/shownmessage.h"

#include <QUndoStack>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

namespace kontur {

struct PracticumInput
{
    int mode = 0;
    std::vector<QPointF> points;  // the end points (2) or the spline's points (>= 2)
    QPointF guideStart, guideEnd; // the guide vectors' tips; the vectors start at the first and last point
    int linesPerSegment = 16;
    bool byPoints = false;

    bool operator==(const PracticumInput &) const = default;
};

// Not final: QML (Qt 6.4) derives from registered types.
class PracticumPlot : public PlotSource
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(Mode mode READ mode WRITE setMode NOTIFY inputChanged)
    Q_PROPERTY(int linesPerSegment READ linesPerSegment WRITE setLinesPerSegment NOTIFY inputChanged)
    Q_PROPERTY(bool byPoints READ byPoints WRITE setByPoints NOTIFY inputChanged)
    Q_PROPERTY(QString details READ details NOTIFY plotChanged)
    // Why nothing is drawn (QML: error.text; none: error.isEmpty).
    Q_PROPERTY(kontur::Message error READ error NOTIFY errorChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoStateChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoStateChanged)

public:
    enum Mode { FunctionSegment, ParametricSegment, MultiSegment };
    Q_ENUM(Mode)

    explicit PracticumPlot(QObject *parent = nullptr);

    [[nodiscard]] Mode mode() const { return static_cast<Mode>(m_in.mode); }
    void setMode(Mode mode);
    [[nodiscard]] int linesPerSegment() const { return m_in.linesPerSegment; }
    void setLinesPerSegment(int lines);
    [[nodiscard]] bool byPoints() const { return m_in.byPoints; }
    void setByPoints(bool byPoints);
    [[nodiscard]] QString details() const { return m_details; }
    [[nodiscard]] Message error() const { return m_error.message(); }
    [[nodiscard]] bool canUndo() const { return m_undo.canUndo(); }
    [[nodiscard]] bool canRedo() const { return m_undo.canRedo(); }

    Q_INVOKABLE void undo() { m_undo.undo(); }
    Q_INVOKABLE void redo() { m_undo.redo(); }
    // The practicum's debug example (KG-203 §3.3): 4 points with step (30, 20), guide vectors along it.
    Q_INVOKABLE void loadDebugExample();
    // KG-202's segment, one tap away (the practicum prints no figures for it, so these are chosen to be
    // read off by hand from its formulas (1)–(3) and (8)–(14)): P0 = (0, 0), P1 = (100, 0), the guide
    // vectors (30, 30) at P0 and (30, −30) at P1. As a function segment k0 = 1, k1 = −1, a3 = −0,01,
    // a4 = 0, so y = x − 0,01 x² rises to 25 at x = 50; as a parametric segment (the mode kept when it
    // is one) the unit tangents make an arch only 17,68 high: the practicum's comparison (§2.4, 5 and 7).
    Q_INVOKABLE void loadSegmentExample();
    Q_INVOKABLE void refresh() { recompute(); }

    [[nodiscard]] const PracticumInput &input() const { return m_in; }
    void setInput(const PracticumInput &input); // one undo step
    // The drawn polyline (ln lines per segment) in world coordinates.
    [[nodiscard]] const QPolygonF &polyline() const { return m_polyline; }

    [[nodiscard]] PlotData plotData() const override;
    void dragDot(int index, QPointF world, bool finished) override;

Q_SIGNALS:
    void inputChanged();
    void undoStateChanged();
    void errorChanged();

private:
    friend class PracticumCommand;
    void setState(const PracticumInput &input);
    void recompute();
    [[nodiscard]] static PracticumInput defaultsFor(int mode);

    PracticumInput m_in;
    QUndoStack m_undo;
    std::optional<PracticumInput> m_dragStart;
    std::optional<QRectF> m_dragWorld;
    QPolygonF m_polyline;
    QString m_details;
    ShownMessage m_error{this, [this] { Q_EMIT errorChanged(); }};
};

} // namespace kontur
