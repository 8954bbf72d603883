// Timings of the spline families for kontur-cli bench (see splinebench.h).
#include "cli/splinebench.h"

#include <QStringList>

#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <random>

namespace kontur::cli {

namespace {

// A random walk heading right: distinct consecutive points, like a traced contour.
std::vector<geo::Point> walk(std::size_t n, double scale, std::mt19937_64 &rng)
{
    std::normal_distribution<double> step(0.0, 0.01 * scale);
    std::vector<geo::Point> pts(n < 4 ? 4 : n);
    geo::Point p(0.0, 0.0);
    for (auto &q : pts) {
        p += geo::Point(0.01 * scale + std::abs(step(rng)), step(rng));
        q = p;
    }
    return pts;
}

// The spline with all its pieces: the parameters, the solved tangents and the points, which are the
// Hermite form of every segment (its Bézier control points are two multiply-adds away, see
// HermiteSpline::segmentControlPoints). With `bezier`, also the flat array of all 3n + 1 Bézier
// control points.
double buildAll(const std::vector<geo::Point> &pts, geo::EndCondition end, bool bezier)
{
    const auto s = geo::cubicSpline(pts, end, geo::Parameterization::ChordLength, geo::Point(1, 0), geo::Point(1, 0));
    if (!s)
        return -1.0;
    if (!bezier)
        return s->tangents()[s->tangents().size() / 2].x();
    const auto ctrl = s->bezierControlPoints();
    return ctrl[ctrl.size() / 2].x();
}

} // namespace

std::optional<SplineBenchTiming> runSplineBench(const QString &op, std::size_t n, int repeat, double scale)
{
    QString name = op;
    const bool bezier = name.endsWith(QLatin1String("+bezier"));
    if (bezier)
        name.chop(7);
    static const QStringList known{QStringLiteral("spline-natural"),  QStringLiteral("spline-clamped"),
                                   QStringLiteral("spline-periodic"), QStringLiteral("global-bspline"),
                                   QStringLiteral("spline-eval"),     QStringLiteral("natural-drag")};
    if (!known.contains(name))
        return std::nullopt;
    std::mt19937_64 rng(20240604);
    SplineBenchTiming timing;
    const auto pts = walk(n, scale, rng);
    if (name == QLatin1String("spline-natural") || name == QLatin1String("spline-clamped") ||
        name == QLatin1String("spline-periodic")) {
        const geo::EndCondition end = name == QLatin1String("spline-natural")   ? geo::EndCondition::Natural
                                      : name == QLatin1String("spline-clamped") ? geo::EndCondition::Clamped
                                                                                : geo::EndCondition::Periodic;
        timing = measure(repeat, 1.0, [&] { return buildAll(pts, end, bezier); });
        timing.per = bezier ? "spline and the array of its Bézier control points" : "spline (all pieces, Hermite form)";
    } else if (name == QLatin1String("global-bspline")) {
        timing = measure(repeat, 1.0, [&] {
            const auto g =
                geo::globalBSpline(pts, geo::Parameterization::ChordLength, geo::Point(1, 0), geo::Point(1, 0));
            return g ? g->controlPoints()[g->controlPoints().size() / 2].x() : -1.0;
        });
        timing.per = "global B-spline";
    } else if (name == QLatin1String("spline-eval")) {
        // The natural spline through N points, evaluated at N sorted parameters over its whole range.
        const auto s = geo::cubicSpline(pts, geo::EndCondition::Natural, geo::Parameterization::ChordLength);
        if (!s)
            return std::nullopt;
        std::vector<double> u(pts.size());
        std::uniform_real_distribution<double> pick(s->startParameter(), s->endParameter());
        for (double &x : u)
            x = pick(rng);
        std::sort(u.begin(), u.end());
        std::vector<geo::Point> out(u.size());
        timing = measure(repeat, 1.0, [&] {
            s->evalSorted(u, out);
            return out[out.size() / 2].y();
        });
        timing.per = "evaluation at N sorted parameters";
    } else if (name == QLatin1String("natural-drag")) {
        // Each operation moves one point of the N-point natural spline and recomputes the spline.
        constexpr int kDrags = 100;
        std::vector<geo::Point> moving = pts;
        std::uniform_int_distribution<std::size_t> pick(0, moving.size() - 1);
        timing = measure(repeat, kDrags, [&] {
            double sum = 0.0;
            for (int d = 0; d < kDrags; ++d) {
                const std::size_t k = pick(rng);
                moving[k] += geo::Point(0.001 * scale, -0.0005 * scale);
                const auto s = geo::cubicSpline(moving, geo::EndCondition::Natural, geo::Parameterization::ChordLength);
                sum += s ? s->tangents()[k].x() : -1.0;
            }
            return sum;
        });
        timing.per = "drag step";
    } else {
        return std::nullopt;
    }
    return timing;
}

} // namespace kontur::cli
