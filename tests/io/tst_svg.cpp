// Tests of SVG: path data (every command, relative forms, implicit repetitions, compact numbers),
// arcs within the stated tolerance, malformed path data with the character, transforms, units, and
// an SVG exported by Kontur re-imported equal to the original curves.
#include "io/shapes.h"
#include "io/svg.h"
#include "iotestutil.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace kontur;
using namespace kontur::io;

class TestSvg final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void pathData_data();
    void pathData();
    void malformedPath_data();
    void malformedPath();
    void arcsWithinTolerance_data();
    void arcsWithinTolerance();
    void exportImportEqual_data();
    void exportImportEqual();
    void exportUnits();
    void transforms();
    void viewBoxScale_data();
    void viewBoxScale();
    void useClones();
    void hiddenContent();
    void skippedContentCounted();
    void shapesAndTitles();
    void malformedSvg_data();
    void malformedSvg();
    void compositeFromShape();
};

void TestSvg::pathData_data()
{
    QTest::addColumn<QString>("d");
    QTest::addColumn<int>("subpaths");
    QTest::addColumn<int>("segments"); // in the last subpath
    QTest::addColumn<bool>("closed");  // the last subpath
    QTest::addColumn<double>("endX");  // the end of the last subpath
    QTest::addColumn<double>("endY");
    QTest::addRow("lines") << "M0 0 L10 0 L10 10" << 1 << 2 << false << 10.0 << 10.0;
    QTest::addRow("implicit lineto") << "M0 0 10 0 10 10" << 1 << 2 << false << 10.0 << 10.0;
    QTest::addRow("relative") << "m1 1 l2 0 0 2 h-2 v-2" << 1 << 4 << false << 1.0 << 1.0;
    QTest::addRow("close adds line") << "M0 0 H4 V4 Z" << 1 << 3 << true << 0.0 << 0.0;
    QTest::addRow("close at start") << "M0 0 L4 0 L0 0 Z" << 1 << 2 << true << 0.0 << 0.0;
    QTest::addRow("after Z") << "M0 0 L4 0 L4 4 z l1 1" << 2 << 1 << false << 1.0 << 1.0;
    QTest::addRow("two subpaths") << "M0 0 L1 1 M5 5 L6 6 L7 5" << 2 << 2 << false << 7.0 << 5.0;
    QTest::addRow("lone moveto dropped") << "M0 0 M1 1 L2 2 M9 9" << 1 << 1 << false << 2.0 << 2.0;
    QTest::addRow("cubic") << "M0 0 C1 1 2 1 3 0" << 1 << 1 << false << 3.0 << 0.0;
    QTest::addRow("smooth cubic") << "M0 0 C1 1 2 1 3 0 S5 -1 6 0 s1 1 2 0" << 1 << 3 << false << 8.0 << 0.0;
    QTest::addRow("quadratic") << "M0 0 Q1 1 2 0 T4 0 t2 0" << 1 << 3 << false << 6.0 << 0.0;
    QTest::addRow("compact numbers") << "M.5.5L-1-2l1e1,2E-1" << 1 << 2 << false << 9.0 << -1.8;
    QTest::addRow("commas everywhere") << "M 0,0 , L 1,1 , 2,2" << 1 << 2 << false << 2.0 << 2.0;
    QTest::addRow("arc") << "M0 0 A5 5 0 0 1 10 0" << 1 << 8 << false << 10.0 << 0.0;
    QTest::addRow("arc compact flags") << "M0 0a5 5 0 0010 0" << 1 << 8 << false << 10.0 << 0.0;
    QTest::addRow("arc zero radius") << "M0 0 A0 5 0 0 1 10 0" << 1 << 1 << false << 10.0 << 0.0;
    QTest::addRow("arc to itself") << "M0 0 L1 0 A5 5 0 0 1 1 0" << 1 << 1 << false << 1.0 << 0.0;
    QTest::addRow("empty") << "" << 0 << 0 << false << 0.0 << 0.0;
}

void TestSvg::pathData()
{
    QFETCH(QString, d);
    QFETCH(int, subpaths);
    QFETCH(int, segments);
    QFETCH(bool, closed);
    QFETCH(double, endX);
    QFETCH(double, endY);
    const QByteArray bytes = d.toLatin1();
    auto r = parseSvgPathData(std::string_view(bytes.data(), static_cast<std::size_t>(bytes.size())));
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(static_cast<int>(r->size()), subpaths);
    if (subpaths == 0)
        return;
    const geo::PiecewiseBezier &last = r->back();
    QCOMPARE(last.segmentCount(), segments);
    QCOMPARE(last.isClosed(), closed);
    QCOMPARE(last.segments().back().endPoint().x(), endX);
    QCOMPARE(last.segments().back().endPoint().y(), endY);
    // Segments join end to start.
    for (int i = 1; i < last.segmentCount(); ++i)
        QCOMPARE(last.segments()[i].startPoint(), last.segments()[i - 1].endPoint());
}

void TestSvg::malformedPath_data()
{
    QTest::addColumn<QString>("d");
    QTest::addColumn<int>("column");
    QTest::addRow("no moveto") << "L1 1" << 1;
    QTest::addRow("number first") << "1 1" << 1;
    QTest::addRow("missing number") << "M1 1 L2" << 8;
    QTest::addRow("unknown command") << "M1 1 X2 2" << 6;
    QTest::addRow("bad flag") << "M0 0 A5 5 0 2 1 10 0" << 13;
    QTest::addRow("number after Z") << "M0 0 L1 1 Z 5" << 13;
    QTest::addRow("exponent without digits") << "M1e 1" << 3;
    QTest::addRow("lone sign") << "M- 1" << 2;
    QTest::addRow("out of range") << "M1e999 0" << 2;
    // Radii whose squares overflow: a clear error at the arc, not a NaN cast (found by fuzzing).
    QTest::addRow("arc radii overflow") << "M0 0 A5 3 30 1 0 10 1e250" << 6;
}

void TestSvg::malformedPath()
{
    QFETCH(QString, d);
    QFETCH(int, column);
    const QByteArray bytes = d.toLatin1();
    auto r = parseSvgPathData(std::string_view(bytes.data(), static_cast<std::size_t>(bytes.size())));
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::PathSyntax);
    QCOMPARE(r.error().column, column);
}

void TestSvg::arcsWithinTolerance_data()
{
    QTest::addColumn<double>("radius");
    QTest::addColumn<double>("sweep"); // degrees
    QTest::addColumn<double>("tolerance");
    QTest::addRow("quarter") << 10.0 << 90.0 << 1e-2;
    QTest::addRow("half tight") << 100.0 << 180.0 << 1e-6;
    QTest::addRow("full tight") << 1000.0 << 359.0 << 1e-9;
    QTest::addRow("small negative") << 1.0 << -30.0 << 1e-12;
}

void TestSvg::arcsWithinTolerance()
{
    QFETCH(double, radius);
    QFETCH(double, sweep);
    QFETCH(double, tolerance);
    const auto cubics = arcToCubics({1, 2}, radius, radius, 0.3, 0.1, sweep * std::numbers::pi / 180, tolerance);
    double worst = 0;
    for (const geo::Bezier &b : cubics)
        for (int i = 0; i <= 64; ++i)
            worst = std::max(worst, std::abs((b.eval(i / 64.0) - geo::Point(1, 2)).norm() - radius));
    QVERIFY2(worst <= tolerance + 1e-12 * radius, qPrintable(QStringLiteral("%1 > %2").arg(worst).arg(tolerance)));
}

void TestSvg::exportImportEqual_data()
{
    test::addSeedRows(25);
}

// Random curves of degrees 1–3 (exact in SVG), open and closed, and of every record kind.
void TestSvg::exportImportEqual()
{
    QFETCH(int, seed);
    test::RandomDocuments random(static_cast<std::uint32_t>(seed));
    std::vector<SvgCurve> curves;
    for (int c = random.integer(1, 5); c > 0; --c) {
        std::vector<geo::Bezier> segs;
        geo::Point cur(random.integer(-100, 100) * 0.37, random.integer(-100, 100) * 1.1);
        const geo::Point start = cur;
        for (int s = random.integer(1, 6); s > 0; --s) {
            std::vector<geo::Point> pts{cur};
            for (int k = random.integer(1, 3); k > 0; --k)
                pts.push_back(random.point());
            cur = pts.back();
            segs.emplace_back(std::move(pts));
        }
        const bool closed = random.coin();
        if (closed)
            segs.emplace_back(std::vector<geo::Point>{cur, random.point(), start});
        curves.push_back({random.text().trimmed(), random.color(), geo::PiecewiseBezier(std::move(segs), closed)});
    }
    // And curves from records of every kind (numbers well inside the fitting's range): each one draws.
    // Segments above degree 3 (higher B-spline orders, the polynomial) are written as cubics within
    // the export's tolerance, so those are compared by distance, the others bit for bit.
    const std::size_t firstRecord = curves.size();
    std::vector<bool> approximated(firstRecord, false);
    for (const QString &kind : knownKinds()) {
        CurveRecord r = random.curve(kind);
        if (r.points.size() > 4 && kind == QLatin1String("bezier"))
            r.points.resize(4); // degree > 3 is approximated (see exportUnits)
        for (geo::Point &p : r.points)
            p = geo::Point(random.integer(-1000, 1000) * 0.01, random.integer(-1000, 1000) * 0.013);
        if (kind == QLatin1String("function-spline")) // y(x) over increasing x
            for (std::size_t i = 0; i < r.points.size(); ++i)
                r.points[i].x() = static_cast<double>(i) - 3.5;
        auto shape = curveShape(r);
        QVERIFY2(shape.ok(),
                 qPrintable(kind + QStringLiteral(": ") + (shape.ok() ? QString() : shape.error().message)));
        bool high = false;
        for (const geo::Bezier &b : shape->segments())
            high = high || b.degree() > 3;
        approximated.push_back(high);
        curves.push_back({r.name.trimmed(), r.color, *shape});
    }
    QCOMPARE(curves.size(), firstRecord + knownKinds().size());
    const QByteArray svg = exportSvg(curves, {});
    auto back = importSvg(svg);
    QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
    QCOMPARE(back->curves.size(), curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const geo::PiecewiseBezier &a = curves[i].curve, &b = back->curves[i].curve;
        QCOMPARE(b.isClosed(), a.isClosed());
        QCOMPARE(back->curves[i].name, curves[i].name);
        QCOMPARE(back->curves[i].color, curves[i].color);
        if (approximated[i]) {
            // Every point of the original lies within the export tolerance (1e-6) of the import.
            for (int s = 0; s < a.segmentCount(); ++s)
                for (int k = 0; k <= 16; ++k) {
                    const geo::Point p = a.segments()[s].eval(k / 16.0);
                    QVERIFY2(b.nearest(p).distance <= 1.01e-6, qPrintable(QString::number(i)));
                }
            continue;
        }
        QCOMPARE(b.segmentCount(), a.segmentCount());
        for (int s = 0; s < a.segmentCount(); ++s) {
            const auto &pa = a.segments()[s].controlPoints(), &pb = b.segments()[s].controlPoints();
            QCOMPARE(pb.size(), pa.size());
            for (std::size_t k = 0; k < pa.size(); ++k)
                QVERIFY((pa[k] - pb[k]).norm() <= 1e-9); // in fact bit for bit
        }
    }
    // As composite curves (cubics only) the same shape.
    SvgImportOptions cubic;
    cubic.cubicOnly = true;
    auto cubics = importSvg(svg, {}, cubic);
    QVERIFY(cubics.ok());
    for (std::size_t i = 0; i < curves.size(); ++i)
        for (int s = 0; !approximated[i] && s < curves[i].curve.segmentCount(); ++s)
            for (double t : {0.0, 0.3, 0.7, 1.0}) {
                const geo::Point pa = curves[i].curve.segments()[s].eval(t);
                const geo::Point pb = cubics->curves[i].curve.segments()[s].eval(t);
                QVERIFY((pa - pb).norm() <= 1e-9 * std::max(1.0, pa.norm()));
            }
}

void TestSvg::exportUnits()
{
    std::vector<SvgCurve> curves{
        {QStringLiteral("a"), QStringLiteral("#ff0000"), geo::PiecewiseBezier({geo::Bezier({{0, 0}, {100, 50}})})}};
    SvgExportOptions mm;
    mm.units = QStringLiteral("mm");
    const QByteArray svg = exportSvg(curves, mm);
    QVERIFY(svg.contains(R"(width="100mm")"));
    QVERIFY(svg.contains(R"(height="50mm")"));
    QVERIFY(svg.contains(R"(viewBox="0 -50 100 50")"));
    QVERIFY(svg.contains(R"(d="M 0 0 L 100 -50")"));
    auto back = importSvg(svg);
    QVERIFY(back.ok());
    QCOMPARE(back->units, QStringLiteral("mm"));
    QCOMPARE(back->curves.front().curve.segments().front().endPoint(), geo::Point(100, 50));
    // A drawing 200 user units wide shown as 100 mm: coordinates scaled into mm.
    auto scaled = importSvg(
        R"X(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100"><path d="M0 0 L200 100"/></svg>)X");
    QVERIFY(scaled.ok());
    QCOMPARE(scaled->curves.front().curve.segments().front().endPoint(), geo::Point(100, -50));
    // Degree 4 has no SVG form: cubics within the tolerance.
    const geo::Bezier quartic({{0, 0}, {1, 3}, {2, -3}, {3, 3}, {4, 0}});
    const QByteArray q =
        exportSvg(std::vector<SvgCurve>{{{}, QStringLiteral("#000000"), geo::PiecewiseBezier({quartic})}});
    auto qb = importSvg(q);
    QVERIFY(qb.ok());
    QVERIFY(qb->curves.front().curve.segmentCount() > 1);
    const geo::PiecewiseBezier &pw = qb->curves.front().curve;
    for (int i = 0; i <= 100; ++i) {
        const geo::Point p = quartic.eval(i / 100.0);
        QVERIFY(pw.nearest(p).distance <= 1e-6);
    }
}

void TestSvg::transforms()
{
    const QByteArray svg = R"X(<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <g transform="translate(10, 20)">
    <g transform="scale(2)">
      <path transform="matrix(1 0 0 1 1 1)" d="M0 0 L1 0"/>
    </g>
    <path transform="rotate(90)" d="M1 0 L2 0"/>
  </g>
  <defs><path d="M0 0 L5 5"/></defs>
  <path transform="skewX(45) translate(0,1)" d="M0 0 L1 0"/>
</svg>)X";
    auto r = importSvg(svg);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->curves.size(), std::size_t(3));
    const auto ends = [&](std::size_t i) { return r->curves[i].curve.segments().front().controlPoints(); };
    // translate(10,20) · scale(2) · translate(1,1): (0,0) → (12, 22), (1,0) → (14, 22); y negated.
    QVERIFY((ends(0)[0] - geo::Point(12, -22)).norm() < 1e-12);
    QVERIFY((ends(0)[1] - geo::Point(14, -22)).norm() < 1e-12);
    QVERIFY((ends(1)[0] - geo::Point(10, -21)).norm() < 1e-12);
    QVERIFY((ends(2)[0] - geo::Point(1, -1)).norm() < 1e-12);
    auto bad =
        importSvg(R"X(<svg xmlns="http://www.w3.org/2000/svg"><path transform="spin(3)" d="M0 0 L1 1"/></svg>)X");
    QVERIFY(!bad.ok());
    QCOMPARE(bad.error().code, ErrorCode::TransformSyntax);
}

// SVG 1.1 §7.7: the viewBox stretched to the width and height (the smaller scale of the two unless
// preserveAspectRatio is none), with the width's unit, px without one; Inkscape's templates
// (793.7 × 1122.5 px over a viewBox of 210 × 297 mm user units) come in at their size in px.
void TestSvg::viewBoxScale_data()
{
    QTest::addColumn<QString>("root");
    QTest::addColumn<QString>("units");
    QTest::addColumn<double>("sx");
    QTest::addColumn<double>("sy");
    const double inkscape = 793.7007874 / 210;
    QTest::addRow("unitless width and height")
        << R"(width="793.7007874" height="1122.519685" viewBox="0 0 210 297")"
        << "px" << std::min(inkscape, 1122.519685 / 297) << std::min(inkscape, 1122.519685 / 297);
    QTest::addRow("unitless width only") << R"(width="420" viewBox="0 0 210 297")"
                                         << "px" << 2.0 << 2.0;
    QTest::addRow("unitless height only") << R"(height="99" viewBox="0,0,210,297")"
                                          << "px" << 99.0 / 297 << 99.0 / 297;
    QTest::addRow("px width") << R"(width="105px" height="148.5px" viewBox="0 0 210 297")"
                              << "px" << 0.5 << 0.5;
    QTest::addRow("meet: the smaller scale") << R"(width="300" height="100" viewBox="0 0 100 100")"
                                             << "px" << 1.0 << 1.0;
    QTest::addRow("preserveAspectRatio none")
        << R"(width="300" height="100" viewBox="0 0 100 100" preserveAspectRatio="none")"
        << "px" << 3.0 << 1.0;
    QTest::addRow("mm") << R"(width="210mm" height="297mm" viewBox="0 0 793.7 1122.5")"
                        << "mm" << 210 / 793.7 << 210 / 793.7;
    QTest::addRow("same numbers: exact") << R"(width="210" height="297" viewBox="0 0 210 297")"
                                         << "px" << 1.0 << 1.0;
    QTest::addRow("no viewBox") << R"(width="500" height="10")"
                                << "px" << 1.0 << 1.0;
    QTest::addRow("percent") << R"(width="100%" height="100%" viewBox="0 0 10 10")"
                             << "px" << 1.0 << 1.0;
}

void TestSvg::viewBoxScale()
{
    QFETCH(QString, root);
    QFETCH(QString, units);
    QFETCH(double, sx);
    QFETCH(double, sy);
    const QString svg =
        QStringLiteral(R"(<svg xmlns="http://www.w3.org/2000/svg" %1><path d="M 10 20 L 110 70"/></svg>)").arg(root);
    auto r = importSvg(svg.toUtf8());
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->units, units);
    const geo::Bezier &line = r->curves.front().curve.segments().front();
    QVERIFY((line.startPoint() - geo::Point(10 * sx, -20 * sy)).norm() <= 1e-12 * (1 + 110 * sx));
    QVERIFY((line.endPoint() - geo::Point(110 * sx, -70 * sy)).norm() <= 1e-12 * (1 + 110 * sx));
    if (sx == 1.0 && sy == 1.0)
        QCOMPARE(line.endPoint(), geo::Point(110, -70)); // bit for bit
}

// <use> (SVG 1.1 §5.6): the named element drawn again with the use's transform and then a
// translation by x and y; symbols drawn only through a use; uses of uses; names of nothing and a
// use of itself draw nothing and end.
void TestSvg::useClones()
{
    const QByteArray svg = R"X(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
  <defs>
    <path id="p" d="M0 0 L10 0"/>
    <g id="pair" transform="translate(100,0)"><path d="M0 0 L0 1"/><path d="M0 0 L0 2"/></g>
  </defs>
  <symbol id="s"><circle cx="0" cy="0" r="3"/></symbol>
  <use href="#p" x="5" y="7" transform="rotate(90)"/>
  <use xlink:href="#s" x="50" y="60"/>
  <use id="u" href="#pair" y="-5"/>
  <g transform="scale(2)"><use href="#u" x="1"/></g>
  <use href="#nothing"/>
  <use id="loop" href="#loop"/>
</svg>)X";
    auto r = importSvg(svg);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->curves.size(), std::size_t(1 + 1 + 2 + 2));
    const auto near = [](const geo::Point &a, const geo::Point &b) { return (a - b).norm() < 1e-12; };
    // rotate(90) · translate(5, 7): (0,0) → (5,7) → (−7, 5); (10,0) → (15,7) → (−7, 15); y negated.
    const geo::PiecewiseBezier &line = r->curves[0].curve;
    QVERIFY(near(line.segments().front().startPoint(), {-7, -5}));
    QVERIFY(near(line.segments().back().endPoint(), {-7, -15}));
    // The symbol's circle about (50, 60).
    const geo::Box circle = r->curves[1].curve.boundingBox();
    QVERIFY(near(circle.center(), {50, -60}));
    QVERIFY(std::abs(circle.sizes().x() - 6) < 1e-9);
    // The group at translate(0,−5) · translate(100,0): its lines from (100, −5).
    QVERIFY(near(r->curves[2].curve.segments().front().startPoint(), {100, 5}));
    QVERIFY(near(r->curves[3].curve.segments().front().endPoint(), {100, 3}));
    // scale(2) · translate(1,0) · (the use u): (100, −5) → (101, −5) → (202, −10).
    QVERIFY(near(r->curves[4].curve.segments().front().startPoint(), {202, 10}));
    QVERIFY(near(r->curves[5].curve.segments().front().endPoint(), {202, 6}));
}

// display:none (attribute or style) leaves out the element and all inside it; visibility:hidden
// leaves out the shapes that inherit it, not a child that says visible.
void TestSvg::hiddenContent()
{
    const QByteArray svg = R"X(<svg xmlns="http://www.w3.org/2000/svg">
  <g style="display:none"><path d="M0 0 L1 0"/></g>
  <path display="none" d="M0 0 L2 0"/>
  <path style="fill:none;display: none" d="M0 0 L3 0"/>
  <g visibility="hidden">
    <path d="M0 0 L4 0"/>
    <path visibility="visible" d="M0 0 L5 0"/>
  </g>
  <path style="visibility:hidden" d="M0 0 L6 0"/>
  <path d="M0 0 L7 0"/>
</svg>)X";
    auto r = importSvg(svg);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->curves.size(), std::size_t(2));
    QCOMPARE(r->curves[0].curve.segments().front().endPoint(), geo::Point(5, 0));
    QCOMPARE(r->curves[1].curve.segments().front().endPoint(), geo::Point(7, 0));
    auto none = importSvg(R"X(<svg xmlns="http://www.w3.org/2000/svg"><path display="none" d="M0 0 L1 0"/></svg>)X");
    QVERIFY(!none.ok());
    QCOMPARE(none.error().code, ErrorCode::NoPaths);
}

// Content that is shown but is no geometry is counted, not dropped without a word: a <text> (its
// <tspan>s inside are part of it), an <image>, a <foreignObject>, each once, and once more per <use>
// that draws one; hidden ones and those only in <defs> are not shown and not counted. The paths
// come in as they would without them (the text's own numbers are not taken for a shape).
void TestSvg::skippedContentCounted()
{
    const QByteArray svg = R"X(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
  <defs><text id="label">Front</text><image href="b.png" width="1" height="1"/></defs>
  <text x="10" y="20">Sleeve <tspan x="10" dy="5">cut 2</tspan></text>
  <image xlink:href="photo.jpg" x="0" y="0" width="100" height="80"/>
  <foreignObject width="10" height="10"><div xmlns="http://www.w3.org/1999/xhtml">note</div></foreignObject>
  <path d="M0 0 L10 0"/>
  <text style="display:none">hidden</text>
  <g visibility="hidden"><image href="c.png" width="1" height="1"/></g>
  <use href="#label" x="5"/>
</svg>)X";
    auto r = importSvg(svg);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->curves.size(), std::size_t(1));
    QCOMPARE(r->curves[0].curve.segments().front().endPoint(), geo::Point(10, 0));
    SkippedCounts expected{};
    expected[static_cast<std::size_t>(SkippedKind::Text)] = 2; // the text and the use of "label"
    expected[static_cast<std::size_t>(SkippedKind::Image)] = 1;
    expected[static_cast<std::size_t>(SkippedKind::Other)] = 1;
    QCOMPARE(r->skipped, expected);
    QCOMPARE(skippedSummary(*r), QStringLiteral("2 texts, 1 image, 1 other element"));

    // Only geometry: nothing skipped, nothing said.
    auto plain = importSvg(R"X(<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L1 0"/></svg>)X");
    QVERIFY(plain.ok());
    QVERIFY(!anySkipped(plain->skipped));
    QVERIFY(skippedSummary(*plain).isEmpty());
    // Nothing to draw but a text: refused, saying what was skipped.
    auto onlyText = importSvg(R"X(<svg xmlns="http://www.w3.org/2000/svg"><text>Back</text></svg>)X");
    QVERIFY(!onlyText.ok());
    QCOMPARE(onlyText.error().code, ErrorCode::NoPaths);
    QVERIFY2(onlyText.error().message.endsWith(QStringLiteral("; skipped: 1 text")),
             qPrintable(onlyText.error().message));
}

void TestSvg::shapesAndTitles()
{
    auto r = importSvg(R"X(<svg xmlns="http://www.w3.org/2000/svg">
<rect id="r1" x="0" y="0" width="4" height="2" stroke="#f00"/>
<circle cx="0" cy="0" r="1" style="fill:none;stroke:#00ff00"><title>Round</title></circle>
<polygon points="0,0 1,0 1,1"/>
<line x1="0" y1="0" x2="3" y2="4"/>
<ellipse cx="0" cy="0" rx="2" ry="1"/>
<rect x="0" y="0" width="4" height="2" rx="1"/>
</svg>)X");
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(r->curves.size(), std::size_t(6));
    QCOMPARE(r->curves[0].name, QStringLiteral("r1"));
    QCOMPARE(r->curves[0].color, QStringLiteral("#ff0000"));
    QCOMPARE(r->curves[0].curve.segmentCount(), 4);
    QVERIFY(r->curves[0].curve.isClosed());
    QCOMPARE(r->curves[1].name, QStringLiteral("Round"));
    QCOMPARE(r->curves[1].color, QStringLiteral("#00ff00"));
    for (const geo::Bezier &b : r->curves[1].curve.segments())
        for (double t : {0.25, 0.5})
            QVERIFY(std::abs(b.eval(t).norm() - 1.0) < 1e-6);
    QCOMPARE(r->curves[2].curve.segmentCount(), 3);
    QCOMPARE(r->curves[3].curve.length(1e-12), 5.0);
    QCOMPARE(r->curves[5].curve.segmentCount(), 4 + 4 * 4); // 4 sides, 4 quarter arcs of 4 cubics (1e-6)
    QVERIFY(r->curves[5].curve.isClosed());
}

void TestSvg::malformedSvg_data()
{
    QTest::addColumn<QByteArray>("svg");
    QTest::addColumn<QString>("code");
    QTest::addColumn<int>("line");
    QTest::addRow("not xml") << QByteArray("<svg><path d='M0 0 L1 1'></svg>") << "xml-syntax" << 1;
    QTest::addRow("not svg") << QByteArray("<html/>") << "not-svg" << 1;
    QTest::addRow("empty") << QByteArray("") << "not-svg" << 1;
    QTest::addRow("no paths") << QByteArray("<svg xmlns='http://www.w3.org/2000/svg'><g/></svg>") << "no-paths" << 1;
    QTest::addRow("bad path") << QByteArray("<svg>\n<g>\n<path d='M0 0 L1'/></g></svg>") << "path-syntax" << 3;
    QTest::addRow("too deep") << QByteArray("<svg>" + QByteArray("<g>").repeated(100) +
                                            QByteArray("</g>").repeated(100) + "</svg>")
                              << "too-deep" << 1;
}

void TestSvg::malformedSvg()
{
    QFETCH(QByteArray, svg);
    QFETCH(QString, code);
    QFETCH(int, line);
    auto r = importSvg(svg, QStringLiteral("in.svg"));
    QVERIFY(!r.ok());
    QCOMPARE(QLatin1String(codeName(r.error().code)), code);
    QCOMPARE(r.error().line, line);
    QCOMPARE(r.error().file, QStringLiteral("in.svg"));
}

void TestSvg::compositeFromShape()
{
    auto subpaths = parseSvgPathData("M0 0 L3 0 Q4 2 3 4 C2 5 1 5 0 4 Z");
    QVERIFY(subpaths.ok());
    auto rec = compositeRecordFromShape(subpaths->front());
    QVERIFY2(rec.ok(), qPrintable(rec.ok() ? QString() : rec.error().toString()));
    QVERIFY(rec->closed);
    QCOMPARE(rec->points.size(), std::size_t(12)); // 4 knots, closed: 3n
    QCOMPARE(rec->nodeTypes, std::vector<QString>(4, QStringLiteral("corner")));
    QVERIFY(!validateCurve(*rec));
    auto shape = curveShape(*rec);
    QVERIFY(shape.ok());
    QCOMPARE(shape->segmentCount(), 4);
    QVERIFY((shape->eval(1.5) - subpaths->front().eval(1.5)).norm() < 1e-12);
}

QTEST_GUILESS_MAIN(TestSvg)
#include "tst_svg.moc"
