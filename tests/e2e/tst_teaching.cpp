// The teaching views in the real window (issue #9 part A): chosen from the Teaching menu, driven by
// mouse, touch and keyboard, and checked on screen — the pixels where the geometry says the de
// Casteljau points, the elevated polygon, the comb and the compared curves are carry their colours.
#include "windowtest.h"

#include "../curveids.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/teaching/teachingcontroller.h"
#include "models/trace/tracecontroller.h"

#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSettings>
#include <QtTest>

#include <functional>
#include <memory>

using kontur::Curve;
using kontur::CurveCanvas;
using kontur::CurveKind;
using kontur::EditController;
using kontur::TeachingController;
using kontur::geo::Point;
using View = TeachingController::View;

class TestTeachingWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }
    QPointF sceneOf(const Point &world) const
    {
        return m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y())));
    }
    // Whether a pixel within `radius` of `at` (scene coordinates) is close to `color`.
    static bool colorNear(const QImage &shot, QPointF at, const QColor &color, int radius = 2)
    {
        const double dpr = shot.devicePixelRatio();
        for (int dy = -radius; dy <= radius; ++dy) {
            for (int dx = -radius; dx <= radius; ++dx) {
                const QPoint p(static_cast<int>(std::lround(at.x() * dpr)) + dx,
                               static_cast<int>(std::lround(at.y() * dpr)) + dy);
                if (!shot.rect().contains(p))
                    continue;
                const QColor c = shot.pixelColor(p);
                if (std::abs(c.red() - color.red()) + std::abs(c.green() - color.green()) +
                        std::abs(c.blue() - color.blue()) <
                    60)
                    return true;
            }
        }
        return false;
    }
    QColor themeColor(const char *name) const
    {
        QObject *painter = item(QStringLiteral("teachingPainter"));
        return painter ? painter->property(name).value<QColor>() : QColor();
    }
    // Chooses a view from the Teaching menu, as a user does.
    void chooseView(const QString &entry)
    {
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("teachingMenuButton"))));
        QQuickItem *menuItem = nullptr;
        QTRY_VERIFY((menuItem = item(entry)) && menuItem->isVisible() && menuItem->width() > 0);
        QVERIFY(kontur::test::clickMenuItem(m_window, menuItem));
        // The bar under the canvas took its room: show every curve in what is left.
        QVERIFY(kontur::test::settled(m_window));
        m_canvas->fitToView();
        QVERIFY(kontur::test::settled(m_window));
    }
    void addCurve(CurveKind kind, std::vector<Point> points)
    {
        m_editor->commands()->addCurves({Curve::make(kind, std::move(points))}, QStringLiteral("test"));
    }

    TeachingController *m_teaching = nullptr;

private Q_SLOTS:
    void initTestCase();
    void init();
    void deCasteljauByMarkerAndSlider();
    void elevationStepsAndAltClick();
    void longPressAddsControlPoint();
    void combDrawsTeethOutside();
    void compareWithLegend();
    void presentationMode();
    void barsInEveryLanguage_data();
    void barsInEveryLanguage();
    void cleanupTestCase() { m_engine.reset(); }
};

// The teaching and tracing bars at 1280×800 in every language: each visible control inside the bar
// and the window, no two overlapping, no label cut short; a screenshot of each to look at
// (KONTUR_SCREENSHOT_DIR).
void TestTeachingWindow::barsInEveryLanguage_data()
{
    QTest::addColumn<QString>("language");
    for (const char *language : {"en", "lv", "sk", "bg", "ru"})
        QTest::addRow("%s", language) << QString::fromLatin1(language);
}

void TestTeachingWindow::barsInEveryLanguage()
{
    QFETCH(QString, language);
    auto *lang = m_engine->findChild<kontur::Language *>();
    auto *trace = m_window->findChild<kontur::TraceController *>(QStringLiteral("trace"));
    QVERIFY(lang && trace);
    QVERIFY(lang->setCurrent(language));
    // Seed 004's contour curve, whose joints the construction marks.
    addCurve(
        CurveKind::Contour,
        {{-350, -100}, {-300, 80}, {-180, 160}, {-60, 120}, {40, 180}, {160, 140}, {260, 60}, {330, -80}, {350, -150}});
    const auto check = [&](const QString &barName, const QString &shot) {
        QQuickItem *bar = item(barName);
        QVERIFY(bar);
        QTRY_VERIFY(bar->isVisible());
        QVERIFY(kontur::test::settled(m_window));
        const QRectF box = bar->mapRectToScene(bar->boundingRect());
        QVERIFY(box.right() <= m_window->width() + 0.5);
        QList<QQuickItem *> controls;
        std::function<void(QQuickItem *)> collect = [&](QQuickItem *it) {
            if (!it->isVisible() || it->width() <= 0)
                return;
            const bool control = it->inherits("QQuickControl") && !it->inherits("QQuickPopup");
            const bool text = it->inherits("QQuickText") && !it->property("text").toString().isEmpty();
            if (control || text) {
                controls << it;
                if (control)
                    return; // its own parts are its business
            }
            for (QQuickItem *child : it->childItems())
                collect(child);
        };
        collect(bar);
        QVERIFY(controls.size() >= 3);
        const auto describe = [](QQuickItem *it) {
            return QStringLiteral("%1 \"%2\"").arg(it->objectName(), it->property("text").toString());
        };
        for (qsizetype i = 0; i < controls.size(); ++i) {
            const QRectF r = controls[i]->mapRectToScene(controls[i]->boundingRect());
            QVERIFY2(r.left() >= box.left() - 0.5 && r.right() <= box.right() + 0.5 && r.top() >= box.top() - 0.5 &&
                         r.bottom() <= box.bottom() + 0.5,
                     qPrintable(language + QStringLiteral(": ") + describe(controls[i]) +
                                QStringLiteral(" is outside its bar")));
            if (controls[i]->inherits("QQuickText"))
                QVERIFY2(!controls[i]->property("truncated").toBool(),
                         qPrintable(language + QStringLiteral(": ") + describe(controls[i]) +
                                    QStringLiteral(" is cut short")));
            for (qsizetype j = i + 1; j < controls.size(); ++j) {
                if (controls[j]->parentItem() == controls[i] || controls[i]->parentItem() == controls[j])
                    continue;
                const QRectF other = controls[j]->mapRectToScene(controls[j]->boundingRect());
                QVERIFY2(r.intersected(other).width() < 0.5 || r.intersected(other).height() < 0.5,
                         qPrintable(language + QStringLiteral(": ") + describe(controls[i]) +
                                    QStringLiteral(" overlaps ") + describe(controls[j])));
            }
        }
        kontur::test::screenshot(m_window, QStringLiteral("bars-%1-%2.png").arg(shot, language));
    };
    for (const auto &[view, shot] :
         {std::pair{View::DeCasteljau, QStringLiteral("decasteljau")},
          std::pair{View::Elevation, QStringLiteral("elevation")}, std::pair{View::Compare, QStringLiteral("compare")},
          std::pair{View::Comb, QStringLiteral("comb")}}) {
        m_teaching->setView(view);
        m_canvas->fitToView();
        check(QStringLiteral("teachingBar"), shot);
    }
    m_teaching->setView(View::None);
    for (const auto &[tool, shot] :
         {std::pair{kontur::TraceController::Tool::Freehand, QStringLiteral("freehand")},
          std::pair{kontur::TraceController::Tool::Calibrate, QStringLiteral("calibrate")},
          std::pair{kontur::TraceController::Tool::Perspective, QStringLiteral("perspective")},
          std::pair{kontur::TraceController::Tool::Outline, QStringLiteral("outline")},
          std::pair{kontur::TraceController::Tool::Seam, QStringLiteral("seam")},
          std::pair{kontur::TraceController::Tool::Deviation, QStringLiteral("deviation")}}) {
        trace->setTool(tool);
        check(QStringLiteral("traceBar"), shot);
    }
    trace->setTool(kontur::TraceController::Tool::None);
    QVERIFY(lang->setCurrent(QStringLiteral("en")));
}

void TestTeachingWindow::initTestCase()
{
    // The settings are the process's own (ownfolders.h): presentation mode starts off.
    QVERIFY(!QSettings().contains(QStringLiteral("presentation")));
    QVERIFY(start(QSize(1280, 800)));
    m_teaching = m_window->findChild<TeachingController *>(QStringLiteral("teaching"));
    QVERIFY(m_teaching);
}

void TestTeachingWindow::init()
{
    m_teaching->setView(View::None);
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_editor->setMode(EditController::Mode::Select);
    m_canvas->resetView();
    QVERIFY(kontur::test::settled(m_window));
}

void TestTeachingWindow::deCasteljauByMarkerAndSlider()
{
    addCurve(CurveKind::Bezier, {{-300, -150}, {-150, 200}, {150, 200}, {300, -150}});
    chooseView(QStringLiteral("teachingDeCasteljau"));
    QCOMPARE(m_teaching->view(), View::DeCasteljau);
    QTRY_VERIFY(item(QStringLiteral("teachingBar"))->isVisible());

    // Drag the marker B(t) along the curve to where t = 0.3.
    const kontur::geo::Bezier curve = m_editor->document()->curve(0).segment(0);
    const QPoint from = sceneOf(curve.eval(m_teaching->parameter())).toPoint();
    const QPoint to = sceneOf(curve.eval(0.3)).toPoint();
    const QPointF centre = m_canvas->center();
    const int steps = m_editor->undoStack()->count();
    QTest::mouseMove(m_window, from);
    QTest::mousePress(m_window, Qt::LeftButton, {}, from);
    for (int step = 1; step <= 12; ++step) {
        const QPoint at = from + (to - from) * step / 12;
        QMouseEvent move(QEvent::MouseMove, at, m_window->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QGuiApplication::sendEvent(m_window, &move);
    }
    QTest::mouseRelease(m_window, Qt::LeftButton, {}, to);
    QVERIFY2(std::abs(m_teaching->parameter() - 0.3) < 0.01, qPrintable(QString::number(m_teaching->parameter())));
    QCOMPARE(m_canvas->center(), centre);            // the view did not pan
    QCOMPARE(m_editor->undoStack()->count(), steps); // and the curve did not move

    // Exactly 0.3 with the keyboard steps from the slider's value, then the points equal the geometry's.
    m_teaching->setParameter(0.25);
    for (int i = 0; i < 5; ++i)
        QTest::keyClick(m_window, Qt::Key_Period);
    QVERIFY(std::abs(m_teaching->parameter() - 0.3) < 1e-12);
    // De Casteljau at t = 0.3 by hand: each level interpolates the previous one at 0.3.
    const std::vector<std::vector<Point>> expected{{{-300, -150}, {-150, 200}, {150, 200}, {300, -150}},
                                                   {{-255, -45}, {-60, 200}, {195, 95}},
                                                   {{-196.5, 28.5}, {16.5, 168.5}},
                                                   {{-132.6, 70.5}}};
    const QVariantList shown = m_teaching->constructionPoints();
    QCOMPARE(shown.size(), 4);
    for (int k = 0; k < 4; ++k) {
        const QVariantList level = shown.at(k).toList();
        QCOMPARE(level.size(), 4 - k);
        for (int i = 0; i < level.size(); ++i) {
            const QPointF p = level.at(i).toPointF();
            QVERIFY((Point(p.x(), p.y()) - expected[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)]).norm() <
                    1e-9);
        }
    }
    // On screen: the level-1 points in the first level colour, the level-2 points in the second,
    // B(t) in the marker colour.
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    const QVariantList levels =
        m_window->findChild<QObject *>(QStringLiteral("teachingPainter"))->property("levelColors").toList();
    for (int k = 1; k <= 2; ++k)
        for (const Point &p : expected[static_cast<std::size_t>(k)])
            QVERIFY2(colorNear(shot, sceneOf(p), levels.at(k - 1).value<QColor>()), qPrintable(QString::number(k)));
    QVERIFY(colorNear(shot, sceneOf(expected[3][0]), themeColor("markerColor"), 3));

    // Split at t: two curves, one undo step.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("splitButton"))));
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QVERIFY((m_editor->document()->curve(1).segment(0).startPoint() - curve.eval(0.3)).norm() < 1e-9);
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_editor->document()->curveCount(), 1);

    // Play and pause from the keyboard.
    QTest::keyClick(m_window, Qt::Key_P);
    QVERIFY(m_teaching->isPlaying());
    QTest::keyClick(m_window, Qt::Key_P);
    QVERIFY(!m_teaching->isPlaying());
}

void TestTeachingWindow::elevationStepsAndAltClick()
{
    addCurve(CurveKind::Bezier, {{-300, -150}, {-150, 200}, {150, 200}, {300, -150}});
    chooseView(QStringLiteral("teachingElevation"));
    QCOMPARE(m_teaching->view(), View::Elevation);
    const int n = 3;
    for (int r = 1; r <= 4; ++r) {
        QTest::keyClick(m_window, Qt::Key_Period);
        QCOMPARE(m_teaching->elevationStep(), r);
        QCOMPARE(m_teaching->elevatedPoints().size(), n + r + 1); // the slider at step r shows n + r + 1 points
    }
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    const QColor elevated = themeColor("elevatedColor");
    int seen = 0;
    for (const QVariant &v : m_teaching->elevatedPoints()) {
        const QPointF p = v.toPointF();
        seen += colorNear(shot, sceneOf(Point(p.x(), p.y())), elevated) ? 1 : 0;
    }
    // The end points lie under the curve's own control points (drawn by the canvas); the rest show.
    QVERIFY2(seen >= n + 4 + 1 - 2, qPrintable(QString::number(seen)));
    // The slider's label names the degrees and the number of points.
    QVERIFY(item(QStringLiteral("elevationReadout"))->property("text").toString().contains(QStringLiteral("(8 point")));

    // Alt+click on empty canvas adds a control point; Alt+click on it removes it again.
    const QPoint empty = sceneOf(Point(0, -100)).toPoint();
    QTest::mouseClick(m_window, Qt::LeftButton, Qt::AltModifier, empty);
    QTRY_COMPARE(m_teaching->degree(), 4);
    QCOMPARE(m_editor->document()->curveCount(), 1);
    QTest::mouseClick(m_window, Qt::LeftButton, Qt::AltModifier, empty);
    QTRY_COMPARE(m_teaching->degree(), 3);
    // Reduce degree from the bar: one undo step.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("reduceButton"))));
    QTRY_COMPARE(m_teaching->degree(), 2);
    m_editor->undo();
    QCOMPARE(m_teaching->degree(), 3);
}

void TestTeachingWindow::longPressAddsControlPoint()
{
    addCurve(CurveKind::Bezier, {{-300, -150}, {-150, 200}, {150, 200}, {300, -150}});
    m_teaching->setView(View::Elevation);
    QVERIFY(kontur::test::settled(m_window));
    m_canvas->fitToView();
    QVERIFY(kontur::test::settled(m_window));
    // A long press by finger on empty canvas: held until the press-and-hold adds the point (the
    // handler answers while the finger is still down), then lifted.
    const QPoint at = sceneOf(Point(0, -100)).toPoint();
    QTest::touchEvent(m_window, m_touch).press(0, at);
    QTRY_COMPARE(m_teaching->degree(), 4);
    QTest::touchEvent(m_window, m_touch).release(0, at);
    QCOMPARE(m_teaching->degree(), 4);
    // The ordinary tap did not also deselect or place anything.
    QCOMPARE(m_editor->document()->curveCount(), 1);
}

void TestTeachingWindow::combDrawsTeethOutside()
{
    const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0) * 250.0;
    addCurve(CurveKind::Bezier, {{250, 0}, {250, k}, {k, 250}, {0, 250}});
    chooseView(QStringLiteral("teachingComb"));
    QCOMPARE(m_teaching->view(), View::Comb);
    m_canvas->zoomOut(); // the teeth reach beyond the fitted curve
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    const QColor comb = themeColor("combColor");
    // The outline through the tips lies outside the arc (κ > 0: teeth away from the centre).
    int outside = 0;
    const QVariantList teeth = m_teaching->combTeeth();
    for (const QVariant &v : teeth) {
        const QPointF tip = v.toMap().value(QStringLiteral("tip")).toPointF();
        QVERIFY(std::hypot(tip.x(), tip.y()) > 255.0);
        outside += colorNear(shot, sceneOf(Point(tip.x(), tip.y())), comb) ? 1 : 0;
    }
    QVERIFY2(outside >= teeth.size() * 9 / 10, qPrintable(QStringLiteral("%1 of %2").arg(outside).arg(teeth.size())));
    // And nothing of the comb inside the arc, at half the radius.
    QVERIFY(!colorNear(shot, sceneOf(Point(90, 90)), comb, 3));
}

void TestTeachingWindow::compareWithLegend()
{
    addCurve(CurveKind::NaturalSpline, {{-300, -100}, {-150, 150}, {0, -50}, {150, 150}, {300, -100}});
    chooseView(QStringLiteral("teachingCompare"));
    QCOMPARE(m_teaching->view(), View::Compare);
    QTRY_VERIFY(item(QStringLiteral("compareLegend"))->isVisible());
    QVERIFY(item(QStringLiteral("legendEntry6")));
    QVERIFY(kontur::test::settled(m_window));
    const QImage shot = m_window->grabWindow();
    const QVariantList palette =
        m_window->findChild<QObject *>(QStringLiteral("teachingPainter"))->property("palette").toList();
    // Each compared curve shows in its colour somewhere along its middle (where the curves part).
    const auto &curves = m_teaching->scene().curves;
    QCOMPARE(curves.size(), std::size_t{8});
    for (const auto &c : curves) {
        const QColor color = palette.at(c.index).value<QColor>();
        int hits = 0;
        for (const auto &piece : c.pieces)
            for (double t : {0.3, 0.5, 0.7})
                hits += colorNear(shot, sceneOf(piece.eval(t)), color, 1) ? 1 : 0;
        QVERIFY2(hits > 0, qPrintable(QString::number(c.index)));
    }
    // A click on a legend entry hides its curve.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("legendEntry0"))));
    QTRY_COMPARE(m_teaching->scene().curves.size(), std::size_t{7});
}

void TestTeachingWindow::presentationMode()
{
    const double width = m_canvas->property("curveWidth").toDouble();
    const double fontSize = m_window->property("font").value<QFont>().pixelSize();
    QTest::keyClick(m_window, Qt::Key_F5);
    QTRY_VERIFY(std::abs(m_canvas->property("curveWidth").toDouble() - 1.75 * width) < 1e-9);
    QVERIFY(m_window->property("font").value<QFont>().pixelSize() > fontSize);
    QCOMPARE(QSettings().value(QStringLiteral("presentation")).toBool(), true);
    QTest::keyClick(m_window, Qt::Key_F5);
    QTRY_VERIFY(std::abs(m_canvas->property("curveWidth").toDouble() - width) < 1e-9);
    QCOMPARE(m_window->property("font").value<QFont>().pixelSize(), fontSize);
    QCOMPARE(QSettings().value(QStringLiteral("presentation")).toBool(), false);
}

QTEST_MAIN(TestTeachingWindow)
#include "tst_teaching.moc"
