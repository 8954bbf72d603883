// DXF export and import (issue 22: plotters and pattern software). Export: a complete AutoCAD 2000
// drawing (tables, blocks, objects, handles and owners), the curves on layers named after them, in the
// document's units with $INSUNITS, either exactly (SPLINE entities whose knot vectors are Bézier
// knots, so the control points are the curves' own Bézier control points) or flattened
// (LWPOLYLINE within a tolerance). Import: SPLINE (any clamped or unclamped B-spline, split into
// Bézier pieces by knot insertion), LINE, LWPOLYLINE and POLYLINE (bulges as arcs), ARC, CIRCLE and
// ELLIPSE, each entity one PiecewiseBezier; INSERTs of BLOCKs exploded (nested, scaled, rotated, MINSERT
// arrays) and HATCH boundary paths as curves; what cannot be drawn is skipped and counted. DXF's y axis
// points up, as Kontur's world does: no flip.
#pragma once

#include "geometry/piecewise.h"
#include "io/drawncurve.h"
#include "io/error.h"
#include "io/limits.h"
#include "io/piece.h"
#include "io/records.h"
#include "io/skipped.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace kontur::io {

enum class DxfFlavour {
    Spline,   // AC1015 (AutoCAD 2000) SPLINE entities with the exact Bézier control points
    Polyline, // AC1015 LWPOLYLINE entities, the curves flattened within a tolerance
};

using DxfCurve = DrawnCurve;

struct DxfExportOptions
{
    // The document's units: mm ($INSUNITS 4), cm (5), in (1). pt is written in inches (divided by
    // 72, the one physical unit DXF has for it); px is written unitless ($INSUNITS 0), numbers as they are.
    QString units = QStringLiteral("px");
    DxfFlavour flavour = DxfFlavour::Spline;
    // Polyline flavour: the largest distance of the polyline from the curve, in the document's
    // units; 0 or less: 0.05 mm in those units (px counted at 96 per inch, as CSS does).
    double tolerance = 0.0;
    // kontur-cli: write the document's pieces as ASTM D6673 (AAMA) blocks (aamaPieces, writeAamaDxf).
    bool aama = false;
};

// The tolerance 0.05 mm in `units` (px at 96 per inch).
[[nodiscard]] double defaultDxfTolerance(const QString &units);

// A complete AutoCAD 2000 drawing (HEADER, CLASSES, TABLES, BLOCKS, ENTITIES, OBJECTS, every object
// with its handle and owner). Each curve with a name is drawn on a layer of its own named after it
// (refused characters as "_", unique regardless of case, non-ASCII characters as \U+XXXX), the
// others on the layer "0"; the importer gives curves their layers' names back.
[[nodiscard]] QByteArray exportDxf(std::span<const DxfCurve> curves, const DxfExportOptions &options = {});
// Replaces the file atomically. A drawing importDxf would refuse with `limits` (more curves or
// points, more bytes), or one with a coordinate that is not finite, is not written.
[[nodiscard]] Result<Ok> writeDxf(const QString &path, std::span<const DxfCurve> curves,
                                  const DxfExportOptions &options = {}, const Limits &limits = {});

// A garment piece as ASTM D6673 (AAMA DXF) exchanges it: a block of its own whose layers are the
// standard's numbers (docs/file-formats.md): 1 the cut line and the piece's text ("Piece Name:",
// "Size:", "Quantity:", "Material:", "Annotation: On fold"), 14 the sew line (when an allowance lies
// around it), 4 the notches (a POINT where each meets the cut line, its direction as the POINT's
// angle; a castle notch also on layer 81, a V notch on 84), 6 the mirror (fold) line, 7 the grain
// line, 8 internal lines, 13 drill holes. A piece without a grainline of its own gets no grain line.
struct AamaPiece
{
    QString name;
    geo::PiecewiseBezier cut;                   // the outline to cut along: the allowance, else the piece
    geo::PiecewiseBezier sew;                   // the piece itself when an allowance is its cut line
    std::vector<geo::PiecewiseBezier> internal; // open curves within the piece
    // The piece's marks (io/piece.h; notch positions along the piece's own curve, `sew` when it has
    // an allowance, else `cut`). Absent for a closed curve that was never made a piece.
    std::optional<PieceMarks> marks;
};

// The pieces of a document: each visible closed curve that is not a seam allowance, cut along its
// allowance (the first that names it) when it has one; visible open curves inside a piece's cut line's
// bounding box are its internal lines. Curves that are none of these are not written.
[[nodiscard]] Result<std::vector<AamaPiece>> aamaPieces(const std::vector<CurveRecord> &records);
// An AutoCAD 2000 drawing of the pieces as ASTM D6673 lays them out: a block per piece, inserted once
// at the origin (the pieces lie where they were drawn), in `options`' units; the flavour chooses exact
// SPLINEs or, as the standard's readers expect, polylines within the tolerance.
[[nodiscard]] QByteArray exportAamaDxf(std::span<const AamaPiece> pieces, const DxfExportOptions &options = {});
// The names of the pieces that have no grainline of their own (their export has no grain line, and
// marker making cannot orient them on the fabric): what the app and kontur-cli warn about.
[[nodiscard]] std::vector<QString> piecesWithoutGrainline(std::span<const AamaPiece> pieces);
[[nodiscard]] Result<Ok> writeAamaDxf(const QString &path, std::span<const AamaPiece> pieces,
                                      const DxfExportOptions &options = {}, const Limits &limits = {});

struct DxfImportOptions
{
    Limits limits; // file size, points (control points and vertices), entities (as curves)
    // Largest distance of the cubics that stand for an arc (ARC, CIRCLE, ELLIPSE, a bulge) from
    // it, in the file's units (Goldapp's bound, see SvgPathOptions::arcTolerance).
    double arcTolerance = 1e-6;
    // The units of a file that names none ($INSUNITS missing, 0 "unitless", or a unit Kontur does
    // not have): "mm", "cm", "in" or "px" (numbers unchanged in each). The app asks the user once;
    // kontur-cli takes --units.
    QString unitlessUnits = QStringLiteral("px");
};

struct DxfImportedCurve
{
    QString name;                              // the entity's layer, unless it is the layer "0"
    QString color = QStringLiteral("#000000"); // its true colour (group 420) when it has one
    geo::PiecewiseBezier curve;                // in the file's units, y up
    int line = 0;                              // the line of the entity's "0" group in the file
    // From an ASTM D6673 (AAMA) piece's block: the piece's name (its "Piece Name:" text, else the
    // block's) and the standard's layer the curve is on (1 cut line, 14 sew line, 7 grain line, 8
    // internal line, 4 notch, …); the curve is named "<piece> cut line" and so on. Else empty and 0.
    QString piece;
    int aamaLayer = 0;
};

// What an ASTM D6673 piece's block holds besides curves: its text (size, quantity, material, "On
// fold") and its POINTs on layers 4 (notches, the angle their direction), 13 (drill holes) and 80–84
// (the notch types), in the imported units, y up. The curves of the piece carry its name as `piece`.
struct DxfAamaPoint
{
    geo::Point at = geo::Point::Zero();
    double angle = 0.0; // degrees counter-clockwise from the x axis, after the block's placement
    int layer = 0;
};
struct DxfAamaPiece
{
    QString name;
    QString size;
    QString material;
    int quantity = 1;
    bool onFold = false;
    std::vector<DxfAamaPoint> points;
};

// What a DXF may hold that Kontur does not draw; such entities are counted and the file is read
// (the app and kontur-cli say what was skipped, as for SVG). The kinds: io/skipped.h.
using DxfSkipped = SkippedKind;
inline constexpr std::size_t kDxfSkippedKinds = kSkippedKinds;

struct DxfImport
{
    // From $INSUNITS: 1 in, 4 mm, 5 cm; feet are read as inches (×12), metres and decimetres as
    // millimetres (×1000) and centimetres (×10); 0, none or any other unit: the options'
    // unitlessUnits (default "px"), numbers unchanged.
    QString units = QStringLiteral("px");
    bool declaredUnits = false; // $INSUNITS named one of the units above (else `units` is unitlessUnits)
    std::vector<DxfImportedCurve> curves;
    std::vector<DxfAamaPiece> pieces; // ASTM D6673 pieces' marks (their curves are among `curves`)
    // Entities not drawn, by DxfSkipped (each counted once per block instance).
    SkippedCounts skipped{};
};

// The skipped entities in English for kontur-cli ("12 texts, 1 3D object"); empty when none were.
[[nodiscard]] QString skippedSummary(const DxfImport &dxf);

// Errors name the line of the file: DxfSyntax (a group code that is no integer, a value that is not
// a number where one belongs, a file that ends inside a pair or section), DxfUnsupported (a binary
// DXF, a rational spline, a spline given by fit points only, an entity outside the drawing plane),
// NoPaths (nothing drawable), and the limits.
[[nodiscard]] Result<DxfImport> importDxf(QByteArrayView dxf, const QString &fileName = {},
                                          const DxfImportOptions &options = {});
[[nodiscard]] Result<DxfImport> readDxf(const QString &path, const DxfImportOptions &options = {});

// Whether a Bézier piece is a straight segment whatever its degree (an imported LINE elevated to a
// cubic): its control points on the chord between its ends, within a few units in the last place.
// The writer draws such pieces as LINE or LWPOLYLINE.
[[nodiscard]] bool isStraight(const geo::Bezier &b);
// The colour of an AutoCAD Color Index (1–255) as "#rrggbb"; 7 (white on screen, black on paper) and
// anything outside 1–255 as black.
[[nodiscard]] QString aciColorName(int aci);

// "A full turn" within the precision angles are written with: files print them with about 12
// significant digits (2π as 6.28318530718, 4e-13 above it), so angles that differ by whole turns
// within 1e-9 of a turn are the same angle (ezdxf compares them with Python's isclose, also 1e-9).
inline constexpr double kFullTurnTolerance = 1e-9;
// The counter-clockwise sweep from the angle `start` to `end` (`period` is a full turn: 360 for
// degrees, 2π for radians) in [0, period]: 0 when they are the same number (nothing is drawn), the
// full `period` (and `full` set) when they differ by whole turns within kFullTurnTolerance.
[[nodiscard]] double sweepOf(double start, double end, double period, bool &full);

// The record an imported curve becomes: a composite curve (its cubic pieces; lines and quadratics
// elevated exactly; node types by continuity, see geo::compositeFromPieces) or, for one piece of
// degree 4 to 100, a Bézier curve of that degree (exact both ways). Pieces of higher degree within
// a curve of several become cubics within `tolerance` (Hermite, halved until close enough).
[[nodiscard]] Result<CurveRecord> recordFromDxfCurve(const geo::PiecewiseBezier &curve, double tolerance = 1e-6);

} // namespace kontur::io
