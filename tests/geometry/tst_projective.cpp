// The projective map of the plane (geometry/projective.h): the four pairs mapped exactly, the
// inverse and composition, the Jacobian against finite differences, affine maps staying affine, and
// degenerate input refused, over random quadrilaterals from 1e-6 to 1e6 in size.
#include "geometry/projective.h"

#include "testutil.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using kontur::geo::ErrorCode;
using kontur::geo::Point;
using kontur::geo::Projective2D;
using kontur::geo::Quad;

namespace {

// A convex quadrilateral of size about `scale` around a centre at most `scale` away from the
// origin: corners at jittered angles a quarter turn apart, at radii between 0.4 and 1 (so no three
// of them lie near a line).
Quad randomQuad(std::mt19937_64 &rng, double scale)
{
    std::uniform_real_distribution<double> jitter(-0.5, 0.5), radius(0.4, 1.0), centre(-1.0, 1.0),
        turn(0.0, 2.0 * std::numbers::pi);
    const double start = turn(rng);
    const Point c(centre(rng) * scale, centre(rng) * scale);
    Quad q;
    for (int i = 0; i < 4; ++i) {
        const double a = start + (i + jitter(rng) * 0.5) * std::numbers::pi / 2.0;
        q[static_cast<std::size_t>(i)] = c + radius(rng) * scale * Point(std::cos(a), std::sin(a));
    }
    return q;
}

double extent(const Quad &q)
{
    double e = 0.0;
    for (const Point &a : q)
        for (const Point &b : q)
            e = std::max(e, (a - b).norm());
    return e;
}

// A point inside the quadrilateral (a random convex combination of its corners).
Point inside(std::mt19937_64 &rng, const Quad &q)
{
    std::uniform_real_distribution<double> w(0.1, 1.0);
    double sum = 0.0;
    Point p = Point::Zero();
    for (const Point &c : q) {
        const double wi = w(rng);
        p += wi * c;
        sum += wi;
    }
    return p / sum;
}

} // namespace

class TestProjective final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void textbookOracle();
    void mapsFourPairs_data();
    void mapsFourPairs();
    void inverseRoundTrip_data() { mapsFourPairs_data(); }
    void inverseRoundTrip();
    void composeIsApplyingInTurn();
    void jacobianMatchesDifferences();
    void affineStaysAffine();
    void degenerateInputIsRefused();
};

void TestProjective::textbookOracle()
{
    // H = [[1,0,0],[0,1,0],[1,0,1]]: (x, y) ↦ (x, y) / (x + 1). It takes the unit square to
    // (0,0), (1/2,0), (1/2,1/2), (0,1), and the square's centre to (1/3, 1/3).
    const Quad square{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    const Quad image{Point(0, 0), Point(0.5, 0), Point(0.5, 0.5), Point(0, 1)};
    const auto h = Projective2D::fromPointPairs(square, image);
    QVERIFY(h.ok());
    QVERIFY(!h->isAffine());
    QVERIFY((h->map(Point(0.5, 0.5)) - Point(1.0 / 3.0, 1.0 / 3.0)).norm() <= 1e-15);
    Eigen::Matrix3d expected;
    expected << 1, 0, 0, 0, 1, 0, 1, 0, 1;
    QVERIFY((h->matrix() - expected).norm() <= 1e-14);
    // Its Jacobian at (x, y): [[1/(x+1)², 0], [−y/(x+1)², 1/(x+1)]].
    const Eigen::Matrix2d j = h->jacobian(Point(1.0, 3.0));
    QVERIFY(std::abs(j(0, 0) - 0.25) <= 1e-14 && std::abs(j(0, 1)) <= 1e-14);
    QVERIFY(std::abs(j(1, 0) + 0.75) <= 1e-14 && std::abs(j(1, 1) - 0.5) <= 1e-14);
    // The line x = −1 goes to infinity.
    QCOMPARE(h->denominator(Point(-1.0, 7.0)), 0.0);
}

void TestProjective::mapsFourPairs_data()
{
    QTest::addColumn<double>("fromScale");
    QTest::addColumn<double>("toScale");
    for (const double a : {1e-6, 1e-3, 1.0, 1e3, 1e6})
        for (const double b : {1e-6, 1.0, 1e6})
            QTest::addRow("%g -> %g", a, b) << a << b;
}

void TestProjective::mapsFourPairs()
{
    QFETCH(double, fromScale);
    QFETCH(double, toScale);
    std::mt19937_64 rng(0x70726f6aULL +
                        static_cast<unsigned long long>(std::log10(fromScale) * 31 + std::log10(toScale)));
    double worst = 0.0;
    for (int trial = 0; trial < 300; ++trial) {
        const Quad from = randomQuad(rng, fromScale), to = randomQuad(rng, toScale);
        const auto h = Projective2D::fromPointPairs(from, to);
        QVERIFY2(h.ok(), h.ok() ? "" : h.error().message.c_str());
        for (std::size_t i = 0; i < 4; ++i)
            worst = std::max(worst, (h->map(from[i]) - to[i]).norm() / extent(to));
    }
    QVERIFY2(worst <= 1e-12, qPrintable(QStringLiteral("worst relative error %1").arg(worst)));
}

void TestProjective::inverseRoundTrip()
{
    QFETCH(double, fromScale);
    QFETCH(double, toScale);
    std::mt19937_64 rng(0x696e76ULL +
                        static_cast<unsigned long long>(std::log10(fromScale) * 31 + std::log10(toScale)));
    for (int trial = 0; trial < 300; ++trial) {
        const Quad from = randomQuad(rng, fromScale), to = randomQuad(rng, toScale);
        const auto h = Projective2D::fromPointPairs(from, to);
        QVERIFY(h.ok());
        const auto inv = h->inverse();
        QVERIFY(inv.ok());
        for (std::size_t i = 0; i < 4; ++i)
            QVERIFY((inv->map(to[i]) - from[i]).norm() <= 1e-12 * extent(from));
        for (int k = 0; k < 4; ++k) {
            const Point p = inside(rng, from);
            QVERIFY2((inv->map(h->map(p)) - p).norm() <= 1e-12 * extent(from), qPrintable(kontur::test::str(p)));
        }
    }
}

void TestProjective::composeIsApplyingInTurn()
{
    std::mt19937_64 rng(0x636f6dULL);
    for (int trial = 0; trial < 200; ++trial) {
        const Quad a = randomQuad(rng, 10.0), b = randomQuad(rng, 1e3), c = randomQuad(rng, 0.1);
        const auto f = Projective2D::fromPointPairs(a, b), g = Projective2D::fromPointPairs(b, c);
        QVERIFY(f.ok() && g.ok());
        const Projective2D fg = f->then(*g);
        for (std::size_t i = 0; i < 4; ++i)
            QVERIFY((fg.map(a[i]) - c[i]).norm() <= 1e-12 * extent(c));
        const Point p = inside(rng, a);
        QVERIFY((fg.map(p) - g->map(f->map(p))).norm() <= 1e-12 * extent(c));
        // A map then its inverse is the identity.
        const Projective2D id = f->then(*f->inverse());
        QVERIFY((id.matrix() - Eigen::Matrix3d::Identity()).norm() <= 1e-12);
    }
}

void TestProjective::jacobianMatchesDifferences()
{
    std::mt19937_64 rng(0x6a6163ULL);
    for (int trial = 0; trial < 200; ++trial) {
        const Quad from = randomQuad(rng, 100.0), to = randomQuad(rng, 1.0);
        const auto h = Projective2D::fromPointPairs(from, to);
        QVERIFY(h.ok());
        const Point p = inside(rng, from);
        const double step = 1e-4;
        const Eigen::Matrix2d j = h->jacobian(p);
        for (int k = 0; k < 2; ++k) {
            const Point d = step * Point::Unit(k);
            const Point central = (h->map(p + d) - h->map(p - d)) / (2.0 * step);
            QVERIFY2((j.col(k) - central).norm() <= 1e-6 * j.norm(),
                     qPrintable(QStringLiteral("trial %1 column %2").arg(trial).arg(k)));
        }
    }
}

void TestProjective::affineStaysAffine()
{
    std::mt19937_64 rng(0x616666ULL);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int trial = 0; trial < 200; ++trial) {
        Eigen::Matrix2d linear;
        linear << u(rng), u(rng), u(rng), u(rng);
        if (std::abs(linear.determinant()) < 0.1)
            continue;
        const Point shift(u(rng) * 1e3, u(rng) * 1e3);
        const Projective2D a = Projective2D::fromAffine(linear, shift);
        QVERIFY(a.isAffine());
        const auto inv = a.inverse();
        QVERIFY(inv.ok() && inv->isAffine());
        QVERIFY(a.then(*inv).isAffine());
        const Point p(u(rng), u(rng));
        QCOMPARE(a.map(p), Point(linear * p + shift)); // exactly: no division by w
        QVERIFY((a.jacobian(p) - linear).norm() <= 1e-15 * linear.norm());
        // Four pairs related by an affine map give it back: the projective row vanishes to rounding.
        const Quad from = randomQuad(rng, 50.0);
        Quad to;
        for (std::size_t i = 0; i < 4; ++i)
            to[i] = a.map(from[i]);
        const auto fitted = Projective2D::fromPointPairs(from, to);
        QVERIFY(fitted.ok());
        const Eigen::Matrix3d &m = fitted->matrix();
        QVERIFY2(std::abs(m(2, 0)) * 100.0 <= 1e-12 && std::abs(m(2, 1)) * 100.0 <= 1e-12,
                 qPrintable(QStringLiteral("%1 %2").arg(m(2, 0)).arg(m(2, 1))));
        // The linear part is found from points 1e3 from the origin but 50 apart: its error is the
        // points' rounding times that ratio.
        QVERIFY2((m.topLeftCorner<2, 2>() - linear).norm() <= 1e-11 * linear.norm(),
                 qPrintable(QStringLiteral("%1").arg((m.topLeftCorner<2, 2>() - linear).norm() / linear.norm())));
    }
}

void TestProjective::degenerateInputIsRefused()
{
    const Quad square{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    const Quad collinear{Point(0, 0), Point(1, 1), Point(2, 2), Point(0, 1)};
    const Quad repeated{Point(0, 0), Point(1, 0), Point(1, 0), Point(0, 1)};
    const Quad onePoint{Point(3, 4), Point(3, 4), Point(3, 4), Point(3, 4)};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Quad notFinite{Point(0, 0), Point(1, nan), Point(1, 1), Point(0, 1)};
    for (const Quad &bad : {collinear, repeated, onePoint}) {
        const auto h = Projective2D::fromPointPairs(square, bad);
        QVERIFY(!h.ok());
        QVERIFY(h.error().code == ErrorCode::IllConditioned || h.error().code == ErrorCode::AllPointsEqual);
        QVERIFY(!Projective2D::fromPointPairs(bad, square).ok());
    }
    // Nearly collinear at a tiny scale is still refused: the test is made after normalisation.
    Quad thin = collinear;
    for (Point &p : thin)
        p *= 1e-9;
    QVERIFY(!Projective2D::fromPointPairs(square, thin).ok());
    QCOMPARE(Projective2D::fromPointPairs(square, notFinite).error().code, ErrorCode::NonFiniteInput);
    Eigen::Matrix3d singular;
    singular << 1, 2, 3, 2, 4, 6, 0, 0, 1;
    QVERIFY(!Projective2D::fromMatrix(singular).ok());
    QVERIFY(!Projective2D::fromAffine(Eigen::Matrix2d::Zero(), Point(1, 2)).inverse().ok());
}

QTEST_APPLESS_MAIN(TestProjective)
#include "tst_projective.moc"
