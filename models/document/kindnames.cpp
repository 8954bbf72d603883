// The translated names of the kinds of curve (see kindnames.h): one case per kind, so that the
// compiler names a kind that has none (-Wswitch).
#include "models/document/kindnames.h"

#include <QCoreApplication>

namespace kontur {

namespace {

struct KindTexts
{
    QString name;
    // A new curve's name with its number as %1, where it is not the kind's name and the number.
    QString numbered = {};
    const char *icon = "kontur-curve";
};

KindTexts textsOf(geo::CurveKind kind)
{
    using geo::CurveKind;
    switch (kind) {
    case CurveKind::Bezier:
        return {.name = QCoreApplication::translate("kontur", "Bézier curve"),
                //: Automatic name of a new curve: %1 is a running number (Bézier 3).
                .numbered = QCoreApplication::translate("kontur", "Bézier %1"),
                .icon = "kontur-bezier"};
    case CurveKind::Interpolating:
        return {.name = QCoreApplication::translate("kontur", "Cubic through 4 points"),
                //: Automatic name of a new cubic through 4 points: %1 is a running number.
                .numbered = QCoreApplication::translate("kontur", "Through 4 points %1")};
    case CurveKind::LeastSquares:
        return {.name = QCoreApplication::translate("kontur", "Least-squares cubic"),
                //: Automatic name of a new least-squares cubic: %1 is a running number.
                .numbered = QCoreApplication::translate("kontur", "Least squares %1"),
                .icon = "kontur-polygon-curve"};
    case CurveKind::Composite:
        return {.name = QCoreApplication::translate("kontur", "Composite curve"),
                //: Automatic name of a new composite curve: %1 is a running number.
                .numbered = QCoreApplication::translate("kontur", "Composite %1")};
    case CurveKind::NaturalSpline:
        return {.name = QCoreApplication::translate("kontur", "Natural spline")};
    case CurveKind::ClampedSpline:
        //: Curve kind: the cubic spline with given first derivatives at both ends (a complete or clamped spline).
        return {.name = QCoreApplication::translate("kontur", "Clamped spline")};
    case CurveKind::NotAKnotSpline:
        //: Curve kind: the cubic spline whose second and next-to-last knots are not knots (the third derivative is
        //: continuous there).
        return {.name = QCoreApplication::translate("kontur", "Not-a-knot spline")};
    case CurveKind::PeriodicSpline:
        return {.name = QCoreApplication::translate("kontur", "Periodic spline"), .icon = "kontur-closed-curve"};
    case CurveKind::CatmullRom:
        return {.name = QCoreApplication::translate("kontur", "Catmull–Rom spline")};
    case CurveKind::HermiteSpline:
        return {.name = QCoreApplication::translate("kontur", "Hermite spline")};
    case CurveKind::BSpline:
        return {.name = QCoreApplication::translate("kontur", "B-spline"), .icon = "kontur-polygon-curve"};
    case CurveKind::GlobalBSpline:
        return {.name = QCoreApplication::translate("kontur", "Global B-spline")};
    case CurveKind::Polynomial:
        return {.name = QCoreApplication::translate("kontur", "Interpolating polynomial"), .icon = "kontur-function"};
    case CurveKind::FunctionSpline:
        return {.name = QCoreApplication::translate("kontur", "Function spline y(x)"), .icon = "kontur-function"};
    case CurveKind::Contour:
        //: Curve kind: quadratic Bézier pieces through the midpoints of the polygon's sides, joined smoothly there.
        return {.name = QCoreApplication::translate("kontur", "Contour curve (midpoint joins)"),
                .icon = "kontur-polygon-curve"};
    }
    return {};
}

} // namespace

QString kindName(geo::CurveKind kind)
{
    return textsOf(kind).name;
}

QString newCurveName(geo::CurveKind kind, int number)
{
    const KindTexts texts = textsOf(kind);
    if (!texts.numbered.isEmpty())
        return texts.numbered.arg(number);
    // "Natural spline 3": the kind's name and a number.
    //: Automatic name of a new curve: %1 is its kind (“Natural spline”), %2 a running number.
    return QCoreApplication::translate("kontur", "%1 %2").arg(texts.name).arg(number);
}

QString kindIconName(geo::CurveKind kind)
{
    return QString::fromLatin1(textsOf(kind).icon);
}

} // namespace kontur
