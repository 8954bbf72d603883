// Kontur's geometry beside lib2geom (Inkscape's geometry library), on the same random data in one
// run (issue 21): the nearest point on a cubic, the arc length to 1e-9 and the stroke fit. Built only
// where Debian's lib2geom-dev is installed (an optional dependency of this program, never of the app);
// run by hand: build/tests/bench/bench_peers. Times are the best of several runs, per operation.
#include "geometry/arclength.h"
#include "geometry/bezier.h"
#include "geometry/nearest.h"
#include "geometry/strokefit.h"

#include <2geom/bezier-curve.h>
#include <2geom/bezier-utils.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// The best time of `rounds` runs of `body` over `count` items, in nanoseconds per item.
double bestPerItem(int rounds, std::size_t count, const std::function<void()> &body)
{
    double best = 1e300;
    for (int r = 0; r < rounds; ++r) {
        const auto start = Clock::now();
        body();
        const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
        best = std::min(best, ns / static_cast<double>(count));
    }
    return best;
}

// The best times of Kontur's and the peer's bodies, their rounds taken in turn (so that a moment
// of load on this shared machine slows both alike), in nanoseconds per item.
std::pair<double, double> bestPerItemInTurn(int rounds, std::size_t count, const std::function<void()> &ours,
                                            const std::function<void()> &peer)
{
    double bestOurs = 1e300, bestPeer = 1e300;
    for (int r = 0; r < rounds; ++r) {
        bestOurs = std::min(bestOurs, bestPerItem(1, count, ours));
        bestPeer = std::min(bestPeer, bestPerItem(1, count, peer));
    }
    return {bestOurs, bestPeer};
}

Geom::CubicBezier toGeom(const kontur::geo::Bezier &b)
{
    const auto &c = b.controlPoints();
    return Geom::CubicBezier(Geom::Point(c[0].x(), c[0].y()), Geom::Point(c[1].x(), c[1].y()),
                             Geom::Point(c[2].x(), c[2].y()), Geom::Point(c[3].x(), c[3].y()));
}

// The 5,000-point stroke of `kontur-cli bench trace-fit`: a line, a wave and a line back, jittered.
std::vector<kontur::geo::Point> benchStroke(std::size_t count)
{
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    std::vector<kontur::geo::Point> stroke(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double u = 3.0 * static_cast<double>(i) / static_cast<double>(count - 1);
        kontur::geo::Point p;
        if (u < 1.0)
            p = {200.0 * u, 0.0};
        else if (u < 2.0)
            p = {200.0 + 40.0 * std::sin(2.0 * 3.141592653589793 * (u - 1.0)), 250.0 * (u - 1.0)};
        else
            p = {200.0 - 200.0 * (u - 2.0), 250.0};
        stroke[i] = p + kontur::geo::Point(jitter(rng), jitter(rng));
    }
    return stroke;
}

// A mouse stroke along three G1 cubics at 256 % (whole screen pixels), 350 samples.
std::vector<kontur::geo::Point> pixelStroke()
{
    const double zoom = 2.56;
    const std::vector<kontur::geo::Bezier> cubics{kontur::geo::Bezier({{0, 0}, {20, 40}, {40, 40}, {60, 30}}),
                                                  kontur::geo::Bezier({{60, 30}, {80, 20}, {100, -10}, {120, 0}}),
                                                  kontur::geo::Bezier({{120, 0}, {140, 10}, {160, 50}, {180, 40}})};
    std::vector<kontur::geo::Point> out;
    for (const auto &c : cubics)
        for (int i = 0; i < 117; ++i) {
            const kontur::geo::Point p = c.eval(i / 117.0);
            out.emplace_back(std::round(p.x() * zoom) / zoom, std::round(p.y() * zoom) / zoom);
        }
    return out;
}

int geomFit(const std::vector<kontur::geo::Point> &stroke, double tolerance)
{
    std::vector<Geom::Point> data;
    for (const auto &p : stroke)
        data.emplace_back(p.x(), p.y());
    std::vector<Geom::Point> out(4 * data.size());
    // The error lib2geom takes is the squared distance.
    return Geom::bezier_fit_cubic_r(out.data(), data.data(), static_cast<int>(data.size()), tolerance * tolerance,
                                    static_cast<unsigned>(data.size()));
}

} // namespace

int main()
{
    std::mt19937_64 rng(20261125);
    std::uniform_real_distribution<double> coord(0.0, 100.0);
    const std::size_t n = 20000;
    std::vector<kontur::geo::Bezier> curves;
    std::vector<Geom::CubicBezier> geomCurves;
    std::vector<kontur::geo::Point> queries;
    for (std::size_t i = 0; i < n; ++i) {
        curves.emplace_back(std::vector<kontur::geo::Point>{
            {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}});
        geomCurves.push_back(toGeom(curves.back()));
        queries.emplace_back(coord(rng), coord(rng));
    }
    volatile double sink = 0.0;

    // Nearest point: time per query, and how much farther lib2geom's answer is than Kontur's exact one.
    const auto [kNearest, gNearest] = bestPerItemInTurn(
        15, n,
        [&] {
            for (std::size_t i = 0; i < n; ++i)
                sink = sink + kontur::geo::nearest(curves[i], queries[i]).distance;
        },
        [&] {
            for (std::size_t i = 0; i < n; ++i)
                sink = sink + geomCurves[i].nearestTime(Geom::Point(queries[i].x(), queries[i].y()));
        });
    double nearestWorse = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = geomCurves[i].nearestTime(Geom::Point(queries[i].x(), queries[i].y()));
        const double d = (curves[i].eval(t) - queries[i]).norm();
        nearestWorse = std::max(nearestWorse, d - kontur::geo::nearest(curves[i], queries[i]).distance);
    }

    // Arc length to 1e-9: time per curve and the largest error against a 1e-13 reference.
    const auto [kLength, gLength] = bestPerItemInTurn(
        5, n,
        [&] {
            for (std::size_t i = 0; i < n; ++i)
                sink = sink + kontur::geo::arcLength(curves[i], 1e-9);
        },
        [&] {
            for (std::size_t i = 0; i < n; ++i)
                sink = sink + geomCurves[i].length(1e-9);
        });
    double kLengthError = 0.0, gLengthError = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double reference = kontur::geo::arcLength(curves[i], 1e-13);
        kLengthError = std::max(kLengthError, std::abs(kontur::geo::arcLength(curves[i], 1e-9) - reference));
        gLengthError = std::max(gLengthError, std::abs(geomCurves[i].length(1e-9) - reference));
    }

    // Stroke fit at 0.5: segments and time.
    kontur::geo::StrokeFitOptions options;
    options.tolerance = 0.5;
    const auto stroke = benchStroke(5000);
    int kSegments = 0, gSegments = 0;
    const double kFit = bestPerItem(7, 1, [&] { kSegments = kontur::geo::fitStroke(stroke, options)->segmentCount(); });
    const double gFit = bestPerItem(7, 1, [&] { gSegments = geomFit(stroke, options.tolerance); });
    const auto pixels = pixelStroke();
    const int kPixel = kontur::geo::fitStroke(pixels, options)->segmentCount();
    const int gPixel = geomFit(pixels, options.tolerance);

    std::printf("operation                          Kontur        lib2geom      ratio (lib2geom / Kontur)\n");
    std::printf("nearest point on a cubic          %8.3f us   %8.3f us   %5.2fx  (lib2geom up to %.2g farther)\n",
                kNearest / 1e3, gNearest / 1e3, gNearest / kNearest, nearestWorse);
    std::printf("arc length to 1e-9                %8.3f us   %8.3f us   %5.2fx  (errors %.1e / %.1e)\n", kLength / 1e3,
                gLength / 1e3, gLength / kLength, kLengthError, gLengthError);
    std::printf("stroke fit, 5000 points, 0.5      %8.3f ms   %8.3f ms   %5.2fx  (%d / %d segments)\n", kFit / 1e6,
                gFit / 1e6, gFit / kFit, kSegments, gSegments);
    std::printf("mouse stroke along 3 cubics, 0.5  %d segments / %d segments\n", kPixel, gPixel);
    return sink == 42.0 ? 1 : 0;
}
