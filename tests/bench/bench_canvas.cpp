// Frame-time benchmarks of the real window (issue targets: with 1,000 curves of 100 Bézier segments,
// a pinch-zoom frame ≤ 16 ms, a handle-drag frame ≤ 8 ms, start-up to the first frame ≤ 500 ms).
// Runs on whatever Qt Quick backend the environment selects (software offscreen, or OpenGL under
// Xvfb); prints a summary with medians and 90th percentiles on stderr and one JSON line on stdout.
// Usage: bench_canvas [--curves N] [--frames F] [--size WxH] [--hide NAME,NAME...] [--stages] [--shot FILE.png]
//                     [--selections N]
//   --size: the window's size (default 1280x800, a landscape tablet; 800x1280 for portrait).
//   --hide: items (by objectName) hidden before measuring, to see what a part of the window costs;
//   the canvas's own parts are canvasLayer (the cached curves) and canvasLive (the selected curve
//   and the points), the window's tool bar is header.
//   --stages: where the frames' time goes: median moments of the render thread's stages, and the
//   processor time each thread of the process used per frame (Linux), which a busy machine
//   disturbs far less than the wall-clock times.
//   --selections: N selection changes instead of one, the rest between two other curves (for a profiler).
//   --shot: saves the window as it is at the end of the drag.
//   QT_QPA_PLATFORM=offscreen QT_QUICK_BACKEND=software bench_canvas      (software)
//   xvfb-run -a -s "-screen 0 1280x1024x24" bench_canvas                   (OpenGL through Mesa)
// KONTUR_PROFILE=1 adds the canvas's own timings per frame (sync, software paint parts).
#include "app/application.h"
#include "app/curvecanvas.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickWindow>
#include <QSignalSpy>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size();
    return m == 0 ? 0.0 : (m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]));
}

// The 90th percentile (nearest rank).
double p90(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

qint64 nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// The stages of a frame: when the change was done on the GUI thread, and when the render thread
// began and ended synchronising, began and ended recording the frame, and had it swapped, in ms
// after the change began.
using Stages = std::array<double, 6>;
constexpr std::array<const char *, 6> kStageNames{"change done",   "sync begins", "sync ends",
                                                  "render begins", "render ends", "swapped"};

// The render thread's marks, in ns of the steady clock (written there, read after the swap).
struct RenderMarks
{
    std::array<std::atomic<qint64>, 5> at{};
    std::atomic<int> swaps{0};
    void watch(QQuickWindow *window)
    {
        const std::array signals{&QQuickWindow::beforeSynchronizing, &QQuickWindow::afterSynchronizing,
                                 &QQuickWindow::beforeRendering, &QQuickWindow::afterRendering,
                                 &QQuickWindow::frameSwapped};
        for (std::size_t k = 0; k < signals.size(); ++k)
            QObject::connect(
                window, signals[k], window,
                [this, k] {
                    at[k].store(nowNs());
                    if (k == 4)
                        ++swaps;
                },
                Qt::DirectConnection);
    }
};

// Waits for the next frame after a change and returns how long it took, in ms; `changeMs`, if
// given, gets the part the change itself took on the GUI thread (models, signals, QML bindings),
// and `stages`, if given, where the time went (from `marks`).
double frame(QQuickWindow *window, const std::function<void()> &change, std::vector<double> *changeMs = nullptr,
             const RenderMarks *marks = nullptr, std::vector<Stages> *stages = nullptr)
{
    QSignalSpy swapped(window, &QQuickWindow::frameSwapped);
    const qint64 start = nowNs();
    change();
    const double changed = static_cast<double>(nowNs() - start) / 1e6;
    if (changeMs)
        changeMs->push_back(changed);
    if (!swapped.wait(5000))
        return -1.0;
    const double total = static_cast<double>(nowNs() - start) / 1e6;
    if (marks && stages) {
        Stages row{changed};
        for (std::size_t k = 0; k < marks->at.size(); ++k)
            row[k + 1] = static_cast<double>(marks->at[k].load() - start) / 1e6;
        stages->push_back(row);
    }
    return total;
}

// Processor time used so far by each thread of this process, in ns, by thread name (Linux:
// /proc/self/task/*/schedstat); threads of one name (a rasterizer's workers) are added up.
std::map<QString, qint64> threadTimes()
{
    std::map<QString, qint64> times;
    const QDir tasks(QStringLiteral("/proc/self/task"));
    for (const QString &tid : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile comm(tasks.filePath(tid + QStringLiteral("/comm")));
        QFile stat(tasks.filePath(tid + QStringLiteral("/schedstat")));
        if (!comm.open(QIODevice::ReadOnly) || !stat.open(QIODevice::ReadOnly))
            continue;
        QString name = QString::fromUtf8(comm.readAll()).trimmed();
        if (tid == QString::number(QCoreApplication::applicationPid()))
            name = QStringLiteral("GUI thread");
        // Worker threads are numbered (llvmpipe-0, llvmpipe-1…): one entry for all of them.
        while (!name.isEmpty() && (name.back().isDigit() || name.back() == QLatin1Char('-')))
            name.chop(1);
        times[name] += QString::fromLatin1(stat.readAll()).section(QLatin1Char(' '), 0, 0).toLongLong();
    }
    return times;
}

// Prints the processor time per frame of each thread between two threadTimes().
void printThreadTimes(const char *title, const std::map<QString, qint64> &before,
                      const std::map<QString, qint64> &after, int frames)
{
    if (frames <= 0)
        return;
    std::fprintf(stderr, "  %s, processor time per frame:\n", title);
    double total = 0.0;
    for (const auto &[name, ns] : after) {
        const auto was = before.find(name);
        const double ms = static_cast<double>(ns - (was == before.end() ? 0 : was->second)) / 1e6 / frames;
        total += ms;
        if (ms >= 0.01)
            std::fprintf(stderr, "    %-16s %6.2f ms\n", qPrintable(name), ms);
    }
    std::fprintf(stderr, "    %-16s %6.2f ms\n", "all threads", total);
}

// The median of each stage over the frames.
void printStages(const char *title, const std::vector<Stages> &frames)
{
    if (frames.empty())
        return;
    std::fprintf(stderr, "  %s, median moments after the change began:\n", title);
    for (std::size_t k = 0; k < kStageNames.size(); ++k) {
        std::vector<double> at;
        for (const Stages &f : frames)
            at.push_back(f[k]);
        std::fprintf(stderr, "    %-14s %7.2f ms\n", kStageNames[k], median(at));
    }
}

// Waits until a change is drawn completely (the frame after the change, and any that follow at
// once, e.g. the layer drawn anew) and returns the time to the last of those frames, in ms;
// `stages`, if given, gets where the time of the first of those frames went (from `marks`).
double completeFrame(QQuickWindow *window, const std::function<void()> &change, double *changeMs = nullptr,
                     const RenderMarks *marks = nullptr, std::vector<Stages> *stages = nullptr)
{
    QSignalSpy swapped(window, &QQuickWindow::frameSwapped);
    QElapsedTimer clock;
    clock.start();
    const qint64 start = nowNs();
    change();
    const double changed = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    if (changeMs)
        *changeMs = changed;
    if (!swapped.wait(5000))
        return -1.0;
    if (marks && stages) {
        Stages row{changed};
        for (std::size_t k = 0; k < marks->at.size(); ++k)
            row[k + 1] = static_cast<double>(marks->at[k].load() - start) / 1e6;
        stages->push_back(row);
    }
    double last = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    while (swapped.wait(100))
        last = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    return last;
}

} // namespace

int main(int argc, char *argv[])
{
    QElapsedTimer startClock;
    startClock.start();
    QGuiApplication app(argc, argv);
    int curves = 1000, frames = 60;
    QStringList hidden;
    bool showStages = false;
    int selections = 1;
    QString shot;
    QSize size(1280, 800);
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const bool hasValue = i + 1 < args.size();
        if (args[i] == QLatin1String("--curves") && hasValue)
            curves = args[++i].toInt();
        else if (args[i] == QLatin1String("--frames") && hasValue)
            frames = args[++i].toInt();
        else if (args[i] == QLatin1String("--hide") && hasValue)
            hidden = args[++i].split(QLatin1Char(','), Qt::SkipEmptyParts);
        else if (args[i] == QLatin1String("--selections") && hasValue)
            selections = args[++i].toInt();
        else if (args[i] == QLatin1String("--stages"))
            showStages = true;
        else if (args[i] == QLatin1String("--shot") && hasValue)
            shot = args[++i];
        else if (args[i] == QLatin1String("--size") && hasValue) {
            const QStringList wh = args[++i].split(QLatin1Char('x'));
            if (wh.size() == 2 && wh[0].toInt() > 0 && wh[1].toInt() > 0)
                size = QSize(wh[0].toInt(), wh[1].toInt());
        }
    }

    QStandardPaths::setTestModeEnabled(true);
    QFile::remove(kontur::Recovery::recoveryPath());
    QQmlApplicationEngine engine;
    QQuickWindow *window = kontur::loadMainWindow(engine, {QStringLiteral("en"), QString(), size});
    if (!window)
        return 1;
    window->resize(size);
    QSignalSpy firstFrame(window, &QQuickWindow::frameSwapped);
    window->show();
    firstFrame.wait(10000);
    const double startup = static_cast<double>(startClock.nsecsElapsed()) / 1e6;

    auto *canvas = window->findChild<kontur::CurveCanvas *>(QStringLiteral("canvas"));
    if (!canvas)
        return 1;
    kontur::EditController *editor = canvas->controller();
    // N composite curves of 34 knots (100 control points, 33 Bézier segments)… and 101-knot ones for
    // 100 segments each: 1,000 curves × 100 segments.
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> where(-2000.0, 2000.0);
    std::uniform_real_distribution<double> wiggle(-20.0, 20.0);
    for (int c = 0; c < curves; ++c) {
        QVariantList rows;
        const double x0 = where(rng), y0 = where(rng);
        for (int k = 0; k <= 100; ++k)
            rows << QVariant(QVariantList{x0 + 4.0 * k, y0 + wiggle(rng)});
        editor->placement()->createFromCoordinates(static_cast<int>(kontur::CurveKind::Composite), rows);
    }
    for (const QString &name : std::as_const(hidden)) {
        auto *item = name == QLatin1String("header") ? window->property("header").value<QQuickItem *>()
                                                     : window->findChild<QQuickItem *>(name);
        if (!item) {
            std::fprintf(stderr, "bench_canvas: no item named %s\n", qPrintable(name));
            return 2;
        }
        // Not only hidden: the canvas parts' visibility follows the canvas's state, their opacity does not.
        item->setOpacity(0.0);
    }
    RenderMarks marks;
    if (showStages)
        marks.watch(window);
    std::vector<Stages> zoomStages, dragStages;
    canvas->fitToView();
    QSignalSpy settle(window, &QQuickWindow::frameSwapped);
    settle.wait(20000);

    // A pinch: the fingers' centroid stays, the scale goes up and down by 2 % a frame (within
    // ±20 %), as QML's PinchHandler reports it.
    std::vector<double> zoomFrames, dragFrames, zoomChanges, dragChanges;
    const QPointF centre(canvas->width() / 2, canvas->height() / 2);
    canvas->pinchStarted(centre);
    double scale = 1.0;
    const auto zoomBefore = threadTimes();
    const int zoomSwapsBefore = marks.swaps;
    for (int f = 0; f < frames; ++f) {
        scale *= f % 20 < 10 ? 1.02 : 1 / 1.02;
        zoomFrames.push_back(frame(
            window, [&] { canvas->pinchUpdated(scale, centre); }, &zoomChanges, &marks, &zoomStages));
    }
    const auto zoomAfter = threadTimes();
    const int zoomSwaps = marks.swaps - zoomSwapsBefore;
    canvas->pinchEnded();
    // The fingers rest: the layer of curves is drawn sharp again at the new view (like a jump).
    while (QSignalSpy(window, &QQuickWindow::frameSwapped).wait(400)) {
    }
    // A jump of the view (the + button): drawn sharp at the new view (the layer anew); then back
    // to the whole drawing.
    double jumpChange = 0.0;
    const double jumpFrame = completeFrame(
        window, [&] { canvas->zoomIn(); }, &jumpChange);
    completeFrame(window, [&] { canvas->fitToView(); });

    const kontur::Curve &first = editor->document()->curve(0);
    const kontur::geo::Point handle = first.definingPoint(151);
    // Pressing on the handle selects its curve (its own frame, as when a finger touches down); its
    // knot is selected, as a user taps it first: only then are its handles shown and grabbed.
    std::vector<double> pressChange;
    std::vector<Stages> pressStages, otherStages, moreStages;
    const double pressFrame = frame(
        window,
        [&] {
            editor->selection()->select(editor->document()->idAt(0), 150);
            editor->beginDrag(QPointF(handle.x(), handle.y()), 1e-6);
        },
        &pressChange, &marks, &pressStages);
    const auto dragBefore = threadTimes();
    const int dragSwapsBefore = marks.swaps;
    for (int f = 0; f < frames; ++f)
        dragFrames.push_back(frame(
            window, [&] { editor->dragTo(QPointF(handle.x() + 0.5 * f, handle.y() + 0.25 * f)); }, &dragChanges, &marks,
            &dragStages));
    const auto dragAfter = threadTimes();
    const int dragSwaps = marks.swaps - dragSwapsBefore;
    if (!shot.isEmpty() && !window->grabWindow().save(shot))
        std::fprintf(stderr, "bench_canvas: could not save %s\n", qPrintable(shot));
    editor->endDrag();

    // Selecting another curve: the layer of the other curves is drawn anew.
    while (QSignalSpy(window, &QQuickWindow::frameSwapped).wait(200)) {
    }
    double otherChange = 0.0;
    const double otherFrame = completeFrame(
        window, [&] { editor->selection()->selectRow(curves > 1 ? 1 : 0); }, &otherChange, &marks, &otherStages);
    // More selection changes, between the second and third curves, for a profiler to see them.
    std::vector<double> moreSelections;
    const auto moreBefore = threadTimes();
    for (int k = 1; k < selections && curves > 2; ++k)
        moreSelections.push_back(completeFrame(
            window, [&] { editor->selection()->selectRow(1 + k % 2); }, nullptr, &marks, &moreStages));
    const auto moreAfter = threadTimes();
    if (!moreSelections.empty())
        std::fprintf(stderr, "  %zu more selection changes, median %.2f ms\n", moreSelections.size(),
                     median(moreSelections));
    // A curve selected when none was: the side panel makes its selected curve's section (settings,
    // coordinates table) anew; not part of the figure below, which is between curves.
    completeFrame(window, [&] { editor->selection()->clear(); });
    double fromNothingChange = 0.0;
    std::vector<Stages> fromNothingStages;
    const auto fromNothingBefore = threadTimes();
    const double fromNothingFrame = completeFrame(
        window, [&] { editor->selection()->selectRow(0); }, &fromNothingChange, &marks, &fromNothingStages);
    const auto fromNothingAfter = threadTimes();
    std::fprintf(stderr,
                 "  selection from nothing, until drawn %.2f ms, of which the change on the GUI thread %.2f ms\n",
                 fromNothingFrame, fromNothingChange);
    const double selectFrame = std::max(pressFrame, otherFrame);
    const double selectChange = pressFrame > otherFrame ? pressChange.front() : otherChange;

    std::fprintf(stderr,
                 "%s backend (layer: %s), %d curves (%d Bezier segments), frames from the change to the swap:\n"
                 "  start-up to the first frame  %8.1f ms   (target <= 500)\n"
                 "  pinch-zoom frame   median %8.2f ms, p90 %8.2f ms   (target <= 16)\n"
                 "    of which the change on the GUI thread, median %5.2f ms\n"
                 "  handle-drag frame  median %8.2f ms, p90 %8.2f ms   (target <= 8)\n"
                 "    of which the change on the GUI thread, median %5.2f ms\n"
                 "  view jump (+ button), until drawn sharp %7.2f ms\n"
                 "    of which the change on the GUI thread %5.2f ms\n"
                 "  selection change, until drawn %8.2f ms   (the slower of two)\n"
                 "    of which the change on the GUI thread (models, side panel) %5.2f ms\n",
                 qPrintable(canvas->graphicsApi()), qPrintable(canvas->layerKind()), curves, curves * 100, startup,
                 median(zoomFrames), p90(zoomFrames), median(zoomChanges), median(dragFrames), p90(dragFrames),
                 median(dragChanges), jumpFrame, jumpChange, selectFrame, selectChange);
    if (showStages) {
        printStages("pinch-zoom frames", zoomStages);
        printThreadTimes("pinch-zoom frames", zoomBefore, zoomAfter, frames);
        std::fprintf(stderr, "    %d frames drawn for %d changes\n", zoomSwaps, frames);
        printStages("handle-drag frames", dragStages);
        printThreadTimes("handle-drag frames", dragBefore, dragAfter, frames);
        std::fprintf(stderr, "    %d frames drawn for %d changes\n", dragSwaps, frames);
        // "sync begins" is when the GUI thread is done with the frame: the change, then the
        // polish of the items it touched (layouts, views making delegates).
        printStages("first selection (curve 0 after the last one made, and the press), first frame", pressStages);
        printStages("second selection (row 1), first frame", otherStages);
        printStages("more selection changes, first frame", moreStages);
        printStages("selection from nothing, first frame", fromNothingStages);
        printThreadTimes("selection from nothing (all its frames)", fromNothingBefore, fromNothingAfter, 1);
        printThreadTimes("more selection changes (a frame: a change)", moreBefore, moreAfter,
                         static_cast<int>(moreSelections.size()));
    }
    std::printf("{\"backend\":\"%s\",\"layer\":\"%s\",\"curves\":%d,\"segments\":%d,\"startup_ms\":%.1f,"
                "\"zoom_frame_median_ms\":%.2f,\"zoom_frame_p90_ms\":%.2f,"
                "\"drag_frame_median_ms\":%.2f,\"drag_frame_p90_ms\":%.2f,"
                "\"zoom_change_median_ms\":%.2f,\"drag_change_median_ms\":%.2f,"
                "\"jump_frame_ms\":%.2f,\"jump_change_ms\":%.2f,\"select_frame_ms\":%.2f,\"select_change_ms\":%.2f}\n",
                qPrintable(canvas->graphicsApi()), qPrintable(canvas->layerKind()), curves, curves * 100, startup,
                median(zoomFrames), p90(zoomFrames), median(dragFrames), p90(dragFrames), median(zoomChanges),
                median(dragChanges), jumpFrame, jumpChange, selectFrame, selectChange);
    return 0;
}
