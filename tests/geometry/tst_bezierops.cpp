// Operations on Bézier curves of any degree: derivatives, de Casteljau levels, sub-curves, degree
// elevation (docs/requirements.md 3 oracle) and reduction, quadratic → cubic, reversal, affine maps, tight
// bounds, curvature and inflections; oracles by hand plus properties over random curves.
#include "geometry/bernstein.h"
#include "geometry/bezier.h"
#include "geometry/polyline.h"
#include "testutil.h"

#include <QtTest>

#include <cmath>

using kontur::geo::Bezier;
using kontur::geo::Point;
using namespace kontur::test;

Q_DECLARE_METATYPE(std::vector<Point>)

class TestBezierOps final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void elevationOracle_data();
    void elevationOracle();
    void elevationByRMatchesRepeatedElevation();
    void elevationAndSplitReproduceTheCurve();
    void elevatedPolygonInConvexHull();
    void reductionUndoesElevation();
    void partitionOfUnity();
    void derivativesMatchFiniteDifferences();
    void endTangents();
    void deCasteljauLevels();
    void subCurve();
    void quadraticToCubic();
    void straightCubicRunsAtConstantSpeed();
    void reverseAndAffine();
    void convexHullContainsCurve();
    void boundingBox_data();
    void boundingBox();
    void boundingBoxIsTight();
    void curvature_data();
    void curvature();
    void inflections_data();
    void inflections();
    void bernsteinRootsFindAll();
    void flattenAnyDegree();
};

void TestBezierOps::elevationOracle_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<int>("r");
    QTest::addColumn<std::vector<Point>>("expected");
    // docs/requirements.md 3: (0,0),(1,2),(3,2),(4,0) → (0,0),(0.75,1.5),(2,2),(3.25,1.5),(4,0).
    QTest::addRow("seed 002 oracle") << std::vector<Point>{{0, 0}, {1, 2}, {3, 2}, {4, 0}} << 1
                                     << std::vector<Point>{{0, 0}, {0.75, 1.5}, {2, 2}, {3.25, 1.5}, {4, 0}};
    // A line elevated: evenly spaced points along it.
    QTest::addRow("line by 3") << std::vector<Point>{{0, 0}, {4, 8}} << 3
                               << std::vector<Point>{{0, 0}, {1, 2}, {2, 4}, {3, 6}, {4, 8}};
    // Quadratic (0,0),(1,1),(2,0) once: b1 = 1/3 b0 + 2/3 b1 = (2/3, 2/3), b2 = 2/3 b1 + 1/3 b2 = (4/3, 2/3).
    QTest::addRow("quadratic") << std::vector<Point>{{0, 0}, {1, 1}, {2, 0}} << 1
                               << std::vector<Point>{{0, 0}, {2.0 / 3, 2.0 / 3}, {4.0 / 3, 2.0 / 3}, {2, 0}};
    QTest::addRow("r = 0") << std::vector<Point>{{1, 2}, {3, 4}} << 0 << std::vector<Point>{{1, 2}, {3, 4}};
}

void TestBezierOps::elevationOracle()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(int, r);
    QFETCH(std::vector<Point>, expected);
    const Bezier e = Bezier(control).elevated(r);
    QCOMPARE(e.controlPoints().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY2((e.controlPoints()[i] - expected[i]).norm() < 1e-14, qPrintable(str(e.controlPoints()[i])));
}

void TestBezierOps::elevationByRMatchesRepeatedElevation()
{
    std::mt19937_64 rng(1);
    for (int trial = 0; trial < 50; ++trial) {
        const Bezier c(randomPoints(rng, 2 + trial % 8));
        const int r = 1 + trial % 7;
        Bezier stepwise = c;
        for (int k = 0; k < r; ++k)
            stepwise = stepwise.elevated(1);
        const Bezier direct = c.elevated(r);
        QCOMPARE(direct.degree(), c.degree() + r);
        for (std::size_t i = 0; i < direct.controlPoints().size(); ++i)
            QVERIFY((direct.controlPoints()[i] - stepwise.controlPoints()[i]).norm() < 1e-12 * 100);
    }
}

void TestBezierOps::elevationAndSplitReproduceTheCurve()
{
    // Property from the issue: elevation and split reproduce the curve to 1e-12 relative.
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 10);
        const double scale = polygonScale(pts);
        const Bezier c(pts);
        const Bezier e = c.elevated(1 + trial % 5);
        const double at = 0.01 + 0.98 * unit(rng);
        const auto [left, right] = c.split(at);
        for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0;
            QVERIFY((e.eval(t) - c.eval(t)).norm() <= 1e-12 * scale);
            QVERIFY((left.eval(t) - c.eval(t * at)).norm() <= 1e-12 * scale);
            QVERIFY((right.eval(t) - c.eval(at + t * (1 - at))).norm() <= 1e-12 * scale);
        }
    }
    // Up to the seed demo's degree 100.
    const Bezier seed({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
    const Bezier e100 = seed.elevated(97);
    QCOMPARE(e100.degree(), 100);
    for (int k = 0; k <= 10; ++k)
        QVERIFY((e100.eval(k / 10.0) - seed.eval(k / 10.0)).norm() < 1e-12 * 4);
}

void TestBezierOps::elevatedPolygonInConvexHull()
{
    // Each elevated point is a convex combination of two neighbours (seed 002): check the weights.
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 50; ++trial) {
        const Bezier c(randomPoints(rng, 3 + trial % 6));
        const Bezier e = c.elevated(1);
        const int n = c.degree();
        for (int i = 1; i <= n; ++i) {
            const Point &a = c.controlPoints()[i - 1];
            const Point &b = c.controlPoints()[i];
            const Point &m = e.controlPoints()[i];
            // m lies on the segment a-b.
            const double cross = (b - a).x() * (m - a).y() - (b - a).y() * (m - a).x();
            QVERIFY(std::abs(cross) <= 1e-9 * (b - a).squaredNorm() + 1e-9);
            const double u = (m - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300);
            QVERIFY(u >= -1e-12 && u <= 1 + 1e-12);
        }
    }
}

void TestBezierOps::reductionUndoesElevation()
{
    std::mt19937_64 rng(4);
    for (int trial = 0; trial < 50; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 8);
        const Bezier c(pts);
        const Bezier back = c.elevated(1).reduced();
        QCOMPARE(back.degree(), c.degree());
        for (std::size_t i = 0; i < pts.size(); ++i)
            QVERIFY((back.controlPoints()[i] - pts[i]).norm() < 1e-10 * polygonScale(pts));
    }
    // A genuine reduction stays close to a curve that is nearly of lower degree.
    const Bezier almost = Bezier({{0, 0}, {1, 2}, {3, 2}, {4, 0}}).elevated(1);
    std::vector<Point> bumped = almost.controlPoints();
    bumped[2] += Point(0.01, 0.0);
    const Bezier reduced = Bezier(bumped).reduced();
    QCOMPARE(reduced.degree(), 3);
    for (int k = 0; k <= 10; ++k)
        QVERIFY((reduced.eval(k / 10.0) - Bezier(bumped).eval(k / 10.0)).norm() < 0.01);
}

void TestBezierOps::partitionOfUnity()
{
    // The Bernstein weights sum to one and are non-negative: B(t) for all-equal points is that point,
    // and each weight (the curve of the unit vector e_i) lies in [0, 1].
    for (int n = 1; n <= 25; ++n) {
        for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0;
            double sum = 0.0;
            for (int i = 0; i <= n; ++i) {
                std::vector<double> e(static_cast<std::size_t>(n + 1), 0.0);
                e[i] = 1.0;
                const double w = kontur::geo::bernsteinEval(e, t);
                QVERIFY(w >= -1e-15 && w <= 1.0 + 1e-15);
                sum += w;
            }
            QVERIFY(std::abs(sum - 1.0) < 1e-13);
        }
    }
}

void TestBezierOps::derivativesMatchFiniteDifferences()
{
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 40; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 7, -1, 1);
        const Bezier c(pts);
        for (double t : {0.1, 0.37, 0.5, 0.9}) {
            const double h = 1e-5;
            const Point fd1 = (c.eval(t + h) - c.eval(t - h)) / (2 * h);
            QVERIFY2((c.derivative(t, 1) - fd1).norm() < 1e-6 * c.degree() * c.degree(), qPrintable(str(fd1)));
            const Point fd2 = (c.derivative(t + h, 1) - c.derivative(t - h, 1)) / (2 * h);
            QVERIFY((c.derivative(t, 2) - fd2).norm() < 1e-5 * std::pow(c.degree(), 3));
        }
        QCOMPARE(c.derivative(0.3, c.degree() + 1), Point(0, 0));
        QCOMPARE(c.derivative(0.3, 0), c.eval(0.3));
    }
}

void TestBezierOps::endTangents()
{
    // Seed 004: B'(0) = n (P1 - P0), B'(1) = n (Pn - Pn-1).
    const Bezier c({{0, 0}, {1, 3}, {4, 3}, {6, 1}, {7, 0}});
    QVERIFY((c.derivative(0.0) - 4.0 * Point(1, 3)).norm() < 1e-13);
    QVERIFY((c.derivative(1.0) - 4.0 * Point(1, -1)).norm() < 1e-13);
    // The cubic's power-basis coefficients (seed 004): c = 3(P1-P0), b = 3(P2-P1) - c, a = P3-P0-b-c.
    const Point p0(0, 0), p1(1, 2), p2(3, 2), p3(4, 0);
    const Point cc = 3 * (p1 - p0), bb = 3 * (p2 - p1) - cc, aa = p3 - p0 - bb - cc;
    const Bezier cubic({p0, p1, p2, p3});
    for (double t : {0.0, 0.2, 0.5, 0.8, 1.0})
        QVERIFY((cubic.eval(t) - (((aa * t + bb) * t + cc) * t + p0)).norm() < 1e-13);
}

void TestBezierOps::deCasteljauLevels()
{
    const Bezier c({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
    const auto levels = c.deCasteljau(0.5);
    QCOMPARE(levels.size(), std::size_t(4));
    QCOMPARE(levels[0], c.controlPoints());
    // Level 1 at t = 1/2: midpoints of the polygon's edges.
    QCOMPARE(levels[1][0], Point(0.5, 1));
    QCOMPARE(levels[1][1], Point(2, 2));
    QCOMPARE(levels[1][2], Point(3.5, 1));
    QCOMPARE(levels[2][0], Point(1.25, 1.5));
    QCOMPARE(levels[3].size(), std::size_t(1));
    QCOMPARE(levels[3][0], c.eval(0.5));
}

void TestBezierOps::subCurve()
{
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 6);
        const Bezier c(pts);
        const double t0 = unit(rng), t1 = unit(rng);
        const Bezier sub = c.subCurve(t0, t1);
        for (int k = 0; k <= 10; ++k) {
            const double u = k / 10.0;
            QVERIFY((sub.eval(u) - c.eval(t0 + u * (t1 - t0))).norm() < 1e-11 * polygonScale(pts));
        }
    }
    const Bezier c({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
    const Bezier point = c.subCurve(0.0, 0.0);
    QCOMPARE(point.eval(0.7), Point(0, 0));
}

void TestBezierOps::quadraticToCubic()
{
    const Point p0(0, 0), p1(3, 6), p2(6, 0);
    const Bezier q({p0, p1, p2});
    const Bezier c = kontur::geo::quadraticToCubic(p0, p1, p2);
    QCOMPARE(c.controlPoints()[1], Point(2, 4));
    QCOMPARE(c.controlPoints()[2], Point(4, 4));
    for (int k = 0; k <= 10; ++k)
        QVERIFY((c.eval(k / 10.0) - q.eval(k / 10.0)).norm() < 1e-14 * 6);
    // It is degree elevation by one.
    const Bezier e = q.elevated(1);
    for (int i = 0; i < 4; ++i)
        QVERIFY((e.controlPoints()[i] - c.controlPoints()[i]).norm() < 1e-14 * 6);
}

// The line from a to b as a cubic: B(t) = a + t (b - a) at every t (the handles at thirds make the
// cubic's polynomial linear), its derivative b - a throughout; over scales 1e-6 to 1e6.
void TestBezierOps::straightCubicRunsAtConstantSpeed()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const double scale = std::pow(10.0, -6 + trial % 13);
        const Point a(scale * u(rng), scale * u(rng)), b(scale * u(rng), scale * u(rng));
        const Bezier c = kontur::geo::straightCubic(a, b);
        QCOMPARE(c.degree(), 3);
        QCOMPARE(c.controlPoints().front(), a);
        QCOMPARE(c.controlPoints().back(), b);
        for (int k = 0; k <= 16; ++k) {
            const double t = k / 16.0;
            QVERIFY((c.eval(t) - (a + t * (b - a))).norm() <= 1e-14 * scale);
            QVERIFY((c.derivative(t) - (b - a)).norm() <= 1e-13 * scale);
        }
    }
}

void TestBezierOps::reverseAndAffine()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int trial = 0; trial < 100; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 8);
        const Bezier c(pts);
        const Bezier r = c.reversed();
        Eigen::Matrix2d a;
        a << u(rng), u(rng), u(rng), u(rng);
        const Point b(u(rng) * 10, u(rng) * 10);
        const Bezier m = c.transformed(a, b);
        const double scale = polygonScale(pts) * 10;
        for (int k = 0; k <= 10; ++k) {
            const double t = k / 10.0;
            QVERIFY((r.eval(t) - c.eval(1 - t)).norm() < 1e-12 * scale);
            // Affine invariance: mapping the control points maps the curve.
            QVERIFY((m.eval(t) - (a * c.eval(t) + b)).norm() < 1e-12 * scale);
        }
        Eigen::Affine2d map = Eigen::Affine2d::Identity();
        map.rotate(0.3).translate(Point(1, 2));
        const Bezier m2 = c.transformed(map);
        QVERIFY((m2.eval(0.4) - map * c.eval(0.4)).norm() < 1e-12 * scale);
    }
}

void TestBezierOps::convexHullContainsCurve()
{
    // For a convex polygon hull test use the half-planes of each hull edge (Andrew's monotone chain).
    std::mt19937_64 rng(8);
    for (int trial = 0; trial < 100; ++trial) {
        auto pts = randomPoints(rng, 3 + trial % 6);
        const Bezier c(pts);
        std::sort(pts.begin(), pts.end(),
                  [](const Point &a, const Point &b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
        auto cross = [](const Point &o, const Point &a, const Point &b) {
            return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
        };
        std::vector<Point> hull(2 * pts.size());
        std::size_t k = 0;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
                --k;
            hull[k++] = pts[i];
        }
        for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
            while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
                --k;
            hull[k++] = pts[i];
        }
        hull.resize(k - 1);
        for (int s = 0; s <= 50; ++s) {
            const Point p = c.eval(s / 50.0);
            for (std::size_t e = 0; e < hull.size(); ++e)
                QVERIFY(cross(hull[e], hull[(e + 1) % hull.size()], p) >= -1e-9);
        }
    }
}

void TestBezierOps::boundingBox_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<Point>("min");
    QTest::addColumn<Point>("max");
    // Symmetric arch: y peaks at t = 1/2 with y = 3/4 · 2 = 1.5; x spans the end points.
    QTest::addRow("arch") << std::vector<Point>{{0, 0}, {1, 2}, {3, 2}, {4, 0}} << Point(0, 0) << Point(4, 1.5);
    // Parabola y = x² from (-1,1) through (0,-1) to (1,1): minimum y = 0 at t = 1/2.
    QTest::addRow("parabola") << std::vector<Point>{{-1, 1}, {0, -1}, {1, 1}} << Point(-1, 0) << Point(1, 1);
    QTest::addRow("line") << std::vector<Point>{{2, 3}, {-1, 5}} << Point(-1, 3) << Point(2, 5);
}

void TestBezierOps::boundingBox()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(Point, min);
    QFETCH(Point, max);
    const auto box = Bezier(control).boundingBox();
    QVERIFY2((box.min() - min).norm() < 1e-14 && (box.max() - max).norm() < 1e-14,
             qPrintable(str(box.min()) + str(box.max())));
}

void TestBezierOps::boundingBoxIsTight()
{
    std::mt19937_64 rng(9);
    for (int trial = 0; trial < 200; ++trial) {
        const auto pts = randomPoints(rng, 2 + trial % 8);
        const Bezier c(pts);
        const auto box = c.boundingBox();
        kontur::geo::Box sampled;
        for (int k = 0; k <= 2000; ++k)
            sampled.extend(c.eval(k / 2000.0));
        // Contains every sample, and exceeds the samples by no more than the sampling gap.
        QVERIFY(box.contains(sampled));
        QVERIFY((box.min() - sampled.min()).norm() < 1e-3 * polygonScale(pts));
        QVERIFY((box.max() - sampled.max()).norm() < 1e-3 * polygonScale(pts));
    }
}

void TestBezierOps::curvature_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<double>("t");
    QTest::addColumn<double>("expected");
    // y = x² at its vertex has κ = 2 (turning left).
    QTest::addRow("parabola vertex") << std::vector<Point>{{-1, 1}, {0, -1}, {1, 1}} << 0.5 << 2.0;
    // y = x² at x = 1 (t = 1): κ = 2 / (1 + 4)^{3/2}.
    QTest::addRow("parabola end") << std::vector<Point>{{-1, 1}, {0, -1}, {1, 1}} << 1.0 << 2.0 / std::pow(5.0, 1.5);
    QTest::addRow("line") << std::vector<Point>{{0, 0}, {1, 1}, {2, 2}, {3, 3}} << 0.3 << 0.0;
    // Mirror image turns right.
    QTest::addRow("mirrored") << std::vector<Point>{{-1, -1}, {0, 1}, {1, -1}} << 0.5 << -2.0;
    // A handle on its knot: zero speed at t = 0, answered as 0 rather than NaN.
    QTest::addRow("zero speed") << std::vector<Point>{{0, 0}, {0, 0}, {1, 1}, {2, 0}} << 0.0 << 0.0;
}

void TestBezierOps::curvature()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(double, t);
    QFETCH(double, expected);
    const double k = Bezier(control).curvature(t);
    QVERIFY2(std::abs(k - expected) < 1e-13, qPrintable(QString::number(k, 'g', 17)));
}

void TestBezierOps::inflections_data()
{
    QTest::addColumn<std::vector<Point>>("control");
    QTest::addColumn<QList<double>>("expected");
    // Point-symmetric S: one inflection in the middle.
    QTest::addRow("S") << std::vector<Point>{{0, 0}, {1, 1}, {2, -1}, {3, 0}} << QList<double>{0.5};
    QTest::addRow("arch") << std::vector<Point>{{0, 0}, {1, 2}, {3, 2}, {4, 0}} << QList<double>{};
    QTest::addRow("line") << std::vector<Point>{{0, 0}, {1, 1}, {2, 2}, {3, 3}} << QList<double>{};
    QTest::addRow("quadratic") << std::vector<Point>{{0, 0}, {1, 1}, {2, 0}} << QList<double>{};
}

void TestBezierOps::inflections()
{
    QFETCH(std::vector<Point>, control);
    QFETCH(QList<double>, expected);
    const auto found = Bezier(control).inflections();
    QCOMPARE(found.size(), std::size_t(expected.size()));
    for (std::size_t i = 0; i < found.size(); ++i)
        QVERIFY(std::abs(found[i] - expected[int(i)]) < 1e-12);
    // Curvature changes sign across each inflection.
    const Bezier c(control);
    for (double t : found)
        QVERIFY(c.curvature(t - 1e-4) * c.curvature(t + 1e-4) < 0);
}

void TestBezierOps::bernsteinRootsFindAll()
{
    // Polynomials with known roots in (0, 1): ∏ (t - r_k), converted to Bernstein form by
    // multiplying linear factors (t - r) = (-r)(1-t) + (1-r) t.
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    for (int trial = 0; trial < 200; ++trial) {
        const int count = 1 + trial % 9;
        std::vector<double> roots(static_cast<std::size_t>(count));
        for (auto &r : roots)
            r = unit(rng);
        std::sort(roots.begin(), roots.end());
        bool separated = true;
        for (int i = 1; i < count; ++i)
            separated = separated && roots[i] - roots[i - 1] > 1e-3;
        if (!separated)
            continue;
        std::vector<double> p{1.0};
        for (double r : roots)
            p = kontur::geo::bernsteinProduct(p, std::vector<double>{-r, 1.0 - r});
        std::vector<double> found;
        kontur::geo::bernsteinRoots(p, found);
        QCOMPARE(found.size(), roots.size());
        for (int i = 0; i < count; ++i)
            QVERIFY2(std::abs(found[i] - roots[i]) < 1e-9, qPrintable(QString::number(found[i] - roots[i])));
    }
    std::vector<double> none;
    kontur::geo::bernsteinRoots(std::vector<double>{1.0, 2.0, 0.5}, none);
    QVERIFY(none.empty());
    kontur::geo::bernsteinRoots(std::vector<double>{0.0, 0.0, 0.0}, none);
    QVERIFY(none.empty());
}

void TestBezierOps::flattenAnyDegree()
{
    // Degree > 15 takes the general path; both stay within the tolerance.
    std::mt19937_64 rng(11);
    for (int degree : {2, 5, 15, 20}) {
        const Bezier c(randomPoints(rng, degree + 1));
        std::vector<Point> poly;
        kontur::geo::flatten(c, 0.05, poly);
        QCOMPARE(poly.front(), c.controlPoints().front());
        QCOMPARE(poly.back(), c.controlPoints().back());
        for (int k = 0; k <= 500; ++k) {
            const Point p = c.eval(k / 500.0);
            const double best = (p - kontur::geo::nearestOnPolyline(poly, p, false).point).norm();
            QVERIFY(best <= 0.05 * (1 + 1e-9));
        }
    }
}

QTEST_APPLESS_MAIN(TestBezierOps)
#include "tst_bezierops.moc"
