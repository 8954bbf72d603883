// Tiling a pattern over pages at true size (see tiling.h).
#include "geometry/tiling.h"

#include <algorithm>
#include <cmath>

namespace kontur::geo {

TileRect Tiling::tile(int row, int column) const
{
    return {column * stepX(), row * stepY(), cellWidth, cellHeight};
}

long long tilesAlong(double length, double cell, double overlap)
{
    if (!(length > cell))
        return 1;
    // n·cell − (n − 1)·overlap ≥ length  ⇔  n ≥ (length − overlap) / (cell − overlap). A length a
    // rounding error above a whole number of steps needs no extra page: 1e-9 mm is far below print.
    const double n = (length - overlap) / (cell - overlap);
    if (!(n < 1e15)) // the caller refuses such counts; keep the conversion defined
        return 1000000000000000LL;
    return static_cast<long long>(std::ceil(n - 1e-9));
}

namespace {

struct Candidate
{
    bool landscape;
    double pageWidth, pageHeight, cellWidth, cellHeight;
    long long rows, columns;
};

Candidate candidate(bool landscape, double w, double h, const TilingOptions &o)
{
    Candidate c{};
    c.landscape = landscape;
    c.pageWidth = landscape ? o.paper.height : o.paper.width;
    c.pageHeight = landscape ? o.paper.width : o.paper.height;
    c.cellWidth = c.pageWidth - 2.0 * o.margin;
    c.cellHeight = c.pageHeight - 2.0 * o.margin;
    c.columns = tilesAlong(w, c.cellWidth, o.overlap);
    c.rows = tilesAlong(h, c.cellHeight, o.overlap);
    return c;
}

Error invalid(std::string message)
{
    return Error{ErrorCode::InvalidArgument, std::move(message)};
}

} // namespace

Result<Tiling> computeTiling(double patternWidth, double patternHeight, const TilingOptions &options)
{
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(patternWidth) || !finite(patternHeight) || patternWidth < 0.0 || patternHeight < 0.0)
        return invalid("the pattern's size is not a finite, non-negative number");
    if (!finite(options.paper.width) || !finite(options.paper.height) || !(options.paper.width > 0.0) ||
        !(options.paper.height > 0.0))
        return invalid("the paper size must be positive");
    if (!finite(options.margin) || options.margin < 0.0 || !finite(options.overlap) || options.overlap < 0.0)
        return invalid("the margin and the overlap must be finite and not negative");
    const double shortCell = std::min(options.paper.width, options.paper.height) - 2.0 * options.margin;
    if (!(shortCell > 0.0))
        return invalid("the margins leave no room on the page");
    if (!(2.0 * options.overlap < shortCell))
        return invalid("the overlap must be less than half the printable width of the page");

    const Candidate portrait = candidate(false, patternWidth, patternHeight, options);
    const Candidate landscape = candidate(true, patternWidth, patternHeight, options);
    // Counts in double first: a huge pattern must not overflow the product.
    const auto pages = [](const Candidate &c) { return static_cast<double>(c.rows) * static_cast<double>(c.columns); };
    const Candidate *chosen = &portrait;
    switch (options.orientation) {
    case PageOrientation::Portrait:
        break;
    case PageOrientation::Landscape:
        chosen = &landscape;
        break;
    case PageOrientation::Auto:
        if (pages(landscape) < pages(portrait))
            chosen = &landscape;
        break;
    }
    if (pages(*chosen) > options.maxPages)
        return invalid("the pattern needs more than " + std::to_string(options.maxPages) + " pages");

    Tiling t;
    t.landscape = chosen->landscape;
    t.pageWidth = chosen->pageWidth;
    t.pageHeight = chosen->pageHeight;
    t.margin = options.margin;
    t.overlap = options.overlap;
    t.cellWidth = chosen->cellWidth;
    t.cellHeight = chosen->cellHeight;
    t.patternWidth = patternWidth;
    t.patternHeight = patternHeight;
    t.rows = static_cast<int>(chosen->rows);
    t.columns = static_cast<int>(chosen->columns);
    return t;
}

std::string tileLabel(int row, int column)
{
    // Bijective base 26 (A … Z, AA …), as spreadsheet columns.
    std::string letters;
    for (int n = row + 1; n > 0; n = (n - 1) / 26)
        letters.insert(letters.begin(), static_cast<char>('A' + (n - 1) % 26));
    return letters + std::to_string(column + 1);
}

} // namespace kontur::geo
