// Record ↔ shape conversions (see shapes.h).
#include "io/shapes.h"

#include <algorithm>

#include "geometry/parameterization.h"

#include <QJsonArray>

namespace kontur::io {

namespace {

Error geometryError(const geo::Error &e)
{
    Error out;
    out.code = ErrorCode::GeometryError;
    out.message = QString::fromStdString(e.message);
    return out;
}

Error invalidRecord(const CurveProblem &problem)
{
    Error e;
    e.code = problem.code;
    e.message = problem.message;
    return e;
}

geo::NodeType nodeTypeOf(const QString &name)
{
    if (name == QLatin1String("symmetric"))
        return geo::NodeType::Symmetric;
    if (name == QLatin1String("corner"))
        return geo::NodeType::Corner;
    return geo::NodeType::Smooth;
}

} // namespace

Result<geo::CurveParts> curveParts(const CurveRecord &curve)
{
    if (const auto problem = validateCurve(curve))
        return invalidRecord(*problem);
    const std::optional<geo::CurveKind> kind = geo::kindFromId(curve.kind.toStdString());
    if (!kind || *kind == geo::CurveKind::Composite) {
        Error e;
        e.code = ErrorCode::InvalidValue;
        e.message = QStringLiteral("a curve of kind \"%1\" has no such parts").arg(curve.kind);
        return e;
    }
    geo::CurveParts parts;
    parts.kind = *kind;
    parts.points = curve.points;
    if (!curve.parameterization.isEmpty())
        (void)geo::parseParameterization(curve.parameterization.toStdString(), parts.parameterization);
    const QJsonValue ends = curve.settings.value(QStringLiteral("tangentEnds"));
    if (ends.isArray()) {
        for (const QJsonValue &value : ends.toArray()) {
            const QJsonArray xy = value.toArray();
            if (!value.isArray() || xy.size() != 2 || !xy.at(0).isDouble() || !xy.at(1).isDouble()) {
                Error e;
                e.code = ErrorCode::InvalidValue;
                e.message = QStringLiteral("a tangent end is not a pair of numbers");
                return e;
            }
            parts.tangentEnds.emplace_back(xy.at(0).toDouble(), xy.at(1).toDouble());
        }
    } else {
        parts.tangentEnds = geo::defaultTangentEnds(parts.kind, parts.points, parts.parameterization);
    }
    const int order = curve.settings.value(QStringLiteral("order")).toInt(0);
    parts.order = order > 0 ? order : geo::defaultOrder(parts.points.size());
    return parts;
}

Result<geo::CompositeCurve> compositeCurve(const CurveRecord &curve)
{
    if (const auto problem = validateCurve(curve))
        return invalidRecord(*problem);
    std::vector<geo::Point> control = curve.points;
    if (curve.closed && !control.empty())
        control.push_back(control.front()); // fromParts wants the repeated first knot
    std::vector<geo::NodeType> types;
    types.reserve(curve.nodeTypes.size());
    for (const QString &t : curve.nodeTypes)
        types.push_back(nodeTypeOf(t));
    auto composite = geo::CompositeCurve::fromParts(std::move(control), std::move(types), curve.closed);
    if (!composite)
        return geometryError(composite.error());
    return std::move(composite.value());
}

Result<geo::PiecewiseBezier> curveShape(const CurveRecord &curve)
{
    if (curve.kind == QLatin1String("composite")) {
        auto composite = compositeCurve(curve);
        if (!composite)
            return composite.error();
        return composite->toPiecewise();
    }
    auto parts = curveParts(curve);
    if (!parts)
        return parts.error();
    auto shape = geo::buildShape(*parts);
    if (!shape)
        return geometryError(shape.error());
    return shape->toPiecewise();
}

geo::PiecewiseBezier elevatedToCubics(const geo::PiecewiseBezier &shape)
{
    std::vector<geo::Bezier> out;
    out.reserve(shape.segments().size());
    for (const geo::Bezier &b : shape.segments())
        out.push_back(b.degree() >= 1 && b.degree() < 3 ? b.elevated(3 - b.degree()) : b);
    return geo::PiecewiseBezier(std::move(out), shape.isClosed());
}

Result<CurveRecord> compositeRecordFromShape(const geo::PiecewiseBezier &shape)
{
    const geo::PiecewiseBezier cubics = elevatedToCubics(shape);
    CurveRecord r;
    r.kind = QStringLiteral("composite");
    if (cubics.isEmpty()) {
        Error e;
        e.code = ErrorCode::GeometryError;
        e.message = QStringLiteral("the path has no segments");
        return e;
    }
    for (const geo::Bezier &b : cubics.segments()) {
        if (b.degree() != 3) {
            Error e;
            e.code = ErrorCode::GeometryError;
            e.message = QStringLiteral("a segment of degree %1 cannot be part of a composite curve").arg(b.degree());
            return e;
        }
        const auto &c = b.controlPoints();
        if (r.points.empty())
            r.points.push_back(c[0]);
        r.points.insert(r.points.end(), {c[1], c[2], c[3]});
    }
    // Closed: the last knot repeats the first; the record does not store it. A closed path of fewer
    // than 3 segments cannot be a closed composite curve (3 knots at least): it stays open.
    if (cubics.isClosed() && cubics.segmentCount() >= 3 && r.points.back() == r.points.front()) {
        r.points.pop_back();
        r.closed = true;
    }
    const int knots = compositeKnotCount(r.points.size(), r.closed);
    r.nodeTypes.assign(static_cast<std::size_t>(knots), QStringLiteral("corner"));
    return r;
}

namespace {

void cubicsWithin(const geo::Bezier &b, double tolerance, int depth, std::vector<geo::Bezier> &out)
{
    const geo::Point p0 = b.startPoint(), p3 = b.endPoint();
    const geo::Bezier h({p0, p0 + b.derivative(0.0) / 3.0, p3 - b.derivative(1.0) / 3.0, p3});
    double err = 0.0;
    for (int i = 1; i < 32; ++i)
        err = std::max(err, (b.eval(i / 32.0) - h.eval(i / 32.0)).norm());
    if (err <= tolerance || depth >= 16) {
        out.push_back(h);
        return;
    }
    const auto [left, right] = b.split(0.5);
    cubicsWithin(left, tolerance, depth + 1, out);
    cubicsWithin(right, tolerance, depth + 1, out);
}

} // namespace

void appendCubicsWithin(const geo::Bezier &segment, double tolerance, std::vector<geo::Bezier> &out)
{
    cubicsWithin(segment, tolerance, 0, out);
}

Result<std::vector<DrawnCurve>> curvesToExport(const std::vector<CurveRecord> &curves, int only)
{
    std::vector<DrawnCurve> drawn;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const CurveRecord &record = curves[i];
        if (only >= 0 ? static_cast<std::size_t>(only) != i : !record.visible)
            continue;
        if (record.points.size() < 2) // a curve being begun: nothing to draw yet
            continue;
        auto shape = curveShape(record);
        if (!shape) {
            Error e = shape.error();
            e.path = QStringLiteral("curves[%1]").arg(i);
            return e;
        }
        if (shape->segmentCount() == 0)
            continue;
        drawn.push_back({record.name, record.color, std::move(shape).value()});
    }
    return drawn;
}

} // namespace kontur::io
