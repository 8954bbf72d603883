// What a person reads of a kind of curve: its translated name, a new curve's automatic name, and
// the icon of its entry in the New curve menu. The one place for them; every view, message and
// list of kinds asks here (the kinds' geometric facts are in geometry/curvekinds.h).
#pragma once

#include "geometry/curvekinds.h"

#include <QString>

namespace kontur {

// "Natural spline", in the current language.
[[nodiscard]] QString kindName(geo::CurveKind kind);
// A new curve's name, in the current language: "Bézier 3", "Natural spline 3" (`number` counts the
// curves made so far).
[[nodiscard]] QString newCurveName(geo::CurveKind kind, int number);
// The name of the icon (qml/icons) of the kind's entry in the New curve menu.
[[nodiscard]] QString kindIconName(geo::CurveKind kind);

} // namespace kontur
