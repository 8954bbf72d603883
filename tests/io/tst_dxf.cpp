// Tests of DXF: Kontur → DXF → Kontur bit for bit in the SPLINE flavour (random curves of degrees 1–5
// and every record kind), the polyline flavour within its tolerance, $INSUNITS both ways, general
// B-splines split into Bézier pieces (checked against de Boor's evaluation), arcs, circles, ellipses
// and bulges within the arc tolerance, the records imported curves become, malformed files answered
// with an error code and the line, never a crash; the exported drawing's AutoCAD 2000 structure
// (sections, tables, blocks, objects, handles and owners) and the curves' layers (names, code pages,
// colours) read back. Over 600 lines because each of these needs its own hand-made files or oracle.
#include "geometry/polyline.h"
#include "io/dxf.h"
#include "io/shapes.h"
#include "iotestutil.h"

#include <QDir>
#include <QFile>
#include <QMap>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace kontur;
using namespace kontur::io;

namespace {

// The distance from p to the polyline through pts.
double distanceToPolyline(const geo::Point &p, const std::vector<geo::Point> &pts)
{
    return (geo::nearestOnPolyline(pts, p, false).point - p).norm();
}

// The B-spline's point at u by the Cox–de Boor recurrence of its basis functions (de Boor 1972),
// independent of the reader's blossoming.
geo::Point deBoorPoint(const std::vector<double> &U, const std::vector<geo::Point> &P, int p, double u)
{
    const std::size_t n = P.size();
    std::vector<double> N(U.size() - 1, 0.0);
    // The span of u (the last non-empty one for u at the domain's end).
    for (std::size_t i = 0; i + 1 < U.size(); ++i)
        if (U[i] <= u && u < U[i + 1])
            N[i] = 1.0;
    if (u >= U[U.size() - 1 - static_cast<std::size_t>(p)])
        for (std::size_t i = U.size() - 2 - static_cast<std::size_t>(p);; --i)
            if (U[i] < U[i + 1]) {
                std::fill(N.begin(), N.end(), 0.0);
                N[i] = 1.0;
                break;
            }
    for (int k = 1; k <= p; ++k)
        for (std::size_t i = 0; i + static_cast<std::size_t>(k) + 1 < U.size(); ++i) {
            const std::size_t ik = i + static_cast<std::size_t>(k);
            double v = 0.0;
            if (U[ik] > U[i])
                v += (u - U[i]) / (U[ik] - U[i]) * N[i];
            if (U[ik + 1] > U[i + 1])
                v += (U[ik + 1] - u) / (U[ik + 1] - U[i + 1]) * N[i + 1];
            N[i] = v;
        }
    geo::Point out = geo::Point::Zero();
    for (std::size_t i = 0; i < n; ++i)
        out += N[i] * P[i];
    return out;
}

QByteArray splineDxf(int degree, const std::vector<double> &knots, const std::vector<geo::Point> &control,
                     const char *extra = "")
{
    QByteArray s = "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n8\n0\n";
    s += extra;
    s += "71\n" + QByteArray::number(degree) + "\n";
    for (double k : knots)
        s += "40\n" + QByteArray::number(k, 'g', 17) + "\n";
    for (const geo::Point &p : control)
        s += "10\n" + QByteArray::number(p.x(), 'g', 17) + "\n20\n" + QByteArray::number(p.y(), 'g', 17) + "\n30\n0\n";
    s += "0\nENDSEC\n0\nEOF\n";
    return s;
}

// The pairs of a DXF file Kontur wrote (group code, value).
std::vector<std::pair<int, QByteArray>> pairsOf(const QByteArray &dxf)
{
    const QList<QByteArray> lines = dxf.split('\n');
    std::vector<std::pair<int, QByteArray>> out;
    for (qsizetype i = 0; i + 1 < lines.size(); i += 2)
        out.emplace_back(lines[i].trimmed().toInt(), lines[i + 1]);
    return out;
}

} // namespace

class TestDxf final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void exportImportExact_data();
    void exportImportExact();
    void polylineWithinTolerance();
    void units_data();
    void units();
    void generalBSplines_data();
    void generalBSplines();
    void arcs_data();
    void arcs();
    void records();
    void malformed_data();
    void malformed();
    void limits();
    void structure_data();
    void structure();
    void layers();
};

void TestDxf::exportImportExact_data()
{
    test::addSeedRows(25);
}

// Random curves of one degree each (1–5), open and closed, and the shapes of every record kind: the
// SPLINE flavour's control points are the curves' own, so they come back bit for bit.
void TestDxf::exportImportExact()
{
    QFETCH(int, seed);
    test::RandomDocuments random(static_cast<std::uint32_t>(seed));
    std::vector<DxfCurve> curves;
    for (int c = random.integer(1, 5); c > 0; --c) {
        const int degree = random.integer(1, 5);
        std::vector<geo::Bezier> segs;
        geo::Point cur = random.point();
        const geo::Point start = cur;
        const bool closed = random.coin();
        const int count = random.integer(closed ? 3 : 1, 6);
        for (int s = 0; s < count; ++s) {
            std::vector<geo::Point> pts{cur};
            for (int k = 1; k <= degree; ++k)
                pts.push_back(closed && s + 1 == count && k == degree ? start : random.point());
            cur = pts.back();
            segs.emplace_back(std::move(pts));
        }
        curves.push_back({QString(), QString(), geo::PiecewiseBezier(std::move(segs), closed)});
    }
    for (const QString &kind : knownKinds()) {
        CurveRecord r = random.curve(kind);
        for (geo::Point &p : r.points)
            p = geo::Point(random.integer(-1000, 1000) * 0.01, random.integer(-1000, 1000) * 0.013);
        if (kind == QLatin1String("function-spline"))
            for (std::size_t i = 0; i < r.points.size(); ++i)
                r.points[i].x() = static_cast<double>(i) - 3.5;
        auto shape = curveShape(r);
        QVERIFY2(shape.ok(), qPrintable(kind));
        curves.push_back({kind, QString(), *shape});
    }
    const QByteArray dxf = exportDxf(curves, {});
    auto back = importDxf(dxf);
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    QCOMPARE(back->curves.size(), curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const geo::PiecewiseBezier &a = curves[i].curve, &b = back->curves[i].curve;
        QCOMPARE(b.segmentCount(), a.segmentCount());
        int degree = 1;
        for (const geo::Bezier &s : a.segments())
            degree = std::max(degree, s.degree());
        for (int s = 0; s < a.segmentCount(); ++s) {
            const geo::Bezier &sa = a.segments()[static_cast<std::size_t>(s)];
            const geo::Bezier &sb = b.segments()[static_cast<std::size_t>(s)];
            if (sb.degree() == 1 && isStraight(sa)) {
                // A run of straight pieces of any degree is written as lines: the same segments.
                QCOMPARE(sb.startPoint(), sa.startPoint());
                QCOMPARE(sb.endPoint(), sa.endPoint());
                continue;
            }
            if (sa.degree() == degree || sa.degree() == 1) {
                // Bit for bit (a polyline's lines stay lines; lines in a curve of higher degree are
                // elevated, the same curve).
                if (sb.degree() == sa.degree()) {
                    QCOMPARE(sb.controlPoints(), sa.controlPoints());
                    continue;
                }
            }
            for (int k = 0; k <= 16; ++k)
                QVERIFY((sa.eval(k / 16.0) - sb.eval(k / 16.0)).norm() <= 1e-9 * (1 + sa.eval(k / 16.0).norm()));
        }
        if (a.isClosed())
            QVERIFY2(b.isClosed(), qPrintable(curves[i].name));
    }
    // And a composite curve comes back as itself: the same record.
    CurveRecord composite = random.curve(QStringLiteral("composite"));
    auto shape = curveShape(composite);
    QVERIFY(shape.ok());
    const std::vector<DxfCurve> one{{QString(), QString(), *shape}};
    auto again = importDxf(exportDxf(one, {}));
    QVERIFY(again.ok());
    auto record = recordFromDxfCurve(again->curves.front().curve);
    QVERIFY(record.ok());
    QCOMPARE(record->points, composite.points);
    QCOMPARE(record->closed, composite.closed);
}

void TestDxf::polylineWithinTolerance()
{
    // A pattern piece's curve in mm: the polyline stays within the default 0.05 mm, its vertices on it.
    const geo::PiecewiseBezier curve({geo::Bezier({{0, 0}, {40, 80}, {120, -30}, {160, 20}}),
                                      geo::Bezier({{160, 20}, {180, 45}, {170, 90}, {120, 100}})},
                                     false);
    for (const auto &[units, tolerance] :
         {std::pair{QStringLiteral("mm"), 0.05}, {QStringLiteral("cm"), 0.005}, {QStringLiteral("mm"), 1.0}}) {
        DxfExportOptions options;
        options.units = units;
        options.flavour = DxfFlavour::Polyline;
        if (tolerance == 1.0)
            options.tolerance = 1.0;
        else
            QCOMPARE(defaultDxfTolerance(units), tolerance);
        const QByteArray dxf = exportDxf(std::vector<DxfCurve>{{QString(), QString(), curve}}, options);
        QVERIFY(dxf.contains("LWPOLYLINE"));
        QVERIFY(!dxf.contains("\nSPLINE\n"));
        auto back = importDxf(dxf);
        QVERIFY(back.ok());
        QCOMPARE(back->units, units);
        std::vector<geo::Point> pts{back->curves.front().curve.segments().front().startPoint()};
        for (const geo::Bezier &b : back->curves.front().curve.segments()) {
            QCOMPARE(b.degree(), 1);
            pts.push_back(b.endPoint());
        }
        QVERIFY(pts.size() > 10);
        QCOMPARE(pts.front(), geo::Point(0, 0));
        QCOMPARE(pts.back(), geo::Point(120, 100));
        double worst = 0.0;
        for (const geo::Bezier &b : curve.segments())
            for (int k = 0; k <= 1000; ++k)
                worst = std::max(worst, distanceToPolyline(b.eval(k / 1000.0), pts));
        QVERIFY2(worst <= tolerance, qPrintable(QString::number(worst)));
        QVERIFY(worst > tolerance / 20); // not needlessly fine
    }
}

void TestDxf::units_data()
{
    QTest::addColumn<QString>("units");
    QTest::addColumn<int>("insunits");
    QTest::addColumn<double>("scale");
    QTest::addColumn<QString>("readBack");
    QTest::addRow("mm") << "mm" << 4 << 1.0 << "mm";
    QTest::addRow("cm") << "cm" << 5 << 1.0 << "cm";
    QTest::addRow("in") << "in" << 1 << 1.0 << "in";
    QTest::addRow("pt as inches") << "pt" << 1 << 1.0 / 72 << "in";
    QTest::addRow("px unitless") << "px" << 0 << 1.0 << "px";
}

void TestDxf::units()
{
    QFETCH(QString, units);
    QFETCH(int, insunits);
    QFETCH(double, scale);
    QFETCH(QString, readBack);
    const geo::PiecewiseBezier curve({geo::Bezier({{0, 0}, {72, 36}, {144, 0}, {216, 72}})}, false);
    DxfExportOptions options;
    options.units = units;
    const QByteArray dxf = exportDxf(std::vector<DxfCurve>{{QString(), QString(), curve}}, options);
    QVERIFY(dxf.contains("$INSUNITS\n 70\n" + QByteArray::number(insunits) + "\n"));
    QVERIFY(dxf.contains("$ACADVER\n  1\nAC1015\n"));
    auto back = importDxf(dxf);
    QVERIFY(back.ok());
    QCOMPARE(back->units, readBack);
    const auto &pts = back->curves.front().curve.segments().front().controlPoints();
    QCOMPARE(pts[3], geo::Point(216 * scale, 72 * scale));
    // Units without a Kontur counterpart: metres as millimetres, feet as inches.
    const QByteArray metres = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
                              "0\nLINE\n10\n0\n20\n0\n11\n1.5\n21\n2\n0\nENDSEC\n0\nEOF\n";
    auto m = importDxf(metres);
    QVERIFY(m.ok());
    QCOMPARE(m->units, QStringLiteral("mm"));
    QCOMPARE(m->curves.front().curve.segments().front().endPoint(), geo::Point(1500, 2000));
}

void TestDxf::generalBSplines_data()
{
    QTest::addColumn<int>("degree");
    QTest::addColumn<QList<double>>("knots");
    QTest::addColumn<int>("pieces");
    QTest::addRow("clamped non-uniform cubic") << 3 << QList<double>{0, 0, 0, 0, 0.2, 0.45, 0.5, 1, 1, 1, 1} << 4;
    QTest::addRow("unclamped uniform cubic") << 3 << QList<double>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10} << 4;
    // A double knot (a corner) and an end knot one time more than needed (its last point unused).
    QTest::addRow("double knot quadratic") << 2 << QList<double>{0, 0, 0, 1, 1, 2, 3, 3, 3, 3} << 3;
    QTest::addRow("quintic") << 5 << QList<double>{0, 0, 0, 0, 0, 0, 1, 3, 4, 4, 4, 4, 4, 4} << 3;
    QTest::addRow("degree 1") << 1 << QList<double>{0, 0, 1, 2, 3, 4, 5, 6, 6} << 6;
}

// A B-spline with any knots becomes Bézier pieces that lie on it (de Boor's evaluation at 50
// parameters of each span).
void TestDxf::generalBSplines()
{
    QFETCH(int, degree);
    QFETCH(QList<double>, knots);
    QFETCH(int, pieces);
    const std::vector<double> U(knots.begin(), knots.end());
    std::vector<geo::Point> P;
    for (std::size_t i = 0; i + static_cast<std::size_t>(degree) + 1 < U.size(); ++i)
        P.emplace_back(10.0 * static_cast<double>(i), (i % 2 ? 7.5 : -3.0) + 0.25 * static_cast<double>(i * i));
    auto back = importDxf(splineDxf(degree, U, P));
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    const geo::PiecewiseBezier &curve = back->curves.front().curve;
    QCOMPARE(curve.segmentCount(), pieces);
    std::vector<std::size_t> spans;
    const std::size_t p = static_cast<std::size_t>(degree);
    for (std::size_t k = p; k + p + 1 < U.size(); ++k)
        if (U[k] < U[k + 1])
            spans.push_back(k);
    QCOMPARE(spans.size(), static_cast<std::size_t>(pieces));
    for (int s = 0; s < pieces; ++s) {
        const std::size_t k = spans[static_cast<std::size_t>(s)];
        const geo::Bezier &b = curve.segments()[static_cast<std::size_t>(s)];
        QCOMPARE(b.degree(), degree);
        for (int j = 0; j <= 50; ++j) {
            const double t = j / 50.0;
            const geo::Point expected = deBoorPoint(U, P, degree, U[k] + t * (U[k + 1] - U[k]));
            QVERIFY2((b.eval(t) - expected).norm() < 1e-10, qPrintable(QStringLiteral("piece %1 t %2").arg(s).arg(t)));
        }
    }
}

void TestDxf::arcs_data()
{
    QTest::addColumn<QByteArray>("entity");
    QTest::addColumn<double>("cx");
    QTest::addColumn<double>("cy");
    QTest::addColumn<double>("rx");
    QTest::addColumn<double>("ry");
    QTest::addColumn<double>("length"); // of the arc, exactly
    QTest::addColumn<bool>("closed");
    const double pi = std::numbers::pi;
    QTest::addRow("arc") << QByteArray("0\nARC\n10\n5\n20\n-2\n40\n10\n50\n30\n51\n120\n") << 5.0 << -2.0 << 10.0
                         << 10.0 << 10 * pi / 2 << false;
    QTest::addRow("arc across 0") << QByteArray("0\nARC\n10\n0\n20\n0\n40\n3\n50\n300\n51\n60\n") << 0.0 << 0.0 << 3.0
                                  << 3.0 << 3 * 2 * pi / 3 << false;
    QTest::addRow("arc seen from below") << QByteArray(
                                                "0\nARC\n10\n5\n20\n1\n40\n2\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n")
                                         << -5.0 << 1.0 << 2.0 << 2.0 << pi << false;
    QTest::addRow("circle") << QByteArray("0\nCIRCLE\n10\n1\n20\n2\n40\n4\n") << 1.0 << 2.0 << 4.0 << 4.0 << 8 * pi
                            << true;
    QTest::addRow("ellipse") << QByteArray(
                                    "0\nELLIPSE\n10\n0\n20\n0\n11\n0\n21\n6\n40\n0.5\n41\n0\n42\n6.283185307179586\n")
                             << 0.0 << 0.0 << 3.0 << 6.0 << 0.0 << true;
    QTest::addRow("bulge half circle") << QByteArray(
                                              "0\nLWPOLYLINE\n90\n2\n70\n0\n10\n0\n20\n0\n42\n1\n10\n10\n20\n0\n")
                                       << 5.0 << 0.0 << 5.0 << 5.0 << 5 * pi << false;
    QTest::addRow("bulge clockwise quarter")
        << QByteArray("0\nLWPOLYLINE\n90\n2\n70\n0\n10\n0\n20\n0\n42\n-0.41421356237309503\n10\n4\n20\n4\n") << 4.0
        << 0.0 << 4.0 << 4.0 << 2 * pi << false;
}

// Every point of the cubics lies within the arc tolerance of the ellipse (x-cx)²/rx² + (y-cy)²/ry² = 1.
void TestDxf::arcs()
{
    QFETCH(QByteArray, entity);
    QFETCH(double, cx);
    QFETCH(double, cy);
    QFETCH(double, rx);
    QFETCH(double, ry);
    QFETCH(double, length);
    QFETCH(bool, closed);
    DxfImportOptions options;
    options.arcTolerance = 1e-7;
    auto back = importDxf("0\nSECTION\n2\nENTITIES\n" + entity + "0\nENDSEC\n0\nEOF\n", {}, options);
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    const geo::PiecewiseBezier &curve = back->curves.front().curve;
    QCOMPARE(curve.isClosed(), closed);
    for (const geo::Bezier &b : curve.segments()) {
        QCOMPARE(b.degree(), 3);
        for (int k = 0; k <= 20; ++k) {
            const geo::Point p = b.eval(k / 20.0) - geo::Point(cx, cy);
            // Radial distance for a circle; for the ellipse its implicit equation scaled to a distance.
            const double e = rx == ry ? std::abs(p.norm() - rx)
                                      : std::abs(std::hypot(p.x() / rx, p.y() / ry) - 1) * std::min(rx, ry);
            QVERIFY2(e <= 2e-7, qPrintable(QString::number(e)));
        }
    }
    if (length > 0)
        QVERIFY(std::abs(curve.length(1e-10) - length) < 1e-6 * length);
    if (closed)
        QCOMPARE(curve.segments().back().endPoint(), curve.segments().front().startPoint());
}

void TestDxf::records()
{
    // Two cubics meeting smoothly, a corner, a line: a composite curve with node types by continuity.
    const geo::PiecewiseBezier curve({geo::Bezier({{0, 0}, {1, 1}, {2, 1}, {3, 0}}),
                                      geo::Bezier({{3, 0}, {4, -1}, {5, -1}, {6, 0}}), geo::Bezier({{6, 0}, {6, 5}})},
                                     false);
    auto r = recordFromDxfCurve(curve);
    QVERIFY(r.ok());
    QCOMPARE(r->kind, QStringLiteral("composite"));
    QCOMPARE(r->nodeTypes, (std::vector<QString>{QStringLiteral("smooth"), QStringLiteral("symmetric"),
                                                 QStringLiteral("corner"), QStringLiteral("smooth")}));
    QCOMPARE(r->points.size(), std::size_t(10));
    auto shape = curveShape(*r);
    QVERIFY(shape.ok());
    QCOMPARE(shape->segments()[1].controlPoints(), curve.segments()[1].controlPoints());
    // One piece of degree 5: a Bézier curve of that degree, exactly.
    const geo::Bezier quintic({{0, 0}, {1, 3}, {2, -1}, {3, 4}, {4, 0}, {5, 2}});
    auto b = recordFromDxfCurve(geo::PiecewiseBezier({quintic}, false));
    QVERIFY(b.ok());
    QCOMPARE(b->kind, QStringLiteral("bezier"));
    QCOMPARE(b->points, quintic.controlPoints());
    // Several pieces of degree 5: cubics within the tolerance.
    const auto [left, right] = quintic.split(0.4);
    auto c = recordFromDxfCurve(geo::PiecewiseBezier({left, right}, false), 1e-6);
    QVERIFY(c.ok());
    QCOMPARE(c->kind, QStringLiteral("composite"));
    auto cs = curveShape(*c);
    QVERIFY(cs.ok());
    for (int k = 0; k <= 200; ++k) {
        const double d = cs->nearest(quintic.eval(k / 200.0)).distance;
        QVERIFY2(d < 2e-6, qPrintable(QString::number(d))); // measured at 31 parameters per piece
    }
}

void TestDxf::malformed_data()
{
    QTest::addColumn<QByteArray>("dxf");
    QTest::addColumn<QString>("code");
    QTest::addColumn<int>("line");
    const QByteArray head = "0\nSECTION\n2\nENTITIES\n";
    QTest::addRow("empty") << QByteArray() << "no-paths" << 0;
    QTest::addRow("no entities") << QByteArray("0\nSECTION\n2\nHEADER\n0\nENDSEC\n0\nEOF\n") << "no-paths" << 8;
    QTest::addRow("bad group code") << head + "0\nLINE\nten\n1\n"
                                    << "dxf-syntax" << 7;
    QTest::addRow("group code with text") << head + "0\nLINE\n10x\n1\n"
                                          << "dxf-syntax" << 7;
    QTest::addRow("truncated after a code") << head + "0\nLINE\n10"
                                            << "dxf-syntax" << 7;
    QTest::addRow("truncated in the section") << head + "0\nLINE\n10\n1\n20\n2\n"
                                              << "dxf-syntax" << 10;
    QTest::addRow("not a number") << head + "0\nLINE\n10\n1,5\n0\nENDSEC\n"
                                  << "dxf-syntax" << 8;
    QTest::addRow("infinite number") << head + "0\nLINE\n10\n1e999\n0\nENDSEC\n"
                                     << "dxf-syntax" << 8;
    QTest::addRow("section without name") << QByteArray("0\nSECTION\n0\nEOF\n") << "dxf-syntax" << 3;
    QTest::addRow("binary") << QByteArray("AutoCAD Binary DXF\r\n\x1a") << "dxf-unsupported" << 1;
    QTest::addRow("fit points only") << head + "0\nSPLINE\n71\n3\n11\n0\n21\n0\n11\n1\n21\n1\n0\nENDSEC\n"
                                     << "no-paths" << 18;
    QTest::addRow("rational") << splineDxf(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}},
                                           "70\n4\n41\n1\n41\n0.7071\n41\n1\n")
                              << "no-paths" << 52;
    QTest::addRow("knots do not fit") << splineDxf(3, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 3}})
                                      << "dxf-syntax" << 5;
    QTest::addRow("decreasing knots") << splineDxf(1, {0, 0, 2, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}) << "dxf-syntax" << 5;
    QTest::addRow("degree 0") << splineDxf(0, {0, 1}, {{0, 0}}) << "dxf-syntax" << 5;
    QTest::addRow("huge degree") << splineDxf(1000000000, {0, 1}, {{0, 0}}) << "dxf-syntax" << 5;
    QTest::addRow("huge declared counts") << head + "0\nSPLINE\n71\n3\n72\n999999999999\n73\n2000000000\n0\nENDSEC\n"
                                          << "dxf-syntax" << 5;
    // What cannot be drawn is skipped (tst_dxf_content counts it); a file of nothing else has no paths.
    QTest::addRow("tilted") << head + "0\nCIRCLE\n10\n0\n20\n0\n40\n1\n210\n0.6\n220\n0\n230\n0.8\n0\nENDSEC\n"
                            << "no-paths" << 20;
    QTest::addRow("mesh") << head + "0\nPOLYLINE\n70\n16\n0\nSEQEND\n0\nENDSEC\n"
                          << "no-paths" << 12;
    QTest::addRow("only text") << head + "0\nTEXT\n1\nhello\n0\nENDSEC\n0\nEOF\n"
                               << "no-paths" << 12;
    QTest::addRow("overflowing metres") << QByteArray("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n") +
                                               head + "0\nLINE\n10\n0\n20\n0\n11\n1e306\n21\n0\n0\nENDSEC\n"
                                        << "number-out-of-range" << 15;
}

void TestDxf::malformed()
{
    QFETCH(QByteArray, dxf);
    QFETCH(QString, code);
    QFETCH(int, line);
    auto r = importDxf(dxf, QStringLiteral("bad.dxf"));
    QVERIFY(!r.ok());
    QCOMPARE(QString::fromLatin1(codeName(r.error().code)), code);
    QCOMPARE(r.error().line, line);
    QVERIFY(r.error().toString().startsWith(QStringLiteral("bad.dxf")));
    // Every prefix of the file is answered too (a file cut short anywhere).
    for (qsizetype n = 0; n < dxf.size(); ++n)
        (void)importDxf(dxf.left(n)).ok();
}

void TestDxf::limits()
{
    const geo::PiecewiseBezier curve(
        {geo::Bezier({{0, 0}, {1, 1}, {2, 1}, {3, 0}}), geo::Bezier({{3, 0}, {4, -1}, {5, -1}, {6, 0}})}, false);
    const std::vector<DxfCurve> curves(5, DxfCurve{QString(), QString(), curve});
    Limits small;
    small.maxPoints = 35; // 5 curves of 7 control points: exactly at the limit
    small.maxCurves = 5;
    const QByteArray dxf = exportDxf(curves, {});
    QVERIFY(importDxf(dxf, {}, DxfImportOptions{small, 1e-6}).ok());
    const QString path = QDir::temp().filePath(QStringLiteral("kontur-tst-dxf-limits.dxf"));
    QVERIFY(writeDxf(path, curves, {}, small).ok());
    small.maxPoints = 34;
    auto refused = importDxf(dxf, {}, DxfImportOptions{small, 1e-6});
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error().code, ErrorCode::TooManyPoints);
    auto notWritten = writeDxf(path, curves, {}, small);
    QVERIFY(!notWritten.ok());
    QCOMPARE(notWritten.error().code, ErrorCode::TooManyPoints);
    small.maxPoints = 100;
    small.maxCurves = 4;
    QCOMPARE(importDxf(dxf, {}, DxfImportOptions{small, 1e-6}).error().code, ErrorCode::TooManyCurves);
    QCOMPARE(writeDxf(path, curves, {}, small).error().code, ErrorCode::TooManyCurves);
    // The polyline flavour counts its vertices, as the reader does: at the limit and one beyond.
    DxfExportOptions flat;
    flat.flavour = DxfFlavour::Polyline;
    const QByteArray polyline = exportDxf(curves, flat);
    const qsizetype from = polyline.indexOf("ENTITIES");
    const qint64 vertices = polyline.mid(from, polyline.indexOf("ENDSEC", from) - from).count("\n 10\n");
    Limits exact;
    exact.maxPoints = vertices;
    QVERIFY(importDxf(polyline, {}, DxfImportOptions{exact, 1e-6}).ok());
    QVERIFY(writeDxf(path, curves, flat, exact).ok());
    exact.maxPoints = vertices - 1;
    QCOMPARE(importDxf(polyline, {}, DxfImportOptions{exact, 1e-6}).error().code, ErrorCode::TooManyPoints);
    QCOMPARE(writeDxf(path, curves, flat, exact).error().code, ErrorCode::TooManyPoints);
    // Huge arcs by the thousand are refused by their cubics' count, before they are all made.
    QByteArray arcs = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n";
    for (int i = 0; i < 2000; ++i)
        arcs += "10\n" + QByteArray::number(i % 2 ? 1e300 : -1e300) + "\n20\n0\n42\n1\n";
    arcs += "0\nENDSEC\n";
    Limits few;
    few.maxPoints = 10'000;
    QCOMPARE(importDxf(arcs, {}, DxfImportOptions{few, 1e-9}).error().code, ErrorCode::TooManyPoints);
    // A coordinate that is not finite is not written.
    const geo::PiecewiseBezier bad({geo::Bezier({{0, 0}, {std::numeric_limits<double>::infinity(), 1}})}, false);
    QCOMPARE(writeDxf(path, std::vector<DxfCurve>{{QStringLiteral("x"), QString(), bad}}).error().code,
             ErrorCode::NumberOutOfRange);
    QFile::remove(path);
}

void TestDxf::structure_data()
{
    QTest::addColumn<int>("flavour");
    QTest::addColumn<int>("curves");
    QTest::addRow("splines") << static_cast<int>(DxfFlavour::Spline) << 3;
    QTest::addRow("polylines") << static_cast<int>(DxfFlavour::Polyline) << 3;
    QTest::addRow("empty drawing") << static_cast<int>(DxfFlavour::Spline) << 0;
}

// A complete AutoCAD 2000 drawing (DXF Reference, AutoCAD 2000): the six sections in order, the nine
// tables with their records, the model and paper space blocks, the root dictionary with ACAD_GROUP and
// ACAD_LAYOUT; every object has a unique handle below $HANDSEED and an owner that exists, and every
// reference (330, 340, 350) names an object of the file; the entities belong to *Model_Space.
void TestDxf::structure()
{
    QFETCH(int, flavour);
    QFETCH(int, curves);
    const geo::PiecewiseBezier curve({geo::Bezier({{0, 0}, {10, 20}, {30, 20}, {40, 0}})}, false);
    const geo::PiecewiseBezier line({geo::Bezier({{-5, -5}, {50, 30}})}, false);
    std::vector<DxfCurve> drawing{{QStringLiteral("Front"), QStringLiteral("#ff0000"), curve},
                                  {QString(), QStringLiteral("#000000"), line},
                                  {QStringLiteral("Back"), QString(), curve}};
    drawing.resize(static_cast<std::size_t>(curves));
    DxfExportOptions options;
    options.units = QStringLiteral("mm");
    options.flavour = static_cast<DxfFlavour>(flavour);
    const QByteArray dxf = exportDxf(drawing, options);
    const auto pairs = pairsOf(dxf);
    QVERIFY(dxf.endsWith("  0\nEOF\n"));

    std::vector<QByteArray> sections;
    QByteArray section;
    QMap<QByteArray, QByteArray> ownerOf;                // handle → owner
    QMap<QByteArray, QByteArray> kindOf;                 // handle → object type
    std::vector<std::pair<QByteArray, QByteArray>> refs; // (from, to) of 330, 340, 350
    QMap<QByteArray, QByteArray> tableOfName;            // "LAYER:Front" → record handle
    QByteArray handseed, current, type, name;
    std::vector<QByteArray> entityOwners, entityLayers, entityTypes;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto &[code, value] = pairs[i];
        if (code == 0) {
            if (value == "SECTION") {
                section = pairs[i + 1].second;
                sections.push_back(section);
            }
            current.clear();
            type = value;
            continue;
        }
        if (section == "HEADER" && code == 9 && value == "$HANDSEED")
            handseed = pairs[i + 1].second;
        if (section == "HEADER")
            continue;
        if ((code == 5 || code == 105) && current.isEmpty() && type != "SECTION") {
            current = value;
            QVERIFY2(!kindOf.contains(value), value.constData()); // unique
            kindOf[value] = type;
        } else if (code == 330 && !current.isEmpty() && !ownerOf.contains(current)) {
            ownerOf[current] = value;
            if (section == "ENTITIES") {
                entityOwners.push_back(value);
                entityTypes.push_back(type);
            }
        } else if (code == 2 && section == "TABLES" && type != "TABLE" && type != "SECTION") {
            tableOfName[type + ':' + value] = current;
        } else if (code == 8 && section == "ENTITIES") {
            entityLayers.push_back(value);
        }
        if ((code == 330 || code == 340 || code == 350) && value != "0")
            refs.emplace_back(current, value);
        // Every object (0 …) but SECTION, ENDSEC, ENDTAB and EOF has its handle first of all.
        if (i > 0 && pairs[i - 1].first == 0 && pairs[i - 1].second != "SECTION" && pairs[i - 1].second != "ENDSEC" &&
            pairs[i - 1].second != "ENDTAB" && pairs[i - 1].second != "EOF")
            QVERIFY2(code == 5 || code == 105 || (code == 2 && pairs[i - 1].second == "TABLE"),
                     (pairs[i - 1].second + " without its handle").constData());
    }
    QCOMPARE(sections, (std::vector<QByteArray>{"HEADER", "CLASSES", "TABLES", "BLOCKS", "ENTITIES", "OBJECTS"}));
    bool ok = false;
    const qulonglong seed = handseed.toULongLong(&ok, 16);
    QVERIFY(ok);
    for (auto it = kindOf.cbegin(); it != kindOf.cend(); ++it) {
        QVERIFY2(it.key().toULongLong(nullptr, 16) < seed, it.key().constData());
        QVERIFY2(ownerOf.contains(it.key()), (it.value() + ' ' + it.key() + " has no owner").constData());
        const QByteArray owner = ownerOf[it.key()];
        QVERIFY2(owner == "0" ? it.value() == "TABLE" || it.value() == "DICTIONARY" : kindOf.contains(owner),
                 (it.value() + ' ' + it.key() + " owned by " + owner).constData());
    }
    for (const auto &[from, to] : refs)
        QVERIFY2(kindOf.contains(to), (from + " refers to " + to).constData());
    for (const char *table : {"VPORT", "LTYPE", "LAYER", "STYLE", "VIEW", "UCS", "APPID", "DIMSTYLE", "BLOCK_RECORD"})
        QVERIFY2(dxf.contains(QByteArray("  0\nTABLE\n  2\n") + table + '\n'), table);
    for (const char *record :
         {"VPORT:*Active", "LTYPE:ByBlock", "LTYPE:ByLayer", "LTYPE:Continuous", "LAYER:0", "STYLE:Standard",
          "APPID:ACAD", "DIMSTYLE:Standard", "BLOCK_RECORD:*Model_Space", "BLOCK_RECORD:*Paper_Space"})
        QVERIFY2(tableOfName.contains(record), record);
    const QByteArray model = tableOfName["BLOCK_RECORD:*Model_Space"];
    QCOMPARE(kindOf.values().count("BLOCK"), 2);
    QCOMPARE(kindOf.values().count("ENDBLK"), 2);
    QCOMPARE(kindOf.values().count("LAYOUT"), 2);
    QVERIFY(dxf.contains("  3\nACAD_GROUP\n") && dxf.contains("  3\nACAD_LAYOUT\n"));
    QCOMPARE(entityOwners, std::vector<QByteArray>(static_cast<std::size_t>(curves), model));
    if (curves == 0) {
        QVERIFY(dxf.contains("$EXTMIN\n 10\n1e+20\n") && dxf.contains("$EXTMAX\n 10\n-1e+20\n"));
        QCOMPARE(tableOfName.keys().count(), 10);
        return;
    }
    // The named curves on their layers (red: ACI 1; no colour: ACI 7), the nameless one on "0"; true
    // colours on the entities.
    QCOMPARE(entityLayers, (std::vector<QByteArray>{"Front", "0", "Back"}));
    QVERIFY(tableOfName.contains("LAYER:Front") && tableOfName.contains("LAYER:Back"));
    QVERIFY(dxf.contains("  2\nFront\n 70\n0\n 62\n1\n"));
    QVERIFY(dxf.contains("  2\nBack\n 70\n0\n 62\n7\n"));
    QCOMPARE(dxf.count("\n420\n16711680\n"), 1);
    QCOMPARE(dxf.count("\n420\n0\n"), 1);
    QCOMPARE(dxf.count("\n420\n"), 2);
    QVERIFY(dxf.contains("$EXTMIN\n 10\n-5\n 20\n-5\n") && dxf.contains("$EXTMAX\n 10\n50\n 20\n30\n"));
    // The importer reads it as before, and the names and colours back.
    auto back = importDxf(dxf);
    QVERIFY(back.ok());
    QCOMPARE(back->curves.size(), std::size_t(3));
    QCOMPARE(back->curves[0].name, QStringLiteral("Front"));
    QCOMPARE(back->curves[0].color, QStringLiteral("#ff0000"));
    QCOMPARE(back->curves[1].name, QString());
    QCOMPARE(back->curves[2].name, QStringLiteral("Back"));
    QCOMPARE(back->curves[2].color, QStringLiteral("#000000"));
}

// Curve names as layer names: refused characters as "_", one layer per name regardless of case (the
// curves of one layer stay on it), never "0" or "Defpoints"; non-ASCII names in the code page that has them
// ($DWGCODEPAGE), else as \U+XXXX; the importer gives the names back, and reads the escape and the code page of other
// files too.
void TestDxf::layers()
{
    const geo::PiecewiseBezier curve({geo::Bezier({{0, 0}, {1, 2}})}, false);
    const auto layerNames = [&](const QStringList &names, QByteArray *page = nullptr) {
        std::vector<DxfCurve> drawing;
        for (const QString &n : names)
            drawing.push_back({n, QStringLiteral("#00ff00"), curve});
        const QByteArray dxf = exportDxf(drawing);
        if (page) {
            const qsizetype at = dxf.indexOf("$DWGCODEPAGE\n  3\n") + 17;
            *page = dxf.mid(at, dxf.indexOf('\n', at) - at);
        }
        auto back = importDxf(dxf);
        QStringList out;
        if (back)
            for (const DxfImportedCurve &c : back->curves)
                out << c.name;
        return out;
    };
    QCOMPARE(layerNames({QStringLiteral("Front: left/right?"), QStringLiteral("front: LEFT/RIGHT?"),
                         QStringLiteral(" a<b>c\\d\"e;f*g|h=i`j'k "), QStringLiteral("0"), QStringLiteral("DEFPOINTS"),
                         QStringLiteral("tab\there")}),
             (QStringList{QStringLiteral("Front_ left_right_"), QStringLiteral("Front_ left_right_"),
                          QStringLiteral("a_b_c_d_e_f_g_h_i_j_k"), QStringLiteral("0 (2)"),
                          QStringLiteral("DEFPOINTS (2)"), QStringLiteral("tab_here")}));
    const QStringList long300{QString(300, QLatin1Char('x')), QString(300, QLatin1Char('X'))};
    const QStringList longBack = layerNames(long300);
    QCOMPARE(longBack.size(), 2);
    QCOMPARE(longBack[0], QString(255, QLatin1Char('x')));
    QCOMPARE(longBack[1], QString(255, QLatin1Char('x'))); // the same layer regardless of case
    QByteArray page;
    const QStringList latvian{QStringLiteral("Priekša — ķīlis"), QStringLiteral("Mugura")};
    QCOMPARE(layerNames(latvian, &page), latvian);
    QCOMPARE(page, QByteArray("ANSI_1257"));
    const QStringList russian{QStringLiteral("Спинка"), QStringLiteral("Рукав")};
    QCOMPARE(layerNames(russian, &page), russian);
    QCOMPARE(page, QByteArray("ANSI_1251"));
    const QStringList slovak{QStringLiteral("Ľavý diel"), QStringLiteral("Rukáv")};
    QCOMPARE(layerNames(slovak, &page), slovak);
    QCOMPARE(page, QByteArray("ANSI_1250"));
    const QStringList mixed{QStringLiteral("Ķīlis"), QStringLiteral("Спинка")};
    QCOMPARE(layerNames(mixed, &page), mixed);
    QCOMPARE(page, QByteArray("ANSI_1252"));
    QCOMPARE(layerNames({QStringLiteral("emoji \U0001F600")}), QStringList{QStringLiteral("emoji _")});
    // Other writers: an AutoCAD 2007 file in UTF-8 whatever its code page, an older one in its code
    // page (ANSI_1251: 0xD1 is "С"), an escape that is none.
    const QByteArray line = "0\nLINE\n8\n%1\n10\n0\n20\n0\n11\n1\n21\n1\n";
    const auto nameIn = [&](const QByteArray &header, const QByteArray &layer) {
        auto r = importDxf("0\nSECTION\n2\nHEADER\n" + header + "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" +
                           QByteArray(line).replace("%1", layer) + "0\nENDSEC\n0\nEOF\n");
        return r ? r->curves.front().name : QStringLiteral("(error)");
    };
    QCOMPARE(nameIn("9\n$ACADVER\n1\nAC1021\n9\n$DWGCODEPAGE\n3\nANSI_1251\n", "Спинка"), QStringLiteral("Спинка"));
    QCOMPARE(nameIn("9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\nANSI_1251\n", "\xD1\\U+043F"), QStringLiteral("Сп"));
    QCOMPARE(nameIn("", "a\\U+12G4\\U+0041"), QStringLiteral("a\\U+12G4A"));
}

QTEST_GUILESS_MAIN(TestDxf)
#include "tst_dxf.moc"
