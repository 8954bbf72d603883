// B-splines (issue 4; seed 003 KG-205, seed 001 §1.1): the open uniform knot vectors of the
// practicum, partition of unity and non-negativity with half-open intervals, de Boor against the
// basis sum, k = 2 is the polygon and k = n the Bézier curve, knot insertion, Bézier pieces,
// derivatives, seed 001's bells (Example 1.15), bad knot vectors.
#include "geometry/splines/bspline.h"
#include "splinetestutil.h"

#include <QtTest>

#include <cmath>
#include <numeric>

using namespace kontur::geo;
using namespace kontur::test;

namespace {

std::vector<double> randomKnots(std::mt19937_64 &rng, int n, int k, bool withRepeats)
{
    std::vector<double> t = randomIncreasing(rng, n + k, 0.0, 0.1, 2.0);
    if (withRepeats) {
        // A few repeated interior knots (multiplicity up to k - 1), and clamped ends.
        std::uniform_int_distribution<int> pick(k, n - 1);
        for (int r = 0; r < 2; ++r) {
            const int i = pick(rng);
            for (int m = 1; m < k - 1 && i + m < n; ++m)
                t[static_cast<std::size_t>(i + m)] = t[static_cast<std::size_t>(i)];
        }
        std::sort(t.begin(), t.end());
        for (int i = 0; i < k; ++i) {
            t[static_cast<std::size_t>(i)] = t[static_cast<std::size_t>(k - 1)];
            t[t.size() - 1 - static_cast<std::size_t>(i)] = t[t.size() - static_cast<std::size_t>(k)];
        }
    }
    return t;
}

// Every order 2..10, with simple knots and with repeated ones (columns "order", "repeats").
void addOrderRows()
{
    QTest::addColumn<int>("order");
    QTest::addColumn<bool>("repeats");
    for (int k = 2; k <= 10; ++k) {
        QTest::addRow("k=%d", k) << k << false;
        QTest::addRow("k=%d, repeated knots", k) << k << true;
    }
}

} // namespace

class TestBSpline final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Seed 003 KG-205, m = 8 points: 0012345677, …, 0000000011111111.
    void openUniformKnots_data()
    {
        QTest::addColumn<int>("order");
        QTest::addColumn<QString>("knots");
        QTest::addRow("k=2") << 2 << "0012345677";
        QTest::addRow("k=3") << 3 << "00012345666";
        QTest::addRow("k=4") << 4 << "000012345555";
        QTest::addRow("k=5") << 5 << "0000012344444";
        QTest::addRow("k=6") << 6 << "00000012333333";
        QTest::addRow("k=7") << 7 << "000000012222222";
        QTest::addRow("k=8") << 8 << "0000000011111111";
    }

    void openUniformKnots()
    {
        QFETCH(int, order);
        QFETCH(QString, knots);
        auto t = kontur::geo::openUniformKnots(8, order);
        QVERIFY(t.ok());
        QString s;
        for (double v : *t)
            s += QString::number(v);
        QCOMPARE(s, knots);
    }

    void partitionOfUnity_data() { addOrderRows(); }

    // Σ N_{i,k}(t) = 1 and N_{i,k}(t) >= 0 over the domain, including every knot (half-open base
    // intervals: no double counting) and the domain end; de Boor equals the basis sum.
    void partitionOfUnity()
    {
        QFETCH(int, order);
        QFETCH(bool, repeats);
        std::mt19937_64 rng(static_cast<unsigned>(order * 10 + repeats));
        const int n = order + 6;
        const auto t = randomKnots(rng, n, order, repeats);
        const auto pts = randomPoints(rng, n);
        auto b = BSpline::create(order, t, pts);
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message.c_str());
        std::vector<double> samples;
        for (int i = order - 1; i <= n; ++i)
            samples.push_back(t[static_cast<std::size_t>(i)]); // every knot of the domain
        for (int s = 0; s <= 200; ++s)
            samples.push_back(b->startParameter() + (b->endParameter() - b->startParameter()) * s / 200.0);
        for (double x : samples) {
            const auto nb = b->basisValues(x);
            double sum = 0.0;
            Point viaBasis = Point::Zero();
            for (std::size_t i = 0; i < nb.size(); ++i) {
                QVERIFY(nb[i] >= 0.0);
                sum += nb[i];
                viaBasis += nb[i] * pts[i];
            }
            QVERIFY2(near(sum, 1.0, 1e-12), qPrintable(QStringLiteral("t=%1: sum %2").arg(x).arg(sum, 0, 'g', 17)));
            QVERIFY(near(b->eval(x), viaBasis, 1e-10));
        }
    }

    // k = 2: the control polygon; k = number of points (open uniform): the Bézier curve.
    void specialOrders()
    {
        std::mt19937_64 rng(3);
        const auto pts = randomPoints(rng, 8);
        auto poly = BSpline::create(2, KnotKind::OpenUniform, pts);
        QVERIFY(poly.ok());
        for (int i = 0; i < 8; ++i)
            QVERIFY(near(poly->eval(i), pts[static_cast<std::size_t>(i)], 1e-12));
        QVERIFY(near(poly->eval(2.25), 0.75 * pts[2] + 0.25 * pts[3], 1e-12));
        for (int m = 2; m <= 10; ++m) {
            const auto p = randomPoints(rng, m);
            auto bez = BSpline::create(m, KnotKind::OpenUniform, p);
            QVERIFY(bez.ok());
            const Bezier ref(p);
            for (double x = 0; x <= 1.0; x += 0.05)
                QVERIFY(near(bez->eval(x), ref.eval(x), 1e-11));
            QCOMPARE(bez->toPiecewise().segmentCount(), 1);
        }
    }

    // Knot insertion keeps the curve; Bézier pieces evaluate like de Boor; derivatives agree with the
    // pieces' derivatives.
    void insertionAndPieces_data() { addOrderRows(); }

    void insertionAndPieces()
    {
        QFETCH(int, order);
        QFETCH(bool, repeats);
        std::mt19937_64 rng(static_cast<unsigned>(100 + order * 10 + repeats));
        const int n = order + 5;
        auto b = BSpline::create(order, randomKnots(rng, n, order, repeats), randomPoints(rng, n));
        QVERIFY(b.ok());
        const double lo = b->startParameter(), hi = b->endParameter();
        std::uniform_real_distribution<double> pick(lo, hi);
        const double at = pick(rng);
        auto ins = b->withKnotInserted(at, std::max(1, order - 2));
        QVERIFY2(ins.ok(), ins.ok() ? "" : ins.error().message.c_str());
        QCOMPARE(ins->controlPointCount(), n + std::max(1, order - 2));
        std::vector<double> bounds;
        const auto pieces = b->bezierPieces(&bounds);
        QCOMPARE(pieces.size() + 1, bounds.size());
        const PiecewiseBezier pw(pieces);
        for (int s = 0; s <= 300; ++s) {
            const double x = lo + (hi - lo) * s / 300.0;
            const Point c = b->eval(x);
            QVERIFY(near(ins->eval(x), c, 1e-10));
            QVERIFY(near(evalPieces(pw, bounds, x), c, 1e-10));
            if (order >= 3 && s % 10 == 5) {
                // The derivative against its Bézier piece's (chain rule with the span length).
                const auto it = std::upper_bound(bounds.begin(), bounds.end(), x);
                const auto k =
                    static_cast<std::size_t>(std::clamp<long>(it - bounds.begin() - 1, 0, long(pieces.size()) - 1));
                const double h = bounds[k + 1] - bounds[k];
                const Point want = pieces[k].derivative((x - bounds[k]) / h) / h;
                QVERIFY2(near(b->derivative(x), want, 1e-8 * (1 + want.norm())),
                         qPrintable(str(b->derivative(x)) + " vs " + str(want)));
                auto dc = b->derivativeCurve();
                QVERIFY(dc.ok());
                QVERIFY(near(dc->eval(x), want, 1e-8 * (1 + want.norm())));
            }
        }
        // Too many insertions, or outside the domain.
        QVERIFY(!b->withKnotInserted(at, order).ok());
        QVERIFY(!b->withKnotInserted(hi + 1).ok());
    }

    void badKnots_data()
    {
        QTest::addColumn<int>("order");
        QTest::addColumn<std::vector<double>>("knots");
        QTest::addColumn<int>("points");
        QTest::addRow("order 1") << 1 << std::vector<double>{0, 1, 2, 3} << 3;
        QTest::addRow("order 11") << 11 << std::vector<double>(23, 0.0) << 12;
        QTest::addRow("wrong length") << 3 << std::vector<double>{0, 0, 0, 1, 1, 1} << 4;
        QTest::addRow("decreasing") << 3 << std::vector<double>{0, 0, 0, 2, 1, 3, 3} << 4;
        QTest::addRow("repeated too often") << 2 << std::vector<double>{0, 1, 1, 1, 2, 3} << 4;
        QTest::addRow("empty domain") << 2 << std::vector<double>{0, 0, 0, 0, 1} << 3;
        QTest::addRow("nan") << 2 << std::vector<double>{0, 1, std::nan(""), 3, 4} << 3;
        QTest::addRow("too few points") << 4 << std::vector<double>{0, 1, 2, 3, 4, 5} << 2;
    }

    void badKnots()
    {
        QFETCH(int, order);
        QFETCH(std::vector<double>, knots);
        QFETCH(int, points);
        std::mt19937_64 rng(1);
        auto b = BSpline::create(order, knots, randomPoints(rng, points));
        QVERIFY(!b.ok());
        QVERIFY(!b.error().message.empty());
    }

    // Seed 001 Example 1.15: knots 0..9, c = (−1/3, 1/5, 1/4, −1/4, 1/3, −3/4), cubic bells.
    void example115()
    {
        std::vector<double> v(10);
        std::iota(v.begin(), v.end(), 0.0);
        const std::vector<double> c{-1.0 / 3, 1.0 / 5, 1.0 / 4, -1.0 / 4, 1.0 / 3, -3.0 / 4};
        QCOMPARE(bellScale(v, 0, 3), 6.0);
        auto s = bellSpline(v, c, 3);
        QVERIFY(s.ok());
        QCOMPARE(s->startParameter(), 3.0);
        QCOMPARE(s->endParameter(), 6.0);
        const double want[] = {43.0 / 60, 19.0 / 20, -5.0 / 12, 1.0 / 3};
        for (int i = 0; i < 4; ++i) {
            const Point p = s->eval(3.0 + i);
            QVERIFY(near(p.x(), 3.0 + i, 1e-14)); // x(t) = t
            QVERIFY2(near(p.y(), want[i], 1e-14), qPrintable(QString::number(p.y(), 'g', 17)));
            // P(v_{i+3}) = c_i + 4 c_{i+1} + c_{i+2}.
            const auto k = static_cast<std::size_t>(i);
            QVERIFY(near(p.y(), c[k] + 4 * c[k + 1] + c[k + 2], 1e-14));
        }
        // The same from the seed's sum of bells, segment by segment (formula 1.3 with docs/requirements.md's reading):
        // P_s(x) = Σ_j c_{s-1+j} Bs^{3,j+1}_{v_{s-1+j}..}(x) on [v_{s+2}, v_{s+3}].
        for (int seg = 1; seg <= 3; ++seg)
            for (double x = seg + 2.0; x <= seg + 3.0; x += 0.125) {
                double sum = 0.0;
                for (int j = 0; j <= 3; ++j) {
                    auto bs = bell(v, seg - 1 + j, 3, j + 1, x);
                    QVERIFY(bs.ok());
                    sum += c[static_cast<std::size_t>(seg - 1 + j)] * *bs;
                }
                QVERIFY(near(s->eval(x).y(), sum, 1e-13));
            }
        // Bells are B-spline pieces: on a non-uniform knot vector too, they sum (unscaled) to one.
        std::mt19937_64 rng(4);
        const auto w = randomIncreasing(rng, 12);
        for (double x = w[3]; x < w[4]; x += 0.01) {
            double sum = 0;
            for (int j = 0; j <= 3; ++j)
                sum += *bell(w, j, 3, j + 1, x) / bellScale(w, j, 3);
            QVERIFY(near(sum, 1.0, 1e-12));
        }
        QVERIFY(!bell(v, 0, 3, 5, 3.0).ok());
        QVERIFY(!bellSpline(v, std::vector<double>{1, 2}, 3).ok());
    }

    void basisFunctionEdges()
    {
        const std::vector<double> t{0, 0, 0, 1, 2, 2, 2};
        // Open knots, order 3, 4 functions; at t = 2 the last function is 1 (the closed last interval).
        QCOMPARE(basisFunction(t, 3, 3, 2.0), 1.0);
        QCOMPARE(basisFunction(t, 0, 3, 0.0), 1.0);
        QCOMPARE(basisFunction(t, 0, 3, -1.0), 0.0);
        QCOMPARE(basisFunction(t, 7, 3, 1.0), 0.0);
        // At the interior knot 1: N_{1,3} = N_{2,3} = 1/2 (no double count).
        QCOMPARE(basisFunction(t, 1, 3, 1.0), 0.5);
        QCOMPARE(basisFunction(t, 2, 3, 1.0), 0.5);
    }
};

QTEST_GUILESS_MAIN(TestBSpline)
#include "tst_bspline.moc"
