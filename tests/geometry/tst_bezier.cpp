// Bézier evaluation against hand-computed values, and the agreement of its three forms
// (de Casteljau, Bernstein sum, the corrected matrix form of docs/requirements.md 1.2).
#include "geometry/bezier.h"

#include <QtTest>

#include <cmath>
#include <random>

using kontur::geo::Bezier;
using kontur::geo::Point;

Q_DECLARE_METATYPE(Point)

namespace {

double binomial(int n, int k)
{
    double r = 1.0;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

Point bernsteinSum(const std::vector<Point> &c, double t)
{
    const int n = static_cast<int>(c.size()) - 1;
    Point sum = Point::Zero();
    for (int i = 0; i <= n; ++i)
        sum += binomial(n, i) * std::pow(t, i) * std::pow(1.0 - t, n - i) * c[i];
    return sum;
}

} // namespace

class TestBezier final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cubicEval_data();
    void cubicEval();
    void matrixFormEqualsDeCasteljau();
    void randomDegreesMatchBernsteinSum();
    void splitReproducesTheCurve();
    void flattenStaysWithinTolerance();
};

void TestBezier::cubicEval_data()
{
    QTest::addColumn<Point>("c0");
    QTest::addColumn<Point>("c1");
    QTest::addColumn<Point>("c2");
    QTest::addColumn<Point>("c3");
    QTest::addColumn<double>("t");
    QTest::addColumn<Point>("expected");

    // Values computed by hand from B(t) = (1-t)³c0 + 3(1-t)²t c1 + 3(1-t)t² c2 + t³c3.
    const Point a(0, 0), b(1, 2), c(3, 2), d(4, 0);
    QTest::addRow("start") << a << b << c << d << 0.0 << Point(0, 0);
    QTest::addRow("end") << a << b << c << d << 1.0 << Point(4, 0);
    // t = 1/2: weights 1/8, 3/8, 3/8, 1/8 → x = (0 + 3 + 9 + 4)/8 = 2, y = (0 + 6 + 6 + 0)/8 = 1.5
    QTest::addRow("middle") << a << b << c << d << 0.5 << Point(2, 1.5);
    // t = 1/4: weights 27/64, 27/64, 9/64, 1/64 → x = (27 + 27 + 4)/64 = 58/64, y = (54 + 18)/64 = 72/64
    QTest::addRow("quarter") << a << b << c << d << 0.25 << Point(58.0 / 64, 72.0 / 64);
    // t = 3/4 mirrors t = 1/4 for this symmetric polygon: x = 4 - 58/64
    QTest::addRow("three quarters") << a << b << c << d << 0.75 << Point(4 - 58.0 / 64, 72.0 / 64);
    // A straight, evenly spaced polygon moves at constant speed: B(t) = (3t, 3t).
    QTest::addRow("line") << Point(0, 0) << Point(1, 1) << Point(2, 2) << Point(3, 3) << 0.3 << Point(0.9, 0.9);
    // t = 1/3: weights 8/27, 12/27, 6/27, 1/27 on (1,0),(0,1),(-1,0),(0,-1)
    // → x = (8 - 6)/27 = 2/27, y = (12 - 1)/27 = 11/27
    QTest::addRow("third") << Point(1, 0) << Point(0, 1) << Point(-1, 0) << Point(0, -1) << 1.0 / 3
                           << Point(2.0 / 27, 11.0 / 27);
}

void TestBezier::cubicEval()
{
    QFETCH(Point, c0);
    QFETCH(Point, c1);
    QFETCH(Point, c2);
    QFETCH(Point, c3);
    QFETCH(double, t);
    QFETCH(Point, expected);

    const Bezier curve({c0, c1, c2, c3});
    QCOMPARE(curve.degree(), 3);
    const Point p = curve.eval(t);
    QVERIFY2((p - expected).norm() < 1e-14,
             qPrintable(QStringLiteral("(%1, %2)").arg(p.x(), 0, 'g', 17).arg(p.y(), 0, 'g', 17)));
    const Point m = kontur::geo::evalCubicMatrix({c0, c1, c2, c3}, t);
    QVERIFY((m - expected).norm() < 1e-14);
}

void TestBezier::matrixFormEqualsDeCasteljau()
{
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
    std::uniform_real_distribution<double> param(0.0, 1.0);
    for (int trial = 0; trial < 1000; ++trial) {
        std::array<Point, 4> c;
        for (auto &p : c)
            p = Point(coord(rng), coord(rng));
        const Bezier curve({c.begin(), c.end()});
        const double t = param(rng);
        QVERIFY((curve.eval(t) - kontur::geo::evalCubicMatrix(c, t)).norm() < 1e-9);
    }
}

void TestBezier::randomDegreesMatchBernsteinSum()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coord(-10.0, 10.0);
    std::uniform_real_distribution<double> param(0.0, 1.0);
    for (int degree = 1; degree <= 20; ++degree) {
        std::vector<Point> c(degree + 1);
        for (auto &p : c)
            p = Point(coord(rng), coord(rng));
        const Bezier curve(c);
        for (int k = 0; k < 50; ++k) {
            const double t = param(rng);
            QVERIFY2((curve.eval(t) - bernsteinSum(c, t)).norm() < 1e-9 * (1 << std::min(degree, 10)),
                     qPrintable(QStringLiteral("degree %1 t %2").arg(degree).arg(t)));
        }
    }
}

void TestBezier::splitReproducesTheCurve()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> coord(-100.0, 100.0);
    std::uniform_real_distribution<double> param(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<Point> c(2 + trial % 6);
        for (auto &p : c)
            p = Point(coord(rng), coord(rng));
        const Bezier curve(c);
        const double at = 0.05 + 0.9 * param(rng);
        const auto [left, right] = curve.split(at);
        for (int k = 0; k <= 10; ++k) {
            const double u = k / 10.0;
            QVERIFY((left.eval(u) - curve.eval(u * at)).norm() < 1e-10);
            QVERIFY((right.eval(u) - curve.eval(at + u * (1 - at))).norm() < 1e-10);
        }
    }
}

void TestBezier::flattenStaysWithinTolerance()
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-500.0, 500.0);
    for (double tolerance : {2.0, 0.25, 0.01}) {
        for (int trial = 0; trial < 50; ++trial) {
            std::vector<Point> c(4);
            for (auto &p : c)
                p = Point(coord(rng), coord(rng));
            const Bezier curve(c);
            std::vector<Point> poly;
            kontur::geo::flatten(curve, tolerance, poly);
            QVERIFY(poly.size() >= 2);
            QCOMPARE(poly.front(), c.front());
            QCOMPARE(poly.back(), c.back());
            // Every sampled curve point must be within tolerance of the polyline.
            for (int k = 0; k <= 400; ++k) {
                const Point p = curve.eval(k / 400.0);
                double best = std::numeric_limits<double>::infinity();
                for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
                    const Point ab = poly[i + 1] - poly[i];
                    const double len2 = ab.squaredNorm();
                    const double u = len2 > 0 ? std::clamp((p - poly[i]).dot(ab) / len2, 0.0, 1.0) : 0.0;
                    best = std::min(best, (p - (poly[i] + u * ab)).norm());
                }
                QVERIFY2(best <= tolerance * (1 + 1e-9), qPrintable(QString::number(best)));
            }
        }
    }
}

QTEST_APPLESS_MAIN(TestBezier)
#include "tst_bezier.moc"
