// The curve kinds the files know (from geometry/curvekinds.h) and the validation of curve records
// (see records.h).
#include "io/records.h"

#include "geometry/curvekinds.h"

#include <array>
#include <cmath>

namespace kontur::io {

namespace {

// What the files check of each kind, from the kinds' table (geometry/curvekinds.h): its id, fewest
// points and parameterization, and its most points. The splines' kManyPoints is no limit besides the
// file limits here (0: "at least n" in the message), while the least-squares cubic and the composite
// curve (counted in knots) name theirs. Their points are knots unless they are a control polygon or a
// composite curve's control vector; only a composite curve is closed by a flag. The spline kinds keep
// their knots (or the B-spline's control points) in `points`; tangent ends and the B-spline order
// live in `settings` ("tangentEnds": [[x, y], …], "order": k).
constexpr KindInfo infoOf(const geo::KindTraits &t)
{
    const bool composite = t.kind == geo::CurveKind::Composite;
    const bool unlimited = t.maxPoints == geo::kManyPoints && !t.fitted && !composite;
    return {t.id,     t.minPoints, unlimited ? 0 : t.maxPoints, t.usesParameterization, !t.controlPolygon && !composite,
            composite};
}

constexpr std::array<KindInfo, geo::kKindCount> kKinds = [] {
    std::array<KindInfo, geo::kKindCount> kinds{};
    for (std::size_t k = 0; k < kinds.size(); ++k)
        kinds[k] = infoOf(geo::kKinds[k]);
    return kinds;
}();

} // namespace

const KindInfo *kindInfo(const QString &kind)
{
    for (const KindInfo &info : kKinds)
        if (kind == QLatin1String(info.id))
            return &info;
    return nullptr;
}

std::vector<QString> knownKinds()
{
    std::vector<QString> out;
    for (const KindInfo &info : kKinds)
        out.push_back(QLatin1String(info.id));
    return out;
}

bool isParameterizationName(const QString &name)
{
    return name == QLatin1String("uniform") || name == QLatin1String("chord") || name == QLatin1String("centripetal");
}

bool isNodeTypeName(const QString &name)
{
    return name == QLatin1String("smooth") || name == QLatin1String("symmetric") || name == QLatin1String("corner");
}

bool isColorName(const QString &color)
{
    if (color.size() != 7 || color.front() != QLatin1Char('#'))
        return false;
    for (int i = 1; i < 7; ++i) {
        const char16_t c = color.at(i).unicode();
        if (!((c >= u'0' && c <= u'9') || (c >= u'a' && c <= u'f') || (c >= u'A' && c <= u'F')))
            return false;
    }
    return true;
}

bool isUnitName(const QString &units)
{
    for (const char *u : {"px", "mm", "cm", "in", "pt"})
        if (units == QLatin1String(u))
            return true;
    return false;
}

double millimetresPerUnit(const QString &units, bool cssPixels)
{
    if (units == QLatin1String("mm"))
        return 1.0;
    if (units == QLatin1String("cm"))
        return 10.0;
    if (units == QLatin1String("in"))
        return 25.4;
    if (units == QLatin1String("pt"))
        return 25.4 / 72.0;
    if (units == QLatin1String("px") && cssPixels)
        return 25.4 / kCssPixelsPerInch;
    return 0.0;
}

int compositeKnotCount(std::size_t pointCount, bool closed)
{
    // Open: 3n - 2 points (n >= 2); closed: 3n (n >= 3), the repeated first knot not stored.
    if (closed)
        return pointCount % 3 == 0 && pointCount >= 9 ? static_cast<int>(pointCount / 3) : 0;
    return (pointCount + 2) % 3 == 0 && pointCount >= 4 ? static_cast<int>((pointCount + 2) / 3) : 0;
}

std::optional<CurveProblem> validateCurve(const CurveRecord &curve)
{
    const KindInfo *info = kindInfo(curve.kind);
    if (!info) {
        const std::vector<QString> kinds = knownKinds();
        return CurveProblem{CurveProblem::Kind, -1, -1, ErrorCode::UnknownKind,
                            QStringLiteral("unknown curve kind \"%1\" (this version knows %2)")
                                .arg(curve.kind, QStringList(kinds.begin(), kinds.end()).join(QStringLiteral(", ")))};
    }
    if (info->usesParameterization && !isParameterizationName(curve.parameterization))
        return CurveProblem{
            CurveProblem::Parameterization, -1, -1, ErrorCode::UnknownParameterization,
            QStringLiteral("%1 curves need a parameterization (uniform, chord or centripetal), not \"%2\"")
                .arg(curve.kind, curve.parameterization)};
    if (!info->usesParameterization && !curve.parameterization.isEmpty())
        return CurveProblem{CurveProblem::Parameterization, -1, -1, ErrorCode::InvalidValue,
                            QStringLiteral("%1 curves do not use a parameterization").arg(curve.kind)};
    if (!isColorName(curve.color))
        return CurveProblem{CurveProblem::Color, -1, -1, ErrorCode::InvalidValue,
                            QStringLiteral("colour \"%1\" is not #rrggbb").arg(curve.color)};
    for (std::size_t i = 0; i < curve.points.size(); ++i)
        for (int c = 0; c < 2; ++c)
            if (!std::isfinite(curve.points[i][c]))
                return CurveProblem{CurveProblem::Point, static_cast<int>(i), c, ErrorCode::NumberOutOfRange,
                                    QStringLiteral("coordinate is not a finite number")};
    const auto count = static_cast<qint64>(curve.points.size());
    if (QLatin1String(info->id) == QLatin1String("composite")) {
        const int knots = compositeKnotCount(curve.points.size(), curve.closed);
        if (knots == 0)
            return CurveProblem{CurveProblem::Points, -1, -1, ErrorCode::WrongPointCount,
                                curve.closed ? QStringLiteral("a closed composite curve stores 3n points for n >= 3 "
                                                              "knots, not %1")
                                                   .arg(count)
                                             : QStringLiteral("an open composite curve stores 3n - 2 points for n >= 2 "
                                                              "knots, not %1")
                                                   .arg(count)};
        if (knots > info->maxPoints)
            return CurveProblem{
                CurveProblem::Points, -1, -1, ErrorCode::WrongPointCount,
                QStringLiteral("%1 knots; composite curves have at most %2").arg(knots).arg(info->maxPoints)};
        if (curve.nodeTypes.size() != static_cast<std::size_t>(knots))
            return CurveProblem{CurveProblem::NodeTypes, -1, -1, ErrorCode::WrongPointCount,
                                QStringLiteral("%1 node types for %2 knots").arg(curve.nodeTypes.size()).arg(knots)};
        for (std::size_t i = 0; i < curve.nodeTypes.size(); ++i)
            if (!isNodeTypeName(curve.nodeTypes[i]))
                return CurveProblem{
                    CurveProblem::NodeType, static_cast<int>(i), -1, ErrorCode::UnknownNodeType,
                    QStringLiteral("unknown node type \"%1\" (smooth, symmetric or corner)").arg(curve.nodeTypes[i])};
        return std::nullopt;
    }
    if (curve.closed && !info->closable)
        return CurveProblem{CurveProblem::Closed, -1, -1, ErrorCode::InvalidValue,
                            QStringLiteral("%1 curves cannot be closed").arg(curve.kind)};
    if (!curve.nodeTypes.empty())
        return CurveProblem{CurveProblem::NodeTypes, -1, -1, ErrorCode::InvalidValue,
                            QStringLiteral("only composite curves have node types")};
    if (count < info->minPoints || (info->maxPoints > 0 && count > info->maxPoints)) {
        const QString what = info->definedByKnots ? QStringLiteral("knots") : QStringLiteral("control points");
        // A maximum of 0 means none (besides the file limits): "at least", never "3 to 0".
        const QString need = info->minPoints == info->maxPoints ? QStringLiteral("exactly %1").arg(info->minPoints)
                             : info->maxPoints > 0
                                 ? QStringLiteral("%1 to %2").arg(info->minPoints).arg(info->maxPoints)
                                 : QStringLiteral("at least %1").arg(info->minPoints);
        return CurveProblem{CurveProblem::Points, -1, -1, ErrorCode::WrongPointCount,
                            QStringLiteral("%1 %2; %3 curves need %4").arg(count).arg(what, curve.kind, need)};
    }
    return std::nullopt;
}

} // namespace kontur::io
