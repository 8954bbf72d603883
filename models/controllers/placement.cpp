// Placement: the points of a new curve, its preview, and the command that adds it.
#include "models/controllers/placement.h"

#include "geometry/composite.h"
#include "models/controllers/editcontroller.h"
#include "models/text/numbers.h"

#include <algorithm>

namespace kontur {

Placement::Placement(EditController *editor)
    : QObject(editor)
    , m_editor(editor)
{
}

void Placement::setKind(int kind)
{
    if (kind < 0 || kind >= kKindCount || kind == static_cast<int>(m_kind))
        return;
    m_kind = static_cast<CurveKind>(kind);
    cancel();
    Q_EMIT settingsChanged();
}

void Placement::setDegree(int degree)
{
    degree = std::clamp(degree, 1, traitsOf(CurveKind::Bezier).maxPoints - 1);
    if (degree == m_degree)
        return;
    m_degree = degree;
    Q_EMIT settingsChanged();
}

void Placement::setParameterization(int parameterization)
{
    if (parameterization < static_cast<int>(geo::Parameterization::Uniform) ||
        parameterization > static_cast<int>(geo::Parameterization::Centripetal) ||
        parameterization == static_cast<int>(m_parameterization))
        return;
    m_parameterization = static_cast<geo::Parameterization>(parameterization);
    Q_EMIT settingsChanged();
}

QVariantList Placement::kinds() const
{
    QVariantList list;
    for (int k = 0; k < kKindCount; ++k)
        list << QVariantMap{
            {QStringLiteral("kind"), k},
            {QStringLiteral("name"), kindName(static_cast<CurveKind>(k))},
            {QStringLiteral("icon"), kindIconName(static_cast<CurveKind>(k))},
            {QStringLiteral("usesParameterization"), traitsOf(static_cast<CurveKind>(k)).usesParameterization}};
    return list;
}

int Placement::requiredPoints() const
{
    if (m_kind == CurveKind::Bezier)
        return m_degree + 1;
    return traitsOf(m_kind).placementCount;
}

std::vector<geo::Bezier> Placement::pendingSegments() const
{
    std::vector<geo::Bezier> segments = previewSegments();
    // The canvas never receives a point that is not finite (knots near the largest double).
    std::erase_if(segments, [](const geo::Bezier &segment) {
        return !std::all_of(segment.controlPoints().begin(), segment.controlPoints().end(),
                            [](const geo::Point &p) { return p.allFinite(); });
    });
    return segments;
}

std::vector<geo::Bezier> Placement::previewSegments() const
{
    std::vector<geo::Bezier> segments;
    if (m_kind == CurveKind::Composite) {
        // Segments appear from the 3rd knot on; the last one waits for "Done" (seed T15, T16).
        if (m_pending.size() >= 3) {
            const geo::CompositeCurve building(m_pending);
            for (int i = 0; i + 1 < building.segmentCount(); ++i)
                segments.push_back(building.segment(i));
        }
    } else if (traitsOf(m_kind).placementCount == 0 && pendingCount() >= traitsOf(m_kind).minPoints) {
        // The open-ended kinds show what "Done" would make, once there are enough points; the others
        // (Bézier, the cubic through 4 points) appear when their last point is placed.
        const Curve preview = Curve::make(m_kind, m_pending, m_parameterization);
        for (int i = 0; i < preview.segmentCount(); ++i)
            segments.push_back(preview.segment(i));
    }
    return segments;
}

void Placement::place(const geo::Point &point)
{
    if (!point.allFinite())
        return;
    if (pendingCount() >= traitsOf(m_kind).maxPoints) {
        m_editor->showMessage(Message::TooManyPoints, {traitsOf(m_kind).maxPoints});
        return;
    }
    m_editor->clearMessage();
    m_pending.push_back(point);
    Q_EMIT pendingChanged();
    if (requiredPoints() > 0 && pendingCount() == requiredPoints())
        finish();
}

bool Placement::finish()
{
    if (m_editor->mode() != EditController::Mode::Place || m_pending.empty())
        return false;
    const KindTraits traits = traitsOf(m_kind);
    if (pendingCount() < traits.minPoints) {
        m_editor->showMessage(Message::TooFewPoints, {static_cast<int>(m_kind), traits.minPoints});
        return false;
    }
    Curve curve = Curve::make(m_kind, std::move(m_pending), m_parameterization);
    m_pending.clear();
    Q_EMIT pendingChanged();
    if (!add(std::move(curve)))
        return false;
    m_editor->clearMessage();
    // The curve is made: the drawing tool is left, so that the next tap selects or moves points instead
    // of starting a curve nobody asked for. The new curve stays selected.
    m_editor->setMode(EditController::Mode::Select);
    return true;
}

bool Placement::add(Curve curve)
{
    if (curve.problem()) {
        // The knots define no curve (e.g. all at one place): keep nothing, say why.
        m_editor->sayError(curve, *curve.problem());
        return false;
    }
    if (!curve.isFinite()) {
        m_editor->showMessage(Message::OutOfRange);
        return false;
    }
    curve.name = m_editor->newCurveName(curve.kind());
    m_editor->commands()->appendCurve(std::move(curve));
    return true;
}

void Placement::cancel()
{
    if (m_pending.empty())
        return;
    m_pending.clear();
    Q_EMIT pendingChanged();
}

void Placement::removeLast()
{
    if (m_pending.empty())
        return;
    m_pending.pop_back();
    Q_EMIT pendingChanged();
}

void Placement::hover(QPointF world)
{
    const geo::Point p(world.x(), world.y());
    if (!p.allFinite() || (m_hasHover && p == m_hover))
        return;
    m_hover = p;
    m_hasHover = true;
    Q_EMIT hoverChanged();
}

void Placement::clearHover()
{
    if (!m_hasHover)
        return;
    m_hasHover = false;
    Q_EMIT hoverChanged();
}

bool Placement::createFromCoordinates(int kind, const QVariantList &rows)
{
    if (kind < 0 || kind >= kKindCount)
        return false;
    const auto k = static_cast<CurveKind>(kind);
    const KindTraits traits = traitsOf(k);
    std::vector<geo::Point> points;
    if (!m_editor->accepted(parsePoints(rows, points)))
        return false;
    if (static_cast<int>(points.size()) > traits.maxPoints) {
        m_editor->showMessage(Message::TooManyPoints, {traits.maxPoints});
        return false;
    }
    if (static_cast<int>(points.size()) < traits.minPoints) {
        m_editor->showMessage(Message::TooFewPoints, {kind, traits.minPoints});
        return false;
    }
    return add(Curve::make(k, std::move(points), m_parameterization));
}

} // namespace kontur
