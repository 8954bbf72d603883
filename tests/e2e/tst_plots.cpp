// The teaching plots in the real window (issue 9 part B): the basis functions under the canvas follow
// the selected curve and point and share t with the de Casteljau view; the function spline view takes
// `3 2 -1 0,5` under the Slovak UI, its derivative handles are dragged with the mouse and undone; the
// Runge comparison and seed 003's segments draw what the geometry says (pixels checked at computed
// places); and the views fit at tablet and desktop sizes.
#include "windowtest.h"

#include "../curveids.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/language.h"
#include "app/plotview.h"
#include "models/controllers/editcontroller.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "models/teaching/basisplot.h"
#include "models/teaching/functionspline.h"
#include "models/teaching/practicumplot.h"

#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

#include <memory>

using kontur::BasisPlot;
using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::FunctionSplinePlot;
using kontur::PlotView;
using kontur::PracticumPlot;

class TestPlots final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    // The pages are popups: QObjects, not items of the window's tree.
    bool isOpen(const QString &name) const
    {
        QObject *popup = m_window->findChild<QObject *>(name);
        return popup && popup->property("opened").toBool();
    }
    template <typename T> T *object(const QString &name) const { return m_window->findChild<T *>(name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }
    QPoint scenePoint(PlotView *view, QPointF world) const { return view->mapToScene(view->toScreen(world)).toPoint(); }
    void chooseTeaching(const QString &entry)
    {
        // No page or menu still closing over the tool bar.
        for (const char *page : {"functionSplineView", "practicumView", "teachingMenu"}) {
            QObject *popup = m_window->findChild<QObject *>(QLatin1String(page));
            QTRY_VERIFY(!popup || !popup->property("visible").toBool());
        }
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("teachingMenuButton"))));
        QQuickItem *menuItem = nullptr;
        QTRY_VERIFY((menuItem = item(entry)) && menuItem->isVisible() && menuItem->width() > 0);
        QVERIFY(kontur::test::clickMenuItem(m_window, menuItem));
    }
    // A left-button drag in steps, with the button held in every move (as a real mouse sends it).
    void drag(QPoint from, QPoint to)
    {
        QTest::mousePress(m_window, Qt::LeftButton, {}, from);
        for (int step = 1; step <= 6; ++step) {
            const QPoint at = from + (to - from) * step / 6;
            QMouseEvent move(QEvent::MouseMove, at, m_window->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                             Qt::NoModifier);
            QGuiApplication::sendEvent(m_window, &move);
        }
        QTest::mouseRelease(m_window, Qt::LeftButton, {}, to);
    }
    // The labels the view wrote last touch no axis, no sampled curve and no other label.
    void checkLabels(PlotView *view, const QString &what)
    {
        QVERIFY(kontur::test::settled(m_window));
        const std::vector<QRectF> labels = view->labelRects();
        QVERIFY2(!labels.empty(), qPrintable(what));
        const kontur::PlotData data = view->source()->plotData();
        const auto meets = [](const QLineF &line, const QRectF &r) {
            if (r.contains(line.p1()) || r.contains(line.p2()))
                return true;
            for (const QLineF &edge : {QLineF(r.topLeft(), r.topRight()), QLineF(r.topRight(), r.bottomRight()),
                                       QLineF(r.bottomRight(), r.bottomLeft()), QLineF(r.bottomLeft(), r.topLeft())})
                if (line.intersects(edge, nullptr) == QLineF::BoundedIntersection)
                    return true;
            return false;
        };
        for (std::size_t i = 0; i < labels.size(); ++i) {
            const QRectF &r = labels[i];
            const QString where = QStringLiteral("%1: label %2 at %3,%4 %5×%6")
                                      .arg(what)
                                      .arg(i)
                                      .arg(r.x())
                                      .arg(r.y())
                                      .arg(r.width())
                                      .arg(r.height());
            for (const QLineF &axis : view->axisLines())
                QVERIFY2(!meets(axis, r), qPrintable(where + QStringLiteral(" on an axis")));
            for (const kontur::PlotSeries &series : data.series)
                for (qsizetype k = 1; k < series.points.size(); ++k)
                    QVERIFY2(!meets(QLineF(view->toScreen(series.points[k - 1]), view->toScreen(series.points[k])), r),
                             qPrintable(where + QStringLiteral(" on the curve ") + series.label));
            for (std::size_t j = i + 1; j < labels.size(); ++j)
                QVERIFY2(!labels[j].intersects(r), qPrintable(where + QStringLiteral(" on another label")));
        }
    }
    // Screenshots for a person to look at, when KONTUR_SCREENSHOT_DIR is set.
    void saveShot(const QString &name) const
    {
        const QString dir = qEnvironmentVariable("KONTUR_SCREENSHOT_DIR");
        if (!dir.isEmpty())
            m_window->grabWindow().save(QStringLiteral("%1/plots-%2.png").arg(dir, name));
    }
    // Whether a pixel near `at` (within 3 px: anti-aliasing) has about this colour.
    static bool colourNear(const QImage &shot, QPoint at, const QColor &colour)
    {
        const qreal dpr = shot.devicePixelRatio();
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) {
                const QPoint p((at.x() + dx) * dpr, (at.y() + dy) * dpr);
                if (!shot.rect().contains(p))
                    continue;
                const QColor c(shot.pixel(p));
                if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                        std::abs(c.blue() - colour.blue()) <
                    90)
                    return true;
            }
        return false;
    }

private Q_SLOTS:
    void initTestCase();
    void init();
    void basisPlotFollowsSelectionAndSharesT();
    void functionSplineTakesSlovakInput();
    void derivativeHandleDraggedAndUndone();
    void rungeComparisonDrawsBothCurves();
    void practicumSegments();
    void layoutAtTabletAndDesktopSizes_data();
    void layoutAtTabletAndDesktopSizes();
    void labelsClearOfCurvesAndAxes_data();
    void labelsClearOfCurvesAndAxes();
    void cleanupTestCase() { m_engine.reset(); }
};

void TestPlots::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
}

// Each test starts from the same window: no page open, no basis panel, an empty document, in
// English, at the first size.
void TestPlots::init()
{
    for (const char *page : {"functionSplineView", "practicumView"}) {
        // A page is made when first opened.
        QObject *popup = m_window->findChild<QObject *>(QLatin1String(page));
        if (!popup)
            continue;
        if (popup->property("visible").toBool())
            QVERIFY(QMetaObject::invokeMethod(popup, "close"));
        QTRY_VERIFY(!popup->property("visible").toBool());
    }
    if (QQuickItem *panel = item(QStringLiteral("basisPanel")); panel && panel->isVisible()) {
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("basisCloseButton"))));
        QTRY_VERIFY(!panel->isVisible());
    }
    auto *language = m_engine->findChild<kontur::Language *>();
    QVERIFY(language && language->setCurrent(QStringLiteral("en")));
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
}

void TestPlots::basisPlotFollowsSelectionAndSharesT()
{
    chooseTeaching(QStringLiteral("teachingBasis"));
    QQuickItem *panel = item(QStringLiteral("basisPanel"));
    QTRY_VERIFY(panel && panel->isVisible());
    auto *basis = object<BasisPlot>(QStringLiteral("basisPlot"));
    auto *view = object<PlotView>(QStringLiteral("basisPlotView"));
    QVERIFY(basis && view);
    QTRY_VERIFY(view->height() > 80);

    m_editor->commands()->addCurves(
        {Curve::make(CurveKind::Bezier, {{-200, -100}, {-100, 150}, {100, 150}, {200, -100}})}, QStringLiteral("test"));
    kontur::test::selectAt(*m_editor, 0, 1);
    QCOMPARE(basis->shownFamily(), BasisPlot::Bernstein);
    QCOMPARE(basis->highlighted(), 1);
    // The highlighted B_{1,3} is drawn in the highlight colour where the geometry puts it: its
    // maximum 4/9 at t = 1/3 — and an unhighlighted one elsewhere is not.
    QVERIFY(kontur::test::settled(m_window));
    QImage shot = m_window->grabWindow();
    QVERIFY(colourNear(shot, scenePoint(view, QPointF(1.0 / 3, 4.0 / 9)), QColor(0xc6, 0x28, 0x28)));
    QVERIFY(!colourNear(shot, scenePoint(view, QPointF(0.7, 0.343)), QColor(0xc6, 0x28, 0x28))); // B_{3,3} only

    // Dragging in the plot moves t, and the de Casteljau view's t with it.
    QObject *teaching = m_window->findChild<QObject *>(QStringLiteral("teaching"));
    QVERIFY(teaching);
    const QPoint from = scenePoint(view, QPointF(0.5, 0.5));
    const QPoint to = scenePoint(view, QPointF(0.25, 0.5));
    drag(from, to);
    QTRY_VERIFY(std::abs(basis->parameter() - 0.25) < 0.01);
    QTRY_VERIFY(std::abs(teaching->property("parameter").toDouble() - basis->parameter()) < 1e-12);
    // And the other way round.
    teaching->setProperty("parameter", 0.8);
    QTRY_COMPARE(basis->parameter(), 0.8);
    // The arrow keys move it too.
    view->forceActiveFocus();
    QTest::keyClick(m_window, Qt::Key_Left);
    QTRY_VERIFY(std::abs(basis->parameter() - 0.79) < 1e-9);

    // A B-spline shows its knot vector under the plot.
    m_editor->commands()->addCurves(
        {Curve::make(CurveKind::BSpline,
                     {{0, 0}, {50, 80}, {100, 0}, {150, 80}, {200, 0}, {250, 80}, {300, 0}, {350, 80}})},
        QStringLiteral("test"));
    m_editor->selection()->selectRow(1);
    QTRY_COMPARE(item(QStringLiteral("basisKnotText"))->property("text").toString(),
                 QStringLiteral("Knot vector: 0 0 0 0 1 2 3 4 5 5 5 5"));
    kontur::test::selectAt(*m_editor, 1, 3);
    QVERIFY(kontur::test::settled(m_window));
    saveShot(QStringLiteral("bspline"));
    // Seed 001's bells, chosen in the plot's own box.
    basis->setFamily(BasisPlot::Bell);
    QVERIFY(kontur::test::settled(m_window));
    saveShot(QStringLiteral("bells"));
    basis->setFamily(BasisPlot::Auto);
    // Closed from its own button.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("basisCloseButton"))));
    QTRY_VERIFY(!panel->isVisible());
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
}

void TestPlots::functionSplineTakesSlovakInput()
{
    auto *language = m_engine->findChild<kontur::Language *>();
    QVERIFY(language->setCurrent(QStringLiteral("sk")));
    chooseTeaching(QStringLiteral("teachingFunctionSpline"));
    QTRY_VERIFY(isOpen(QStringLiteral("functionSplineView")));
    auto *spline = object<FunctionSplinePlot>(QStringLiteral("functionSplinePlot"));
    QVERIFY(spline);
    // The list of methods speaks the language, and keeps the method shown across a switch.
    QQuickItem *methodBox = item(QStringLiteral("functionSplineMethod"));
    QVERIFY(methodBox);
    const int method = spline->method();
    QTRY_COMPARE(methodBox->property("displayText").toString(), spline->methodNames().value(method));
    QVERIFY(language->setCurrent(QStringLiteral("en")));
    QTRY_COMPARE(spline->methodNames().value(FunctionSplinePlot::Clamped), QStringLiteral("Clamped spline (C-spline)"));
    QTRY_COMPARE(methodBox->property("displayText").toString(), spline->methodNames().value(method));
    QCOMPARE(methodBox->property("currentIndex").toInt(), method);
    QVERIFY(language->setCurrent(QStringLiteral("sk")));
    QTRY_VERIFY(spline->methodNames().value(FunctionSplinePlot::Clamped) !=
                QStringLiteral("Clamped spline (C-spline)"));
    QTRY_COMPARE(methodBox->property("displayText").toString(), spline->methodNames().value(method));
    // Something else first, so the typed values are a change.
    spline->setValuesText(QStringLiteral("1 1"));
    QVERIFY(spline->apply());

    QQuickItem *field = item(QStringLiteral("functionValuesField"));
    QTRY_VERIFY(field && field->isVisible());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(field));
    QTRY_VERIFY(field->hasActiveFocus());
    field->setProperty("text", QString()); // as select-all and typing over it would
    for (const char c : QByteArray("3 2 -1 0,5"))
        QTest::keyClick(m_window, c);
    kontur::test::ensureVisible(item(QStringLiteral("functionSplineDraw")));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("functionSplineDraw"))));
    QTRY_COMPARE(spline->input().values, (std::vector<double>{3, 2, -1, 0.5}));
    QVERIFY(spline->error().isEmpty());
    // Numbers are shown the Slovak way: the slopes -2,9 and -0,4 of docs/requirements.md 2.
    QTRY_VERIFY(
        item(QStringLiteral("functionSplineSummary"))->property("text").toString().contains(QStringLiteral("-2,9")));

    // The curve is drawn where the spline is: at x = 0.5 and 2.5, in the spline's colour.
    auto *view = object<PlotView>(QStringLiteral("functionSplinePlotView"));
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    for (double x : {0.5, 1.5, 2.5})
        QVERIFY2(colourNear(shot, scenePoint(view, QPointF(x, spline->splineAt(x))), QColor(0x1f, 0x4e, 0x9c)),
                 qPrintable(QString::number(x)));
    // Not where it is not.
    QVERIFY(!colourNear(shot, scenePoint(view, QPointF(1.5, spline->splineAt(1.5) + 1)), QColor(0x1f, 0x4e, 0x9c)));

    // A bad number: a message naming it, the text kept, the curve unchanged.
    field->setProperty("text", QStringLiteral("3 2 x 0,5"));
    spline->setValuesText(QStringLiteral("3 2 x 0,5"));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("functionSplineDraw"))));
    QTRY_VERIFY(item(QStringLiteral("functionSplineError"))->isVisible());
    QCOMPARE(field->property("text").toString(), QStringLiteral("3 2 x 0,5"));
    QCOMPARE(spline->input().values, (std::vector<double>{3, 2, -1, 0.5}));
    spline->refreshTexts();
    QVERIFY(language->setCurrent(QStringLiteral("en")));
}

void TestPlots::derivativeHandleDraggedAndUndone()
{
    chooseTeaching(QStringLiteral("teachingFunctionSpline"));
    auto *spline = object<FunctionSplinePlot>(QStringLiteral("functionSplinePlot"));
    auto *view = object<PlotView>(QStringLiteral("functionSplinePlotView"));
    QVERIFY(spline && view);
    QTRY_VERIFY(isOpen(QStringLiteral("functionSplineView")));
    // Seed 001's example: values 3 2 -1 0.5 on [0, 3], clamped with zero end slopes.
    kontur::FunctionSplineInput seed;
    seed.method = FunctionSplinePlot::Clamped;
    seed.values = {3.0, 2.0, -1.0, 0.5};
    seed.derivatives = {0.0, 0.0};
    spline->setInput(seed);
    spline->refreshTexts();
    QCOMPARE(spline->method(), FunctionSplinePlot::Clamped);
    const std::vector<double> before = spline->input().derivatives;
    QCOMPARE(before, (std::vector<double>{0, 0}));
    // The first handle is dot 4 (after the 4 knots); drag it so its slope to the knot (0, 3) is 1.
    const kontur::PlotData data = spline->plotData();
    const QPointF handle = data.dots[4].position;
    const QPoint from = scenePoint(view, handle);
    const QPoint to = scenePoint(view, QPointF(0.3, 3.3));
    drag(from, to);
    // Within the pixel rounding of the mouse position.
    QTRY_VERIFY(std::abs(spline->input().derivatives[0] - 1.0) < 0.05);
    // The field shows the dragged derivative (1 within the same rounding: 0.98 as well as 1.02).
    QTRY_VERIFY(std::abs(QLocale::c().toDouble(
                    item(QStringLiteral("derivativesField"))->property("text").toString().section(QLatin1Char(' '), 0, 0)) -
                1.0) < 0.05);
    // The spline's slope at the knot follows.
    QVERIFY(std::abs(spline->knotSlopes().front() - spline->input().derivatives[0]) < 1e-9);
    // Ctrl+Z in the view undoes the whole drag in one step.
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(spline->input().derivatives, before);
    QCOMPARE(m_editor->document()->curveCount(), 0); // the document is not touched
    // Török's solver chosen from its list: the same slopes, one step of the view's undo.
    QQuickItem *solver = item(QStringLiteral("functionSplineSolver"));
    QVERIFY(solver && solver->isVisible());
    QVERIFY(QMetaObject::invokeMethod(solver, "activated", Q_ARG(int, FunctionSplinePlot::Torok)));
    QTRY_COMPARE(spline->solver(), FunctionSplinePlot::Torok);
    QVERIFY(std::abs(spline->knotSlopes()[1] + 2.9) < 1e-12);
    QVERIFY(spline->summary().contains(QStringLiteral("agree")));
    // "Add to document": the spline joins the drawing as one undo step there; the view stays open.
    QQuickItem *add = item(QStringLiteral("functionSplineAdd"));
    QVERIFY(add && add->isVisible() && add->isEnabled());
    kontur::test::ensureVisible(add);
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(add));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(m_editor->document()->curve(0).kind(), CurveKind::Composite);
    QTRY_VERIFY(item(QStringLiteral("functionSplineAdded"))->isVisible());
    saveShot(QStringLiteral("function-spline-added"));
    QVERIFY(isOpen(QStringLiteral("functionSplineView")));
    // Closed from its own button.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("functionSplineClose"))));
    QTRY_VERIFY(!isOpen(QStringLiteral("functionSplineView")));
}

void TestPlots::rungeComparisonDrawsBothCurves()
{
    chooseTeaching(QStringLiteral("teachingRunge"));
    QTRY_VERIFY(isOpen(QStringLiteral("functionSplineView")));
    auto *spline = object<FunctionSplinePlot>(QStringLiteral("functionSplinePlot"));
    auto *view = object<PlotView>(QStringLiteral("functionSplinePlotView"));
    QVERIFY(spline->showPolynomial());
    QCOMPARE(spline->input().values.size(), std::size_t(11));
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    // The polynomial's swing near the ends (Runge) in red, the spline near the function in blue.
    for (double x : {-0.95, 0.95, -0.7})
        QVERIFY2(colourNear(shot, scenePoint(view, QPointF(x, spline->polynomialAt(x))), QColor(0xc6, 0x28, 0x28)),
                 qPrintable(QString::number(x)));
    QVERIFY(spline->polynomialAt(0.95) > 1.5);
    for (double x : {-0.95, 0.3, 0.95})
        QVERIFY(colourNear(shot, scenePoint(view, QPointF(x, spline->splineAt(x))), QColor(0x1f, 0x4e, 0x9c)));
    saveShot(QStringLiteral("runge"));
    // Seed 001's B-spline of bells from the same page: the curve where the geometry says.
    spline->setShowPolynomial(false);
    spline->setMethod(FunctionSplinePlot::BellSpline);
    QVERIFY(kontur::test::settled(m_window));
    const QImage bells = m_window->grabWindow();
    saveShot(QStringLiteral("bell-spline"));
    for (double x : {-0.3, 0.0, 0.3})
        QVERIFY(colourNear(bells, scenePoint(view, QPointF(x, spline->splineAt(x))), QColor(0x1f, 0x4e, 0x9c)));
    spline->undo();
    QCOMPARE(spline->method(), FunctionSplinePlot::Natural);
    // Escape closes the view.
    QTest::keyClick(m_window, Qt::Key_Escape);
    QTRY_VERIFY(!isOpen(QStringLiteral("functionSplineView")));
}

void TestPlots::practicumSegments()
{
    chooseTeaching(QStringLiteral("teachingPracticum"));
    QTRY_VERIFY(isOpen(QStringLiteral("practicumView")));
    auto *practicum = object<PracticumPlot>(QStringLiteral("practicumPlot"));
    auto *view = object<PlotView>(QStringLiteral("practicumPlotView"));
    QVERIFY(practicum && view);
    QVERIFY(kontur::test::settled(m_window));
    QImage shot = m_window->grabWindow();
    saveShot(QStringLiteral("practicum"));
    // The segment at its middle sample: y = 1 + x - 3/16 x² at x = 2.
    QVERIFY(colourNear(shot, scenePoint(view, QPointF(2, 2.25)), QColor(0x1f, 0x4e, 0x9c)));
    // One line per segment: the chord, so the middle is on the straight line from P0 to P1.
    practicum->setLinesPerSegment(1);
    QVERIFY(kontur::test::settled(m_window));
    shot = m_window->grabWindow();
    QVERIFY(colourNear(shot, scenePoint(view, QPointF(2, 1.5)), QColor(0x1f, 0x4e, 0x9c)));
    QVERIFY(!colourNear(shot, scenePoint(view, QPointF(2, 2.25)), QColor(0x1f, 0x4e, 0x9c)));
    // Drag the end guide vector's grip with the mouse: one undo step.
    const kontur::PlotData data = practicum->plotData();
    const QPoint from = scenePoint(view, data.dots[3].position);
    const QPoint to = scenePoint(view, QPointF(5, 3));
    drag(from, to);
    QTRY_VERIFY(QLineF(practicum->input().guideEnd, QPointF(5, 3)).length() < 0.05);
    QVERIFY(!practicum->details().contains(QStringLiteral("k1 = -0.500")));
    practicum->undo();
    QCOMPARE(practicum->input().guideEnd, QPointF(5, 1.5));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("practicumClose"))));
    QTRY_VERIFY(!isOpen(QStringLiteral("practicumView")));
}

void TestPlots::labelsClearOfCurvesAndAxes_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addRow("1280x800") << QSize(1280, 800);
    QTest::addRow("1920x1080") << QSize(1920, 1080);
}

// The curves' labels in the Runge comparison (the y axis ran through them) and in the basis plot
// (they sat on the curves), Hermite's derivative bases among them, clear of every axis and curve.
void TestPlots::labelsClearOfCurvesAndAxes()
{
    QFETCH(QSize, size);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    chooseTeaching(QStringLiteral("teachingRunge"));
    QTRY_VERIFY(isOpen(QStringLiteral("functionSplineView")));
    auto *view = object<PlotView>(QStringLiteral("functionSplinePlotView"));
    QVERIFY(view);
    checkLabels(view, QStringLiteral("Runge"));
    saveShot(QStringLiteral("labels-runge-%1").arg(size.width()));
    QTest::keyClick(m_window, Qt::Key_Escape);
    QTRY_VERIFY(!isOpen(QStringLiteral("functionSplineView")));

    m_editor->commands()->addCurves(
        {Curve::make(CurveKind::Bezier, {{-200, -100}, {-100, 150}, {100, 150}, {200, -100}})}, QStringLiteral("test"));
    kontur::test::selectAt(*m_editor, 0, 1);
    chooseTeaching(QStringLiteral("teachingBasis"));
    QTRY_VERIFY(item(QStringLiteral("basisPanel")) && item(QStringLiteral("basisPanel"))->isVisible());
    auto *basis = object<BasisPlot>(QStringLiteral("basisPlot"));
    auto *basisView = object<PlotView>(QStringLiteral("basisPlotView"));
    QVERIFY(basis && basisView);
    for (const auto family : {BasisPlot::Bernstein, BasisPlot::BSpline, BasisPlot::Bell, BasisPlot::Hermite}) {
        basis->setFamily(family);
        checkLabels(basisView, QStringLiteral("basis family %1").arg(static_cast<int>(family)));
    }
    saveShot(QStringLiteral("labels-hermite-%1").arg(size.width()));
    basis->setFamily(BasisPlot::Auto);
}

void TestPlots::layoutAtTabletAndDesktopSizes_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addRow("tablet 800x1280") << QSize(800, 1280);
    QTest::addRow("desktop 1280x720") << QSize(1280, 720);
}

void TestPlots::layoutAtTabletAndDesktopSizes()
{
    QFETCH(QSize, size);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    chooseTeaching(QStringLiteral("teachingBasis"));
    QQuickItem *panel = item(QStringLiteral("basisPanel"));
    QTRY_VERIFY(panel->isVisible());
    QQuickItem *canvas = item(QStringLiteral("canvas"));
    auto *basisView = object<PlotView>(QStringLiteral("basisPlotView"));
    QTRY_VERIFY(basisView->height() >= 80);
    // The canvas keeps most of the room, and the panel lies inside the window above the message line.
    QVERIFY2(canvas->height() >= size.height() * 0.35, qPrintable(QString::number(canvas->height())));
    const QRectF panelRect = panel->mapRectToScene(QRectF(0, 0, panel->width(), panel->height()));
    QVERIFY(panelRect.bottom() <= size.height() && panelRect.right() <= size.width() + 0.5);
    QVERIFY(panelRect.top() >= canvas->mapRectToScene(QRectF(0, 0, canvas->width(), canvas->height())).bottom() - 0.5);
    saveShot(QStringLiteral("basis-%1x%2").arg(size.width()).arg(size.height()));

    // The function spline page: inputs and a plot of useful size, side by side or stacked.
    chooseTeaching(QStringLiteral("teachingFunctionSpline"));
    QTRY_VERIFY(isOpen(QStringLiteral("functionSplineView")));
    auto *plot = object<PlotView>(QStringLiteral("functionSplinePlotView"));
    QTRY_VERIFY(plot->height() >= 250 && plot->width() >= 380);
    QQuickItem *draw = item(QStringLiteral("functionSplineDraw"));
    kontur::test::ensureVisible(draw); // the inputs scroll: a control scrolled to lies in them, not on the plot
    QVERIFY(kontur::test::settled(m_window));
    const QRectF drawRect = draw->mapRectToScene(QRectF(0, 0, draw->width(), draw->height()));
    const QRectF plotRect = plot->mapRectToScene(QRectF(0, 0, plot->width(), plot->height()));
    QVERIFY(!drawRect.intersects(plotRect));
    QVERIFY(draw->height() >= 44);
    saveShot(QStringLiteral("function-spline-%1x%2").arg(size.width()).arg(size.height()));
    QTest::keyClick(m_window, Qt::Key_Escape);
    QTRY_VERIFY(!m_window->findChild<QObject *>(QStringLiteral("functionSplineView"))->property("visible").toBool());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("basisCloseButton"))));
    QTRY_VERIFY(!panel->isVisible());
}

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"
