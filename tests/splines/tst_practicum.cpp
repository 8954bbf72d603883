// Seed 003's splines (docs/requirements.md 4): KG-202's non-parametric and parametric segments (end points and
// end slopes met, the Bézier form equal to the practicum's polynomial), and KG-203's debug oracle
// (T = 36.055, B = (180, 120), K = (0.832, 0.554)), which is the chord-length clamped spline.
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/practicum.h"
#include "splinetestutil.h"

#include <QtTest>

#include <cmath>

using namespace kontur::geo;
using namespace kontur::test;

class TestPracticum final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void functionSegment()
    {
        const Point p0(10, 20), p1(110, 60), g0(30, 40), g1(50, -10);
        auto s = practicumFunctionSegment(p0, p1, g0, g1);
        QVERIFY(s.ok());
        QCOMPARE(s->t, 100.0);
        QCOMPARE(s->k0, 40.0 / 30);
        QCOMPARE(s->k1, -10.0 / 50);
        QVERIFY(near(s->value(0), 20, 1e-12));
        QVERIFY(near(s->value(100), 60, 1e-12));
        const double e = 1e-5;
        QVERIFY(near((s->value(e) - s->value(0)) / e, s->k0, 1e-4));
        QVERIFY(near((s->value(100) - s->value(100 - e)) / e, s->k1, 1e-4));
        const Bezier b = s->toBezier();
        for (double f = 0; f <= 1; f += 0.05) {
            const Point q = b.eval(f);
            QVERIFY(near(q.x(), 10 + 100 * f, 1e-12));
            QVERIFY(near(q.y(), s->value(100 * f), 1e-10));
        }
        QVERIFY(!practicumFunctionSegment(p0, Point(10, 50), g0, g1).ok());
        QVERIFY(!practicumFunctionSegment(p0, p1, Point(0, 1), g1).ok());
    }

    void parametricSegment()
    {
        const Point p0(0, 0), p1(60, 80), g0(3, 4), g1(-1, 0);
        auto s = practicumParametricSegment(p0, p1, g0, g1);
        QVERIFY(s.ok());
        QCOMPARE(s->t2, 100.0);
        QVERIFY(near(s->k0, Point(0.6, 0.8), 1e-15));
        QVERIFY(near(s->value(100), p1, 1e-10));
        const Bezier b = s->toBezier();
        for (double f = 0; f <= 1; f += 0.05)
            QVERIFY(near(b.eval(f), s->value(100 * f), 1e-10));
        // Unit tangents with respect to the chord parameter at both ends.
        QVERIFY(near(b.derivative(0.0) / 100, s->k0, 1e-12));
        QVERIFY(near(b.derivative(1.0) / 100, Point(-1, 0), 1e-12));
        QCOMPARE(practicumParametricSegment(p0, p0, g0, g1).error().code, ErrorCode::CoincidentPoints);
        QCOMPARE(practicumParametricSegment(p0, p1, Point(0, 0), g1).error().code, ErrorCode::InvalidArgument);
    }

    // KG-203 §3.3: 4 collinear points with step (30, 20), guide vectors parallel to it.
    void debugOracle()
    {
        const std::vector<Point> pts{{100, 100}, {130, 120}, {160, 140}, {190, 160}};
        auto r = practicumSpline(pts, Point(30, 20), Point(60, 40));
        QVERIFY(r.ok());
        for (int j = 1; j <= 3; ++j)
            QVERIFY(near(r->T[static_cast<std::size_t>(j)], 36.055, 1e-3)); // √1300 = 36.0555…, printed truncated
        for (int i = 1; i <= 2; ++i)
            QVERIFY(near(r->B[static_cast<std::size_t>(i)], Point(180, 120), 1e-12));
        for (int i = 0; i <= 3; ++i)
            QVERIFY2(near(r->K[static_cast<std::size_t>(i)], Point(0.832, 0.554), 1e-3), // printed truncated
                     qPrintable(str(r->K[static_cast<std::size_t>(i)])));
        // Collinear points and tangents: the spline is the straight line, at unit speed.
        for (double t = 0; t <= r->spline.endParameter(); t += 1.0)
            QVERIFY(near(r->spline.eval(t), pts[0] + t * Point(30, 20).normalized(), 1e-10));
    }

    // KG-203 is the clamped spline with chord-length parameters and unit end tangents.
    void equalsClampedChord()
    {
        std::mt19937_64 rng(21);
        for (int m : {2, 3, 4, 8, 30}) {
            const auto pts = randomPoints(rng, m);
            const Point g0(1, 2), g1(-2, 1);
            auto r = practicumSpline(pts, g0, g1);
            auto c = cubicSpline(pts, EndCondition::Clamped, Parameterization::ChordLength, g0.normalized(),
                                 g1.normalized());
            QVERIFY(r.ok() && c.ok());
            for (std::size_t i = 0; i < pts.size(); ++i)
                QVERIFY(near(r->K[i], c->tangents()[i], 1e-10));
            QCOMPARE(r->spline.toPiecewise().segmentCount(), m - 1);
        }
    }

    void badInput()
    {
        const std::vector<Point> pts{{0, 0}, {1, 1}, {1, 1}};
        QCOMPARE(practicumSpline(pts, Point(1, 0), Point(1, 0)).error().code, ErrorCode::CoincidentPoints);
        QCOMPARE(practicumSpline(std::vector<Point>{{0, 0}}, Point(1, 0), Point(1, 0)).error().code,
                 ErrorCode::TooFewPoints);
        QCOMPARE(practicumSpline(std::vector<Point>{{0, 0}, {1, 0}}, Point(0, 0), Point(1, 0)).error().code,
                 ErrorCode::InvalidArgument);
    }
};

QTEST_GUILESS_MAIN(TestPracticum)
#include "tst_practicum.moc"
