// Frame-time benchmarks of the real window (issue targets: with 1,000 curves of 100 Bézier segments,
// a pinch-zoom frame ≤ 16 ms, a handle-drag frame ≤ 8 ms, start-up to the first frame ≤ 500 ms).
// Runs on whatever Qt Quick backend the environment selects (software offscreen, or OpenGL under
// Xvfb); prints a summary with medians and 90th percentiles on stderr and one JSON line on stdout.
// Usage: bench_canvas [--curves N] [--frames F]
//   QT_QPA_PLATFORM=offscreen QT_QUICK_BACKEND=software bench_canvas      (software)
//   xvfb-run -a -s "-screen 0 1280x1024x24" bench_canvas                   (OpenGL through Mesa)
// KONTUR_PROFILE=1 adds the canvas's own timings per frame (sync, software paint parts).
#include "app/application.h"
#include "app/curvecanvas.h"
#include "models/document.h"
#include "models/editcontroller.h"
#include "models/filecontroller.h"

#include <QFile>
#include <QStandardPaths>

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickWindow>
#include <QSignalSpy>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// Waits for the next frame after a change and returns how long it took, in ms; `changeMs`, if
// given, gets the part the change itself took on the GUI thread (models, signals, QML bindings).
double frame(QQuickWindow *window, const std::function<void()> &change, std::vector<double> *changeMs = nullptr)
{
    QSignalSpy swapped(window, &QQuickWindow::frameSwapped);
    QElapsedTimer clock;
    clock.start();
    change();
    if (changeMs)
        changeMs->push_back(static_cast<double>(clock.nsecsElapsed()) / 1e6);
    if (!swapped.wait(5000))
        return -1.0;
    return static_cast<double>(clock.nsecsElapsed()) / 1e6;
}

// Waits until a change is drawn completely (the frame after the change, and any that follow at
// once, e.g. the layer drawn anew) and returns the time to the last of those frames, in ms.
double completeFrame(QQuickWindow *window, const std::function<void()> &change)
{
    QSignalSpy swapped(window, &QQuickWindow::frameSwapped);
    QElapsedTimer clock;
    clock.start();
    change();
    if (!swapped.wait(5000))
        return -1.0;
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
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--curves"))
            curves = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--frames"))
            frames = args[i + 1].toInt();
    }

    QStandardPaths::setTestModeEnabled(true);
    QFile::remove(kontur::FileController::recoveryPath());
    QQmlApplicationEngine engine;
    QQuickWindow *window = kontur::loadMainWindow(engine, {QStringLiteral("en"), QString()});
    if (!window)
        return 1;
    window->resize(1280, 800);
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
        editor->createFromCoordinates(static_cast<int>(kontur::CurveKind::Composite), rows);
    }
    canvas->fitToView();
    QSignalSpy settle(window, &QQuickWindow::frameSwapped);
    settle.wait(20000);

    // A pinch: the fingers' centroid stays, the scale goes up and down by 2 % a frame (within
    // ±20 %), as QML's PinchHandler reports it.
    std::vector<double> zoomFrames, dragFrames, zoomChanges, dragChanges;
    const QPointF centre(canvas->width() / 2, canvas->height() / 2);
    canvas->pinchStarted(centre);
    double scale = 1.0;
    for (int f = 0; f < frames; ++f) {
        scale *= f % 20 < 10 ? 1.02 : 1 / 1.02;
        zoomFrames.push_back(frame(window, [&] { canvas->pinchUpdated(scale, centre); }, &zoomChanges));
    }
    canvas->pinchEnded();
    // The fingers rest: the layer of curves is drawn sharp again at the new view (like a jump).
    while (QSignalSpy(window, &QQuickWindow::frameSwapped).wait(400)) {
    }
    // A jump of the view (the + button): drawn sharp at the new view (the layer anew); then back
    // to the whole drawing.
    const double jumpFrame = completeFrame(window, [&] { canvas->zoomIn(); });
    completeFrame(window, [&] { canvas->fitToView(); });

    const kontur::Curve &first = editor->document()->curve(0);
    const kontur::geo::Point handle = first.definingPoint(151);
    // Pressing on the handle selects its curve (its own frame, as when a finger touches down).
    const double pressFrame = frame(window, [&] {
        editor->selectCurve(0);
        editor->beginDrag(QPointF(handle.x(), handle.y()), 1e-6);
    });
    for (int f = 0; f < frames; ++f)
        dragFrames.push_back(
            frame(window, [&] { editor->dragTo(QPointF(handle.x() + 0.5 * f, handle.y() + 0.25 * f)); }, &dragChanges));
    editor->endDrag();

    // Selecting another curve: the layer of the other curves is drawn anew.
    while (QSignalSpy(window, &QQuickWindow::frameSwapped).wait(200)) {
    }
    const double selectFrame =
        std::max(pressFrame, completeFrame(window, [&] { editor->selectCurve(curves > 1 ? 1 : 0); }));

    std::fprintf(stderr,
                 "%s backend, %d curves (%d Bezier segments), frames from the change to the swap:\n"
                 "  start-up to the first frame  %8.1f ms   (target <= 500)\n"
                 "  pinch-zoom frame   median %8.2f ms, p90 %8.2f ms   (target <= 16)\n"
                 "    of which the change on the GUI thread, median %5.2f ms\n"
                 "  handle-drag frame  median %8.2f ms, p90 %8.2f ms   (target <= 8)\n"
                 "    of which the change on the GUI thread, median %5.2f ms\n"
                 "  view jump (+ button), until drawn sharp %7.2f ms\n"
                 "  selection change, until drawn %8.2f ms   (the slower of two)\n",
                 qPrintable(canvas->graphicsApi()), curves, curves * 100, startup, median(zoomFrames),
                 p90(zoomFrames), median(zoomChanges), median(dragFrames), p90(dragFrames), median(dragChanges),
                 jumpFrame, selectFrame);
    std::printf("{\"backend\":\"%s\",\"curves\":%d,\"segments\":%d,\"startup_ms\":%.1f,"
                "\"zoom_frame_median_ms\":%.2f,\"zoom_frame_p90_ms\":%.2f,"
                "\"drag_frame_median_ms\":%.2f,\"drag_frame_p90_ms\":%.2f,"
                "\"zoom_change_median_ms\":%.2f,\"drag_change_median_ms\":%.2f,"
                "\"jump_frame_ms\":%.2f,\"select_frame_ms\":%.2f}\n",
                qPrintable(canvas->graphicsApi()), curves, curves * 100, startup, median(zoomFrames),
                p90(zoomFrames), median(dragFrames), p90(dragFrames), median(zoomChanges), median(dragChanges),
                jumpFrame, selectFrame);
    return 0;
}
