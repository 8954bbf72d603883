// The pattern PDF (issue 22): the visible curves at true size, tiled over A4 or Letter pages
// (geometry/tiling.h decides the pages), with page labels, cut and overlap lines and alignment
// marks, a first page with a 10 cm test square and the overview, and the whole document embedded as
// XMP metadata (io/pdf.h) so the PDF opens in Kontur again. Qt Gui (QPdfWriter, QPainter) without
// Qt Quick: the app (PrintController) and kontur-cli share it. Its texts are translated (context
// "kontur::print"); kontur-cli builds a QGuiApplication for them.
//
// Decisions (docs/file-formats.md): the background picture is not printed (a scan under the traced
// lines only blurs them and costs ink; the PDF is for cutting along the curves). Hidden curves are
// not printed. A document in px is printed at 96 px per inch (the CSS reference pixel), and page 1
// says so. Curves are drawn in their colour, 0.3 mm wide on paper.
#pragma once

#include "geometry/tiling.h"
#include "io/error.h"
#include "io/records.h"

#include <QString>

namespace kontur {

inline constexpr double kPrintLineWidthMm = 0.3;
inline constexpr double kPrintPaddingMm = 5.0; // around the curves' box, so no line is cut at its edge
inline constexpr double kPxPerInch = 96.0;     // io::kCssPixelsPerInch

// Millimetres per document unit (px: 25.4 / 96). 0 for an unknown unit.
[[nodiscard]] double mmPerUnit(const QString &units);

struct PrintPlan
{
    geo::Tiling tiling;
    double mmPerUnit = 1.0;
    double minX = 0.0, maxY = 0.0; // the curves' box corner (document units) at the pattern's (padding, padding)
    // The PDF's pages: the first page (test square and overview) and the tiles.
    [[nodiscard]] int pdfPageCount() const { return tiling.pageCount() + 1; }
};

// The pages of the document's visible curves. Errors: no visible curve with a shape (NoPaths), a
// curve whose shape cannot be built, and the tiling's refusals (InvalidValue).
[[nodiscard]] io::Result<PrintPlan> planPrint(const io::DocumentData &doc, const geo::TilingOptions &options);

// Writes the PDF atomically (the old file stays on failure). `title` names the pattern on page 1 and
// in the metadata. Errors: those of planPrint, CannotWrite.
[[nodiscard]] io::Result<io::Ok> writePatternPdf(const QString &path, const io::DocumentData &doc,
                                                 const geo::TilingOptions &options, const QString &title);

} // namespace kontur
