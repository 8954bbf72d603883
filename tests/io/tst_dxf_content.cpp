// Tests of what a real CAD file holds beyond plain entities, each on a small file built here: arcs and
// ellipses whose end angle was printed with 12 digits (a full turn), blocks exploded through nested
// and arrayed INSERTs, hatch boundaries, the entities Kontur skips (counted, never refusing the
// file) and the units of files without $INSUNITS. The answers come from DXF's own rules (the
// insertion transform, the parametric ellipse), computed here independently of the reader; and the
// export of what was read (layers, colours, straight pieces) and of garment pieces (ASTM D6673).
// Over 600 lines because every case writes its own small DXF file group by group.
#include "geometry/offset.h"
#include "geometry/seams.h"
#include "io/aama.h"
#include "io/dxf.h"
#include "io/piece.h"
#include "io/seam.h"
#include "io/shapes.h"

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

// A DXF text from group codes and values.
QByteArray dxfOf(std::initializer_list<std::pair<int, const char *>> pairs)
{
    QByteArray s;
    for (const auto &[code, value] : pairs)
        s += QByteArray::number(code) + "\n" + value + "\n";
    return s;
}

// The steps of DXF's insertion transform applied one after the other to a point (the DXF Reference's
// order: minus the base point, scaled, rotated by degrees, plus the insertion point and the array
// offset along the rotated axes), written out without matrices so the reader's composition is checked.
geo::Point inserted(geo::Point p, geo::Point base, double sx, double sy, double degrees, geo::Point at,
                    geo::Point offset = geo::Point::Zero())
{
    const double a = degrees * std::numbers::pi / 180.0;
    const double x = (p.x() - base.x()) * sx + offset.x();
    const double y = (p.y() - base.y()) * sy + offset.y();
    return {at.x() + x * std::cos(a) - y * std::sin(a), at.y() + x * std::sin(a) + y * std::cos(a)};
}

bool near(const geo::Point &a, const geo::Point &b, double tolerance = 1e-12)
{
    return (a - b).norm() <= tolerance * (1 + a.norm());
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
    void nestedInserts();
    void minsertArray();
    void blockArcsScaled();
    void drawingOnlyInBlocks();
    void blockLoopsAndHugeArrays();
    void hatchPolylineBoundary();
    void hatchEdgeBoundary();
    void hatchWithSourceObjects();
    void skippedEntities();
    void unitlessUnits_data();
    void unitlessUnits();
    void layersColoursAndLinesSurviveExport();
    void aamaPiecesRoundTrip();
    void aamaMarksRoundTrip_data();
    void aamaMarksRoundTrip();
    void aamaHemComesBack_data();
    void aamaHemComesBack();
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

// A block inside a block, each INSERT with its own base point, scale, rotation and layer: every end
// point where the DXF rule puts it, and block content on layer "0" on the INSERT's layer.
void TestDxfContent::nestedInserts()
{
    const QByteArray blocks =
        dxfOf({{0, "SECTION"}, {2, "BLOCKS"}, {0, "BLOCK"}, {2, "inner"}, {8, "0"},    {10, "1"},   {20, "1"},
               {70, "0"},      {0, "LINE"},   {8, "0"},     {10, "1"},    {20, "1"},   {11, "3"},   {21, "1.5"},
               {0, "LINE"},    {8, "Seams"},  {10, "2"},    {20, "2"},    {11, "2"},   {21, "4"},   {0, "ENDBLK"},
               {0, "BLOCK"},   {2, "outer"},  {8, "0"},     {10, "-1"},   {20, "0.5"}, {70, "0"},   {0, "INSERT"},
               {8, "0"},       {2, "inner"},  {10, "10"},   {20, "0"},    {41, "2"},   {42, "0.5"}, {50, "90"},
               {0, "ENDBLK"},  {0, "ENDSEC"}});
    const QByteArray ents = dxfOf({{0, "SECTION"},
                                   {2, "ENTITIES"},
                                   {0, "INSERT"},
                                   {8, "Front"},
                                   {2, "outer"},
                                   {10, "100"},
                                   {20, "50"},
                                   {41, "1.5"},
                                   {42, "-3"},
                                   {50, "30"},
                                   {0, "ENDSEC"},
                                   {0, "EOF"}});
    const auto dxf = importDxf(blocks + ents);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(2));
    const auto place = [](geo::Point p) {
        const geo::Point inOuter = inserted(p, {1, 1}, 2, 0.5, 90, {10, 0});
        return inserted(inOuter, {-1, 0.5}, 1.5, -3, 30, {100, 50});
    };
    const geo::PiecewiseBezier &first = dxf->curves[0].curve;
    QVERIFY(near(first.segments().front().startPoint(), place({1, 1})));
    QVERIFY(near(first.segments().back().endPoint(), place({3, 1.5})));
    QCOMPARE(dxf->curves[0].name, QStringLiteral("Front"));
    const geo::PiecewiseBezier &second = dxf->curves[1].curve;
    QVERIFY(near(second.segments().front().startPoint(), place({2, 2})));
    QVERIFY(near(second.segments().back().endPoint(), place({2, 4})));
    QCOMPARE(dxf->curves[1].name, QStringLiteral("Seams"));
}

// A MINSERT of 3 columns and 2 rows, rotated: six copies, offset along the rotated axes.
void TestDxfContent::minsertArray()
{
    const QByteArray text =
        dxfOf({{0, "SECTION"}, {2, "BLOCKS"}, {0, "BLOCK"},   {2, "tick"},     {10, "0"},     {20, "0"},
               {0, "LINE"},    {8, "0"},      {10, "0"},      {20, "0"},       {11, "1"},     {21, "0"},
               {0, "ENDBLK"},  {0, "ENDSEC"}, {0, "SECTION"}, {2, "ENTITIES"}, {0, "INSERT"}, {8, "Grid"},
               {2, "tick"},    {10, "5"},     {20, "6"},      {41, "2"},       {42, "2"},     {50, "45"},
               {70, "3"},      {71, "2"},     {44, "10"},     {45, "20"},      {0, "ENDSEC"}, {0, "EOF"}});
    const auto dxf = importDxf(text);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(6));
    std::size_t k = 0;
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 3; ++column, ++k) {
            // The offset is not scaled: column · 10 and row · 20 along the rotated axes.
            const geo::Bezier &line = dxf->curves[k].curve.segments().front();
            const double a = std::numbers::pi / 4;
            const geo::Point start(5 + column * 10 * std::cos(a) - row * 20 * std::sin(a),
                                   6 + column * 10 * std::sin(a) + row * 20 * std::cos(a));
            QVERIFY2(near(line.startPoint(), start), qPrintable(QStringLiteral("%1 %2").arg(row).arg(column)));
            QVERIFY(near(line.endPoint(), start + 2 * geo::Point(std::cos(a), std::sin(a))));
            QCOMPARE(dxf->curves[k].name, QStringLiteral("Grid"));
        }
}

// A circle in a block scaled 2 × 1 is the ellipse with semi-axes 2r and r: the cubics are mapped
// with the points (a Bézier curve's affine image is the Bézier curve of the images).
void TestDxfContent::blockArcsScaled()
{
    const QByteArray text =
        dxfOf({{0, "SECTION"}, {2, "BLOCKS"},  {0, "BLOCK"},    {2, "hole"},   {10, "0"},     {20, "0"},
               {0, "CIRCLE"},  {8, "0"},       {10, "0"},       {20, "0"},     {40, "3"},     {0, "ENDBLK"},
               {0, "ENDSEC"},  {0, "SECTION"}, {2, "ENTITIES"}, {0, "INSERT"}, {2, "hole"},   {10, "7"},
               {20, "-2"},     {41, "2"},      {42, "1"},       {50, "90"},    {0, "ENDSEC"}, {0, "EOF"}});
    DxfImportOptions options;
    options.arcTolerance = 1e-7;
    const auto dxf = importDxf(text, {}, options);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
    QVERIFY(dxf->curves[0].curve.isClosed());
    QVERIFY(offEllipse(dxf->curves[0].curve, {7, -2}, 6, 3, std::numbers::pi / 2) <= 1e-6);
    QVERIFY(std::abs(dxf->curves[0].curve.length(1e-10) - ellipsePerimeter(6, 3)) < 1e-5);
}

// The whole drawing in a block (and ENTITIES before BLOCKS, as some writers put them): it imports.
void TestDxfContent::drawingOnlyInBlocks()
{
    const QByteArray ents = dxfOf(
        {{0, "SECTION"}, {2, "ENTITIES"}, {0, "INSERT"}, {8, "0"}, {2, "*U7"}, {10, "1"}, {20, "2"}, {0, "ENDSEC"}});
    const QByteArray blocks = dxfOf({{0, "SECTION"},
                                     {2, "BLOCKS"},
                                     {0, "BLOCK"},
                                     {2, "*U7"},
                                     {10, "0"},
                                     {20, "0"},
                                     {0, "LWPOLYLINE"},
                                     {8, "Pattern"},
                                     {90, "3"},
                                     {70, "1"},
                                     {10, "0"},
                                     {20, "0"},
                                     {10, "4"},
                                     {20, "0"},
                                     {10, "4"},
                                     {20, "3"},
                                     {0, "ENDBLK"},
                                     {0, "ENDSEC"},
                                     {0, "EOF"}});
    const auto dxf = importDxf(ents + blocks);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
    QVERIFY(dxf->curves[0].curve.isClosed());
    QCOMPARE(dxf->curves[0].curve.segments().front().startPoint(), geo::Point(1, 2));
    QCOMPARE(dxf->curves[0].curve.length(1e-12), 12.0);
    QCOMPARE(dxf->curves[0].name, QStringLiteral("Pattern"));
}

// A block that inserts itself stops at the depth limit (counted, not a hang); an array of a million
// copies is refused by the instance limit before it is walked.
void TestDxfContent::blockLoopsAndHugeArrays()
{
    const QByteArray loop =
        dxfOf({{0, "SECTION"},  {2, "BLOCKS"}, {0, "BLOCK"}, {2, "A"},      {10, "0"},     {20, "0"},
               {0, "LINE"},     {10, "0"},     {20, "0"},    {11, "1"},     {21, "0"},     {0, "INSERT"},
               {2, "A"},        {10, "0"},     {20, "1"},    {0, "ENDBLK"}, {0, "ENDSEC"}, {0, "SECTION"},
               {2, "ENTITIES"}, {0, "INSERT"}, {2, "A"},     {10, "0"},     {20, "0"},     {0, "INSERT"},
               {2, "missing"},  {10, "0"},     {20, "0"},    {0, "ENDSEC"}, {0, "EOF"}});
    const auto dxf = importDxf(loop);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(32)); // one line per level, 32 levels
    QCOMPARE(dxf->curves.back().curve.segments().front().startPoint(), geo::Point(0, 31));
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Other)], 2); // the 33rd level, the missing block
    const QByteArray huge =
        dxfOf({{0, "SECTION"},  {2, "BLOCKS"},   {0, "BLOCK"},   {2, "empty"},    {10, "0"},     {20, "0"},
               {0, "ENDBLK"},   {0, "ENDSEC"},   {0, "SECTION"}, {2, "ENTITIES"}, {0, "INSERT"}, {2, "empty"},
               {70, "1000000"}, {71, "1000000"}, {44, "1"},      {45, "1"},       {0, "LINE"},   {10, "0"},
               {20, "0"},       {11, "1"},       {21, "0"},      {0, "ENDSEC"},   {0, "EOF"}});
    const auto refused = importDxf(huge);
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error().code, ErrorCode::TooManyCurves);
}

// A hatch whose outline exists only as the hatch: its polyline boundary (with a bulge) is the curve.
void TestDxfContent::hatchPolylineBoundary()
{
    const QByteArray text = entities(dxfOf(
        {{0, "HATCH"}, {8, "Fill"}, {10, "0"}, {20, "0"}, {30, "0"},  {210, "0"}, {220, "0"}, {230, "1"}, {2, "SOLID"},
         {70, "1"},    {71, "0"},   {91, "1"}, {92, "2"}, {72, "1"},  {73, "1"},  {93, "4"},  {10, "0"},  {20, "0"},
         {42, "0"},    {10, "10"},  {20, "0"}, {42, "1"}, {10, "10"}, {20, "10"}, {42, "0"},  {10, "0"},  {20, "10"},
         {42, "0"},    {97, "0"},   {75, "0"}, {76, "1"}, {98, "1"},  {10, "5"},  {20, "5"}}));
    DxfImportOptions options;
    options.arcTolerance = 1e-8;
    const auto dxf = importDxf(text, {}, options);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
    const geo::PiecewiseBezier &c = dxf->curves[0].curve;
    QVERIFY(c.isClosed());
    QCOMPARE(dxf->curves[0].name, QStringLiteral("Fill"));
    // Three sides and a half circle of radius 5 bulging to the right of (10,0) → (10,10).
    QVERIFY(std::abs(c.length(1e-10) - (30 + 5 * std::numbers::pi)) < 1e-6);
    double maxX = 0;
    for (const geo::Bezier &b : c.segments())
        for (int k = 0; k <= 50; ++k)
            maxX = std::max(maxX, b.eval(k / 50.0).x());
    QVERIFY(std::abs(maxX - 15) < 1e-6);
}

// Edge boundaries: lines, a counter-clockwise and a clockwise arc (angles stored as 360° minus the
// angle), a full ellipse and a spline, each path one closed curve.
void TestDxfContent::hatchEdgeBoundary()
{
    const QByteArray text =
        entities(dxfOf({{0, "HATCH"},
                        {8, "0"},
                        {10, "0"},
                        {20, "0"},
                        {30, "0"},
                        {2, "SOLID"},
                        {70, "1"},
                        {71, "0"},
                        {91, "4"},
                        // 1: a square with a half circle on top, outwards (ccw from 0° to 180°)
                        {92, "1"},
                        {93, "4"},
                        {72, "1"},
                        {10, "0"},
                        {20, "0"},
                        {11, "10"},
                        {21, "0"},
                        {72, "1"},
                        {10, "10"},
                        {20, "0"},
                        {11, "10"},
                        {21, "10"},
                        {72, "2"},
                        {10, "5"},
                        {20, "10"},
                        {40, "5"},
                        {50, "0"},
                        {51, "180"},
                        {73, "1"},
                        {72, "1"},
                        {10, "0"},
                        {20, "10"},
                        {11, "0"},
                        {21, "0"},
                        {97, "0"},
                        // 2: the same square with the half circle inwards: clockwise from 0° to −180°, stored 0, 180
                        {92, "1"},
                        {93, "4"},
                        {72, "1"},
                        {10, "20"},
                        {20, "0"},
                        {11, "30"},
                        {21, "0"},
                        {72, "1"},
                        {10, "30"},
                        {20, "0"},
                        {11, "30"},
                        {21, "10"},
                        {72, "2"},
                        {10, "25"},
                        {20, "10"},
                        {40, "5"},
                        {50, "0"},
                        {51, "180"},
                        {73, "0"},
                        {72, "1"},
                        {10, "20"},
                        {20, "10"},
                        {11, "20"},
                        {21, "0"},
                        {97, "0"},
                        // 3: a full ellipse, semi-axes 4 and 2, centred at (50, 0)
                        {92, "1"},
                        {93, "1"},
                        {72, "3"},
                        {10, "50"},
                        {20, "0"},
                        {11, "4"},
                        {21, "0"},
                        {40, "0.5"},
                        {50, "0"},
                        {51, "360"},
                        {73, "1"},
                        {97, "0"},
                        // 4: a cubic spline arch closed by a line
                        {92, "1"},
                        {93, "2"},
                        {72, "4"},
                        {94, "3"},
                        {73, "0"},
                        {74, "0"},
                        {95, "8"},
                        {96, "4"},
                        {40, "0"},
                        {40, "0"},
                        {40, "0"},
                        {40, "0"},
                        {40, "1"},
                        {40, "1"},
                        {40, "1"},
                        {40, "1"},
                        {10, "60"},
                        {20, "0"},
                        {10, "61"},
                        {20, "2"},
                        {10, "63"},
                        {20, "2"},
                        {10, "64"},
                        {20, "0"},
                        {72, "1"},
                        {10, "64"},
                        {20, "0"},
                        {11, "60"},
                        {21, "0"},
                        {97, "0"},
                        {75, "0"},
                        {76, "1"},
                        {98, "0"}}));
    DxfImportOptions options;
    options.arcTolerance = 1e-8;
    const auto dxf = importDxf(text, {}, options);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(4));
    for (const DxfImportedCurve &c : dxf->curves) {
        QVERIFY(c.curve.isClosed());
        QCOMPARE(c.curve.segments().back().endPoint(), c.curve.segments().front().startPoint());
    }
    const auto extremeY = [](const geo::PiecewiseBezier &c, bool top) {
        double y = top ? -1e300 : 1e300;
        for (const geo::Bezier &b : c.segments())
            for (int k = 0; k <= 50; ++k)
                y = top ? std::max(y, b.eval(k / 50.0).y()) : std::min(y, b.eval(k / 50.0).y());
        return y;
    };
    const double pi = std::numbers::pi;
    QVERIFY(std::abs(dxf->curves[0].curve.length(1e-10) - (30 + 5 * pi)) < 1e-6);
    QVERIFY(std::abs(extremeY(dxf->curves[0].curve, true) - 15) < 1e-6);
    QVERIFY(std::abs(dxf->curves[1].curve.length(1e-10) - (30 + 5 * pi)) < 1e-6);
    QVERIFY(std::abs(extremeY(dxf->curves[1].curve, true) - 10) < 1e-9); // the arc dips to y = 5 inside
    double toDip = 1e300;                                                // the clockwise arc passes through (25, 5)
    for (const geo::Bezier &b : dxf->curves[1].curve.segments())
        for (int k = 0; k <= 400; ++k)
            toDip = std::min(toDip, (b.eval(k / 400.0) - geo::Point(25, 5)).norm());
    QVERIFY2(toDip < 1e-3, qPrintable(QString::number(toDip)));
    QVERIFY(offEllipse(dxf->curves[2].curve, {50, 0}, 4, 2, 0) <= 1e-7);
    QVERIFY(std::abs(dxf->curves[2].curve.length(1e-10) - ellipsePerimeter(4, 2)) < 1e-6);
    const geo::Bezier &arch = dxf->curves[3].curve.segments().front();
    QCOMPARE(arch.controlPoints(), (std::vector<geo::Point>{{60, 0}, {61, 2}, {63, 2}, {64, 0}}));
    QCOMPARE(dxf->curves[3].curve.segmentCount(), 2);
}

// A boundary path that names its source objects (97 > 0) is the outline of entities that are read
// as themselves: it is not read a second time.
void TestDxfContent::hatchWithSourceObjects()
{
    const QByteArray text = entities(dxfOf(
        {{0, "CIRCLE"}, {5, "2A"}, {10, "0"},   {20, "0"}, {40, "1"}, {0, "HATCH"}, {10, "0"}, {20, "0"}, {30, "0"},
         {2, "SOLID"},  {70, "1"}, {71, "1"},   {91, "1"}, {92, "1"}, {93, "1"},    {72, "2"}, {10, "0"}, {20, "0"},
         {40, "1"},     {50, "0"}, {51, "360"}, {73, "1"}, {97, "1"}, {330, "2A"},  {75, "0"}, {76, "1"}, {98, "0"}}));
    const auto dxf = importDxf(text);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
}

// Entities Kontur does not draw are counted by kind and the rest of the file is read.
void TestDxfContent::skippedEntities()
{
    const QByteArray text = entities(dxfOf(
        {{0, "TEXT"},   {10, "0"},     {20, "0"},       {40, "2.5"},   {1, "Front"},  {0, "MTEXT"},     {10, "0"},
         {20, "0"},     {40, "2.5"},   {1, "Cut 2"},    {0, "TEXT"},   {10, "0"},     {20, "0"},        {1, "odd"},
         {210, "0.6"},  {220, "0"},    {230, "0.8"},    {0, "3DFACE"}, {10, "0"},     {20, "0"},        {30, "0"},
         {11, "1"},     {21, "0"},     {31, "0"},       {12, "1"},     {22, "1"},     {32, "1"},        {13, "1"},
         {23, "1"},     {33, "1"},     {0, "POLYLINE"}, {66, "1"},     {70, "64"},    {71, "3"},        {72, "1"},
         {0, "VERTEX"}, {10, "0"},     {20, "0"},       {70, "192"},   {0, "VERTEX"}, {10, "1"},        {20, "0"},
         {70, "192"},   {0, "SEQEND"}, {0, "SPLINE"},   {70, "8"},     {71, "3"},     {74, "3"},        {11, "0"},
         {21, "0"},     {11, "1"},     {21, "1"},       {11, "2"},     {21, "0"},     {0, "CIRCLE"},    {10, "0"},
         {20, "0"},     {40, "1"},     {210, "1"},      {220, "0"},    {230, "0"},    {0, "DIMENSION"}, {2, "*D1"},
         {10, "0"},     {20, "0"},     {0, "POINT"},    {10, "3"},     {20, "3"},     {0, "LINE"},      {10, "0"},
         {20, "0"},     {11, "5"},     {21, "0"}}));
    const auto dxf = importDxf(text);
    QVERIFY2(dxf.ok(), qPrintable(errorText(dxf)));
    QCOMPARE(dxf->curves.size(), std::size_t(1));
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Text)], 2);
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Solid3D)], 4); // face, mesh, odd text, circle
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Spline)], 1);
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Dimension)], 1);
    QCOMPARE(dxf->skipped[static_cast<std::size_t>(DxfSkipped::Other)], 1);
    QCOMPARE(skippedSummary(*dxf), QStringLiteral("2 texts, 1 dimension, 4 3D objects, 1 spline given only by fit "
                                                  "points or weights, 1 other entity"));
    // Nothing drawable at all: refused, saying what was skipped.
    const auto none = importDxf(entities(dxfOf({{0, "TEXT"}, {10, "0"}, {20, "0"}, {1, "x"}})));
    QVERIFY(!none.ok());
    QCOMPARE(none.error().code, ErrorCode::NoPaths);
    QVERIFY2(none.error().message.contains(QStringLiteral("skipped: 1 text")), qPrintable(none.error().message));
}

// A file that names no units takes the units the user chose (the app asks, kontur-cli --units); a
// HEADER that closes early keeps the units it had read.
void TestDxfContent::unitlessUnits_data()
{
    QTest::addColumn<QByteArray>("dxf");
    QTest::addColumn<QString>("chosen");
    QTest::addColumn<QString>("units");
    QTest::addColumn<bool>("declared");
    QTest::addColumn<double>("x"); // the line's end, in `units`
    const QByteArray line = entities(dxfOf({{0, "LINE"}, {10, "0"}, {20, "0"}, {11, "2.5"}, {21, "0"}}));
    const QByteArray header = dxfOf({{0, "SECTION"}, {2, "HEADER"}, {9, "$ACADVER"}, {1, "AC1015"}});
    QTest::addRow("no header, mm chosen") << line << "mm"
                                          << "mm" << false << 2.5;
    QTest::addRow("no header, nothing chosen") << line << "px"
                                               << "px" << false << 2.5;
    QTest::addRow("unitless 0, in chosen")
        << header + dxfOf({{9, "$INSUNITS"}, {70, "0"}, {0, "ENDSEC"}}) + line << "in"
        << "in" << false << 2.5;
    QTest::addRow("metres declared") << header + dxfOf({{9, "$INSUNITS"}, {70, "6"}, {0, "ENDSEC"}}) + line << "in"
                                     << "mm" << true << 2500.0;
    QTest::addRow("header closing early keeps cm") << header + dxfOf({{9, "$INSUNITS"}, {70, "5"}}) + line << "mm"
                                                   << "cm" << true << 2.5;
    QTest::addRow("header closing early keeps feet")
        << header + dxfOf({{9, "$INSUNITS"}, {70, "2"}, {9, "$MEASUREMENT"}, {70, "0"}}) + line << "mm"
        << "in" << true << 30.0;
    // dxflib (LibreCAD's support/library/misc/a3.dxf) closes the HEADER after $HANDSEED and writes the
    // rest of it, $INSUNITS 4 among them, after that ENDSEC and before a second one: millimetres, as
    // ezdxf reads it, not the chosen units.
    const QByteArray dxflib = dxfOf({{999, "dxflib 2.0.1.3"},
                                     {0, "SECTION"},
                                     {2, "HEADER"},
                                     {9, "$ACADVER"},
                                     {1, "AC1015"},
                                     {9, "$HANDSEED"},
                                     {5, "FFFF"},
                                     {0, "ENDSEC"},
                                     {9, "$EXTMIN"},
                                     {10, "0.0"},
                                     {20, "0.0"},
                                     {30, "0.0"},
                                     {9, "$INSUNITS"},
                                     {70, "4"},
                                     {9, "$DIMAUNIT"},
                                     {70, "0"},
                                     {0, "ENDSEC"}});
    QTest::addRow("dxflib's early ENDSEC, $INSUNITS after it") << dxflib + line << "px"
                                                               << "mm" << true << 2.5;
    QTest::addRow("dxflib's early ENDSEC, inches after it") << dxfOf({{0, "SECTION"},
                                                                      {2, "HEADER"},
                                                                      {9, "$HANDSEED"},
                                                                      {5, "FFFF"},
                                                                      {0, "ENDSEC"},
                                                                      {9, "$INSUNITS"},
                                                                      {70, "1"},
                                                                      {0, "ENDSEC"}}) +
                                                                   line
                                                            << "mm"
                                                            << "in" << true << 2.5;
    // An ENDSEC followed by the next section ends the HEADER: units given later are no header's.
    QTest::addRow("ENDSEC then a section")
        << header + dxfOf({{0, "ENDSEC"}, {0, "SECTION"}, {2, "TABLES"}, {0, "ENDSEC"}}) + line << "cm"
        << "cm" << false << 2.5;
}

void TestDxfContent::unitlessUnits()
{
    QFETCH(QByteArray, dxf);
    QFETCH(QString, chosen);
    QFETCH(QString, units);
    QFETCH(bool, declared);
    QFETCH(double, x);
    DxfImportOptions options;
    options.unitlessUnits = chosen;
    const auto read = importDxf(dxf, {}, options);
    QVERIFY2(read.ok(), qPrintable(errorText(read)));
    QCOMPARE(read->units, units);
    QCOMPARE(read->declaredUnits, declared);
    QCOMPARE(read->curves.size(), std::size_t(1));
    QCOMPARE(read->curves[0].curve.segments().front().endPoint().x(), x);
}

// Import → the records the app keeps (lines elevated to cubics) → export: the curves stay on their
// source layers (one LAYER each, not one per curve), keep their colours (true colour, ACI, by layer,
// by block) and their straight pieces are written as LINE and LWPOLYLINE again.
void TestDxfContent::layersColoursAndLinesSurviveExport()
{
    QByteArray text = dxfOf(
        {{0, "SECTION"},   {2, "TABLES"}, {0, "TABLE"},      {2, "LAYER"},   {70, "3"},     {0, "LAYER"}, {2, "Walls"},
         {70, "0"},        {62, "1"},     {6, "CONTINUOUS"}, {0, "LAYER"},   {2, "Doors"},  {70, "0"},    {62, "-5"},
         {420, "3355443"}, {0, "ENDTAB"}, {0, "ENDSEC"},     {0, "SECTION"}, {2, "BLOCKS"}, {0, "BLOCK"}, {2, "B"},
         {10, "0"},        {20, "0"},     {0, "LINE"},       {8, "0"},       {62, "0"},     {10, "0"},    {20, "0"},
         {11, "0"},        {21, "9"},     {0, "ENDBLK"},     {0, "ENDSEC"}});
    text += entities(
        dxfOf({{0, "LINE"},  {8, "Walls"},  {10, "0"},    {20, "0"},  {11, "10"}, {21, "0"},         {0, "LINE"},
               {8, "walls"}, {10, "10"},    {20, "0"},    {11, "10"}, {21, "10"}, {0, "LINE"},       {8, "Walls"},
               {62, "3"},    {10, "10"},    {20, "10"},   {11, "0"},  {21, "10"}, {0, "LWPOLYLINE"}, {8, "Doors"},
               {90, "3"},    {70, "1"},     {10, "1"},    {20, "1"},  {10, "3"},  {20, "1"},         {10, "3"},
               {20, "4"},    {0, "ARC"},    {8, "Walls"}, {10, "5"},  {20, "5"},  {40, "2"},         {50, "0"},
               {51, "90"},   {0, "INSERT"}, {8, "Frame"}, {62, "4"},  {2, "B"},   {10, "20"},        {20, "0"}}));
    const auto first = importDxf(text);
    QVERIFY2(first.ok(), qPrintable(errorText(first)));
    QCOMPARE(first->curves.size(), std::size_t(6));
    const QStringList names{QStringLiteral("Walls"), QStringLiteral("walls"), QStringLiteral("Walls"),
                            QStringLiteral("Doors"), QStringLiteral("Walls"), QStringLiteral("Frame")};
    // By layer red (ACI 1), ACI 3 green, the layer's true colour 0x333333, by block cyan (ACI 4).
    const QStringList colours{QStringLiteral("#ff0000"), QStringLiteral("#ff0000"), QStringLiteral("#00ff00"),
                              QStringLiteral("#333333"), QStringLiteral("#ff0000"), QStringLiteral("#00ffff")};
    std::vector<DxfCurve> drawing;
    for (std::size_t i = 0; i < first->curves.size(); ++i) {
        const DxfImportedCurve &c = first->curves[i];
        QCOMPARE(c.name, names[static_cast<qsizetype>(i)]);
        QCOMPARE(c.color, colours[static_cast<qsizetype>(i)]);
        // What the app keeps: a composite curve, its lines elevated to cubics.
        auto record = recordFromDxfCurve(c.curve);
        QVERIFY(record.ok());
        auto shape = curveShape(*record);
        QVERIFY(shape.ok());
        QCOMPARE(shape->segments().front().degree(), 3);
        drawing.push_back({c.name, c.color, *shape});
    }
    const QByteArray written = exportDxf(drawing);
    QStringList layers, types;
    const QList<QByteArray> lines = written.split('\n');
    for (qsizetype i = 0; i + 3 < lines.size(); i += 2) {
        if (lines[i].trimmed() == "0" && lines[i + 1].trimmed() == "LAYER") {
            for (qsizetype k = i + 2; k + 1 < lines.size() && lines[k].trimmed() != "0"; k += 2)
                if (lines[k].trimmed() == "2")
                    layers << QString::fromLatin1(lines[k + 1].trimmed());
        }
        if (lines[i].trimmed() == "0" && (lines[i + 1].trimmed() == "LINE" || lines[i + 1].trimmed() == "LWPOLYLINE" ||
                                          lines[i + 1].trimmed() == "SPLINE"))
            types << QString::fromLatin1(lines[i + 1].trimmed());
    }
    QCOMPARE(layers, (QStringList{QStringLiteral("0"), QStringLiteral("Walls"), QStringLiteral("Doors"),
                                  QStringLiteral("Frame")}));
    QCOMPARE(types, (QStringList{QStringLiteral("LINE"), QStringLiteral("LINE"), QStringLiteral("LINE"),
                                 QStringLiteral("LWPOLYLINE"), QStringLiteral("SPLINE"), QStringLiteral("LINE")}));
    const auto again = importDxf(written);
    QVERIFY2(again.ok(), qPrintable(errorText(again)));
    QCOMPARE(again->curves.size(), std::size_t(6));
    for (std::size_t i = 0; i < again->curves.size(); ++i) {
        QCOMPARE(again->curves[i].color, colours[static_cast<qsizetype>(i)]);
        QCOMPARE(again->curves[i].name.toCaseFolded(), names[static_cast<qsizetype>(i)].toCaseFolded());
        QCOMPARE(again->curves[i].curve.segments().front().startPoint(),
                 first->curves[i].curve.segments().front().startPoint());
    }
    QVERIFY(again->curves[3].curve.isClosed());
    QCOMPARE(again->curves[3].curve.segmentCount(), 3);
}

// ASTM D6673: a piece with its seam allowance, an internal line and a piece without allowance become
// one block each (cut line on layer 1, sew line 14, internal line 8, the piece's name as text; no
// grain line, since these pieces have none of their own), inserted at the origin; read back, every curve names its
// piece and layer, and in the spline flavour the cut and sew lines are the document's curves bit for bit.
void TestDxfContent::aamaPiecesRoundTrip()
{
    // A closed composite curve through four corners with straight handles (3n control points), which
    // the writer draws as a polyline (the same segments, the same parameters: handles at thirds).
    const auto square = [](double x0, double y0, double size, const QString &name) {
        CurveRecord r;
        r.kind = QStringLiteral("composite");
        r.name = name;
        r.closed = true;
        const std::vector<geo::Point> corners{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
        for (std::size_t k = 0; k < 4; ++k) {
            const geo::Point a = corners[k], b = corners[(k + 1) % 4];
            r.points.insert(r.points.end(), {a, a + (b - a) / 3, a + (b - a) * 2 / 3});
            r.nodeTypes.push_back(QStringLiteral("corner"));
        }
        return r;
    };
    std::vector<CurveRecord> records{square(0, 0, 100, QStringLiteral("Front")),
                                     square(-10, -10, 120, QStringLiteral("Front allowance")),
                                     square(300, 0, 50, QStringLiteral("Back")), square(500, 0, 10, QString())};
    SeamSettings seam;
    seam.source = 0;
    seam.options = defaultSeamOptions(QStringLiteral("mm"));
    records[1].settings.insert(QLatin1String(kSeamKey), seamToJson(seam));
    records[3].visible = false; // hidden: not a piece
    CurveRecord dart;
    dart.kind = QStringLiteral("bezier");
    dart.name = QStringLiteral("Dart");
    dart.points = {{40, 20}, {50, 60}, {60, 20}};
    records.push_back(dart);
    const auto pieces = aamaPieces(records);
    QVERIFY(pieces.ok());
    QCOMPARE(pieces->size(), std::size_t(2));
    const AamaPiece &front = pieces->front();
    QCOMPARE(front.name, QStringLiteral("Front"));
    QCOMPARE(front.cut.boundingBox().min(), geo::Point(-10, -10));
    QCOMPARE(front.sew.boundingBox().max(), geo::Point(100, 100));
    QCOMPARE(front.internal.size(), std::size_t(1));
    QVERIFY(pieces->back().sew.isEmpty());

    DxfExportOptions options;
    options.units = QStringLiteral("mm");
    const QByteArray dxf = exportAamaDxf(*pieces, options);
    QVERIFY(dxf.contains("\n  0\nINSERT\n"));
    QVERIFY(dxf.contains("Piece Name: Front"));
    const auto back = importDxf(dxf);
    QVERIFY2(back.ok(), qPrintable(errorText(back)));
    QCOMPARE(back->units, QStringLiteral("mm"));
    QCOMPARE(back->skipped[static_cast<std::size_t>(DxfSkipped::Text)], 0); // name and quantity: the pieces'
    QCOMPARE(back->pieces.size(), std::size_t(2));
    QCOMPARE(back->pieces[0].quantity, 1);
    QVERIFY(!dxf.contains("\n  8\n7\n")); // no entity on layer 7
    QCOMPARE(piecesWithoutGrainline(*pieces), (std::vector<QString>{QStringLiteral("Front"), QStringLiteral("Back")}));
    QStringList names;
    for (const DxfImportedCurve &c : back->curves)
        names << c.name;
    QCOMPARE(names, (QStringList{QStringLiteral("Front cut line"), QStringLiteral("Front sew line"),
                                 QStringLiteral("Front internal line"), QStringLiteral("Back cut line")}));
    QCOMPARE(back->curves[1].aamaLayer, 14);
    QCOMPARE(back->curves[1].piece, QStringLiteral("Front"));
    // The spline flavour is exact: the cut line is the allowance, the sew line the piece, the
    // internal line the dart, point for point.
    for (const auto &[k, shape] : {std::pair{0, &front.cut}, {1, &front.sew}, {2, &front.internal.front()}}) {
        const geo::PiecewiseBezier &got = back->curves[static_cast<std::size_t>(k)].curve;
        QCOMPARE(got.segmentCount(), shape->segmentCount());
        for (int i = 0; i < got.segmentCount(); ++i)
            for (int t = 0; t <= 8; ++t)
                QVERIFY((got.segments()[static_cast<std::size_t>(i)].eval(t / 8.0) -
                         shape->segments()[static_cast<std::size_t>(i)].eval(t / 8.0))
                            .norm() <= 1e-12);
    }
    for (const DxfImportedCurve &c : back->curves)
        QVERIFY(c.aamaLayer != 7); // no grain line the pieces do not have
    // A file whose blocks are not pieces keeps its layers' names.
    const auto plain = importDxf(entities(dxfOf({{0, "LINE"}, {8, "1"}, {10, "0"}, {20, "0"}, {11, "1"}, {21, "0"}})));
    QVERIFY(plain.ok());
    QCOMPARE(plain->curves.front().name, QStringLiteral("1"));
}

void TestDxfContent::aamaMarksRoundTrip_data()
{
    QTest::addColumn<bool>("polylines");
    QTest::addColumn<bool>("allowance");
    QTest::addRow("splines, allowance") << false << true;
    QTest::addRow("polylines, allowance") << true << true;
    QTest::addRow("splines, no allowance") << false << false;
}

// Kontur → AAMA → Kontur keeps every mark of a piece traced at an angle (a rectangle turned 30°):
// size, quantity, material, fold, the grainline, notches of each kind and angle at their places
// along the seam, drill holes; the cut line comes back as the piece's allowance of the same width.
void TestDxfContent::aamaMarksRoundTrip()
{
    QFETCH(bool, polylines);
    QFETCH(bool, allowance);
    const double a = std::numbers::pi / 6;
    const auto turned = [&](double x, double y) {
        return geo::Point(x * std::cos(a) - y * std::sin(a) + 50, x * std::sin(a) + y * std::cos(a) + 20);
    };
    CurveRecord piece;
    piece.kind = QStringLiteral("composite");
    piece.name = QStringLiteral("Bodice front");
    piece.closed = true;
    const std::vector<geo::Point> corners{turned(0, 0), turned(200, 0), turned(200, 400), turned(0, 400)};
    for (std::size_t k = 0; k < 4; ++k) {
        const geo::Point p = corners[k], q = corners[(k + 1) % 4];
        piece.points.insert(piece.points.end(), {p, p + (q - p) / 3, p + (q - p) * 2 / 3});
        piece.nodeTypes.push_back(QStringLiteral("corner"));
    }
    PieceMarks marks;
    marks.size = QStringLiteral("38");
    marks.quantity = 2;
    marks.material = QStringLiteral("Wool");
    marks.fold = Segment{corners[3], corners[0]};
    marks.grainline = Segment{turned(100, 50), turned(100, 350)};
    marks.notches = {{80.0, NotchKind::Slit, 0.0}, {250.5, NotchKind::V, 0.0}, {700.25, NotchKind::Castle, 20.0}};
    marks.drillHoles = {turned(60, 300), turned(140, 300)};
    // With an allowance, the hem (the first seam) is 30 mm wide, the others the allowance's 10.
    if (allowance)
        marks.seamWidths = {30.0};
    piece.settings.insert(QLatin1String(kPieceKey), pieceToJson(marks));
    std::vector<CurveRecord> records{piece};
    if (allowance) {
        // The allowance as Kontur computes it: the rectangle 30 mm out at the hem and 10 mm elsewhere,
        // mitred corners.
        CurveRecord cut = piece;
        cut.name = QStringLiteral("Bodice front allowance");
        cut.settings = {};
        const std::vector<geo::Point> out{turned(-10, -30), turned(210, -30), turned(210, 410), turned(-10, 410)};
        cut.points.clear();
        for (std::size_t k = 0; k < 4; ++k) {
            const geo::Point p = out[k], q = out[(k + 1) % 4];
            cut.points.insert(cut.points.end(), {p, p + (q - p) / 3, p + (q - p) * 2 / 3});
        }
        SeamSettings seam;
        seam.source = 0;
        seam.options = defaultSeamOptions(QStringLiteral("mm"));
        cut.settings.insert(QLatin1String(kSeamKey), seamToJson(seam));
        records.push_back(cut);
    }
    const auto pieces = aamaPieces(records);
    QVERIFY(pieces.ok());
    QCOMPARE(pieces->size(), std::size_t(1));
    QVERIFY(piecesWithoutGrainline(*pieces).empty());
    DxfExportOptions options;
    options.units = QStringLiteral("mm");
    options.flavour = polylines ? DxfFlavour::Polyline : DxfFlavour::Spline;
    const QByteArray dxf = exportAamaDxf(*pieces, options);
    for (const char *text :
         {"Piece Name: Bodice front", "Size: 38", "Quantity: 2", "Material: Wool", "Annotation: On fold"})
        QVERIFY2(dxf.contains(text), text);
    const auto back = importDxf(dxf);
    QVERIFY2(back.ok(), qPrintable(errorText(back)));
    QCOMPARE(back->skipped[static_cast<std::size_t>(DxfSkipped::Text)], 0);
    QCOMPARE(back->skipped[static_cast<std::size_t>(DxfSkipped::Other)], 0);
    const auto got = dxfRecords(*back, QStringLiteral("bodice.dxf"));
    QVERIFY2(got.ok(), qPrintable(got.ok() ? QString() : got.error().toString()));
    QCOMPARE(got->size(), records.size()); // the piece (and its allowance); no grain, fold or notch curves
    const CurveRecord &own = got->front();
    QCOMPARE(own.name, QStringLiteral("Bodice front"));
    const auto read = pieceFromSettings(own.settings);
    QVERIFY(read.has_value());
    QCOMPARE(read->size, marks.size);
    QCOMPARE(read->quantity, marks.quantity);
    QCOMPARE(read->material, marks.material);
    const double tol = 1e-9;
    const auto near = [&](const geo::Point &p, const geo::Point &q) { return (p - q).norm() <= tol; };
    QVERIFY(read->grainline && near(read->grainline->a, marks.grainline->a) &&
            near(read->grainline->b, marks.grainline->b));
    QVERIFY(read->fold && near(read->fold->a, marks.fold->a) && near(read->fold->b, marks.fold->b));
    QCOMPARE(read->notches.size(), marks.notches.size());
    for (std::size_t i = 0; i < marks.notches.size(); ++i) {
        QCOMPARE(read->notches[i].kind, marks.notches[i].kind);
        QVERIFY2(std::abs(read->notches[i].position - marks.notches[i].position) <= 1e-6,
                 qPrintable(QString::number(read->notches[i].position, 'g', 17)));
        QVERIFY2(std::abs(read->notches[i].angle - marks.notches[i].angle) <= 1e-6,
                 qPrintable(QString::number(read->notches[i].angle, 'g', 17)));
    }
    QCOMPARE(read->drillHoles.size(), marks.drillHoles.size());
    for (std::size_t i = 0; i < marks.drillHoles.size(); ++i)
        QVERIFY(near(read->drillHoles[i], marks.drillHoles[i]));
    if (allowance) {
        const auto seam = seamFromSettings(got->back().settings, static_cast<int>(got->size()));
        QVERIFY(seam.has_value());
        QCOMPARE(seam->source, 0);
        QVERIFY2(std::abs(seam->options.distance - 10.0) <= 1e-6, qPrintable(QString::number(seam->options.distance)));
        // The cut line's distance per seam gives the hem's width back.
        QCOMPARE(read->seamWidths.size(), std::size_t(1));
        QVERIFY(read->seamWidths[0] && std::abs(*read->seamWidths[0] - 30.0) <= 1e-6);
        QVERIFY(!pieceFromSettings(got->back().settings).has_value());
    }
    // A piece without a grainline has none in the file, and the export says which.
    records.front().settings.insert(QLatin1String(kPieceKey), pieceToJson(PieceMarks{}));
    const auto bare = aamaPieces(records);
    QVERIFY(bare.ok());
    QCOMPARE(piecesWithoutGrainline(*bare), std::vector<QString>{QStringLiteral("Bodice front")});
    QVERIFY(!exportAamaDxf(*bare, options).contains("\n  8\n7\n"));
}

// A flared piece (a trapezoid, the hem 40 mm wider than the top and curved) whose hem's allowance is 30 mm with
// turned-back corners and the sides' 10 mm: Kontur → AAMA → Kontur gives the hem's width (as typed) and
// its turned-back corners back (mitred corners there would lie up to several millimetres off the cut
// line, so the hem is found, not assumed).
void TestDxfContent::aamaHemComesBack_data()
{
    QTest::addColumn<bool>("polylines");
    QTest::addRow("splines") << false;
    QTest::addRow("polylines") << true;
}

void TestDxfContent::aamaHemComesBack()
{
    CurveRecord piece;
    piece.kind = QStringLiteral("composite");
    piece.name = QStringLiteral("Skirt");
    piece.closed = true;
    const std::vector<geo::Point> corners{{0, 0}, {240, 0}, {220, 300}, {20, 300}};
    std::vector<geo::Point> control;
    for (std::size_t k = 0; k < 4; ++k) {
        const geo::Point p = corners[k], q = corners[(k + 1) % 4];
        // The hem curves down by 22.5 mm in its middle, as a flared skirt's does.
        const std::vector<geo::Point> segment = k == 0
                                                    ? std::vector<geo::Point>{p, {80, -30}, {160, -30}}
                                                    : std::vector<geo::Point>{p, p + (q - p) / 3, p + (q - p) * 2 / 3};
        piece.points.insert(piece.points.end(), segment.begin(), segment.end());
        control.insert(control.end(), segment.begin(), segment.end());
        piece.nodeTypes.push_back(QStringLiteral("corner"));
    }
    control.push_back(corners.front());
    PieceMarks marks;
    marks.grainline = Segment{{120, 50}, {120, 250}};
    marks.seamWidths = {30.0};
    marks.hems = {0};
    piece.settings.insert(QLatin1String(kPieceKey), pieceToJson(marks));
    std::vector<geo::Bezier> segments;
    for (std::size_t i = 0; i + 3 < control.size(); i += 3)
        segments.emplace_back(std::vector<geo::Point>(control.begin() + static_cast<std::ptrdiff_t>(i),
                                                      control.begin() + static_cast<std::ptrdiff_t>(i) + 4));
    const geo::PiecewiseBezier own(segments, true);
    geo::OffsetOptions options = defaultSeamOptions(QStringLiteral("mm"));
    options.segmentDistances = geo::segmentDistancesOf(own, marks.seamWidths, options.distance);
    options.hems = geo::segmentHemsOf(own, marks.hems);
    const auto made = geo::offsetCurve(own, options);
    QVERIFY(made.ok());
    CurveRecord cut;
    cut.kind = QStringLiteral("composite");
    cut.name = QStringLiteral("Skirt allowance");
    cut.closed = true;
    for (const geo::Bezier &b : made->curve.segments()) {
        const auto &c = b.controlPoints();
        cut.points.insert(cut.points.end(), c.begin(), c.end() - 1);
        cut.nodeTypes.push_back(QStringLiteral("corner"));
    }
    SeamSettings seam;
    seam.source = 0;
    seam.options = defaultSeamOptions(QStringLiteral("mm"));
    cut.settings.insert(QLatin1String(kSeamKey), seamToJson(seam));
    const auto pieces = aamaPieces({piece, cut});
    QVERIFY(pieces.ok());
    QFETCH(bool, polylines);
    DxfExportOptions dxfOptions;
    dxfOptions.units = QStringLiteral("mm");
    dxfOptions.flavour = polylines ? DxfFlavour::Polyline : DxfFlavour::Spline;
    const auto back = importDxf(exportAamaDxf(*pieces, dxfOptions));
    QVERIFY(back.ok());
    const auto got = dxfRecords(*back, QStringLiteral("skirt.dxf"));
    QVERIFY(got.ok());
    QCOMPARE(got->size(), std::size_t(2));
    const auto read = pieceFromSettings(got->front().settings);
    QVERIFY(read.has_value());
    QCOMPARE(read->seamWidths.size(), std::size_t(1));
    QCOMPARE(read->seamWidths[0].value_or(0), 30.0); // as typed, not 29.998 as measured
    QCOMPARE(read->hems, std::vector<int>{0});
    // The cut line is the allowance the piece's widths make, linked, with polylines too: their chord
    // at each corner is a hundredth of the curve, so it leaves along the curve's tangent (a chord
    // within the tolerance turned the hem's corners by up to 0.9 mm, and the cut line stayed apart).
    QVERIFY(seamFromSettings(got->back().settings, 2).has_value());
}

QTEST_GUILESS_MAIN(TestDxfContent)
#include "tst_dxf_content.moc"
