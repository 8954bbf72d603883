// Curve: the kinds' rules for rows, moves and structure, and the derived caches.
// Over 600 lines because every kind's row layout, moves and structural edits are the one place those
// rules live (docs/architecture.md: each rule in one place); the shapes themselves are built in geometry/curveshape.
#include "models/document/curve.h"

#include "geometry/arclength.h"
#include "geometry/seams.h"
#include "geometry/splines/bspline.h"
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/knots.h"
#include "geometry/splines/polynomial.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>

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
    return geo::Error{geo::ErrorCode::InvalidArgument, std::string(what) + " is not possible for this kind of curve"};
}

bool isFitted(CurveKind kind)
{
    return geo::isFittedKind(kind);
}

using geo::hasEndTangents;

} // namespace

QString pointLabel(PointRole role, int number)
{
    // The seed labels knot rows P<i> and control point rows C<i>, counting from 0 like c0..c3;
    // tangent ends are T<i>.
    QChar prefix = QLatin1Char('C');
    if (role == PointRole::Knot)
        prefix = QLatin1Char('P');
    else if (role == PointRole::TangentEnd)
        prefix = QLatin1Char('T');
    return prefix + QString::number(number);
}

Curve Curve::make(CurveKind kind, std::vector<geo::Point> points, geo::Parameterization parameterization)
{
    Curve curve;
    curve.m_kind = kind;
    // Kinds without a parameterization keep the default, so that equal curves compare equal.
    curve.m_parameterization = traitsOf(kind).usesParameterization ? parameterization : geo::Parameterization::Uniform;
    if (kind == CurveKind::Composite) {
        curve.m_composite = geo::CompositeCurve(points);
    } else {
        curve.m_points = std::move(points);
        curve.m_order = geo::defaultOrder(curve.m_points.size());
        curve.initTangentEnds();
    }
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

geo::Result<Curve> Curve::makeOffset(const geo::PiecewiseBezier &source, const geo::OffsetOptions &options,
                                     geo::OffsetControl *control)
{
    auto offset = geo::offsetCurve(source, options, control);
    if (!offset)
        return offset.error();
    auto composite = geo::compositeFromPieces(offset->curve.segments(), offset->curve.isClosed());
    if (!composite)
        return composite.error();
    return makeComposite(std::move(composite).value());
}

geo::Result<Curve> Curve::restore(CurveKind kind, std::vector<geo::Point> points, std::vector<geo::Point> tangentEnds,
                                  int order, geo::Parameterization parameterization)
{
    if (kind == CurveKind::Composite)
        return geo::Error{geo::ErrorCode::InvalidArgument, "composite curves are restored from their control vector"};
    Curve curve = make(kind, std::move(points), parameterization);
    if (!tangentEnds.empty()) {
        if (tangentEnds.size() != curve.m_tangentEnds.size())
            return geo::Error{geo::ErrorCode::InvalidArgument,
                              "this kind of curve has " + std::to_string(curve.m_tangentEnds.size()) +
                                  " tangent ends, not " + std::to_string(tangentEnds.size())};
        for (const geo::Point &p : tangentEnds)
            if (!p.allFinite())
                return geo::Error{geo::ErrorCode::NonFiniteInput, "a tangent end is not finite"};
        curve.m_tangentEnds = std::move(tangentEnds);
    }
    if (traitsOf(kind).takesOrder && order > 0) {
        const auto set = curve.setOrder(order);
        if (!set.ok())
            return set.error();
    }
    curve.recompute();
    return curve;
}

void Curve::initTangentEnds()
{
    m_tangentEnds = geo::defaultTangentEnds(m_kind, m_points, m_parameterization);
}

void Curve::setParameterization(geo::Parameterization p)
{
    if (!traitsOf(m_kind).usesParameterization || p == m_parameterization)
        return;
    m_parameterization = p;
    recompute();
}

geo::Result<geo::Ok> Curve::setOrder(int order)
{
    if (!traitsOf(m_kind).takesOrder)
        return wrongKindError("an order");
    if (order < 2 || order > 10 || order > knotCount())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the order must lie between 2 and the number of control "
                                                           "points (at most 10)"};
    m_order = order;
    recompute();
    return geo::Ok{};
}

bool Curve::isClosed() const
{
    return (m_kind == CurveKind::Composite && m_composite.isClosed()) || traitsOf(m_kind).closed;
}

int Curve::definingCount() const
{
    if (m_kind != CurveKind::Composite)
        return knotCount() + static_cast<int>(m_tangentEnds.size());
    // A closed composite curve stores its first knot again at the end; that copy is no row.
    const int n = static_cast<int>(m_composite.controlPoints().size());
    return m_composite.isClosed() ? n - 1 : n;
}

geo::Point Curve::definingPoint(int i) const
{
    if (m_kind == CurveKind::Composite)
        return m_composite.controlPoints()[static_cast<std::size_t>(i)];
    if (i < knotCount())
        return m_points[static_cast<std::size_t>(i)];
    return m_tangentEnds[static_cast<std::size_t>(i - knotCount())];
}

std::vector<geo::Point> Curve::definingPoints() const
{
    if (m_kind != CurveKind::Composite) {
        std::vector<geo::Point> points = m_points;
        points.insert(points.end(), m_tangentEnds.begin(), m_tangentEnds.end());
        return points;
    }
    std::vector<geo::Point> points = m_composite.controlPoints();
    if (m_composite.isClosed() && !points.empty())
        points.pop_back();
    return points;
}

int Curve::rowCount() const
{
    const int defining = definingCount();
    if (isFitted(m_kind) && m_shape.fit)
        return defining + 4;
    return defining;
}

int Curve::minimumPoints() const
{
    const int minimum = traitsOf(m_kind).minPoints;
    return isClosed() ? std::max(3, minimum) : minimum;
}

void Curve::copyStyleFrom(const Curve &other)
{
    name = other.name;
    color = other.color;
    visible = other.visible;
    locked = other.locked;
}

int Curve::knotOfRow(int row) const
{
    if (row < 0 || row >= definingCount())
        return -1;
    if (m_kind == CurveKind::Composite)
        return m_composite.knotOfControl(row);
    return row < placedCount() ? row : -1;
}

int Curve::rowOfKnot(int knot) const
{
    if (knot < 0 || knot >= placedCount())
        return -1;
    return m_kind == CurveKind::Composite ? 3 * knot : knot;
}

bool Curve::isRowShown(int row, int selectedRow) const
{
    if (row < 0 || row >= rowCount())
        return false;
    if (m_kind != CurveKind::Composite || isKnotRow(row))
        return true;
    const int knot = knotOfRow(row);
    const int selectedKnot = knotOfRow(selectedRow);
    if (knot < 0 || selectedKnot < 0)
        return false;
    int apart = std::abs(knot - selectedKnot);
    if (isClosed()) // the last knot's neighbour is the first
        apart = std::min(apart, m_composite.knotCount() - apart);
    return apart <= 1;
}

PointRow Curve::row(int i) const
{
    PointRow r;
    if (m_kind == CurveKind::Composite) {
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
    const int n = knotCount();
    if (i < n) {
        r.position = m_points[static_cast<std::size_t>(i)];
        // Bézier, B-spline and contour points control the curve; the others are knots.
        r.role = traitsOf(m_kind).controlPolygon ? PointRole::ControlPoint : PointRole::Knot;
        r.number = i;
        return r;
    }
    const int tangents = static_cast<int>(m_tangentEnds.size());
    if (i < n + tangents) {
        r.position = m_tangentEnds[static_cast<std::size_t>(i - n)];
        r.role = PointRole::TangentEnd;
        // The knot the tangent belongs to.
        r.number = hasEndTangents(m_kind) ? (i == n ? 0 : n - 1) : i - n;
        return r;
    }
    r.position = m_shape.fit->control[static_cast<std::size_t>(i - n)];
    r.role = PointRole::ControlPoint;
    r.editable = false;
    r.number = i - n;
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
    const int n = knotCount();
    for (const PointChange &c : changes) {
        const geo::Point &p = useAfter ? c.after : c.before;
        if (c.row >= 0 && c.row < n)
            m_points[static_cast<std::size_t>(c.row)] = p;
        else if (c.row >= n && c.row < n + static_cast<int>(m_tangentEnds.size()))
            m_tangentEnds[static_cast<std::size_t>(c.row - n)] = p;
    }
    recompute();
}

geo::Result<std::vector<PointChange>> Curve::move(int row, const geo::Point &target, geo::HandleMove mode)
{
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
    if (row < 0 || row >= rowCount())
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point " + std::to_string(row), row};
    if (!target.allFinite())
        return geo::Error{geo::ErrorCode::NonFiniteInput, "the position is not finite", row};
    if (m_kind != CurveKind::Composite) {
        if (row >= definingCount())
            return derivedPointError(row);
        std::vector<PointChange> changes;
        const geo::Point before = definingPoint(row);
        if (before == target)
            return changes;
        changes.push_back({row, before, target});
        // A knot carries its tangent end with it: the tangent stays what it was.
        const int n = knotCount();
        int tangentRow = -1;
        if (geo::hasKnotTangents(m_kind) && row < n)
            tangentRow = n + row;
        else if (hasEndTangents(m_kind) && row == 0)
            tangentRow = n;
        else if (hasEndTangents(m_kind) && row == n - 1)
            tangentRow = n + 1;
        if (tangentRow >= 0) {
            const geo::Point end = definingPoint(tangentRow);
            changes.push_back({tangentRow, end, end + (target - before)});
        }
        setPoints(changes, true);
        return changes;
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
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
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
        geo::CompositeCurve rebuilt(knots);
        // Closing merges a last knot that equals the first: such a knot would add no row.
        if (closed && (!rebuilt.close().ok() || rebuilt.knotCount() != static_cast<int>(knots.size())))
            return geo::Error{geo::ErrorCode::CoincidentPoints, "the new knot lies on the first knot", index};
        m_composite = std::move(rebuilt);
        recompute();
        return geo::Ok{};
    }
    const int n = knotCount();
    if (index < 0 || index > n)
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point position " + std::to_string(index), index};
    // End tangents stay with the end knots: keep their offsets.
    geo::Point startOffset = geo::Point::Zero(), endOffset = geo::Point::Zero();
    if (hasEndTangents(m_kind) && n >= 2) {
        startOffset = m_tangentEnds[0] - m_points.front();
        endOffset = m_tangentEnds[1] - m_points.back();
    }
    m_points.insert(m_points.begin() + index, p);
    if (hasEndTangents(m_kind) && !m_tangentEnds.empty()) {
        m_tangentEnds = {m_points.front() + startOffset, m_points.back() + endOffset};
    } else if (geo::hasKnotTangents(m_kind)) {
        // A new knot's tangent points from its neighbour before to its neighbour after.
        const geo::Point prev = m_points[static_cast<std::size_t>(std::max(index - 1, 0))];
        const geo::Point next = m_points[static_cast<std::size_t>(std::min(index + 1, n))];
        geo::Point direction = (next - prev) / 6.0;
        if (!(direction.squaredNorm() > 0.0))
            direction = geo::Point(1, 0);
        m_tangentEnds.insert(m_tangentEnds.begin() + index, p + direction);
    }
    recompute();
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::removePoint(int index)
{
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
    if (m_kind == CurveKind::Composite) {
        const auto range = m_composite.deleteKnot(index);
        if (!range.ok())
            return range.error();
        recompute();
        return geo::Ok{};
    }
    const int n = knotCount();
    if (index < 0 || index >= n)
        return geo::Error{geo::ErrorCode::IndexOutOfRange, "no point " + std::to_string(index), index};
    geo::Point startOffset = geo::Point::Zero(), endOffset = geo::Point::Zero();
    if (hasEndTangents(m_kind) && n >= 2) {
        startOffset = m_tangentEnds[0] - m_points.front();
        endOffset = m_tangentEnds[1] - m_points.back();
    }
    m_points.erase(m_points.begin() + index);
    if (hasEndTangents(m_kind) && !m_tangentEnds.empty() && !m_points.empty())
        m_tangentEnds = {m_points.front() + startOffset, m_points.back() + endOffset};
    else if (geo::hasKnotTangents(m_kind))
        m_tangentEnds.erase(m_tangentEnds.begin() + index);
    if (traitsOf(m_kind).takesOrder)
        m_order = std::min(m_order, std::max(2, knotCount()));
    recompute();
    return geo::Ok{};
}

geo::Result<geo::Ok> Curve::setNodeType(int knot, geo::NodeType type)
{
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
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
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
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
    if (seam)
        return geo::Error{geo::ErrorCode::InvalidArgument, "a seam allowance follows its curve"};
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
    return m_shape.segmentCount();
}

geo::Bezier Curve::segment(int i) const
{
    if (m_kind == CurveKind::Composite)
        return m_composite.segment(i);
    return m_shape.segment(i);
}

double Curve::length(double accuracy) const
{
    // Every segment is asked the same relative accuracy r: an error of at most r times the length
    // of its control polygon (which bounds its arc length), so the errors add up to at most r times
    // the curve's size and no segment is asked more than doubles resolve for its size. An accuracy
    // that is not positive asks r = 1e-9 (the curve list; as geo::arcLength's own default); a
    // positive one is absolute, turned into r by the curve's size. r is never below kFinest: the
    // quadrature's error estimate is itself rounded to a few ulps of the value, so a relative
    // accuracy near 1e-16 is never met and the refinement halves to its depth limit (2^50
    // evaluations: the freeze of issue #17 with coordinates around 1e7 and an absolute 1e-9).
    constexpr double kDefault = 1e-9;
    constexpr double kFinest = 1e-13;
    const auto polygonLength = [](const geo::Bezier &b) {
        double sum = 0.0;
        const auto &p = b.controlPoints();
        for (std::size_t i = 1; i < p.size(); ++i)
            sum += std::hypot(p[i].x() - p[i - 1].x(), p[i].y() - p[i - 1].y());
        return sum;
    };
    double relative = kDefault;
    if (accuracy > 0.0 && std::isfinite(accuracy)) {
        double size = 0.0;
        for (std::size_t i = 0; i < m_segmentLength.size(); ++i)
            size += polygonLength(segment(static_cast<int>(i)));
        relative = size > 0.0 ? std::max(accuracy / size, kFinest) : kDefault;
    }
    // Cached lengths were measured to m_lengthAccuracy (relative): good enough when that is at least
    // as fine as asked; measured again when asked finer, or far coarser (so that one fine question
    // does not make every later measurement slow).
    if (!(relative >= m_lengthAccuracy && relative <= 1e3 * m_lengthAccuracy)) {
        std::fill(m_segmentLength.begin(), m_segmentLength.end(), kStale);
        m_lengthAccuracy = relative;
    }
    double total = 0.0;
    for (std::size_t i = 0; i < m_segmentLength.size(); ++i) {
        if (std::isnan(m_segmentLength[i])) {
            // Measured on a copy scaled by a power of two to coordinates near 1 (exact), so that
            // neither squares of large coordinates overflow nor those of tiny ones underflow.
            const geo::Bezier b = segment(static_cast<int>(i));
            double largest = 0.0;
            for (const geo::Point &p : b.controlPoints())
                largest = std::max({largest, std::abs(p.x()), std::abs(p.y())});
            if (!(largest > 0.0) || !std::isfinite(largest)) {
                m_segmentLength[i] = 0.0;
                continue;
            }
            const int exponent = std::ilogb(largest);
            std::vector<geo::Point> scaled = b.controlPoints();
            for (geo::Point &p : scaled)
                p = geo::Point(std::ldexp(p.x(), -exponent), std::ldexp(p.y(), -exponent));
            const geo::Bezier unit(std::move(scaled));
            const double part = geo::arcLength(unit, m_lengthAccuracy * polygonLength(unit));
            m_segmentLength[i] = std::ldexp(part, exponent);
        }
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

std::vector<std::pair<int, int>> Curve::guides() const
{
    std::vector<std::pair<int, int>> pairs;
    const int rows = rowCount();
    const int placed = placedCount();
    const auto polygon = [&](int first, int end) {
        for (int r = first; r + 1 < end; ++r)
            pairs.emplace_back(r, r + 1);
    };
    if (m_kind == CurveKind::Composite) {
        for (int r = 0; r < rows; ++r)
            if (!geo::CompositeCurve::isKnotIndex(r))
                pairs.emplace_back(r, (3 * m_composite.knotOfControl(r)) % rows);
    } else if (traitsOf(m_kind).controlPolygon) {
        polygon(0, placed);
    } else if (isFitted(m_kind)) {
        // The fitted cubic's four control points are the last rows.
        if (fit() && rows >= 4)
            polygon(rows - 4, rows);
    } else if (hasEndTangents(m_kind)) {
        // The two end tangents' ends follow the knots.
        if (rows >= placed + 2) {
            pairs.emplace_back(0, placed);
            pairs.emplace_back(placed - 1, placed + 1);
        }
    } else if (geo::hasKnotTangents(m_kind)) {
        // One tangent end per knot, in the knots' order after them.
        for (int k = 0; k < placed && placed + k < rows; ++k)
            pairs.emplace_back(k, placed + k);
    }
    return pairs;
}

bool Curve::isFinite() const
{
    for (int i = 0; i < rowCount(); ++i)
        if (!row(i).position.allFinite())
            return false;
    return m_kind == CurveKind::Composite || m_shape.allFinite();
}

geo::PiecewiseBezier Curve::toPiecewise() const
{
    std::vector<geo::Bezier> segments;
    segments.reserve(static_cast<std::size_t>(segmentCount()));
    for (int i = 0; i < segmentCount(); ++i)
        segments.push_back(segment(i));
    return geo::PiecewiseBezier(std::move(segments), isClosed());
}

namespace {

// A hash of 64-bit words in four independent lanes (each word xor-ed in, then multiplied by an odd
// constant), so that the processor works on four at once: 2,000 knots' 12,000 coordinates take a
// few microseconds, a drag step's share. The lanes are folded with boost::hash_combine's mix. Only
// a pre-filter: equal input, equal hash; unequal input is told apart by the exact comparison after.
class WordHash
{
public:
    void add(std::uint64_t word)
    {
        std::uint64_t &lane = m_lanes[m_count++ & 3U];
        lane = (lane ^ word) * 0x9e3779b97f4a7c15ULL;
    }
    void add(const std::vector<geo::Point> &points)
    {
        add(points.size());
        // Two points a round, one coordinate a lane, the lanes in registers.
        auto [a, b, c, d] = m_lanes;
        const auto mix = [](std::uint64_t &lane, double v) {
            lane = (lane ^ std::bit_cast<std::uint64_t>(v)) * 0x9e3779b97f4a7c15ULL;
        };
        std::size_t i = 0;
        for (; i + 1 < points.size(); i += 2) {
            mix(a, points[i].x());
            mix(b, points[i].y());
            mix(c, points[i + 1].x());
            mix(d, points[i + 1].y());
        }
        if (i < points.size()) {
            mix(a, points[i].x());
            mix(b, points[i].y());
        }
        m_lanes = {a, b, c, d};
    }
    [[nodiscard]] std::size_t value() const
    {
        std::size_t hash = m_count;
        for (const std::uint64_t lane : m_lanes)
            hash ^= lane + 0x9e3779b97f4a7c15ULL + (hash << 6U) + (hash >> 2U);
        return hash;
    }

private:
    std::array<std::uint64_t, 4> m_lanes{1, 2, 3, 4};
    std::size_t m_count = 0;
};

} // namespace

std::size_t Curve::geometryHash() const
{
    WordHash hash;
    hash.add(static_cast<std::uint64_t>(m_kind));
    hash.add(static_cast<std::uint64_t>(m_order));
    hash.add(static_cast<std::uint64_t>(m_parameterization));
    hash.add(m_points);
    hash.add(m_tangentEnds);
    if (m_kind == CurveKind::Composite) {
        hash.add(m_composite.controlPoints());
        for (int k = 0; k < m_composite.knotCount(); ++k)
            hash.add(static_cast<std::uint64_t>(m_composite.nodeType(k)));
        hash.add(m_composite.isClosed() ? 1U : 0U);
    }
    return hash.value();
}

bool Curve::sameState(const Curve &other) const
{
    return m_kind == other.m_kind && name == other.name && color == other.color && visible == other.visible &&
           locked == other.locked && m_parameterization == other.m_parameterization && m_points == other.m_points &&
           m_tangentEnds == other.m_tangentEnds && m_order == other.m_order && m_composite == other.m_composite &&
           seam == other.seam && piece == other.piece;
}

void Curve::recompute()
{
    m_problem.reset();
    m_shape = {};
    if (m_kind != CurveKind::Composite) {
        geo::CurveParts parts;
        parts.kind = m_kind;
        parts.points = m_points;
        parts.tangentEnds = m_tangentEnds;
        parts.order = m_order;
        parts.parameterization = m_parameterization;
        auto shape = geo::buildShape(parts);
        if (shape.ok())
            m_shape = std::move(shape.value());
        else
            m_problem = shape.error();
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

bool allowanceHasSeams(const Curve &source)
{
    return source.piece && source.isClosed() && (!source.piece->seamWidths.empty() || !source.piece->hems.empty());
}

geo::OffsetOptions allowanceOptions(const Curve &source, geo::OffsetOptions options)
{
    if (!allowanceHasSeams(source))
        return allowanceOptions(source, std::move(options), {});
    return allowanceOptions(source, std::move(options), geo::seamSpans(source.toPiecewise()));
}

geo::OffsetOptions allowanceOptions(const Curve &source, geo::OffsetOptions options,
                                    const std::vector<geo::SeamSpan> &seams)
{
    options.segmentDistances.clear();
    options.hems.clear();
    if (!allowanceHasSeams(source))
        return options;
    const int segments = source.segmentCount();
    options.segmentDistances = geo::segmentDistancesOf(segments, seams, source.piece->seamWidths, options.distance);
    if (!source.piece->hems.empty())
        options.hems = geo::segmentHemsOf(segments, seams, source.piece->hems);
    return options;
}

} // namespace kontur
