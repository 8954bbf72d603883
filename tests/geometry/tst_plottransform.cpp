// The world ↔ plot transform of seed 001 §3.2.1 against docs/requirements.md 2's example, and its inverse.
#include "geometry/plottransform.h"

#include <QtTest>

using kontur::geo::Box;
using kontur::geo::PlotTransform;
using kontur::geo::Point;

Q_DECLARE_METATYPE(Point)

class TestPlotTransform final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void oracle_data();
    void oracle();
    void roundTrip();
    void degenerateWorldIsHarmless();
};

void TestPlotTransform::oracle_data()
{
    QTest::addColumn<Point>("world");
    QTest::addColumn<Point>("plot");
    QTest::addColumn<double>("tolerance");
    // Plot 640×360, world [−15, 15]×[−10, 10] (docs/requirements.md 2): x: (7.97 + 15)/30·640 = 490.0267, which the
    // seed prints rounded to 490.03; y: (10 − 5)/20·360 = 90.
    QTest::addRow("spec example, as printed") << Point(7.97, 5) << Point(490.03, 90) << 0.005;
    QTest::addRow("spec example, exact") << Point(7.97, 5) << Point(22.97 * 64 / 3, 90) << 1e-12;
    QTest::addRow("world origin at the plot centre") << Point(0, 0) << Point(320, 180) << 1e-12;
    QTest::addRow("top left") << Point(-15, 10) << Point(0, 0) << 1e-12;
    QTest::addRow("bottom right") << Point(15, -10) << Point(640, 360) << 1e-12;
}

void TestPlotTransform::oracle()
{
    QFETCH(Point, world);
    QFETCH(Point, plot);
    QFETCH(double, tolerance);
    const PlotTransform transform(Box(Point(-15, -10), Point(15, 10)), 640, 360);
    QVERIFY((transform.toPlot(world) - plot).norm() < tolerance);
    QVERIFY((transform.toWorld(plot) - world).norm() < tolerance);
}

void TestPlotTransform::roundTrip()
{
    const PlotTransform transform(Box(Point(-3.5, 2), Point(100, 2.25)), 1920, 1080);
    for (int i = 0; i < 100; ++i) {
        const Point w(-3.5 + i * 1.03, 2 + i * 0.0025);
        QVERIFY((transform.toWorld(transform.toPlot(w)) - w).norm() < 1e-12);
    }
}

void TestPlotTransform::degenerateWorldIsHarmless()
{
    const PlotTransform flat(Box(Point(0, 1), Point(5, 1)), 640, 360);
    const Point p = flat.toPlot(Point(2, 3));
    QVERIFY(p.allFinite());
    const PlotTransform empty(Box(Point(0, 0), Point(1, 1)), 0, 360);
    QVERIFY(empty.toWorld(Point(10, 10)).allFinite());
}

QTEST_APPLESS_MAIN(TestPlotTransform)
#include "tst_plottransform.moc"
