// kontur-cli bench sheets: see sheetbench.h.
#include "cli/sheetbench.h"

#include "cli/json.h"
#include "cli/output.h"
#include "picture/photomat.h"
#include "picture/picture.h"
#include "vision/sheet.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace kontur::cli {

namespace {

constexpr double kPrecisePx = 2.0; // every corner within this of the label: found
constexpr double kNearPx = 20.0;   // within this: the right sheet, imprecisely; beyond: a wrong one

std::optional<std::array<geo::Point, 4>> cornersOf(const QJsonValue &value)
{
    const QJsonArray array = value.toArray();
    if (array.size() != 4)
        return std::nullopt;
    std::array<geo::Point, 4> out;
    for (int i = 0; i < 4; ++i) {
        const QJsonArray p = array.at(i).toArray();
        if (p.size() != 2 || !p.at(0).isDouble() || !p.at(1).isDouble())
            return std::nullopt;
        out[static_cast<std::size_t>(i)] = geo::Point(p.at(0).toDouble(), p.at(1).toDouble());
    }
    return out;
}

// The largest corner distance, for the pairing of found and labelled corners in cyclic order (either
// direction) that makes it least.
double cornerError(const std::array<geo::Point, 4> &found, const std::array<geo::Point, 4> &label)
{
    double best = INFINITY;
    for (int dir : {1, -1})
        for (int shift = 0; shift < 4; ++shift) {
            double worst = 0;
            for (int i = 0; i < 4; ++i)
                worst = std::max(worst, (found[static_cast<std::size_t>(i)] -
                                         label[static_cast<std::size_t>(((dir * i + shift) % 4 + 4) % 4)])
                                            .norm());
            best = std::min(best, worst);
        }
    return best;
}

const char *codeName(vision::ErrorCode code)
{
    switch (code) {
    case vision::ErrorCode::InvalidImage:
        return "invalid_image";
    case vision::ErrorCode::InvalidArgument:
        return "invalid_argument";
    case vision::ErrorCode::NoSheetFound:
        return "no_sheet";
    case vision::ErrorCode::SheetNotFlat:
        return "not_flat";
    case vision::ErrorCode::WrongProportions:
        return "wrong_proportions";
    case vision::ErrorCode::NoCornerFound:
        return "no_corner";
    case vision::ErrorCode::Degenerate:
        return "degenerate";
    case vision::ErrorCode::NoPieceFound:
        return "no_piece";
    }
    return "unknown";
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

} // namespace

int runSheetBench(const QStringList &args)
{
    QCommandLineParser parser;
    // A developer's benchmark: its help stays in English (see bench.cpp).
    parser.setApplicationDescription(QStringLiteral(
        "The sheet finder on labelled real photos: for each photo in LABELS.json (under DIR), whether the "
        "sheet was found with every corner within 2 px of the label (found), within 20 px (imprecise), a "
        "different rectangle (wrong) or none; photos labelled as excluded (no flat, whole sheet) count as "
        "accepted when a sheet is found in them."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("sheets"), QStringLiteral("The operation."));
    parser.addPositionalArgument(QStringLiteral("dir"), QStringLiteral("The folder the photos' names are under."));
    parser.addPositionalArgument(QStringLiteral("labels"), QStringLiteral("The labels (JSON)."));
    parser.addOption({QStringLiteral("sheet"), QStringLiteral("The sheet's size for every photo (default a4)."),
                      QStringLiteral("size"), QStringLiteral("a4")});
    parser.addOption(
        {QStringLiteral("only"), QStringLiteral("Only photos whose name contains this."), QStringLiteral("text")});
    QTextStream err(stderr);
    if (!parser.parse(args)) {
        err << "kontur-cli: " << parser.errorText() << '\n';
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        printHelp(parser, args);
        return 0;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 3) {
        err << "kontur-cli: bench sheets needs DIR and LABELS.json\n";
        return 2;
    }
    const auto size = vision::parseSheetSize(parser.value(QStringLiteral("sheet")).toStdString());
    if (!size) {
        err << "kontur-cli: --sheet needs a4, a3, letter or WxH[mm|cm|in]\n";
        return 2;
    }
    QFile file(positional.at(2));
    if (!file.open(QIODevice::ReadOnly)) {
        err << "kontur-cli: cannot read " << positional.at(2) << '\n';
        return 1;
    }
    QJsonParseError parseError;
    const QJsonObject labels = QJsonDocument::fromJson(file.readAll(), &parseError).object();
    if (parseError.error != QJsonParseError::NoError || !labels.value(QStringLiteral("photos")).isObject()) {
        err << "kontur-cli: " << positional.at(2) << " is not a labels file (an object with \"photos\")\n";
        return 1;
    }
    const QDir dir(positional.at(1));
    const QString only = parser.value(QStringLiteral("only"));

    Json json;
    json.beginObject().key("op").value("sheets");
    json.key("results").beginArray();
    int found = 0, imprecise = 0, wrong = 0, none = 0, missing = 0, accepted = 0, refused = 0;
    std::vector<double> errors, times, megapixels;
    const auto run = [&](const QString &name, const std::optional<std::array<geo::Point, 4>> &label,
                         const QString &paper) {
        const ImageRead read = readImage(dir.filePath(name));
        json.beginObject().key("photo").value(name.toStdString());
        if (!read.ok()) {
            ++missing;
            json.key("status").value("missing").endObject();
            return;
        }
        const cv::Mat photo = bgrMat(read.image);
        vision::SheetOptions options;
        options.sizeMm = *size;
        // The paper the label names; of a paper of no standard size, the proportions its labelled corners
        // show (as a user would type its size).
        if (const auto named = vision::parseSheetSize(paper.toStdString()))
            options.sizeMm = *named;
        else if (label && !paper.isEmpty())
            options.sizeMm = geo::Point(1.0, vision::seenRectangle(*label, photo.size(), read.focalPx()).aspect);
        json.key("sheet_mm").point(options.sizeMm);
        options.focalPx = read.focalPx();
        json.key("focal_px").value(options.focalPx);
        QElapsedTimer timer;
        timer.start();
        const auto sheet = vision::findSheet(photo, options);
        const double ms = timer.nsecsElapsed() / 1e6;
        times.push_back(ms);
        megapixels.push_back(photo.total() / 1e6);
        json.key("megapixels").value(photo.total() / 1e6).key("ms").value(ms);
        if (sheet) {
            json.key("corners").points(sheet->corners);
            std::array<double, 4> rms{};
            for (std::size_t i = 0; i < 4; ++i)
                rms[i] = sheet->edges[i].rms;
            json.key("edge_rms_px").numbers(rms);
            for (std::size_t i = 0; i < 4; ++i)
                rms[i] = sheet->edges[i].bow;
            json.key("edge_bow_px").numbers(rms);
            for (std::size_t i = 0; i < 4; ++i)
                rms[i] = static_cast<double>(sheet->edges[i].count) / std::max(1, sheet->edges[i].sampled);
            json.key("edge_inlier_share").numbers(rms);
        } else
            json.key("reason").value(codeName(sheet.error().code));
        if (!sheet && sheet.error().code == vision::ErrorCode::WrongProportions)
            json.key("seen_aspect").value(sheet.error().seenAspect);
        if (!label) {
            (sheet ? accepted : refused) += 1;
            json.key("status").value(sheet ? "accepted" : "refused").endObject();
            return;
        }
        if (!sheet) {
            ++none;
            json.key("status").value("none").endObject();
            return;
        }
        const double e = cornerError(sheet->corners, *label);
        json.key("max_corner_error_px").value(e);
        // Whether the labelled corners agree with the EXIF focal length (picture/exif.h), and the focal
        // length they show, as a share of it.
        if (options.focalPx > 0) {
            const vision::SeenRectangle seen = vision::seenRectangle(*label, photo.size(), options.focalPx);
            const vision::SeenRectangle free = vision::seenRectangle(*label, photo.size());
            json.key("focal_agrees").value(seen.focalUsed).key("focal_seen_share").value(free.focalPx / options.focalPx);
        }
        const char *status = e <= kPrecisePx ? "found" : e <= kNearPx ? "imprecise" : "wrong";
        (e <= kPrecisePx ? found : e <= kNearPx ? imprecise : wrong) += 1;
        if (e <= kNearPx)
            errors.push_back(e);
        json.key("status").value(status).endObject();
    };
    const QJsonObject photos = labels.value(QStringLiteral("photos")).toObject();
    for (auto it = photos.begin(); it != photos.end(); ++it) {
        if (!only.isEmpty() && !it.key().contains(only))
            continue;
        const auto corners = cornersOf(it.value().toObject().value(QStringLiteral("corners")));
        if (!corners) {
            err << "kontur-cli: " << it.key() << ": its label has no four corners\n";
            return 1;
        }
        run(it.key(), corners, it.value().toObject().value(QStringLiteral("paper")).toString());
    }
    const QJsonObject excluded = labels.value(QStringLiteral("excluded")).toObject();
    for (auto it = excluded.begin(); it != excluded.end(); ++it)
        if (only.isEmpty() || it.key().contains(only))
            run(it.key(), std::nullopt, {});
    json.endArray();
    const int labelled = found + imprecise + wrong + none;
    json.key("labelled").value(labelled).key("found").value(found).key("imprecise").value(imprecise);
    json.key("wrong").value(wrong).key("none").value(none).key("missing").value(missing);
    json.key("found_share").value(labelled > 0 ? static_cast<double>(found) / labelled : 0.0);
    json.key("excluded_accepted").value(accepted).key("excluded_refused").value(refused);
    json.key("median_corner_error_px").value(median(errors));
    json.key("max_corner_error_px").value(errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end()));
    json.key("median_ms").value(median(times));
    json.key("max_ms").value(times.empty() ? 0.0 : *std::max_element(times.begin(), times.end()));
    json.key("max_megapixels")
        .value(megapixels.empty() ? 0.0 : *std::max_element(megapixels.begin(), megapixels.end()));
    return printResult(json.endObject());
}

} // namespace kontur::cli
