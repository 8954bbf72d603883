// The file formats Kontur reads and writes: one table, one row a format (its suffix, its name, what
// reads it, what writes it, what a file of it keeps), and one reader that takes any of them. The app
// (DocumentFiles), kontur-cli and the QML file dialogs (DocumentFiles::filePatterns) all read this
// table; adding a format is one row here and its reader (docs/architecture.md, "Adding a file format").
#pragma once

#include "io/document.h"
#include "io/error.h"
#include "io/skipped.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <span>

namespace kontur::io {

enum class Format { PointsText, Csv, Kontur, Svg, Pdf, Dxf };

struct FormatInfo
{
    Format format;
    const char *suffix; // lower case, without the dot
    const char *name;   // as kontur-cli names it ("points-text")
    bool document;      // Open reads it as a whole document; else its curves are imported into one
    const char *writer; // how the app writes it (Save, Print, Export, Append); kontur-cli convert writes all
    const char *keeps;  // what a file of it keeps (docs/file-formats.md says it in full)
};

// Every format, in the order the dialogs list them: the documents first.
[[nodiscard]] std::span<const FormatInfo> formats();
// The format of a path by its suffix (any case); nullptr when Kontur has none for it.
[[nodiscard]] const FormatInfo *formatOf(const QString &path);
[[nodiscard]] const FormatInfo &infoOf(Format format);
// "*.kontur *.pdf": the patterns of the formats that are documents (`documents`), or of the others.
[[nodiscard]] QString filePatterns(bool documents);
// ".kontur, .pdf, .txt, .csv, .svg, .dxf": every suffix, for a message about an unknown one (no word
// in it, so that it stands in any language).
[[nodiscard]] QString suffixList();

// How the formats without a kind of their own are read.
struct ReadOptions
{
    QString kind = QStringLiteral("composite"); // the curve made of a plain list of points (text, CSV)
    QString parameterization;                   // for that curve, when its kind uses one
    QString unitlessUnits = QStringLiteral("px"); // a DXF's units when its $INSUNITS names none
    bool cubicOnly = false;                       // SVG: quadratic pieces elevated, as a composite curve takes them
    bool nameByFile = false; // a CSV file's curve is named after the file (kontur-cli); else unnamed
    // How a path of no suffix of the table is read (the app reads any other file as points text, the
    // form of a hand-written list); none: refused, naming the suffixes (kontur-cli).
    std::optional<Format> otherSuffix;
};

struct ReadFile
{
    const FormatInfo *format = nullptr;
    DocumentData document;       // the curves (and for a document, everything else it keeps)
    SkippedCounts skipped{};     // what a drawing held that was not read (SVG, DXF)
    bool declaredUnits = true;   // false: a DXF named no units, `document.units` is ReadOptions::unitlessUnits
    QString skippedSummary;      // the skipped in English for kontur-cli; empty when none
};

// Any format of the table, by its suffix. A path of no known suffix is read as options.otherSuffix,
// or else is CannotOpen, naming the suffixes.
[[nodiscard]] Result<ReadFile> readFile(const QString &path, const ReadOptions &options = {});

} // namespace kontur::io
