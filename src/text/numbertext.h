// Numbers as the user reads and types them: in the UI language's format (QLocale's default), or
// with a decimal point as in files. The one place that parses typed numbers and formats shown ones,
// below the models so that the pattern PDF (src/print) writes its numbers the same way; the QML
// singleton Numbers (models/text/numbers.h) hands them to QML.
#pragma once

#include "geometry/bezier.h"

#include <QLocale>
#include <QString>
#include <QVariant>

#include <vector>

namespace kontur {

// What became of a typed number.
enum class Parsed {
    Number,   // a finite double
    NotValid, // empty, not a number, or NaN / infinity spelled out
    TooLarge, // a number beyond the largest double (1e400): refused, never stored as infinity
};

// A number typed by the user (a text, or a number QML passed as such): the double nearest to the
// text, never rounded to what a view shows. A text is read in the UI language's format (QLocale's
// default) or else with a decimal point as in files; a typographic minus (U+2212) reads as "-", and
// spaces (plain, no-break or narrow no-break) between groups of three digits of the integer part
// group thousands ("1 234,5" in Latvian, "12 345 678" in any language).
[[nodiscard]] Parsed parseNumber(const QVariant &value, double &out);
// The same in the format of `locale` (and else with a decimal point).
[[nodiscard]] Parsed parseNumber(const QString &text, const QLocale &locale, double &out);
// Several typed numbers separated by spaces, semicolons, or commas where the comma is not the
// locale's decimal separator ("3; 2; -1; 0,5" in Latvian, "3, 2, -1, 0.5" in English). On failure,
// `badToken` (if given) is the first token that is not a number; `out` holds the numbers before it.
[[nodiscard]] Parsed parseNumberList(const QString &text, const QLocale &locale, std::vector<double> &out,
                                     QString *badToken = nullptr);
// One token of a typed list of numbers (split as parseNumberList splits), where it stands in the text:
// `start` and `length` in QString units; `isNumber` when it reads as a number (`value`), and the
// decimals it shows (shownDecimals).
struct ListToken
{
    qsizetype start = 0;
    qsizetype length = 0;
    bool isNumber = false;
    double value = 0.0;
    int decimals = 0;
};
[[nodiscard]] std::vector<ListToken> numberListTokens(const QString &text, const QLocale &locale);
// The decimals a typed number shows: "3" 0, "0,5" 1, "2.75" 2, "1,5e-2" 3 (never below 0, at most 17).
[[nodiscard]] int shownDecimals(const QString &token, const QLocale &locale);
// What one tap of a stepper adds to a typed number: a unit of its last shown decimal, but at least
// 10^-maxDecimals (a value shown with 4 decimals is not stepped by 0.0001, which no plot shows).
[[nodiscard]] double stepFor(const ListToken &token, int maxDecimals);
// The typed list with only its `index`-th number changed by `direction` (+1 or -1) steps (stepFor),
// written in `locale`'s format with the decimals it showed; every other character stays as typed.
// Empty when `index` is not a number of the list or the result would not be finite.
[[nodiscard]] QString stepListNumber(const QString &text, const QLocale &locale, int index, int direction,
                                     int maxDecimals);

// Typed points: `rows` lists [x, y] pairs of typed numbers. NotValid for a row that is not a pair;
// the first failure decides (NotValid before TooLarge within a row).
[[nodiscard]] Parsed parsePoints(const QVariantList &rows, std::vector<geo::Point> &out);

// A number as the side panel shows it, in the UI language's format (QLocale's default): at most
// `decimals` decimals and 7 significant digits from 10^-decimals up to 1e9 (1,234.568, 12,345.68,
// 10,000,123), in exponent form with 3 significant digits beyond (1e+300, -1.23e-6); so a table
// cell never overflows (at most 12 narrow characters) and a tiny value never reads as 0. Shown values are
// rounded; stored ones never are. "—" for a value that is not finite.
[[nodiscard]] QString displayNumber(double value, int decimals);
// Every digit of a number, in the UI language's format without group separators: the shortest text
// that reads back as the same double (for editing a cell, and for the clipboard).
[[nodiscard]] QString exactNumber(double value);

// How fixedNumber writes: with the locale's group separators (a length in a bar), or without (a list
// the user edits, where "1 234" or "1,234" would read as two numbers); with every decimal asked for (a
// column, an axis), or without trailing zeros (typed numbers come back as typed).
struct NumberStyle
{
    bool grouping = true;
    bool trailingZeros = true;
};
// A number with `decimals` decimals in `locale`'s format (the UI language's by default). A value that
// rounds to zero shows no minus sign; "—" for a value that is not finite. The one formatter of fixed
// decimals: bars, plots' axes and read-outs, lists of numbers, lengths with their units.
[[nodiscard]] QString fixedNumber(double value, int decimals, const QLocale &locale = QLocale(),
                                  NumberStyle style = {});
// A number to `digits` significant digits (1.23e+12, 0.000123, 130), in `locale`'s format, no leading
// zero in the exponent; "—" for a value that is not finite. For scales, errors and factors.
[[nodiscard]] QString significantNumber(double value, int digits, const QLocale &locale = QLocale());

} // namespace kontur
