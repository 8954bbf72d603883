// Curve data: roles of points, drawing segments, translated names.
#include "models/curve.h"

namespace kontur {

PointRole Curve::roleOf(int /*point*/) const
{
    switch (kind) {
    case CurveKind::Bezier:
        return PointRole::ControlPoint;
    }
    return PointRole::ControlPoint;
}

std::vector<geo::Bezier> Curve::segments() const
{
    switch (kind) {
    case CurveKind::Bezier:
        if (points.size() < 2)
            return {};
        return {geo::Bezier(points)};
    }
    return {};
}

QString kindName(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Bezier:
        return QCoreApplication::translate("kontur", "Bézier curve");
    }
    return {};
}

QString pointLabel(PointRole role, int index)
{
    // The seed labels knot rows P<i> and control point rows C<i>; numbering starts at 0 like c0..c3.
    const QChar prefix = role == PointRole::Knot ? QLatin1Char('P') : QLatin1Char('C');
    return prefix + QString::number(index);
}

} // namespace kontur
