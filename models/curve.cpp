// Curve: the kinds' rules for rows, moves and structure, and the derived caches.
#include "models/curve.h"

#include "geometry/arclength.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

namespace {

constexpr double kStale = std::numeric_limits<double>::quiet_NaN();

geo::Error derivedPointError(int row)
{
    return geo::Error{geo::ErrorCode::InvalidArgument,
                      "the control points of this curve follow from its knots and cannot be moved", row};
}

geo::Error wrongKindError(const char *what)
{
    return geo::Error{geo::ErrorCode::InvalidArgument, std::string(what) + " is only possible on a composite curve"};
}

} // namespace

KindTraits traitsOf(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Bezier:
        // Degree up to 100, as far as seed 002's demonstration elevates.
        return {2, 101, 4, false};
    case CurveKind::Interpolating:
        return {4, 4, 4, true};
    case CurveKind::LeastSquares:
        return {4, 1'000'000, 0, true};
    case CurveKind::Composite:
        return {2, 1'000'000, 0, false};
    }
    return {2, 2, 2, false};
}

QString kindName(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Bezier:
        return QCoreApplication::translate("kontur", "Bézier curve");
    case CurveKind::Interpolating:
        return QCoreApplication::translate("kontur", "Cubic through 4 points");
    case CurveKind::LeastSquares:
        return QCoreApplication::translate("kontur", "Least-squares cubic");
    case CurveKind::Composite:
        return QCoreApplication::translate("kontur", "Composite curve");
    }
    return {};
}

const char *kindId(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Bezier:
        return "bezier";
    case CurveKind::Interpolating:
        return "interpolating";
    case CurveKind::LeastSquares:
        return "least-squares";
    case CurveKind::Composite:
        return "composite";
    }
    return "";
}

QString pointLabel(PointRole role, int number)
{
    // The seed labels knot rows P<i> and control point rows C<i>, counting from 0 like c0..c3.
    const QChar prefix = role == PointRole::Knot ? QLatin1Char('P') : QLatin1Char('C');
    return prefix + QString::number(number);
}

Curve Curve::make(CurveKind kind, std::vector<geo::Point> points, geo::Parameterization parameterization)
{
    Curve curve;
    curve.m_kind = kind;
    curve.m_parameterization = parameterization;
    if (kind == CurveKind::Composite)
        curve.m_composite = geo::CompositeCurve(points);
    else
        curve.m_points = std::move(points);
    curve.recompute();
    return curve;
}

geo::Result<Curve> Curve::makeComposite(geo::CompositeCurve composite)
{
    Curve curve;
    curve.m_kind = CurveKind::Composite;
    curve.m_composite = std::move(composite);
    curve.recompute();
    return curve;
}

void Curve::setParameterization(geo::Parameterization p)
{
    if (!traitsOf(m_kind).usesParameterization || p == m_parameterization)
        return;
    m_parameterization = p;
    recompute();
}

bool Curve::isClosed() const
{
    return m_kind == CurveKind::Composite && m_composite.isClosed();
}

int Curve::definingCount() const
{
    if (m_kind != CurveKind::Composite)
        return static_cast<int>(m_points.size());
    // A closed composite curve stores its first knot again at the end; that copy is no row.
    const int n = static_cast<int>(m_composite.controlPoints().size());
    return m_composite.isClosed() ? n - 1 : n;
}

geo::Point Curve::definingPoint(int i) const
{
    const auto &points = m_kind == CurveKind::Composite ? m_composite.controlPoints() : m_points;
    return points[static_cast<std::size_t>(i)];
}

std::vector<geo::Point> Curve::definingPoints() const
{
    if (m_kind != CurveKind::Composite)
        return m_points;
    std::vector<geo::Point> points = m_composite.controlPoints();
    if (m_composite.isClosed() && !points.empty())
        points.pop_back();
    return points;
}

int Curve::rowCount() const
{
    const int defining = definingCount();
    if ((m_kind == CurveKind::Interpolating || m_kind == CurveKind::LeastSquares) && m_fit)
        return defining + 4;
    return defining;
}

PointRow Curve::row(int i) const
{
    PointRow r;
    switch (m_kind) {
    case CurveKind::Bezier:
        r.position = m_points[static_cast<std::size_t>(i)];
        r.role = PointRole::ControlPoint;
        r.number = i;
        return r;
    case CurveKind::Interpolating:
    case CurveKind::LeastSquares: {
        const int n = static_cast<int>(m_points.size());
        if (i < n) {
            r.position = m_points[static_cast<std::size_t>(i)];
            r.role = PointRole::Knot;
            r.number = i;
        } else {
            r.position = m_fit->control[static_cast<std::size_t>(i - n)];
            r.role = PointRole::ControlPoint;
            r.editable = false;
            r.number = i - n;
        }
        return r;
    }
    case CurveKind::Composite:
        r.position = m_composite.controlPoints()[static_cast<std::size_t>(i)];
        if (geo::CompositeCurve::isKnotIndex(i)) {
            r.role = PointRole::Knot;
            r.number = i / 3;
            r.nodeType = m_composite.nodeType(i / 3);
        } else {
            r.role = PointRole::Handle;
            r.number = i;
        }
        return r;
    }
    return r;
}

void Curve::setPoints(const std::vector<PointChange> &changes, bool useAfter)
{
    if (m_kind == CurveKind::Composite) {
        for (const PointChange &c : changes) {
            m_composite.setControlPoint(c.row, useAfter ? c.after : c.before);
            // A control point belongs to the segments around its knot.
            const int knot = m_composite.knotOfControl(c.row);
            touchSegments(knot - 1, 2);
        }
        return;
    }
    for (const PointChange &c : changes)
        if (c.row >= 0 && c.row < static_cast<int>(m_points.size()))
            m_points[static_cast<std::size_t>(c.row)] = useAfter ? c.after : c.before;
    recompute();
}

geo::Result<std::vector<PointChange>> Curve::move(int row, const geo::Point &target, geo::HandleMove mode)
{
    if (row < 0 || row >= rowCount())
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point " + std::to_string(row), row};
    if (!target.allFinite())
        return geo::Error{geo::ErrorCode::NonFiniteInput, "the position is not finite", row};
    if (m_kind != CurveKind::Composite) {
        if (row >= static_cast<int>(m_points.size()))
            return derivedPointError(row);
        PointChange change{row, m_points[static_cast<std::size_t>(row)], target};
        if (change.before == change.after)
            return std::vector<PointChange>{};
        m_points[static_cast<std::size_t>(row)] = target;
        recompute();
        return std::vector<PointChange>{change};
    }

    // Composite: the geometry applies the rule; what changed is found by comparing the few points
    // a move can reach (the point, its knot's handles, the opposite handle, and on a closed curve
    // the points around the first knot, which the last segment shares).
    const auto &control = m_composite.controlPoints();
    const int last = static_cast<int>(control.size()) - 1;
    std::vector<int> window;
    for (int i = row - 2; i <= row + 2; ++i)
        window.push_back(i);
    if (m_composite.isClosed())
        window.insert(window.end(), {0, 1, last - 1});
    std::sort(window.begin(), window.end());
    window.erase(std::unique(window.begin(), window.end()), window.end());
    std::erase_if(window, [&](int i) { return i < 0 || i > last || (m_composite.isClosed() && i == last); });
    std::vector<geo::Point> before;
    before.reserve(window.size());
    for (int i : window)
        before.push_back(control[static_cast<std::size_t>(i)]);

    const auto range = m_composite.moveControlPoint(row, target, mode);
    if (!range.ok())
        return range.error();
    touchSegments(range->first, range->count);

    std::vector<PointChange> changes;
    for (std::size_t k = 0; k < window.size(); ++k) {
        const geo::Point &after = m_composite.controlPoints()[static_cast<std::size_t>(window[k])];
        if (after != before[k])
            changes.push_back({window[k], before[k], after});
    }
    return changes;
}

geo::Result<geo::Ok> Curve::insertPoint(int index, const geo::Point &p)
{
    if (!p.allFinite())
        return geo::Error{geo::ErrorCode::NonFiniteInput, "the position is not finite", index};
    if (m_kind == CurveKind::Composite) {
        // A knot added through the table: the curve is built again from its knots by the seed's
        // rule, as the seed's coordinates window does.
        std::vector<geo::Point> knots = m_composite.knots();
        if (index < 0 || index > static_cast<int>(knots.size()))
            return geo::Error{geo::ErrorCode::IndexOutOfRange, "no knot position " + std::to_string(index), index};
        const bool closed = m_composite.isClosed();
        knots.insert(knots.begin() + index, p);
        m_composite = geo::CompositeCurve(knots);
        if (closed)
            (void)m_composite.close();
        recompute();
        return geo::Ok{};
    }
    if (index < 0 || index > static_cast<int>(m_points.size()))
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point position " + std::to_string(index), index};
    m_points.insert(m_points.begin() + index, p);
    recompute();
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::removePoint(int index)
{
    if (m_kind == CurveKind::Composite) {
        const auto range = m_composite.deleteKnot(index);
        if (!range.ok())
            return range.error();
        recompute();
        return geo::Ok{};
    }
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point " + std::to_string(index), index};
    m_points.erase(m_points.begin() + index);
    recompute();
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::setNodeType(int knot, geo::NodeType type)
{
    if (m_kind != CurveKind::Composite)
        return wrongKindError("a node type");
    const auto range = m_composite.setNodeType(knot, type);
    if (!range.ok())
        return range.error();
    touchSegments(range->first, range->count);
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::insertKnotOnSegment(int segment, double t)
{
    if (m_kind != CurveKind::Composite)
        return wrongKindError("inserting a knot on a segment");
    const auto range = m_composite.insertKnot(segment, t);
    if (!range.ok())
        return range.error();
    recompute();
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::close()
{
    if (m_kind != CurveKind::Composite)
        return wrongKindError("closing");
    const auto range = m_composite.close();
    if (!range.ok())
        return range.error();
    recompute();
    return geo::Ok{};
}

int Curve::segmentCount() const
{
    if (m_kind == CurveKind::Composite)
        return m_composite.segmentCount();
    return m_single ? 1 : 0;
}

geo::Bezier Curve::segment(int i) const
{
    if (m_kind == CurveKind::Composite)
        return m_composite.segment(i);
    return *m_single;
}

double Curve::length(double accuracy) const
{
    if (accuracy != m_lengthAccuracy) {
        std::fill(m_segmentLength.begin(), m_segmentLength.end(), kStale);
        m_lengthAccuracy = accuracy;
    }
    // Each segment gets the whole accuracy budget divided evenly.
    const double each = accuracy / std::max<std::size_t>(1, m_segmentLength.size());
    double total = 0.0;
    for (std::size_t i = 0; i < m_segmentLength.size(); ++i) {
        if (std::isnan(m_segmentLength[i]))
            m_segmentLength[i] = geo::arcLength(segment(static_cast<int>(i)), each);
        total += m_segmentLength[i];
    }
    return total;
}

ContinuitySummary Curve::continuity() const
{
    ContinuitySummary summary;
    const int segments = segmentCount();
    summary.joints = static_cast<int>(m_jointLevel.size());
    for (std::size_t j = 0; j < m_jointLevel.size(); ++j) {
        if (m_jointLevel[j] < 0) {
            const int left = static_cast<int>(j);
            const int right = (left + 1) % segments;
            m_jointLevel[j] = static_cast<signed char>(geo::jointContinuity(segment(left), segment(right)).level);
        }
        summary.weakest = std::min(summary.weakest, static_cast<geo::Continuity>(m_jointLevel[j]));
    }
    return summary;
}

geo::Box Curve::bounds() const
{
    geo::Box box;
    for (int i = 0; i < rowCount(); ++i)
        box.extend(row(i).position);
    return box;
}

geo::PiecewiseBezier Curve::toPiecewise() const
{
    std::vector<geo::Bezier> segments;
    segments.reserve(static_cast<std::size_t>(segmentCount()));
    for (int i = 0; i < segmentCount(); ++i)
        segments.push_back(segment(i));
    return geo::PiecewiseBezier(std::move(segments), isClosed());
}

bool Curve::sameState(const Curve &other) const
{
    return m_kind == other.m_kind && name == other.name && color == other.color && visible == other.visible &&
           locked == other.locked && m_parameterization == other.m_parameterization && m_points == other.m_points &&
           m_composite == other.m_composite;
}

void Curve::recompute()
{
    m_single.reset();
    m_fit.reset();
    m_problem.reset();
    switch (m_kind) {
    case CurveKind::Bezier:
        if (m_points.size() >= 2)
            m_single = geo::Bezier(m_points);
        break;
    case CurveKind::Interpolating:
    case CurveKind::LeastSquares: {
        geo::FitOptions options;
        options.alpha = geo::exponentOf(m_parameterization);
        // Knots dragged onto each other are a normal moment of editing: allowed where the fit can
        // still be made (at least 4 distinct parameters).
        options.allowCoincidentPoints = true;
        auto fit = geo::fitCubic(m_points, options);
        if (fit.ok()) {
            m_single = fit->curve();
            m_fit = std::move(fit.value());
        } else {
            m_problem = fit.error();
        }
        break;
    }
    case CurveKind::Composite:
        break;
    }
    resizeCaches();
}

void Curve::resizeCaches()
{
    const int segments = segmentCount();
    m_segmentLength.assign(static_cast<std::size_t>(segments), kStale);
    const int joints = isClosed() ? segments : std::max(0, segments - 1);
    m_jointLevel.assign(static_cast<std::size_t>(joints), -1);
}

void Curve::touchSegments(int first, int count)
{
    const int segments = static_cast<int>(m_segmentLength.size());
    if (segments == 0)
        return;
    const int joints = static_cast<int>(m_jointLevel.size());
    const bool closed = isClosed();
    for (int k = 0; k < count; ++k) {
        int s = first + k;
        if (closed)
            s = ((s % segments) + segments) % segments;
        if (s < 0 || s >= segments)
            continue;
        m_segmentLength[static_cast<std::size_t>(s)] = kStale;
        // Joint j joins segment j to segment j + 1: a segment touches joints s - 1 and s.
        for (int j : {s - 1, s}) {
            if (closed)
                j = ((j % joints) + joints) % joints;
            if (j >= 0 && j < joints)
                m_jointLevel[static_cast<std::size_t>(j)] = -1;
        }
    }
}

} // namespace kontur
