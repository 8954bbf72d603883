// SVG export and import (issue 7). Export: each curve one <path> of exact line, quadratic and cubic
// segments (never a polyline) in the document's units, y flipped (Kontur's world has y up, SVG y
// down), numbers in the shortest round-trip form, so a Kontur SVG re-imports to the same curves.
// Import: the <path> elements (and line, polyline, polygon, rect, circle, ellipse) with the
// transforms of the element and its ancestors, <use> clones, hidden content left out, the viewBox
// scaled to the root's width and height; each subpath one PiecewiseBezier. Texts, images and other
// content that is no geometry are counted, not read.
#pragma once

#include "geometry/piecewise.h"
#include "io/drawncurve.h"
#include "io/error.h"
#include "io/limits.h"
#include "io/skipped.h"
#include "io/svgpath.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <span>
#include <vector>

namespace kontur::io {

using SvgCurve = DrawnCurve;

struct SvgExportOptions
{
    QString units = QStringLiteral("px"); // px: width/height plain numbers; mm, cm, in, pt: with that unit
    double margin = 0.0;                  // around the curves' bounding box, in units
    double strokeWidth = 0.0;             // in units; 0: 1 px, or 0.25 mm in physical units
    // Segments of degree above 3 have no SVG form: they are written as cubics that stay within
    // this distance (units) of the curve (Hermite cubics with the same end tangents, subdivided).
    double highDegreeTolerance = 1e-6;
};

[[nodiscard]] QByteArray exportSvg(std::span<const SvgCurve> curves, const SvgExportOptions &options = {});
// Replaces the file atomically. A drawing importSvg would refuse with `limits` (more curves or
// segments, more bytes) is not written.
[[nodiscard]] Result<Ok> writeSvg(const QString &path, std::span<const SvgCurve> curves,
                                  const SvgExportOptions &options = {}, const Limits &limits = {});

struct SvgImportOptions
{
    SvgPathOptions path;    // arc tolerance
    Limits limits;          // file size, segments (as points), subpaths (as curves), element nesting
    bool cubicOnly = false; // elevate lines and quadratics to cubics (exact), as composite curves need
};

struct SvgImportedCurve
{
    QString name;                              // the path's <title>, else its id; may be empty
    QString color = QStringLiteral("#000000"); // its stroke when that is a colour, else black
    geo::PiecewiseBezier curve;                // in Kontur's world: y up, in `SvgImport::units`
    int line = 0;                              // the element's line in the file
};

struct SvgImport
{
    // The unit of the root's width (or height) when it has a viewBox: coordinates are scaled from
    // user units by the viewBox rule into that unit, px when the width has none. Otherwise "px" and
    // user units.
    QString units = QStringLiteral("px");
    std::vector<SvgImportedCurve> curves;
    // Content that is shown but is no geometry, counted per element (each <use> copy once more):
    // <text> and <flowRoot> as texts, <image> as images, <foreignObject>, <video>, <audio>,
    // <iframe> and <canvas> as other elements. Hidden content and what only <defs> and the like
    // hold is not counted: it is not shown either.
    SkippedCounts skipped{};
};

// The skipped elements in English for kontur-cli ("1 text, 1 image"); empty when none were.
[[nodiscard]] QString skippedSummary(const SvgImport &svg);

// Errors: XmlSyntax and the structure errors with the line and column of the element; PathSyntax
// with the element's position and the character in the d attribute in the message.
[[nodiscard]] Result<SvgImport> importSvg(QByteArrayView svg, const QString &fileName = {},
                                          const SvgImportOptions &options = {});
[[nodiscard]] Result<SvgImport> readSvg(const QString &path, const SvgImportOptions &options = {});

} // namespace kontur::io
