// Offset curves (seam allowance, issue #22): circles offset to exact radii, rounded rectangles,
// square corners with miter / bevel / round joins, random closed curves over scales, the loops of a
// tight curve's inside offset cut away; every case checked by the two-way distance property: each
// point of the result is at the distance ± tolerance from the source, and each valid offset point of
// the source lies within tolerance of the result. Over 600 lines because the cases share those
// oracles (twoWay, samples, selfCrossing, randomKnots) and the work-budget checks their pieces.
#include "geometry/composite.h"
#include "geometry/offset.h"
#include "testutil.h"

#include <QtTest>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

using kontur::geo::Bezier;
using kontur::geo::OffsetJoin;
using kontur::geo::OffsetOptions;
using kontur::geo::OffsetSide;
using kontur::geo::PiecewiseBezier;
using kontur::geo::Point;

namespace {

constexpr double pi = std::numbers::pi;

// A long wavy closed piece of `knots` composite knots (a radius of 200 with waves of 30 and 10):
// its inside offset at 40 crosses itself often, and the trimming's nearest-point queries on so many
// segments make it the slow case the app computes off its GUI thread.
PiecewiseBezier wavyPiece(int knots)
{
    std::vector<Point> p;
    for (int i = 0; i < knots; ++i) {
        const double t = 2 * pi * i / knots;
        const double r = 200 + 30 * std::sin(7 * t) + 10 * std::sin(23 * t);
        p.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    kontur::geo::CompositeCurve comp(p);
    (void)comp.close();
    return comp.toPiecewise();
}

// A circle of `pieces` cubic arcs (radial error about 2.7e-4 r (4 / pieces)^6).
PiecewiseBezier circle(const Point &c, double r, int pieces, bool clockwise = false)
{
    std::vector<Bezier> out;
    const double phi = 2 * pi / pieces * (clockwise ? -1 : 1);
    const double k = 4.0 / 3.0 * std::tan(phi / 4) * r;
    for (int i = 0; i < pieces; ++i) {
        const double a0 = i * phi, a1 = a0 + phi;
        const Point p0 = c + r * Point(std::cos(a0), std::sin(a0)), p3 = c + r * Point(std::cos(a1), std::sin(a1));
        out.emplace_back(std::vector<Point>{p0, p0 + k * Point(-std::sin(a0), std::cos(a0)),
                                            p3 - k * Point(-std::sin(a1), std::cos(a1)), p3});
    }
    std::vector<Point> last = out.back().controlPoints();
    last.back() = out.front().startPoint();
    out.back() = Bezier(last);
    return PiecewiseBezier(std::move(out), true);
}

Bezier seg(const Point &a, const Point &b)
{
    return Bezier({a, b});
}

// A rectangle w × h at the origin with corners of radius r (quarter circles of 4 cubic pieces each).
PiecewiseBezier roundedRect(double w, double h, double r)
{
    std::vector<Bezier> out;
    const auto arc = [&](const Point &c, double from) {
        const PiecewiseBezier q = circle(c, r, 16);
        const int first = static_cast<int>(std::lround(from / (pi / 8)));
        for (int i = 0; i < 4; ++i)
            out.push_back(q.segments()[static_cast<std::size_t>(first + i)]);
    };
    out.push_back(seg({r, 0}, {w - r, 0}));
    arc({w - r, r}, 1.5 * pi);
    out.push_back(seg({w, r}, {w, h - r}));
    arc({w - r, h - r}, 0.0);
    out.push_back(seg({w - r, h}, {r, h}));
    arc({r, h - r}, 0.5 * pi);
    out.push_back(seg({0, h - r}, {0, r}));
    arc({r, r}, pi);
    // Snap the joints (the arcs' ends agree to rounding).
    for (std::size_t i = 0; i < out.size(); ++i) {
        std::vector<Point> c = out[i].controlPoints();
        c.back() = out[(i + 1) % out.size()].startPoint();
        out[i] = Bezier(c);
    }
    return PiecewiseBezier(std::move(out), true);
}

std::vector<Point> samples(const PiecewiseBezier &curve, int perSegment)
{
    std::vector<Point> out;
    for (const Bezier &b : curve.segments())
        for (int k = 0; k < perSegment; ++k)
            out.push_back(b.eval((k + 0.5) / perSegment));
    return out;
}

struct TwoWay
{
    double forward = 0.0;  // largest | distance(result point, source) − d |
    double backward = 0.0; // largest distance from a valid offset point of the source to the result
};

// The two-way distance property by sampling.
TwoWay twoWay(const PiecewiseBezier &source, const PiecewiseBezier &result, double d, int sign)
{
    TwoWay tw;
    for (const Point &q : samples(result, 24))
        tw.forward = std::max(tw.forward, std::abs(source.nearest(q).distance - d));
    for (const Bezier &b : source.segments())
        for (int k = 0; k <= 24; ++k) {
            const double t = k / 24.0;
            const Point der = b.derivative(t);
            if (der.norm() == 0.0)
                continue;
            const Point n(-der.y() / der.norm(), der.x() / der.norm());
            const Point o = b.eval(t) + sign * d * n;
            if (source.nearest(o).distance < d * (1 - 1e-9))
                continue; // cut away: nearer another part of the source
            tw.backward = std::max(tw.backward, result.nearest(o).distance);
        }
    return tw;
}

// 4 to 11 knots around the origin at about `scale`, one in each of as many equal sectors: a random
// piece's outline once closed.
std::vector<Point> randomKnots(std::mt19937_64 &rng, double scale)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = 4 + static_cast<int>(unit(rng) * 8);
    std::vector<Point> knots;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * pi * (i + 0.7 * unit(rng)) / n;
        knots.push_back(scale * (0.6 + 0.4 * unit(rng)) * Point(std::cos(a), std::sin(a)));
    }
    return knots;
}

// Whether the polyline of a curve crosses itself (segments that share no end).
bool selfCrossing(const PiecewiseBezier &curve, double tol)
{
    std::vector<Point> p;
    curve.flatten(tol, p);
    const auto cross = [](const Point &a, const Point &b) { return a.x() * b.y() - a.y() * b.x(); };
    const std::size_t n = p.size();
    for (std::size_t i = 0; i + 1 < n; ++i)
        for (std::size_t j = i + 2; j + 1 < n; ++j) {
            if (curve.isClosed() && i == 0 && j + 2 == n)
                continue;
            const Point r = p[i + 1] - p[i], s = p[j + 1] - p[j];
            const double den = cross(r, s);
            if (den == 0.0)
                continue;
            const double a = cross(p[j] - p[i], s) / den, b = cross(p[j] - p[i], r) / den;
            if (a > 1e-9 && a < 1 - 1e-9 && b > 1e-9 && b < 1 - 1e-9)
                return true;
        }
    return false;
}

} // namespace

class TestOffset : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void circleRadius_data()
    {
        QTest::addColumn<double>("radius");
        QTest::addColumn<double>("distance");
        QTest::addColumn<bool>("outside");
        QTest::addColumn<bool>("clockwise");
        QTest::addRow("outside ccw") << 10.0 << 1.0 << true << false;
        QTest::addRow("outside cw") << 10.0 << 1.0 << true << true;
        QTest::addRow("inside ccw") << 10.0 << 1.0 << false << false;
        QTest::addRow("inside cw") << 10.0 << 1.0 << false << true;
        QTest::addRow("inside deep") << 10.0 << 9.0 << false << false;
        QTest::addRow("large outside") << 300.0 << 15.0 << true << false;
    }
    void circleRadius()
    {
        QFETCH(double, radius);
        QFETCH(double, distance);
        QFETCH(bool, outside);
        QFETCH(bool, clockwise);
        const PiecewiseBezier src = circle({3, -2}, radius, 32, clockwise);
        OffsetOptions o;
        o.distance = distance;
        o.side = outside ? OffsetSide::Outside : OffsetSide::Inside;
        o.tolerance = 0.005;
        const auto r = kontur::geo::offsetCurve(src, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        QVERIFY(r->curve.isClosed());
        const double expected = outside ? radius + distance : radius - distance;
        for (const Point &q : samples(r->curve, 32))
            QVERIFY2(std::abs((q - Point(3, -2)).norm() - expected) <= o.tolerance,
                     qPrintable(QString::number((q - Point(3, -2)).norm() - expected)));
        const TwoWay tw = twoWay(src, r->curve, distance, kontur::geo::offsetSign(src, o.side));
        QVERIFY2(tw.forward <= o.tolerance && tw.backward <= o.tolerance,
                 qPrintable(QStringLiteral("%1 %2").arg(tw.forward).arg(tw.backward)));
        QCOMPARE(r->loopsRemoved, 0);
    }

    void wideInsideLeavesNothing()
    {
        OffsetOptions o;
        o.distance = 12.0;
        o.side = OffsetSide::Inside;
        QVERIFY(!kontur::geo::offsetCurve(circle({0, 0}, 10.0, 8), o).ok());
        o.distance = 0.0;
        QVERIFY(!kontur::geo::offsetCurve(circle({0, 0}, 10.0, 8), o).ok());
    }

    void roundedRectangle_data()
    {
        QTest::addColumn<bool>("outside");
        QTest::addColumn<double>("corner");
        QTest::addRow("outside") << true << 3.0;
        QTest::addRow("inside") << false << 3.0;
        QTest::addRow("inside sharp") << false << 0.5;
    }
    void roundedRectangle()
    {
        QFETCH(bool, outside);
        QFETCH(double, corner);
        const PiecewiseBezier src = roundedRect(40.0, 25.0, corner);
        OffsetOptions o;
        o.distance = 1.0;
        o.side = outside ? OffsetSide::Outside : OffsetSide::Inside;
        o.join = OffsetJoin::Round;
        o.tolerance = 0.005;
        const auto r = kontur::geo::offsetCurve(src, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        QVERIFY(r->curve.isClosed());
        // The larger (smaller) rounded rectangle: its box grows (shrinks) by the distance.
        const kontur::geo::Box box = r->curve.boundingBox();
        const double s = outside ? 1.0 : -1.0;
        QVERIFY(std::abs(box.min().x() + s) <= o.tolerance && std::abs(box.max().x() - 40.0 - s) <= o.tolerance);
        QVERIFY(std::abs(box.min().y() + s) <= o.tolerance && std::abs(box.max().y() - 25.0 - s) <= o.tolerance);
        // Its corners are arcs of radius corner ± distance about the source's corner centres; a corner
        // tighter than the distance becomes sharp inside (its loop cut).
        const double cr = corner + s * 1.0;
        const Point centre(40.0 - corner, 25.0 - corner);
        const Point diag =
            outside || cr > 0 ? Point(centre + cr * Point(1, 1).normalized()) : Point(40.0 - 1.0, 25.0 - 1.0);
        QVERIFY2(r->curve.nearest(diag).distance <= o.tolerance,
                 qPrintable(QString::number(r->curve.nearest(diag).distance)));
        const TwoWay tw = twoWay(src, r->curve, 1.0, kontur::geo::offsetSign(src, o.side));
        QVERIFY2(tw.forward <= o.tolerance && tw.backward <= o.tolerance,
                 qPrintable(QStringLiteral("%1 %2").arg(tw.forward).arg(tw.backward)));
        QVERIFY(!selfCrossing(r->curve, 0.01));
        if (!outside && corner < 1.0)
            QVERIFY(r->loopsRemoved >= 4);
    }

    // A square of straight pieces: a miter gives the larger square, a limit below d√2 bevels, round
    // gives quarter circles.
    void squareJoins()
    {
        const std::vector<Point> c{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
        std::vector<Bezier> sides;
        for (int i = 0; i < 4; ++i)
            sides.push_back(seg(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>((i + 1) % 4)]));
        const PiecewiseBezier square(sides, true);
        OffsetOptions o;
        o.distance = 1.0;
        o.miterLimit = 2.0;
        auto r = kontur::geo::offsetCurve(square, o);
        QVERIFY(r.ok());
        QVERIFY(r->curve.nearest({-1, -1}).distance < 1e-9);
        QVERIFY(r->curve.nearest({11, 11}).distance < 1e-9);
        QVERIFY(std::abs(r->curve.length(1e-9) - 48.0) < 1e-6);
        o.miterLimit = 1.4; // below √2: bevel
        r = kontur::geo::offsetCurve(square, o);
        QVERIFY(r.ok());
        QVERIFY(std::abs(r->curve.length(1e-9) - (40.0 + 4 * std::sqrt(2.0))) < 1e-6);
        o.join = OffsetJoin::Round;
        r = kontur::geo::offsetCurve(square, o);
        QVERIFY(r.ok());
        QVERIFY(std::abs(r->curve.length(1e-9) - (40.0 + 2 * pi)) < 1e-3);
        // Inside: the smaller square, whatever the join (the corners' loops are cut).
        o.side = OffsetSide::Inside;
        for (OffsetJoin j : {OffsetJoin::Miter, OffsetJoin::Bevel, OffsetJoin::Round}) {
            o.join = j;
            r = kontur::geo::offsetCurve(square, o);
            QVERIFY(r.ok());
            QVERIFY2(std::abs(r->curve.length(1e-9) - 32.0) < 1e-6, qPrintable(QString::number(r->curve.length(1e-9))));
            QVERIFY(r->curve.nearest({1, 1}).distance < 1e-6);
        }
    }

    // Open curves: Left and Right follow the direction; Outside is away from the chord's area.
    void openSides()
    {
        const PiecewiseBezier arch({Bezier({{0, 0}, {0, 10}, {10, 10}, {10, 0}})}, false);
        OffsetOptions o;
        o.side = OffsetSide::Outside;
        auto r = kontur::geo::offsetCurve(arch, o);
        QVERIFY(r.ok());
        QVERIFY(!r->curve.isClosed());
        QVERIFY(r->curve.boundingBox().max().y() > arch.boundingBox().max().y() + 0.9);
        // The arch runs clockwise over its chord's area: its left is the outside.
        QCOMPARE(kontur::geo::offsetSign(arch, OffsetSide::Outside), kontur::geo::offsetSign(arch, OffsetSide::Left));
        o.side = OffsetSide::Right;
        r = kontur::geo::offsetCurve(arch, o);
        QVERIFY(r.ok());
        QVERIFY(r->curve.boundingBox().max().y() < arch.boundingBox().max().y() - 0.9);
    }

    // An ellipse 10 × 1.5 has a radius of curvature 0.225 at its ends: its inside offset at 1 turns
    // back there (swallowtails); the loops are cut and the result does not cross itself.
    void tightInsideLoopsCut()
    {
        std::vector<Bezier> pieces;
        const PiecewiseBezier c = circle({0, 0}, 1.0, 32);
        for (const Bezier &b : c.segments()) {
            std::vector<Point> p = b.controlPoints();
            for (Point &q : p)
                q = Point(10.0 * q.x(), 1.5 * q.y());
            pieces.emplace_back(p);
        }
        const PiecewiseBezier ellipse(pieces, true);
        OffsetOptions o;
        o.distance = 1.0;
        o.side = OffsetSide::Inside;
        o.join = OffsetJoin::Round;
        const auto r = kontur::geo::offsetCurve(ellipse, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        QVERIFY(r->loopsRemoved >= 2);
        QVERIFY(!selfCrossing(r->curve, 0.002));
        const TwoWay tw = twoWay(ellipse, r->curve, 1.0, kontur::geo::offsetSign(ellipse, o.side));
        QVERIFY2(tw.forward <= o.tolerance && tw.backward <= o.tolerance,
                 qPrintable(QStringLiteral("%1 %2").arg(tw.forward).arg(tw.backward)));
        // Open and tight: a hairpin offset on its inside.
        const PiecewiseBezier hairpin({Bezier({{0, 0}, {20, 0}, {20, 6}, {0, 6}})}, false);
        o.side = OffsetSide::Inside;
        const auto h = kontur::geo::offsetCurve(hairpin, o);
        QVERIFY(h.ok());
        QVERIFY(!selfCrossing(h->curve, 0.002));
    }

    // 200 random star-shaped closed composite curves over scales 0.01 … 1000, both sides, round
    // joins: the two-way property within tolerance.
    void randomClosed()
    {
        std::mt19937_64 rng(22);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int failures = 0, tested = 0;
        for (int run = 0; run < 200; ++run) {
            const double scale = std::pow(10.0, -2.0 + 5.0 * unit(rng));
            const std::vector<Point> knots = randomKnots(rng, scale);
            kontur::geo::CompositeCurve comp(knots);
            if (!comp.close().ok())
                continue;
            const PiecewiseBezier src = comp.toPiecewise();
            if (selfCrossing(src, 1e-4 * scale))
                continue; // a source that crosses itself has no well-defined sides
            OffsetOptions o;
            o.distance = scale * (0.01 + 0.1 * unit(rng));
            o.tolerance = o.distance * 0.005;
            o.join = OffsetJoin::Round;
            o.side = run % 2 ? OffsetSide::Inside : OffsetSide::Outside;
            const auto r = kontur::geo::offsetCurve(src, o);
            QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
            ++tested;
            const TwoWay tw = twoWay(src, r->curve, o.distance, kontur::geo::offsetSign(src, o.side));
            if (!(tw.forward <= o.tolerance && tw.backward <= o.tolerance)) {
                ++failures;
                qWarning() << run << scale << o.distance << tw.forward / o.tolerance << tw.backward / o.tolerance
                           << r->loopsRemoved << r->partsDropped << int(o.side);
                for (const Point &k : knots)
                    qWarning() << k.x() << k.y();
            }
        }
        QCOMPARE(failures, 0);
        QVERIFY2(tested >= 180, qPrintable(QString::number(tested))); // few sources cross themselves
    }

    // The same random pieces as polylines of short chords (as AAMA writes a sew line, or a trace
    // before its fit): where a concave bend's chords are shorter than the distance turns them, a
    // chord's offset vanishes between its neighbours' and the loops are shallower than the tolerance.
    // Judged by a fixed margin those came out differently on the two sides of a crossing and the
    // allowance fell apart (a traced bodice's: open, 3 parts dropped, 803 mm of about 1,125).
    void randomPolylines()
    {
        std::mt19937_64 rng(45);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int failures = 0, tested = 0;
        for (int run = 0; run < 120; ++run) {
            const double scale = std::pow(10.0, -2.0 + 5.0 * unit(rng));
            kontur::geo::CompositeCurve comp(randomKnots(rng, scale));
            if (!comp.close().ok())
                continue;
            const PiecewiseBezier smooth = comp.toPiecewise();
            if (selfCrossing(smooth, 1e-4 * scale))
                continue;
            std::vector<Point> points;
            smooth.flatten((1e-5 + 1e-4 * unit(rng)) * scale, points);
            std::vector<Bezier> chords;
            for (std::size_t i = 0; i < points.size(); ++i)
                if (const Point &a = points[i], &b = points[(i + 1) % points.size()]; (b - a).norm() > 0)
                    chords.push_back(seg(a, b));
            const PiecewiseBezier src(std::move(chords), true);
            OffsetOptions o;
            o.distance = scale * (0.01 + 0.1 * unit(rng));
            o.tolerance = o.distance * 0.005;
            o.join = OffsetJoin::Round;
            o.side = run % 2 ? OffsetSide::Inside : OffsetSide::Outside;
            const auto r = kontur::geo::offsetCurve(src, o);
            QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
            ++tested;
            // Two ways, sampled more sparsely than twoWay (the chords are many): the allowance's points
            // at the distance, and each chord's middle pushed out by it, where that is nearest its own
            // chord, on the allowance.
            double forward = 0.0, backward = 0.0;
            for (const Point &q : samples(r->curve, 3))
                forward = std::max(forward, std::abs(src.nearest(q).distance - o.distance));
            const int sign = kontur::geo::offsetSign(src, o.side);
            for (const Bezier &c : src.segments()) {
                const Point t = (c.endPoint() - c.startPoint()).normalized();
                const Point out = c.eval(0.5) + sign * o.distance * Point(-t.y(), t.x());
                if (src.nearest(out).distance >= o.distance * (1 - 1e-9))
                    backward = std::max(backward, r->curve.nearest(out).distance);
            }
            if (!r->curve.isClosed() || !(forward <= o.tolerance && backward <= o.tolerance)) {
                ++failures;
                qWarning() << run << scale << src.segmentCount() << o.distance << r->curve.isClosed() << r->partsDropped
                           << forward / o.tolerance << backward / o.tolerance << int(o.side);
            }
        }
        QCOMPARE(failures, 0);
        QVERIFY2(tested >= 100, qPrintable(QString::number(tested)));
    }

    // Absurd settings (a tolerance below what doubles resolve, widths out of all proportion, a curve at
    // 1e150 or 1e300) return within the work budget: a result within the tolerance used, or a
    // refusal with its reason. Before the budget these froze or ran out of memory.
    void boundedWork_data()
    {
        QTest::addColumn<double>("radius");
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("tolerance");
        QTest::addColumn<int>("expected"); // -1: a result; else the ErrorCode
        const int ok = -1, prop = static_cast<int>(kontur::geo::ErrorCode::OutOfProportion);
        QTest::addRow("tolerance 1e-300") << 10.0 << 1.0 << 1e-300 << ok;
        QTest::addRow("tolerance 1e-8 at 1e150") << 1e150 << 1e149 << 1e-8 << ok;
        QTest::addRow("width 10 at 1e150") << 1e150 << 10.0 << 0.05 << ok;
        QTest::addRow("width 1e299 at 1e300") << 1e300 << 1e299 << 0.05 << ok;
        QTest::addRow("width 1e12") << 10.0 << 1e12 << 0.005 << prop;
        QTest::addRow("width 1e308") << 10.0 << 1e308 << 1e-300 << prop;
        QTest::addRow("width 1e4 tolerance 1e-12") << 10.0 << 1e4 << 1e-12 << ok;
    }
    void boundedWork()
    {
        QFETCH(double, radius);
        QFETCH(double, distance);
        QFETCH(double, tolerance);
        QFETCH(int, expected);
        const PiecewiseBezier src = circle({radius / 3, 0}, radius, 8);
        OffsetOptions o;
        o.distance = distance;
        o.tolerance = tolerance;
        o.join = OffsetJoin::Round;
        kontur::geo::detail::resetOffsetWork();
        const auto r = kontur::geo::offsetCurve(src, o);
        const std::uint64_t work = kontur::geo::detail::offsetWork();
        qInfo("%llu steps", static_cast<unsigned long long>(work));
        // The budget is checked after each step, which spends at most a few hundred units.
        QVERIFY2(work <= kontur::geo::kOffsetBudget + 1000, qPrintable(QString::number(work)));
        if (expected >= 0) {
            QVERIFY(!r.ok());
            QCOMPARE(static_cast<int>(r.error().code), expected);
            return;
        }
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        QVERIFY(r->tolerance >= tolerance);
        QCOMPARE(r->tolerance, std::max(tolerance, kontur::geo::resolvableOffsetTolerance(src, distance)));
        // The two-way distance property within the tolerance used.
        for (const Point &q : samples(r->curve, 8))
            QVERIFY(q.allFinite());
        const TwoWay tw = twoWay(src, r->curve, distance, kontur::geo::offsetSign(src, o.side));
        QVERIFY2(tw.forward <= r->tolerance && tw.backward <= r->tolerance,
                 qPrintable(QStringLiteral("%1 %2").arg(tw.forward / r->tolerance).arg(tw.backward / r->tolerance)));
    }

    // The budget is far above what a real piece needs: a bodice at 0.05 mm uses well under 1 %.
    void typicalWorkFarBelowBudget()
    {
        const std::vector<Point> knots{{0, 0},     {120, -5},  {230, 0},  {250, 150}, {235, 300}, {200, 420},
                                       {150, 430}, {110, 380}, {60, 400}, {20, 430},  {-10, 300}, {5, 150}};
        kontur::geo::CompositeCurve comp(knots);
        QVERIFY(comp.close().ok());
        for (OffsetSide side : {OffsetSide::Outside, OffsetSide::Inside}) {
            OffsetOptions o;
            o.distance = 10.0;
            o.tolerance = 0.05;
            o.side = side;
            kontur::geo::detail::resetOffsetWork();
            QVERIFY(kontur::geo::offsetCurve(comp.toPiecewise(), o).ok());
            qInfo("%llu steps", static_cast<unsigned long long>(kontur::geo::detail::offsetWork()));
            QVERIFY(kontur::geo::detail::offsetWork() < kontur::geo::kOffsetBudget / 100);
        }
    }

    // Cancel from another thread (the app's Cancel button) stops the offset within a few steps,
    // whichever stage it is in: the fitting at a tolerance finer than any piece needs, or the
    // trimming of a long source's loops. The steps spent after the flag was set are counted
    // (published every kOffsetPublishSteps, so the count at the moment of cancelling may lag by that
    // many); the time it took is printed, not asserted.
    void cancelMidway_data()
    {
        QTest::addColumn<int>("knots"); // 0: a circle of 8 arcs
        QTest::addColumn<double>("tolerance");
        QTest::addColumn<double>("distance");
        QTest::addColumn<int>("side");
        QTest::addColumn<double>("cancelAt"); // the progress at which Cancel is pressed
        QTest::addColumn<double>("stageEnd"); // the progress at which that stage ends
        QTest::addColumn<int>("cancelWork");  // and the steps after which it is pressed
        QTest::addRow("fitting") << 0 << 1e-300 << 1.0 << int(OffsetSide::Outside) << 0.0 << 0.4 << 20'000;
        QTest::addRow("trimming") << 8000 << 0.05 << 40.0 << int(OffsetSide::Inside) << 0.55 << 1.0 << 100'000;
    }
    void cancelMidway()
    {
        QFETCH(int, knots);
        QFETCH(double, tolerance);
        QFETCH(double, distance);
        QFETCH(int, side);
        QFETCH(double, cancelAt);
        QFETCH(double, stageEnd);
        QFETCH(int, cancelWork);
        const PiecewiseBezier src = knots > 0 ? wavyPiece(knots) : circle({0, 0}, 10.0, 8);
        OffsetOptions o;
        o.distance = distance;
        o.tolerance = tolerance;
        o.side = static_cast<OffsetSide>(side);
        o.join = OffsetJoin::Round;
        kontur::geo::OffsetControl control;
        std::optional<kontur::geo::Result<kontur::geo::OffsetResult>> result;
        std::atomic<bool> done{false};
        std::thread worker([&] {
            result.emplace(kontur::geo::offsetCurve(src, o, &control));
            done = true;
        });
        // Wait (by the published counters, not by time) until the offset is well into its stage.
        std::vector<double> seen;
        while (!done &&
               (control.work.load() < static_cast<std::uint64_t>(cancelWork) || control.progress.load() < cancelAt)) {
            seen.push_back(control.progress.load());
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        const std::uint64_t workAtCancel = control.work.load();
        const double progressAtCancel = control.progress.load();
        const auto cancelled = std::chrono::steady_clock::now();
        control.cancel();
        worker.join();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cancelled).count();
        QVERIFY2(workAtCancel > 0 && result, "the offset finished before it could be cancelled");
        QVERIFY(!result->ok());
        QCOMPARE(result->error().code, kontur::geo::ErrorCode::Cancelled);
        const std::uint64_t after = control.work.load() - workAtCancel;
        qInfo("cancelled at %llu steps (progress %.2f); %llu steps and %.2f ms after Cancel",
              static_cast<unsigned long long>(workAtCancel), progressAtCancel, static_cast<unsigned long long>(after),
              ms);
        // The publishing lag, plus one fitted interval (8 steps) for each of the at most 30 levels of
        // subdivision pending when the flag is seen, plus a step of the other stages.
        QVERIFY2(after <= kontur::geo::kOffsetPublishSteps + 30 * 8 + 16, qPrintable(QString::number(after)));
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));
        QVERIFY(progressAtCancel >= cancelAt && progressAtCancel < stageEnd);
    }

    // A control that is never cancelled changes nothing: the same curve as without one; the progress
    // ends at 1 and the work published is the work counted. Cancelled before it starts, the offset
    // answers at once.
    void controlWithoutCancel()
    {
        const PiecewiseBezier src = wavyPiece(200);
        OffsetOptions o;
        o.distance = 40.0;
        o.tolerance = 0.05;
        o.side = OffsetSide::Inside;
        kontur::geo::OffsetControl control;
        kontur::geo::detail::resetOffsetWork();
        const auto with = kontur::geo::offsetCurve(src, o, &control);
        QVERIFY(with.ok());
        QCOMPARE(control.work.load(), kontur::geo::detail::offsetWork());
        QCOMPARE(control.progress.load(), 1.0);
        const auto without = kontur::geo::offsetCurve(src, o);
        QVERIFY(without.ok());
        QCOMPARE(with->curve.segmentCount(), without->curve.segmentCount());
        for (int i = 0; i < with->curve.segmentCount(); ++i)
            QVERIFY(with->curve.segments()[i].controlPoints() == without->curve.segments()[i].controlPoints());

        kontur::geo::OffsetControl stopped;
        stopped.cancel();
        const auto none = kontur::geo::offsetCurve(src, o, &stopped);
        QVERIFY(!none.ok());
        QCOMPARE(none.error().code, kontur::geo::ErrorCode::Cancelled);
        QVERIFY(stopped.work.load() <= 64);
    }

    void typicalPieceTiming()
    {
        // A bodice-like closed piece of 12 composite knots in millimetres, 10 mm allowance, 0.05 mm.
        const std::vector<Point> knots{{0, 0},     {120, -5},  {230, 0},  {250, 150}, {235, 300}, {200, 420},
                                       {150, 430}, {110, 380}, {60, 400}, {20, 430},  {-10, 300}, {5, 150}};
        kontur::geo::CompositeCurve comp(knots);
        QVERIFY(comp.close().ok());
        const PiecewiseBezier src = comp.toPiecewise();
        OffsetOptions o;
        o.distance = 10.0;
        o.tolerance = 0.05;
        QElapsedTimer timer;
        timer.start();
        const int runs = 20;
        for (int i = 0; i < runs; ++i)
            QVERIFY(kontur::geo::offsetCurve(src, o).ok());
        const double ms = timer.nsecsElapsed() / 1e6 / runs;
        const auto r = kontur::geo::offsetCurve(src, o);
        qInfo("offset of a 12-knot piece: %.3f ms, %d pieces", ms, r->curve.segmentCount());
        const TwoWay tw = twoWay(src, r->curve, o.distance, kontur::geo::offsetSign(src, o.side));
        QVERIFY(tw.backward <= o.tolerance);
    }
};

QTEST_APPLESS_MAIN(TestOffset)
#include "tst_offset.moc"
