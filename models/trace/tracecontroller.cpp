// TraceController: see tracecontroller.h.
#include "models/trace/tracecontroller.h"

#include "models/text/languagewatch.h"

namespace kontur {

TraceController::TraceController(QObject *parent)
    : QObject(parent)
    , m_context(new TraceContext(this))
    , m_freehand(new FreehandTool(m_context, this))
    , m_calibration(new CalibrationTool(m_context, this))
    , m_perspective(new PerspectiveTool(m_context, this))
    , m_measure(new MeasureTool(m_context, this))
    , m_seam(new SeamTool(m_context, this))
    , m_deviation(new DeviationTool(m_context, this))
    , m_backgroundMove(new BackgroundMoveTool(m_context, this))
    , m_outline(new OutlineTool(m_context, this))
{
    // A traced piece is a finished step: the tool leaves (the message line says what was traced), so
    // that a stray tap while printing or exporting traces nothing.
    connect(m_outline, &OutlineTool::traced, this, [this] { setTool(Tool::None); });
    connect(m_context, &TraceContext::messageChanged, this, &TraceController::messageChanged);
    connect(m_context, &TraceContext::snappingChanged, this, &TraceController::snappingChanged);
    connect(m_context, &TraceContext::gridStepChanged, this, &TraceController::gridStepChanged);
    connect(m_context, &TraceContext::worldMapped, this, &TraceController::worldMapped);
    // What the canvas draws, and the label written next to a result.
    connect(m_freehand, &FreehandTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(m_calibration, &CalibrationTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(m_perspective, &PerspectiveTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(m_measure, &MeasureTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(m_seam, &SeamTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(m_deviation, &DeviationTool::overlayChanged, this, &TraceController::overlayChanged);
    connect(this, &TraceController::overlayChanged, this, &TraceController::labelChanged);
    connect(this, &TraceController::toolChanged, this, &TraceController::labelChanged);
    // The hint follows the tool and its marks.
    connect(this, &TraceController::toolChanged, this, &TraceController::hintChanged);
    connect(m_calibration, &CalibrationTool::marksChanged, this, &TraceController::hintChanged);
    connect(m_perspective, &PerspectiveTool::marksChanged, this, &TraceController::hintChanged);
    connect(this, &TraceController::backgroundChanged, this, &TraceController::hintChanged);
    // A language switch sends LanguageChange several times (installTranslator, removeTranslator),
    // before Language::setCurrent sets the UI locale that numbers use: the translated texts are
    // announced once, when the switch is done (a zero timer, restarted by each event).
    m_languageSwitch.setSingleShot(true);
    connect(&m_languageSwitch, &QTimer::timeout, this, [this] {
        Q_EMIT hintChanged();
        announceTexts();
    });
    new LanguageWatch(this, [this] { m_languageSwitch.start(0); });
}

void TraceController::announceTexts()
{
    Q_EMIT m_calibration->textsChanged();
    Q_EMIT m_measure->textsChanged();
    Q_EMIT m_seam->textsChanged();
    Q_EMIT m_deviation->textsChanged();
}

void TraceController::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor) {
        m_editor->document()->disconnect(this);
        m_editor->disconnect(this);
    }
    m_editor = editor;
    m_context->setEditor(editor);
    if (m_editor) {
        // One tool at a time: placing a new curve leaves the tracing tool (its taps are the curve's).
        connect(m_editor, &EditController::modeChanged, this, [this] {
            if (m_editor->mode() == EditController::Mode::Place)
                setTool(Tool::None);
        });
        Document *doc = m_editor->document();
        connect(doc, &Document::unitsChanged, this, [this] {
            // The calibration's error is in mm: known once the unit is (a calibration sets both).
            Q_EMIT m_perspective->calibratedChanged();
            const QString u = units();
            if (u != m_lastUnits) {
                m_lastUnits = u;
                m_freehand->setTolerance(FreehandTool::defaultTolerance(u));
                Q_EMIT unitsChanged();
                announceTexts();
            }
        });
        connect(doc, &Document::backgroundChanged, this, [this] {
            Q_EMIT backgroundChanged();
            Q_EMIT m_perspective->calibratedChanged();
            Q_EMIT m_calibration->textsChanged();
            Q_EMIT overlayChanged();
        });
        // Results refer to curves by id and shape: any structural change makes them stale.
        const auto changed = [this] {
            m_seam->documentChanged();
            m_deviation->documentChanged();
        };
        connect(doc, &Document::curveInserted, this, changed);
        connect(doc, &Document::curveRemoved, this, changed);
        connect(doc, &Document::curveMoved, this, changed);
        connect(doc, &Document::curveChanged, this, changed);
        connect(doc, &Document::rowsChanged, this, changed);
        m_lastUnits = units();
        m_freehand->setTolerance(FreehandTool::defaultTolerance(m_lastUnits));
    }
    Q_EMIT editorChanged();
    Q_EMIT unitsChanged();
    Q_EMIT backgroundChanged();
}

void TraceController::setTool(Tool tool)
{
    if (m_tool == tool)
        return;
    m_freehand->cancelStroke();
    m_tool = tool;
    // ... and a tracing tool ends the placing of a new curve.
    if (tool != Tool::None && m_editor && m_editor->mode() == EditController::Mode::Place)
        m_editor->setMode(EditController::Mode::Select);
    m_calibration->clear();
    m_measure->clear();
    m_perspective->clear();
    m_context->say(Message::None);
    Q_EMIT toolChanged();
    Q_EMIT overlayChanged();
}

bool TraceController::backgroundCalibrated() const
{
    const Document *doc = m_context->document();
    return doc && doc->background().calibrated;
}

void TraceController::tap(QPointF world, double hitRadius)
{
    if (!m_editor)
        return;
    m_context->say(Message::None);
    switch (m_tool) {
    case Tool::None:
    case Tool::Freehand:
    case Tool::MoveBackground:
        return;
    case Tool::Perspective:
        m_perspective->tap(world);
        break;
    case Tool::Outline:
        m_outline->traceAt(world);
        break;
    case Tool::Calibrate:
        m_calibration->tap(world, hitRadius);
        break;
    case Tool::Measure:
        m_measure->tap(world, hitRadius);
        break;
    case Tool::Seam:
        m_seam->tap(world, hitRadius);
        break;
    case Tool::Deviation:
        m_deviation->tap(world, hitRadius);
        break;
    }
    Q_EMIT overlayChanged();
}

void TraceController::clear()
{
    m_calibration->clear();
    m_perspective->clear();
    m_measure->clear();
    m_seam->clear();
    m_deviation->clear();
}

bool TraceController::hasLabel() const
{
    switch (m_tool) {
    case Tool::Measure:
        return m_measure->hasLabel();
    case Tool::Seam:
        return m_seam->hasLabel();
    case Tool::Deviation:
        return m_deviation->hasLabel();
    case Tool::Calibrate:
        return m_calibration->hasLabel();
    default:
        return false;
    }
}

QPointF TraceController::labelAnchor() const
{
    switch (m_tool) {
    case Tool::Measure:
        return m_measure->labelAnchor();
    case Tool::Calibrate:
        return m_calibration->labelAnchor();
    case Tool::Seam:
        return m_seam->labelAnchor();
    case Tool::Deviation:
        return m_deviation->labelAnchor();
    default:
        return {};
    }
}

QString TraceController::hint() const
{
    switch (m_tool) {
    case Tool::None:
        return {};
    case Tool::Freehand:
        return tr("Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.");
    case Tool::Calibrate:
        return m_calibration->points() < 2 ? tr("Tap two points on the picture whose real distance you know.")
                                           : tr("Type the real distance between the two points.");
    case Tool::Measure:
        return tr("Tap two points to measure the straight distance.");
    case Tool::Seam:
        return tr("Tap two knots of one curve to measure the length along it.");
    case Tool::Deviation:
        return tr("Tap the traced curve, then the reference curve.");
    case Tool::MoveBackground:
        return tr("Drag the picture to move it; two fingers zoom.");
    case Tool::Perspective:
        if (m_perspective->marks() < 4)
            return m_perspective->calibrated() && m_perspective->marks() == 0
                       ? tr("Drag a corner onto the rectangle's corner in the picture, or tap four new corners.")
                       : tr("Tap the four corners of a rectangle whose size you know, in any order.");
        return tr("Choose the rectangle's size and apply; drag a corner to refine it.");
    case Tool::Outline:
        return tr("Tap inside a pattern piece on the picture to trace its outline.");
    }
    return {};
}

} // namespace kontur
