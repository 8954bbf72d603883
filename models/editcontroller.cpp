// EditController: placing, picking, dragging and editing curves with the seed's rules, with undo.
// Over 600 lines for now: placing, picking, dragging and editing share one controller; issue #18 splits
// it into placement, selection, curve commands and background.
#include "models/editcontroller.h"

#include "geometry/nearest.h"
#include "models/commands.h"
#include "models/languagewatch.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImageReader>
#include <QLocale>
#include <QUrl>

#include <cmath>
#include <limits>

namespace kontur {

namespace {

geo::Point toPoint(QPointF p)
{
    return {p.x(), p.y()};
}

bool isKind(int kind)
{
    return kind >= 0 && kind < kKindCount;
}

// What became of a typed number.
enum class Parsed {
    Number,   // a finite double
    NotValid, // empty, not a number, or NaN / infinity spelled out
    TooLarge, // a number beyond the largest double (1e400): refused, never stored as infinity
};

// A number typed by the user: in the UI language's format, or with a decimal point as in files. The
// double nearest to the text, never rounded to what the table shows.
Parsed parseNumber(const QVariant &value, double &out)
{
    if (value.typeId() == QMetaType::Double || value.typeId() == QMetaType::Int) {
        out = value.toDouble();
        return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
    }
    const QString text = value.toString().trimmed();
    if (text.isEmpty())
        return Parsed::NotValid;
    bool overflow = false;
    for (const QLocale &locale : {QLocale(), QLocale::c()}) {
        bool ok = false;
        out = locale.toDouble(text, &ok);
        if (ok)
            return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
        // QLocale answers infinity with ok == false for a number too large for a double.
        overflow = overflow || std::isinf(out);
    }
    return overflow ? Parsed::TooLarge : Parsed::NotValid;
}

} // namespace

EditController::EditController(QObject *parent)
    : QObject(parent)
    , m_document(new Document(this))
    , m_curves(new CurveListModel(m_document, this))
    , m_points(new PointListModel(m_document, this))
{
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &EditController::undoStateChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &EditController::undoStateChanged);
    connect(&m_undo, &QUndoStack::cleanChanged, this, &EditController::undoStateChanged);
    connect(this, &EditController::pendingChanged, this, &EditController::undoStateChanged);
    connect(m_document, &Document::backgroundChanged, this, &EditController::backgroundChanged);
    new LanguageWatch(this, [this] { retranslate(); });

    // The hit-test index follows point moves in place and rebuilds after anything structural.
    connect(m_document, &Document::rowsChanged, this,
            [this](int curve, int first, int last) { m_index.update(*m_document, curve, first, last); });
    for (auto signal : {&Document::curveInserted, &Document::curveRemoved, &Document::curveChanged})
        connect(m_document, signal, this, [this](int) { m_index.invalidate(); });
    connect(m_document, &Document::curveMoved, this, [this](int, int) { m_index.invalidate(); });

    // Undo may remove or move the selected curve: keep the selection pointing at real rows.
    connect(m_document, &Document::curveRemoved, this, [this](int index) {
        if (m_drag.curve == index) {
            m_drag = {};
            Q_EMIT draggingChanged();
        }
        if (m_selectedCurve == index)
            setSelection(-1, -1);
        else if (m_selectedCurve > index)
            setSelection(m_selectedCurve - 1, m_selectedPoint);
    });
    connect(m_document, &Document::curveInserted, this, [this](int index) {
        if (m_selectedCurve >= index)
            setSelection(m_selectedCurve + 1, m_selectedPoint);
    });
    connect(m_document, &Document::curveMoved, this,
            [this](int from, int to) { setSelection(indexAfterMove(m_selectedCurve, from, to), m_selectedPoint); });
    connect(m_document, &Document::curveChanged, this, [this](int index) {
        if (index == m_selectedCurve && m_selectedPoint >= m_document->curve(index).rowCount())
            setSelection(index, -1);
    });
}

EditController::~EditController()
{
    // The stack's commands point at the document: drop them before the document goes.
    m_undo.clear();
}

// --- modes and settings ---------------------------------------------------------------------

void EditController::setMode(Mode mode)
{
    if (mode == m_mode)
        return;
    m_mode = mode;
    clearMessage();
    if (!m_pending.empty()) {
        m_pending.clear();
        Q_EMIT pendingChanged();
    }
    Q_EMIT modeChanged();
}

void EditController::setPlacementKind(int kind)
{
    if (!isKind(kind) || kind == static_cast<int>(m_placementKind))
        return;
    m_placementKind = static_cast<CurveKind>(kind);
    cancelPlacement();
    Q_EMIT placementChanged();
}

void EditController::setPlacementDegree(int degree)
{
    degree = std::clamp(degree, 1, traitsOf(CurveKind::Bezier).maxPoints - 1);
    if (degree == m_placementDegree)
        return;
    m_placementDegree = degree;
    Q_EMIT placementChanged();
}

void EditController::setParameterization(int parameterization)
{
    if (parameterization < Uniform || parameterization > Centripetal ||
        parameterization == static_cast<int>(m_parameterization))
        return;
    m_parameterization = static_cast<geo::Parameterization>(parameterization);
    Q_EMIT placementChanged();
}

void EditController::setHandleMode(HandleMode mode)
{
    if (mode == m_handleMode)
        return;
    m_handleMode = mode;
    Q_EMIT handleModeChanged();
}

void EditController::startPlacing(int kind)
{
    setPlacementKind(kind);
    setMode(Mode::Place);
    cancelPlacement();
}

QVariantList EditController::kinds() const
{
    QVariantList list;
    for (int k = 0; k < kKindCount; ++k)
        list << QVariantMap{
            {QStringLiteral("kind"), k},
            {QStringLiteral("name"), kindName(static_cast<CurveKind>(k))},
            {QStringLiteral("usesParameterization"), traitsOf(static_cast<CurveKind>(k)).usesParameterization}};
    return list;
}

int EditController::requiredPoints() const
{
    if (m_placementKind == CurveKind::Bezier)
        return m_placementDegree + 1;
    return traitsOf(m_placementKind).placementCount;
}

std::vector<geo::Bezier> EditController::pendingSegments() const
{
    std::vector<geo::Bezier> segments = previewSegments();
    // The canvas never receives a point that is not finite (knots near the largest double).
    std::erase_if(segments, [](const geo::Bezier &segment) {
        return !std::all_of(segment.controlPoints().begin(), segment.controlPoints().end(),
                            [](const geo::Point &p) { return p.allFinite(); });
    });
    return segments;
}

std::vector<geo::Bezier> EditController::previewSegments() const
{
    std::vector<geo::Bezier> segments;
    switch (m_placementKind) {
    case CurveKind::Composite:
        // Segments appear from the 3rd knot on; the last one waits for "Done" (seed T15, T16).
        if (m_pending.size() >= 3) {
            const geo::CompositeCurve building(m_pending);
            for (int i = 0; i + 1 < building.segmentCount(); ++i)
                segments.push_back(building.segment(i));
        }
        break;
    case CurveKind::Bezier:
    case CurveKind::Interpolating:
        break; // these appear when their last point is placed
    default:
        // The open-ended kinds show what "Done" would make, once there are enough points.
        if (pendingCount() >= traitsOf(m_placementKind).minPoints) {
            const Curve preview = Curve::make(m_placementKind, m_pending, m_parameterization);
            for (int i = 0; i < preview.segmentCount(); ++i)
                segments.push_back(preview.segment(i));
        }
        break;
    }
    return segments;
}

// --- selection and messages -----------------------------------------------------------------

void EditController::selectCurve(int curve)
{
    if (curve < -1 || curve >= m_document->curveCount())
        curve = -1;
    setSelection(curve, curve == m_selectedCurve ? m_selectedPoint : -1);
}

void EditController::selectPoint(int curve, int row)
{
    if (!m_document->isValidRow(curve, row))
        return;
    setSelection(curve, row);
}

void EditController::setSelection(int curve, int point)
{
    if (curve == m_selectedCurve && point == m_selectedPoint)
        return;
    m_selectedCurve = curve;
    m_selectedPoint = curve >= 0 ? point : -1;
    m_curves->setSelectedRow(curve);
    m_points->setCurve(curve);
    Q_EMIT selectionChanged();
}

void EditController::say(Message::Id id, QVariantList args)
{
    m_message = Message{id, std::move(args)};
    Q_EMIT messageChanged();
}

void EditController::clearMessage()
{
    if (m_message.isEmpty())
        return;
    m_message = {};
    Q_EMIT messageChanged();
}

void EditController::sayError(const Curve &curve, const geo::Error &error)
{
    const int kind = static_cast<int>(curve.kind());
    switch (error.code) {
    case geo::ErrorCode::TooFewPoints:
        say(Message::TooFewPoints, {kind, traitsOf(curve.kind()).minPoints});
        return;
    case geo::ErrorCode::AllPointsEqual:
    case geo::ErrorCode::CoincidentPoints:
    case geo::ErrorCode::TooFewDistinctParameters:
    case geo::ErrorCode::IllConditioned:
        say(Message::FitFailed, {kind});
        return;
    case geo::ErrorCode::NonFiniteInput:
        // Every number reaching the geometry from here is finite (typed ones are parsed, gestures
        // checked): a result that is not went past the largest double.
        say(Message::OutOfRange);
        return;
    case geo::ErrorCode::IndexOutOfRange:
    case geo::ErrorCode::InvalidArgument:
        say(Message::NotPossibleForKind, {kind});
        return;
    }
}

bool EditController::editable(int curve)
{
    if (curve < 0 || curve >= m_document->curveCount())
        return false;
    if (m_document->curve(curve).locked) {
        say(Message::CurveLocked, {m_document->curve(curve).name});
        return false;
    }
    return true;
}

QString EditController::newCurveName(CurveKind kind)
{
    ++m_createdCount;
    switch (kind) {
    case CurveKind::Bezier:
        return QCoreApplication::translate("kontur", "Bézier %1").arg(m_createdCount);
    case CurveKind::Interpolating:
        return QCoreApplication::translate("kontur", "Through 4 points %1").arg(m_createdCount);
    case CurveKind::LeastSquares:
        return QCoreApplication::translate("kontur", "Least squares %1").arg(m_createdCount);
    case CurveKind::Composite:
        return QCoreApplication::translate("kontur", "Composite %1").arg(m_createdCount);
    default:
        // "Natural spline 3": the kind's name and a number.
        return QCoreApplication::translate("kontur", "%1 %2").arg(kindName(kind)).arg(m_createdCount);
    }
}

// --- hit testing --------------------------------------------------------------------------------

PointRef EditController::hitTest(const geo::Point &world, double radius)
{
    const PointHit hit = m_index.nearest(*m_document, world, radius);
    return hit.isValid() ? PointRef{hit.curve, hit.row} : PointRef{};
}

CurveHit EditController::curveAt(const geo::Point &world, double radius)
{
    CurveHit best;
    if (!world.allFinite() || !(radius > 0.0))
        return best;
    best.distance = radius;
    for (int c = 0; c < m_document->curveCount(); ++c) {
        const Curve &curve = m_document->curve(c);
        if (!curve.visible)
            continue;
        // The curve lies in the hull of its rows: skip it when their box is too far.
        if (m_index.curveBox(*m_document, c, radius).exteriorDistance(world) > best.distance)
            continue;
        for (int s = 0; s < curve.segmentCount(); ++s) {
            const geo::Bezier segment = curve.segment(s);
            geo::Box box;
            for (const geo::Point &p : segment.controlPoints())
                box.extend(p);
            if (box.exteriorDistance(world) > best.distance)
                continue;
            const auto nearest = geo::nearest(segment, world);
            if (nearest.distance <= best.distance)
                best = {c, s, nearest.t, nearest.distance};
        }
    }
    return best;
}

// --- gestures -------------------------------------------------------------------------------

void EditController::tap(QPointF world, double hitRadius)
{
    const geo::Point p = toPoint(world);
    if (!p.allFinite())
        return;
    switch (m_mode) {
    case Mode::Place:
        if (pendingCount() >= traitsOf(m_placementKind).maxPoints) {
            say(Message::TooManyPoints, {traitsOf(m_placementKind).maxPoints});
            return;
        }
        clearMessage();
        m_pending.push_back(p);
        Q_EMIT pendingChanged();
        if (requiredPoints() > 0 && pendingCount() == requiredPoints())
            finishPlacement();
        return;
    case Mode::Select: {
        const PointRef hit = hitTest(p, hitRadius);
        if (hit.isValid()) {
            setSelection(hit.curve, hit.point);
            return;
        }
        const CurveHit onCurve = curveAt(p, hitRadius);
        setSelection(onCurve.curve, -1);
        return;
    }
    }
}

bool EditController::finishPlacement()
{
    if (m_mode != Mode::Place || m_pending.empty())
        return false;
    const KindTraits traits = traitsOf(m_placementKind);
    if (pendingCount() < traits.minPoints) {
        say(Message::TooFewPoints, {static_cast<int>(m_placementKind), traits.minPoints});
        return false;
    }
    Curve curve = Curve::make(m_placementKind, std::move(m_pending), m_parameterization);
    m_pending.clear();
    Q_EMIT pendingChanged();
    if (curve.problem()) {
        // The knots define no curve (e.g. all at one place): keep nothing, say why.
        sayError(curve, *curve.problem());
        return false;
    }
    if (!curve.isFinite()) {
        say(Message::OutOfRange);
        return false;
    }
    curve.name = newCurveName(m_placementKind);
    const int index = m_document->curveCount();
    m_undo.push(CurvePresenceCommand::add(m_document, index, std::move(curve)));
    setSelection(index, -1);
    clearMessage();
    return true;
}

bool EditController::beginDrag(QPointF world, double hitRadius, bool constrained)
{
    const geo::Point p = toPoint(world);
    const PointRef hit = p.allFinite() ? hitTest(p, hitRadius) : PointRef{};
    if (!hit.isValid())
        return false;
    setSelection(hit.curve, hit.point);
    const Curve &curve = m_document->curve(hit.curve);
    if (!editable(hit.curve))
        return true; // taken (nothing under it should pan), but nothing moves
    if (!curve.row(hit.point).editable) {
        say(Message::ControlPointsNotMovable, {static_cast<int>(curve.kind())});
        return true;
    }
    clearMessage();
    m_drag = hit;
    m_dragMode =
        (constrained || m_handleMode == HandleMode::Constrained) ? geo::HandleMove::Constrained : geo::HandleMove::Free;
    m_grabOffset = curve.row(hit.point).position - p;
    ++m_dragSerial;
    Q_EMIT draggingChanged();
    return true;
}

void EditController::dragTo(QPointF world)
{
    const geo::Point p = toPoint(world);
    if (!m_drag.isValid() || !p.allFinite() || !m_document->isValidRow(m_drag.curve, m_drag.point))
        return;
    const geo::Point target = p + m_grabOffset;
    if (!target.allFinite()) {
        say(Message::OutOfRange);
        return;
    }
    auto changes = m_document->movePoint(m_drag.curve, m_drag.point, target, m_dragMode);
    if (!changes.ok()) {
        sayError(m_document->curve(m_drag.curve), changes.error());
        return;
    }
    if (!changes->empty())
        m_undo.push(new MovePointsCommand(m_document, m_drag.curve, std::move(changes.value()), m_dragSerial));
    const Curve &curve = m_document->curve(m_drag.curve);
    if (curve.problem())
        sayError(curve, *curve.problem());
    else if (m_message.id == Message::FitFailed)
        clearMessage();
}

void EditController::endDrag()
{
    if (!m_drag.isValid())
        return;
    m_drag = {};
    Q_EMIT draggingChanged();
}

void EditController::hover(QPointF world)
{
    const geo::Point p = toPoint(world);
    if (!p.allFinite() || (m_hasHover && p == m_hover))
        return;
    m_hover = p;
    m_hasHover = true;
    Q_EMIT hoverChanged();
}

void EditController::clearHover()
{
    if (!m_hasHover)
        return;
    m_hasHover = false;
    Q_EMIT hoverChanged();
}

void EditController::cancelPlacement()
{
    if (m_pending.empty())
        return;
    m_pending.clear();
    Q_EMIT pendingChanged();
}

void EditController::removeLastPending()
{
    if (m_pending.empty())
        return;
    m_pending.pop_back();
    Q_EMIT pendingChanged();
}

// --- commands -------------------------------------------------------------------------------

void EditController::undo()
{
    if (!m_pending.empty()) {
        removeLastPending();
        return;
    }
    endDrag();
    m_undo.undo();
}

void EditController::redo()
{
    endDrag();
    m_undo.redo();
}

template <typename Edit> bool EditController::editCurve(int index, const QString &text, Edit edit)
{
    if (!editable(index))
        return false;
    const Curve &before = m_document->curve(index);
    Curve after = before;
    const geo::Result<geo::Ok> result = edit(after);
    if (!result.ok()) {
        sayError(before, result.error());
        return false;
    }
    if (!after.isFinite()) {
        // Finite input whose result is not (a point moved near the largest double carries a handle
        // past it): refused, so that no model and no canvas ever holds infinity or NaN.
        say(Message::OutOfRange);
        return false;
    }
    if (after.sameState(before))
        return true;
    m_undo.push(new ReplaceCurveCommand(m_document, index, before, std::move(after), text));
    return true;
}

bool EditController::deleteCurve(int curve)
{
    if (!editable(curve))
        return false;
    m_undo.push(CurvePresenceCommand::remove(m_document, curve));
    return true;
}

bool EditController::moveCurve(int from, int to)
{
    if (from < 0 || from >= m_document->curveCount() || to < 0 || to >= m_document->curveCount() || from == to)
        return false;
    m_undo.push(new MoveCurveCommand(m_document, from, to));
    return true;
}

bool EditController::setCurveParameterization(int curve, int parameterization)
{
    if (curve < 0 || curve >= m_document->curveCount() || parameterization < Uniform || parameterization > Centripetal)
        return false;
    const Curve &c = m_document->curve(curve);
    if (!traitsOf(c.kind()).usesParameterization) {
        say(Message::NoParameterization, {static_cast<int>(c.kind())});
        return false;
    }
    return editCurve(curve, QCoreApplication::translate("kontur", "Change parameterization"), [&](Curve &edited) {
        edited.setParameterization(static_cast<geo::Parameterization>(parameterization));
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool EditController::setCurveName(int curve, const QString &name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty())
        return false;
    return editCurve(curve, QCoreApplication::translate("kontur", "Rename curve"), [&](Curve &edited) {
        edited.name = trimmed;
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool EditController::setCurveColor(int curve, const QColor &color)
{
    if (!color.isValid())
        return false;
    return editCurve(curve, QCoreApplication::translate("kontur", "Change colour"), [&](Curve &edited) {
        edited.color = color;
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool EditController::setCurveVisible(int curve, bool visible)
{
    // Hiding and showing work on locked curves too: a lock protects the shape, not the view.
    if (curve < 0 || curve >= m_document->curveCount() || m_document->curve(curve).visible == visible)
        return false;
    Curve after = m_document->curve(curve);
    after.visible = visible;
    m_undo.push(new ReplaceCurveCommand(m_document, curve, m_document->curve(curve), std::move(after),
                                        visible ? QCoreApplication::translate("kontur", "Show curve")
                                                : QCoreApplication::translate("kontur", "Hide curve")));
    return true;
}

bool EditController::setCurveLocked(int curve, bool locked)
{
    if (curve < 0 || curve >= m_document->curveCount() || m_document->curve(curve).locked == locked)
        return false;
    Curve after = m_document->curve(curve);
    after.locked = locked;
    m_undo.push(new ReplaceCurveCommand(m_document, curve, m_document->curve(curve), std::move(after),
                                        locked ? QCoreApplication::translate("kontur", "Lock curve")
                                               : QCoreApplication::translate("kontur", "Unlock curve")));
    return true;
}

bool EditController::setNodeType(int curve, int knot, int type)
{
    if (type < Smooth || type > Corner)
        return false;
    return editCurve(curve, QCoreApplication::translate("kontur", "Change node type"),
                     [&](Curve &edited) { return edited.setNodeType(knot, static_cast<geo::NodeType>(type)); });
}

bool EditController::insertPoint(int curve, int index, QPointF position)
{
    if (curve < 0 || curve >= m_document->curveCount())
        return false;
    const Curve &c = m_document->curve(curve);
    const KindTraits traits = traitsOf(c.kind());
    const int count = c.placedCount();
    if (count >= traits.maxPoints) {
        say(Message::TooManyPoints, {traits.maxPoints});
        return false;
    }
    if (!toPoint(position).allFinite()) {
        // The table's "Add row" beyond a last point near the largest double.
        say(Message::OutOfRange);
        return false;
    }
    // Closing merges a last knot equal to the first (geo::CompositeCurve::close): such a knot adds nothing.
    if (c.kind() == CurveKind::Composite && c.isClosed() && index == count &&
        toPoint(position) == c.composite().knot(0)) {
        say(Message::KnotOnFirstKnot);
        return false;
    }
    return editCurve(curve, QCoreApplication::translate("kontur", "Add point"),
                     [&](Curve &edited) { return edited.insertPoint(index, toPoint(position)); });
}

bool EditController::removePoint(int curve, int index)
{
    if (curve < 0 || curve >= m_document->curveCount())
        return false;
    const Curve &c = m_document->curve(curve);
    const KindTraits traits = traitsOf(c.kind());
    const int count = c.placedCount();
    const int minimum = c.isClosed() ? std::max(3, traits.minPoints) : traits.minPoints;
    if (count <= minimum) {
        say(Message::TooFewPoints, {static_cast<int>(c.kind()), minimum});
        return false;
    }
    return editCurve(curve, QCoreApplication::translate("kontur", "Delete point"),
                     [&](Curve &edited) { return edited.removePoint(index); });
}

bool EditController::setCurveOrder(int curve, int order)
{
    return editCurve(curve, QCoreApplication::translate("kontur", "Change order"),
                     [&](Curve &edited) { return edited.setOrder(order); });
}

bool EditController::insertKnotOnSegment(int curve, int segment, double t)
{
    return editCurve(curve, QCoreApplication::translate("kontur", "Insert knot"),
                     [&](Curve &edited) { return edited.insertKnotOnSegment(segment, t); });
}

bool EditController::closeCurve(int curve)
{
    return editCurve(curve, QCoreApplication::translate("kontur", "Close curve"),
                     [&](Curve &edited) { return edited.close(); });
}

bool EditController::setControlPoints(int curve, const std::vector<geo::Point> &points, const QString &text)
{
    if (curve < 0 || curve >= m_document->curveCount() || m_document->curve(curve).kind() != CurveKind::Bezier)
        return false;
    const KindTraits traits = traitsOf(CurveKind::Bezier);
    const int count = static_cast<int>(points.size());
    if (count < traits.minPoints || count > traits.maxPoints)
        return false;
    return editCurve(curve, text, [&](Curve &edited) -> geo::Result<geo::Ok> {
        Curve made = Curve::make(CurveKind::Bezier, points);
        if (made.problem())
            return *made.problem();
        made.name = edited.name;
        made.color = edited.color;
        made.visible = edited.visible;
        made.locked = edited.locked;
        edited = std::move(made);
        return geo::Ok{};
    });
}

bool EditController::splitBezier(int curve, double t)
{
    if (!editable(curve) || m_document->curve(curve).kind() != CurveKind::Bezier || !(t > 0.0 && t < 1.0))
        return false;
    const Curve &before = m_document->curve(curve);
    const auto [left, right] = before.segment(0).split(t);
    Curve first = Curve::make(CurveKind::Bezier, left.controlPoints());
    Curve second = Curve::make(CurveKind::Bezier, right.controlPoints());
    if (!first.isFinite() || !second.isFinite()) {
        say(Message::OutOfRange);
        return false;
    }
    first.name = before.name;
    first.color = before.color;
    first.visible = before.visible;
    second.name = newCurveName(CurveKind::Bezier);
    second.color = before.color;
    second.visible = before.visible;
    m_undo.beginMacro(QCoreApplication::translate("kontur", "Split curve"));
    m_undo.push(new ReplaceCurveCommand(m_document, curve, before, std::move(first),
                                        QCoreApplication::translate("kontur", "Split curve")));
    m_undo.push(CurvePresenceCommand::add(m_document, curve + 1, std::move(second)));
    m_undo.endMacro();
    return true;
}

bool EditController::parseRows(const QVariantList &rows, std::vector<geo::Point> &out)
{
    out.clear();
    for (const QVariant &row : rows) {
        const QVariantList xy = row.toList();
        double x = 0.0, y = 0.0;
        const Parsed px = xy.size() == 2 ? parseNumber(xy[0], x) : Parsed::NotValid;
        const Parsed py = xy.size() == 2 ? parseNumber(xy[1], y) : Parsed::NotValid;
        if (px == Parsed::NotValid || py == Parsed::NotValid) {
            say(Message::FillAllValues);
            return false;
        }
        if (px == Parsed::TooLarge || py == Parsed::TooLarge) {
            say(Message::OutOfRange);
            return false;
        }
        out.emplace_back(x, y);
    }
    return true;
}

bool EditController::applyCoordinates(int curve, const QVariantList &rows)
{
    if (curve < 0 || curve >= m_document->curveCount())
        return false;
    std::vector<geo::Point> points;
    if (!parseRows(rows, points))
        return false;
    const Curve &c = m_document->curve(curve);
    if (static_cast<int>(points.size()) != c.definingCount()) {
        // Rows are added and deleted with insertPoint / removePoint; here they are only edited.
        say(Message::FillAllValues);
        return false;
    }
    // Only the rows the user changed are applied, in order; a composite knot that moves carries its
    // handles, which then are not "changed" rows even though their typed values are the old ones.
    std::vector<RowEdit> moves;
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        const geo::Point &p = points[static_cast<std::size_t>(i)];
        if (c.definingPoint(i) != p)
            moves.push_back({i, p.x(), p.y()});
    }
    return moveRows(curve, moves, QCoreApplication::translate("kontur", "Edit coordinates"));
}

bool EditController::moveRows(int curve, const std::vector<RowEdit> &moves, const QString &text)
{
    const auto mode = m_handleMode == HandleMode::Constrained ? geo::HandleMove::Constrained : geo::HandleMove::Free;
    // Knots first: a knot carries its handles (and nothing else moves with a handle), so a handle or
    // tangent end typed in the same OK ends where it was typed, not shifted by its knot's move.
    std::vector<RowEdit> ordered = moves;
    if (curve >= 0 && curve < m_document->curveCount()) {
        const Curve &c = m_document->curve(curve);
        std::stable_partition(ordered.begin(), ordered.end(), [&](const RowEdit &m) {
            return m.row >= 0 && m.row < c.rowCount() && c.row(m.row).role == PointRole::Knot;
        });
    }
    return editCurve(curve, text, [&](Curve &edited) {
        for (const RowEdit &move : ordered) {
            // An axis not given keeps the double the row holds now, after the rows before it moved
            // (a knot carries its handles): never the rounded text the table shows.
            geo::Point position = edited.row(move.row).position;
            if (move.x)
                position.x() = *move.x;
            if (move.y)
                position.y() = *move.y;
            // Composite handles keep the mode's rule, as if dragged there (SPEC.md 1.4).
            const auto moved = edited.move(move.row, position, mode);
            if (!moved.ok())
                return geo::Result<geo::Ok>(moved.error());
        }
        return geo::Result<geo::Ok>(geo::Ok{});
    });
}

bool EditController::applyEdits(int curve, const QVariantList &edits)
{
    if (curve < 0 || curve >= m_document->curveCount())
        return false;
    const Curve &c = m_document->curve(curve);
    std::vector<RowEdit> moves;
    for (const QVariant &item : edits) {
        const QVariantMap edit = item.toMap();
        const int row = edit.value(QStringLiteral("row"), -1).toInt();
        if (row < 0 || row >= c.rowCount())
            return false;
        RowEdit move{row, {}, {}};
        for (const auto &[key, axis] :
             {std::pair{QStringLiteral("x"), &move.x}, std::pair{QStringLiteral("y"), &move.y}}) {
            if (!edit.contains(key))
                continue; // not typed: the stored double stays
            double value = 0.0;
            switch (parseNumber(edit.value(key), value)) {
            case Parsed::Number:
                *axis = value;
                break;
            case Parsed::NotValid:
                say(Message::FillAllValues);
                return false;
            case Parsed::TooLarge:
                say(Message::OutOfRange);
                return false;
            }
        }
        if (!move.x && !move.y)
            continue;
        if (!c.row(row).editable) {
            say(Message::ControlPointsNotMovable, {static_cast<int>(c.kind())});
            return false;
        }
        moves.push_back(move);
    }
    if (moves.empty())
        return true;
    return moveRows(curve, moves, QCoreApplication::translate("kontur", "Edit coordinates"));
}

bool EditController::nudgeSelected(QPointF delta)
{
    const int curve = m_selectedCurve, row = m_selectedPoint;
    if (!m_document->isValidRow(curve, row) || !std::isfinite(delta.x()) || !std::isfinite(delta.y()))
        return false;
    const Curve &c = m_document->curve(curve);
    if (!c.row(row).editable) {
        say(Message::ControlPointsNotMovable, {static_cast<int>(c.kind())});
        return false;
    }
    const geo::Point target = c.row(row).position + toPoint(delta);
    if (!target.allFinite()) {
        say(Message::OutOfRange);
        return false;
    }
    return moveRows(curve, {{row, target.x(), target.y()}}, QCoreApplication::translate("kontur", "Move point"));
}

int EditController::pointIndexOfRow(int curve, int row) const
{
    if (!m_document->isValidRow(curve, row))
        return -1;
    const Curve &c = m_document->curve(curve);
    if (c.kind() == CurveKind::Composite)
        return geo::CompositeCurve::isKnotIndex(row) ? row / 3 : -1;
    return row < c.placedCount() ? row : -1;
}

bool EditController::deleteSelection()
{
    const int curve = m_selectedCurve;
    if (curve < 0)
        return false;
    const int index = pointIndexOfRow(curve, m_selectedPoint);
    if (index >= 0) {
        const Curve &c = m_document->curve(curve);
        const int count = c.placedCount();
        const int minimum = c.isClosed() ? std::max(3, traitsOf(c.kind()).minPoints) : traitsOf(c.kind()).minPoints;
        if (count > minimum)
            return removePoint(curve, index);
    }
    return deleteCurve(curve);
}

bool EditController::addRowAfterSelection()
{
    const int curve = m_selectedCurve;
    if (curve < 0)
        return false;
    const Curve &c = m_document->curve(curve);
    const int count = c.placedCount();
    int after = pointIndexOfRow(curve, m_selectedPoint);
    if (after < 0)
        after = count - 1;
    const auto placed = [&](int i) {
        return c.kind() == CurveKind::Composite ? c.composite().knot(i) : c.definingPoint(i);
    };
    geo::Point position = placed(after);
    if (after + 1 < count)
        position = 0.5 * (placed(after) + placed(after + 1));
    else if (after > 0)
        position = placed(after) + (placed(after) - placed(after - 1));
    else
        position += geo::Point(10, 0);
    if (!insertPoint(curve, after + 1, QPointF(position.x(), position.y())))
        return false;
    const int row = c.kind() == CurveKind::Composite ? 3 * (after + 1) : after + 1;
    setSelection(curve, row);
    return true;
}

bool EditController::deleteSelectedRow()
{
    const int index = pointIndexOfRow(m_selectedCurve, m_selectedPoint);
    if (index < 0)
        return false;
    return removePoint(m_selectedCurve, index);
}

QString EditController::coordinatesText(int curve) const
{
    if (curve < 0 || curve >= m_document->curveCount())
        return {};
    const Curve &c = m_document->curve(curve);
    // Every digit the double has, and no group separators, which spreadsheets would take for the
    // end of the number.
    const auto number = [](double v) { return kontur::exactNumber(v); };
    QString text;
    for (int r = 0; r < c.rowCount(); ++r) {
        const PointRow row = c.row(r);
        text += pointLabel(row.role, row.number) + QLatin1Char('\t') + number(row.position.x()) + QLatin1Char('\t') +
                number(row.position.y()) + QLatin1Char('\n');
    }
    return text;
}

QVariantList EditController::jointReport(int curve, int limit) const
{
    QVariantList list;
    if (curve < 0 || curve >= m_document->curveCount())
        return list;
    const Curve &c = m_document->curve(curve);
    const int segments = c.segmentCount();
    const int joints = c.isClosed() ? segments : segments - 1;
    for (int j = 0; j < joints && j < limit; ++j) {
        const auto report = geo::jointContinuity(c.segment(j), c.segment((j + 1) % segments));
        list << QVariantMap{{QStringLiteral("joint"), j + 1},
                            {QStringLiteral("level"), QString::fromLatin1(geo::nameOf(report.level))},
                            {QStringLiteral("angle"), report.angle * 180.0 / M_PI},
                            {QStringLiteral("c1Jump"), report.c1Jump}};
    }
    return list;
}

int EditController::degreeOf(int curve) const
{
    if (curve < 0 || curve >= m_document->curveCount())
        return -1;
    const Curve &c = m_document->curve(curve);
    return c.segmentCount() > 0 ? c.segment(0).degree() : -1;
}

bool EditController::createFromCoordinates(int kind, const QVariantList &rows)
{
    if (!isKind(kind))
        return false;
    const auto k = static_cast<CurveKind>(kind);
    const KindTraits traits = traitsOf(k);
    std::vector<geo::Point> points;
    if (!parseRows(rows, points))
        return false;
    if (static_cast<int>(points.size()) > traits.maxPoints) {
        say(Message::TooManyPoints, {traits.maxPoints});
        return false;
    }
    if (static_cast<int>(points.size()) < traits.minPoints) {
        say(Message::TooFewPoints, {kind, traits.minPoints});
        return false;
    }
    Curve curve = Curve::make(k, std::move(points), m_parameterization);
    if (curve.problem()) {
        sayError(curve, *curve.problem());
        return false;
    }
    if (!curve.isFinite()) {
        say(Message::OutOfRange);
        return false;
    }
    curve.name = newCurveName(k);
    const int index = m_document->curveCount();
    m_undo.push(CurvePresenceCommand::add(m_document, index, std::move(curve)));
    setSelection(index, -1);
    return true;
}

void EditController::replaceDocument(std::vector<Curve> curves, const Background &background, const QString &units,
                                     bool modified)
{
    cancelPlacement();
    endDrag();
    setSelection(-1, -1);
    m_undo.clear();
    while (m_document->curveCount() > 0)
        (void)m_document->takeCurve(m_document->curveCount() - 1);
    m_createdCount = 0;
    for (Curve &curve : curves) {
        if (curve.name.isEmpty())
            curve.name = newCurveName(curve.kind());
        m_document->insertCurve(m_document->curveCount(), std::move(curve));
    }
    m_document->setBackground(background);
    m_document->setUnits(units);
    m_undo.setClean();
    // A recovered or imported document is saved nowhere yet: not clean, though nothing can be undone.
    if (modified)
        m_undo.resetClean();
    clearMessage();
    Q_EMIT undoStateChanged();
    Q_EMIT documentReplaced();
}

void EditController::addCurves(std::vector<Curve> curves, const QString &text)
{
    if (curves.empty())
        return;
    m_undo.beginMacro(text);
    for (Curve &curve : curves) {
        if (curve.name.isEmpty())
            curve.name = newCurveName(curve.kind());
        m_undo.push(CurvePresenceCommand::add(m_document, m_document->curveCount(), std::move(curve)));
    }
    m_undo.endMacro();
    setSelection(m_document->curveCount() - 1, -1);
    Q_EMIT documentReplaced();
}

void EditController::resetAll()
{
    cancelPlacement();
    endDrag();
    if (m_document->curveCount() == 0 && m_document->background() == Background{})
        return;
    m_undo.beginMacro(QCoreApplication::translate("kontur", "Reset all"));
    for (int c = m_document->curveCount() - 1; c >= 0; --c)
        m_undo.push(CurvePresenceCommand::remove(m_document, c));
    if (!(m_document->background() == Background{}))
        m_undo.push(new BackgroundCommand(m_document, m_document->background(), Background{}));
    m_undo.endMacro();
    clearMessage();
}

void EditController::setBackground(const Background &background)
{
    if (background == m_document->background())
        return;
    m_undo.push(new BackgroundCommand(m_document, m_document->background(), background));
}

bool EditController::loadBackground(const QUrl &file)
{
    const QString path = file.isLocalFile() ? file.toLocalFile() : file.toString();
    QImageReader reader(path);
    // A hostile or broken file must not exhaust memory: Qt refuses images above this many MiB.
    QImageReader::setAllocationLimit(512);
    const QSize size = reader.size();
    if (!QFileInfo(path).isFile() || !reader.canRead() || !size.isValid() || size.isEmpty()) {
        say(Message::FileUploadError, {QFileInfo(path).fileName()});
        return false;
    }
    Background background;
    background.file = QFileInfo(path).absoluteFilePath();
    background.origin = QPointF(-size.width() / 2.0, size.height() / 2.0);
    background.scale = 1.0;
    setBackground(background);
    clearMessage();
    return true;
}

void EditController::clearBackground()
{
    setBackground(Background{});
}

void EditController::setBackgroundVisible(bool visible)
{
    Background background = m_document->background();
    background.visible = visible;
    setBackground(background);
}

void EditController::setBackgroundOpacity(double opacity)
{
    Background background = m_document->background();
    background.opacity = std::clamp(opacity, 0.0, 1.0);
    setBackground(background);
}

void EditController::retranslate()
{
    m_curves->retranslate();
    Q_EMIT textsChanged();
    // The message is translated when shown; re-announce it so bound texts refresh.
    Q_EMIT messageChanged();
}

} // namespace kontur
