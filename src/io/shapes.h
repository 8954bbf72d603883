// From records to curve shapes and back, for the formats that need shapes (SVG) and for kontur-cli:
// the PiecewiseBezier a record draws, and the composite curve (Corner nodes) an imported path becomes.
// The models do the same with their own types; this is the headless version.
#pragma once

#include "geometry/piecewise.h"
#include "io/error.h"
#include "io/records.h"

namespace kontur::io {

// bezier: one segment through the control points; composite: CompositeCurve::fromParts(...)
// .toPiecewise(); interpolating / least-squares: the cubic of fit.h with the record's
// parameterization. Other kinds: UnsupportedKind. A geometry refusal is GeometryError.
[[nodiscard]] Result<geo::PiecewiseBezier> curveShape(const CurveRecord &curve);

// A composite curve record with Corner nodes through the segments (each elevated to a cubic; lines
// and quadratics exactly, higher degrees by degree reduction is not possible exactly, so they are
// refused with GeometryError). A closed input whose last segment ends at the first segment's start
// gives a closed record.
[[nodiscard]] Result<CurveRecord> compositeRecordFromShape(const geo::PiecewiseBezier &shape);

// The same curve with every segment of degree < 3 elevated to a cubic (exact); higher degrees unchanged.
[[nodiscard]] geo::PiecewiseBezier elevatedToCubics(const geo::PiecewiseBezier &shape);

} // namespace kontur::io
