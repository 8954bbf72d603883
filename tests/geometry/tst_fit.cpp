// Parameterizations (docs/requirements.md 1.3), the cubic through 4 knots and the least-squares cubic
// (docs/requirements.md 1.2): oracles, properties over random data, and the typed errors on degenerate input.
#include "geometry/fit.h"
#include "testutil.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QtTest>

#include <cmath>

using kontur::geo::Bezier;
using kontur::geo::ErrorCode;
using kontur::geo::Parameterization;
using kontur::geo::Point;
using namespace kontur::test;

Q_DECLARE_METATYPE(std::vector<Point>)
Q_DECLARE_METATYPE(std::vector<double>)
Q_DECLARE_METATYPE(Parameterization)
Q_DECLARE_METATYPE(ErrorCode)

class TestFit final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parameters_data();
    void parameters();
    void interpolationPassesThroughPoints();
    void leastSquaresMatchesDenseQr();
    void seminormalMatchesStreamingQr();
    void leastSquaresBeatsPerturbedPolygons();
    void recoversExactCubic();
    void reparameterizationImproves();
    void errors_data();
    void errors();
    void allowCoincident();
    void largeInput();
};

void TestFit::parameters_data()
{
    QTest::addColumn<std::vector<Point>>("points");
    QTest::addColumn<double>("alpha");
    QTest::addColumn<std::vector<double>>("expected");
    const std::vector<Point> five{{0, 0}, {3, 4}, {3, 5}, {3, 9}, {4, 9}};
    // docs/requirements.md 1.3: uniform on 5 points is 0, 0.25, 0.5, 0.75, 1.
    QTest::addRow("uniform") << five << 0.0 << std::vector<double>{0, 0.25, 0.5, 0.75, 1};
    // Steps 5, 1, 4, 1 → L = 11.
    QTest::addRow("chord") << five << 1.0 << std::vector<double>{0, 5.0 / 11, 6.0 / 11, 10.0 / 11, 1};
    // Square roots √5, 1, 2, 1 → L = 4 + √5.
    const double r5 = std::sqrt(5.0), l = 4 + r5;
    QTest::addRow("centripetal") << five << 0.5 << std::vector<double>{0, r5 / l, (r5 + 1) / l, (r5 + 3) / l, 1};
    // General α = 0.25 on steps 16, 1, 81: 2, 1, 3 → L = 6.
    QTest::addRow("alpha 1/4") << std::vector<Point>{{0, 0}, {16, 0}, {16, 1}, {16, 82}} << 0.25
                               << std::vector<double>{0, 2.0 / 6, 3.0 / 6, 1};
}

void TestFit::parameters()
{
    QFETCH(std::vector<Point>, points);
    QFETCH(double, alpha);
    QFETCH(std::vector<double>, expected);
    const auto s = kontur::geo::parameterize(points, alpha);
    QVERIFY(s.ok());
    QCOMPARE(s->size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY2(std::abs((*s)[i] - expected[i]) < 1e-15, qPrintable(QString::number((*s)[i], 'g', 17)));
}

void TestFit::interpolationPassesThroughPoints()
{
    std::mt19937_64 rng(31);
    for (int trial = 0; trial < 200; ++trial) {
        const auto pts = randomPoints(rng, 4);
        for (double alpha : {0.0, 0.25, 0.5, 1.0}) {
            const auto fit = kontur::geo::interpolateCubic(pts, alpha);
            QVERIFY(fit.ok());
            const Bezier c = fit->curve();
            for (int i = 0; i < 4; ++i)
                QVERIFY2((c.eval(fit->params[i]) - pts[i]).norm() < 1e-9 * polygonScale(pts),
                         qPrintable(str(c.eval(fit->params[i]) - pts[i])));
            QVERIFY(fit->rms < 1e-9 * polygonScale(pts));
            QVERIFY(fit->maxError < 1e-9 * polygonScale(pts));
            // The end knots are the end control points (s_0 = 0, s_3 = 1).
            QVERIFY((fit->control[0] - pts[0]).norm() < 1e-9 * polygonScale(pts));
            QVERIFY((fit->control[3] - pts[3]).norm() < 1e-9 * polygonScale(pts));
        }
    }
    const auto wrongCount = kontur::geo::interpolateCubic(randomPoints(rng, 5), Parameterization::Uniform);
    QVERIFY(!wrongCount.ok());
    QCOMPARE(wrongCount.error().code, ErrorCode::InvalidArgument);
}

void TestFit::leastSquaresMatchesDenseQr()
{
    // Reference: Eigen's dense column-pivoting QR on the n×4 Bernstein matrix.
    std::mt19937_64 rng(32);
    for (int trial = 0; trial < 50; ++trial) {
        const auto pts = randomPoints(rng, 4 + trial * 7);
        const auto fit = kontur::geo::fitCubic(pts, Parameterization::Centripetal);
        QVERIFY(fit.ok());
        const int n = static_cast<int>(pts.size());
        Eigen::MatrixXd a(n, 4), b(n, 2);
        for (int i = 0; i < n; ++i) {
            const double t = fit->params[i], s = 1 - t;
            a.row(i) << s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t;
            b.row(i) << pts[i].x(), pts[i].y();
        }
        const Eigen::MatrixXd c = a.colPivHouseholderQr().solve(b);
        for (int j = 0; j < 4; ++j)
            QVERIFY((fit->control[j] - Point(c(j, 0), c(j, 1))).norm() < 1e-9 * polygonScale(pts));
        const double rms = std::sqrt((a * c - b).squaredNorm() / n);
        QVERIFY(std::abs(fit->rms - rms) < 1e-9 * polygonScale(pts));
    }
}

void TestFit::seminormalMatchesStreamingQr()
{
    // The corrected semi-normal equations against the streaming QR they replaced (kept as
    // detail::fitCubicWithParamsQr), on random point sets at scales 1e-6…1e6: parameters spread over
    // [0, 1], and clustered ones (most of them in a short interval) whose Bernstein matrix B is
    // ill-conditioned (κ(B) up to ~1e9), with points near a random cubic (relative noise 1e-12…1e-2).
    //
    // Tolerance, from the perturbation theory of least squares (Wedin; Björck, "Numerical Methods
    // for Least Squares Problems", 1996, Thm 1.4.6): a backward stable solver's control points are
    // within ~ε κ (‖c‖ + κ ‖r‖ / σ_max(B)) of the exact ones (c the solution, r the residual); both
    // solvers are held to 64 times that of each other. The semi-normal equations without their
    // refinement step err by ~ε κ² ‖c‖, which exceeds it as soon as κ is more than ~64 and the
    // residual small: the clustered sets with little noise exist to catch exactly that.
    std::mt19937_64 rng(36);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    int refined = 0, qrZone = 0, compared = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double scale = std::pow(10.0, -6.0 + 12.0 * unit(rng));
        const auto control = randomPoints(rng, 4, -scale, scale);
        const Bezier truth(control);
        const int n = 4 + static_cast<int>(unit(rng) * 200);
        std::vector<double> s(n);
        const bool clustered = trial % 2 == 1;
        const double width = std::pow(10.0, -6.0 * unit(rng));
        const double start = unit(rng) * (1.0 - width);
        for (int i = 0; i < n; ++i)
            s[i] = clustered && i >= 2 ? start + width * unit(rng) : unit(rng);
        const double noise = scale * std::pow(10.0, -12.0 + 10.0 * unit(rng));
        std::vector<Point> pts(n);
        for (int i = 0; i < n; ++i)
            pts[i] = truth.eval(s[i]) + noise * Point(2 * unit(rng) - 1, 2 * unit(rng) - 1);
        const auto fast = kontur::geo::fitCubicWithParams(pts, s);
        const auto reference = kontur::geo::detail::fitCubicWithParamsQr(pts, s);
        QCOMPARE(fast.ok(), reference.ok());
        if (!reference.ok()) {
            QCOMPARE(fast.error().code, reference.error().code);
            continue;
        }
        Eigen::MatrixXd b(n, 4);
        for (int i = 0; i < n; ++i) {
            const double t = s[i], u = 1 - t;
            b.row(i) << u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t;
        }
        const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(b).singularValues();
        const double kappa = sv(0) / sv(3);
        refined += kappa > 100 && kappa < 2000 ? 1 : 0;
        qrZone += kappa > 1e4 ? 1 : 0;
        double cn = 0.0;
        for (const Point &c : reference->control)
            cn = std::max(cn, c.norm());
        const double residual = reference->rms * std::sqrt(static_cast<double>(n));
        const double tol = 64 * eps * kappa * (cn + kappa * residual / sv(0));
        for (int j = 0; j < 4; ++j)
            QVERIFY2((fast->control[j] - reference->control[j]).norm() <= tol,
                     qPrintable(QStringLiteral("trial %1 κ %2: control %3 differs by %4, tolerance %5")
                                    .arg(trial)
                                    .arg(kappa)
                                    .arg(j)
                                    .arg((fast->control[j] - reference->control[j]).norm())
                                    .arg(tol)));
        // The reported residuals are those of the returned control points.
        QVERIFY(std::abs(fast->rms - reference->rms) <= tol + 1e-12 * reference->rms);
        QVERIFY(std::abs(fast->maxError - reference->maxError) <= 2 * tol + 1e-12 * reference->maxError);
        ++compared;
    }
    // Every regime was exercised: refined semi-normal solutions and the QR's.
    QVERIFY2(refined >= 100, qPrintable(QString::number(refined)));
    QVERIFY2(qrZone >= 100, qPrintable(QStringLiteral("%1 %2 %3").arg(refined).arg(qrZone).arg(compared)));
    QVERIFY2(compared >= 2500, qPrintable(QStringLiteral("%1 %2 %3").arg(refined).arg(qrZone).arg(compared)));
}

void TestFit::leastSquaresBeatsPerturbedPolygons()
{
    std::mt19937_64 rng(33);
    std::normal_distribution<double> jitter(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const auto pts = randomPoints(rng, 5 + trial);
        const auto fit = kontur::geo::fitCubic(pts, Parameterization::ChordLength);
        QVERIFY(fit.ok());
        auto sse = [&](const std::array<Point, 4> &c) {
            const Bezier b({c.begin(), c.end()});
            double sum = 0;
            for (std::size_t i = 0; i < pts.size(); ++i)
                sum += (b.eval(fit->params[i]) - pts[i]).squaredNorm();
            return sum;
        };
        const double best = sse(fit->control);
        QVERIFY(std::abs(std::sqrt(best / pts.size()) - fit->rms) < 1e-9 * polygonScale(pts));
        for (int k = 0; k < 20; ++k) {
            auto c = fit->control;
            for (auto &p : c)
                p += Point(jitter(rng), jitter(rng)) * (k < 10 ? 1e-3 : 1.0);
            QVERIFY(sse(c) >= best);
        }
    }
}

void TestFit::recoversExactCubic()
{
    // Points on a cubic at known parameters: the fit returns the cubic with zero residual.
    std::mt19937_64 rng(34);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const auto control = randomPoints(rng, 4);
        const Bezier c(control);
        std::vector<double> s(50);
        std::vector<Point> pts(50);
        for (int i = 0; i < 50; ++i) {
            s[i] = unit(rng);
            pts[i] = c.eval(s[i]);
        }
        const auto fit = kontur::geo::fitCubicWithParams(pts, s);
        QVERIFY(fit.ok());
        for (int j = 0; j < 4; ++j)
            QVERIFY((fit->control[j] - control[j]).norm() < 1e-9 * polygonScale(control));
        QVERIFY(fit->maxError < 1e-9 * polygonScale(control));
    }
}

void TestFit::reparameterizationImproves()
{
    // Points on a quarter circle: the seed's fit (0 rounds) versus parameter correction.
    std::vector<Point> pts;
    for (int i = 0; i <= 40; ++i) {
        const double a = M_PI / 2 * std::pow(i / 40.0, 1.7);
        pts.emplace_back(100 * std::cos(a), 100 * std::sin(a));
    }
    const auto seed = kontur::geo::fitCubic(pts, kontur::geo::FitOptions{1.0, 0, false});
    const auto better = kontur::geo::fitCubic(pts, kontur::geo::FitOptions{1.0, 10, false});
    QVERIFY(seed.ok() && better.ok());
    QCOMPARE(seed->iterations, 0);
    QVERIFY(better->iterations > 0);
    QVERIFY(better->rms < seed->rms);
}

void TestFit::errors_data()
{
    QTest::addColumn<std::vector<Point>>("points");
    QTest::addColumn<double>("alpha");
    QTest::addColumn<ErrorCode>("code");
    QTest::addColumn<int>("index");
    QTest::addRow("three points") << std::vector<Point>{{0, 0}, {1, 0}, {2, 1}} << 1.0 << ErrorCode::TooFewPoints << 3;
    QTest::addRow("all equal") << std::vector<Point>(6, Point(2, 3)) << 1.0 << ErrorCode::AllPointsEqual << -1;
    QTest::addRow("all equal uniform") << std::vector<Point>(4, Point(2, 3)) << 0.0 << ErrorCode::AllPointsEqual << -1;
    QTest::addRow("coincident chord") << std::vector<Point>{{0, 0}, {1, 0}, {1, 0}, {2, 1}, {3, 0}} << 1.0
                                      << ErrorCode::CoincidentPoints << 2;
    QTest::addRow("coincident centripetal")
        << std::vector<Point>{{0, 0}, {0, 0}, {1, 0}, {2, 1}} << 0.5 << ErrorCode::CoincidentPoints << 1;
    QTest::addRow("coincident uniform") << std::vector<Point>{{0, 0}, {1, 0}, {2, 1}, {2, 1}} << 0.0
                                        << ErrorCode::CoincidentPoints << 3;
    QTest::addRow("not a number") << std::vector<Point>{{0, 0}, {1, NAN}, {2, 1}, {3, 0}} << 1.0
                                  << ErrorCode::NonFiniteInput << 1;
    QTest::addRow("infinite uniform") << std::vector<Point>{{0, 0}, {1, 0}, {INFINITY, 1}, {3, 0}} << 0.0
                                      << ErrorCode::NonFiniteInput << 2;
    QTest::addRow("bad alpha") << std::vector<Point>{{0, 0}, {1, 0}, {2, 1}, {3, 0}} << 1.5
                               << ErrorCode::InvalidArgument << -1;
}

void TestFit::errors()
{
    QFETCH(std::vector<Point>, points);
    QFETCH(double, alpha);
    QFETCH(ErrorCode, code);
    QFETCH(int, index);
    const auto fit = kontur::geo::fitCubic(points, kontur::geo::FitOptions{alpha, 0, false});
    QVERIFY(!fit.ok());
    QCOMPARE(fit.error().code, code);
    QCOMPARE(fit.error().index, index);
    QVERIFY(!fit.error().message.empty());
}

void TestFit::allowCoincident()
{
    // Repeated points are harmless when allowed, but fewer than 4 distinct parameters are not.
    const std::vector<Point> repeated{{0, 0}, {1, 1}, {1, 1}, {2, 0}, {3, 1}};
    const auto ok = kontur::geo::fitCubic(repeated, kontur::geo::FitOptions{1.0, 0, true});
    QVERIFY(ok.ok());
    QVERIFY(std::isfinite(ok->rms));
    const std::vector<Point> three{{0, 0}, {1, 1}, {1, 1}, {2, 0}, {2, 0}};
    const auto bad = kontur::geo::fitCubic(three, kontur::geo::FitOptions{1.0, 0, true});
    QVERIFY(!bad.ok());
    QCOMPARE(bad.error().code, ErrorCode::TooFewDistinctParameters);
    const auto badParams = kontur::geo::fitCubicWithParams(three, {0, 0.5, 0.5, 1, 1});
    QCOMPARE(badParams.error().code, ErrorCode::TooFewDistinctParameters);
}

void TestFit::largeInput()
{
    // 200 000 noisy points on a known cubic: the fit stays close to it (a streaming QR regression).
    const Bezier truth({{0, 0}, {100, 300}, {300, -200}, {400, 100}});
    std::mt19937_64 rng(35);
    std::normal_distribution<double> noise(0.0, 0.5);
    std::vector<Point> pts(200000);
    std::vector<double> s(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        s[i] = static_cast<double>(i) / (pts.size() - 1);
        pts[i] = truth.eval(s[i]) + Point(noise(rng), noise(rng));
    }
    const auto fit = kontur::geo::fitCubicWithParams(pts, s);
    QVERIFY(fit.ok());
    for (int j = 0; j < 4; ++j)
        QVERIFY((fit->control[j] - truth.controlPoints()[j]).norm() < 0.1);
    QVERIFY(std::abs(fit->rms - 0.5 * std::sqrt(2.0)) < 0.01);
}

QTEST_APPLESS_MAIN(TestFit)
#include "tst_fit.moc"
