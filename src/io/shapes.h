// From records to curve shapes and back, for the formats that need shapes (SVG) and for kontur-cli:
// the PiecewiseBezier a record draws, and the composite curve (Corner nodes) an imported path becomes.
// A record's parts are read here once; the shape itself is built by geo::buildShape, the same
// function the app's curves use, so a record draws the same in the window, in exports and in the CLI.
#pragma once

#include "geometry/composite.h"
#include "geometry/curveshape.h"
#include "geometry/piecewise.h"
#include "io/drawncurve.h"
#include "io/error.h"
#include "io/records.h"

namespace kontur::io {

// The parts of a record of any kind but composite: its points, the tangent ends from
// settings.tangentEnds (the kind's defaults when the record has none), the B-spline order from
// settings.order (the default for its point count when absent) and the parameterization.
// Errors: an invalid record (validateCurve), a composite record, tangent ends that are not pairs of
// numbers.
[[nodiscard]] Result<geo::CurveParts> curveParts(const CurveRecord &curve);

// A composite record's curve: its control vector, node types and closure. Errors: an invalid
// record, a control vector the geometry refuses (GeometryError).
[[nodiscard]] Result<geo::CompositeCurve> compositeCurve(const CurveRecord &curve);

// The segments a record of any of the 14 kinds draws. Errors: an invalid record; a geometry refusal
// (degenerate knots, …) is GeometryError with the geometry's message.
[[nodiscard]] Result<geo::PiecewiseBezier> curveShape(const CurveRecord &curve);

// The curves a vector export (SVG, DXF) writes, in the document's order: every visible curve that
// draws at least one segment; with `only` >= 0, just that curve, hidden or not. The same rule for the
// app and kontur-cli. Errors: a curve whose record does not draw (curveShape's errors, with the
// curve's index in the error's path).
[[nodiscard]] Result<std::vector<DrawnCurve>> curvesToExport(const std::vector<CurveRecord> &curves, int only = -1);

// A composite curve record with Corner nodes through the segments (each elevated to a cubic; lines
// and quadratics exactly, higher degrees by degree reduction is not possible exactly, so they are
// refused with GeometryError). A closed input whose last segment ends at the first segment's start
// gives a closed record.
[[nodiscard]] Result<CurveRecord> compositeRecordFromShape(const geo::PiecewiseBezier &shape);

// The same curve with every segment of degree < 3 elevated to a cubic (exact); higher degrees unchanged.
[[nodiscard]] geo::PiecewiseBezier elevatedToCubics(const geo::PiecewiseBezier &shape);

// A segment of degree > 3 as cubics within `tolerance`, appended to `out` (the SVG and DXF exports,
// whose paths and splines take at most cubics): the Hermite cubic with the same end points and end
// derivatives (c1 = p0 + B'(0)/3, c2 = p3 - B'(1)/3), compared at 31 inner parameters, halved until
// close enough (at most 16 halvings deep).
void appendCubicsWithin(const geo::Bezier &segment, double tolerance, std::vector<geo::Bezier> &out);

// The records of the curves an import read (SVG paths, DXF entities: anything with name, color, curve
// and line), each named and coloured as in the file; `toRecord` makes the record of a curve. Its error
// names the file and the curve's line.
template <typename Imported, typename ToRecord>
[[nodiscard]] Result<std::vector<CurveRecord>> importedRecords(const std::vector<Imported> &curves, const QString &path,
                                                               ToRecord toRecord)
{
    std::vector<CurveRecord> records;
    records.reserve(curves.size());
    for (const Imported &c : curves) {
        Result<CurveRecord> record = toRecord(c.curve);
        if (!record) {
            Error e = record.error();
            e.file = path;
            e.line = c.line;
            return e;
        }
        record->name = c.name;
        record->color = c.color;
        records.push_back(std::move(record).value());
    }
    return records;
}

} // namespace kontur::io
