// Polynomial interpolation for the Runge comparison (issue 4): interpolation, exact reproduction of
// polynomials, the Runge phenomenon against the natural spline, Bézier pieces, bad input.
#include "geometry/splines/cubicspline.h"
#include "geometry/splines/polynomial.h"
#include "splinetestutil.h"

#include <QtTest>

#include <cmath>

using namespace kontur::geo;
using namespace kontur::test;

class TestPolynomial final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void reproducesPolynomials()
    {
        std::mt19937_64 rng(2);
        auto f = [](double x) { return 1 - 2 * x + 0.5 * x * x * x - 0.01 * std::pow(x, 5); };
        for (int n : {6, 9, 15}) {
            const auto x = randomIncreasing(rng, n, -3.0, 0.2, 1.0);
            std::vector<double> y(x.size());
            for (std::size_t i = 0; i < x.size(); ++i)
                y[i] = f(x[i]);
            auto p = functionPolynomial(x, y);
            QVERIFY(p.ok());
            QCOMPARE(p->degree(), n - 1);
            const auto pw = p->toPiecewise();
            QCOMPARE(pw.segmentCount(), n - 1);
            for (double t = x.front(); t <= x.back(); t += 0.01) {
                QVERIFY(near(p->eval(t).y(), f(t), 1e-9 * (1 + std::abs(f(t)))));
                const Point q = evalPieces(pw, x, t);
                QVERIFY2(near(q, p->eval(t), 1e-8 * (1 + std::abs(f(t)))),
                         qPrintable(str(q) + " vs " + str(p->eval(t))));
            }
            for (std::size_t i = 0; i < x.size(); ++i)
                QCOMPARE(p->eval(x[i]).y(), y[i]);
        }
    }

    // Runge: 1/(1 + 25x²) at 11 equally spaced points on [−1, 1]: the polynomial's error near the
    // ends is about 1.9, the natural spline's stays below 0.02.
    void runge()
    {
        const int n = 11;
        std::vector<double> x(n), y(n);
        for (int i = 0; i < n; ++i) {
            x[static_cast<std::size_t>(i)] = -1.0 + 2.0 * i / (n - 1);
            y[static_cast<std::size_t>(i)] =
                1 / (1 + 25 * x[static_cast<std::size_t>(i)] * x[static_cast<std::size_t>(i)]);
        }
        auto p = functionPolynomial(x, y);
        auto s = functionSpline(x, y, EndCondition::Natural);
        QVERIFY(p.ok() && s.ok());
        double ep = 0, es = 0;
        for (double t = -1; t <= 1; t += 0.001) {
            const double f = 1 / (1 + 25 * t * t);
            ep = std::max(ep, std::abs(p->eval(t).y() - f));
            es = std::max(es, std::abs(s->functionValue(t) - f));
        }
        QVERIFY2(ep > 1.8 && ep < 2.0, qPrintable(QString::number(ep)));
        QVERIFY2(es < 0.03, qPrintable(QString::number(es)));
    }

    void parametric()
    {
        std::mt19937_64 rng(5);
        const auto pts = randomPoints(rng, 7);
        for (auto param : {Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal}) {
            auto p = polynomialInterpolant(pts, param);
            QVERIFY(p.ok());
            for (std::size_t i = 0; i < pts.size(); ++i)
                QCOMPARE(p->eval(p->parameters()[i]), pts[i]);
            const auto pw = p->toPiecewise();
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                QVERIFY(near(pw.segments()[i].startPoint(), pts[i], 1e-9 * 100));
                QVERIFY(near(pw.segments()[i].endPoint(), pts[i + 1], 1e-9 * 100));
            }
        }
    }

    void badInput()
    {
        std::mt19937_64 rng(6);
        QCOMPARE(polynomialInterpolant(randomPoints(rng, 1), Parameterization::Uniform).error().code,
                 ErrorCode::TooFewPoints);
        QCOMPARE(
            polynomialInterpolant(randomPoints(rng, kMaxPolynomialPoints + 1), Parameterization::Uniform).error().code,
            ErrorCode::InvalidArgument);
        QCOMPARE(functionPolynomial(std::vector<double>{0, 1, 1}, std::vector<double>{0, 1, 2}).error().code,
                 ErrorCode::InvalidArgument);
        QCOMPARE(functionPolynomial(std::vector<double>{0, 1}, std::vector<double>{0, std::nan("")}).error().code,
                 ErrorCode::NonFiniteInput);
    }
};

QTEST_GUILESS_MAIN(TestPolynomial)
#include "tst_polynomial.moc"
