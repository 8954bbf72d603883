// One curve of a document as plain data: its kind, name, style and defining points.
#pragma once

#include "geometry/bezier.h"

#include <QColor>
#include <QCoreApplication>
#include <QString>

#include <vector>

namespace kontur {

// The kinds a document holds. The skeleton has the Bézier curve by control points; the
// models issue adds the fitted, composite and spline kinds.
enum class CurveKind { Bezier };

// What a point means for its curve; the canvas draws each role differently (SPEC.md 1.1 req. 6).
enum class PointRole { ControlPoint, Knot, Handle, TangentEnd };

struct Curve
{
    CurveKind kind = CurveKind::Bezier;
    QString name;
    QColor color = QColor(0, 0, 0);
    std::vector<geo::Point> points;

    [[nodiscard]] PointRole roleOf(int point) const;
    // The Bézier segments that draw this curve, in order.
    [[nodiscard]] std::vector<geo::Bezier> segments() const;

    friend bool operator==(const Curve &, const Curve &) = default;
};

// The translated name of a kind, for lists and titles.
[[nodiscard]] QString kindName(CurveKind kind);
// The row label of the seed's coordinates window: P<i> for knots, C<i> for control points.
[[nodiscard]] QString pointLabel(PointRole role, int index);

} // namespace kontur
