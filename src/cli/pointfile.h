// Reading point lists for kontur-cli: one "x y" pair per line (a comma or semicolon may separate
// them), '#' starts a comment, blank lines are skipped; numbers use '.' whatever the locale. A .txt
// file with Kontur's curve records (as the app appends them) is read by the app's reader
// (io/pointstext.h): the points of its first record, a composite curve's knots.
#pragma once

#include "geometry/bezier.h"

#include <QString>

#include <optional>
#include <string_view>
#include <vector>

namespace kontur::cli {

struct PointFile
{
    std::vector<geo::Point> points;
    QString error; // "FILE:LINE: what is wrong", empty on success
    QString path;  // the file as given, for the messages about its points
    int records = 0;    // the curve records in the file (0: a plain list of points)
    int recordLine = 0; // the line of the record whose points were read
};

[[nodiscard]] PointFile readPointFile(const QString &path);
[[nodiscard]] PointFile parsePoints(std::string_view text, const QString &name);

// "1.5" → 1.5; "x,y" lists for --at and --nearest. Empty optional on malformed text.
[[nodiscard]] std::optional<double> parseNumber(std::string_view s);
[[nodiscard]] std::optional<std::vector<double>> parseNumberList(std::string_view s);

} // namespace kontur::cli
