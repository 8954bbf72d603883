// Seed 001's interpolating splines (docs/requirements.md 2): the global B-spline (Examples 1.20 and 1.23, the
// O(k) solve against the seed's full system), the clamped spline on uniform knots with the
// corrected h, Török's half-size procedure with the corrected boundary terms (equal to the classical
// system for k = 2…60), and the equalities clamped = global B-spline = general clamped spline.
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/globalbspline.h"
#include "geometry/splines/torok.h"
#include "splinetestutil.h"

#include <Eigen/Dense>
#include <QtTest>

#include <cmath>

using namespace kontur::geo;
using namespace kontur::test;

class TestSeed001Splines final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Example 1.20: V = (2, 15/4, 5) → h = 3/2, U = (−5/2, −1, 1/2, 2, 15/4, 5, 13/2, 8, 19/2).
    void example120()
    {
        const std::vector<double> v{2, 15.0 / 4, 5};
        const auto u = globalBSplineKnots(v);
        const std::vector<double> want{-2.5, -1, 0.5, 2, 3.75, 5, 6.5, 8, 9.5};
        QCOMPARE(u.size(), want.size());
        for (std::size_t i = 0; i < u.size(); ++i)
            QVERIFY(near(u[i], want[i], 1e-15));
    }

    // Example 1.23: C = (−1/2, 11/10, 3/4), d = (−2, 4/5) → b ≈ (0.290301, −0.224190, 0.138259,
    // −0.034416, 0.271097) for the scaled bells.
    void example123()
    {
        const std::vector<double> v{2, 15.0 / 4, 5}, c{-0.5, 1.1, 0.75};
        auto g = globalBSplineFunction(v, c, -2.0, 0.8);
        QVERIFY(g.ok());
        const double want[] = {0.290301, -0.224190, 0.138259, -0.034416, 0.271097};
        QCOMPARE(g->coefficients.size(), 5u);
        for (int i = 0; i < 5; ++i)
            QVERIFY2(near(g->coefficients[static_cast<std::size_t>(i)], want[i], 5e-7),
                     qPrintable(QString::number(g->coefficients[static_cast<std::size_t>(i)], 'g', 10)));
        // It interpolates and meets the end derivatives.
        for (std::size_t i = 0; i < 3; ++i)
            QVERIFY(near(g->spline.eval(v[i]).y(), c[i], 1e-13));
        const Point dl = g->spline.derivative(2.0), dr = g->spline.derivative(5.0);
        QVERIFY(near(dl.y() / dl.x(), -2.0, 1e-12));
        QVERIFY(near(dr.y() / dr.x(), 0.8, 1e-12));
    }

    // The O(k) solution equals the seed's (k + 2)×(k + 2) system L b = (c, d_left, d_right) built
    // from the bells and solved densely.
    void againstFullSystem_data()
    {
        QTest::addColumn<int>("k");
        for (int k : {2, 3, 4, 7, 20})
            QTest::addRow("k=%d", k) << k;
    }

    void againstFullSystem()
    {
        QFETCH(int, k);
        std::mt19937_64 rng(static_cast<unsigned>(k));
        const auto v = randomIncreasing(rng, k, -3.0);
        const auto c = randomValues(rng, k);
        const double dl = 1.5, dr = -0.7;
        auto g = globalBSplineFunction(v, c, dl, dr);
        QVERIFY(g.ok());
        const auto &u = g->knots;
        const int m = k + 2;
        Eigen::MatrixXd L = Eigen::MatrixXd::Zero(m, m);
        Eigen::VectorXd rhs(m);
        auto bsAt = [&](int j, double x) { // the bell of N_j on the span containing x (x in its support)
            for (int p = 1; p <= 4; ++p) {
                const auto lo = static_cast<std::size_t>(j + 4 - p);
                if (x >= u[lo] && x <= u[lo + 1])
                    return *bell(u, j, 3, p, x);
            }
            return 0.0;
        };
        for (int i = 0; i < k; ++i) {
            for (int j = 0; j < m; ++j)
                L(i, j) = bsAt(j, v[static_cast<std::size_t>(i)]);
            rhs(i) = c[static_cast<std::size_t>(i)];
        }
        // Derivative rows by a central difference of the bell pieces (polynomials: exact up to rounding).
        const double e = 1e-6 * (v.back() - v.front());
        for (int j = 0; j < m; ++j) {
            for (int p = 1; p <= 4; ++p) {
                const auto lo = static_cast<std::size_t>(j + 4 - p);
                if (lo + 1 < u.size() && u[lo] == v.front())
                    L(k, j) = (*bell(u, j, 3, p, v.front() + e) - *bell(u, j, 3, p, v.front() - e)) / (2 * e);
                if (lo + 1 < u.size() && u[lo + 1] == v.back())
                    L(k + 1, j) = (*bell(u, j, 3, p, v.back() + e) - *bell(u, j, 3, p, v.back() - e)) / (2 * e);
            }
        }
        rhs(k) = dl;
        rhs(k + 1) = dr;
        const Eigen::VectorXd b = L.fullPivLu().solve(rhs);
        for (int j = 0; j < m; ++j)
            QVERIFY2(near(g->coefficients[static_cast<std::size_t>(j)], b(j), 1e-6 * (1 + std::abs(b(j)))),
                     qPrintable(QStringLiteral("b_%1: %2 vs %3")
                                    .arg(j)
                                    .arg(g->coefficients[static_cast<std::size_t>(j)])
                                    .arg(b(j))));
    }

    // docs/requirements.md 2: y = (3, 2, −1, 0.5), h = 1, d_0 = d_3 = 0 → d_2 = −0.4, d_1 = −2.9, both solvers.
    void torokExample()
    {
        const std::vector<double> y{3, 2, -1, 0.5};
        for (auto solver : {ClampedSolver::Classical, ClampedSolver::Torok}) {
            auto d = uniformClampedSlopes(y, 1.0, 0.0, 0.0, solver);
            QVERIFY(d.ok());
            QVERIFY(near((*d)[2], -0.4, 1e-15));
            QVERIFY(near((*d)[1], -2.9, 1e-15));
        }
    }

    void torokEqualsClassical_data()
    {
        QTest::addColumn<int>("k");
        for (int k = 2; k <= 60; ++k)
            QTest::addRow("k=%d", k) << k;
    }

    // Török's procedure with the corrected boundary terms gives the classical derivatives for every
    // k, odd and even; and both equal the general clamped spline's derivatives.
    void torokEqualsClassical()
    {
        QFETCH(int, k);
        std::mt19937_64 rng(static_cast<unsigned>(k));
        for (int trial = 0; trial < 5; ++trial) {
            const auto y = randomValues(rng, k);
            const double h = 0.25 + trial, d0 = randomValues(rng, 1)[0], dn = randomValues(rng, 1)[0];
            auto a = uniformClampedSlopes(y, h, d0, dn, ClampedSolver::Classical);
            auto b = uniformClampedSlopes(y, h, d0, dn, ClampedSolver::Torok);
            QVERIFY(a.ok() && b.ok());
            std::vector<double> x(static_cast<std::size_t>(k));
            for (int i = 0; i < k; ++i)
                x[static_cast<std::size_t>(i)] = 1.0 + h * i;
            auto general = functionSplineSlopes(x, y, EndCondition::Clamped, d0, dn);
            QVERIFY(general.ok());
            for (std::size_t i = 0; i < y.size(); ++i) {
                const double scale = 1 + std::abs((*a)[i]);
                QVERIFY2(near((*a)[i], (*b)[i], 1e-12 * scale),
                         qPrintable(QStringLiteral("d_%1: %2 vs %3").arg(i).arg((*a)[i]).arg((*b)[i])));
                QVERIFY(near((*a)[i], (*general)[i], 1e-12 * scale));
            }
        }
    }

    // On uniform knots the clamped spline equals the global B-spline (seed 001 §1.4); and on any knots
    // the global B-spline is the clamped cubic spline (the unique C² cubic with those conditions).
    void clampedEqualsGlobal_data()
    {
        QTest::addColumn<bool>("uniform");
        QTest::addRow("uniform") << true;
        QTest::addRow("non-uniform") << false;
    }

    void clampedEqualsGlobal()
    {
        QFETCH(bool, uniform);
        std::mt19937_64 rng(uniform ? 1 : 2);
        for (int k : {2, 3, 4, 5, 10, 31}) {
            std::vector<double> x =
                uniform ? std::vector<double>(static_cast<std::size_t>(k)) : randomIncreasing(rng, k);
            if (uniform)
                for (int i = 0; i < k; ++i)
                    x[static_cast<std::size_t>(i)] = -2.0 + 0.75 * i;
            const auto y = randomValues(rng, k);
            const double d0 = 0.3, dn = -1.2;
            auto g = globalBSplineFunction(x, y, d0, dn);
            auto c = uniform ? uniformClampedSpline(x, y, d0, dn, ClampedSolver::Torok)
                             : functionSpline(x, y, EndCondition::Clamped, d0, dn);
            QVERIFY(g.ok() && c.ok());
            for (double t = x.front(); t <= x.back(); t += (x.back() - x.front()) / 113) {
                const Point p = g->spline.eval(t);
                QVERIFY(near(p.x(), t, 1e-12 * (1 + std::abs(t))));
                QVERIFY2(near(p.y(), c->functionValue(t), 1e-11 * (1 + std::abs(p.y()))),
                         qPrintable(
                             QStringLiteral("k=%1 x=%2: %3 vs %4").arg(k).arg(t).arg(p.y()).arg(c->functionValue(t))));
            }
        }
    }

    // The parametric global B-spline through points: interpolation, end tangents, C² and the
    // clamped cubic spline over the same parameters.
    void parametricGlobal()
    {
        std::mt19937_64 rng(8);
        for (auto param : {Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal}) {
            const auto pts = randomPoints(rng, 9);
            const Point t0(1, 2), t1(-3, 0.5);
            auto g = globalBSpline(pts, param, t0, t1);
            auto c = cubicSpline(pts, EndCondition::Clamped, param, t0, t1);
            QVERIFY(g.ok() && c.ok());
            QCOMPARE(g->controlPointCount(), 11);
            const auto &u = c->parameters();
            for (std::size_t i = 0; i < pts.size(); ++i)
                QVERIFY(near(g->eval(u[i]), pts[i], 1e-10));
            QVERIFY(near(g->derivative(u.front()), t0, 1e-10));
            QVERIFY(near(g->derivative(u.back()), t1, 1e-10));
            for (double t = u.front(); t <= u.back(); t += (u.back() - u.front()) / 200)
                QVERIFY(near(g->eval(t), c->eval(t), 1e-9));
            const auto joints = g->toPiecewise().continuity(1e-8);
            QCOMPARE(joints.size(), pts.size() - 2);
            if (param == Parameterization::Uniform)
                for (const auto &j : joints)
                    QCOMPARE(j.level, Continuity::C2);
        }
    }

    void badInput()
    {
        const std::vector<double> y{1, 2, 3};
        QCOMPARE(uniformClampedSpline(std::vector<double>{0, 1, 3}, y, 0, 0).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(uniformClampedSpline(std::vector<double>{0, 1}, y, 0, 0).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(uniformClampedSlopes(y, 0.0, 0, 0, ClampedSolver::Torok).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(uniformClampedSlopes(std::vector<double>{1}, 1.0, 0, 0, ClampedSolver::Torok).error().code,
                 ErrorCode::TooFewPoints);
        QCOMPARE(globalBSplineFunction(std::vector<double>{0, 0, 1}, y, 0, 0).error().code, ErrorCode::InvalidArgument);
        QCOMPARE(globalBSplineFunction(std::vector<double>{0}, std::vector<double>{1}, 0, 0).error().code,
                 ErrorCode::TooFewPoints);
        const std::vector<Point> pts{{0, 0}, {1, 1}, {2, 0}};
        // A zero start derivative is valid (issue #17): the curve leaves (0, 0) at speed zero, and it
        // still interpolates with the end derivative given.
        const auto zero = globalBSpline(pts, Parameterization::ChordLength, Point(0, 0), Point(1, 0));
        QVERIFY(zero.ok());
        QVERIFY(zero->derivative(zero->startParameter()).norm() < 1e-12);
        QVERIFY((zero->derivative(zero->endParameter()) - Point(1, 0)).norm() < 1e-12);
        QVERIFY((zero->eval(zero->startParameter()) - Point(0, 0)).norm() < 1e-12);
        QVERIFY((zero->eval(zero->endParameter()) - Point(2, 0)).norm() < 1e-12);
        QCOMPARE(
            globalBSpline(std::vector<Point>{{0, 0}, {0, 0}}, Parameterization::ChordLength, Point(1, 0), Point(1, 0))
                .error()
                .code,
            ErrorCode::AllPointsEqual);
    }

    void largeGlobal()
    {
        std::mt19937_64 rng(13);
        const auto pts = randomPoints(rng, 200'000);
        auto g = globalBSpline(pts, Parameterization::ChordLength, Point(1, 0), Point(0, 1));
        QVERIFY(g.ok());
        for (const Point &p : g->controlPoints())
            QVERIFY(std::isfinite(p.x()) && std::isfinite(p.y()));
    }
};

QTEST_GUILESS_MAIN(TestSeed001Splines)
#include "tst_seed001splines.moc"
