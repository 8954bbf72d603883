// Printing a pattern at true size over small pages (issue 22): how many pages of a paper size, in
// which orientation, and which part of the pattern each page shows. Pure geometry in millimetres with
// y down (the page's direction); the PDF writer (models/patternpdf.*) draws what this decides.
//
// A page prints its printable area (the page less `margin` on every side, which home printers cannot
// reach). Neighbouring pages repeat `overlap` millimetres of the pattern, so that one page can be laid
// over the next and taped: column c shows x in [c·(w − overlap), c·(w − overlap) + w] for a printable
// width w, rows likewise in y.
#pragma once

#include "geometry/result.h"

#include <string>

namespace kontur::geo {

enum class PageOrientation { Auto, Portrait, Landscape };

struct PaperSize
{
    double width = 210.0;  // mm, portrait
    double height = 297.0; // mm, portrait
};
inline constexpr PaperSize kPaperA4{210.0, 297.0};
inline constexpr PaperSize kPaperLetter{215.9, 279.4}; // 8.5 × 11 in

struct TilingOptions
{
    PaperSize paper = kPaperA4;
    double margin = 10.0;  // mm on every side that is not printed on (printers' unprintable edge)
    double overlap = 10.0; // mm of the pattern repeated on neighbouring pages
    PageOrientation orientation = PageOrientation::Auto;
    int maxPages = 10000; // more is refused (a drawing in the wrong units, not a pattern)
};

// A rectangle of the pattern, mm, y down.
struct TileRect
{
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};

struct Tiling
{
    bool landscape = false;
    double pageWidth = 0.0, pageHeight = 0.0; // the oriented page, mm
    double margin = 0.0, overlap = 0.0;       // as asked
    double cellWidth = 0.0, cellHeight = 0.0; // the printable area of a page, mm
    double patternWidth = 0.0, patternHeight = 0.0;
    int rows = 0, columns = 0;

    [[nodiscard]] int pageCount() const { return rows * columns; }
    // The distance from one page's start to the next one's (printable size less the overlap).
    [[nodiscard]] double stepX() const { return cellWidth - overlap; }
    [[nodiscard]] double stepY() const { return cellHeight - overlap; }
    // The part of the pattern the page in `row`, `column` (0-based) shows.
    [[nodiscard]] TileRect tile(int row, int column) const;
};

// How many pages of printable length `cell` cover `length` when neighbours share `overlap`: 1 when it
// fits, else the least n with n·cell − (n − 1)·overlap ≥ length. Needs cell > overlap ≥ 0.
[[nodiscard]] long long tilesAlong(double length, double cell, double overlap);

// The tiling of a pattern of the given size (mm). Auto orientation takes the one with fewer pages
// (portrait on a tie). Errors (InvalidArgument): a non-finite or negative size, a margin or overlap
// that leaves no room on the page (the overlap must be less than half the printable width and height),
// more than maxPages pages.
[[nodiscard]] Result<Tiling> computeTiling(double patternWidth, double patternHeight, const TilingOptions &options);

// The page's name: its row as letters (A … Z, AA, AB, …) and its column as a number from 1: "B3".
[[nodiscard]] std::string tileLabel(int row, int column);

} // namespace kontur::geo
