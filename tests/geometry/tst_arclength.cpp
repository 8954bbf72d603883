// Arc length against closed forms (line, quadratic) within the requested accuracy, its inverse,
// a cusp, and the global nearest point against dense sampling.
#include "geometry/arclength.h"
#include "geometry/nearest.h"
#include "geometry/piecewise.h"
#include "testutil.h"

#include <QtTest>

#include <cmath>
#include <limits>

using kontur::geo::Bezier;
using kontur::geo::Point;
using namespace kontur::test;

Q_DECLARE_METATYPE(std::vector<Point>)

namespace {

// ∫₀¹ sqrt(a t² + b t + c) dt in closed form (a > 0, b² < 4ac: the quadratic Bézier with a
// non-degenerate hodograph). Antiderivative: (2at+b)Q/(4a) + (4ac-b²)/(8a^{3/2}) ln(2√a Q + 2at + b).
double quadraticLength(const Point &p0, const Point &p1, const Point &p2)
{
    const Point A = p1 - p0, B = p2 - 2 * p1 + p0;
    const double a = 4 * B.squaredNorm(), b = 8 * A.dot(B), c = 4 * A.squaredNorm();
    auto F = [&](double t) {
        const double q = std::sqrt(a * t * t + b * t + c);
        return (2 * a * t + b) * q / (4 * a) +
               (4 * a * c - b * b) / (8 * std::pow(a, 1.5)) * std::log(2 * std::sqrt(a) * q + 2 * a * t + b);
    };
    return F(1) - F(0);
}

// Composite Simpson on [lo, hi] with m (even) intervals, for smooth reference integrals.
double simpsonSpeed(const Bezier &c, double lo, double hi, int m)
{
    const Bezier h = c.derivativeCurve(1);
    const double step = (hi - lo) / m;
    double sum = h.eval(lo).norm() + h.eval(hi).norm();
    for (int i = 1; i < m; ++i)
        sum += (i % 2 ? 4 : 2) * h.eval(lo + i * step).norm();
    return sum * step / 3;
}

// An independent reference for a cubic's length, in long double: the speed's minimum found by
// sampling and ternary search, then 5-point Gauss–Legendre on pieces growing geometrically from
// 1e-16 away from it up to 1/2048, so that a dip of any width is resolved.
long double referenceLength(const Bezier &c)
{
    const auto &p = c.controlPoints();
    auto speed = [&](long double t) {
        const long double s = 1 - t;
        long double v[2];
        for (int k = 0; k < 2; ++k)
            v[k] = 3 * (s * s * (p[1][k] - p[0][k]) + 2 * s * t * (p[2][k] - p[1][k]) + t * t * (p[3][k] - p[2][k]));
        return std::sqrt(v[0] * v[0] + v[1] * v[1]);
    };
    constexpr int kSamples = 4096;
    int best = 0;
    long double bestSpeed = speed(0);
    for (int i = 1; i <= kSamples; ++i)
        if (const long double v = speed(static_cast<long double>(i) / kSamples); v < bestSpeed) {
            bestSpeed = v;
            best = i;
        }
    long double lo = std::max(0, best - 1) / static_cast<long double>(kSamples);
    long double hi = std::min(kSamples, best + 1) / static_cast<long double>(kSamples);
    for (int k = 0; k < 200; ++k) {
        const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (speed(m1) < speed(m2) ? hi : lo) = speed(m1) < speed(m2) ? m2 : m1;
    }
    const long double tm = (lo + hi) / 2;
    static constexpr long double x[5] = {
        0.0L, 0.538469310105683091036314420700208805L, -0.538469310105683091036314420700208805L,
        0.906179845938663992797626878299392965L, -0.906179845938663992797626878299392965L};
    static constexpr long double w[5] = {
        0.568888888888888888888888888888888889L, 0.478628670499366468041291514835638192L,
        0.478628670499366468041291514835638192L, 0.236926885056189087514264040719917363L,
        0.236926885056189087514264040719917363L};
    auto side = [&](long double end) {
        const long double length = std::abs(end - tm), direction = end > tm ? 1 : -1;
        long double sum = 0, at = 0, h = std::min(length, 1e-16L);
        while (at < length) {
            const long double next = std::min(length, at + h), centre = (at + next) / 2, half = (next - at) / 2;
            for (int i = 0; i < 5; ++i)
                sum += half * w[i] * speed(tm + direction * (centre + half * x[i]));
            at = next;
            h = std::min(h * 1.15L, 1.0L / 2048);
        }
        return sum;
    };
    return side(0) + side(1);
}

} // namespace

class TestArcLength final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void line_data();
    void line();
    void quadraticClosedForm();
    void cubicWithinAccuracy();
    void cuspWithinAccuracy();
    void estimateHonestWhereSpeedDips();
    void parameterAtLength();
    void degenerate();
    void scaledLengths_data();
    void scaledLengths();
    void boundedWork();
    void nearestOracle_data();
    void nearestOracle();
    void nearestAgainstDenseSampling();
    void nearestCubicMatchesRoots();
    void nearestDistanceAgreesWithHypot();
    void principalSqrtMatchesStd();
};

void TestArcLength::line_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<double>("expected");
    QTest::addRow("segment") << std::vector<Point>{{0, 0}, {3, 4}} << 5.0;
    // Unevenly spaced collinear control points: still the straight segment's length.
    QTest::addRow("cubic line") << std::vector<Point>{{0, 0}, {1, 0}, {1.5, 0}, {10, 0}} << 10.0;
    QTest::addRow("elevated line") << Bezier({{1, 1}, {4, 5}}).elevated(7).controlPoints() << 5.0;
}

void TestArcLength::line()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(double, expected);
    for (double accuracy : {1e-3, 1e-9, 1e-12}) {
        const double len = kontur::geo::arcLength(Bezier(control), accuracy);
        QVERIFY2(std::abs(len - expected) <= accuracy, qPrintable(QString::number(len - expected)));
    }
}

void TestArcLength::quadraticClosedForm()
{
    std::mt19937_64 rng(21);
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const auto p = randomPoints(rng, 3);
        const Point A = p[1] - p[0], B = p[2] - 2 * p[1] + p[0];
        // The closed form loses digits when the hodograph is nearly degenerate; skip those.
        if (std::abs(A.x() * B.y() - A.y() * B.x()) < 1e-2 * A.norm() * B.norm())
            continue;
        const double exact = quadraticLength(p[0], p[1], p[2]);
        for (double accuracy : {1e-2, 1e-6, 1e-9}) {
            const double len = kontur::geo::arcLength(Bezier(p), accuracy);
            QVERIFY2(
                std::abs(len - exact) <= accuracy,
                qPrintable(QStringLiteral("%1 vs %2 at %3").arg(len, 0, 'g', 17).arg(exact, 0, 'g', 17).arg(accuracy)));
        }
        ++checked;
    }
    QVERIFY(checked > 200);
}

void TestArcLength::cubicWithinAccuracy()
{
    // Reference: Simpson with 20000 intervals between the speed's minima is far below 1e-9 here
    // (cubics whose speed stays away from zero; cusps are tested separately).
    std::mt19937_64 rng(22);
    for (int trial = 0; trial < 30; ++trial) {
        const Bezier c(randomPoints(rng, 4));
        const Bezier h = c.derivativeCurve(1);
        double minSpeed = 1e300;
        for (int k = 0; k <= 1000; ++k)
            minSpeed = std::min(minSpeed, h.eval(k / 1000.0).norm());
        if (minSpeed < 20)
            continue;
        const double reference = simpsonSpeed(c, 0, 1, 20000);
        for (double accuracy : {1e-3, 1e-7, 1e-9}) {
            const double len = kontur::geo::arcLength(c, accuracy);
            QVERIFY2(std::abs(len - reference) <= accuracy,
                     qPrintable(QString::number(len - reference) + QStringLiteral(" at ") + QString::number(accuracy)));
        }
    }
}

void TestArcLength::cuspWithinAccuracy()
{
    // (0,0),(1,1),(0,1),(1,0) has a cusp at t = 1/2 where the speed is 0: the speed is smooth on
    // each half, so Simpson per half gives the reference.
    const Bezier c({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
    QVERIFY(c.derivative(0.5).norm() < 1e-15);
    const double reference = simpsonSpeed(c, 0, 0.5, 200000) + simpsonSpeed(c, 0.5, 1, 200000);
    for (double accuracy : {1e-4, 1e-8, 1e-10}) {
        const double len = kontur::geo::arcLength(c, accuracy);
        QVERIFY2(std::abs(len - reference) <= accuracy, qPrintable(QString::number(len - reference)));
    }
    // The same cusp scaled up a thousand times.
    const Bezier big = c.transformed(Eigen::Matrix2d::Identity() * 1000, Point(5, 5));
    QVERIFY(std::abs(kontur::geo::arcLength(big, 1e-6) - 1000 * reference) <= 1e-6 + 1e-9 * 1000);
}

void TestArcLength::estimateHonestWhereSpeedDips()
{
    // The reported accuracy is an upper bound, also where the speed dips without reaching zero.
    // The first curve's speed falls to 52.7 (of up to 334) around t = 0.42, so smoothly that a single
    // Gauss–Kronrod rule over [0, 1] had |K15 − G7| below 1e-6 with an actual error of 3.4e-4.
    std::vector<Bezier> curves{Bezier({{98.923121043410646, 74.251979959948059},
                                       {83.8908287077697, 38.629384237718291},
                                       {92.715166701140035, 20.446337338253802},
                                       {8.3555107115374927, 93.403346073338284}})};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 100);
    while (curves.size() < 3000)
        curves.push_back(Bezier({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}));
    int checked = 0;
    for (const Bezier &c : curves) {
        const long double reference = referenceLength(c);
        for (double accuracy : {1e-3, 1e-6, 1e-9, 1e-12}) {
            const auto e = kontur::geo::arcLengthEstimate(c, 0.0, 1.0, accuracy);
            const double error = static_cast<double>(std::abs(e.length - reference));
            QVERIFY2(error <= e.accuracy, qPrintable(QStringLiteral("curve %1: error %2 above the reported %3")
                                                         .arg(checked / 4)
                                                         .arg(error)
                                                         .arg(e.accuracy)));
            ++checked;
        }
    }
    QCOMPARE(checked, 12000);
}

void TestArcLength::parameterAtLength()
{
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const Bezier c(randomPoints(rng, 3 + trial % 4));
        const double total = kontur::geo::arcLength(c, 1e-10);
        const double s = unit(rng) * total;
        const double t = kontur::geo::parameterAtLength(c, s, 1e-8);
        QVERIFY(t >= 0 && t <= 1);
        QVERIFY2(std::abs(kontur::geo::arcLength(c, 0, t, 1e-11) - s) <= 1e-8, qPrintable(QString::number(t)));
    }
    const Bezier c({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
    QCOMPARE(kontur::geo::parameterAtLength(c, -1, 1e-9), 0.0);
    QCOMPARE(kontur::geo::parameterAtLength(c, 1e9, 1e-9), 1.0);
    // Symmetric curve: half the length at t = 1/2.
    const double half = 0.5 * kontur::geo::arcLength(c, 1e-12);
    QVERIFY(std::abs(kontur::geo::parameterAtLength(c, half, 1e-10) - 0.5) < 1e-9);
}

void TestArcLength::degenerate()
{
    // All control points equal: length 0, never NaN; a non-positive accuracy falls back.
    const Bezier dot({{2, 2}, {2, 2}, {2, 2}, {2, 2}});
    QCOMPARE(kontur::geo::arcLength(dot, 1e-9), 0.0);
    QCOMPARE(kontur::geo::arcLength(dot, 0.0), 0.0);
    QCOMPARE(kontur::geo::parameterAtLength(dot, 1.0, 1e-9), 1.0);
    const double len = kontur::geo::arcLength(Bezier({{0, 0}, {3, 4}}), -1);
    QCOMPARE(len, 5.0);
    QCOMPARE(kontur::geo::arcLength(Bezier(), 1e-9), 0.0);
}

void TestArcLength::nearestOracle_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<Point>("query");
    QTest::addColumn<double>("t");
    QTest::addColumn<double>("distance");
    const std::vector<Point> arch{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
    // Above the apex (2, 1.5).
    QTest::addRow("apex") << arch << Point(2, 5) << 0.5 << 3.5;
    QTest::addRow("before start") << arch << Point(-3, -4) << 0.0 << 5.0;
    QTest::addRow("on the curve") << arch << Point(2, 1.5) << 0.5 << 0.0;
    QTest::addRow("segment middle") << std::vector<Point>{{0, 0}, {10, 0}} << Point(4, 3) << 0.4 << 3.0;
    // The parabola y = x² from (-1,1) to (1,1), queried from (0, 2): equidistant branches at
    // x = ±sqrt(3/2)... outside [-1, 1], so the ends (distance sqrt(2)) win over the vertex (2): t = 0 first.
    QTest::addRow("two equal ends") << std::vector<Point>{{-1, 1}, {0, -1}, {1, 1}} << Point(0, 2) << 0.0
                                    << std::sqrt(2.0);
}

void TestArcLength::nearestOracle()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(Point, query);
    QFETCH(double, t);
    QFETCH(double, distance);
    const auto n = kontur::geo::nearest(Bezier(control), query);
    QVERIFY2(std::abs(n.t - t) < 1e-9, qPrintable(QString::number(n.t, 'g', 17)));
    QVERIFY(std::abs(n.distance - distance) < 1e-12);
    QVERIFY((n.point - Bezier(control).eval(n.t)).norm() < 1e-12);
}

void TestArcLength::nearestAgainstDenseSampling()
{
    std::mt19937_64 rng(24);
    for (int trial = 0; trial < 300; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 6);
        const Bezier c(pts);
        const Point q = randomPoints(rng, 1, -150, 150)[0];
        const auto n = kontur::geo::nearest(c, q);
        QVERIFY(std::abs((c.eval(n.t) - q).norm() - n.distance) < 1e-9);
        double sampled = 1e300;
        for (int k = 0; k <= 4000; ++k)
            sampled = std::min(sampled, (c.eval(k / 4000.0) - q).norm());
        // Never worse than any sample (global), and samples get within their spacing of it.
        QVERIFY2(n.distance <= sampled + 1e-9, qPrintable(QStringLiteral("%1 > %2").arg(n.distance).arg(sampled)));
        QVERIFY(sampled - n.distance < 0.5);
    }
}

void TestArcLength::nearestCubicMatchesRoots()
{
    // The cubic path prunes by Bernstein bounds; the root finder over every rising root of
    // (B − q)·B' is the reference. Random cubics and queries at scales 1e-6 … 1e6, with queries on
    // the curve, repeated control points, collinear control points, and the centre of a circular
    // arc (D nearly constant, where the pruning cannot settle and the reference answers).
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0), around(-0.2, 1.2);
    const double k = 0.5522847498307936; // the quarter circle's handle length
    int compared = 0;
    for (double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        for (int trial = 0; trial < 4000; ++trial) {
            std::vector<Point> c(4);
            for (Point &p : c)
                p = scale * Point(unit(rng), unit(rng));
            if (trial % 7 == 0)
                c[2] = c[1];
            if (trial % 11 == 0)
                c[3] = c[0] + 2.0 * (c[1] - c[0]);
            if (trial % 13 == 0)
                c = {scale * Point(1, 0), scale * Point(1, k), scale * Point(k, 1), scale * Point(0, 1)};
            const Bezier curve(c);
            Point q = scale * Point(around(rng), around(rng));
            if (trial % 5 == 0)
                q = curve.eval(unit(rng));
            if (trial % 13 == 0)
                q = Point(0, 0);
            const auto fast = kontur::geo::nearest(curve, q);
            const auto reference = kontur::geo::detail::nearestByRoots(curve, q);
            QVERIFY2(std::abs(fast.distance - reference.distance) <= 1e-13 * scale,
                     qPrintable(QStringLiteral("scale %1 trial %2: %3 vs %4")
                                    .arg(scale)
                                    .arg(trial)
                                    .arg(fast.distance, 0, 'g', 17)
                                    .arg(reference.distance, 0, 'g', 17)));
            QVERIFY(fast.t >= 0.0 && fast.t <= 1.0);
            QVERIFY((curve.eval(fast.t) - fast.point).norm() <= 1e-13 * scale);
            ++compared;
        }
    }
    QCOMPARE(compared, 20000);
}

void TestArcLength::nearestDistanceAgreesWithHypot()
{
    // The distance a query reports is |point − q| by sqrt(dx² + dy²) where the squares are well
    // inside doubles and by hypot (the old way, the reference here) elsewhere: within two ulps of
    // hypot at every scale from 1e-300 to 1e300, and finite at the largest doubles.
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(0.0, 1.0), around(-0.5, 1.5);
    for (double scale : {1e-300, 1e-160, 1e-150, 1e-6, 1.0, 1e6, 1e150, 1e160, 1e300}) {
        for (int trial = 0; trial < 500; ++trial) {
            std::vector<Point> c(4);
            for (Point &p : c)
                p = scale * Point(unit(rng), unit(rng));
            const Point q = scale * Point(around(rng), around(rng));
            const auto n = kontur::geo::nearest(Bezier(c), q);
            const double reference = std::hypot(n.point.x() - q.x(), n.point.y() - q.y());
            QVERIFY(std::isfinite(n.distance));
            QVERIFY2(std::abs(n.distance - reference) <= 2.0 * std::numeric_limits<double>::epsilon() * reference,
                     qPrintable(QStringLiteral("scale %1: %2 vs %3")
                                    .arg(scale)
                                    .arg(n.distance, 0, 'g', 17)
                                    .arg(reference, 0, 'g', 17)));
        }
    }
    // Differences near 1e308, whose squares overflow: still the distance (from a straight cubic's
    // middle).
    const auto huge = kontur::geo::nearest(
        Bezier({Point(-9e307, 0), Point(-3e307, 0), Point(3e307, 0), Point(9e307, 0)}), Point(0, -9e307));
    QVERIFY2(std::abs(huge.distance - 9e307) <= 1e-12 * 9e307, qPrintable(QString::number(huge.distance)));
}

void TestArcLength::principalSqrtMatchesStd()
{
    // The branch points' square root against std::sqrt (the old way, the reference): within four
    // ulps and on the same branch, for random w of magnitudes 1e-150 … 1e150 in every quadrant, on
    // both sides of the cut along the negative real axis (±0 imaginary parts) and on the axes.
    std::mt19937_64 rng(2718);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-150.0, 150.0);
    using C = std::complex<double>;
    std::vector<C> ws{C(0.0, 0.0), C(4.0, 0.0),  C(-4.0, 0.0),      C(-4.0, -0.0),
                      C(0.0, 4.0), C(0.0, -4.0), C(-1e-150, 1e-300)};
    for (int i = 0; i < 20000; ++i)
        ws.emplace_back(std::pow(10.0, exponent(rng)) * C(unit(rng), unit(rng)));
    for (const C w : ws) {
        const C ours = kontur::geo::detail::principalSqrt(w), reference = std::sqrt(w);
        QVERIFY2(std::abs(ours - reference) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(reference),
                 qPrintable(QStringLiteral("sqrt(%1 %2i) = %3 %4i, %5 %6i expected")
                                .arg(w.real())
                                .arg(w.imag())
                                .arg(ours.real())
                                .arg(ours.imag())
                                .arg(reference.real())
                                .arg(reference.imag())));
        QCOMPARE(std::signbit(ours.imag()), std::signbit(reference.imag()));
    }
}

void TestArcLength::scaledLengths_data()
{
    QTest::addColumn<double>("scale");
    QTest::addColumn<bool>("raised"); // an absolute 1e-9 is below what doubles resolve at this scale
    QTest::addRow("1e7") << 1e7 << true;
    QTest::addRow("1e160") << 1e160 << true;
    QTest::addRow("1e300") << 1e300 << true;
    QTest::addRow("1e-170") << 1e-170 << false;
}

// Issue #17: an absolute 1e-9 at 1e7 used to halve 50 levels deep, 1e160 overflowed |B'|² into an
// endless refinement, 1e-170 underflowed it to a length of 0. Now the work is the same at every
// scale and the length is the scaled unit length.
void TestArcLength::scaledLengths()
{
    QFETCH(double, scale);
    QFETCH(bool, raised);
    const std::vector<Point> unit = {Point(0, 0), Point(1, 2), Point(3, -1), Point(4, 1)};
    // The unit length by composite Simpson with 20000 intervals (error ~1e-15 on this smooth speed).
    const double reference = simpsonSpeed(Bezier(unit), 0.0, 1.0, 20000);
    std::vector<Point> pts = unit;
    for (Point &p : pts)
        p *= scale;
    const Bezier curve(pts);
    kontur::geo::detail::resetSpeedEvaluations();
    const auto e = kontur::geo::arcLengthEstimate(curve, 0.0, 1.0, 1e-9);
    const auto evaluations = kontur::geo::detail::speedEvaluations();
    QVERIFY2(evaluations <= 15u * 64u, qPrintable(QString::number(evaluations)));
    QVERIFY(std::isfinite(e.length));
    if (raised) {
        const double floor = kontur::geo::resolvableAccuracy(curve);
        QVERIFY(floor > 1e-9);
        QCOMPARE(e.accuracy, floor);
        QVERIFY2(std::abs(e.length - scale * reference) <= 1e-12 * scale * reference,
                 qPrintable(QString::number(e.length / (scale * reference) - 1.0)));
    } else {
        // 1e-9 is far above this curve's size: honoured as asked, and a tighter request that falls
        // below the floor is raised and then matches the unit length.
        QCOMPARE(e.accuracy, 1e-9);
        QVERIFY(std::abs(e.length - scale * reference) <= 1e-9);
        const auto tight = kontur::geo::arcLengthEstimate(curve, 0.0, 1.0, 1e-300);
        QCOMPARE(tight.accuracy, kontur::geo::resolvableAccuracy(curve));
        QVERIFY(tight.accuracy > 1e-300);
        QVERIFY2(std::abs(tight.length - scale * reference) <= 1e-12 * scale * reference,
                 qPrintable(QString::number(tight.length / (scale * reference) - 1.0)));
    }
    QCOMPARE(kontur::geo::arcLength(curve, 1e-9), e.length);
    const double half = kontur::geo::parameterAtLength(curve, 0.5 * e.length, 1e-9);
    QVERIFY(half > 0.0 && half < 1.0);
}

// The evaluation budget caps the work even for a request nothing can meet, and the estimate
// reports what it reached.
void TestArcLength::boundedWork()
{
    // A curve far from the origin (its floor is large) with a tiny size: every tolerance is too tight.
    const Bezier loop({Point(0, 0), Point(2, 1), Point(-1, 1), Point(1, 0)});
    const double floor = kontur::geo::resolvableAccuracy(loop);
    QVERIFY(floor > 0.0 && floor < 1e-13);
    kontur::geo::detail::resetSpeedEvaluations();
    const auto e = kontur::geo::arcLengthEstimate(loop, 0.0, 1.0, 0.0 /* default: 1e-9 × polygon */);
    QVERIFY(e.accuracy > 0.0);
    QVERIFY(kontur::geo::detail::speedEvaluations() <= 15u * kontur::geo::kArcLengthBudget);
    kontur::geo::detail::resetSpeedEvaluations();
    const auto tight = kontur::geo::arcLengthEstimate(loop, 0.0, 1.0, 1e-300);
    QVERIFY(kontur::geo::detail::speedEvaluations() <= 15u * kontur::geo::kArcLengthBudget);
    QVERIFY(tight.accuracy >= floor);
    QVERIFY(std::abs(tight.length - e.length) <= e.accuracy + tight.accuracy);
    // Piecewise: the segments' accuracies add up.
    const kontur::geo::PiecewiseBezier two({loop, loop});
    const auto both = two.lengthEstimate(1e-300);
    QCOMPARE(both.accuracy, 2.0 * tight.accuracy);
    QCOMPARE(both.length, 2.0 * tight.length);
}

QTEST_APPLESS_MAIN(TestArcLength)
#include "tst_arclength.moc"
