// EditController: owns the document and its undo stack, routes gestures, says why edits are refused.
#include "models/controllers/editcontroller.h"

#include "geometry/nearest.h"
#include "models/document/commands.h"
#include "models/text/languagewatch.h"

namespace kontur {

EditController::EditController(QObject *parent)
    : QObject(parent)
    , m_document(new Document(this))
    , m_curves(new CurveListModel(m_document, this))
    , m_points(new PointListModel(m_document, this))
    , m_selection(new Selection(m_document, this))
    , m_selectedCurve(new SelectedCurveModel(m_curves, m_document, this))
    , m_placement(new Placement(this))
    , m_commands(new CurveCommands(this))
    , m_background(new BackgroundController(this))
{
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &EditController::undoStateChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &EditController::undoStateChanged);
    connect(&m_undo, &QUndoStack::cleanChanged, this, &EditController::undoStateChanged);
    connect(m_placement, &Placement::pendingChanged, this, &EditController::undoStateChanged);
    connect(m_background, &BackgroundController::report, this, [this](const Message &message) {
        if (message.isEmpty())
            clearMessage();
        else
            showMessage(message.id, message.args);
    });
    // Translated texts follow a language switch (QEvent::LanguageChange from installTranslator).
    new LanguageWatch(this, [this] { retranslate(); });

    // The hit-test index follows point moves in place and rebuilds after anything structural.
    connect(m_document, &Document::rowsChanged, this,
            [this](int curve, int first, int last) { m_index.update(*m_document, curve, first, last); });
    for (auto signal : {&Document::curveInserted, &Document::curveRemoved, &Document::curveChanged})
        connect(m_document, signal, this, [this](int) { m_index.invalidate(); });
    connect(m_document, &Document::curveMoved, this, [this](int, int) { m_index.invalidate(); });

    // The models show the selection; a drag ends when its curve goes (undo of its creation).
    connect(m_selection, &Selection::curveChanged, this, [this] {
        m_curves->setSelected(m_selection->curveId());
        m_points->setCurve(m_selection->curveId());
        m_selectedCurve->setCurve(m_selection->curveId());
    });
    connect(m_document, &Document::curveRemoved, this, [this](int) {
        if (m_drag.isValid() && !m_document->contains(m_drag.curve))
            endDrag();
    });
}

EditController::~EditController()
{
    // The stack's commands point at the document: drop them before the document goes.
    m_undo.clear();
}

// --- undo -------------------------------------------------------------------------------------

void EditController::push(QUndoCommand *command)
{
    m_undo.push(command);
}

void EditController::undo()
{
    if (m_placement->pendingCount() > 0) {
        m_placement->removeLast();
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

void EditController::replaceDocument(std::vector<Curve> curves, const Background &background, const QString &units,
                                     bool modified)
{
    // Not a command: opening a file starts a new history.
    m_placement->cancel();
    endDrag();
    m_selection->clear();
    m_undo.clear();
    const Document::EditKey key;
    while (m_document->curveCount() > 0)
        (void)m_document->takeCurve(key, m_document->curveCount() - 1);
    m_createdCount = 0;
    for (Curve &curve : curves) {
        if (curve.name.isEmpty()) {
            curve.name = newCurveName(curve.kind());
            curve.nameGenerated = true;
        }
        m_document->insertCurve(key, m_document->curveCount(), std::move(curve));
    }
    const std::vector<int> unusable = m_document->resolveSeamLinks(key, 0);
    m_document->setBackground(key, background);
    m_document->setUnits(key, units);
    m_undo.setClean();
    // A recovered or imported document is saved nowhere yet: not clean, though nothing can be undone.
    if (modified)
        m_undo.resetClean();
    clearMessage();
    // Settings that give no allowance (saved by hand, or by another version) are said, not computed on.
    if (!unusable.empty()) {
        const Curve &first = m_document->curve(unusable.front());
        showMessage(Message::SeamAllowanceKept, {first.name, first.seam->options.distance});
    }
    Q_EMIT undoStateChanged();
    Q_EMIT documentReplaced();
}

// --- modes ------------------------------------------------------------------------------------

void EditController::setMode(Mode mode)
{
    if (mode == m_mode)
        return;
    m_mode = mode;
    clearMessage();
    m_placement->cancel();
    Q_EMIT modeChanged();
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
    m_placement->setKind(kind);
    setMode(Mode::Place);
    m_placement->cancel();
}

// --- messages ---------------------------------------------------------------------------------

void EditController::showMessage(Message::Id id, QVariantList args)
{
    m_message.show(Message{id, std::move(args)});
}

void EditController::clearMessage()
{
    m_message.clear();
}

void EditController::sayError(const Curve &curve, const geo::Error &error)
{
    const int kind = static_cast<int>(curve.kind());
    if (curve.seam && error.code == geo::ErrorCode::InvalidArgument) {
        showMessage(Message::SeamAllowanceFollows);
        return;
    }
    switch (error.code) {
    case geo::ErrorCode::TooFewPoints:
        showMessage(Message::TooFewPoints, {kind, traitsOf(curve.kind()).minPoints});
        return;
    case geo::ErrorCode::AllPointsEqual:
    case geo::ErrorCode::CoincidentPoints:
    case geo::ErrorCode::TooFewDistinctParameters:
    case geo::ErrorCode::IllConditioned:
        showMessage(Message::FitFailed, {kind});
        return;
    case geo::ErrorCode::NonFiniteInput:
        // Every number reaching the geometry from here is finite (typed ones are parsed, gestures
        // checked): a result that is not went past the largest double.
        showMessage(Message::OutOfRange);
        return;
    case geo::ErrorCode::IndexOutOfRange:
    case geo::ErrorCode::InvalidArgument:
    case geo::ErrorCode::OutOfProportion:
    case geo::ErrorCode::WorkBudget:
    case geo::ErrorCode::Cancelled: // edits are not cancelled from another thread; listed for the switch
        showMessage(Message::NotPossibleForKind, {kind});
        return;
    }
}

bool EditController::accepted(Parsed parsed)
{
    switch (parsed) {
    case Parsed::Number:
        return true;
    case Parsed::NotValid:
        showMessage(Message::FillAllValues);
        return false;
    case Parsed::TooLarge:
        showMessage(Message::OutOfRange);
        return false;
    }
    return false;
}

QString EditController::newCurveName(CurveKind kind)
{
    return kontur::newCurveName(kind, ++m_createdCount);
}

// --- hit testing --------------------------------------------------------------------------------

PointRef EditController::hitTest(const geo::Point &world, double radius)
{
    // Only what is drawn can be grabbed: a composite curve's handles away from the selected knot are not.
    const int selectedCurve = m_selection->curveRow();
    const int selectedPoint = m_selection->point();
    const PointHit hit = m_index.nearest(*m_document, world, radius, [&](int curve, int row) {
        return m_document->curve(curve).isRowShown(row, curve == selectedCurve ? selectedPoint : -1);
    });
    return hit.isValid() ? PointRef{m_document->idAt(hit.curve), hit.row} : PointRef{};
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
                best = {curve.id(), s, nearest.t, nearest.distance};
        }
    }
    return best;
}

// --- gestures -------------------------------------------------------------------------------

void EditController::tap(QPointF world, double hitRadius)
{
    const geo::Point p(world.x(), world.y());
    if (!p.allFinite())
        return;
    switch (m_mode) {
    case Mode::Place:
        m_placement->place(p);
        return;
    case Mode::Select: {
        const PointRef hit = hitTest(p, hitRadius);
        if (hit.isValid()) {
            m_selection->select(hit.curve, hit.point);
            return;
        }
        m_selection->select(curveAt(p, hitRadius).curve);
        return;
    }
    }
}

bool EditController::beginDrag(QPointF world, double hitRadius, bool constrained)
{
    const geo::Point p(world.x(), world.y());
    const PointRef hit = p.allFinite() ? hitTest(p, hitRadius) : PointRef{};
    if (!hit.isValid())
        return false;
    m_selection->select(hit.curve, hit.point);
    const Curve &curve = *m_document->find(hit.curve);
    if (curve.locked) {
        showMessage(Message::CurveLocked, {curve.name});
        return true; // taken (nothing under it should pan), but nothing moves
    }
    if (!curve.row(hit.point).editable) {
        showMessage(Message::ControlPointsNotMovable, {static_cast<int>(curve.kind())});
        return true;
    }
    clearMessage();
    m_drag = hit;
    m_dragMode = constrained ? geo::HandleMove::Constrained : handleMoveMode();
    m_grabOffset = curve.row(hit.point).position - p;
    ++m_dragSerial;
    // Until the release, the curve's seam allowances follow on a worker thread (Document::beginLiveEdit).
    m_document->beginLiveEdit(Document::EditKey{});
    Q_EMIT draggingChanged();
    return true;
}

void EditController::dragTo(QPointF world)
{
    const geo::Point p(world.x(), world.y());
    const Curve *curve = m_drag.isValid() ? m_document->find(m_drag.curve) : nullptr;
    if (!curve || !p.allFinite() || m_drag.point >= curve->rowCount())
        return;
    const geo::Point target = p + m_grabOffset;
    if (!target.allFinite()) {
        showMessage(Message::OutOfRange);
        return;
    }
    // The command makes the move in its first redo (inside push); until then the document is as it was.
    std::optional<geo::Error> failure;
    // A move changes the curve in place (the document's curves stay where they are): `curve` still points at it.
    push(new MovePointCommand(m_document, {m_drag.curve, m_drag.point, target, m_dragMode}, m_dragSerial, &failure));
    if (failure)
        sayError(*curve, *failure);
    else if (curve->problem())
        sayError(*curve, *curve->problem());
    else if (m_message.message().id == Message::FitFailed)
        clearMessage();
}

void EditController::endDrag()
{
    if (!m_drag.isValid())
        return;
    m_drag = {};
    m_document->endLiveEdit(Document::EditKey{});
    Q_EMIT draggingChanged();
}

void EditController::retranslate()
{
    m_curves->retranslate();
    m_points->retranslate();
    m_placement->retranslate();
    Q_EMIT textsChanged();
}

} // namespace kontur
