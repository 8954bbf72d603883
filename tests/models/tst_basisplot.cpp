// The teaching plots' models: the basis functions under the canvas (Bernstein, B-spline with its
// knot vector, seed 001's bells, Hermite) with their highlight and t marker, and the function spline
// y(x) view of seed 001 with its locale input, derivative handles, undo and the Runge comparison,
// and seed 003's segments with guide vectors and lines per segment.
// Over 600 lines because every basis family has its values written out as oracles.
#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "models/teaching/basisplot.h"
#include "models/teaching/functionspline.h"
#include "models/teaching/practicumplot.h"

#include <QRandomGenerator>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>

using kontur::BasisPlot;
using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::FunctionSplinePlot;
using kontur::Message;
using kontur::geo::Point;

class TestBasisPlot final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init() { QLocale::setDefault(QLocale::c()); }
    void cleanupTestCase() { QLocale::setDefault(QLocale::c()); }

    void bernsteinValuesAndPartitionOfUnity();
    void bSplineKnotVectorOfSeed003();
    void bSplinePartitionOfUnity_data();
    void bSplinePartitionOfUnity();
    void bellsOfSeed001();
    void hermiteBases();
    void hermiteBasesOnTheCurvesSegments();
    void followsTheSelectedCurveAndPoint();
    void markerFollowsParameter();
    void tooManyFunctionsAreNotDrawn();

    void seedExampleClampedSlopes();
    void slovakInputWithDecimalComma();
    void badInputKeepsTextAndCurve();
    void hermiteExample130();
    void clampedEqualsGlobalBSplineOnUniformKnots();
    void globalBSplineShowsControlValuesOfExample123();
    void torokSolverAgreesAndUndoes();
    void addToDocumentIsOneUndoStepAndExact();
    void derivativeHandleSlopeIsTheDerivative();
    void knotDragIsOneUndoStep();
    void dragIsOneCommandFromItsFirstStep();
    void errorFollowsALanguageSwitch();
    void methodSwitchKeepsTheCurveAndUndoes();
    void rungeComparison();
    void interpolatesOverRandomInputs();
    void bellSplineExample115();
    void courseExamplesLoadWithTheirNumbers();

    void practicumFunctionSegment();
    void practicumDebugExample();
    void practicumLinesPerSegmentAndDrags();
};

void TestBasisPlot::bernsteinValuesAndPartitionOfUnity()
{
    BasisPlot plot;
    plot.setFamily(BasisPlot::Bernstein);
    plot.setDegree(3);
    QCOMPARE(plot.shownFamily(), BasisPlot::Bernstein);
    QCOMPARE(plot.functionCount(), 4);
    // B_{1,3}(1/2) = 3 · 1/2 · 1/4.
    QCOMPARE(plot.value(1, 0.5), 0.375);
    QCOMPARE(plot.value(0, 0.0), 1.0);
    QCOMPARE(plot.value(3, 1.0), 1.0);
    QRandomGenerator rng(9);
    for (int degree : {1, 2, 5, 12, 30}) {
        plot.setDegree(degree);
        QCOMPARE(plot.functionCount(), degree + 1);
        for (int k = 0; k < 50; ++k) {
            const double t = rng.generateDouble();
            double sum = 0;
            for (int i = 0; i <= degree; ++i) {
                QVERIFY(plot.value(i, t) >= 0);
                sum += plot.value(i, t);
            }
            QVERIFY2(std::abs(sum - 1) < 1e-12, qPrintable(QString::number(sum - 1)));
        }
    }
    // The plot draws one series per function over [0, 1], and the marker's dots lie on them.
    plot.setDegree(3);
    plot.setParameter(0.3);
    const kontur::PlotData data = plot.plotData();
    QCOMPARE(data.series.size(), std::size_t(4));
    QVERIFY(data.marker.has_value());
    QCOMPARE(*data.marker, 0.3);
    QCOMPARE(data.dots.size(), std::size_t(4));
    QVERIFY(std::abs(data.dots[2].position.y() - 3 * 0.09 * 0.7) < 1e-12);
    QCOMPARE(data.series[0].points.first().x(), 0.0);
    QCOMPARE(data.series[0].points.last().x(), 1.0);
}

void TestBasisPlot::bSplineKnotVectorOfSeed003()
{
    // KG-205: m = 8 points, k = 4 → 0000 1 2 3 4 5555, shown under the plot.
    BasisPlot plot;
    plot.setFamily(BasisPlot::BSpline);
    plot.setCount(8);
    plot.setOrder(4);
    const std::vector<double> expected{0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5};
    QCOMPARE(plot.knots(), expected);
    QCOMPARE(plot.knotText(), QStringLiteral("Knot vector: 0 0 0 0 1 2 3 4 5 5 5 5"));
    QCOMPARE(plot.domainStart(), 0.0);
    QCOMPARE(plot.domainEnd(), 5.0);
    // Clamped ends: N_0 starts at 1, N_7 ends at 1.
    QCOMPARE(plot.value(0, 0.0), 1.0);
    QCOMPARE(plot.value(7, 5.0), 1.0);
    // The knots are marked on the axis.
    QCOMPARE(plot.plotData().xMarks, expected);
    // Order 2 gives the hat functions of the polygon: N_i peaks with 1 at its own knot.
    plot.setOrder(2);
    QCOMPARE(plot.value(3, 3.0), 1.0);
    QCOMPARE(plot.value(3, 2.5), 0.5);
}

void TestBasisPlot::bSplinePartitionOfUnity_data()
{
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("order");
    QTest::addRow("8, cubic") << 8 << 4;
    QTest::addRow("5, quadratic") << 5 << 3;
    QTest::addRow("10, order 10") << 10 << 10;
    QTest::addRow("4, Bézier") << 4 << 4;
}

void TestBasisPlot::bSplinePartitionOfUnity()
{
    QFETCH(int, count);
    QFETCH(int, order);
    BasisPlot plot;
    plot.setFamily(BasisPlot::BSpline);
    plot.setCount(count);
    plot.setOrder(order);
    QCOMPARE(plot.functionCount(), count);
    QRandomGenerator rng(static_cast<quint32>(count * 100 + order));
    for (int k = 0; k < 200; ++k) {
        const double t = plot.domainStart() + rng.generateDouble() * (plot.domainEnd() - plot.domainStart());
        double sum = 0;
        for (int i = 0; i < count; ++i)
            sum += plot.value(i, t);
        QVERIFY2(std::abs(sum - 1) < 1e-12, qPrintable(QStringLiteral("t = %1, sum = %2").arg(t).arg(sum)));
    }
    // When k equals the number of points the basis is Bernstein's (k = m gives the Bézier curve).
    if (count == order) {
        BasisPlot bernstein;
        bernstein.setFamily(BasisPlot::Bernstein);
        bernstein.setDegree(order - 1);
        for (double t : {0.1, 0.5, 0.77})
            for (int i = 0; i < count; ++i)
                QVERIFY(std::abs(plot.value(i, t) - bernstein.value(i, t)) < 1e-12);
    }
}

void TestBasisPlot::bellsOfSeed001()
{
    // Unit-spaced cubic bells are 6 N: at the knots they take 1, 4, 1 (docs/requirements.md 2:
    // P(v_{i+3}) = c_i + 4c_{i+1} + c_{i+2}).
    BasisPlot plot;
    plot.setFamily(BasisPlot::Bell);
    plot.setOrder(4);
    plot.setCount(6);
    QCOMPARE(plot.knots().front(), 0.0);
    QCOMPARE(plot.knots().back(), 9.0);
    QVERIFY(std::abs(plot.value(0, 1.0) - 1) < 1e-12);
    QVERIFY(std::abs(plot.value(0, 2.0) - 4) < 1e-12);
    QVERIFY(std::abs(plot.value(0, 3.0) - 1) < 1e-12);
    // Example 1.15: c = (−1/3, 1/5, 1/4, −1/4, 1/3, −3/4) gives P(3) = 43/60, P(6) = 1/3.
    const double c[] = {-1.0 / 3, 1.0 / 5, 1.0 / 4, -1.0 / 4, 1.0 / 3, -3.0 / 4};
    auto p = [&](double x) {
        double sum = 0;
        for (int i = 0; i < 6; ++i)
            sum += c[i] * plot.value(i, x);
        return sum;
    };
    QVERIFY(std::abs(p(3) - 43.0 / 60) < 1e-12);
    QVERIFY(std::abs(p(4) - 19.0 / 20) < 1e-12);
    QVERIFY(std::abs(p(5) + 5.0 / 12) < 1e-12);
    QVERIFY(std::abs(p(6) - 1.0 / 3) < 1e-12);
    // The plot's range reaches the bells' peak of 4.
    QVERIFY(plot.plotData().world.bottom() >= 4.0);
}

void TestBasisPlot::hermiteBases()
{
    BasisPlot plot;
    plot.setFamily(BasisPlot::Hermite);
    QCOMPARE(plot.functionCount(), 4);
    // Values and slopes at the ends: Hs(0,1) is 1 at 0, Hds(0,1) has slope 1 at 0, and so on.
    const double h = 1e-6;
    auto slope = [&](int i, double x) { return (plot.value(i, x + h) - plot.value(i, x - h)) / (2 * h); };
    QCOMPARE(plot.value(0, 0), 1.0);
    QCOMPARE(plot.value(0, 1), 0.0);
    QCOMPARE(plot.value(2, 1), 1.0);
    QCOMPARE(plot.value(1, 0), 0.0);
    QVERIFY(std::abs(slope(1, 0) - 1) < 1e-6);
    QVERIFY(std::abs(slope(3, 1) - 1) < 1e-6);
    QVERIFY(std::abs(slope(0, 0)) < 1e-6);
    QVERIFY(std::abs(slope(2, 1)) < 1e-6);
    for (double x : {0.2, 0.5, 0.9})
        QVERIFY(std::abs(plot.value(0, x) + plot.value(2, x) - 1) < 1e-12);
    // Hds dips to -4/27 at x = 1/3: drawn 4 times taller and labelled so, in the plot's range.
    const kontur::PlotData data = plot.plotData();
    QCOMPARE(data.series[1].label, QStringLiteral("4·Hds(0,1)"));
    QCOMPARE(data.series[1].points[10].y(), 4 * plot.value(1, data.series[1].points[10].x()));
    QVERIFY(data.world.top() < -4 * 4.0 / 27);
}

void TestBasisPlot::hermiteBasesOnTheCurvesSegments()
{
    // A spline in Hermite form shows a value basis Hs_k and a derivative basis Hds_k per knot over its
    // own segments (knot k at x = k, as the de Casteljau view's u): with the knots and the segments'
    // end derivatives as weights they give the curve itself.
    EditController editor;
    BasisPlot plot;
    plot.setEditor(&editor);
    editor.commands()->addCurves({Curve::make(CurveKind::NaturalSpline, {{0, 0}, {100, 60}, {180, -20}, {300, 40}},
                                              kontur::geo::Parameterization::Uniform)},
                                 QStringLiteral("test"));
    kontur::test::selectAt(editor, 0, 2);
    QCOMPARE(plot.shownFamily(), BasisPlot::Hermite);
    QCOMPARE(plot.functionCount(), 8);
    QCOMPARE(plot.highlighted(), 4); // knot 2's value basis
    const kontur::PlotData data = plot.plotData();
    for (const kontur::PlotSeries &series : data.series)
        if (series.id == 5)
            QCOMPARE(series.label, QStringLiteral("4·Hds2")); // drawn 4 times taller
    QVERIFY(plot.title().contains(QStringLiteral("3 segment")));
    const Curve &curve = editor.document()->curve(0);
    const int m = curve.segmentCount();
    QCOMPARE(m, 3);
    for (int step = 0; step <= 60; ++step) {
        const double x = m * step / 60.0;
        Point sum(0, 0);
        double unity = 0.0;
        for (int k = 0; k <= m; ++k) {
            const kontur::geo::Bezier segment = curve.segment(std::min(k, m - 1));
            const std::vector<Point> &b = segment.controlPoints();
            const Point knot = k < m ? b[0] : b[3];
            const Point derivative = k < m ? 3.0 * (b[1] - b[0]) : 3.0 * (b[3] - b[2]);
            sum += knot * plot.value(2 * k, x) + derivative * plot.value(2 * k + 1, x);
            unity += plot.value(2 * k, x);
        }
        const int seg = std::min(static_cast<int>(x), m - 1);
        QVERIFY2((sum - curve.segment(seg).eval(x - seg)).norm() < 1e-9, qPrintable(QString::number(x)));
        QVERIFY(std::abs(unity - 1.0) < 1e-12);
    }
    // A knot's bases are zero beyond the segments beside it.
    QCOMPARE(plot.value(0, 1.5), 0.0);
    QCOMPARE(plot.value(7, 1.0), 0.0);
    QCOMPARE(plot.plotData().xMarks, (std::vector<double>{0, 1, 2, 3}));
}

void TestBasisPlot::followsTheSelectedCurveAndPoint()
{
    EditController editor;
    BasisPlot plot;
    plot.setEditor(&editor);
    QSignalSpy changed(&plot, &kontur::PlotSource::plotChanged);
    editor.commands()->addCurves(
        {Curve::make(CurveKind::Bezier, {{0, 0}, {1, 2}, {2, 3}, {3, 1}, {4, 0}, {5, 2}}),
         Curve::make(CurveKind::BSpline, {{0, 0}, {1, 2}, {2, 3}, {3, 1}, {4, 0}, {5, 2}, {6, 1}}),
         Curve::make(CurveKind::NaturalSpline, {{0, 0}, {1, 2}, {2, 3}})},
        QStringLiteral("test"));
    editor.selection()->selectRow(0);
    QCOMPARE(plot.shownFamily(), BasisPlot::Bernstein);
    QCOMPARE(plot.functionCount(), 6);
    QCOMPARE(plot.highlighted(), -1);
    kontur::test::selectAt(editor, 0, 2);
    QCOMPARE(plot.highlighted(), 2);
    QVERIFY(changed.count() > 0);
    // The highlighted series is drawn wider.
    const kontur::PlotData data = plot.plotData();
    for (const kontur::PlotSeries &s : data.series)
        QCOMPARE(s.width > 3, s.id == 2);
    // Hovering a curve in the plot highlights it instead, until the pointer leaves.
    plot.hoverSeries(4);
    QCOMPARE(plot.highlighted(), 4);
    plot.hoverSeries(-1);
    QCOMPARE(plot.highlighted(), 2);

    kontur::test::selectAt(editor, 1, 5);
    QCOMPARE(plot.shownFamily(), BasisPlot::BSpline);
    QCOMPARE(plot.functionCount(), 7);
    QCOMPARE(plot.highlighted(), 5);
    QCOMPARE(plot.knots(), (std::vector<double>{0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4}));
    // A new order of the curve is a new basis.
    QVERIFY(editor.commands()->setCurveOrder(kontur::test::idAt(editor, 1), 3));
    QCOMPARE(plot.knots(), (std::vector<double>{0, 0, 0, 1, 2, 3, 4, 5, 5, 5}));

    editor.selection()->selectRow(2);
    QCOMPARE(plot.shownFamily(), BasisPlot::Hermite);
    // An explicit family wins over the selection.
    plot.setFamily(BasisPlot::Bell);
    QCOMPARE(plot.shownFamily(), BasisPlot::Bell);
    plot.setFamily(BasisPlot::Auto);
    editor.selection()->selectRow(-1);
    QCOMPARE(plot.shownFamily(), BasisPlot::Bernstein);
    QCOMPARE(plot.functionCount(), 4);
}

void TestBasisPlot::markerFollowsParameter()
{
    BasisPlot plot;
    plot.setFamily(BasisPlot::BSpline);
    plot.setCount(8);
    plot.setOrder(4);
    QSignalSpy spy(&plot, &BasisPlot::parameterChanged);
    plot.setParameter(0.4);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(*plot.plotData().marker, 2.0); // 0.4 of [0, 5]
    plot.dragMarker(4.0);
    QCOMPARE(plot.parameter(), 0.8);
    plot.dragMarker(99.0);
    QCOMPARE(plot.parameter(), 1.0);
    plot.setParameter(std::nan(""));
    QCOMPARE(plot.parameter(), 1.0);
    // The values at t are listed with their sum.
    plot.setParameter(0.5);
    QVERIFY(plot.valuesText().contains(QStringLiteral("sum 1.000")));
}

void TestBasisPlot::tooManyFunctionsAreNotDrawn()
{
    EditController editor;
    BasisPlot plot;
    plot.setEditor(&editor);
    std::vector<Point> points;
    for (int i = 0; i < BasisPlot::kMaxFunctions + 5; ++i)
        points.emplace_back(i, i % 3);
    editor.commands()->addCurves({Curve::make(CurveKind::BSpline, points)}, QStringLiteral("test"));
    editor.selection()->selectRow(0);
    QCOMPARE(plot.functionCount(), 0);
    QVERIFY(plot.title().contains(QString::number(BasisPlot::kMaxFunctions + 5)));
    QVERIFY(plot.plotData().series.empty());
}

// --- the function spline view ---

void TestBasisPlot::seedExampleClampedSlopes()
{
    // docs/requirements.md 2 (Török): y = (3, 2, −1, 0.5), h = 1, d_0 = d_3 = 0 → d_1 = −2.9, d_2 = −0.4.
    FunctionSplinePlot plot;
    QCOMPARE(plot.method(), FunctionSplinePlot::Clamped);
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 -1 0.5"));
    const std::vector<double> slopes = plot.knotSlopes();
    QCOMPARE(slopes.size(), std::size_t(4));
    QVERIFY(std::abs(slopes[1] + 2.9) < 1e-12);
    QVERIFY(std::abs(slopes[2] + 0.4) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(2.0) + 1) < 1e-12);
    QVERIFY(plot.summary().contains(QStringLiteral("-2.9")));
}

void TestBasisPlot::slovakInputWithDecimalComma()
{
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    FunctionSplinePlot plot;
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 -1 0,5"));
    plot.setValuesText(QStringLiteral("1,5 2 -1 0,25 4"));
    plot.setIntervalText(QStringLiteral("0 2,5"));
    plot.setDerivativesText(QStringLiteral("0,5; -1"));
    QVERIFY(plot.apply());
    QCOMPARE(plot.input().values, (std::vector<double>{1.5, 2, -1, 0.25, 4}));
    QCOMPARE(plot.input().b, 2.5);
    QCOMPARE(plot.input().derivatives, (std::vector<double>{0.5, -1}));
    QCOMPARE(plot.knotX()[1], 0.625);
    // A point is read too; the texts come back in Slovak.
    plot.setValuesText(QStringLiteral("0.5 1"));
    QVERIFY(plot.apply());
    QCOMPARE(plot.valuesText(), QStringLiteral("0,5 1"));
    // Under English a comma separates numbers.
    QLocale::setDefault(QLocale(QStringLiteral("en")));
    std::vector<double> out;
    QVERIFY(FunctionSplinePlot::parseNumbers(QStringLiteral("3, 2,-1;0.5"), QLocale(), out));
    QCOMPARE(out, (std::vector<double>{3, 2, -1, 0.5}));
    for (const char *code : {"lv", "bg", "ru"}) {
        QVERIFY(FunctionSplinePlot::parseNumbers(QStringLiteral("3 2 -1 0,5"), QLocale(QLatin1String(code)), out));
        QCOMPARE(out, (std::vector<double>{3, 2, -1, 0.5}));
    }
}

void TestBasisPlot::badInputKeepsTextAndCurve()
{
    FunctionSplinePlot plot;
    const kontur::FunctionSplineInput before = plot.input();
    QSignalSpy errors(&plot, &FunctionSplinePlot::errorChanged);
    plot.setValuesText(QStringLiteral("3 x 1"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error(), Message(Message::FunctionValuesNotNumbers, {QStringLiteral("x")}));
    QVERIFY(plot.error().text().contains(QStringLiteral("“x”")));
    QCOMPARE(plot.valuesText(), QStringLiteral("3 x 1"));
    QVERIFY(plot.input() == before);
    QVERIFY(!plot.canUndo());
    plot.setValuesText(QStringLiteral("3"));
    QVERIFY(!plot.apply());
    plot.setValuesText(QStringLiteral("1 2 3"));
    plot.setIntervalText(QStringLiteral("2 1"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error().id, Message::IntervalOrder);
    QVERIFY(plot.error().text().startsWith(QStringLiteral("Interval")));
    plot.setIntervalText(QStringLiteral("0 1"));
    plot.setDerivativesText(QStringLiteral("1"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error().id, Message::DerivativesTwo);
    QVERIFY(plot.error().text().startsWith(QStringLiteral("Derivatives")));
    plot.setDerivativesText(QStringLiteral("1 1"));
    QVERIFY(plot.apply());
    QVERIFY(plot.error().text().isEmpty());
    QVERIFY(errors.count() >= 2);
    // Not uniform: the knots must increase.
    plot.setUniformKnots(false);
    plot.setKnotsText(QStringLiteral("0 2 1"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error().id, Message::KnotsOrder);
    QVERIFY(plot.error().text().startsWith(QStringLiteral("Knots")));
}

void TestBasisPlot::hermiteExample130()
{
    // Example 1.30: V = (1, 2, 3), c = (−1/10, 1, 11/10), d = (−2, 1, 0): P(1.5) = 3/40, P(2.5) = 47/40.
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    FunctionSplinePlot plot;
    plot.setMethod(FunctionSplinePlot::Hermite);
    plot.setValuesText(QStringLiteral("-0,1 1 1,1"));
    plot.setIntervalText(QStringLiteral("1 3"));
    plot.setDerivativesText(QStringLiteral("-2 1 0"));
    QVERIFY2(plot.apply(), qPrintable(plot.error().text()));
    QVERIFY(std::abs(plot.splineAt(1.5) - 3.0 / 40) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(2.5) - 47.0 / 40) < 1e-12);
    // Every knot has a handle.
    QCOMPARE(plot.plotData().dots.size(), std::size_t(6));
}

void TestBasisPlot::clampedEqualsGlobalBSplineOnUniformKnots()
{
    // docs/requirements.md 2: with uniform knots the clamped spline equals the global B-spline exactly.
    QRandomGenerator rng(2014);
    for (int trial = 0; trial < 20; ++trial) {
        kontur::FunctionSplineInput in;
        in.method = FunctionSplinePlot::Clamped;
        const int n = 2 + static_cast<int>(rng.bounded(10));
        for (int i = 0; i < n; ++i)
            in.values.push_back(rng.generateDouble() * 10 - 5);
        in.a = rng.generateDouble() * 4 - 2;
        in.b = in.a + 0.5 + rng.generateDouble() * 6;
        in.derivatives = {rng.generateDouble() * 4 - 2, rng.generateDouble() * 4 - 2};
        FunctionSplinePlot clamped;
        clamped.setInput(in);
        in.method = FunctionSplinePlot::GlobalBSpline;
        FunctionSplinePlot global;
        global.setInput(in);
        for (int k = 0; k < 20; ++k) {
            const double x = in.a + (in.b - in.a) * rng.generateDouble();
            QVERIFY2(std::abs(clamped.splineAt(x) - global.splineAt(x)) < 1e-9,
                     qPrintable(QStringLiteral("n = %1, x = %2").arg(n).arg(x)));
        }
    }
}

// The global B-spline's control values b are shown, so that a class compares them with the course's
// Example 1.23 (knots 2, 15/4, 5; values −1/2, 11/10, 3/4; end slopes −2, 4/5 → b ≈ 0.290301, −0.224190,
// 0.138259, −0.034416, 0.271097), in the UI language's number format; other methods show none.
void TestBasisPlot::globalBSplineShowsControlValuesOfExample123()
{
    QLocale::setDefault(QLocale::c());
    FunctionSplinePlot plot;
    plot.setMethod(FunctionSplinePlot::GlobalBSpline);
    plot.setUniformKnots(false);
    plot.setKnotsText(QStringLiteral("2 3.75 5"));
    plot.setValuesText(QStringLiteral("-0.5 1.1 0.75"));
    plot.setDerivativesText(QStringLiteral("-2 0.8"));
    QVERIFY2(plot.apply(), qPrintable(plot.error().text()));
    QVERIFY2(plot.summary().contains(QStringLiteral("Control values b: 0.2903; -0.2242; 0.1383; -0.0344; 0.2711")),
             qPrintable(plot.summary()));
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    plot.refreshTexts();
    QVERIFY2(plot.summary().contains(QStringLiteral("0,2903; -0,2242; 0,1383; -0,0344; 0,2711")), qPrintable(plot.summary()));
    QLocale::setDefault(QLocale::c());
    plot.setMethod(FunctionSplinePlot::Clamped);
    QVERIFY(!plot.summary().contains(QStringLiteral("Control values")));
}

// The course's examples, each loaded by one call (one tap in the view) and one undo step, show the
// numbers the course prints (docs/requirements.md 2), in the UI language's number format.
void TestBasisPlot::courseExamplesLoadWithTheirNumbers()
{
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    FunctionSplinePlot plot;
    plot.setMethod(FunctionSplinePlot::Natural);
    plot.setValuesText(QStringLiteral("1 2 3 4 5"));
    QVERIFY(plot.apply());
    plot.loadExample(FunctionSplinePlot::Example130);
    QCOMPARE(plot.method(), FunctionSplinePlot::Hermite);
    QVERIFY(std::abs(plot.splineAt(1.5) - 3.0 / 40) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(2.5) - 47.0 / 40) < 1e-12);
    QVERIFY2(plot.summary().contains(QStringLiteral("Between the knots: P(1,5) = 0,075; P(2,5) = 1,175")),
             qPrintable(plot.summary()));
    QCOMPARE(plot.valuesText(), QStringLiteral("-0,1 1 1,1"));
    plot.loadExample(FunctionSplinePlot::Example123);
    QCOMPARE(plot.method(), FunctionSplinePlot::GlobalBSpline);
    QVERIFY2(plot.summary().contains(QStringLiteral("0,2903; -0,2242; 0,1383; -0,0344; 0,2711")), qPrintable(plot.summary()));
    QCOMPARE(plot.knotsText(), QStringLiteral("2 3,75 5"));
    plot.loadExample(FunctionSplinePlot::TorokExample);
    QCOMPARE(plot.method(), FunctionSplinePlot::Clamped);
    QCOMPARE(plot.solver(), FunctionSplinePlot::Torok);
    const std::vector<double> slopes = plot.knotSlopes();
    QCOMPARE(slopes.size(), std::size_t(4));
    QVERIFY(std::abs(slopes[1] + 2.9) < 1e-12);
    QVERIFY(std::abs(slopes[2] + 0.4) < 1e-12);
    QVERIFY2(plot.summary().contains(QStringLiteral("-2,9; -0,4")), qPrintable(plot.summary()));
    // The agreement a class reads: below 10⁻¹⁵ it is rounding, not a number such as "4,4e-16".
    QVERIFY(plot.solverDifference() < 1e-15);
    QVERIFY2(plot.summary().contains(QStringLiteral("less than 10⁻¹⁵")), qPrintable(plot.summary()));
    QVERIFY(!plot.summary().contains(QStringLiteral("e-1")));
    // Each example one undo step: back to Example 1.23, 1.30, the typed natural spline.
    plot.undo();
    QCOMPARE(plot.method(), FunctionSplinePlot::GlobalBSpline);
    plot.undo();
    QCOMPARE(plot.method(), FunctionSplinePlot::Hermite);
    plot.undo();
    QCOMPARE(plot.method(), FunctionSplinePlot::Natural);
    QCOMPARE(plot.valuesText(), QStringLiteral("1 2 3 4 5"));
}

void TestBasisPlot::torokSolverAgreesAndUndoes()
{
    // docs/requirements.md 2: Kontur offers Török's half-size system as an alternative solver and shows that both
    // agree. The seed example first, then random uniform inputs against the classical solver's curve.
    FunctionSplinePlot plot;
    QVERIFY(std::isfinite(plot.solverDifference()));
    QVERIFY(plot.solverDifference() < 1e-12);
    plot.setSolver(FunctionSplinePlot::Torok);
    QCOMPARE(plot.solver(), FunctionSplinePlot::Torok);
    std::vector<double> slopes = plot.knotSlopes();
    QCOMPARE(slopes.size(), std::size_t(4));
    QVERIFY(std::abs(slopes[1] + 2.9) < 1e-12);
    QVERIFY(std::abs(slopes[2] + 0.4) < 1e-12);
    QVERIFY(plot.summary().contains(QStringLiteral("Török's half-size system and the classical system agree")));
    QVERIFY(plot.canUndo());
    plot.undo();
    QCOMPARE(plot.solver(), FunctionSplinePlot::Classical);
    plot.redo();
    QCOMPARE(plot.solver(), FunctionSplinePlot::Torok);

    QRandomGenerator rng(2015);
    for (int trial = 0; trial < 20; ++trial) {
        kontur::FunctionSplineInput in;
        in.method = FunctionSplinePlot::Clamped;
        const int n = 2 + static_cast<int>(rng.bounded(12)); // odd and even k: both last rows of Török
        for (int i = 0; i < n; ++i)
            in.values.push_back(rng.generateDouble() * 10 - 5);
        in.a = rng.generateDouble() * 4 - 2;
        in.b = in.a + 0.5 + rng.generateDouble() * 6;
        in.derivatives = {rng.generateDouble() * 4 - 2, rng.generateDouble() * 4 - 2};
        FunctionSplinePlot classical;
        classical.setInput(in);
        in.solver = FunctionSplinePlot::Torok;
        FunctionSplinePlot torok;
        torok.setInput(in);
        QVERIFY2(torok.solverDifference() < 1e-9, qPrintable(QString::number(torok.solverDifference())));
        for (int k = 0; k < 20; ++k) {
            const double x = in.a + (in.b - in.a) * rng.generateDouble();
            QVERIFY2(std::abs(classical.splineAt(x) - torok.splineAt(x)) < 1e-9,
                     qPrintable(QStringLiteral("n = %1, x = %2").arg(n).arg(x)));
        }
    }

    // Török's procedure is for evenly spaced knots: on others the classical system is drawn, and said.
    kontur::FunctionSplineInput uneven = plot.input();
    uneven.uniform = false;
    uneven.knots = {0.0, 1.0, 2.5, 3.0};
    plot.setInput(uneven);
    QVERIFY(!std::isfinite(plot.solverDifference()));
    QVERIFY(plot.summary().contains(QStringLiteral("the classical system is drawn")));
    QVERIFY(std::abs(plot.splineAt(2.5) + 1) < 1e-12);
}

void TestBasisPlot::addToDocumentIsOneUndoStepAndExact()
{
    // Every method's spline goes into the document as the same curve: the natural one as a function
    // spline y(x) through the knots, the others as the composite curve of their cubic pieces.
    for (int method = FunctionSplinePlot::Natural; method <= FunctionSplinePlot::BellSpline; ++method) {
        EditController editor;
        FunctionSplinePlot plot;
        plot.setMethod(static_cast<FunctionSplinePlot::Method>(method));
        QVERIFY(plot.hasCurve());
        const int undoBefore = editor.undoStack()->count();
        const QString name = plot.addToDocument(&editor);
        QVERIFY2(!name.isEmpty(), qPrintable(QString::number(method)));
        QCOMPARE(editor.document()->curveCount(), 1);
        QCOMPARE(editor.undoStack()->count(), undoBefore + 1);
        const Curve &added = editor.document()->curve(0);
        QCOMPARE(added.name, name);
        QCOMPARE(added.kind(),
                 method == FunctionSplinePlot::Natural ? CurveKind::FunctionSpline : CurveKind::Composite);
        // Points of the curve are the plot's spline: y = splineAt(x) along the whole curve.
        for (int seg = 0; seg < added.segmentCount(); ++seg)
            for (int k = 0; k <= 8; ++k) {
                const Point p = added.segment(seg).eval(k / 8.0);
                QVERIFY2(std::abs(p.y() - plot.splineAt(p.x())) < 1e-9,
                         qPrintable(QStringLiteral("method %1 at x = %2").arg(method).arg(p.x())));
            }
        editor.undo();
        QCOMPARE(editor.document()->curveCount(), 0);
    }
    // Nothing drawn (a bad input never drawn): nothing added.
    EditController editor;
    FunctionSplinePlot empty;
    kontur::FunctionSplineInput none;
    none.values = {1.0};
    empty.setInput(none);
    QVERIFY(!empty.hasCurve());
    QVERIFY(empty.addToDocument(&editor).isEmpty());
    QCOMPARE(editor.document()->curveCount(), 0);
    QVERIFY(empty.addToDocument(nullptr).isEmpty());
}

void TestBasisPlot::derivativeHandleSlopeIsTheDerivative()
{
    FunctionSplinePlot plot;
    plot.setPlotArea(QSizeF(600, 300));
    kontur::PlotData data = plot.plotData();
    // Knots, then the two end handles of the clamped spline.
    QCOMPARE(data.dots.size(), std::size_t(6));
    for (std::size_t h : {std::size_t(4), std::size_t(5)}) {
        const kontur::PlotDot &handle = data.dots[h];
        QVERIFY(handle.draggable && handle.anchor);
        const QPointF d = handle.position - *handle.anchor;
        QVERIFY(std::abs(d.y() / d.x() - 0.0) < 1e-12);
    }
    // Drag the first handle so that its slope to the knot (0, 3) is 1.5: the derivative becomes 1.5.
    plot.dragDot(4, QPointF(0.2, 3.3), false);
    QVERIFY(std::abs(plot.input().derivatives[0] - 1.5) < 1e-12);
    QVERIFY(plot.canUndo()); // the drag's one command exists from its first step
    plot.dragDot(4, QPointF(0.4, 3.0 + 0.4 * 2), true);
    QVERIFY(std::abs(plot.input().derivatives[0] - 2.0) < 1e-12);
    QVERIFY(plot.canUndo());
    QCOMPARE(plot.derivativesText(), QStringLiteral("2 0"));
    data = plot.plotData();
    const QPointF d = data.dots[4].position - *data.dots[4].anchor;
    QVERIFY(std::abs(d.y() / d.x() - 2.0) < 1e-9);
    // Its distance on screen stays the same whatever the slope (56 px).
    const double sx = 600 / data.world.width();
    const double sy = 300 / data.world.height();
    QVERIFY(std::abs(std::hypot(d.x() * sx, d.y() * sy) - 56) < 1e-6);
    // A drag straight above the knot has no slope: the derivative stays.
    plot.dragDot(5, QPointF(3.0, 10.0), true);
    QCOMPARE(plot.input().derivatives[1], 0.0);
    plot.undo();
    QCOMPARE(plot.input().derivatives[0], 0.0);
}

void TestBasisPlot::knotDragIsOneUndoStep()
{
    FunctionSplinePlot plot;
    for (int step = 1; step <= 5; ++step)
        plot.dragDot(1, QPointF(1.0, 2.0 + 0.1 * step), false);
    plot.dragDot(1, QPointF(1.3, 4.0), true);
    QCOMPARE(plot.input().values[1], 4.0);
    QCOMPARE(plot.knotX()[1], 1.0); // x stays: the knots come from the interval
    QVERIFY(std::abs(plot.splineAt(1.0) - 4.0) < 1e-12);
    plot.undo();
    QCOMPARE(plot.input().values[1], 2.0);
    QVERIFY(!plot.canUndo());
    plot.redo();
    QCOMPARE(plot.input().values[1], 4.0);
}

void TestBasisPlot::dragIsOneCommandFromItsFirstStep()
{
    FunctionSplinePlot plot; // seed 001: values 3 2 -1 0.5 on [0, 3]
    QSignalSpy inputs(&plot, &FunctionSplinePlot::inputChanged);
    // 100 steps of the third knot's drag from -1 up to 1.5, then the release there.
    for (int step = 1; step <= 100; ++step) {
        plot.dragDot(2, QPointF(2.0, -1.0 + 2.5 * step / 100.0), false);
        QVERIFY(plot.canUndo()); // the command exists from the first step on
    }
    plot.dragDot(2, QPointF(2.0, 1.5), true);
    QCOMPARE(inputs.count(), 100); // the release changes nothing more
    QCOMPARE(plot.input().values, (std::vector<double>{3.0, 2.0, 1.5, 0.5}));
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 1.5 0.5")); // the field follows on release
    plot.undo();
    QVERIFY(!plot.canUndo()); // one undo step for the whole drag
    QCOMPARE(plot.input().values, (std::vector<double>{3.0, 2.0, -1.0, 0.5}));
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 -1 0.5"));
    // A drag that ends where it began leaves no undo step; the next drag is a step of its own.
    plot.redo();
    plot.dragDot(0, QPointF(0.0, 4.0), false);
    plot.dragDot(0, QPointF(0.0, 3.0), true);
    QCOMPARE(plot.input().values[0], 3.0);
    plot.undo();
    QCOMPARE(plot.input().values, (std::vector<double>{3.0, 2.0, -1.0, 0.5}));
    QVERIFY(!plot.canUndo());
}

void TestBasisPlot::errorFollowsALanguageSwitch()
{
    FunctionSplinePlot plot;
    plot.setValuesText(QStringLiteral("1 x 2"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error().text(), QStringLiteral("Function values: “x” is not a number."));
    QSignalSpy errors(&plot, &FunctionSplinePlot::errorChanged);
    QSignalSpy texts(&plot, &FunctionSplinePlot::textsChanged);
    // A switch sends LanguageChange several times, then sets the UI locale (Language::setCurrent):
    // the error (a Message, made when read) is announced again at each, and the fields are written
    // again once, in the new number format, when the switch is done.
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    QCOMPARE(errors.count(), 2);
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    QVERIFY(texts.wait());
    QCOMPARE(texts.count(), 1);
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 -1 0,5"));
    QCOMPARE(errors.count(), 2);
    QCOMPARE(plot.error().text(), QStringLiteral("Function values: “x” is not a number.")); // no translator here
}

void TestBasisPlot::methodSwitchKeepsTheCurveAndUndoes()
{
    FunctionSplinePlot plot;
    const double before = plot.splineAt(1.7);
    // Hermite takes the clamped spline's slopes at every knot: the same curve.
    plot.setMethod(FunctionSplinePlot::Hermite);
    QCOMPARE(plot.derivativeCount(), 4);
    QCOMPARE(plot.input().derivatives.size(), std::size_t(4));
    QVERIFY(std::abs(plot.splineAt(1.7) - before) < 1e-12);
    plot.setMethod(FunctionSplinePlot::Natural);
    QCOMPARE(plot.derivativeCount(), 0);
    plot.undo();
    plot.undo();
    QCOMPARE(plot.method(), FunctionSplinePlot::Clamped);
    QCOMPARE(plot.input().derivatives, (std::vector<double>{0, 0}));
    // Not uniform: the knots become editable and keep their places.
    plot.setUniformKnots(false);
    QCOMPARE(plot.knotsText(), QStringLiteral("0 1 2 3"));
    plot.setKnotsText(QStringLiteral("0 0.5 2 3"));
    QVERIFY(plot.apply());
    QCOMPARE(plot.knotX()[1], 0.5);
    QVERIFY(std::abs(plot.splineAt(0.5) - 2) < 1e-12);
}

void TestBasisPlot::rungeComparison()
{
    FunctionSplinePlot plot;
    plot.loadRungeExample(11);
    QVERIFY(plot.showPolynomial());
    QCOMPARE(plot.method(), FunctionSplinePlot::Natural);
    QCOMPARE(plot.input().values.size(), std::size_t(11));
    // Both pass through the points; between the outer ones the polynomial swings far out (Runge's
    // phenomenon: about 1.9 near ±0.96 for 11 points) while the spline stays near the function.
    for (double x : plot.knotX()) {
        QVERIFY(std::abs(plot.polynomialAt(x) - 1 / (1 + 25 * x * x)) < 1e-12);
        QVERIFY(std::abs(plot.splineAt(x) - 1 / (1 + 25 * x * x)) < 1e-12);
    }
    double worstPolynomial = 0, worstSpline = 0;
    for (int i = 0; i <= 1000; ++i) {
        const double x = -1 + 2.0 * i / 1000;
        const double f = 1 / (1 + 25 * x * x);
        worstPolynomial = std::max(worstPolynomial, std::abs(plot.polynomialAt(x) - f));
        worstSpline = std::max(worstSpline, std::abs(plot.splineAt(x) - f));
    }
    QVERIFY2(worstPolynomial > 1.9 && worstPolynomial < 2.0, qPrintable(QString::number(worstPolynomial)));
    QVERIFY2(worstSpline < 0.05, qPrintable(QString::number(worstSpline)));
    // The plot shows the function (dashed), the polynomial and the spline on the same axes.
    const kontur::PlotData data = plot.plotData();
    QCOMPARE(data.series.size(), std::size_t(3));
    QVERIFY(data.series[0].dashed);
    QVERIFY(data.world.bottom() > 1.9);
    QVERIFY(plot.summary().contains(QStringLiteral("degree 10")));
    // Editing a value leaves Runge's function out.
    plot.dragDot(5, QPointF(0, 0.5), true);
    QCOMPARE(plot.plotData().series.size(), std::size_t(2));
}

void TestBasisPlot::interpolatesOverRandomInputs()
{
    QRandomGenerator rng(3);
    for (int trial = 0; trial < 40; ++trial) {
        kontur::FunctionSplineInput in;
        in.method = static_cast<int>(rng.bounded(4));
        in.uniform = rng.bounded(2) == 0;
        const int n = 2 + static_cast<int>(rng.bounded(15));
        double x = rng.generateDouble();
        for (int i = 0; i < n; ++i) {
            in.values.push_back(rng.generateDouble() * 20 - 10);
            in.knots.push_back(x);
            x += 0.1 + rng.generateDouble();
        }
        in.a = in.knots.front();
        in.b = in.knots.back();
        const int derivatives =
            in.method == FunctionSplinePlot::Hermite ? n : (in.method == FunctionSplinePlot::Natural ? 0 : 2);
        for (int i = 0; i < derivatives; ++i)
            in.derivatives.push_back(rng.generateDouble() * 6 - 3);
        FunctionSplinePlot plot;
        plot.setInput(in);
        const std::vector<double> xs = plot.knotX();
        for (int i = 0; i < n; ++i) {
            QVERIFY2(std::abs(plot.splineAt(xs[static_cast<std::size_t>(i)]) - in.values[static_cast<std::size_t>(i)]) <
                         1e-9,
                     qPrintable(QStringLiteral("trial %1, method %2, knot %3").arg(trial).arg(in.method).arg(i)));
            QVERIFY(std::abs(plot.polynomialAt(xs[static_cast<std::size_t>(i)]) -
                             in.values[static_cast<std::size_t>(i)]) < 1e-6);
        }
        // The input derivatives are the spline's slopes at their knots.
        const std::vector<double> slopes = plot.knotSlopes();
        if (in.method == FunctionSplinePlot::Hermite)
            for (int i = 0; i < n; ++i)
                QVERIFY(std::abs(slopes[static_cast<std::size_t>(i)] - in.derivatives[static_cast<std::size_t>(i)]) <
                        1e-9);
        if (derivatives == 2) {
            QVERIFY(std::abs(slopes.front() - in.derivatives[0]) < 1e-7);
            QVERIFY(std::abs(slopes.back() - in.derivatives[1]) < 1e-7);
        }
    }
}

void TestBasisPlot::bellSplineExample115()
{
    // Seed 001 Example 1.15: knots 0..9, c = (−1/3, 1/5, 1/4, −1/4, 1/3, −3/4):
    // P(3) = 43/60, P(4) = 19/20, P(5) = −5/12, P(6) = 1/3 (docs/requirements.md 2).
    QLocale::setDefault(QLocale(QStringLiteral("sk")));
    FunctionSplinePlot plot;
    plot.setMethod(FunctionSplinePlot::BellSpline);
    QCOMPARE(plot.derivativeCount(), 0);
    plot.setValuesText(QStringLiteral("-0,333333333333333 0,2 0,25 -0,25 0,333333333333333 -0,75"));
    plot.setIntervalText(QStringLiteral("0 9"));
    QVERIFY2(plot.apply(), qPrintable(plot.error().text()));
    QCOMPARE(plot.knotX().size(), std::size_t(10));
    QCOMPARE(plot.knotX()[4], 4.0);
    QVERIFY(std::abs(plot.splineAt(3) - 43.0 / 60) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(4) - 19.0 / 20) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(5) + 5.0 / 12) < 1e-12);
    QVERIFY(std::abs(plot.splineAt(6) - 1.0 / 3) < 1e-12);
    QVERIFY2(plot.summary().contains(QStringLiteral("0,7167")), qPrintable(plot.summary()));
    // The dots stand at the Greville abscissae 2..7 with height 6 c_i; dragging one sets c_i.
    QCOMPARE(plot.dotX().front(), 2.0);
    QVERIFY(std::abs(plot.dotY()[1] - 6 * 0.2) < 1e-12);
    plot.dragDot(1, QPointF(3, 3.0), true);
    QVERIFY(std::abs(plot.input().values[1] - 0.5) < 1e-12);
    // Not uniform: it takes four knots more than values.
    plot.setUniformKnots(false);
    plot.setKnotsText(QStringLiteral("0 1 2 3 4 5 6 7 8"));
    QVERIFY(!plot.apply());
    QCOMPARE(plot.error(), Message(Message::KnotsCountBells, {10}));
    QCOMPARE(plot.error().text(), QStringLiteral("Knots: give 10 number(s), four more than the number of values."));
    plot.setKnotsText(QStringLiteral("0 1 2 3 4 5 6 7 8 10"));
    QVERIFY2(plot.apply(), qPrintable(plot.error().text()));
    // Back to an interpolating spline: the knots are spread again over the same range.
    plot.setMethod(FunctionSplinePlot::Natural);
    QCOMPARE(plot.knotX().size(), std::size_t(6));
    QCOMPARE(plot.knotX().back(), 10.0);
}

// --- seed 003's segments ---

void TestBasisPlot::practicumFunctionSegment()
{
    // KG-202: P0 = (0, 1), P1 = (4, 2), k0 = 1, k1 = -1/2, t = 4:
    // a3 = 3(y1 - y0)/t² - (2k0 + k1)/t = 3/16 - 3/8, a4 = 2(y0 - y1)/t³ + (k0 + k1)/t² = -2/64 + 1/32.
    kontur::PracticumPlot plot;
    QCOMPARE(plot.mode(), kontur::PracticumPlot::FunctionSegment);
    QVERIFY(plot.details().contains(QStringLiteral("a3 = -0.188")));
    QVERIFY(plot.details().contains(QStringLiteral("a4 = 0.000")));
    const QPolygonF &line = plot.polyline();
    QCOMPARE(line.size(), plot.linesPerSegment() + 1);
    QCOMPARE(line.first(), QPointF(0, 1));
    QVERIFY(std::abs(line.last().y() - 2) < 1e-12);
    // y = 1 + x - 3/16 x² at x = 2.
    QVERIFY(std::abs(line[line.size() / 2].y() - (1 + 2 - 0.75)) < 1e-12);
    // A vertical guide vector has no slope: an error, and nothing drawn.
    QSignalSpy errors(&plot, &kontur::PracticumPlot::errorChanged);
    plot.dragDot(2, QPointF(0, 3), true);
    QCOMPARE(plot.error().id, Message::GuideVertical);
    QCOMPARE(plot.error().text(),
             QStringLiteral("A vertical guide vector has no slope dy/dx: a function segment needs one."));
    QCOMPARE(errors.count(), 1);
    QVERIFY(plot.polyline().isEmpty());
    // The end points one above the other: no function segment either.
    plot.undo();
    QVERIFY(plot.error().isEmpty());
    plot.dragDot(1, QPointF(0, 2), true);
    QCOMPARE(plot.error().id, Message::SegmentSameX);
    QVERIFY(plot.polyline().isEmpty());
    // As a parametric segment, end points on each other are the fault.
    plot.setMode(kontur::PracticumPlot::ParametricSegment);
    plot.dragDot(1, plot.input().points.front(), true);
    QCOMPARE(plot.error().id, Message::SegmentDegenerate);
    QVERIFY(plot.polyline().isEmpty());
    // A spline with two neighbouring points on each other.
    plot.setMode(kontur::PracticumPlot::MultiSegment);
    plot.dragDot(1, plot.input().points.front(), true);
    QCOMPARE(plot.error().id, Message::SplineDegenerate);
    QVERIFY(plot.polyline().isEmpty());
    // A language switch announces the error again, to be read in the new language.
    const qsizetype announced = errors.count();
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    QCOMPARE(errors.count(), announced + 1);
    QCOMPARE(plot.error().id, Message::SplineDegenerate);
}

void TestBasisPlot::practicumDebugExample()
{
    // KG-203 §3.3: 4 collinear points with step (30, 20), guide vectors along it: T = 36.055,
    // K_i = (0.832, 0.554).
    kontur::PracticumPlot plot;
    plot.loadDebugExample();
    QCOMPARE(plot.mode(), kontur::PracticumPlot::MultiSegment);
    QVERIFY2(plot.details().contains(QStringLiteral("36.056")), qPrintable(plot.details()));
    QCOMPARE(plot.details().count(QStringLiteral("(0.832; 0.555)")), 4);
    // The spline is the straight line through the points.
    for (const QPointF &p : plot.polyline())
        QVERIFY(std::abs(p.y() - p.x() * 2 / 3) < 1e-9);
}

void TestBasisPlot::practicumLinesPerSegmentAndDrags()
{
    kontur::PracticumPlot plot;
    plot.setMode(kontur::PracticumPlot::MultiSegment);
    plot.setLinesPerSegment(3);
    // 5 points, 4 segments of 3 lines each: 13 points through every knot.
    QCOMPARE(plot.polyline().size(), 13);
    for (int i = 0; i < 5; ++i)
        QVERIFY(QLineF(plot.polyline()[3 * i], plot.input().points[static_cast<std::size_t>(i)]).length() < 1e-9);
    plot.setByPoints(true);
    QVERIFY(plot.plotData().series.front().asDots);
    // Dragging the first point carries its guide vector; the whole drag is one undo step.
    const QPointF grip = plot.input().guideStart;
    const int before = plot.canUndo() ? 1 : 0;
    plot.dragDot(0, QPointF(0.5, 0.5), false);
    plot.dragDot(0, QPointF(1, 1), true);
    QVERIFY(before == 1);
    QCOMPARE(plot.input().guideStart, grip + QPointF(1, 1));
    plot.undo();
    QCOMPARE(plot.input().points.front(), QPointF(0, 0));
    QVERIFY(plot.input().byPoints);
    // The drawn range has one scale on both axes, so directions are true.
    plot.setPlotArea(QSizeF(600, 300));
    const QRectF world = plot.plotData().world;
    QVERIFY(std::abs(world.width() / world.height() - 2.0) < 1e-9);
}

QTEST_GUILESS_MAIN(TestBasisPlot)
#include "tst_basisplot.moc"
