// EditController: placing, picking and dragging points, with undo.
#include "models/editcontroller.h"

#include "models/commands.h"
#include "models/curvelistmodel.h"
#include "models/document.h"
#include "models/pointlistmodel.h"

#include <cmath>
#include <limits>

namespace kontur {

namespace {
geo::Point toPoint(QPointF p)
{
    return {p.x(), p.y()};
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
    connect(this, &EditController::pendingChanged, this, &EditController::undoStateChanged);
    // Undo may remove the selected curve: keep the selection pointing at real rows.
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
}

EditController::~EditController()
{
    // The stack's commands point at the document: drop them before the document goes.
    m_undo.clear();
}

void EditController::setMode(Mode mode)
{
    if (mode == m_mode)
        return;
    m_mode = mode;
    if (!m_pending.empty()) {
        m_pending.clear();
        Q_EMIT pendingChanged();
    }
    Q_EMIT modeChanged();
}

void EditController::selectCurve(int curve)
{
    if (curve < -1 || curve >= m_document->curveCount())
        curve = -1;
    setSelection(curve, curve == m_selectedCurve ? m_selectedPoint : -1);
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

PointRef EditController::hitTest(const geo::Point &world, double radius) const
{
    // A scan is fine for the documents of the skeleton; the models issue brings a spatial index.
    PointRef best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto &curves = m_document->curves();
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const auto &points = curves[c].points;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d = (points[i] - world).norm();
            // Ties go to the later curve: it is drawn on top.
            if (d <= radius && d <= bestDistance) {
                bestDistance = d;
                best = {static_cast<int>(c), static_cast<int>(i)};
            }
        }
    }
    return best;
}

void EditController::tap(QPointF world, double hitRadius)
{
    const geo::Point p = toPoint(world);
    if (!p.allFinite())
        return;
    switch (m_mode) {
    case Mode::PlaceBezier:
        m_pending.push_back(p);
        Q_EMIT pendingChanged();
        if (pendingCount() == requiredPoints())
            finishPlacement();
        return;
    case Mode::Select: {
        const PointRef hit = hitTest(p, hitRadius);
        setSelection(hit.curve, hit.point);
        return;
    }
    }
}

void EditController::finishPlacement()
{
    Curve curve;
    curve.kind = CurveKind::Bezier;
    curve.name = QCoreApplication::translate("kontur", "Bézier %1").arg(++m_createdCount);
    curve.points = std::move(m_pending);
    m_pending.clear();
    const int index = m_document->curveCount();
    m_undo.push(new AddCurveCommand(m_document, index, std::move(curve)));
    Q_EMIT pendingChanged();
    setSelection(index, -1);
}

bool EditController::beginDrag(QPointF world, double hitRadius)
{
    const geo::Point p = toPoint(world);
    const PointRef hit = p.allFinite() ? hitTest(p, hitRadius) : PointRef{};
    if (!hit.isValid())
        return false;
    m_drag = hit;
    m_dragStart = m_document->curve(hit.curve).points[static_cast<std::size_t>(hit.point)];
    m_grabOffset = m_dragStart - p;
    ++m_dragSerial;
    setSelection(hit.curve, hit.point);
    Q_EMIT draggingChanged();
    return true;
}

void EditController::dragTo(QPointF world)
{
    const geo::Point p = toPoint(world);
    if (!m_drag.isValid() || !p.allFinite() || !m_document->isValidPoint(m_drag.curve, m_drag.point))
        return;
    const geo::Point target = p + m_grabOffset;
    const geo::Point current = m_document->curve(m_drag.curve).points[static_cast<std::size_t>(m_drag.point)];
    if (target == current)
        return;
    m_undo.push(new MovePointCommand(m_document, m_drag.curve, m_drag.point, current, target, m_dragSerial));
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

void EditController::undo()
{
    if (!m_pending.empty()) {
        // While placing, undo takes back the last placed point first.
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

void EditController::retranslate()
{
    m_curves->retranslate();
}

} // namespace kontur
