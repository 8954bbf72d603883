// Record ↔ shape conversions (see shapes.h).
#include "io/shapes.h"

#include "geometry/composite.h"
#include "geometry/fit.h"
#include "geometry/parameterization.h"

namespace kontur::io {

namespace {

Error geometryError(const geo::Error &e)
{
    Error out;
    out.code = ErrorCode::GeometryError;
    out.message = QString::fromStdString(e.message);
    return out;
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

Result<geo::PiecewiseBezier> curveShape(const CurveRecord &curve)
{
    if (const auto problem = validateCurve(curve)) {
        Error e;
        e.code = problem->code;
        e.message = problem->message;
        return e;
    }
    if (curve.kind == QLatin1String("bezier"))
        return geo::PiecewiseBezier({geo::Bezier(curve.points)});
    if (curve.kind == QLatin1String("composite")) {
        std::vector<geo::Point> control = curve.points;
        if (curve.closed)
            control.push_back(control.front()); // fromParts wants the repeated first knot
        std::vector<geo::NodeType> types;
        for (const QString &t : curve.nodeTypes)
            types.push_back(nodeTypeOf(t));
        auto composite = geo::CompositeCurve::fromParts(std::move(control), std::move(types), curve.closed);
        if (!composite)
            return geometryError(composite.error());
        return composite->toPiecewise();
    }
    if (curve.kind == QLatin1String("interpolating") || curve.kind == QLatin1String("least-squares")) {
        geo::Parameterization p = geo::Parameterization::Uniform;
        if (!geo::parseParameterization(curve.parameterization.toStdString(), p)) {
            Error e;
            e.code = ErrorCode::UnknownParameterization;
            e.message = QStringLiteral("unknown parameterization \"%1\"").arg(curve.parameterization);
            return e;
        }
        auto fit = curve.kind == QLatin1String("interpolating") ? geo::interpolateCubic(curve.points, p)
                                                                : geo::fitCubic(curve.points, p);
        if (!fit)
            return geometryError(fit.error());
        return geo::PiecewiseBezier({fit->curve()});
    }
    Error e;
    e.code = ErrorCode::UnsupportedKind;
    e.message = QStringLiteral("curves of kind \"%1\" cannot be drawn by this version yet").arg(curve.kind);
    return e;
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

} // namespace kontur::io
