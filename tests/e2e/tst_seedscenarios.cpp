// The seed's acceptance scenarios (thesis §4.2) that tst_scenarios does not cover, each in the real
// window: T02–T14, T17–T19, T21, T22 and T26, by mouse, finger and keyboard (file steps through the
// DocumentFiles and Exporter, as the file dialogs would call them), the point roles in their colours on the
// screen, and a stylus that works like a finger (tap places, drag moves, a stroke on empty canvas pans).
// Over 600 lines because each of the thesis's scenarios is one written-out test in the real window.
#include "windowtest.h"

#include "../curveids.h"
#include "../oracles.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/backgroundcontroller.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"
#include "models/text/numbers.h"

#include <QGuiApplication>
#include <QJSValue>
#include <QJsonDocument>
#include <QPointingDevice>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QStyleHints>
#include <QTabletEvent>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

using kontur::CurveCanvas;
using kontur::CurveKind;
using kontur::EditController;
using kontur::Message;
using kontur::geo::Point;
using kontur::test::near;
using kontur::test::text;

namespace {

// Oracles for the least-squares cubic, written here apart from the library (src/geometry/fit.cpp
// solves by a streaming QR): the parameters of docs/requirements.md 1.2 and the cubic Bernstein basis.
std::vector<double> parametersOf(const std::vector<Point> &knots, double alpha)
{
    std::vector<double> s{0.0};
    for (std::size_t i = 1; i < knots.size(); ++i) {
        const double d = std::hypot(knots[i].x() - knots[i - 1].x(), knots[i].y() - knots[i - 1].y());
        s.push_back(s.back() + (alpha == 0.0 ? 1.0 : std::pow(d, alpha)));
    }
    for (double &v : s)
        v /= s.back();
    return s;
}

std::array<double, 4> bernstein(double t)
{
    const double u = 1.0 - t;
    return {u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t};
}

// How far `control` is from the least-squares cubic of `knots` at `params`: the largest component of
// the normal equations' residual Σ_i b_j(s_i) (B(s_i) − p_i), j = 0..3, which is zero exactly at the
// minimum, relative to the knots' size.
double normalResidual(const std::array<Point, 4> &control, const std::vector<Point> &knots,
                      const std::vector<double> &params)
{
    double size = 1.0;
    for (const Point &p : knots)
        size = std::max({size, std::abs(p.x()), std::abs(p.y())});
    std::array<Point, 4> sums{Point(0, 0), Point(0, 0), Point(0, 0), Point(0, 0)};
    for (std::size_t i = 0; i < knots.size(); ++i) {
        const std::array<double, 4> b = bernstein(params[i]);
        Point at(0, 0);
        for (std::size_t j = 0; j < 4; ++j)
            at += b[j] * control[j];
        for (std::size_t j = 0; j < 4; ++j)
            sums[j] += b[j] * (at - knots[i]);
    }
    double worst = 0.0;
    for (const Point &v : sums)
        worst = std::max({worst, std::abs(v.x()), std::abs(v.y())});
    return worst / size;
}

} // namespace

class TestSeedScenarios final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    // The visible item of that name: the panel exists twice (beside the canvas, and in the drawer
    // used on narrow screens), and only one of them is shown.
    QQuickItem *item(const QString &name) const { return kontur::test::findVisibleItem(m_window, name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }
    QPoint sceneOf(const Point &world) const
    {
        return m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y()))).toPoint();
    }
    Point worldOf(QPoint scene) const
    {
        const QPointF w = m_canvas->toWorld(m_canvas->mapFromScene(QPointF(scene)));
        return {w.x(), w.y()};
    }
    const kontur::Curve &curve(int i = 0) const { return m_editor->document()->curve(i); }
    void click(const char *name)
    {
        QQuickItem *it = item(QString::fromLatin1(name));
        QVERIFY2(it && it->isVisible() && it->isEnabled(), name);
        kontur::test::ensureVisible(it);
        // Two clicks are never taken for a double click (a button's second press of one emits no
        // clicked()): QTest stamps each click 500 ms after the one before, whatever the clock says.
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(it));
    }
    void tap(QPoint at)
    {
        QTest::touchEvent(m_window, m_touch).press(0, at);
        QTest::touchEvent(m_window, m_touch).release(0, at);
    }
    void mouseDrag(QPoint from, QPoint to, Qt::MouseButton button = Qt::LeftButton)
    {
        QTest::mousePress(m_window, button, {}, from);
        for (int step = 1; step <= 10; ++step) {
            const QPoint at = from + (to - from) * step / 10;
            // QTest::mouseMove carries no buttons in Qt 6.4; a real drag does.
            QMouseEvent move(QEvent::MouseMove, at, m_window->mapToGlobal(at), Qt::NoButton, button, Qt::NoModifier);
            QGuiApplication::sendEvent(m_window, &move);
        }
        QTest::mouseRelease(m_window, button, {}, to);
    }
    void touchDrag(QPoint from, QPoint to)
    {
        QTest::touchEvent(m_window, m_touch).press(0, from);
        for (int step = 1; step <= 10; ++step) {
            QTest::touchEvent(m_window, m_touch).move(0, from + (to - from) * step / 10);
        }
        QTest::touchEvent(m_window, m_touch).release(0, to);
    }
    // Presses a button from the keyboard: focus (as Tab would give it) and Space.
    void press(const char *name)
    {
        QQuickItem *it = item(QString::fromLatin1(name));
        QVERIFY2(it && it->isVisible() && it->isEnabled(), name);
        kontur::test::ensureVisible(it);
        it->forceActiveFocus(Qt::TabFocusReason);
        QTRY_VERIFY(it->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_Space);
    }
    // Picks a kind from the "New curve" menu, as a user does.
    void chooseKind(CurveKind kind)
    {
        click("newCurveMenuButton");
        QQuickItem *entry = nullptr;
        QTRY_VERIFY((entry = item(QStringLiteral("newKind%1").arg(static_cast<int>(kind)))) && entry->isVisible() &&
                    entry->width() > 0);
        QVERIFY(kontur::test::clickMenuItem(m_window, entry));
        QTRY_COMPARE(m_editor->placement()->kind(), static_cast<int>(kind));
        QTRY_VERIFY(!entry->isVisible());
        // The click on the menu entry must not reach the canvas below as a tap.
        QCOMPARE(m_editor->placement()->pendingCount(), 0);
    }
    // Types into a field of the coordinates table from the keyboard: focus, select all, type.
    void type(const QString &field, const QString &text, bool enter)
    {
        kontur::test::typeIntoTable(m_window, field, text, enter);
    }
    // Chooses entry `index` of a ComboBox by opening its popup and clicking the entry.
    void choose(const char *boxName, int index)
    {
        QQuickItem *box = nullptr;
        QTRY_VERIFY2(
            (box = item(QString::fromLatin1(boxName))) && box->isVisible(),
            qPrintable(
                QStringLiteral("%1 hidden; the panel shows %2")
                    .arg(QString::fromLatin1(boxName))
                    .arg(QString::fromUtf8(
                        QJsonDocument::fromVariant(
                            item(QStringLiteral("sidePanel"))->property("curveData").value<QJSValue>().toVariant())
                            .toJson(QJsonDocument::Compact)))));
        QVERIFY(kontur::test::standsStill(m_window, box));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(box));
        auto *popup = box->property("popup").value<QObject *>();
        QVERIFY(popup);
        QTRY_VERIFY(popup->property("opened").toBool());
        auto *list = popup->property("contentItem").value<QQuickItem *>();
        QVERIFY(list);
        QQuickItem *entry = nullptr;
        const QString wanted = box->property("model").toStringList().value(index);
        std::function<void(QQuickItem *)> find = [&](QQuickItem *it) {
            if (!entry && it->inherits("QQuickAbstractButton") && it->property("text").toString() == wanted)
                entry = it;
            for (QQuickItem *child : it->childItems())
                find(child);
        };
        find(list);
        QVERIFY2(entry, qPrintable(wanted));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(entry));
        QTRY_VERIFY(!popup->property("visible").toBool());
    }
    QString bannerText() const
    {
        QQuickItem *text = item(QStringLiteral("messageText"));
        return text && text->isVisible() ? text->property("text").toString() : QString();
    }
    QImage grab()
    {
        m_canvas->update();
        if (!kontur::test::settled(m_window))
            return {};
        QImage image = m_window->grabWindow();
        if (const QByteArray dir = qgetenv("KONTUR_SCREENSHOT_DIR"); !dir.isEmpty())
            image.save(QStringLiteral("%1/seed-%2.png")
                           .arg(QString::fromLocal8Bit(dir), QString::fromLatin1(QTest::currentTestFunction())));
        return image;
    }
    // The pixel within `radius` of a window position whose colour is nearest to `colour`, as a distance.
    static int nearestColour(const QImage &image, QPoint at, const QColor &colour, int radius)
    {
        const qreal dpr = image.devicePixelRatio();
        int best = 1000;
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                const QPoint p = ((QPointF(at) + QPointF(dx, dy)) * dpr).toPoint();
                if (!image.rect().contains(p))
                    continue;
                const QColor c = image.pixelColor(p);
                best = std::min(best, std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                                          std::abs(c.blue() - colour.blue()));
            }
        return best;
    }
    void verifyCurveDrawn(const QImage &image, const kontur::Curve &c)
    {
        const QColor ink = m_canvas->property("curveColor").value<QColor>();
        for (int s = 0; s < c.segmentCount(); ++s)
            for (int k = 1; k < 8; ++k) {
                const QPoint at = sceneOf(c.segment(s).eval(k / 8.0));
                QVERIFY2(nearestColour(image, at, ink, 1) < 150,
                         qPrintable(QStringLiteral("no curve pixel at segment %1, t=%2 (%3, %4)")
                                        .arg(s)
                                        .arg(k / 8.0)
                                        .arg(at.x())
                                        .arg(at.y())));
            }
    }
    void resetDocument()
    {
        m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->setHandleMode(EditController::HandleMode::Free);
        m_editor->placement()->setParameterization(kontur::Parameterizations::Uniform);
        m_editor->clearMessage();
        m_canvas->resetView();
        m_canvas->setProperty("showGrid", true);
        // What a test changes for itself (language, window size) is set back here too, so that a
        // test that failed half-way does not leave it to the next one.
        auto *language = m_engine->findChild<kontur::Language *>();
        QVERIFY(language && language->setCurrent(QStringLiteral("en")));
        m_window->resize(1280, 800);
        QTRY_COMPARE(m_window->size(), QSize(1280, 800));
        QVERIFY(kontur::test::settled(m_window));
    }

private Q_SLOTS:
    void initTestCase();
    void init() { resetDocument(); }
    void t02_fourClicksWithRubberBand();
    void t03_mouseDragRebuildsTheCurve();
    void t04_tableListsTheFourControlPoints();
    void tableFollowsAnotherCurve();
    void t05_bezierCurvesUseNoParameterization();
    void t06_typedKnotsGiveTheInterpolatingCubic();
    void t07_controlPointsOfAFittedCubicDoNotMove();
    void t08_typedKnotRebuildsTheCurve();
    void t09_appendingNeverOverwrites();
    void t10_leastSquaresRowsWithinLimits();
    void t11_centripetalLeastSquaresFromAFile();
    void t12_leastSquaresControlPointsDoNotMove();
    void t13_fingerDragRefitsTheLeastSquaresCubic();
    void t14_parameterizationBoxRecomputes();
    void t17_compositeByKeyboardWithMessages8And10();
    void t18_typedHandleKeepsTheConstraint();
    void t19_freeHandleDragKeepsCollinearity();
    void t21_rightButtonKnotDragCarriesHandles();
    void t22_typedKnotCarriesHandles();
    void t26_windowFollowsResizing();
    void pointRolesInTheirColours();
    void stylusWorksLikeAFinger();
    void seed004_contourCurveOverAPicture();
    void cleanupTestCase() { m_engine.reset(); }
};

void TestSeedScenarios::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
}

void TestSeedScenarios::t02_fourClicksWithRubberBand()
{
    click("newBezierButton");
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Place);
    const std::vector<QPoint> clicks{sceneOf({-200, -100}), sceneOf({-100, 150}), sceneOf({100, 150}),
                                     sceneOf({200, -100})};
    for (std::size_t i = 0; i < clicks.size(); ++i) {
        QTest::mouseMove(m_window, clicks[i] + QPoint(30, 20));
        if (i > 0) {
            // The dashed line runs from the last point to the pointer.
            QTRY_VERIFY(m_editor->placement()->hasHover());
            QVERIFY((m_editor->placement()->hoverPoint() - worldOf(clicks[i] + QPoint(30, 20))).norm() < 1e-6);
        }
        QTest::mouseClick(m_window, Qt::LeftButton, {}, clicks[i]);
    }
    // Exactly four: the fourth click finished the curve; a fifth starts the next one.
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(curve().kind(), CurveKind::Bezier);
    QCOMPARE(curve().definingCount(), 4);
    QCOMPARE(m_editor->placement()->pendingCount(), 0);
    for (int i = 0; i < 4; ++i)
        QVERIFY((curve().definingPoint(i) - worldOf(clicks[static_cast<std::size_t>(i)])).norm() < 1e-9);
    verifyCurveDrawn(grab(), curve());
    click("selectButton");
}

void TestSeedScenarios::t03_mouseDragRebuildsTheCurve()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier), QVariantList{QVariantList{-200, -100}, QVariantList{-100, 150},
                                                          QVariantList{100, 150}, QVariantList{200, -100}}));
    const QPoint from = sceneOf({-100, 150});
    const QPoint to = from + QPoint(-40, 60);
    mouseDrag(from, to);
    QTRY_VERIFY(!m_editor->isDragging());
    // The point follows the pointer (within the press's rounding to whole pixels).
    const Point c1 = curve().definingPoint(1);
    QVERIFY((c1 - worldOf(to)).norm() < 1.0);
    // B(1/2) = (c0 + 3 c1 + 3 c2 + c3) / 8, drawn where it is.
    const Point mid = (Point(-200, -100) + 3 * c1 + 3 * Point(100, 150) + Point(200, -100)) / 8;
    QVERIFY((curve().segment(0).eval(0.5) - mid).norm() < 1e-9);
    verifyCurveDrawn(grab(), curve());
}

void TestSeedScenarios::t04_tableListsTheFourControlPoints()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{0, 0}, QVariantList{10, 30}, QVariantList{40, 30}, QVariantList{50, 0}}));
    // Choosing the curve by one of its control points shows exactly its four rows.
    m_editor->selection()->selectRow(-1);
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf({40, 30}));
    QTRY_COMPARE(m_editor->selection()->curveRow(), 0);
    const QStringList expected{QStringLiteral("0.000"), QStringLiteral("10.000"), QStringLiteral("40.000"),
                               QStringLiteral("50.000")};
    for (int row = 0; row < 4; ++row) {
        QQuickItem *x = nullptr;
        QTRY_VERIFY((x = item(QStringLiteral("x%1").arg(row))) && x->isVisible());
        QTRY_COMPARE(x->property("text").toString(), expected[row]);
    }
    QCOMPARE(item(QStringLiteral("y1"))->property("text").toString(), QStringLiteral("30.000"));
    QVERIFY(!item(QStringLiteral("x4")) || !item(QStringLiteral("x4"))->isVisible());
    QCOMPARE(m_editor->points()->index(3).data(kontur::PointListModel::LabelRole).toString(), QStringLiteral("C3"));
}

// The table keeps its rows' delegates when it shows another curve: it shows exactly the other
// curve's rows, from the first, with nothing typed for the first curve and no cell being edited.
void TestSeedScenarios::tableFollowsAnotherCurve()
{
    QVariantList knots;
    for (int k = 0; k < 12; ++k)
        knots << QVariant(QVariantList{20.0 * k, k % 2 == 0 ? 0.0 : 40.0});
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite), knots));
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{0, 100}, QVariantList{10, 130}, QVariantList{40, 130}, QVariantList{50, 100}}));
    const int composite = m_editor->document()->curve(0).rowCount();
    QCOMPARE(composite, 34);
    const auto shows = [this](int row) {
        const QQuickItem *x = item(QStringLiteral("x%1").arg(row));
        return x && x->isVisible() ? x->property("text").toString() : QString();
    };
    const auto text = [this](int curve, int row) {
        return kontur::displayNumber(m_editor->document()->curve(curve).row(row).position.x(), 3);
    };
    QQuickItem *list = nullptr;

    // The long curve, scrolled down, a cell typed but not applied and still being edited.
    m_editor->selection()->selectRow(0);
    QTRY_VERIFY((list = item(QStringLiteral("pointList"))));
    QTRY_COMPARE(list->property("count").toInt(), composite);
    type(QStringLiteral("x20"), QStringLiteral("777"), false);
    QVERIFY(item(QStringLiteral("coordinatesTable"))->property("dirty").toBool());
    QVERIFY(item(QStringLiteral("x20"))->hasActiveFocus());
    QVERIFY(list->property("contentY").toDouble() > list->property("originY").toDouble());

    // The short one: its four rows from the first, nothing typed, no cell edited.
    m_editor->selection()->selectRow(1);
    QTRY_COMPARE(list->property("count").toInt(), 4);
    for (int row = 0; row < 4; ++row)
        QTRY_COMPARE(shows(row), text(1, row));
    QTRY_VERIFY(!item(QStringLiteral("x4")) || !item(QStringLiteral("x4"))->isVisible());
    QCOMPARE(list->property("contentY").toDouble(), list->property("originY").toDouble());
    QVERIFY(!item(QStringLiteral("coordinatesTable"))->property("dirty").toBool());
    QVERIFY(!list->hasActiveFocus());
    kontur::test::ensureVisible(list);
    grab();

    // Back to the long one: its own numbers, the typed one gone.
    m_editor->selection()->selectRow(0);
    QTRY_COMPARE(list->property("count").toInt(), composite);
    for (int row = 0; row < 6; ++row)
        QTRY_COMPARE(shows(row), text(0, row));
    QVERIFY(QMetaObject::invokeMethod(list, "positionViewAtIndex", Q_ARG(int, 20), Q_ARG(int, 4 /* Contain */)));
    QTRY_COMPARE(shows(20), text(0, 20));
    QVERIFY(shows(20) != QStringLiteral("777"));
}

void TestSeedScenarios::t05_bezierCurvesUseNoParameterization()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{0, 0}, QVariantList{10, 30}, QVariantList{40, 30}, QVariantList{50, 0}}));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf({10, 30}));
    QTRY_COMPARE(m_editor->selection()->curveRow(), 0);
    // The panel offers no parameterization for it; asked anyway (as a file or script would), the
    // answer is the seed's message 7 in the banner, and nothing changes.
    QTRY_VERIFY(!item(QStringLiteral("parameterizationBox"))->isVisible());
    QVERIFY(!m_editor->commands()->setCurveParameterization(kontur::test::idAt(*m_editor, 0),
                                                            kontur::Parameterizations::ChordLength));
    QCOMPARE(m_editor->message().id, Message::NoParameterization);
    QTRY_COMPARE(bannerText(), m_editor->messageText());
    QVERIFY(bannerText().contains(QStringLiteral("parameterization")));
    QVERIFY(!m_editor->canRedo());
}

void TestSeedScenarios::t06_typedKnotsGiveTheInterpolatingCubic()
{
    // The knots are placed roughly by finger, then typed exactly on the keyboard and applied with OK.
    chooseKind(CurveKind::Interpolating);
    for (const Point &p : {Point(-150, 0), Point(-50, 80), Point(60, 90), Point(160, 0)})
        tap(sceneOf(p) + QPoint(3, -2));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1); // four knots finish it
    QCOMPARE(curve().parameterization(), kontur::geo::Parameterization::Uniform);
    const std::vector<Point> knots{{-150, 0}, {-50, 80}, {60, 90}, {160, 0}};
    for (int i = 0; i < 4; ++i) {
        type(QStringLiteral("x%1").arg(i), QString::number(knots[static_cast<std::size_t>(i)].x()), false);
        type(QStringLiteral("y%1").arg(i), QString::number(knots[static_cast<std::size_t>(i)].y()), false);
    }
    click("applyCoordinatesButton");
    QTRY_VERIFY((curve().definingPoint(1) - knots[1]).norm() < 1e-12);
    // Through every typed knot at the uniform parameters 0, 1/3, 2/3, 1.
    for (int i = 0; i < 4; ++i)
        QVERIFY((curve().segment(0).eval(i / 3.0) - knots[static_cast<std::size_t>(i)]).norm() < 1e-9);
    // One undo takes the whole table back.
    m_editor->undo();
    QVERIFY((curve().definingPoint(1) - knots[1]).norm() > 1.0);
    m_editor->redo();
    verifyCurveDrawn(grab(), curve());
}

void TestSeedScenarios::t07_controlPointsOfAFittedCubicDoNotMove()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Interpolating),
        QVariantList{QVariantList{-150, 0}, QVariantList{-50, 120}, QVariantList{60, 110}, QVariantList{160, 0}}));
    const Point control = curve().row(5).position; // C1, derived from the knots
    QVERIFY(m_editor->hitTest(control, 1.0).isValid());
    const QPoint from = sceneOf(control);
    mouseDrag(from, from + QPoint(50, 50));
    QCOMPARE(curve().row(5).position, control);
    QCOMPARE(m_editor->message().id, Message::ControlPointsNotMovable);
    QTRY_COMPARE(bannerText(), m_editor->messageText());
    QVERIFY(bannerText().contains(QStringLiteral("control points")));
    // Its table row is read-only.
    QTRY_VERIFY(item(QStringLiteral("x5")));
    QVERIFY(item(QStringLiteral("x5"))->property("readOnly").toBool());
}

void TestSeedScenarios::t08_typedKnotRebuildsTheCurve()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Interpolating),
        QVariantList{QVariantList{-150, 0}, QVariantList{-50, 120}, QVariantList{60, 110}, QVariantList{160, 0}}));
    kontur::test::selectAt(*m_editor, 0, 1);
    type(QStringLiteral("x1"), QStringLiteral("-40"), false);
    type(QStringLiteral("y1"), QStringLiteral("150.5"), true); // Enter applies, like OK
    QTRY_COMPARE(curve().definingPoint(1), Point(-40, 150.5));
    QVERIFY((curve().segment(0).eval(1.0 / 3) - Point(-40, 150.5)).norm() < 1e-9);
    QCOMPARE(curve().definingPoint(2), Point(60, 110));
}

void TestSeedScenarios::t09_appendingNeverOverwrites()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("points.txt"));
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Interpolating),
        QVariantList{QVariantList{0, 0}, QVariantList{10, 20}, QVariantList{30, 25}, QVariantList{40, 0}}));
    m_editor->selection()->selectRow(0);
    // The file does not exist: it is made. Then a second record goes after the first (the seed's own
    // test log records the whole file being overwritten here).
    QVERIFY(m_exporter->appendPoints(QUrl::fromLocalFile(path)));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray first = file.readAll();
    file.close();
    QVERIFY(first.contains("30 25"));
    QVERIFY(m_exporter->appendPoints(QUrl::fromLocalFile(path)));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray both = file.readAll();
    QVERIFY(both.startsWith(first));
    QVERIFY(both.size() > first.size());
    QCOMPARE(both.count("30 25"), 2);
    // Read back, the two records are two curves through the same knots.
    resetDocument();
    QVERIFY(m_files->importFile(QUrl::fromLocalFile(path), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(curve(1).kind(), CurveKind::Interpolating);
    QCOMPARE(curve(1).definingPoint(2), Point(30, 25));
}

void TestSeedScenarios::t10_leastSquaresRowsWithinLimits()
{
    chooseKind(CurveKind::LeastSquares);
    const std::vector<Point> knots{{-200, 0}, {-120, 90}, {-40, 130}, {40, 120}, {120, 80}, {200, -10}};
    for (const Point &p : knots)
        tap(sceneOf(p));
    click("doneButton");
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    choose("parameterizationBox", kontur::Parameterizations::ChordLength);
    QTRY_COMPARE(curve().parameterization(), kontur::geo::Parameterization::ChordLength);
    // Add a row after the selected knot, then delete rows down to the limit of 4; the next is refused.
    kontur::test::selectAt(*m_editor, 0, 5);
    press("addRowButton");
    QTRY_COMPARE(curve().definingCount(), 7);
    for (int count = 6; count >= 4; --count) {
        kontur::test::selectAt(*m_editor, 0, 0);
        press("deleteRowButton");
        QTRY_COMPARE(curve().definingCount(), count);
    }
    kontur::test::selectAt(*m_editor, 0, 0);
    press("deleteRowButton");
    QTRY_COMPARE(m_editor->message().id, Message::TooFewPoints);
    QCOMPARE(curve().definingCount(), 4);
    QTRY_COMPARE(bannerText(), m_editor->messageText());
    QVERIFY(bannerText().contains(QStringLiteral("4")));
    // Four knots determine the cubic: it passes through each at its chord-length parameter.
    const std::vector<Point> left = curve().definingPoints();
    const std::vector<double> params = parametersOf(left, 1.0);
    for (std::size_t i = 0; i < left.size(); ++i) {
        const std::array<double, 4> b = bernstein(params[i]);
        Point at(0, 0);
        for (std::size_t j = 0; j < 4; ++j)
            at += b[j] * curve().fit()->control[j];
        QVERIFY2((at - left[i]).norm() < 1e-9 * 200, qPrintable(QString::number((at - left[i]).norm())));
    }
    QVERIFY(curve().fit()->rms < 1e-9);
}

void TestSeedScenarios::t11_centripetalLeastSquaresFromAFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("knots.txt"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("# hand-written knots\n-200 0\n-120 90\n-40 130\n40 120\n120 80\n200 -10\n");
    file.close();
    m_editor->placement()->setParameterization(kontur::Parameterizations::Centripetal);
    // The file dialog's accepted file goes to this entry point.
    QVERIFY(m_files->importFile(QUrl::fromLocalFile(path), static_cast<int>(CurveKind::LeastSquares)));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(curve().kind(), CurveKind::LeastSquares);
    const std::vector<Point> knots{{-200, 0}, {-120, 90}, {-40, 130}, {40, 120}, {120, 80}, {200, -10}};
    QCOMPARE(curve().definingPoints(), knots);
    QCOMPARE(curve().parameterization(), kontur::geo::Parameterization::Centripetal);
    // Centripetal parameters and the normal equations solved in 60-digit arithmetic (mpmath),
    // independently of the library.
    QVERIFY2(near(curve().fit()->control,
                  {Point(-199.98112568635484, -0.60452106371528844), Point(-95.087487116681457, 186.53801089816656),
                   Point(95.087487116681457, 159.26755574716598), Point(199.98112568635484, -10.227389169094066)}),
             text(curve().fit()->control).constData());
    QVERIFY(std::abs(curve().fit()->rms - 1.9392019961921241) < 1e-9);
    verifyCurveDrawn(grab(), curve());
    // A file that is not a points list is refused with the seed's message 2 and changes nothing.
    const QString bad = dir.filePath(QStringLiteral("bad.txt"));
    QFile badFile(bad);
    QVERIFY(badFile.open(QIODevice::WriteOnly));
    badFile.write("1 2\nthree four\n");
    badFile.close();
    QVERIFY(!m_files->importFile(QUrl::fromLocalFile(bad), static_cast<int>(CurveKind::LeastSquares)));
    QCOMPARE(m_editor->document()->curveCount(), 1);
    QVERIFY(!m_editor->message().isEmpty());
}

void TestSeedScenarios::t12_leastSquaresControlPointsDoNotMove()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::LeastSquares),
                                                         QVariantList{QVariantList{-200, 0}, QVariantList{-100, 100},
                                                                      QVariantList{0, 140}, QVariantList{100, 100},
                                                                      QVariantList{200, 0}}));
    const int row = curve().definingCount() + 1; // C1
    const Point control = curve().row(row).position;
    const QPoint from = sceneOf(control);
    // By finger this time.
    touchDrag(from, from + QPoint(60, -40));
    QCOMPARE(curve().row(row).position, control);
    QCOMPARE(m_editor->message().id, Message::ControlPointsNotMovable);
    QTRY_VERIFY(!bannerText().isEmpty());
}

void TestSeedScenarios::t13_fingerDragRefitsTheLeastSquaresCubic()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::LeastSquares),
                                                         QVariantList{QVariantList{-200, 0}, QVariantList{-100, 100},
                                                                      QVariantList{0, 140}, QVariantList{100, 100},
                                                                      QVariantList{200, 0}}));
    // Before the drag: the uniform least-squares cubic of the typed knots, in exact fractions from
    // the normal equations: (−200, −4/7), (−200/3, 1276/7), (200/3, 1276/7), (200, −4/7).
    const std::array<Point, 4> before = curve().fit()->control;
    QVERIFY2(near(before, {Point(-200, -4.0 / 7), Point(-200.0 / 3, 1276.0 / 7), Point(200.0 / 3, 1276.0 / 7),
                           Point(200, -4.0 / 7)}),
             text(before).constData());
    const QPoint from = sceneOf({0, 140});
    const QPoint to = from + QPoint(20, -80);
    touchDrag(from, to);
    QTRY_VERIFY(!m_editor->isDragging());
    std::vector<Point> knots = curve().definingPoints();
    QVERIFY((knots[2] - worldOf(to)).norm() < 1.0);
    // The dragged knot is where the finger let go, so the oracle is the least-squares condition
    // itself, at the uniform parameters 0, ¼, ½, ¾, 1; the cubic before the drag was a different one.
    QCOMPARE(parametersOf(knots, 0.0), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    QVERIFY2(normalResidual(curve().fit()->control, knots, parametersOf(knots, 0.0)) < 1e-12,
             text(curve().fit()->control).constData());
    QVERIFY(normalResidual(before, knots, parametersOf(knots, 0.0)) > 1e-3);
    verifyCurveDrawn(grab(), curve());
}

void TestSeedScenarios::t14_parameterizationBoxRecomputes()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::LeastSquares),
                                                         QVariantList{QVariantList{-200, 0}, QVariantList{-180, 100},
                                                                      QVariantList{-150, 120}, QVariantList{150, 120},
                                                                      QVariantList{200, 0}}));
    m_editor->selection()->selectRow(0);
    std::vector<std::array<Point, 4>> controls;
    for (int p : {kontur::Parameterizations::ChordLength, kontur::Parameterizations::Centripetal,
                  kontur::Parameterizations::Uniform}) {
        choose("parameterizationBox", p);
        QTRY_COMPARE(static_cast<int>(curve().parameterization()), p);
        controls.push_back(curve().fit()->control);
    }
    // Each parameterization's fit, from the normal equations in 60-digit arithmetic (mpmath); the
    // uniform one in exact fractions is (−1322/7, 16/7), (−25978/63, 8944/63), (11542/63, 13424/63),
    // (1478/7, 16/7).
    QVERIFY2(near(controls[0],
                  {Point(-200.47328647719398, 0.39245284074615542), Point(-234.24304327751937, 218.67018122427325),
                   Point(218.9996727165613, 228.31781464793506), Point(199.88798064251292, 0.092887325505274366)}),
             text(controls[0]).constData());
    QVERIFY2(near(controls[1],
                  {Point(-196.13538082702446, 1.4473597777581361), Point(-350.07785553717675, 162.83157459833871),
                   Point(268.93969164722292, 221.17092310589281), Point(201.84703030526331, 0.69174147632252648)}),
             text(controls[1]).constData());
    QVERIFY2(near(controls[2], {Point(-1322.0 / 7, 16.0 / 7), Point(-25978.0 / 63, 8944.0 / 63),
                                Point(11542.0 / 63, 13424.0 / 63), Point(1478.0 / 7, 16.0 / 7)}),
             text(controls[2]).constData());
}

void TestSeedScenarios::t17_compositeByKeyboardWithMessages8And10()
{
    // Two knots by finger and Done, then rows added and filled in from the keyboard.
    chooseKind(CurveKind::Composite);
    tap(sceneOf({-200, 0}));
    tap(sceneOf({-100, 80}));
    QTRY_COMPARE(m_editor->placement()->pendingCount(), 2);
    click("doneButton");
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(curve().composite().knotCount(), 2);
    kontur::test::selectAt(*m_editor, 0, curve().definingCount() - 1); // the last knot
    press("addRowButton");
    QTRY_COMPARE(curve().composite().knotCount(), 3);
    kontur::test::selectAt(*m_editor, 0, curve().definingCount() - 1);
    press("addRowButton");
    QTRY_COMPARE(curve().composite().knotCount(), 4);
    const int lastKnot = curve().definingCount() - 1;
    // An empty value is the seed's message 10, whether Enter or OK applies it; nothing changes.
    type(QStringLiteral("x%1").arg(lastKnot), QString(), true);
    QCOMPARE(item(QStringLiteral("x%1").arg(lastKnot))->property("text").toString(), QString());
    QVERIFY(item(QStringLiteral("coordinatesTable"))->property("dirty").toBool());
    QTRY_COMPARE(m_editor->message().id, Message::FillAllValues);
    QVERIFY(!bannerText().isEmpty());
    m_editor->clearMessage();
    click("applyCoordinatesButton");
    QTRY_COMPARE(m_editor->message().id, Message::FillAllValues);
    QCOMPARE(curve().composite().knotCount(), 4);
    type(QStringLiteral("x%1").arg(lastKnot), QStringLiteral("1505"), false);
    // Backspace edits the field (it is also the shortcut that takes back a placed point).
    QTest::keyClick(m_window, Qt::Key_Backspace);
    QCOMPARE(item(QStringLiteral("x%1").arg(lastKnot))->property("text").toString(), QStringLiteral("150"));
    type(QStringLiteral("y%1").arg(lastKnot), QStringLiteral("-20"), false);
    click("applyCoordinatesButton");
    QTRY_COMPARE(curve().composite().knot(3), Point(150, -20));
    QCOMPARE(curve().segmentCount(), 3); // finished: through every knot
    QCOMPARE(curve().segment(2).eval(1.0), Point(150, -20));
    // Enter finishes an open-ended curve being placed (the Done button's key).
    chooseKind(CurveKind::Composite);
    tap(sceneOf({-200, -120}));
    tap(sceneOf({-100, -60}));
    QTRY_COMPARE(m_editor->placement()->pendingCount(), 2);
    // A menu opened meanwhile and closed by a tap beside it: the tap only closes the menu.
    click("newCurveMenuButton");
    QQuickItem *entry = nullptr;
    QTRY_VERIFY((entry = item(QStringLiteral("newKind%1").arg(static_cast<int>(CurveKind::Composite)))) &&
                entry->isVisible());
    QObject *menu = entry->property("menu").value<QObject *>();
    QVERIFY(menu);
    QTRY_VERIFY(menu->property("opened").toBool()); // its opening transition is over
    const QPointF beside = entry->mapToScene(QPointF(entry->width() + 60.0, entry->height() / 2.0));
    QVERIFY(m_canvas->contains(m_canvas->mapFromScene(beside)));
    tap(beside.toPoint());
    QTRY_VERIFY(!entry->isVisible());
    QCOMPARE(m_editor->placement()->pendingCount(), 2);
    tap(sceneOf({0, -120}));
    QTRY_COMPARE(m_editor->placement()->pendingCount(), 3);
    m_window->contentItem()->forceActiveFocus();
    QTest::keyClick(m_window, Qt::Key_Return);
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(curve(1).composite().knotCount(), 3);
    QVERIFY(m_editor->commands()->deleteCurve(kontur::test::idAt(*m_editor, 1)));
    m_editor->setMode(EditController::Mode::Select);
    // A cubic through 4 points has room for no fifth: Add row gives the seed's message 8.
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Interpolating),
        QVariantList{QVariantList{0, 0}, QVariantList{10, 20}, QVariantList{30, 25}, QVariantList{40, 0}}));
    kontur::test::selectAt(*m_editor, 1, 3);
    QCOMPARE(m_editor->selection()->curveRow(), 1);
    press("addRowButton");
    QTRY_COMPARE(m_editor->message().id, Message::TooManyPoints);
    QCOMPARE(curve(1).definingCount(), 4);
}

void TestSeedScenarios::t18_typedHandleKeepsTheConstraint()
{
    // The seed refuses typed handle coordinates (message 6); Kontur takes them and keeps the rule.
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{-200, -50}, QVariantList{-60, 80}, QVariantList{80, -40}, QVariantList{200, 60}}));
    const Point knot = curve().definingPoint(3);
    const double oppositeLength = (curve().definingPoint(2) - knot).norm();
    kontur::test::selectAt(*m_editor, 0, 4);
    type(QStringLiteral("x4"), QString::number(knot.x() + 60), false);
    type(QStringLiteral("y4"), QString::number(knot.y() + 20), true);
    QTRY_VERIFY((curve().definingPoint(4) - (knot + Point(60, 20))).norm() < 1e-9);
    const Point in = curve().definingPoint(2) - knot;
    QVERIFY(std::abs(in.x() * 20 - in.y() * 60) < 1e-6 && in.dot(Point(60, 20)) < 0); // collinear, opposite
    QVERIFY(std::abs(in.norm() - oppositeLength) < 1e-9);
}

void TestSeedScenarios::t19_freeHandleDragKeepsCollinearity()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite),
                                                         QVariantList{QVariantList{-250, -50}, QVariantList{-120, 80},
                                                                      QVariantList{0, -40}, QVariantList{120, 90},
                                                                      QVariantList{250, 0}}));
    const std::vector<Point> before = curve().definingPoints();
    const int handle = 7; // outgoing handle of knot 2
    const Point knot = before[6];
    const double oppositeLength = (before[5] - knot).norm();
    const QPoint from = sceneOf(before[handle]);
    const QPoint to = from + QPoint(25, 45);
    mouseDrag(from, to); // left button: the seed's free move
    QTRY_VERIFY(!m_editor->isDragging());
    const std::vector<Point> after = curve().definingPoints();
    QVERIFY((after[handle] - worldOf(to)).norm() < 1.0);
    const Point opposite = after[5] - knot, dragged = after[handle] - knot;
    QVERIFY(std::abs(opposite.x() * dragged.y() - opposite.y() * dragged.x()) <
            1e-6 * opposite.norm() * dragged.norm());
    QVERIFY(opposite.dot(dragged) < 0);
    QVERIFY(std::abs(opposite.norm() - oppositeLength) < 1e-9);
    for (std::size_t i = 0; i < after.size(); ++i)
        if (i != 5 && i != static_cast<std::size_t>(handle))
            QCOMPARE(after[i], before[i]);
    verifyCurveDrawn(grab(), curve());
}

void TestSeedScenarios::t21_rightButtonKnotDragCarriesHandles()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{-200, -50}, QVariantList{-60, 80}, QVariantList{80, -40}, QVariantList{200, 60}}));
    const std::vector<Point> before = curve().definingPoints();
    // The composite curve's handles by docs/requirements.md 1.2 (inner handles 0.5 · l/(l1 + l2) along
    // p_i+1 − p_i−1, end handles mirrored across the end chord's perpendicular bisector), evaluated
    // in 50-digit arithmetic (mpmath) apart from the library's composite rule.
    const std::vector<Point> handles{
        {-200, -50}, {-192.19270957003355, 20.858131446972277}, {-131.24152517344384, 77.455659815234148},
        {-60, 80},   {8.7584748265561563, 82.455659815234148},  {9.6209472602183103, -34.586226712324485},
        {80, -40},   {139.62094726021831, -44.586226712324485}, {193.75972430946013, 0.52942082871036131},
        {200, 60}};
    QCOMPARE(before.size(), handles.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        QVERIFY2(
            (before[i] - handles[i]).norm() < 1e-12 * 200,
            qPrintable(
                QStringLiteral("c%1: %2, %3").arg(i).arg(before[i].x(), 0, 'g', 17).arg(before[i].y(), 0, 'g', 17)));
    const QPoint from = sceneOf(before[3]);
    const QPoint to = from + QPoint(30, -25);
    mouseDrag(from, to, Qt::RightButton);
    QTRY_VERIFY(!m_editor->isDragging());
    const std::vector<Point> after = curve().definingPoints();
    const Point delta = after[3] - before[3];
    QVERIFY((after[3] - worldOf(to)).norm() < 1.0);
    for (int i : {2, 4})
        QVERIFY((after[static_cast<std::size_t>(i)] - (before[static_cast<std::size_t>(i)] + delta)).norm() < 1e-9);
    for (std::size_t i = 0; i < after.size(); ++i)
        if (i < 2 || i > 4)
            QCOMPARE(after[i], before[i]);
}

void TestSeedScenarios::t22_typedKnotCarriesHandles()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{-200, -50}, QVariantList{-60, 80}, QVariantList{80, -40}, QVariantList{200, 60}}));
    const std::vector<Point> before = curve().definingPoints();
    kontur::test::selectAt(*m_editor, 0, 6);
    type(QStringLiteral("x6"), QStringLiteral("95"), false);
    type(QStringLiteral("y6"), QStringLiteral("-30"), true);
    QTRY_COMPARE(curve().definingPoint(6), Point(95, -30));
    const Point delta = Point(95, -30) - before[6];
    for (int i : {5, 7})
        QVERIFY((curve().definingPoint(i) - (before[static_cast<std::size_t>(i)] + delta)).norm() < 1e-9);
    QCOMPARE(curve().definingPoint(3), before[3]);
}

void TestSeedScenarios::t26_windowFollowsResizing()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{-150, -80}, QVariantList{-60, 120}, QVariantList{60, 120}, QVariantList{150, -80}}));
    for (const QSize size : {QSize(1000, 700), QSize(1600, 900), QSize(1280, 800)}) {
        m_window->resize(size);
        QTRY_COMPARE(m_window->size(), size);
        QVERIFY(kontur::test::settled(m_window));
        // The canvas takes the room it gets and the curve is drawn where the geometry says.
        const QRectF canvas = m_canvas->mapRectToScene(m_canvas->boundingRect());
        QVERIFY(QRectF(QPointF(0, 0), QSizeF(size)).contains(canvas));
        QVERIFY(canvas.width() > size.width() / 2.0);
        verifyCurveDrawn(grab(), curve());
    }
}

void TestSeedScenarios::pointRolesInTheirColours()
{
    // A composite curve shows knots (filled dots in the curve colour) and handles (rings in the
    // control point colour); a fitted cubic shows its derived control points faintly.
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{-250, -80}, QVariantList{-80, 100}, QVariantList{80, -60}, QVariantList{240, 80}}));
    // Knot 1 is selected: the handles of knots 0 to 2 are shown, not that of knot 3 (Inkscape's node
    // tool: handles only around the selected knot).
    m_editor->selection()->select(m_editor->document()->idAt(0), 3);
    m_canvas->setProperty("showGrid", false);
    const QImage image = grab();
    const QColor knotColour = m_canvas->property("curveColor").value<QColor>();
    const QColor handleColour = m_canvas->property("controlPointColor").value<QColor>();
    const int radius = static_cast<int>(std::ceil(m_canvas->property("pointRadius").toDouble())) + 2;
    const kontur::Curve &c = curve();
    for (int row = 0; row < c.definingCount(); ++row) {
        const QPoint at = sceneOf(c.definingPoint(row));
        const bool isKnot = row % 3 == 0;
        if (!c.isRowShown(row, 3)) {
            QCOMPARE(row, 8);
            QVERIFY2(nearestColour(image, at, handleColour, radius) > 60, "a hidden handle is not drawn");
            continue;
        }
        const QColor expected = isKnot ? knotColour : handleColour;
        QVERIFY2(nearestColour(image, at, expected, isKnot ? 1 : radius) < 60,
                 qPrintable(QStringLiteral("row %1 at (%2, %3): nearest %4")
                                .arg(row)
                                .arg(at.x())
                                .arg(at.y())
                                .arg(nearestColour(image, at, expected, radius))));
        if (!isKnot) // a handle is no knot-coloured dot
            QVERIFY(nearestColour(image, at, knotColour, 0) > 60);
    }
    m_canvas->setProperty("showGrid", true);
}

void TestSeedScenarios::stylusWorksLikeAFinger()
{
    // Qt 6.4 offers tablet events to Qt Quick's pointer handlers (TapHandler, DragHandler and
    // HoverHandler accept every device by default): the hovering pen moves the rubber band, and the
    // pressed pen is followed by the drag handler. A pen press that no handler accepts (the tap handler
    // only watches it) comes again as a mouse press, and the tap completes on the pen's release. The
    // canvas needs nothing stylus-specific.
    QPointingDevice stylus(
        QStringLiteral("test stylus"), 4242, QInputDevice::DeviceType::Stylus, QPointingDevice::PointerType::Pen,
        QInputDevice::Capability::Position | QInputDevice::Capability::Pressure | QInputDevice::Capability::Hover, 1,
        2);
    // What the platform does with a pen (QGuiApplicationPrivate::processTabletEvent): the tablet event
    // goes to the window first; what nobody accepts comes again as a mouse event
    // (Qt::AA_SynthesizeMouseForUnhandledTabletEvents, on by default). A test cannot enter the platform
    // path for tablets without Qt's private headers, so the tablet events are sent to the window and
    // the synthesized mouse presses and releases take QTest's platform path.
    const auto send = [&](QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        const QPointF global = m_window->mapToGlobal(QPointF(at));
        QTabletEvent event(type, &stylus, QPointF(at), global, buttons ? 0.6 : 0.0, 0, 0, 0, 0, 0, Qt::NoModifier,
                           button, buttons);
        QGuiApplication::sendEvent(m_window, &event);
        if (!event.isAccepted()) {
            // The synthesized mouse event goes through the platform path, as the real one does.
            if (type == QEvent::TabletPress)
                QTest::mousePress(m_window, button, Qt::NoModifier, at);
            else if (type == QEvent::TabletRelease)
                QTest::mouseRelease(m_window, button, Qt::NoModifier, at);
            else {
                QMouseEvent mouse(QEvent::MouseMove, QPointF(at), QPointF(at), global, Qt::NoButton, buttons,
                                  Qt::NoModifier);
                QGuiApplication::sendEvent(m_window, &mouse);
            }
        }
    };
    const auto penTap = [&](QPoint at) {
        send(QEvent::TabletMove, at, Qt::NoButton, Qt::NoButton); // hovering, as a pen does
        send(QEvent::TabletPress, at, Qt::LeftButton, Qt::LeftButton);
        send(QEvent::TabletRelease, at, Qt::LeftButton, Qt::NoButton);
    };
    const auto penStroke = [&](QPoint from, QPoint to) {
        send(QEvent::TabletPress, from, Qt::LeftButton, Qt::LeftButton);
        for (int step = 1; step <= 10; ++step)
            send(QEvent::TabletMove, from + (to - from) * step / 10, Qt::NoButton, Qt::LeftButton);
        send(QEvent::TabletRelease, to, Qt::LeftButton, Qt::NoButton);
    };

    // Taps place the four control points of a Bézier curve.
    click("newBezierButton");
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Place);
    const std::vector<Point> points{{-200, -100}, {-100, 150}, {100, 150}, {200, -100}};
    for (std::size_t i = 0; i < points.size(); ++i) {
        penTap(sceneOf(points[i]));
        if (i < 3)
            QTRY_COMPARE(m_editor->placement()->pendingCount(), static_cast<int>(i + 1));
    }
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    for (int i = 0; i < 4; ++i)
        QVERIFY((curve().definingPoint(i) - points[static_cast<std::size_t>(i)]).norm() < 1.0);
    click("selectButton");
    QTRY_COMPARE(m_editor->mode(), EditController::Mode::Select);

    // A stroke from a point moves it, as one undo step.
    const Point before = curve().definingPoint(2);
    const QPoint from = sceneOf(before);
    const QPoint to = from + QPoint(50, 40);
    penStroke(from, to);
    QTRY_VERIFY(!m_editor->isDragging());
    QVERIFY2(
        (curve().definingPoint(2) - worldOf(to)).norm() < 1.0,
        qPrintable(QStringLiteral("(%1, %2)").arg(curve().definingPoint(2).x()).arg(curve().definingPoint(2).y())));
    m_editor->undo();
    QCOMPARE(curve().definingPoint(2), before);
    m_editor->redo();

    // A stroke on empty canvas pans: the world point under the pen stays under it.
    const QPoint start = m_canvas->mapToScene(QPointF(60, m_canvas->height() - 60)).toPoint();
    const Point worldAtStart = worldOf(start);
    const std::vector<Point> unchanged = curve().definingPoints();
    penStroke(start, start + QPoint(120, -70));
    QTRY_VERIFY((worldOf(start + QPoint(120, -70)) - worldAtStart).norm() < 1.0);
    QCOMPARE(curve().definingPoints(), unchanged);
    verifyCurveDrawn(grab(), curve());
}

// Seed 004's program (§8.2.1) as its user works it: open a picture, tap points along an outline for
// the contour curve, finish; "new" starts a second curve not tied to the first; "save" writes the PNG
// with the curves over the picture; "refresh" (Reset all) clears curves and picture, as one undo step.
void TestSeedScenarios::seed004_contourCurveOverAPicture()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("car.png"));
    QVERIFY(kontur::test::loadPlainPicture(m_canvas, file, QSize(500, 300), QColor(200, 220, 240)));

    chooseKind(CurveKind::Contour);
    const std::vector<Point> roof{{-200, -60}, {-190, 20}, {-130, 60}, {-60, 80}, {0, 100},
                                  {60, 80},    {130, 60},  {190, 20},  {200, -60}};
    for (const Point &p : roof)
        tap(sceneOf(p));
    QTRY_COMPARE(m_editor->placement()->pendingCount(), static_cast<int>(roof.size()));
    click("doneButton");
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    const kontur::Curve &first = curve(0);
    QCOMPARE(first.kind(), CurveKind::Contour);
    // 9 points: three cubics joined at M23, M45 and M67, then the quadratic (M67, P7, P8).
    QCOMPARE(first.segmentCount(), 4);
    for (int j = 0; j < 3; ++j) {
        const Point joint = (first.definingPoint(2 * j + 2) + first.definingPoint(2 * j + 3)) / 2.0;
        QVERIFY((first.segment(j).endPoint() - joint).norm() < 1e-9);
        QVERIFY((first.segment(j + 1).startPoint() - joint).norm() < 1e-9);
    }
    QCOMPARE(first.segment(3).degree(), 2);
    for (std::size_t i = 0; i < roof.size(); ++i) // a tap places the point under the finger
        QVERIFY((first.definingPoint(static_cast<int>(i)) - roof[i]).norm() < 1.0);
    // The curve passes near its control points, whose markers cover it there: most samples show ink.
    const auto mostlyDrawn = [this](const QImage &image, const kontur::Curve &c) {
        const QColor ink = m_canvas->property("curveColor").value<QColor>();
        int hits = 0, samples = 0;
        for (int seg = 0; seg < c.segmentCount(); ++seg)
            for (int k = 1; k < 8; ++k, ++samples)
                hits += nearestColour(image, sceneOf(c.segment(seg).eval(k / 8.0)), ink, 1) < 150 ? 1 : 0;
        return hits >= samples * 4 / 5;
    };
    QVERIFY(mostlyDrawn(grab(), first));

    // "new": the next curve starts afresh.
    chooseKind(CurveKind::Contour);
    const std::vector<Point> wheel{{-150, -150}, {-150, -100}, {-100, -80}, {-50, -100}, {-50, -150}};
    for (const Point &p : wheel)
        tap(sceneOf(p));
    QTRY_COMPARE(m_editor->placement()->pendingCount(), 5);
    click("doneButton");
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(curve(1).segmentCount(), 2);
    QVERIFY((curve(1).segment(0).startPoint() - curve(0).segment(0).startPoint()).norm() > 10);
    const QImage shot = grab();
    QVERIFY(mostlyDrawn(shot, curve(0)));
    QVERIFY(mostlyDrawn(shot, curve(1)));

    // "save": the PNG of the view, the curves over the picture.
    const QString png = dir.filePath(QStringLiteral("traced.png"));
    m_editor->clearMessage();
    QVERIFY(m_exporter->exportPng(m_canvas, QUrl::fromLocalFile(png), 1.0));
    QTRY_COMPARE(m_editor->message().id, kontur::Message::FileSaved);
    QImage written(png);
    QCOMPARE(written.size(), m_canvas->size().toSize());
    const QColor ink = m_canvas->property("curveColor").value<QColor>();
    const QPointF onCurve =
        m_canvas->toScreen(QPointF(curve(0).segment(1).eval(0.5).x(), curve(0).segment(1).eval(0.5).y()));
    QVERIFY(nearestColour(written, onCurve.toPoint(), ink, 1) < 150);
    const QPointF onPicture = m_canvas->toScreen(QPointF(150, -120)); // inside the picture, away from both curves
    const QColor under(written.pixel(onPicture.toPoint()));
    QVERIFY2(std::abs(under.red() - 200) < 12 && std::abs(under.blue() - 240) < 12, qPrintable(under.name()));

    // "refresh": everything goes, and comes back with one undo.
    auto *reset = m_window->findChild<QObject *>(QStringLiteral("resetDialog"));
    QVERIFY(reset);
    QTest::mouseClick(m_window, Qt::LeftButton, {},
                      centerOf(kontur::test::findVisibleItem(m_window, QStringLiteral("resetButton"))));
    QTRY_VERIFY(reset->property("opened").toBool());
    QVERIFY(QMetaObject::invokeMethod(reset, "accept"));
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
    QVERIFY(m_editor->background()->file().isEmpty());
    m_editor->undo();
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(curve(0).kind(), CurveKind::Contour);
    QVERIFY(!m_editor->background()->file().isEmpty());
}

QTEST_MAIN(TestSeedScenarios)
#include "tst_seedscenarios.moc"
