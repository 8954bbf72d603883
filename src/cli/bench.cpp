// kontur-cli bench: single-threaded timings of the geometry core on deterministic random input, for
// the figures the issue asks for (not a timed test). Prints the median and minimum over samples.
#include "cli/commands.h"

#include "cli/benchtiming.h"
#include "cli/iocommands.h"
#include "cli/json.h"
#include "cli/output.h"
#include "cli/pointfile.h"
#include "cli/sheetbench.h"
#include "cli/splinebench.h"
#include "geometry/arclength.h"
#include "geometry/composite.h"
#include "geometry/fit.h"
#include "geometry/nearest.h"
#include "geometry/strokefit.h"
#include "io/document.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

namespace kontur::cli {

namespace {

using Clock = std::chrono::steady_clock;

std::vector<geo::Bezier> randomCubics(std::size_t n, double scale, std::mt19937_64 &rng)
{
    std::uniform_real_distribution<double> coord(0.0, scale);
    std::vector<geo::Bezier> curves;
    curves.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        curves.emplace_back(std::vector<geo::Point>{
            {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}});
    return curves;
}

} // namespace

int runBench(const QStringList &args)
{
    // The sheet finder on labelled photos takes a folder and a file rather than a size (sheetbench.h).
    if (args.size() >= 2 && args.at(1) == QLatin1String("sheets"))
        return runSheetBench(args);
    QCommandLineParser parser;
    // A developer's benchmark: its help stays in English, like the operation names it lists, and is
    // not given to translators.
    parser.setApplicationDescription(QStringLiteral(
        "Time one operation: fit-ls, bezier-length, bezier-nearest, flatten, elevate, composite-drag, trace-fit, "
        "document-save, document-open, open-1e6, save-1e6, info-1e6, spline-natural, spline-clamped, spline-periodic, "
        "global-bspline, spline-eval, natural-drag; and sheets DIR LABELS.json (see bench sheets --help)."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("op"), QStringLiteral("The operation."));
    parser.addOptions({
        {QStringLiteral("n"), QStringLiteral("Problem size: points, curves or knots."), QStringLiteral("N"),
         QStringLiteral("1000")},
        {QStringLiteral("repeat"), QStringLiteral("Timed samples (default 15)."), QStringLiteral("R"),
         QStringLiteral("15")},
        {QStringLiteral("accuracy"), QStringLiteral("Arc length accuracy (default 1e-9)."), QStringLiteral("accuracy"),
         QStringLiteral("1e-9")},
        {QStringLiteral("scale"), QStringLiteral("Size of the random curves (default 100)."), QStringLiteral("scale"),
         QStringLiteral("100")},
    });
    QTextStream err(stderr);
    if (!parser.parse(args)) {
        err << "kontur-cli: " << parser.errorText() << '\n';
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        printHelp(parser, args);
        return 0;
    }
    if (parser.positionalArguments().size() != 1) {
        err << "kontur-cli: bench needs one operation\n";
        return 2;
    }
    const QString op = parser.positionalArguments().first();
    bool ok = false;
    const long long n = parser.value(QStringLiteral("n")).toLongLong(&ok);
    bool okRepeat = false;
    const int repeat = parser.value(QStringLiteral("repeat")).toInt(&okRepeat);
    const auto accuracy = parseNumber(parser.value(QStringLiteral("accuracy")).toStdString());
    const auto scale = parseNumber(parser.value(QStringLiteral("scale")).toStdString());
    if (!ok || n < 1 || n > 100'000'000 || !okRepeat || repeat < 1 || !accuracy || !(*accuracy > 0.0) || !scale ||
        !(*scale > 0.0)) {
        err << "kontur-cli: bench needs --n from 1 to 1e8, --repeat >= 1, positive --accuracy and --scale\n";
        return 2;
    }
    const auto count = static_cast<std::size_t>(n);
    long long reportedN = n; // the problem size the result is for
    std::mt19937_64 rng(20240601);
    BenchTiming timing;
    const char *per = "operation";

    if (op == QLatin1String("fit-ls")) {
        // N noisy points along a wavy arc: the least-squares cubic with chord-length parameters.
        std::normal_distribution<double> noise(0.0, 0.01 * *scale);
        std::vector<geo::Point> pts(count < 4 ? 4 : count);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const double u = static_cast<double>(i) / static_cast<double>(pts.size() - 1);
            pts[i] = geo::Point(*scale * u + noise(rng), *scale * 0.3 * std::sin(3.0 * u) + noise(rng));
        }
        per = "fit";
        timing = measure(repeat, 1.0, [&] {
            const auto fit = geo::fitCubic(pts, geo::Parameterization::ChordLength);
            return fit ? fit->rms : -1.0;
        });
    } else if (op == QLatin1String("bezier-length")) {
        const auto curves = randomCubics(count, *scale, rng);
        per = "curve";
        timing = measure(repeat, static_cast<double>(count), [&] {
            double sum = 0.0;
            for (const auto &c : curves)
                sum += geo::arcLength(c, *accuracy);
            return sum;
        });
    } else if (op == QLatin1String("bezier-nearest")) {
        const auto curves = randomCubics(count, *scale, rng);
        std::uniform_real_distribution<double> coord(-0.2 * *scale, 1.2 * *scale);
        std::vector<geo::Point> queries(count);
        for (auto &q : queries)
            q = geo::Point(coord(rng), coord(rng));
        per = "query";
        timing = measure(repeat, static_cast<double>(count), [&] {
            double sum = 0.0;
            for (std::size_t i = 0; i < count; ++i)
                sum += geo::nearest(curves[i], queries[i]).distance;
            return sum;
        });
    } else if (op == QLatin1String("flatten")) {
        const auto curves = randomCubics(count, *scale, rng);
        std::vector<geo::Point> poly;
        per = "curve (tolerance 0.25)";
        timing = measure(repeat, static_cast<double>(count), [&] {
            double sum = 0.0;
            for (const auto &c : curves) {
                poly.clear();
                geo::flatten(c, 0.25, poly);
                sum += static_cast<double>(poly.size());
            }
            return sum;
        });
    } else if (op == QLatin1String("elevate")) {
        const auto curves = randomCubics(count, *scale, rng);
        per = "cubic elevated by one";
        timing = measure(repeat, static_cast<double>(count), [&] {
            double sum = 0.0;
            for (const auto &c : curves)
                sum += c.elevated(1).controlPoints()[2].x();
            return sum;
        });
    } else if (op == QLatin1String("composite-drag")) {
        // An N-knot composite curve; each operation is one drag step (alternately a knot move and a
        // free handle move at a random place) plus re-flattening the segments it touched.
        std::vector<geo::Point> knots(count < 2 ? 2 : count);
        std::normal_distribution<double> step(0.0, 0.01 * *scale);
        geo::Point p(0.0, 0.0);
        for (std::size_t i = 0; i < knots.size(); ++i) {
            p += geo::Point(0.01 * *scale + std::abs(step(rng)), step(rng));
            knots[i] = p;
        }
        geo::CompositeCurve curve(knots);
        constexpr int kDrags = 1000;
        std::uniform_int_distribution<int> pickKnot(0, curve.knotCount() - 1);
        std::uniform_int_distribution<int> pickControl(0, static_cast<int>(curve.controlPoints().size()) - 1);
        std::vector<geo::Point> poly;
        per = "drag step";
        timing = measure(repeat, kDrags, [&] {
            double sum = 0.0;
            for (int d = 0; d < kDrags; ++d) {
                geo::Result<geo::SegmentRange> touched = geo::SegmentRange{};
                if (d % 2 == 0) {
                    const int k = pickKnot(rng);
                    touched = curve.moveKnot(k, curve.knot(k) + geo::Point(0.001, -0.001));
                } else {
                    int c = pickControl(rng);
                    if (geo::CompositeCurve::isKnotIndex(c))
                        c = c + 1 < static_cast<int>(curve.controlPoints().size()) ? c + 1 : c - 1;
                    touched =
                        curve.moveHandle(c, curve.controlPoints()[c] + geo::Point(0.001, 0.002), geo::HandleMove::Free);
                }
                if (!touched)
                    continue;
                poly.clear();
                for (int s = 0; s < touched->count; ++s)
                    geo::flatten(curve.segment((touched->first + s) % curve.segmentCount()), 0.25, poly);
                sum += static_cast<double>(poly.size());
            }
            return sum;
        });
    } else if (op == QLatin1String("trace-fit")) {
        // Freehand tracing (issue 10): an N-point stroke along a pattern contour in mm (a straight
        // side, a corner, an S-shaped curve, a corner, a straight side; about 700 mm) with ±0.15 mm hand
        // jitter, fitted within 0.5 mm by the multi-segment fit with corners.
        std::uniform_real_distribution<double> jitter(-0.15, 0.15);
        std::vector<geo::Point> stroke(count < 2 ? 2 : count);
        for (std::size_t i = 0; i < stroke.size(); ++i) {
            const double u = 3.0 * static_cast<double>(i) / static_cast<double>(stroke.size() - 1);
            geo::Point p;
            if (u < 1.0)
                p = geo::Point(200.0 * u, 0.0);
            else if (u < 2.0)
                p = geo::Point(200.0 + 40.0 * std::sin(2.0 * 3.141592653589793 * (u - 1.0)), 250.0 * (u - 1.0));
            else
                p = geo::Point(200.0 - 200.0 * (u - 2.0), 250.0);
            stroke[i] = p + geo::Point(jitter(rng), jitter(rng));
        }
        per = "stroke fit";
        geo::StrokeFitOptions options;
        options.tolerance = 0.5;
        timing = measure(repeat, 1.0, [&] {
            const auto fit = geo::fitStroke(stroke, options);
            return fit ? double(fit->segmentCount()) : -1.0;
        });
    } else if (op == QLatin1String("document-save") || op == QLatin1String("document-open") ||
               op == QLatin1String("open-1e6") || op == QLatin1String("save-1e6") || op == QLatin1String("info-1e6")) {
        // A document holding one composite curve (full-precision handles), saved to and opened from a
        // temporary .kontur file. document-save/open: N knots (3N - 2 stored points). Issue 21's
        // document goals, open-1e6, save-1e6 and info-1e6: 10⁶ stored points (--n to change it), and
        // info-1e6 opens it and describes it as `kontur-cli info` does (lengths to 1e-9, boxes,
        // continuity).
        const bool million = op.endsWith(QLatin1String("-1e6"));
        const std::size_t points = million && !parser.isSet(QStringLiteral("n")) ? 1'000'000 : count;
        if (million)
            reportedN = static_cast<long long>(points);
        std::uniform_real_distribution<double> coord(0.0, *scale);
        std::vector<geo::Point> knots(std::max<std::size_t>(2, million ? (points + 2) / 3 : count));
        for (std::size_t i = 0; i < knots.size(); ++i)
            knots[i] = geo::Point(static_cast<double>(i) * *scale + coord(rng), coord(rng));
        io::CurveRecord record;
        record.kind = QStringLiteral("composite");
        record.points = geo::CompositeCurve(knots).controlPoints();
        record.nodeTypes.assign(knots.size(), QStringLiteral("smooth"));
        io::DocumentData doc;
        doc.curves.push_back(std::move(record));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bench.kontur"));
        if (auto saved = io::saveDocument(path, doc); !saved) {
            err << "kontur-cli: " << saved.error().toString() << '\n';
            return 1;
        }
        per = "document";
        const bool save = op == QLatin1String("document-save") || op == QLatin1String("save-1e6");
        const bool describe = op == QLatin1String("info-1e6");
        timing = measure(repeat, 1.0, [&] {
            if (save)
                return io::saveDocument(path, doc).ok() ? 1.0 : -1.0;
            const auto opened = io::openDocument(path);
            if (!opened)
                return -1.0;
            if (!describe)
                return static_cast<double>(opened->curves.front().points.size());
            Json json;
            describeDocument(json, path, *opened, *accuracy);
            return static_cast<double>(json.str().size());
        });
        timing.checksum += static_cast<double>(QFileInfo(path).size());
    } else if (auto spline = runSplineBench(op, count, repeat, *scale)) {
        // The spline families (issue 4): see splinebench.h.
        timing.samples = std::move(spline->samples);
        timing.checksum = spline->checksum;
        per = spline->per;
    } else {
        err << "kontur-cli: unknown bench operation \"" << op
            << "\" (fit-ls, bezier-length, bezier-nearest, flatten, elevate, composite-drag, trace-fit, document-save, "
               "document-open, open-1e6, save-1e6, info-1e6, "
            << kSplineBenchOps << ")\n";
        return 2;
    }

    std::vector<double> sorted = timing.samples;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t m = sorted.size();
    const double median = m % 2 == 1 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1] + sorted[m / 2]);
    Json json;
    json.beginObject();
    json.key("op").value(op.toStdString());
    json.key("n").value(reportedN);
    json.key("median_ns").value(median);
    json.key("min_ns").value(sorted.front());
    json.key("samples").value(static_cast<long long>(m));
    json.key("per").value(per);
    json.key("checksum").value(timing.checksum);
    json.endObject();
    return printResult(json);
}

} // namespace kontur::cli
