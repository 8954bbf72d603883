// End-to-end: the real main window. Four clicks make a curve, a drag moves a point, a two-finger
// pinch and the wheel zoom, the language switches at run time; the grabbed window shows the curve
// where the geometry says it is. Runs on the software backend and on OpenGL (see CMakeLists.txt).
#include "windowtest.h"

#include "../curveids.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"

#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QtTest>

#include <array>
#include <memory>

using kontur::CurveCanvas;
using kontur::EditController;

class TestE2E final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const char *objectName) const
    {
        auto *found = m_window->contentItem()->findChild<QQuickItem *>(QLatin1String(objectName));
        if (!found)
            found = m_window->findChild<QQuickItem *>(QLatin1String(objectName));
        return found;
    }
    QPoint centerOf(const char *objectName) const
    {
        QQuickItem *it = item(objectName);
        return it ? it->mapToScene(QPointF(it->width() / 2, it->height() / 2)).toPoint() : QPoint();
    }
    // Canvas item coordinates → window coordinates.
    QPointF scene(QPointF canvasPos) const { return m_canvas->mapToScene(canvasPos); }
    QPointF sceneOfWorld(const kontur::geo::Point &p) const { return scene(m_canvas->toScreen(QPointF(p.x(), p.y()))); }
    QImage grab()
    {
        m_canvas->update();
        if (!kontur::test::settled(m_window))
            return {};
        QImage image = m_window->grabWindow();
        if (const QByteArray dir = qgetenv("KONTUR_SCREENSHOT_DIR"); !dir.isEmpty())
            image.save(QStringLiteral("%1/%2-%3.png")
                           .arg(QString::fromLocal8Bit(dir), m_canvas->graphicsApi(),
                                QString::fromLatin1(QTest::currentTestFunction())));
        return image;
    }
    void verifyCurveDrawn(const QImage &image, const kontur::Curve &curve)
    {
        const kontur::geo::Bezier bezier = curve.segment(0);
        // Only what lies on the canvas can be seen; most of the curve must be there.
        const QRectF onCanvas = m_canvas->mapRectToScene(m_canvas->boundingRect()).adjusted(3, 3, -3, -3);
        int checked = 0;
        for (int k = 1; k < 20; ++k) {
            const QPointF at = sceneOfWorld(bezier.eval(k / 20.0));
            if (!onCanvas.contains(at))
                continue;
            ++checked;
            QVERIFY2(kontur::test::darkestNear(image, at) < 90,
                     qPrintable(QStringLiteral("no curve pixel at t=%1 (%2, %3): darkest %4")
                                    .arg(k / 20.0)
                                    .arg(at.x())
                                    .arg(at.y())
                                    .arg(kontur::test::darkestNear(image, at))));
        }
        QVERIFY2(checked >= 10, qPrintable(QStringLiteral("only %1 curve samples on the canvas").arg(checked)));
    }

    // Where fourClicksMakeACurve clicks, in canvas coordinates.
    static constexpr std::array<QPointF, 4> kClicks{QPointF(150, 500), QPointF(250, 120), QPointF(550, 120),
                                                    QPointF(650, 500)};
    // The curve those four clicks make, typed in: the tests that need a curve make their own and
    // do not rely on what an earlier test left.
    void addClickedCurve()
    {
        QVariantList rows;
        for (const QPointF &c : kClicks) {
            const QPointF w = m_canvas->toWorld(c);
            rows << QVariant(QVariantList{w.x(), w.y()});
        }
        QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(kontur::CurveKind::Bezier), rows));
        QCOMPARE(m_editor->document()->curveCount(), 1);
    }

private Q_SLOTS:
    void initTestCase();
    void init();
    void rendersOnTheExpectedBackend();
    void fourClicksMakeACurve();
    void dragMovesAPoint();
    void pinchZoomsAboutTheFingers();
    void twoFingersPan();
    void wheelZoomsAboutTheCursor();
    void zoomButtonsAndFit();
    void languageSwitchesAtRunTime();
    void cleanupTestCase();
};

void TestE2E::initTestCase()
{
    QVERIFY(start(QSize(1100, 720)));
    QTRY_VERIFY(m_canvas->width() > 400 && m_canvas->height() > 400);
}

// Each test starts from an empty document at the first view, selecting, in English.
void TestE2E::init()
{
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    // The window fits the view to a replaced document once control returns to the event loop
    // (Qt.callLater, a queued call): deliver it now, or it would fit the next test's curve mid-test.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::MetaCall);
    m_editor->setMode(EditController::Mode::Select);
    m_canvas->resetView();
    auto *language = m_engine->findChild<kontur::Language *>();
    QVERIFY(language && language->setCurrent(QStringLiteral("en")));
    QTRY_COMPARE(item("newBezierButton")->property("text").toString(), QStringLiteral("New Bézier"));
    // A frame drawn: layouts are polished before each frame, so the tool bar is laid out for the
    // texts it shows now (after a language switch) and the buttons are where the tests click.
    QSignalSpy swapped(m_window, &QQuickWindow::frameSwapped);
    m_window->update();
    QVERIFY(swapped.wait());
}

void TestE2E::rendersOnTheExpectedBackend()
{
    const QByteArray expected = qgetenv("KONTUR_EXPECT_GRAPHICS_API");
    QTRY_VERIFY(!m_canvas->graphicsApi().isEmpty());
    if (!expected.isEmpty())
        QCOMPARE(m_canvas->graphicsApi(), QString::fromLatin1(expected));
    // The y axis runs through the canvas centre at first; without the grid an empty canvas is white
    // there. (Near the top: the first-run hint's starts lie over the middle of an empty canvas.)
    const QPointF centre = scene(QPointF(m_canvas->toScreen(QPointF(0, 0)).x(), m_canvas->height() * 0.08));
    const QImage withGrid = grab();
    QVERIFY(m_canvas->property("showGrid").toBool());
    QVERIFY2(kontur::test::darkestNear(withGrid, centre, 2) < 225, // the axis colour, blended
             qPrintable(QString::number(kontur::test::darkestNear(withGrid, centre, 2))));
    m_canvas->setProperty("showGrid", false);
    const QImage image = grab();
    QVERIFY(kontur::test::darkestNear(image, centre, 3) > 240);
    m_canvas->setProperty("showGrid", true);
}

void TestE2E::fourClicksMakeACurve()
{
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("newBezierButton"));
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Place);

    const std::array<QPointF, 4> &clicks = kClicks;
    for (std::size_t i = 0; i < clicks.size(); ++i) {
        // The mouse hovers first, as a real pointer does: the rubber band follows it.
        QTest::mouseMove(m_window, scene(clicks[i]).toPoint());
        QTest::mouseClick(m_window, Qt::LeftButton, {}, scene(clicks[i]).toPoint());
        if (i < 3)
            QTRY_COMPARE(m_editor->placement()->pendingCount(), static_cast<int>(i + 1));
    }
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    // The curve is made: the drawing tool is left and shown so, the new curve selected.
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Select);
    QCOMPARE(m_editor->selection()->curveRow(), 0);
    QObject *bezierButton = m_window->findChild<QObject *>(QStringLiteral("newBezierButton"));
    QVERIFY(bezierButton);
    QTRY_VERIFY(!bezierButton->property("checked").toBool());
    const kontur::Curve &curve = m_editor->document()->curve(0);
    QCOMPARE(curve.definingCount(), 4);
    for (std::size_t i = 0; i < 4; ++i) {
        const QPointF w = m_canvas->toWorld(scene(clicks[i]).toPoint() - scene(QPointF(0, 0)));
        QVERIFY2(std::abs(curve.definingPoint(static_cast<int>(i)).x() - w.x()) < 1e-6 &&
                     std::abs(curve.definingPoint(static_cast<int>(i)).y() - w.y()) < 1e-6,
                 qPrintable(QStringLiteral("point %1").arg(i)));
    }

    const QImage image = grab();
    verifyCurveDrawn(image, curve);
    // Away from the curve and its polygon the canvas stays light (at most a grid line).
    QVERIFY(kontur::test::darkestNear(image, scene(QPointF(400, 620)), 3) > 200);
}

void TestE2E::dragMovesAPoint()
{
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("selectButton"));
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Select);
    addClickedCurve();
    const kontur::Curve before = m_editor->document()->curve(0);
    const QPoint from = sceneOfWorld(before.definingPoint(1)).toPoint();
    const QPoint to = from + QPoint(-60, 200);

    QTest::mousePress(m_window, Qt::LeftButton, {}, from);
    for (int step = 1; step <= 10; ++step) {
        QTest::mouseMove(m_window, from + (to - from) * step / 10);
    }
    QTest::mouseRelease(m_window, Qt::LeftButton, {}, to);
    QTRY_VERIFY(!m_editor->isDragging());

    const kontur::Curve &after = m_editor->document()->curve(0);
    const QPointF moved = sceneOfWorld(after.definingPoint(1));
    QVERIFY2(QLineF(moved, QPointF(to)).length() < 1.0,
             qPrintable(QStringLiteral("point at (%1, %2), pointer at (%3, %4)")
                            .arg(moved.x())
                            .arg(moved.y())
                            .arg(to.x())
                            .arg(to.y())));
    QCOMPARE(after.definingPoint(0), before.definingPoint(0));
    QCOMPARE(after.definingPoint(2), before.definingPoint(2));
    QCOMPARE(after.definingPoint(3), before.definingPoint(3));
    verifyCurveDrawn(grab(), after);

    // One undo takes the whole drag back.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("undoButton"));
    QTRY_COMPARE(m_editor->document()->curve(0).definingPoint(1), before.definingPoint(1));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("redoButton"));
    QTRY_COMPARE(m_editor->document()->curve(0).definingPoint(1), after.definingPoint(1));
}

void TestE2E::pinchZoomsAboutTheFingers()
{
    addClickedCurve();
    QPointingDevice *touch = QTest::createTouchDevice();
    const double zoomBefore = m_canvas->zoom();
    // Pinch around a point off the canvas centre: that point must stay under the fingers.
    const QPointF centroid(300, 300);
    const QPointF worldAtCentroid = m_canvas->toWorld(centroid);
    const QPoint c = scene(centroid).toPoint();

    QTest::touchEvent(m_window, touch).press(0, c - QPoint(60, 0)).press(1, c + QPoint(60, 0));
    for (int step = 1; step <= 12; ++step) {
        const int spread = 60 + 5 * step;
        QTest::touchEvent(m_window, touch).move(0, c - QPoint(spread, 0)).move(1, c + QPoint(spread, 0));
    }
    QTest::touchEvent(m_window, touch).release(0, c - QPoint(120, 0)).release(1, c + QPoint(120, 0));
    QVERIFY(kontur::test::settled(m_window));

    const double ratio = m_canvas->zoom() / zoomBefore;
    // The fingers went from 120 px to 240 px apart; the handler starts after a drag threshold.
    QVERIFY2(ratio > 1.5 && ratio < 2.05, qPrintable(QString::number(ratio)));
    const QPointF nowAt = m_canvas->toScreen(worldAtCentroid);
    QVERIFY2(QLineF(nowAt, centroid).length() < 3.0,
             qPrintable(QStringLiteral("(%1, %2)").arg(nowAt.x()).arg(nowAt.y())));
    QCOMPARE(m_editor->document()->curveCount(), 1); // a pinch places and moves nothing
    verifyCurveDrawn(grab(), m_editor->document()->curve(0));
}

void TestE2E::twoFingersPan()
{
    addClickedCurve();
    QPointingDevice *touch = QTest::createTouchDevice();
    const double zoomBefore = m_canvas->zoom();
    const QPointF start(300, 300);
    const QPointF worldAtStart = m_canvas->toWorld(start);
    const QPoint c = scene(start).toPoint();
    const QPoint spread(0, 50);
    QTest::touchEvent(m_window, touch).press(0, c - spread).press(1, c + spread);
    const QPoint shift(120, -80);
    for (int step = 1; step <= 10; ++step) {
        const QPoint d = shift * step / 10;
        QTest::touchEvent(m_window, touch).move(0, c - spread + d).move(1, c + spread + d);
    }
    QTest::touchEvent(m_window, touch).release(0, c - spread + shift).release(1, c + spread + shift);
    QVERIFY(kontur::test::settled(m_window));

    // The fingers kept their distance: the zoom stays, and the content moved with them.
    QVERIFY2(std::abs(m_canvas->zoom() / zoomBefore - 1.0) < 0.02, qPrintable(QString::number(m_canvas->zoom())));
    const QPointF nowAt = m_canvas->toScreen(worldAtStart);
    QVERIFY2(QLineF(nowAt, start + QPointF(shift)).length() < 3.0,
             qPrintable(QStringLiteral("(%1, %2)").arg(nowAt.x()).arg(nowAt.y())));
    QCOMPARE(m_editor->document()->curveCount(), 1);
}

void TestE2E::wheelZoomsAboutTheCursor()
{
    addClickedCurve();
    const QPointF cursor(500, 250);
    const QPointF world = m_canvas->toWorld(cursor);
    const double zoomBefore = m_canvas->zoom();
    const QPointF pos = scene(cursor);
    QWheelEvent wheel(pos, m_window->mapToGlobal(pos), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QGuiApplication::sendEvent(m_window, &wheel);
    QTRY_VERIFY(m_canvas->zoom() != zoomBefore);
    QVERIFY(std::abs(m_canvas->zoom() - zoomBefore / 1.2) < 1e-9 * zoomBefore);
    QVERIFY(QLineF(m_canvas->toScreen(world), cursor).length() < 1e-6);
    verifyCurveDrawn(grab(), m_editor->document()->curve(0));
}

void TestE2E::zoomButtonsAndFit()
{
    addClickedCurve();
    const double zoomBefore = m_canvas->zoom();
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("zoomInButton"));
    QTRY_VERIFY(std::abs(m_canvas->zoom() - zoomBefore * 1.25) < 1e-9 * zoomBefore);
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf("zoomOutButton"));
    QTRY_VERIFY(std::abs(m_canvas->zoom() - zoomBefore) < 1e-9 * zoomBefore);
    QVERIFY(item("zoomReadout")->property("text").toString().endsWith(QLatin1String("%")));

    m_canvas->fitToView();
    // After fitting, every control point is on the canvas, a touch target away from its edges.
    for (const auto &p : m_editor->document()->curve(0).definingPoints()) {
        const QPointF s = m_canvas->toScreen(QPointF(p.x(), p.y()));
        QVERIFY(s.x() >= m_canvas->hitRadius() && s.x() <= m_canvas->width() - m_canvas->hitRadius());
        QVERIFY(s.y() >= m_canvas->hitRadius() && s.y() <= m_canvas->height() - m_canvas->hitRadius());
    }
    verifyCurveDrawn(grab(), m_editor->document()->curve(0));
}

void TestE2E::languageSwitchesAtRunTime()
{
    addClickedCurve();
    auto *language = m_engine->findChild<kontur::Language *>();
    QVERIFY(language);
    QQuickItem *button = item("newBezierButton");
    QCOMPARE(button->property("text").toString(), QStringLiteral("New Bézier"));
    const QHash<QString, QString> expected{
        {QStringLiteral("lv"), QStringLiteral("Jauna Bezjē")},
        {QStringLiteral("sk"), QStringLiteral("Nová Bézierova")},
        {QStringLiteral("bg"), QStringLiteral("Нова крива на Безие")},
        {QStringLiteral("ru"), QStringLiteral("Новая кривая Безье")},
    };
    const QHash<QString, QString> kindNames{
        {QStringLiteral("lv"), QStringLiteral("Bezjē līkne")},
        {QStringLiteral("sk"), QStringLiteral("Bézierova krivka")},
        {QStringLiteral("bg"), QStringLiteral("Крива на Безие")},
        {QStringLiteral("ru"), QStringLiteral("Кривая Безье")},
    };
    for (auto it = expected.cbegin(); it != expected.cend(); ++it) {
        QVERIFY(language->setCurrent(it.key()));
        QTRY_VERIFY2(button->property("text").toString().startsWith(it.value()),
                     qPrintable(button->property("text").toString()));
        // Numbers follow the language: a decimal comma in all four.
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
        // Texts held by the models follow too.
        QCOMPARE(m_editor->curves()->index(0).data(kontur::CurveListModel::KindNameRole).toString(),
                 kindNames.value(it.key()));
    }
    grab(); // the Russian UI, for a look
    QVERIFY(!language->setCurrent(QStringLiteral("xx")));
    // The choice is remembered for the next start (the test's own settings folder).
    kontur::Language::remember(QStringLiteral("bg"));
    QCOMPARE(kontur::Language::systemDefault(), QStringLiteral("bg"));
    kontur::Language::remember(QStringLiteral("en"));
    QVERIFY(language->setCurrent(QStringLiteral("en")));
    QTRY_COMPARE(button->property("text").toString(), QStringLiteral("New Bézier"));
}

void TestE2E::cleanupTestCase()
{
    m_engine.reset();
}

QTEST_MAIN(TestE2E)
#include "tst_e2e.moc"
