// TraceController: tracing a garment pattern (issue #10). It owns one small object per tool of the
// "Trace" group (models/trace/): FreehandTool (strokes fitted with a composite curve),
// CalibrationTool (two points a known distance apart), PerspectiveTool (the four corners of a known
// rectangle), OutlineTool (a piece's outline found in the picture), MeasureTool, SeamTool, DeviationTool and
// BackgroundMoveTool, which share one TraceContext (the editor, the message channel, snapping). It says which tool is
// in use, sends taps to it, and gives QML the tool's hint, message and label. QML reaches a tool's own state and
// commands as a property (trace.freehand.tolerance, trace.perspective.calibratePerspective(…)): one
// object in QML for the group, and no forwarding of each tool's API through this one.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/trace/backgroundmovetool.h"
#include "models/trace/calibrationtool.h"
#include "models/trace/deviationtool.h"
#include "models/trace/freehandtool.h"
#include "models/trace/measuretool.h"
#include "models/trace/outlinetool.h"
#include "models/trace/perspectivetool.h"
#include "models/trace/seamtool.h"
#include "models/trace/tracecontext.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class TraceController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(Tool tool READ tool WRITE setTool NOTIFY toolChanged)
    Q_PROPERTY(kontur::FreehandTool *freehand READ freehand CONSTANT)
    Q_PROPERTY(kontur::CalibrationTool *calibration READ calibration CONSTANT)
    Q_PROPERTY(kontur::PerspectiveTool *perspective READ perspective CONSTANT)
    Q_PROPERTY(kontur::MeasureTool *measure READ measure CONSTANT)
    Q_PROPERTY(kontur::SeamTool *seam READ seam CONSTANT)
    Q_PROPERTY(kontur::DeviationTool *deviation READ deviation CONSTANT)
    Q_PROPERTY(kontur::BackgroundMoveTool *backgroundMove READ backgroundMove CONSTANT)
    Q_PROPERTY(kontur::OutlineTool *outline READ outline CONSTANT)
    Q_PROPERTY(bool snapping READ snapping WRITE setSnapping NOTIFY snappingChanged)
    Q_PROPERTY(double gridStep READ gridStep WRITE setGridStep NOTIFY gridStepChanged)
    Q_PROPERTY(QString units READ units NOTIFY unitsChanged)
    Q_PROPERTY(bool backgroundLocked READ backgroundLocked WRITE setBackgroundLocked NOTIFY backgroundChanged)
    Q_PROPERTY(bool backgroundCalibrated READ backgroundCalibrated NOTIFY backgroundChanged)
    // The last refusal or problem, in the current language (empty: none).
    // The tools' last refusal or problem; QML shows `message.text` (ShownMessage in TraceContext).
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)
    // What the tool in use does and what to do next with it, in the current language.
    Q_PROPERTY(QString hint READ hint NOTIFY hintChanged)
    // Where the current tool's result is written on the canvas (world), and whether there is one.
    Q_PROPERTY(QPointF labelAnchor READ labelAnchor NOTIFY labelChanged)
    Q_PROPERTY(bool hasLabel READ hasLabel NOTIFY labelChanged)

public:
    enum class Tool {
        None,           // the canvas edits as usual
        Freehand,       // a one-finger / stylus / mouse drag draws a stroke that becomes a composite curve
        Calibrate,      // two taps on the picture, then the real distance between them
        Measure,        // two taps: the straight distance
        Seam,           // two knots of one curve: the length along it between them
        Deviation,      // two curves: the largest and mean distance between them
        MoveBackground, // a drag moves the background picture; one undo step per drag
        Perspective,    // four taps on the corners of a known rectangle; a drag refines a corner
        Outline,        // a tap inside a pattern piece: its outline found in the picture becomes a curve
    };
    Q_ENUM(Tool)

    explicit TraceController(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(TraceController)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] Tool tool() const { return m_tool; }
    // One tool at a time: choosing one drops the marks of the others, and ends the placing of a new
    // curve; placing a new curve leaves the tool.
    void setTool(Tool tool);

    [[nodiscard]] TraceContext *context() const { return m_context; }
    [[nodiscard]] FreehandTool *freehand() const { return m_freehand; }
    [[nodiscard]] CalibrationTool *calibration() const { return m_calibration; }
    [[nodiscard]] PerspectiveTool *perspective() const { return m_perspective; }
    [[nodiscard]] MeasureTool *measure() const { return m_measure; }
    [[nodiscard]] SeamTool *seam() const { return m_seam; }
    [[nodiscard]] DeviationTool *deviation() const { return m_deviation; }
    [[nodiscard]] BackgroundMoveTool *backgroundMove() const { return m_backgroundMove; }
    [[nodiscard]] OutlineTool *outline() const { return m_outline; }

    [[nodiscard]] bool snapping() const { return m_context->snapping(); }
    void setSnapping(bool on) { m_context->setSnapping(on); }
    [[nodiscard]] double gridStep() const { return m_context->gridStep(); }
    void setGridStep(double step) { m_context->setGridStep(step); }
    // The knot, calibration mark or grid crossing within `radius` of `world` while snapping is on.
    [[nodiscard]] Q_INVOKABLE QPointF snap(QPointF world, double radius) const
    {
        return m_context->snap(world, radius);
    }
    [[nodiscard]] QString units() const { return m_context->units(); }
    [[nodiscard]] bool backgroundLocked() const { return m_context->backgroundLocked(); }
    void setBackgroundLocked(bool locked) { m_context->setBackgroundLocked(locked); }
    [[nodiscard]] bool backgroundCalibrated() const;

    // A tap of the tool in use, in world coordinates.
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    // Drops the points and results of every tool.
    Q_INVOKABLE void clear();

    [[nodiscard]] Message message() const { return m_context->message(); }
    [[nodiscard]] QString hint() const;
    [[nodiscard]] QPointF labelAnchor() const;
    [[nodiscard]] bool hasLabel() const;

Q_SIGNALS:
    void editorChanged();
    void toolChanged();
    void snappingChanged();
    void gridStepChanged();
    void unitsChanged();
    void backgroundChanged();
    void messageChanged();
    void hintChanged();
    void labelChanged();
    // Anything drawn over the canvas changed.
    void overlayChanged();
    // A calibration mapped the world by p ↦ scale · R(radians) p: the view may follow, so that the
    // picture stays where it was on the screen.
    void worldMapped(double scale, double radians);

private:
    // The translated texts of every tool, announced again (language switch, units).
    void announceTexts();

    QPointer<EditController> m_editor;
    Tool m_tool = Tool::None;
    TraceContext *m_context;
    FreehandTool *m_freehand;
    CalibrationTool *m_calibration;
    PerspectiveTool *m_perspective;
    MeasureTool *m_measure;
    SeamTool *m_seam;
    DeviationTool *m_deviation;
    BackgroundMoveTool *m_backgroundMove;
    OutlineTool *m_outline;
    QTimer m_languageSwitch; // announces the translated texts after a language switch
    QString m_lastUnits;
};

} // namespace kontur
