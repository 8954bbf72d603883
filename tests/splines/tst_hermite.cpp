// Hermite splines (issue 4, seed 001 §1.3): Example 1.30, the corrected basis of docs/requirements.md 2, tangents
// met at every knot, C¹ joints, Catmull–Rom against an independent Barry–Goldman evaluation,
// cardinal and finite-difference tangents, editing, sorted evaluation, Bézier pieces, bad input.
#include "geometry/splines/hermite.h"
#include "geometry/splines/knots.h"
#include "splinetestutil.h"

#include <QtTest>

#include <cmath>

using namespace kontur::geo;
using namespace kontur::test;

Q_DECLARE_METATYPE(kontur::geo::Parameterization)
Q_DECLARE_METATYPE(kontur::geo::TangentRule)

namespace {

// docs/requirements.md 2: Hs_{a,b}(x) = (1 - 2(x-a)/(a-b)) (x-b)²/(a-b)², Hds_{a,b}(x) = (x-b)²(x-a)/(b-a)².
double hs(double a, double b, double x)
{
    return (1 - 2 * (x - a) / (a - b)) * (x - b) * (x - b) / ((a - b) * (a - b));
}
double hds(double a, double b, double x)
{
    return (x - b) * (x - b) * (x - a) / ((b - a) * (b - a));
}

// Barry–Goldman pyramid for the Catmull–Rom segment p1→p2 with knots t0..t3 (the definition the
// tangent formula must agree with).
Point barryGoldman(const Point &p0, const Point &p1, const Point &p2, const Point &p3, double t0, double t1, double t2,
                   double t3, double t)
{
    auto lerp = [](const Point &a, const Point &b, double ta, double tb, double x) {
        return Point(((tb - x) * a + (x - ta) * b) / (tb - ta));
    };
    const Point a1 = lerp(p0, p1, t0, t1, t), a2 = lerp(p1, p2, t1, t2, t), a3 = lerp(p2, p3, t2, t3, t);
    const Point b1 = lerp(a1, a2, t0, t2, t), b2 = lerp(a2, a3, t1, t3, t);
    return lerp(b1, b2, t1, t2, t);
}

} // namespace

class TestHermite final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Seed 001 Example 1.30: V = (1, 2, 3), c = (−1/10, 1, 11/10), d = (−2, 1, 0).
    void example130()
    {
        const std::vector<double> v{1, 2, 3}, c{-0.1, 1, 1.1}, d{-2, 1, 0};
        auto s = HermiteSpline::function(v, c, d);
        QVERIFY(s.ok());
        QVERIFY(near(s->functionValue(1.5), 3.0 / 40, 1e-15));
        QVERIFY(near(s->functionValue(2.5), 47.0 / 40, 1e-15));
        // The corrected basis of docs/requirements.md 2, on both segments.
        for (double x = 1; x <= 3; x += 0.125) {
            const int i = x < 2 ? 0 : 1;
            const double a = v[static_cast<std::size_t>(i)], b = v[static_cast<std::size_t>(i) + 1];
            const double want =
                c[static_cast<std::size_t>(i)] * hs(a, b, x) + c[static_cast<std::size_t>(i) + 1] * hs(b, a, x) +
                d[static_cast<std::size_t>(i)] * hds(a, b, x) + d[static_cast<std::size_t>(i) + 1] * hds(b, a, x);
            QVERIFY(near(s->functionValue(x), want, 1e-14));
        }
    }

    void tangentsMet_data()
    {
        QTest::addColumn<Parameterization>("param");
        QTest::addColumn<bool>("closed");
        for (auto p : {Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal})
            for (bool closed : {false, true})
                QTest::addRow("%s%s", nameOf(p), closed ? "/closed" : "") << p << closed;
    }

    // User tangents are met at every knot, values interpolated, joints C¹ (G1 in the Bézier report).
    void tangentsMet()
    {
        QFETCH(Parameterization, param);
        QFETCH(bool, closed);
        std::mt19937_64 rng(5);
        for (int trial = 0; trial < 20; ++trial) {
            const auto pts = randomPoints(rng, 6);
            const auto tan = randomPoints(rng, 6, -20, 20);
            auto s = hermiteSpline(pts, tan, param, closed);
            QVERIFY(s.ok());
            const auto &u = s->parameters();
            for (std::size_t i = 0; i < pts.size(); ++i) {
                QVERIFY(near(s->eval(u[i]), pts[i], 1e-12 * 100));
                if (i > 0) // the derivative from the left at knot i
                    QVERIFY(near(s->segment(static_cast<int>(i) - 1).derivative(1.0) / (u[i] - u[i - 1]), tan[i],
                                 1e-11 * 20));
                if (i + 1 < u.size()) // and from the right
                    QVERIFY(
                        near(s->segment(static_cast<int>(i)).derivative(0.0) / (u[i + 1] - u[i]), tan[i], 1e-11 * 20));
            }
            if (closed)
                QVERIFY(near(s->eval(u.back()), pts.front(), 1e-12));
            const auto pw = s->toPiecewise();
            for (const auto &j : pw.continuity(1e-9))
                QVERIFY(j.g1);
            for (double x = u.front(); x <= u.back(); x += (u.back() - u.front()) / 97)
                QVERIFY(near(evalPieces(pw, u, x), s->eval(x), 1e-12 * 100));
        }
    }

    void catmullRom_data()
    {
        QTest::addColumn<Parameterization>("param");
        for (auto p : {Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal})
            QTest::addRow("%s", nameOf(p)) << p;
    }

    // Interior segments equal the Barry–Goldman pyramid (the definition of non-uniform Catmull–Rom).
    void catmullRom()
    {
        QFETCH(Parameterization, param);
        std::mt19937_64 rng(11);
        for (int trial = 0; trial < 20; ++trial) {
            const auto pts = randomPoints(rng, 7);
            auto s = hermiteSpline(pts, param, TangentRule::CatmullRom);
            QVERIFY(s.ok());
            const auto &u = s->parameters();
            for (std::size_t i = 1; i + 2 < pts.size(); ++i)
                for (double f = 0; f <= 1.0; f += 0.1) {
                    const double t = u[i] + f * (u[i + 1] - u[i]);
                    const Point want =
                        barryGoldman(pts[i - 1], pts[i], pts[i + 1], pts[i + 2], u[i - 1], u[i], u[i + 1], u[i + 2], t);
                    QVERIFY2(near(s->eval(t), want, 1e-10), qPrintable(str(s->eval(t)) + " vs " + str(want)));
                }
            if (param == Parameterization::Uniform)
                QVERIFY(near(s->tangents()[3], (pts[4] - pts[2]) / 2, 1e-12));
        }
    }

    void otherRules()
    {
        std::mt19937_64 rng(12);
        const auto pts = randomPoints(rng, 6);
        auto cr = hermiteSpline(pts, Parameterization::Uniform, TangentRule::CatmullRom);
        auto card0 = hermiteSpline(pts, Parameterization::Uniform, TangentRule::Cardinal, 0.0);
        auto card1 = hermiteSpline(pts, Parameterization::Uniform, TangentRule::Cardinal, 1.0);
        auto cardHalf = hermiteSpline(pts, Parameterization::ChordLength, TangentRule::Cardinal, 0.5);
        auto fd = hermiteSpline(pts, Parameterization::ChordLength, TangentRule::FiniteDifference);
        QVERIFY(cr.ok() && card0.ok() && card1.ok() && cardHalf.ok() && fd.ok());
        for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
            QVERIFY(near(card0->tangents()[i], cr->tangents()[i], 1e-12)); // tension 0 = Catmull–Rom
            QVERIFY(card1->tangents()[i].norm() == 0.0);                   // tension 1: stops
            const auto &u = fd->parameters();
            const Point d0 = (pts[i] - pts[i - 1]) / (u[i] - u[i - 1]), d1 = (pts[i + 1] - pts[i]) / (u[i + 1] - u[i]);
            QVERIFY(near(fd->tangents()[i], 0.5 * (d0 + d1), 1e-12));
            const auto &uc = cardHalf->parameters();
            QVERIFY(near(cardHalf->tangents()[i], 0.5 * (pts[i + 1] - pts[i - 1]) / (uc[i + 1] - uc[i - 1]), 1e-12));
        }
        // Closed rules wrap around and stay C¹ across the seam.
        for (auto rule : {TangentRule::CatmullRom, TangentRule::Cardinal, TangentRule::FiniteDifference}) {
            auto c = hermiteSpline(pts, Parameterization::Centripetal, rule, 0.3, true);
            QVERIFY(c.ok());
            QCOMPARE(c->segmentCount(), 6);
            const auto joints = c->toPiecewise().continuity(1e-9);
            QCOMPARE(joints.size(), 6u);
            for (const auto &j : joints)
                QVERIFY(j.g1);
        }
        QCOMPARE(hermiteSpline(pts, Parameterization::Uniform, TangentRule::Cardinal, 1.5).error().code,
                 ErrorCode::InvalidArgument);
    }

    void editing()
    {
        const std::vector<Point> pts{{0, 0}, {1, 1}, {2, 0}};
        auto s = hermiteSpline(pts, Parameterization::Uniform, TangentRule::CatmullRom);
        QVERIFY(s.ok());
        QVERIFY(s->setTangent(1, Point(0, 3)).ok());
        QVERIFY(near(s->derivative(1.0), Point(0, 3), 1e-12));
        QVERIFY(s->setPoint(2, Point(5, 5)).ok());
        QVERIFY(near(s->eval(2.0), Point(5, 5), 1e-12));
        QCOMPARE(s->setTangent(3, Point(1, 0)).error().code, ErrorCode::IndexOutOfRange);
        QCOMPARE(s->setPoint(0, Point(std::nan(""), 0)).error().code, ErrorCode::NonFiniteInput);
        // Locate clamps to the range and assigns knots to the segment on their right.
        QCOMPARE(s->locate(-5).segment, 0);
        QCOMPARE(s->locate(1.0).segment, 1);
        QCOMPARE(s->locate(1.0).t, 0.0);
        QCOMPARE(s->locate(2.0).segment, 1);
        QCOMPARE(s->locate(2.0).t, 1.0);
    }

    // Sorted evaluation (chunked, lane-merged) equals eval, for long sorted input, unsorted input,
    // parameters outside the range, and closed curves.
    void evalSorted()
    {
        std::mt19937_64 rng(31);
        for (bool closed : {false, true}) {
            const auto pts = randomPoints(rng, 3000);
            auto s = hermiteSpline(pts, Parameterization::ChordLength, TangentRule::CatmullRom, 0.0, closed);
            QVERIFY(s.ok());
            std::uniform_real_distribution<double> pick(s->startParameter() - 5, s->endParameter() + 5);
            std::vector<double> u(10000);
            for (auto &x : u)
                x = pick(rng);
            std::vector<Point> out(u.size());
            for (bool sorted : {true, false}) {
                if (sorted)
                    std::sort(u.begin(), u.end());
                else
                    std::shuffle(u.begin(), u.end(), rng);
                s->evalSorted(u, out);
                for (std::size_t k = 0; k < u.size(); ++k)
                    QVERIFY2(
                        near(out[k], s->eval(u[k]), 1e-10),
                        qPrintable(QStringLiteral("u=%1: %2 vs %3").arg(u[k]).arg(str(out[k]), str(s->eval(u[k])))));
            }
        }
    }

    void badInput()
    {
        const std::vector<Point> pts{{0, 0}, {1, 1}, {2, 0}};
        const std::vector<Point> zero{{1, 0}, {0, 0}, {1, 0}};
        auto r = hermiteSpline(pts, zero, Parameterization::ChordLength);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().index, 1); // the zero-length tangent, named
        QCOMPARE(
            hermiteSpline(std::vector<Point>{{0, 0}}, Parameterization::Uniform, TangentRule::CatmullRom).error().code,
            ErrorCode::TooFewPoints);
        QCOMPARE(HermiteSpline::create({0, 1, 1}, pts, zero).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(HermiteSpline::create({0, 1}, pts, zero).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(HermiteSpline::function(std::vector<double>{0, 1}, std::vector<double>{0, std::nan("")},
                                         std::vector<double>{0, 0})
                     .error()
                     .code,
                 ErrorCode::NonFiniteInput);
        const std::vector<Point> dup{{0, 0}, {0, 0}, {1, 1}};
        QCOMPARE(hermiteSpline(dup, Parameterization::Uniform, TangentRule::CatmullRom).error().code,
                 ErrorCode::CoincidentPoints);
    }
};

QTEST_GUILESS_MAIN(TestHermite)
#include "tst_hermite.moc"
