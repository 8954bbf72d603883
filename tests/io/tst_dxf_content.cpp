// Tests of what a real CAD file holds beyond plain entities, each on a small file built here: arcs and
// ellipses whose end angle was printed with 12 digits (a full turn), blocks exploded through nested
// and arrayed INSERTs, hatch boundaries, the entities Kontur skips (counted, never refusing the
// file) and the units of files without $INSUNITS. The answers come from DXF's own rules (the
// insertion transform, the parametric ellipse), computed here independently of the reader.
#include "io/dxf.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace kontur;
using namespace kontur::io;

namespace {

QByteArray entities(const QByteArray &body)
{
    return "0\nSECTION\n2\nENTITIES\n" + body + "0\nENDSEC\n0\nEOF\n";
}

QString errorText(const Result<DxfImport> &r)
{
    return r.ok() ? QString() : r.error().toString();
}

// The largest distance of the curve's points (21 per piece) from the ellipse with centre c, semi-axes
// a (along the angle phi) and b, measured through the implicit equation scaled to a length.
double offEllipse(const geo::PiecewiseBezier &curve, geo::Point c, double a, double b, double phi)
{
    double worst = 0.0;
    for (const geo::Bezier &s : curve.segments())
        for (int k = 0; k <= 20; ++k) {
            const geo::Point d = s.eval(k / 20.0) - c;
            const double u = d.x() * std::cos(phi) + d.y() * std::sin(phi);
            const double v = -d.x() * std::sin(phi) + d.y() * std::cos(phi);
            worst = std::max(worst, std::abs(std::hypot(u / a, v / b) - 1) * std::min(a, b));
        }
    return worst;
}

// The ellipse's perimeter by Gauss–Kummer's series in h = ((a − b)/(a + b))², to double precision.
double ellipsePerimeter(double a, double b)
{
    const double h = std::pow((a - b) / (a + b), 2);
    double sum = 1.0, term = 1.0;
    for (int n = 1; n < 60; ++n) {
        // binomial(1/2, n)² hⁿ
        term *= (0.5 - (n - 1)) / n;
        sum += term * term * std::pow(h, n);
    }
    return std::numbers::pi * (a + b) * sum;
}

} // namespace

class TestDxfContent final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void sweep_data();
    void sweep();
    void roundedFullTurn_data();
    void roundedFullTurn();
};

void TestDxfContent::sweep_data()
{
    QTest::addColumn<double>("start");
    QTest::addColumn<double>("end");
    QTest::addColumn<double>("period");
    QTest::addColumn<double>("sweep");
    QTest::addColumn<bool>("full");
    const double tau = 2 * std::numbers::pi;
    QTest::addRow("2pi printed with 12 digits") << 0.0 << 6.28318530718 << tau << tau << true;
    QTest::addRow("2pi printed with 12 digits, below") << 0.0 << 6.28318530717 << tau << tau << true;
    QTest::addRow("pi to -pi") << std::numbers::pi << -std::numbers::pi << tau << tau << true;
    QTest::addRow("a millionth short of a turn") << 0.0 << tau - 1e-6 << tau << tau - 1e-6 << false;
    QTest::addRow("same angle") << 1.0 << 1.0 << tau << 0.0 << false;
    QTest::addRow("degrees 0 to 360.000000000001") << 0.0 << 360.000000000001 << 360.0 << 360.0 << true;
    QTest::addRow("degrees 300 to 60") << 300.0 << 60.0 << 360.0 << 120.0 << false;
    QTest::addRow("degrees -90 to 270") << -90.0 << 270.0 << 360.0 << 360.0 << true;
}

void TestDxfContent::sweep()
{
    QFETCH(double, start);
    QFETCH(double, end);
    QFETCH(double, period);
    QFETCH(double, sweep);
    QFETCH(bool, full);
    bool isFull = !full;
    const double got = sweepOf(start, end, period, isFull);
    QCOMPARE(isFull, full);
    QVERIFY2(std::abs(got - sweep) <= 1e-12 * period, qPrintable(QString::number(got, 'g', 17)));
}

// The 800 × 600 ellipse and a circle-like arc with end angles as files print them: whole closed
// curves of the right length, not curves of length 1e-7.
void TestDxfContent::roundedFullTurn_data()
{
    QTest::addColumn<QByteArray>("entity");
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("b");
    QTest::addColumn<double>("phi");
    QTest::addRow("ellipse 0 to 6.28318530718")
        << QByteArray("0\nELLIPSE\n10\n100\n20\n50\n11\n400\n21\n0\n40\n0.75\n41\n0\n42\n6.28318530718\n") << 400.0
        << 300.0 << 0.0;
    QTest::addRow("tilted ellipse 1.5 to 7.78318530718")
        << QByteArray("0\nELLIPSE\n10\n100\n20\n50\n11\n0\n21\n400\n40\n0.75\n41\n1.5\n42\n7.78318530718\n") << 400.0
        << 300.0 << std::numbers::pi / 2;
    QTest::addRow("arc 45 to 405.000000000001")
        << QByteArray("0\nARC\n10\n100\n20\n50\n40\n250\n50\n45\n51\n405.000000000001\n") << 250.0 << 250.0 << 0.0;
}

void TestDxfContent::roundedFullTurn()
{
    QFETCH(QByteArray, entity);
    QFETCH(double, a);
    QFETCH(double, b);
    QFETCH(double, phi);
    DxfImportOptions options;
    options.arcTolerance = 1e-7;
    const auto dxf = importDxf(entities(entity), {}, options);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
    const geo::PiecewiseBezier &curve = dxf->curves.front().curve;
    QVERIFY(curve.isClosed());
    QCOMPARE(curve.segments().back().endPoint(), curve.segments().front().startPoint());
    QVERIFY(offEllipse(curve, geo::Point(100, 50), a, b, phi) <= 2e-7);
    const double length = curve.length(1e-10);
    QVERIFY2(std::abs(length - ellipsePerimeter(a, b)) < 1e-6 * length, qPrintable(QString::number(length, 'g', 17)));
}

QTEST_GUILESS_MAIN(TestDxfContent)
#include "tst_dxf_content.moc"
