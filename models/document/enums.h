// The enumerations QML uses, as Qt namespaces (Q_NAMESPACE / Q_ENUM_NS): QML reads CurveKind.Bezier,
// NodeType.Corner, Parameterization.ChordLength. The geometry defines them without Qt
// (geometry/curveshape.h, composite.h, parameterization.h); these are their names for QML, with the
// same values, checked below so that they cannot drift apart.
#pragma once

#include "geometry/composite.h"
#include "geometry/curveshape.h"
#include "geometry/parameterization.h"

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace kontur {

namespace CurveKinds {
Q_NAMESPACE
QML_NAMED_ELEMENT(CurveKind)
enum Kind {
    Bezier = static_cast<int>(geo::CurveKind::Bezier),
    Interpolating = static_cast<int>(geo::CurveKind::Interpolating),
    LeastSquares = static_cast<int>(geo::CurveKind::LeastSquares),
    Composite = static_cast<int>(geo::CurveKind::Composite),
    NaturalSpline = static_cast<int>(geo::CurveKind::NaturalSpline),
    ClampedSpline = static_cast<int>(geo::CurveKind::ClampedSpline),
    NotAKnotSpline = static_cast<int>(geo::CurveKind::NotAKnotSpline),
    PeriodicSpline = static_cast<int>(geo::CurveKind::PeriodicSpline),
    CatmullRom = static_cast<int>(geo::CurveKind::CatmullRom),
    HermiteSpline = static_cast<int>(geo::CurveKind::HermiteSpline),
    BSpline = static_cast<int>(geo::CurveKind::BSpline),
    GlobalBSpline = static_cast<int>(geo::CurveKind::GlobalBSpline),
    Polynomial = static_cast<int>(geo::CurveKind::Polynomial),
    FunctionSpline = static_cast<int>(geo::CurveKind::FunctionSpline),
    Contour = static_cast<int>(geo::CurveKind::Contour),
};
Q_ENUM_NS(Kind)
// Every kind has its name here: the kinds are numbered 0..kKindCount-1 and the last is named.
static_assert(geo::kKindCount == Contour + 1, "a curve kind has no QML name");
} // namespace CurveKinds

namespace NodeTypes {
Q_NAMESPACE
QML_NAMED_ELEMENT(NodeType)
enum Type {
    Smooth = static_cast<int>(geo::NodeType::Smooth),
    Symmetric = static_cast<int>(geo::NodeType::Symmetric),
    Corner = static_cast<int>(geo::NodeType::Corner),
};
Q_ENUM_NS(Type)
} // namespace NodeTypes

namespace Parameterizations {
Q_NAMESPACE
QML_NAMED_ELEMENT(Parameterization)
enum Type {
    Uniform = static_cast<int>(geo::Parameterization::Uniform),
    ChordLength = static_cast<int>(geo::Parameterization::ChordLength),
    Centripetal = static_cast<int>(geo::Parameterization::Centripetal),
};
Q_ENUM_NS(Type)
} // namespace Parameterizations

} // namespace kontur
