// kontur-cli trace PHOTO --sheet SIZE [--corners x,y;x,y;x,y;x,y] [--json] [OUT.kontur]: the photo read
// as the app reads it (picture/picture.h: EXIF orientation, HEIC), in colour, traced by
// vision/tracephoto.h (sheet, rectification, outlines); the outlines written as composite curves in mm
// over the calibrated photo. --json prints the sheet whenever one was found, pieces or not.
#include "cli/tracecommand.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "cli/pointfile.h"
#include "io/document.h"
#include "picture/photomat.h"
#include "picture/picture.h"
#include "vision/sheet.h"
#include "vision/tracephoto.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QRegularExpression>

namespace kontur::cli {
namespace {

// What the sheet finder's refusal means to the user, and what to do: the messages name --corners.
QString sheetProblem(const vision::Error &error, const QString &path, const QString &sheetName, geo::Point sizeMm)
{
    switch (error.code) {
    case vision::ErrorCode::SheetNotFlat:
        return tr("%1: the sheet is not flat (its edges are not straight); lay it flat and photograph it again, "
                  "or give its four corners roughly with --corners x,y;x,y;x,y;x,y")
            .arg(path);
    case vision::ErrorCode::WrongProportions:
        //: %2 and %4 are proportions such as 2.35 and 1.41 (long side : short side), %3 the sheet's size as given.
        return tr("%1: the rectangle found is about %2 : 1, not %3 (%4 : 1); give the sheet's size with --sheet, "
                  "or its four corners roughly with --corners x,y;x,y;x,y;x,y")
            .arg(path, QString::number(error.seenAspect, 'f', 2), sheetName,
                 QString::number(std::max(sizeMm.x(), sizeMm.y()) / std::min(sizeMm.x(), sizeMm.y()), 'f', 2));
    default:
        return tr("%1: no reference sheet found (a white rectangle with four straight, clear edges); give its four "
                  "corners roughly with --corners x,y;x,y;x,y;x,y")
            .arg(path);
    }
}

// "x,y;x,y;x,y;x,y" (or the points separated by spaces): four points.
std::optional<std::array<geo::Point, 4>> parseCorners(const QString &text)
{
    static const QRegularExpression separator(QStringLiteral("[;\\s]+"));
    const QStringList parts = text.trimmed().split(separator, Qt::SkipEmptyParts);
    if (parts.size() != 4)
        return std::nullopt;
    std::array<geo::Point, 4> out;
    for (int i = 0; i < 4; ++i) {
        auto numbers = parseNumberList(parts[i].toStdString());
        if (!numbers || numbers->size() != 2 || !std::isfinite((*numbers)[0]) || !std::isfinite((*numbers)[1]))
            return std::nullopt;
        out[i] = geo::Point((*numbers)[0], (*numbers)[1]);
    }
    return out;
}

// A traced outline as a composite curve record in mm (the repeated first knot not stored).
io::CurveRecord curveRecord(const vision::Outline &outline, int number)
{
    io::CurveRecord record;
    record.kind = QStringLiteral("composite");
    //: Automatic name of a curve traced along a piece's outline in the photo: %1 is a running number.
    record.name = tr("Outline %1").arg(number);
    record.closed = outline.closed;
    record.points = outline.control;
    if (outline.closed && !record.points.empty())
        record.points.pop_back();
    for (int k = 0; k < outline.knotCount(); ++k)
        record.nodeTypes.push_back(outline.corner.at(static_cast<std::size_t>(k)) ? QStringLiteral("corner")
                                                                                  : QStringLiteral("smooth"));
    return record;
}

} // namespace

int runTrace(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Trace a pattern photographed beside a reference sheet: the sheet is found (its corners to a\n"
           "fraction of a pixel), the photo rectified into the sheet's plane and every pattern piece's outline\n"
           "written as a closed composite curve in mm to OUT.kontur, with the photo as its calibrated\n"
           "background. --json prints the corners, the calibration's estimated error and each curve's knots."));
    parser.addPositionalArgument(QStringLiteral("photo"), tr("The photo (PNG, JPEG, PGM, ...)."));
    parser.addPositionalArgument(QStringLiteral("out"), tr("The document to write (.kontur)."),
                                 QStringLiteral("[OUT.kontur]"));
    parser.addOption({QStringLiteral("sheet"),
                      tr("The sheet's size: a4, a3, letter or WxH with mm (default), cm or in."),
                      QStringLiteral("size"), QStringLiteral("a4")});
    parser.addOption({QStringLiteral("corners"),
                      tr("Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are "
                         "searched near them."),
                      QStringLiteral("points")});
    parser.addOption({QStringLiteral("json"), tr("Print the sheet's corners, the calibration error and the "
                                                 "outlines' knots as JSON.")});
    // One file name (the photo) or two (and the document to write).
    (void)parser.parse(args);
    const int files = parser.positionalArguments().size() >= 2 ? 2 : 1;
    if (const int code = parseCommandLine(parser, args, files); code != 0)
        return code < 0 ? 0 : code;
    const QStringList positional = parser.positionalArguments();
    const QString out = positional.value(1);
    const bool asJson = parser.isSet(QStringLiteral("json"));
    if (out.isEmpty() && !asJson)
        return fail(tr("trace needs an output file OUT.kontur, or --json for the sheet's corners"), 2);
    const auto size = vision::parseSheetSize(parser.value(QStringLiteral("sheet")).toStdString());
    if (!size)
        return fail(
            tr("--sheet needs a4, a3, letter or WxH[mm|cm|in], got \"%1\"").arg(parser.value(QStringLiteral("sheet"))),
            2);
    vision::PhotoTraceOptions options;
    options.sheet.sizeMm = *size;
    if (parser.isSet(QStringLiteral("corners"))) {
        options.sheet.cornerHints = parseCorners(parser.value(QStringLiteral("corners")));
        if (!options.sheet.cornerHints)
            return fail(tr("--corners needs four points x,y separated by semicolons or spaces"), 2);
    }
    const QString path = positional.at(0);
    QElapsedTimer total;
    total.start();
    const ImageRead read = readImage(path);
    if (!read.ok())
        return fail(tr("%1: cannot read the photo").arg(path));
    const cv::Mat photo = bgrMat(read.image);
    options.sheet.focalPx = read.focalPx();

    QElapsedTimer timer;
    timer.start();
    const auto found = vision::findSheet(photo, options.sheet);
    if (!found)
        return fail(sheetProblem(found.error(), path, parser.value(QStringLiteral("sheet")), *size));
    // The sheet alone: all that is wanted without an output file, and what is said when no piece is found.
    vision::PhotoTrace sheetOnly;
    sheetOnly.sheet = *found;
    sheetOnly.calibrationErrorMm = vision::calibrationErrorAtPhotoCornersMm(*found, photo.size());
    vision::Result<vision::PhotoTrace> traced =
        out.isEmpty() ? vision::Result<vision::PhotoTrace>(sheetOnly) : vision::tracePieces(photo, *found, options);
    const double ms = timer.nsecsElapsed() / 1e6;
    const bool noPiece = !traced && traced.error().code == vision::ErrorCode::NoPieceFound;
    if (!traced && !noPiece)
        return fail(tr("%1: %2").arg(path, QString::fromStdString(traced.error().message)));
    if (noPiece)
        traced = sheetOnly; // said (with --json, printed) before the refusal
    const vision::Sheet &sheet = traced->sheet;
    const double error = traced->calibrationErrorMm;

    if (!out.isEmpty() && !noPiece) {
        io::DocumentData doc;
        doc.units = QStringLiteral("mm");
        int number = 0;
        for (const vision::Outline &outline : traced->outlines)
            doc.curves.push_back(curveRecord(outline, ++number));
        // The photo under the curves, placed by the same calibration.
        io::BackgroundRecord background;
        background.file = QFileInfo(path).absoluteFilePath();
        background.perspective = true;
        for (std::size_t i = 0; i < 4; ++i) {
            background.corners[2 * i] = sheet.corners[i].x();
            background.corners[2 * i + 1] = sheet.corners[i].y();
        }
        background.rectWidth = sheet.sizeMm.x();
        background.rectHeight = sheet.sizeMm.y();
        doc.background = background;
        if (const auto saved = io::saveDocument(out, doc); !saved)
            return fail(tr("%1: %2").arg(out, saved.error().message));
    }
    const auto noPieceFailure = [&] {
        return fail(
            tr("%1: no pattern piece found beside the sheet; nothing was written (the sheet was found)").arg(path));
    };
    if (!asJson)
        return noPiece ? noPieceFailure() : 0;

    Json json;
    json.beginObject().key("input").value(path.toStdString());
    json.key("width").value(photo.cols).key("height").value(photo.rows);
    json.key("sheet").beginObject();
    json.key("size_mm").point(sheet.sizeMm);
    json.key("corners").points(sheet.corners);
    json.key("edges").beginArray();
    for (const auto &edge : sheet.edges)
        json.beginObject().key("rms_px").value(edge.rms).key("points").value(edge.count).endObject();
    json.endArray();
    json.endObject();
    // Beyond the horizon the far side is unbounded: reported as -1 (JSON has no infinity).
    json.key("calibration_error_mm").value(std::isfinite(error) ? error : -1.0);
    json.key("calibration_warning").value(!(error <= 0.5));
    if (!out.isEmpty() && !noPiece) {
        json.key("output").value(out.toStdString());
        json.key("px_per_mm").value(traced->pxPerMm);
        json.key("curves").beginArray();
        for (const vision::Outline &outline : traced->outlines) {
            int corners = 0, lines = 0;
            for (int k = 0; k < outline.knotCount(); ++k)
                corners += outline.corner.at(static_cast<std::size_t>(k)) ? 1 : 0;
            for (bool line : outline.line)
                lines += line ? 1 : 0;
            json.beginObject().key("knots").value(outline.knotCount()).key("corners").value(corners);
            json.key("lines").value(lines).key("max_error_mm").value(outline.maxError).endObject();
        }
        json.endArray();
        json.key("trace_ms").value(ms);
    } else {
        json.key("find_ms").value(ms);
    }
    if (noPiece)
        json.key("curves").beginArray().endArray().key("trace_ms").value(ms);
    json.key("total_ms").value(total.nsecsElapsed() / 1e6);
    const int printed = printResult(json.endObject());
    return printed == 0 && noPiece ? noPieceFailure() : printed;
}

} // namespace kontur::cli
