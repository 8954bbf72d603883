// kontur-cli trace PHOTO --sheet SIZE [--corners x,y;x,y;x,y;x,y] --json: the photo read by QImage,
// converted to an 8-bit grey cv::Mat, the sheet found by vision/sheet.h. Writing traced outlines to a
// file comes with the outline tracer; until then an output file is refused rather than left empty.
#include "cli/tracecommand.h"
#include "cli/options.h"
#include "cli/output.h"

#include "cli/json.h"
#include "cli/pointfile.h"
#include "vision/sheet.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QImage>
#include <QRegularExpression>

#include <cstring>

namespace kontur::cli {
namespace {

// The photo as an 8-bit grey cv::Mat that owns its pixels (QImage's rows are 4-byte aligned).
cv::Mat grayOf(const QImage &image)
{
    const QImage gray = image.convertToFormat(QImage::Format_Grayscale8);
    cv::Mat out(gray.height(), gray.width(), CV_8UC1);
    for (int y = 0; y < gray.height(); ++y)
        std::memcpy(out.ptr(y), gray.constScanLine(y), static_cast<std::size_t>(gray.width()));
    return out;
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

} // namespace

int runTrace(const QStringList &args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Find the reference sheet in a photo of a pattern: its corners to a fraction of a pixel and the\n"
           "calibration's estimated error in mm at the photo's far side (JSON with --json).\n"
           "Tracing the pattern's outlines into a file is not available yet."));
    parser.addPositionalArgument(QStringLiteral("photo"), tr("The photo (PNG, JPEG, PGM, ...)."));
    parser.addOption({QStringLiteral("sheet"),
                      tr("The sheet's size: a4, a3, letter or WxH with mm (default), cm or in."),
                      QStringLiteral("size"), QStringLiteral("a4")});
    parser.addOption({QStringLiteral("corners"),
                      tr("Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are "
                         "searched near them."),
                      QStringLiteral("points")});
    parser.addOption({QStringLiteral("json"), tr("Print the sheet's corners and the calibration error as JSON.")});
    if (const int code = parseCommandLine(parser, args, 1); code != 0)
        return code < 0 ? 0 : code;
    if (!parser.isSet(QStringLiteral("json")))
        return fail(tr("tracing outlines into a file is not available yet: give --json for the sheet's corners"), 2);
    const auto size = vision::parseSheetSize(parser.value(QStringLiteral("sheet")).toStdString());
    if (!size)
        return fail(
            tr("--sheet needs a4, a3, letter or WxH[mm|cm|in], got \"%1\"").arg(parser.value(QStringLiteral("sheet"))),
            2);
    vision::SheetOptions options;
    options.sizeMm = *size;
    if (parser.isSet(QStringLiteral("corners"))) {
        options.cornerHints = parseCorners(parser.value(QStringLiteral("corners")));
        if (!options.cornerHints)
            return fail(tr("--corners needs four points x,y separated by semicolons or spaces"), 2);
    }
    const QString path = parser.positionalArguments().at(0);
    const QImage image(path);
    if (image.isNull())
        return fail(tr("%1: cannot read the photo").arg(path));
    const cv::Mat gray = grayOf(image);

    QElapsedTimer timer;
    timer.start();
    const auto sheet = vision::findSheet(gray, options);
    const double ms = timer.nsecsElapsed() / 1e6;
    if (!sheet)
        return fail(tr("%1: no reference sheet found (a white rectangle with four straight, clear edges)").arg(path));
    const double error = vision::calibrationErrorAtPhotoCornersMm(*sheet, gray.size());

    Json json;
    json.beginObject().key("input").value(path.toStdString());
    json.key("width").value(gray.cols).key("height").value(gray.rows);
    json.key("sheet").beginObject();
    json.key("size_mm").point(sheet->sizeMm);
    json.key("corners").points(sheet->corners);
    json.key("edges").beginArray();
    for (const auto &edge : sheet->edges)
        json.beginObject().key("rms_px").value(edge.rms).key("points").value(edge.count).endObject();
    json.endArray();
    json.endObject();
    // Beyond the horizon the far side is unbounded: reported as -1 (JSON has no infinity).
    json.key("calibration_error_mm").value(std::isfinite(error) ? error : -1.0);
    json.key("calibration_warning").value(!(error <= 0.5));
    json.key("find_ms").value(ms);
    return printResult(json.endObject());
}

} // namespace kontur::cli
