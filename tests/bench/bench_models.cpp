// Benchmarks of the model layer (issue targets in the comments), printed as JSON like
// `kontur-cli bench`. Run by hand with the sizes, e.g.
//   bench_models drag-composite --n 100000   bench_models drag-natural --n 10000   bench_models hit-test --n 1000
//   bench_models drag-piece --n 2000          bench_models drag-piece-allowance --n 2000
//   bench_models nudge-piece-allowance --n 2000   bench_models step-seam-width --n 2000
#include "../curveids.h"
#include "io/seam.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/seamwidths.h"
#include "models/document/document.h"
#include "models/document/enums.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;
using kontur::test::rowsOf;

namespace {

struct Timing
{
    std::vector<double> samples; // ns per operation
    std::vector<double> settle;  // drags: ms from the release until every seam allowance is exact
    double checksum = 0.0;
};

// The time of one drag step: `repeat` drags from `start`, each of `steps` steps of `step` (one merged
// undo command), timed per step and undone after; `checksum` reads the dragged curve afterwards so
// that no step can be left out. After each release: how long until the seam allowances, computed on
// a worker thread during the drag, are exact (the events of that thread handled here).
// With `distinct`, each drag goes a little farther than the one before, so that no drag ends where
// an earlier one did (whose allowance the document remembers).
template <class Checksum>
Timing timeDrag(EditController &editor, Point start, int steps, Point step, int repeat, Checksum checksum,
                bool distinct = false)
{
    Timing timing;
    QElapsedTimer clock;
    for (int r = 0; r < repeat; ++r) {
        editor.beginDrag(QPointF(start.x(), start.y()), 1e-6);
        const double scale = distinct ? 1.0 + 0.25 * r : 1.0;
        clock.start();
        for (int s = 0; s < steps; ++s)
            editor.dragTo(QPointF(start.x() + step.x() * s * scale, start.y() + step.y() * s * scale));
        timing.samples.push_back(static_cast<double>(clock.nsecsElapsed()) / steps);
        clock.start();
        editor.endDrag();
        while (!editor.document()->allowancesSettled())
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        timing.settle.push_back(static_cast<double>(clock.nsecsElapsed()) / 1e6);
        timing.checksum += checksum();
        editor.undo();
    }
    return timing;
}

// One drag step on an N-knot composite curve: move a handle, recompute the two segments it
// touches, merge the undo command, notify the curve's row and the moved rows (target: 50 µs at
// N = 100,000). The point list shows that curve, as in the app.
Timing dragComposite(int n, int repeat)
{
    EditController editor;
    std::vector<Point> knots;
    knots.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        knots.emplace_back(10.0 * i, (i % 2) ? 15.0 : -15.0);
    editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite), rowsOf(knots));
    const int handle = 3 * (n / 2) + 1;
    // The handle's knot is selected, as a user taps it first: only then are its handles shown.
    editor.selection()->select(editor.document()->idAt(0), handle - 1);
    const Point start = editor.document()->curve(0).definingPoint(handle);
    return timeDrag(editor, start, 200, Point(0.01, 0.02), repeat,
                    [&] { return editor.document()->curve(0).definingPoint(handle).x(); });
}

// One drag step on an N-point natural spline (chord parameterization): the whole spline is
// solved again, as its every piece depends on every point (target: 1 ms at N = 10,000).
Timing dragNatural(int n, int repeat)
{
    EditController editor;
    std::vector<Point> points;
    for (int i = 0; i < n; ++i)
        points.emplace_back(10.0 * i, 20.0 * std::sin(0.3 * i));
    editor.placement()->setParameterization(kontur::Parameterizations::ChordLength);
    editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::NaturalSpline), rowsOf(points));
    editor.selection()->selectRow(0);
    const Point start = points[static_cast<std::size_t>(n / 2)];
    return timeDrag(editor, start, 20, Point(0.1, 0.2), repeat,
                    [&] { return editor.document()->curve(0).segment(n / 2).controlPoints()[1].x(); });
}

// A garment piece: a closed composite curve of N knots (a wavy outline about 40 cm across, in cm),
// with its linked 1 cm seam allowance when `withAllowance`.
void openPiece(EditController &editor, int n, bool withAllowance)
{
    std::vector<Point> knots;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        const double r = 20 + 3 * std::sin(7 * t) + 1 * std::sin(23 * t);
        knots.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    kontur::Curve piece = kontur::Curve::make(CurveKind::Composite, std::move(knots));
    (void)piece.close();
    piece.piece = kontur::io::PieceMarks{};
    std::vector<kontur::Curve> curves{piece};
    if (withAllowance) {
        const kontur::geo::OffsetOptions options = kontur::io::defaultSeamOptions(QStringLiteral("cm"));
        kontur::Curve allowance = *kontur::Curve::makeOffset(piece, options);
        allowance.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
        curves.push_back(std::move(allowance));
    }
    editor.replaceDocument(std::move(curves), {}, QStringLiteral("cm"), false);
}

// One drag step of a knot of the garment piece, with its allowance when `withAllowance` (the goal:
// the same time per step as without; 40 steps a drag, as the canvas sends them).
Timing dragPiece(int n, int repeat, bool withAllowance)
{
    EditController editor;
    openPiece(editor, n, withAllowance);
    const int knot = 3 * (n / 2);
    editor.selection()->select(editor.document()->idAt(0), knot);
    const Point start = editor.document()->curve(0).definingPoint(knot);
    return timeDrag(
        editor, start, 40, Point(0.01, 0.02), repeat,
        [&] {
            const kontur::Document &doc = *editor.document();
            return doc.curve(0).definingPoint(knot).x() + (withAllowance ? doc.curve(1).definingPoint(0).x() : 0.0);
        },
        true);
}

// One arrow-key nudge of a knot of the garment piece with its 1 cm allowance (`width` false), or one
// + step of a seam's width (true): 10 in a row (a held key, fast taps), each timed on this thread
// (the goal: no offset here, as for a drag step); then how long until the allowance is exact (the
// worker's events handled here), and every step undone. Each series nudges by a distance of its
// own, or steps from a width of its own, so that no state is one the document remembers.
Timing stepPiece(int n, int repeat, bool width)
{
    EditController editor;
    openPiece(editor, n, true);
    kontur::SeamWidths seams;
    seams.setEditor(&editor);
    const int knot = 3 * (n / 2);
    const kontur::Document &doc = *editor.document();
    Timing timing;
    QElapsedTimer clock;
    constexpr int steps = 10;
    for (int r = 0; r < repeat; ++r) {
        const int start = editor.undoStack()->index();
        if (width) {
            editor.selection()->select(doc.idAt(0), -1);
            seams.selectSeam(0);           // the whole outline: the wavy piece has no corner
            seams.setWidth(1.0 + 0.1 * r); // typed: made here, untimed
        } else {
            editor.selection()->select(doc.idAt(0), knot);
        }
        clock.start();
        for (int s = 0; s < steps; ++s) {
            if (width)
                seams.stepWidth(1);
            else
                editor.commands()->nudgeSelected(QPointF(0.01 * (1 + r), 0.02));
        }
        timing.samples.push_back(static_cast<double>(clock.nsecsElapsed()) / steps);
        clock.start();
        while (!doc.allowancesSettled())
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        timing.settle.push_back(static_cast<double>(clock.nsecsElapsed()) / 1e6);
        timing.checksum += doc.curve(0).definingPoint(knot).x() + doc.curve(1).definingPoint(0).x();
        while (editor.undoStack()->index() > start)
            editor.undo();
        while (!doc.allowancesSettled())
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return timing;
}

// A hit test (nearest point within the touch radius, else the nearest curve) in a document of
// N curves with 100 points each (target: 20 µs at N = 1,000, i.e. 100,000 points).
Timing hitTest(int n, int repeat)
{
    EditController editor;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> where(0.0, 10000.0);
    std::uniform_real_distribution<double> near(-60.0, 60.0);
    for (int c = 0; c < n; ++c) {
        // 34 knots: 100 control points on a composite curve.
        std::vector<Point> knots;
        const Point origin(where(rng), where(rng));
        for (int k = 0; k < 34; ++k)
            knots.push_back(origin + Point(8.0 * k + near(rng) * 0.1, near(rng)));
        editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite), rowsOf(knots));
    }
    const double radius = 22.0; // 44 px touch target at 100 %
    Timing timing;
    timing.checksum += static_cast<int>(
        editor.hitTest(Point(0, 0), radius).curve); // builds the index, as the first pointer event does
    QElapsedTimer clock;
    constexpr int queries = 2000;
    std::vector<Point> targets(queries);
    for (auto &q : targets)
        q = Point(where(rng), where(rng));
    for (int r = 0; r < repeat; ++r) {
        clock.start();
        for (const Point &q : targets) {
            const kontur::PointRef hit = editor.hitTest(q, radius);
            if (hit.isValid())
                timing.checksum += hit.point;
            else
                timing.checksum += static_cast<int>(editor.curveAt(q, radius).curve);
        }
        timing.samples.push_back(static_cast<double>(clock.nsecsElapsed()) / queries);
    }
    return timing;
}

// One picture point mapped to the world through a perspective-calibrated background, `n` points per
// sample, each with its own imageToWorld() (the four-point solve each time, as a tool that maps a
// few marks does) — the cost of having no cache in the value type.
Timing backgroundMap(int n, int repeat)
{
    kontur::Background bg;
    bg.perspective = true;
    bg.corners = {QPointF(102, 95), QPointF(1890, 140), QPointF(1810, 1320), QPointF(160, 1250)};
    bg.rectWidth = 297;
    bg.rectHeight = 210;
    Timing timing;
    QElapsedTimer clock;
    for (int r = 0; r < repeat; ++r) {
        clock.start();
        for (int i = 0; i < n; ++i)
            timing.checksum += bg.toWorld(QPointF(i % 1900, (7 * i) % 1300)).x();
        timing.samples.push_back(static_cast<double>(clock.nsecsElapsed()) / n);
    }
    return timing;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(
            stderr,
            "usage: bench_models drag-composite|drag-natural|drag-piece|drag-piece-allowance|nudge-piece-allowance|"
            "step-seam-width|hit-test|background-map "
            "[--n N] [--repeat R]\n");
        return 2;
    }
    const QString op = args[1];
    const bool piece = op.startsWith(QLatin1String("drag-piece")) || op == QLatin1String("nudge-piece-allowance") ||
                       op == QLatin1String("step-seam-width");
    int n = op == QLatin1String("hit-test")       ? 1000
            : op == QLatin1String("drag-natural") ? 10000
            : piece                               ? 2000
                                                  : 100000;
    int repeat = piece ? 5 : 15;
    for (qsizetype i = 2; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--n"))
            n = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--repeat"))
            repeat = args[i + 1].toInt();
    }
    if (n < 2 || repeat < 1) {
        std::fprintf(stderr, "bench_models: --n needs at least 2 and --repeat at least 1\n");
        return 2;
    }
    Timing timing;
    if (op == QLatin1String("drag-composite"))
        timing = dragComposite(n, repeat);
    else if (op == QLatin1String("drag-natural"))
        timing = dragNatural(n, repeat);
    else if (op == QLatin1String("hit-test"))
        timing = hitTest(n, repeat);
    else if (op == QLatin1String("background-map"))
        timing = backgroundMap(n, repeat);
    else if (op == QLatin1String("drag-piece"))
        timing = dragPiece(n, repeat, false);
    else if (op == QLatin1String("drag-piece-allowance"))
        timing = dragPiece(n, repeat, true);
    else if (op == QLatin1String("nudge-piece-allowance"))
        timing = stepPiece(n, repeat, false);
    else if (op == QLatin1String("step-seam-width"))
        timing = stepPiece(n, repeat, true);
    else {
        std::fprintf(stderr, "bench_models: unknown operation \"%s\"\n", qPrintable(op));
        return 2;
    }
    std::sort(timing.samples.begin(), timing.samples.end());
    const std::size_t m = timing.samples.size();
    const double median = m % 2 ? timing.samples[m / 2] : 0.5 * (timing.samples[m / 2 - 1] + timing.samples[m / 2]);
    std::string settle;
    if (!timing.settle.empty()) {
        std::sort(timing.settle.begin(), timing.settle.end());
        settle = ",\"release_to_exact_median_ms\":" + std::to_string(timing.settle[timing.settle.size() / 2]) +
                 ",\"release_to_exact_max_ms\":" + std::to_string(timing.settle.back());
    }
    std::printf("{\"op\":\"%s\",\"n\":%d,\"median_ns\":%.1f,\"min_ns\":%.1f,\"samples\":%zu%s,\"checksum\":%.17g}\n",
                qPrintable(op), n, median, timing.samples.front(), m, settle.c_str(), timing.checksum);
    return 0;
}
