// The table of file formats and the one reader over it (see formats.h).
#include "io/formats.h"

#include "io/csv.h"
#include "io/aama.h"
#include "io/dxf.h"
#include "io/pdf.h"
#include "io/pointstext.h"
#include "io/records.h"
#include "io/shapes.h"
#include "io/svg.h"

#include <QFileInfo>

#include <array>

namespace kontur::io {

namespace {

constexpr std::array<FormatInfo, 6> kFormats{{
    {Format::Kontur, "kontur", "kontur", true, "Save",
     "the whole document: every curve exactly (kind, points, nodes, settings), units, background, view"},
    {Format::Pdf, "pdf", "pdf", true, "Print pattern to PDF",
     "the pattern at true size on pages, and the whole document inside it, read back exactly"},
    {Format::PointsText, "txt", "points-text", false, "Append to a points file",
     "curve records (kind, points, name, colour, nodes, settings) appended, or a hand-written list of points"},
    {Format::Csv, "csv", "csv", false, "Export CSV", "the points of one curve, one \"x,y\" row each"},
    {Format::Svg, "svg", "svg", false, "Export SVG",
     "the drawn curves as cubic paths with their colours and names, in real units"},
    {Format::Dxf, "dxf", "dxf", false, "Export DXF",
     "the drawn curves as lines, arcs, splines and polylines on layers with colours, units in $INSUNITS"},
}};

// A plain list of points as the curve of options.kind; the error names the kind and the file.
Result<CurveRecord> curveOfPoints(std::vector<geo::Point> points, const QString &path, const ReadOptions &options)
{
    const KindInfo *info = kindInfo(options.kind);
    auto curve = curveFromPoints(options.kind, info && info->usesParameterization ? options.parameterization : QString(),
                                 std::move(points));
    if (!curve) {
        Error e = curve.error();
        e.file = path;
        e.message = QStringLiteral("as a %1 curve: %2").arg(options.kind, e.message);
        return e;
    }
    return curve;
}

Result<ReadFile> readText(const QString &path, const ReadOptions &options)
{
    auto records = readPointsText(path);
    if (!records)
        return records.error();
    ReadFile out;
    for (TextRecord &r : *records) {
        if (!r.curve.kind.isEmpty()) {
            out.document.curves.push_back(std::move(r.curve));
            continue;
        }
        auto curve = curveOfPoints(std::move(r.curve.points), path, options);
        if (!curve) {
            Error e = curve.error();
            e.line = r.line;
            return e;
        }
        curve->name = r.curve.name;
        out.document.curves.push_back(std::move(curve).value());
    }
    return out;
}

Result<ReadFile> readCsv(const QString &path, const ReadOptions &options)
{
    auto points = readCsvPoints(path);
    if (!points)
        return points.error();
    auto curve = curveOfPoints(std::move(points).value(), path, options);
    if (!curve)
        return curve.error();
    if (options.nameByFile)
        curve->name = QFileInfo(path).completeBaseName();
    ReadFile out;
    out.document.curves.push_back(std::move(curve).value());
    return out;
}

Result<ReadFile> readSvgFile(const QString &path, const ReadOptions &options)
{
    SvgImportOptions svgOptions;
    svgOptions.cubicOnly = options.cubicOnly;
    auto svg = readSvg(path, svgOptions);
    if (!svg)
        return svg.error();
    auto records = importedRecords(svg->curves, path, &compositeRecordFromShape);
    if (!records)
        return records.error();
    ReadFile out;
    out.document.units = svg->units;
    out.document.curves = std::move(records).value();
    out.skipped = svg->skipped;
    out.skippedSummary = skippedSummary(*svg);
    return out;
}

Result<ReadFile> readDxfFile(const QString &path, const ReadOptions &options)
{
    DxfImportOptions dxfOptions;
    dxfOptions.unitlessUnits = options.unitlessUnits;
    auto dxf = readDxf(path, dxfOptions);
    if (!dxf)
        return dxf.error();
    // ASTM D6673 (AAMA) pieces come back as pieces with their marks (io/aama.h).
    auto records = dxfRecords(*dxf, path);
    if (!records)
        return records.error();
    ReadFile out;
    out.document.units = dxf->units;
    out.document.curves = std::move(records).value();
    out.skipped = dxf->skipped;
    out.declaredUnits = dxf->declaredUnits;
    out.skippedSummary = skippedSummary(*dxf);
    return out;
}

Result<ReadFile> readWhole(Result<DocumentData> document)
{
    if (!document)
        return document.error();
    ReadFile out;
    out.document = std::move(document).value();
    return out;
}

} // namespace

std::span<const FormatInfo> formats()
{
    return kFormats;
}

const FormatInfo *formatOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (const FormatInfo &f : kFormats)
        if (suffix == QLatin1String(f.suffix))
            return &f;
    return nullptr;
}

const FormatInfo &infoOf(Format format)
{
    for (const FormatInfo &f : kFormats)
        if (f.format == format)
            return f;
    return kFormats.front(); // unreachable: every Format has its row
}

QString filePatterns(bool documents)
{
    QStringList patterns;
    for (const FormatInfo &f : kFormats)
        if (f.document == documents)
            patterns << QStringLiteral("*.") + QLatin1String(f.suffix);
    return patterns.join(QLatin1Char(' '));
}

QString suffixList()
{
    QStringList suffixes;
    for (const FormatInfo &f : kFormats)
        suffixes << QStringLiteral(".") + QLatin1String(f.suffix);
    return suffixes.join(QStringLiteral(", "));
}

Result<ReadFile> readFile(const QString &path, const ReadOptions &options)
{
    const FormatInfo *format = formatOf(path);
    if (!format && options.otherSuffix)
        format = &infoOf(*options.otherSuffix);
    if (!format) {
        Error e;
        e.code = ErrorCode::CannotOpen;
        e.file = path;
        e.message = QStringLiteral("unknown file type (%1)").arg(suffixList());
        return e;
    }
    Result<ReadFile> read = [&]() -> Result<ReadFile> {
        switch (format->format) {
        case Format::PointsText:
            return readText(path, options);
        case Format::Csv:
            return readCsv(path, options);
        case Format::Kontur:
            return readWhole(openDocument(path));
        case Format::Pdf:
            return readWhole(openPdfDocument(path));
        case Format::Svg:
            return readSvgFile(path, options);
        case Format::Dxf:
            return readDxfFile(path, options);
        }
        return readWhole(openDocument(path)); // unreachable: every Format is read above
    }();
    if (read)
        read->format = format;
    return read;
}

} // namespace kontur::io
