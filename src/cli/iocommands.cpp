// kontur-cli convert / info (see iocommands.h): the format is chosen by the file's extension
// (.txt points text, .csv, .kontur, .svg, .dxf, .pdf); points without a kind become curves of --kind. A
// .pdf output is the pattern printed at true size (src/print/patternpdf.h); a .pdf input is one Kontur wrote.
#include "cli/iocommands.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "geometry/piecewise.h"
#include "geometry/seams.h"
#include "io/aama.h"
#include "io/csv.h"
#include "io/document.h"
#include "io/dxf.h"
#include "io/formats.h"
#include "io/pdf.h"
#include "io/piece.h"
#include "io/pointstext.h"
#include "io/seam.h"
#include "io/shapes.h"
#include "io/svg.h"
#include "print/patternpdf.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>

#include <cmath>
#include <cstdio>

namespace kontur::cli {

namespace {

// The io error, with its place and its code name, as one line (beside cli::fail for plain texts). An
// error that names no file is about `file` (every error about a file names it).
using cli::fail;
int fail(io::Error error, const QString &file)
{
    if (error.file.isEmpty())
        error.file = file;
    return fail(error.toString() + QStringLiteral(" [") + QLatin1String(io::codeName(error.code)) + QLatin1Char(']'));
}

// The formats are io/formats.h's table: the same suffixes, names and readers as the app's.
using io::Format;

// The name of a path's format ("points-text"), "unknown" when it has none.
const char *formatName(const QString &path)
{
    const io::FormatInfo *f = io::formatOf(path);
    return f ? f->name : "unknown";
}

// "FILE: unknown file type (.kontur, .pdf, …)", in the user's language.
QString unknownType(const QString &path)
{
    return tr("%1: unknown file type (%2)").arg(path, io::suffixList());
}

struct LoadOptions
{
    QString kind = QStringLiteral("composite"); // for points without a kind
    QString parameterization = QStringLiteral("chord");
    QString units = QStringLiteral("px"); // of a DXF that names none
};

// Any file of the table as a document (io::readFile, the app's reader too); points of unknown kind
// become curves of options.kind. What a drawing held that was not read is said on stderr.
io::Result<io::DocumentData> load(const QString &path, const LoadOptions &options)
{
    io::ReadOptions read;
    read.kind = options.kind;
    read.parameterization = options.parameterization;
    read.unitlessUnits = options.units;
    read.nameByFile = true;
    auto file = io::readFile(path, read);
    if (!file)
        return file.error();
    if (!file->skippedSummary.isEmpty())
        QTextStream(stderr) << "kontur-cli: " << tr("%1: not drawn: %2").arg(path, file->skippedSummary) << '\n';
    return std::move(file->document);
}

io::Result<geo::PiecewiseBezier> shapeOf(const io::CurveRecord &c, std::size_t index)
{
    auto shape = io::curveShape(c);
    if (!shape) {
        io::Error e = shape.error();
        e.path = QStringLiteral("curves[%1]").arg(index);
        return e;
    }
    return shape;
}

int save(const io::DocumentData &doc, const QString &path, int curveIndex, const geo::TilingOptions &print,
         const io::DxfExportOptions &dxfOptions)
{
    const io::FormatInfo *format = io::formatOf(path);
    if (!format)
        return fail(unknownType(path), 2);
    switch (format->format) {
    case Format::PointsText:
        // The points text format only ever appends (docs/requirements.md 1.5, seed T09).
        for (std::size_t i = 0; i < doc.curves.size(); ++i) {
            const io::CurveRecord &c = doc.curves[i];
            std::vector<geo::Point> derived;
            if (const io::KindInfo *info = io::kindInfo(c.kind); info && info->usesParameterization)
                if (auto shape = io::curveShape(c); shape && !shape->isEmpty())
                    derived = shape->segments().front().controlPoints();
            if (curveIndex >= 0 && static_cast<int>(i) != curveIndex)
                continue;
            if (auto r = io::appendPointsRecord(path, c, derived); !r)
                return fail(r.error(), path);
        }
        return 0;
    case Format::Csv: {
        if (curveIndex < 0 && doc.curves.size() != 1)
            return fail(tr("%1: a CSV file holds the points of one curve; the input has %2: choose one with --curve N")
                            .arg(path)
                            .arg(doc.curves.size()));
        const std::size_t i = curveIndex < 0 ? 0 : static_cast<std::size_t>(curveIndex);
        if (auto r = io::writeCsvPoints(path, doc.curves[i].points); !r)
            return fail(r.error(), path);
        return 0;
    }
    case Format::Kontur:
        if (auto r = io::saveDocument(path, doc); !r)
            return fail(r.error(), path);
        return 0;
    case Format::Svg: {
        auto curves = io::curvesToExport(doc.curves, curveIndex);
        if (!curves)
            return fail(curves.error(), path);
        io::SvgExportOptions options;
        options.units = doc.units;
        if (auto r = io::writeSvg(path, *curves, options); !r)
            return fail(r.error(), path);
        return 0;
    }
    case Format::Pdf: {
        io::DocumentData printed = doc;
        if (curveIndex >= 0)
            printed.curves = {doc.curves[static_cast<std::size_t>(curveIndex)]};
        if (auto r = writePatternPdf(path, printed, print, QFileInfo(path).completeBaseName()); !r)
            return fail(r.error(), path);
        return 0;
    }
    case Format::Dxf: {
        auto curves = io::curvesToExport(doc.curves, curveIndex);
        if (!curves)
            return fail(curves.error(), path);
        io::DxfExportOptions options = dxfOptions;
        options.units = doc.units;
        if (options.aama) {
            auto pieces = io::aamaPieces(doc.curves);
            if (!pieces)
                return fail(pieces.error(), path);
            if (auto r = io::writeAamaDxf(path, *pieces, options); !r)
                return fail(r.error(), path);
            // No grain line is invented for a piece without one; say which pieces lack it.
            if (const auto bare = io::piecesWithoutGrainline(*pieces); !bare.empty()) {
                QStringList names;
                for (const QString &name : bare)
                    names << (name.isEmpty() ? QStringLiteral("-") : name);
                QTextStream(stderr) << "kontur-cli: "
                                    << tr("%1: no grain line written for pieces without a grainline: %2")
                                           .arg(path, names.join(QStringLiteral(", ")))
                                    << '\n';
            }
            return 0;
        }
        if (auto r = io::writeDxf(path, *curves, options); !r)
            return fail(r.error(), path);
        return 0;
    }
    }
    return fail(unknownType(path), 2); // unreachable: every format of the table is written above
}

// --kind and --param, for the points that carry no kind: the same two options in every command that
// reads files.
QList<QCommandLineOption> loadOptionDefinitions()
{
    return {
        {QStringLiteral("kind"), tr("Kind of curve for points without one (default composite)."),
         QStringLiteral("kind"), QStringLiteral("composite")},
        {QStringLiteral("param"), tr("Parameterization for fitted kinds (default chord)."), QStringLiteral("param"),
         QStringLiteral("chord")},
        {QStringLiteral("units"), tr("Units of a DXF that names none: mm, cm, in or px (default px)."),
         QStringLiteral("units"), QStringLiteral("px")},
    };
}

// Reads --kind (a kind of the file formats) and --param; returns 0 or the exit code of the usage error.
int readLoadOptions(const QCommandLineParser &parser, LoadOptions &options)
{
    options.kind = parser.value(QStringLiteral("kind"));
    if (!io::kindInfo(options.kind))
        return fail(tr("unknown --kind \"%1\"").arg(options.kind), 2);
    geo::Parameterization param;
    if (const int code = readParam(parser, param); code != 0)
        return code;
    options.parameterization = QString::fromLatin1(geo::nameOf(param));
    options.units = parser.value(QStringLiteral("units")).toLower();
    if (!QStringList{QStringLiteral("mm"), QStringLiteral("cm"), QStringLiteral("in"), QStringLiteral("px")}.contains(
            options.units))
        return fail(tr("--units needs mm, cm, in or px"), 2);
    return 0;
}

// --paper, --orientation and --overlap of a PDF output.
int readPrintOptions(const QCommandLineParser &parser, geo::TilingOptions &options)
{
    const QString paper = parser.value(QStringLiteral("paper")).toLower();
    if (paper == QLatin1String("a4"))
        options.paper = geo::kPaperA4;
    else if (paper == QLatin1String("letter"))
        options.paper = geo::kPaperLetter;
    else
        return fail(tr("--paper needs a4 or letter"), 2);
    const QString orientation = parser.value(QStringLiteral("orientation")).toLower();
    if (orientation == QLatin1String("auto"))
        options.orientation = geo::PageOrientation::Auto;
    else if (orientation == QLatin1String("portrait"))
        options.orientation = geo::PageOrientation::Portrait;
    else if (orientation == QLatin1String("landscape"))
        options.orientation = geo::PageOrientation::Landscape;
    else
        return fail(tr("--orientation needs auto, portrait or landscape"), 2);
    bool ok = false;
    options.overlap = parser.value(QStringLiteral("overlap")).toDouble(&ok);
    // Up to 50 mm: less than half the printable width of A4 and Letter (190 and 195.9 mm).
    if (!ok || !(options.overlap >= 0.0 && options.overlap <= 50.0))
        return fail(tr("--overlap needs millimetres from 0 to 50"), 2);
    return 0;
}

// "bbox": [min x, min y, max x, max y].
void writeBox(Json &json, const geo::Box &box)
{
    json.key("bbox")
        .beginArray()
        .value(box.min().x())
        .value(box.min().y())
        .value(box.max().x())
        .value(box.max().y())
        .endArray();
}

} // namespace

int runConvert(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Convert between points text (.txt), CSV, Kontur documents (.kontur), SVG and DXF, by extension.\n"
           "A .txt output is appended to, never overwritten; other outputs are replaced atomically.\n"
           "A .pdf output prints the visible curves at true size over A4 or Letter pages (a first page with\n"
           "a 10 cm test square and the overview, then the pages to tape together); the document is kept\n"
           "inside, so a PDF Kontur wrote converts back."));
    parser.addPositionalArgument(QStringLiteral("in"), tr("The input file."));
    parser.addPositionalArgument(QStringLiteral("out"), tr("The output file."));
    parser.addOptions(loadOptionDefinitions());
    parser.addOption({QStringLiteral("curve"), tr("Write only curve N (0-based)."), QStringLiteral("n")});
    parser.addOption({QStringLiteral("paper"), tr("PDF: the paper, a4 or letter (default a4)."),
                      QStringLiteral("paper"), QStringLiteral("a4")});
    parser.addOption({QStringLiteral("orientation"),
                      tr("PDF: auto (the one with fewer pages), portrait or landscape (default auto)."),
                      QStringLiteral("orientation"), QStringLiteral("auto")});
    parser.addOption({QStringLiteral("overlap"), tr("PDF: millimetres neighbouring pages repeat (default 10)."),
                      QStringLiteral("mm"), QStringLiteral("10")});
    parser.addOption({QStringLiteral("dxf"),
                      tr("DXF output: spline (exact Bézier control points, default) or polyline (flattened)."),
                      QStringLiteral("flavour"), QStringLiteral("spline")});
    parser.addOption({QStringLiteral("aama"),
                      tr("DXF output as ASTM D6673 (AAMA) garment pieces: a block per closed curve, its cut line "
                         "(its seam allowance, if any) and texts on layer 1, sew line 14, notches 4, mirror line 6, "
                         "the piece's own grain line 7 (none if it has none), internal lines 8, drill holes 13; "
                         "polylines unless --dxf spline is given.")});
    parser.addOption({QStringLiteral("tolerance"),
                      tr("DXF polyline output: largest distance from the curves, in the document's units "
                         "(default 0.05 mm)."),
                      QStringLiteral("t")});
    if (const int code = parseCommandLine(parser, args, 2); code != 0)
        return code < 0 ? 0 : code;
    geo::TilingOptions print;
    if (const int code = readPrintOptions(parser, print); code != 0)
        return code;
    LoadOptions options;
    if (const int code = readLoadOptions(parser, options); code != 0)
        return code;
    io::DxfExportOptions dxfOptions;
    if (const QString flavour = parser.value(QStringLiteral("dxf")); flavour == QLatin1String("polyline"))
        dxfOptions.flavour = io::DxfFlavour::Polyline;
    else if (flavour != QLatin1String("spline"))
        return fail(tr("unknown --dxf \"%1\" (spline or polyline)").arg(flavour), 2);
    if (parser.isSet(QStringLiteral("aama"))) {
        dxfOptions.aama = true;
        if (!parser.isSet(QStringLiteral("dxf")))
            dxfOptions.flavour = io::DxfFlavour::Polyline; // what the standard's readers expect
    }
    if (parser.isSet(QStringLiteral("tolerance"))) {
        bool ok = false;
        dxfOptions.tolerance = parser.value(QStringLiteral("tolerance")).toDouble(&ok);
        if (!ok || !(dxfOptions.tolerance > 0) || !std::isfinite(dxfOptions.tolerance))
            return fail(tr("--tolerance needs a positive number"), 2);
    }
    const QString in = parser.positionalArguments().at(0), out = parser.positionalArguments().at(1);
    for (const QString &file : {in, out})
        if (!io::formatOf(file))
            return fail(unknownType(file), 2);
    int curveIndex = -1;
    auto doc = load(in, options);
    if (!doc)
        return fail(doc.error(), in);
    if (parser.isSet(QStringLiteral("curve"))) {
        bool ok = false;
        curveIndex = parser.value(QStringLiteral("curve")).toInt(&ok);
        if (!ok || curveIndex < 0 || curveIndex >= static_cast<int>(doc->curves.size()))
            return fail(tr("--curve needs a curve number from 0 to %1").arg(static_cast<int>(doc->curves.size()) - 1),
                        2);
    }
    if (const int code = save(*doc, out, curveIndex, print, dxfOptions); code != 0)
        return code;
    Json json;
    json.beginObject().key("input").value(in.toStdString()).key("output").value(out.toStdString());
    json.key("curves").value(static_cast<long long>(curveIndex >= 0 ? 1 : doc->curves.size())).endObject();
    return printResult(json);
}

void describeDocument(Json &json, const QString &path, const io::DocumentData &doc, double accuracy)
{
    json.beginObject();
    json.key("file").value(path.toStdString());
    json.key("format").value(formatName(path));
    json.key("units").value(doc.units.toStdString());
    geo::Box all;
    json.key("curves").beginArray();
    for (std::size_t i = 0; i < doc.curves.size(); ++i) {
        const io::CurveRecord &c = doc.curves[i];
        json.beginObject();
        json.key("index").value(static_cast<long long>(i));
        json.key("name").value(c.name.toStdString());
        json.key("kind").value(c.kind.toStdString());
        if (!c.parameterization.isEmpty())
            json.key("parameterization").value(c.parameterization.toStdString());
        json.key("closed").value(c.closed);
        json.key("points").value(static_cast<long long>(c.points.size()));
        if (c.kind == QLatin1String("composite"))
            json.key("knots").value(io::compositeKnotCount(c.points.size(), c.closed));
        auto shape = shapeOf(c, i);
        if (!shape) {
            json.key("error").value(shape.error().message.toStdString());
            json.endObject();
            continue;
        }
        json.key("segments").value(shape->segmentCount());
        // The accuracy reached is reported beside the length: at coordinates where doubles cannot
        // resolve the one asked, it is raised to what they can (never silently worse than stated).
        const geo::LengthEstimate length = shape->lengthEstimate(accuracy);
        json.key("length").value(length.length);
        json.key("length_accuracy").value(length.accuracy);
        const geo::Box box = shape->boundingBox();
        all.extend(box);
        writeBox(json, box);
        // The weakest joint says what the curve is honestly (docs/requirements.md 1.2: composite curves are G1).
        geo::Continuity weakest = geo::Continuity::C2;
        const auto joints = shape->continuity();
        for (const geo::JointContinuity &j : joints)
            weakest = std::min(weakest, j.level);
        json.key("joints").value(static_cast<long long>(joints.size()));
        json.key("continuity").value(joints.empty() ? "C2" : geo::nameOf(weakest));
        json.endObject();
    }
    json.endArray();
    if (!all.isEmpty())
        writeBox(json, all);
    json.endObject();
}

int runOffset(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Add seam allowances: the offset of each curve (or of curve N) at a distance, written after the\n"
           "input's curves. In a .kontur output each allowance keeps its link to its curve."));
    parser.addPositionalArgument(QStringLiteral("in"), tr("The input file."));
    parser.addPositionalArgument(QStringLiteral("out"), tr("The output file."));
    parser.addOptions(loadOptionDefinitions());
    parser.addOption({QStringLiteral("curve"), tr("Offset only curve N (0-based)."), QStringLiteral("n")});
    parser.addOption(
        {QStringLiteral("distance"), tr("Distance in the document's units (default 1 cm)."), QStringLiteral("d")});
    parser.addOption({QStringLiteral("side"), tr("outside, inside, left or right (default outside)."),
                      QStringLiteral("side"), QStringLiteral("outside")});
    parser.addOption({QStringLiteral("join"), tr("Corners: miter, bevel or round (default miter)."),
                      QStringLiteral("join"), QStringLiteral("miter")});
    parser.addOption(
        {QStringLiteral("miter-limit"), tr("Longest miter from the corner (default 3 cm)."), QStringLiteral("length")});
    parser.addOption(
        {QStringLiteral("tolerance"), tr("Largest error of the offset (default 0.05 mm)."), QStringLiteral("t")});
    if (const int code = parseCommandLine(parser, args, 2); code != 0)
        return code < 0 ? 0 : code;
    LoadOptions options;
    if (const int code = readLoadOptions(parser, options); code != 0)
        return code;
    const QString in = parser.positionalArguments().at(0), out = parser.positionalArguments().at(1);
    for (const QString &file : {in, out})
        if (!io::formatOf(file))
            return fail(unknownType(file), 2);
    auto doc = load(in, options);
    if (!doc)
        return fail(doc.error(), in);
    geo::OffsetOptions offset = io::defaultSeamOptions(doc->units);
    const auto positive = [&](const char *name, double &value, bool zeroAllowed) {
        if (!parser.isSet(QLatin1String(name)))
            return true;
        bool ok = false;
        const double v = parser.value(QLatin1String(name)).toDouble(&ok);
        if (!ok || !std::isfinite(v) || v < 0 || (v == 0 && !zeroAllowed))
            return false;
        value = v;
        return true;
    };
    if (!positive("distance", offset.distance, false))
        return fail(tr("--distance needs a positive number"), 2);
    if (!positive("miter-limit", offset.miterLimit, true))
        return fail(tr("--miter-limit needs a number of at least 0"), 2);
    if (!positive("tolerance", offset.tolerance, false))
        return fail(tr("--tolerance needs a positive number"), 2);
    if (!geo::offsetSideFromId(parser.value(QStringLiteral("side")).toStdString(), offset.side))
        return fail(tr("unknown --side \"%1\"").arg(parser.value(QStringLiteral("side"))), 2);
    if (!geo::offsetJoinFromId(parser.value(QStringLiteral("join")).toStdString(), offset.join))
        return fail(tr("unknown --join \"%1\"").arg(parser.value(QStringLiteral("join"))), 2);
    const int count = static_cast<int>(doc->curves.size());
    int only = -1;
    if (parser.isSet(QStringLiteral("curve"))) {
        bool ok = false;
        only = parser.value(QStringLiteral("curve")).toInt(&ok);
        if (!ok || only < 0 || only >= count)
            return fail(tr("--curve needs a curve number from 0 to %1").arg(count - 1), 2);
    }
    Json json;
    json.beginObject().key("input").value(in.toStdString()).key("output").value(out.toStdString());
    json.key("units").value(doc->units.toStdString());
    json.key("distance").value(offset.distance).key("side").value(geo::offsetSideId(offset.side));
    json.key("join").value(geo::offsetJoinId(offset.join)).key("miter_limit").value(offset.miterLimit);
    json.key("tolerance").value(offset.tolerance);
    json.key("allowances").beginArray();
    for (int i = 0; i < count; ++i) {
        if (only >= 0 && i != only)
            continue;
        auto shape = shapeOf(doc->curves[static_cast<std::size_t>(i)], static_cast<std::size_t>(i));
        if (!shape)
            return fail(shape.error(), in);
        // A piece with widths per seam gets them, as the app computes its allowance.
        geo::OffsetOptions used = offset;
        const auto marks = io::pieceFromSettings(doc->curves[static_cast<std::size_t>(i)].settings);
        if (marks && (!marks->seamWidths.empty() || !marks->hems.empty()) && shape->isClosed()) {
            const std::vector<geo::SeamSpan> seams = geo::seamSpans(*shape);
            used.segmentDistances =
                geo::segmentDistancesOf(shape->segmentCount(), seams, marks->seamWidths, offset.distance);
            if (!marks->hems.empty())
                used.hems = geo::segmentHemsOf(shape->segmentCount(), seams, marks->hems);
        }
        QElapsedTimer timer;
        timer.start();
        auto result = geo::offsetCurve(*shape, used);
        const double ms = static_cast<double>(timer.nsecsElapsed()) / 1e6;
        if (!result.ok())
            return fail(tr("%1: curve %2: %3").arg(in).arg(i).arg(QString::fromStdString(result.error().message)));
        auto record = io::compositeRecordFromShape(result->curve);
        if (!record)
            return fail(record.error(), in);
        const io::CurveRecord &source = doc->curves[static_cast<std::size_t>(i)];
        record->name = source.name.isEmpty() ? QStringLiteral("Seam allowance") : source.name + QStringLiteral(" +");
        record->color = source.color;
        record->settings.insert(QLatin1String(io::kSeamKey), io::seamToJson({i, offset}));
        json.beginObject().key("source").value(static_cast<long long>(i));
        json.key("index").value(static_cast<long long>(doc->curves.size()));
        json.key("segments").value(result->curve.segmentCount()).key("closed").value(result->curve.isClosed());
        json.key("length").value(result->curve.length(1e-9));
        json.key("loops_removed").value(result->loopsRemoved).key("parts_dropped").value(result->partsDropped);
        // The tolerance used: the one asked, or what doubles resolve at this size when that is finer.
        json.key("tolerance_used").value(result->tolerance);
        json.key("milliseconds").value(ms);
        json.endObject();
        doc->curves.push_back(std::move(record).value());
    }
    json.endArray().endObject();
    if (const int code = save(*doc, out, -1, geo::TilingOptions{}, io::DxfExportOptions{}); code != 0)
        return code;
    return printResult(json);
}

int runInfo(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(tr("Describe the curves of a file as JSON: kinds, point counts, lengths, "
                                        "bounding boxes, continuity."));
    parser.addPositionalArgument(QStringLiteral("file"), tr("A .txt, .csv, .kontur, .svg or .dxf file."));
    parser.addOptions(loadOptionDefinitions());
    parser.addOption({QStringLiteral("accuracy"), tr("Absolute accuracy of the lengths (default 1e-9)."),
                      QStringLiteral("a"), QStringLiteral("1e-9")});
    if (const int code = parseCommandLine(parser, args, 1); code != 0)
        return code < 0 ? 0 : code;
    LoadOptions options;
    if (const int code = readLoadOptions(parser, options); code != 0)
        return code;
    bool ok = false;
    const double accuracy = parser.value(QStringLiteral("accuracy")).toDouble(&ok);
    if (!ok || !(accuracy > 0))
        return fail(tr("--accuracy needs a positive number"), 2);
    const QString path = parser.positionalArguments().at(0);
    auto doc = load(path, options);
    if (!doc)
        return fail(doc.error(), path);

    Json json;
    describeDocument(json, path, *doc, accuracy);
    return printResult(json);
}

} // namespace kontur::cli
