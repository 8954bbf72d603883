// TraceController: see tracecontroller.h.
// Over 600 lines because the tracing tools (calibrate, freehand, measure, seam, deviation, background
// move) share one tool state, its overlay and its translated texts; the geometry lives in src/geometry.
#include "models/tracecontroller.h"

#include "geometry/strokefit.h"
#include "models/commands.h"
#include "models/languagewatch.h"
#include "models/perspective.h"
#include "models/tracecommands.h"
#include "models/units.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur {

namespace {

geo::Point toPoint(const QPointF &p)
{
    return {p.x(), p.y()};
}

QPointF toQPoint(const geo::Point &p)
{
    return {p.x(), p.y()};
}

// The curve mapped by p ↦ k R p (a similarity about the world origin): its defining points are
// mapped, and every kind's construction commutes with similarities, so the shape maps exactly.
geo::Result<Curve> mapCurve(const Curve &curve, const Eigen::Matrix2d &linear)
{
    auto map = [&](std::vector<geo::Point> pts) {
        for (geo::Point &p : pts)
            p = linear * p;
        return pts;
    };
    geo::Result<Curve> mapped = [&]() -> geo::Result<Curve> {
        if (curve.kind() == CurveKind::Composite) {
            const geo::CompositeCurve &c = curve.composite();
            std::vector<geo::NodeType> types;
            for (int k = 0; k < c.knotCount(); ++k)
                types.push_back(c.nodeType(k));
            auto composite = geo::CompositeCurve::fromParts(map(c.controlPoints()), types, c.isClosed());
            if (!composite)
                return composite.error();
            if (c.isFinished())
                composite->finish();
            return Curve::makeComposite(std::move(*composite));
        }
        return Curve::restore(curve.kind(), map(curve.placedPoints()), map(curve.tangentEnds()),
                              curve.order() > 0 ? curve.order() : 4, curve.parameterization());
    }();
    if (!mapped)
        return mapped;
    mapped->name = curve.name;
    mapped->color = curve.color;
    mapped->visible = curve.visible;
    mapped->locked = curve.locked;
    return mapped;
}

bool parseLocaleNumber(const QString &text, double &out)
{
    bool ok = false;
    const QString t = text.trimmed();
    out = QLocale().toDouble(t, &ok);
    if (!ok)
        out = QLocale::c().toDouble(t, &ok);
    return ok && std::isfinite(out);
}

} // namespace

TraceController::TraceController(QObject *parent)
    : QObject(parent)
{
    // The hint follows the tool and its marks; the written results follow results and units.
    connect(this, &TraceController::toolChanged, this, &TraceController::hintChanged);
    connect(this, &TraceController::calibrationChanged, this, &TraceController::hintChanged);
    connect(this, &TraceController::perspectiveChanged, this, &TraceController::hintChanged);
    connect(this, &TraceController::backgroundChanged, this, &TraceController::hintChanged);
    for (auto signal : {&TraceController::resultChanged, &TraceController::unitsChanged,
                        &TraceController::calibrationChanged, &TraceController::backgroundChanged})
        connect(this, signal, this, &TraceController::textsChanged);
    // A language switch sends LanguageChange several times (installTranslator, removeTranslator),
    // before Language::setCurrent sets the UI locale that numbers use: the translated texts are
    // announced once, when the switch is done (a zero timer, restarted by each event).
    m_languageSwitch.setSingleShot(true);
    connect(&m_languageSwitch, &QTimer::timeout, this, [this] {
        Q_EMIT messageChanged();
        Q_EMIT hintChanged();
        Q_EMIT textsChanged();
    });
    new LanguageWatch(this, [this] { m_languageSwitch.start(0); });
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
    if (m_editor) {
        // One tool at a time: placing a new curve leaves the tracing tool (its taps are the curve's).
        connect(m_editor, &EditController::modeChanged, this, [this] {
            if (m_editor->mode() == EditController::Mode::Place)
                setTool(Tool::None);
        });
        Document *doc = m_editor->document();
        connect(doc, &Document::unitsChanged, this, [this] {
            const QString u = units();
            if (u != m_lastUnits) {
                m_lastUnits = u;
                setTolerance(defaultTolerance(u));
                Q_EMIT unitsChanged();
            }
        });
        connect(doc, &Document::backgroundChanged, this, [this] {
            Q_EMIT backgroundChanged();
            Q_EMIT overlayChanged();
        });
        // Results refer to curves by index and shape: any structural change makes them stale.
        connect(doc, &Document::curveInserted, this, &TraceController::onDocumentChanged);
        connect(doc, &Document::curveRemoved, this, &TraceController::onDocumentChanged);
        connect(doc, &Document::curveMoved, this, &TraceController::onDocumentChanged);
        connect(doc, &Document::curveChanged, this, &TraceController::onDocumentChanged);
        connect(doc, &Document::rowsChanged, this, &TraceController::onDocumentChanged);
        m_lastUnits = units();
        m_tolerance = defaultTolerance(m_lastUnits);
    }
    Q_EMIT editorChanged();
    Q_EMIT unitsChanged();
    Q_EMIT toleranceChanged();
    Q_EMIT backgroundChanged();
}

void TraceController::onDocumentChanged()
{
    // The seam and the deviation are measured again on the changed curves (cheap: a few segments),
    // or dropped when their curves are gone.
    if (m_seamKnots.size() == 2) {
        if (!measureSeam(static_cast<int>(m_seamCurve), m_seamKnots[0], m_seamKnots[1]))
            clear();
    }
    if (m_hasDeviation && m_deviationPick.size() == 2) {
        if (!compareCurves(static_cast<int>(m_deviationPick[0]), static_cast<int>(m_deviationPick[1])))
            clear();
    }
}

void TraceController::setTool(Tool tool)
{
    if (m_tool == tool)
        return;
    cancelStroke();
    m_tool = tool;
    // ... and a tracing tool ends the placing of a new curve.
    if (tool != Tool::None && m_editor && m_editor->mode() == EditController::Mode::Place)
        m_editor->setMode(EditController::Mode::Select);
    m_calibration.clear();
    m_measure.clear();
    m_perspective.clear();
    m_cornerDrag = -1;
    setMessage(Note::None);
    Q_EMIT toolChanged();
    Q_EMIT perspectiveChanged();
    Q_EMIT calibrationChanged();
    Q_EMIT resultChanged();
    Q_EMIT overlayChanged();
}

void TraceController::setTolerance(double tolerance)
{
    if (!(tolerance > 0.0) || !std::isfinite(tolerance) || tolerance == m_tolerance)
        return;
    m_tolerance = tolerance;
    Q_EMIT toleranceChanged();
    Q_EMIT effectiveToleranceChanged();
}

void TraceController::setPixelSize(double size)
{
    if (!(size >= 0.0) || !std::isfinite(size) || size == m_pixelSize)
        return;
    m_pixelSize = size;
    Q_EMIT effectiveToleranceChanged();
}

double TraceController::effectiveTolerance() const
{
    return std::max(m_tolerance, inputPrecision * m_pixelSize);
}

bool TraceController::setToleranceText(const QString &text)
{
    double value = 0.0;
    if (!parseLocaleNumber(text, value) || !(value > 0.0)) {
        setMessage(Note::ToleranceNotPositive);
        return false;
    }
    setTolerance(value);
    setMessage(Note::None);
    return true;
}

void TraceController::setSnapping(bool on)
{
    if (m_snapping == on)
        return;
    m_snapping = on;
    Q_EMIT snappingChanged();
}

QString TraceController::units() const
{
    return document() ? document()->units() : QStringLiteral("px");
}

double TraceController::defaultTolerance(const QString &units)
{
    if (units == QLatin1String("mm"))
        return 0.5;
    if (units == QLatin1String("cm"))
        return 0.05;
    if (units == QLatin1String("in"))
        return 0.02;
    if (units == QLatin1String("pt"))
        return 1.5;
    return 1.0;
}

void TraceController::setMessage(Note note, const QString &arg)
{
    if (m_note == note && m_noteArg == arg)
        return;
    m_note = note;
    m_noteArg = arg;
    Q_EMIT messageChanged();
}

QString TraceController::message() const
{
    // Translated here, when shown, so that a message follows a language switch.
    switch (m_note) {
    case Note::None:
        return {};
    case Note::ToleranceNotPositive:
        return tr("The tolerance must be a positive number.");
    case Note::StrokeTooShort:
        return tr("Draw along the contour with one finger, a stylus or the mouse.");
    case Note::StrokeNotFitted:
        return tr("The stroke could not be fitted.");
    case Note::NoPicture:
        return tr("Load a background picture first.");
    case Note::TapKnot:
        return tr("Tap a knot of the curve.");
    case Note::TapCurve:
        return tr("Tap a curve.");
    case Note::TapOtherCurve:
        return tr("Tap a second, different curve.");
    case Note::NoKnots:
        return tr("This kind of curve has no knots to measure between.");
    case Note::NotComparable:
        return tr("These curves cannot be compared.");
    case Note::NoMarks:
        return tr("Tap two points on the picture first.");
    case Note::DistanceNotPositive:
        return tr("Type the real distance between the two points as a positive number.");
    case Note::LockedCalibrate:
        return tr("The background is locked. Unlock it to calibrate again.");
    case Note::UnknownUnit:
        return tr("Choose mm, cm or in.");
    case Note::SamePoints:
        return tr("The two points must be different.");
    case Note::LockedMove:
        return tr("The background is locked. Unlock it to move it.");
    case Note::CurveNotTurnable:
        return tr("Curve \"%1\" cannot be turned; calibrate without aligning.").arg(m_noteArg);
    case Note::NotConvex:
        return tr("The four points are no corners of a rectangle seen in the picture. Tap them again.");
    case Note::NoCorners:
        return tr("Tap the four corners of the rectangle first.");
    case Note::SidesNotPositive:
        return tr("Type the rectangle's width and height as positive numbers.");
    case Note::PerspectiveSet:
        return tr("The picture has a perspective calibration. Clear it to calibrate by two points.");
    case Note::CornerNotConvex:
        return tr("There the corners would not make a rectangle; the corner stays where it was.");
    }
    return {};
}

// ---------------------------------------------------------------------------------------------
// Snapping

QPointF TraceController::snap(QPointF world, double radius) const
{
    if (!m_snapping || !m_editor || !(radius > 0.0))
        return world;
    const geo::Point w = toPoint(world);
    // Knots and control points first: joining a new curve to an existing one matters most.
    const PointRef hit = m_editor->hitTest(w, radius);
    if (hit.isValid())
        return toQPoint(document()->find(hit.curve)->row(hit.point).position);
    // Then the calibration marks.
    const Background &bg = document()->background();
    if (bg.calibrated && !bg.file.isEmpty()) {
        for (const QPointF &mark : {bg.calibrationA, bg.calibrationB}) {
            const geo::Point m = bg.toWorld(mark);
            if ((m - w).norm() <= radius)
                return toQPoint(m);
        }
    }
    // Then the grid's crossings.
    if (m_gridStep > 0.0 && std::isfinite(m_gridStep)) {
        const geo::Point g(std::round(w.x() / m_gridStep) * m_gridStep, std::round(w.y() / m_gridStep) * m_gridStep);
        if ((g - w).norm() <= radius)
            return toQPoint(g);
    }
    return world;
}

// ---------------------------------------------------------------------------------------------
// Freehand

void TraceController::beginStroke(QPointF world, double snapRadius)
{
    m_stroke.clear();
    m_stroke.push_back(toPoint(snap(world, snapRadius)));
    m_strokeTolerance = effectiveTolerance(); // at the zoom the stroke is drawn at
    m_drawing = true;
    setMessage(Note::None);
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
}

void TraceController::extendStroke(QPointF world)
{
    if (!m_drawing)
        return;
    const geo::Point p = toPoint(world);
    if (!p.allFinite() || p == m_stroke.back())
        return;
    m_stroke.push_back(p);
    Q_EMIT overlayChanged();
}

geo::Result<Curve> TraceController::curveFromStroke(const std::vector<geo::Point> &stroke, double tolerance)
{
    geo::StrokeFitOptions options;
    options.tolerance = tolerance;
    const auto fit = geo::fitStroke(stroke, options);
    if (!fit)
        return fit.error();
    std::vector<geo::NodeType> types;
    for (bool corner : fit->corner)
        types.push_back(corner ? geo::NodeType::Corner : geo::NodeType::Smooth);
    auto composite = geo::CompositeCurve::fromParts(fit->control, std::move(types), false);
    if (!composite)
        return composite.error();
    composite->finish();
    return Curve::makeComposite(std::move(*composite));
}

bool TraceController::endStroke(double snapRadius)
{
    if (!m_drawing)
        return false;
    m_drawing = false;
    std::vector<geo::Point> stroke = std::move(m_stroke);
    m_stroke.clear();
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
    if (stroke.size() >= 2)
        stroke.back() = toPoint(snap(toQPoint(stroke.back()), snapRadius));
    // A stroke shorter than the tolerance is a tap, not a curve.
    double length = 0.0;
    for (std::size_t i = 1; i < stroke.size(); ++i)
        length += (stroke[i] - stroke[i - 1]).norm();
    if (!m_editor || stroke.size() < 2 || length <= m_strokeTolerance) {
        setMessage(Note::StrokeTooShort);
        return false;
    }
    auto curve = curveFromStroke(stroke, m_strokeTolerance);
    if (!curve) {
        setMessage(Note::StrokeNotFitted);
        return false;
    }
    m_lastSegments = curve->segmentCount();
    curve->name = tr("Traced %1").arg(m_editor->document()->curveCount() + 1);
    // appendCurve, not addCurves, which announces a new document (the view would jump to show every
    // curve while the user traces).
    m_editor->commands()->appendCurve(std::move(*curve), tr("Freehand curve"));
    Q_EMIT resultChanged();
    return true;
}

void TraceController::cancelStroke()
{
    if (!m_drawing && m_stroke.empty())
        return;
    m_drawing = false;
    m_stroke.clear();
    Q_EMIT strokeChanged();
    Q_EMIT overlayChanged();
}

// ---------------------------------------------------------------------------------------------
// Two-point tools

void TraceController::clear()
{
    m_calibration.clear();
    m_perspective.clear();
    Q_EMIT perspectiveChanged();
    m_measure.clear();
    m_seamCurve = CurveId::None;
    m_seamKnots.clear();
    m_seamLength = -1.0;
    m_deviationPick.clear();
    m_hasDeviation = false;
    Q_EMIT calibrationChanged();
    Q_EMIT resultChanged();
    Q_EMIT overlayChanged();
}

void TraceController::tap(QPointF world, double hitRadius)
{
    if (!m_editor)
        return;
    setMessage(Note::None);
    const geo::Point w = toPoint(world);
    switch (m_tool) {
    case Tool::None:
    case Tool::Freehand:
    case Tool::MoveBackground:
        return;
    case Tool::Perspective:
        if (document()->background().file.isEmpty()) {
            setMessage(Note::NoPicture);
            return;
        }
        if (m_perspective.size() >= 4)
            m_perspective.clear();
        m_perspective.push_back(w);
        Q_EMIT perspectiveChanged();
        Q_EMIT overlayChanged();
        break;
    case Tool::Calibrate:
        if (document()->background().file.isEmpty()) {
            setMessage(Note::NoPicture);
            return;
        }
        if (m_calibration.size() >= 2)
            m_calibration.clear();
        m_calibration.push_back(toPoint(snap(world, hitRadius)));
        Q_EMIT calibrationChanged();
        Q_EMIT resultChanged();
        break;
    case Tool::Measure:
        if (m_measure.size() >= 2)
            m_measure.clear();
        m_measure.push_back(toPoint(snap(world, hitRadius)));
        Q_EMIT resultChanged();
        break;
    case Tool::Seam: {
        const PointRef hit = m_editor->hitTest(w, hitRadius);
        if (!hit.isValid() || document()->find(hit.curve)->row(hit.point).role != PointRole::Knot) {
            setMessage(Note::TapKnot);
            return;
        }
        const int knot = document()->find(hit.curve)->knotOfRow(hit.point);
        if (m_seamKnots.size() != 1 || m_seamCurve != hit.curve) {
            m_seamKnots = {knot};
            m_seamCurve = hit.curve;
            m_seamLength = -1.0;
            Q_EMIT resultChanged();
        } else {
            measureSeam(static_cast<int>(hit.curve), m_seamKnots[0], knot);
        }
        break;
    }
    case Tool::Deviation: {
        const CurveHit hit = m_editor->curveAt(w, hitRadius);
        if (!hit.isValid()) {
            setMessage(Note::TapCurve);
            return;
        }
        if (m_deviationPick.size() != 1) {
            m_deviationPick = {hit.curve};
            m_hasDeviation = false;
            Q_EMIT resultChanged();
        } else if (m_deviationPick[0] == hit.curve) {
            setMessage(Note::TapOtherCurve);
            return;
        } else {
            compareCurves(static_cast<int>(m_deviationPick[0]), static_cast<int>(hit.curve));
        }
        break;
    }
    }
    Q_EMIT overlayChanged();
}

double TraceController::measureDistance() const
{
    return m_measure.size() == 2 ? (m_measure[1] - m_measure[0]).norm() : 0.0;
}

bool TraceController::measureSeam(int curveId, int knotA, int knotB)
{
    Document *doc = document();
    const Curve *found = doc ? doc->find(static_cast<CurveId>(curveId)) : nullptr;
    if (!found)
        return false;
    const Curve &curve = *found;
    const geo::PiecewiseBezier pw = curve.toPiecewise();
    const int knots = curve.placedCount();
    const int expected = curve.isClosed() ? knots : knots - 1;
    if (!traitsOf(curve.kind()).knotToKnot || pw.segmentCount() != expected) {
        setMessage(Note::NoKnots);
        return false;
    }
    const auto length = geo::lengthBetween(pw, knotA, knotB, kLengthAccuracy);
    if (!length) {
        setMessage(Note::TapKnot);
        return false;
    }
    m_seamCurve = curve.id();
    m_seamKnots = {knotA, knotB};
    m_seamLength = *length;
    Q_EMIT resultChanged();
    Q_EMIT overlayChanged();
    return true;
}

std::vector<geo::Bezier> TraceController::seamSegments() const
{
    std::vector<geo::Bezier> out;
    Document *doc = document();
    const Curve *seamCurve = doc ? doc->find(m_seamCurve) : nullptr;
    if (!seamCurve || m_seamKnots.size() != 2)
        return out;
    const geo::PiecewiseBezier pw = seamCurve->toPiecewise();
    const int n = pw.segmentCount();
    int first = m_seamKnots[0], last = m_seamKnots[1];
    if (last < first && !pw.isClosed())
        std::swap(first, last);
    const int count = last >= first ? last - first : last - first + n;
    for (int k = 0; k < count && n > 0; ++k)
        out.push_back(pw.segments()[static_cast<std::size_t>((first + k) % n)]);
    return out;
}

std::vector<geo::Point> TraceController::seamMarks() const
{
    std::vector<geo::Point> out;
    Document *doc = document();
    const Curve *seamCurve = doc ? doc->find(m_seamCurve) : nullptr;
    if (!seamCurve)
        return out;
    for (int k : m_seamKnots) {
        const int row = seamCurve->rowOfKnot(k);
        if (row >= 0)
            out.push_back(seamCurve->row(row).position);
    }
    return out;
}

bool TraceController::compareCurves(int a, int b)
{
    Document *doc = document();
    const Curve *first = doc ? doc->find(static_cast<CurveId>(a)) : nullptr;
    const Curve *second = doc ? doc->find(static_cast<CurveId>(b)) : nullptr;
    if (!first || !second || a == b)
        return false;
    const auto d = geo::deviation(first->toPiecewise(), second->toPiecewise());
    if (!d) {
        setMessage(Note::NotComparable);
        return false;
    }
    m_deviationPick = {first->id(), second->id()};
    m_deviation = *d;
    m_hasDeviation = true;
    Q_EMIT resultChanged();
    Q_EMIT overlayChanged();
    return true;
}

// ---------------------------------------------------------------------------------------------
// Calibration

double TraceController::calibrationImageDistance() const
{
    if (m_calibration.size() != 2 || !document())
        return 0.0;
    const Background &bg = document()->background();
    const QPointF d = bg.toImage(m_calibration[1]) - bg.toImage(m_calibration[0]);
    return std::hypot(d.x(), d.y());
}

bool TraceController::backgroundLocked() const
{
    return document() && document()->background().locked;
}

void TraceController::setBackgroundLocked(bool locked)
{
    if (!m_editor || backgroundLocked() == locked || document()->background().file.isEmpty())
        return;
    Background bg = document()->background();
    bg.locked = locked;
    m_editor->background()->setBackground(bg);
}

bool TraceController::backgroundCalibrated() const
{
    return document() && document()->background().calibrated;
}

bool TraceController::calibrate(const QString &distanceText, const QString &unit, int align)
{
    if (!document())
        return false;
    if (m_calibration.size() != 2) {
        setMessage(Note::NoMarks);
        return false;
    }
    double distance = 0.0;
    if (!parseLocaleNumber(distanceText, distance) || !(distance > 0.0)) {
        setMessage(Note::DistanceNotPositive);
        return false;
    }
    const Background &bg = document()->background();
    const bool ok = calibrateImagePoints(bg.toImage(m_calibration[0]), bg.toImage(m_calibration[1]), distance, unit,
                                         static_cast<Align>(std::clamp(align, 0, 2)));
    if (ok) {
        m_calibration.clear();
        Q_EMIT calibrationChanged();
        Q_EMIT resultChanged();
        Q_EMIT overlayChanged();
    }
    return ok;
}

bool TraceController::calibrateImagePoints(QPointF imageA, QPointF imageB, double distance, const QString &unit,
                                           Align align)
{
    Document *doc = document();
    if (!doc)
        return false;
    const Background before = doc->background();
    if (before.file.isEmpty()) {
        setMessage(Note::NoPicture);
        return false;
    }
    if (before.locked) {
        setMessage(Note::LockedCalibrate);
        return false;
    }
    if (before.perspective) {
        setMessage(Note::PerspectiveSet);
        return false;
    }
    if (unit != QLatin1String("mm") && unit != QLatin1String("cm") && unit != QLatin1String("in")) {
        setMessage(Note::UnknownUnit);
        return false;
    }
    const geo::Point wa = before.toWorld(imageA), wb = before.toWorld(imageB);
    const double worldDistance = (wb - wa).norm();
    if (!(worldDistance > 0.0) || !(distance > 0.0) || !std::isfinite(distance)) {
        setMessage(Note::SamePoints);
        return false;
    }
    // The world is scaled by k and turned by θ about its origin: p ↦ k R(θ) p.
    const double k = distance / worldDistance;
    const double phi = std::atan2(wb.y() - wa.y(), wb.x() - wa.x());
    double theta = 0.0;
    if (align == Horizontal)
        theta = std::round(phi / std::numbers::pi) * std::numbers::pi - phi;
    else if (align == Vertical)
        theta =
            std::round((phi - std::numbers::pi / 2) / std::numbers::pi) * std::numbers::pi + std::numbers::pi / 2 - phi;
    const Eigen::Matrix2d linear = k * Eigen::Rotation2Dd(theta).toRotationMatrix();

    Background after = before;
    after.origin = toQPoint(linear * toPoint(before.origin));
    after.scale = before.scale * k;
    after.rotation = std::remainder(before.rotation + theta * 180.0 / std::numbers::pi, 360.0);
    after.calibrated = true;
    after.calibrationA = imageA;
    after.calibrationB = imageB;
    after.calibrationDistance = distance;

    if (!pushCalibration(tr("Calibrate background"), before, after, unit, k, theta))
        return false;
    setMessage(Note::None);
    return true;
}

bool TraceController::pushCalibration(const QString &text, const Background &before, const Background &after,
                                      const QString &unit, double scale, double radians)
{
    Document *doc = document();
    const Eigen::Matrix2d linear = scale * Eigen::Rotation2Dd(radians).toRotationMatrix();
    // The curves follow the picture, so that what was traced stays on it.
    std::vector<std::pair<int, Curve>> mapped;
    for (int c = 0; c < doc->curveCount(); ++c) {
        auto m = mapCurve(doc->curve(c), linear);
        if (!m) {
            setMessage(Note::CurveNotTurnable, doc->curve(c).name);
            return false;
        }
        mapped.emplace_back(c, std::move(*m));
    }
    auto *calibration = new QUndoCommand(text);
    for (auto &[index, curve] : mapped)
        new ReplaceCurveCommand(doc, doc->idAt(index), doc->curve(index), std::move(curve), QString(), calibration);
    // The view follows the mapping on the first redo, on undo and on redo.
    new CalibrationCommand(
        doc, before, after, doc->units(), unit, scale, radians,
        [self = QPointer<TraceController>(this)](double s, double r) {
            if (self)
                Q_EMIT self->worldMapped(s, r);
        },
        calibration);
    m_editor->push(calibration);
    return true;
}

// ---------------------------------------------------------------------------------------------

bool TraceController::hasLabel() const
{
    switch (m_tool) {
    case Tool::Measure:
        return m_measure.size() == 2;
    case Tool::Seam:
        return m_seamLength >= 0.0 && m_seamKnots.size() == 2;
    case Tool::Deviation:
        return m_hasDeviation;
    case Tool::Calibrate:
        return m_calibration.size() == 2;
    default:
        return false;
    }
}

QPointF TraceController::labelAnchor() const
{
    switch (m_tool) {
    case Tool::Measure:
        if (m_measure.size() == 2)
            return toQPoint((m_measure[0] + m_measure[1]) / 2);
        break;
    case Tool::Calibrate:
        if (m_calibration.size() == 2)
            return toQPoint((m_calibration[0] + m_calibration[1]) / 2);
        break;
    case Tool::Seam: {
        const std::vector<geo::Point> marks = seamMarks();
        if (!marks.empty())
            return toQPoint(marks.back());
        break;
    }
    case Tool::Deviation:
        if (m_hasDeviation)
            return toQPoint(m_deviation.maximumAt);
        break;
    default:
        break;
    }
    return {};
}

QString TraceController::hint() const
{
    switch (m_tool) {
    case Tool::None:
        return {};
    case Tool::Freehand:
        return tr("Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.");
    case Tool::Calibrate:
        return m_calibration.size() < 2 ? tr("Tap two points on the picture whose real distance you know.")
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
        if (m_perspective.size() < 4)
            return backgroundPerspective() && m_perspective.empty()
                       ? tr("Drag a corner onto the rectangle's corner in the picture, or tap four new corners.")
                       : tr("Tap the four corners of a rectangle whose size you know, in any order.");
        return tr("Choose the rectangle's size and apply; drag a corner to refine it.");
    }
    return {};
}

bool TraceController::beginBackgroundMove()
{
    m_moving = false;
    if (!m_editor)
        return false;
    const Background &bg = document()->background();
    if (bg.file.isEmpty()) {
        setMessage(Note::NoPicture);
        return false;
    }
    if (bg.locked) {
        setMessage(Note::LockedMove);
        return false;
    }
    setMessage(Note::None);
    m_moving = true;
    ++m_moveSerial;
    return true;
}

void TraceController::moveBackgroundBy(QPointF worldDelta)
{
    if (!m_moving || !m_editor || worldDelta.isNull())
        return;
    // Each step is a command whose redo() moves the picture; the stack merges the steps of one drag
    // into its first command, so the whole drag is one undo step.
    Background after = document()->background();
    after.origin += worldDelta;
    if (after.perspective)
        after.rectOrigin += worldDelta;
    m_editor->push(new BackgroundCommand(document(), document()->background(), after, nullptr, m_moveSerial));
}

void TraceController::endBackgroundMove()
{
    m_moving = false;
}

// ---------------------------------------------------------------------------------------------
// Texts

QString TraceController::measureText() const
{
    return formatLength(measureDistance(), units());
}

QString TraceController::seamText() const
{
    return formatLength(std::max(m_seamLength, 0.0), units());
}

QString TraceController::deviationMaximumText() const
{
    return formatLength(deviationMaximum(), units());
}

QString TraceController::deviationMeanText() const
{
    return formatLength(deviationMean(), units());
}

QString TraceController::calibrationImageText() const
{
    return formatNumber(calibrationImageDistance(), 1);
}

} // namespace kontur
