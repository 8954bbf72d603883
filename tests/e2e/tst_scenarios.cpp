// Scenarios of the seed's tool in the real window, by touch, mouse and keyboard: a composite curve
// placed by finger and finished with Done (T15, T16), a constrained right-button handle drag (T20),
// typed coordinates with a decimal comma under the Latvian UI (T08/T22), deleting with the keyboard
// (T23), a background picture under the curves (T24, T25), the layout at tablet and desktop sizes, and
// per language: nothing cut, too wide or overlapping (menus too), and no English left in the dialogs.
// Over 600 lines because each scenario is written out step by step in the real window, as a user does it.
#include "windowtest.h"

#include "../curveids.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"

#include <QGuiApplication>
#include <QPointer>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

#include <functional>
#include <memory>

using kontur::CurveCanvas;
using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;

class TestScenarios final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    // Searches the visual tree: delegates and popup contents have no QObject parent in the window.
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }
    QPoint sceneOf(const Point &world) const
    {
        return m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y()))).toPoint();
    }
    void resetDocument()
    {
        m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
        m_editor->setMode(EditController::Mode::Select);
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

    // What does not fit, under `root`: a button's or menu item's text wider than the room the control
    // gives it, a one-line text wider than itself (it runs into its neighbours), and visible controls
    // of one layout or positioner (tool bar, panel rows, button rows) that overlap. List rows are left
    // out: they elide long curve names on purpose.
    static QStringList misfits(QQuickItem *root)
    {
        QStringList found;
        const auto label = [](QQuickItem *it) {
            const QString text = it->property("text").toString();
            return text.isEmpty() ? (it->objectName().isEmpty() ? QString::fromLatin1(it->metaObject()->className())
                                                                : it->objectName())
                                  : text;
        };
        std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
            if (!it->isVisible() || it->opacity() == 0.0 || it->inherits("QQuickListView"))
                return;
            const QString text = it->property("text").toString();
            if (it->inherits("QQuickAbstractButton") && !text.isEmpty()) {
                const double need = it->property("implicitContentWidth").toDouble();
                const double have = it->property("availableWidth").toDouble();
                if (need > have + 1.0)
                    found << QStringLiteral("%1 (needs %2 px, has %3)").arg(text).arg(need).arg(have);
            }
            if (it->inherits("QQuickText") && !text.isEmpty() && it->property("wrapMode").toInt() == 0 &&
                it->property("elide").toInt() == 0 && it->width() > 0 &&
                it->property("contentWidth").toDouble() > it->width() + 1.0)
                found << QStringLiteral("%1 (text %2 px wide, item %3)")
                             .arg(text)
                             .arg(it->property("contentWidth").toDouble())
                             .arg(it->width());
            if (it->inherits("QQuickLayout") || it->inherits("QQuickBasePositioner")) {
                QList<QQuickItem *> children;
                for (QQuickItem *child : it->childItems())
                    if (child->isVisible() && child->width() > 0 && child->height() > 0)
                        children << child;
                for (qsizetype i = 0; i < children.size(); ++i)
                    for (qsizetype j = i + 1; j < children.size(); ++j) {
                        const QRectF a = children[i]->mapRectToScene(children[i]->boundingRect());
                        const QRectF b = children[j]->mapRectToScene(children[j]->boundingRect());
                        const QRectF both = a.intersected(b);
                        if (both.width() > 1.0 && both.height() > 1.0)
                            found << QStringLiteral("%1 overlaps %2").arg(label(children[i]), label(children[j]));
                    }
            }
            for (QQuickItem *child : it->childItems())
                walk(child);
        };
        walk(root);
        return found;
    }
    void saveShot(const QString &name) const
    {
        if (const QByteArray dir = qgetenv("KONTUR_SCREENSHOT_DIR"); !dir.isEmpty())
            m_window->grabWindow().save(QStringLiteral("%1/%2.png").arg(QString::fromLocal8Bit(dir), name));
    }
    // Opens a tool bar button's menu, checks its items fit, closes it.
    void checkMenu(const char *button, const QString &shot)
    {
        QQuickItem *opener = item(QString::fromLatin1(button));
        QVERIFY(opener && opener->isVisible());
        QObject *menu = nullptr;
        for (QObject *child : opener->children())
            if (child->inherits("QQuickMenu"))
                menu = child;
        QVERIFY2(menu, button);
        QVERIFY(QMetaObject::invokeMethod(menu, "open"));
        QTRY_VERIFY(menu->property("opened").toBool());
        auto *content = menu->property("contentItem").value<QQuickItem *>();
        QVERIFY(content);
        saveShot(shot);
        QStringList found;
        // The menu's items are delegates of its ListView: check them one by one.
        std::function<void(QQuickItem *)> items = [&](QQuickItem *it) {
            if (it->inherits("QQuickMenuItem") && it->isVisible())
                found << misfits(it);
            for (QQuickItem *child : it->childItems())
                items(child);
        };
        items(content);
        QVERIFY(QMetaObject::invokeMethod(menu, "close"));
        QTRY_VERIFY(!menu->property("visible").toBool());
        QVERIFY2(found.isEmpty(), qPrintable(found.join(QStringLiteral(" | "))));
    }

private Q_SLOTS:
    void initTestCase();
    void init() { resetDocument(); }
    void compositeWithDone();
    void constrainedRightButtonDrag();
    void decimalCommaUnderLatvian();
    void deleteKeyRemovesPointThenCurve();
    void backgroundUnderTheCurves();
    void switchHandlesShow();
    void t01_mainWindowShows();
    void t27_zoomScalesBackgroundAndCurvesTogether();
    void t28_resetAllAsksFirst();
    void layoutAtTabletAndDesktopSizes_data();
    void layoutAtTabletAndDesktopSizes();
    void longestTranslationsFit_data();
    void longestTranslationsFit();
    void dialogsSpeakTheLanguage_data();
    void dialogsSpeakTheLanguage();
    void cleanupTestCase() { m_engine.reset(); }
};

void TestScenarios::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
}

void TestScenarios::compositeWithDone()
{
    // The kind comes from the "New curve" menu, as a user picks it.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("newCurveMenuButton"))));
    QQuickItem *compositeItem = nullptr;
    QTRY_VERIFY((compositeItem = item(QStringLiteral("newKind%1").arg(static_cast<int>(CurveKind::Composite)))) &&
                compositeItem->isVisible() && compositeItem->width() > 0);
    QVERIFY(kontur::test::clickMenuItem(m_window, compositeItem));
    QTRY_COMPARE(m_editor->placement()->kind(), static_cast<int>(CurveKind::Composite));
    QTRY_VERIFY(item(QStringLiteral("doneButton"))->isVisible());

    const std::vector<QPointF> taps{{150, 500}, {260, 320}, {420, 420}, {560, 250}, {700, 450}};
    for (std::size_t i = 0; i < taps.size(); ++i) {
        // By finger, as on a tablet (the seed's T15 uses the mouse; tst_e2e does that).
        const QPoint at = m_canvas->mapToScene(taps[i]).toPoint();
        QTest::touchEvent(m_window, m_touch).press(0, at);
        QTest::touchEvent(m_window, m_touch).release(0, at);
        QTRY_COMPARE(m_editor->placement()->pendingCount(), static_cast<int>(i + 1));
        // Segments appear from the third knot on (T15).
        QCOMPARE(m_editor->placement()->pendingSegments().size(), i >= 2 ? i - 1 : std::size_t(0));
    }
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("doneButton"))));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    const kontur::Curve &curve = m_editor->document()->curve(0);
    QCOMPARE(curve.kind(), CurveKind::Composite);
    QCOMPARE(curve.segmentCount(), 4); // Done adds the last segment (T16)
    QCOMPARE(m_editor->curves()->index(0).data(kontur::CurveListModel::ContinuityRole).toString(),
             QStringLiteral("G1"));
    // Done leaves the drawing tool: the next click, on Teaching, opens its menu and places nothing
    // (Done had shifted the bar, and a tool still armed took that click as a new point).
    QCOMPARE(m_editor->mode(), kontur::EditController::Mode::Select);
    QTRY_VERIFY(!item(QStringLiteral("doneButton"))->isVisible());
    QQuickItem *teaching = item(QStringLiteral("teachingMenuButton"));
    QVERIFY(kontur::test::clickInView(m_window, teaching));
    auto *teachingMenu = teaching->property("menu").value<QObject *>();
    QVERIFY(teachingMenu);
    QTRY_VERIFY(teachingMenu->property("opened").toBool());
    QCOMPARE(m_editor->placement()->pendingCount(), 0);
    QCOMPARE(m_editor->document()->curveCount(), 1);
    // Closed and gone before the next test: an open menu is modal and takes the next click.
    QMetaObject::invokeMethod(teachingMenu, "close");
    QTRY_VERIFY(!teachingMenu->property("visible").toBool());
}

void TestScenarios::constrainedRightButtonDrag()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{-200, -100}, QVariantList{-60, 80}, QVariantList{120, -40}, QVariantList{250, 90}}));
    const kontur::Curve &curve = m_editor->document()->curve(0);
    const Point knot = curve.definingPoint(3), handle = curve.definingPoint(4), opposite = curve.definingPoint(2);
    const Point ray = (knot - opposite).normalized();
    const QPoint from = sceneOf(handle);
    const QPoint to = from + QPoint(40, 70);
    // The knot first: its handles are shown (and can be grabbed) once it is selected.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf(knot));
    QTRY_COMPARE(m_editor->selection()->point(), 3);
    QTest::mousePress(m_window, Qt::RightButton, {}, from);
    for (int step = 1; step <= 8; ++step) {
        QMouseEvent move(QEvent::MouseMove, from + (to - from) * step / 8,
                         m_window->mapToGlobal(from + (to - from) * step / 8), Qt::NoButton, Qt::RightButton,
                         Qt::NoModifier);
        QGuiApplication::sendEvent(m_window, &move);
    }
    QTest::mouseRelease(m_window, Qt::RightButton, {}, to);
    QTRY_VERIFY(!m_editor->isDragging());
    const Point moved = m_editor->document()->curve(0).definingPoint(4);
    // On the ray from the knot away from the opposite handle, which did not move (T20).
    const Point offset = moved - knot;
    QVERIFY2(std::abs(offset.x() * ray.y() - offset.y() * ray.x()) < 1e-9 && offset.dot(ray) > 0,
             qPrintable(QStringLiteral("(%1, %2)").arg(moved.x()).arg(moved.y())));
    QVERIFY((moved - handle).norm() > 1.0);
    QCOMPARE(m_editor->document()->curve(0).definingPoint(2), opposite);
}

void TestScenarios::decimalCommaUnderLatvian()
{
    auto *language = m_engine->findChild<kontur::Language *>();
    QVERIFY(language->setCurrent(QStringLiteral("lv")));
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{0, 0}, QVariantList{50, 100}, QVariantList{150, 100}, QVariantList{200, 0}}));
    QQuickItem *field = nullptr;
    QTRY_VERIFY((field = item(QStringLiteral("x1"))) && field->isVisible());
    // The table shows numbers the Latvian way.
    QTRY_COMPARE(field->property("text").toString(), QStringLiteral("50,000"));
    // The field may be below the fold of the panel (with Roboto's metrics it is): scrolled to first.
    QVERIFY(kontur::test::clickInView(m_window, field));
    QTRY_VERIFY(field->hasActiveFocus());
    field->setProperty("text", QString()); // as select-all and typing over it would
    for (const char c : {'1', '2', ',', '5'})
        QTest::keyClick(m_window, c);
    QTest::keyClick(m_window, Qt::Key_Return);
    QTRY_COMPARE(m_editor->document()->curve(0).definingPoint(1), Point(12.5, 100));
    m_editor->undo();
    QCOMPARE(m_editor->document()->curve(0).definingPoint(1), Point(50, 100));
    QVERIFY(language->setCurrent(QStringLiteral("en")));
}

void TestScenarios::deleteKeyRemovesPointThenCurve()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{-150, 0}, QVariantList{-50, 120}, QVariantList{50, 120}, QVariantList{150, 0}}));
    m_canvas->forceActiveFocus();
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf(Point(50, 120)));
    QTRY_COMPARE(m_editor->selection()->point(), 2);
    QTest::keyClick(m_window, Qt::Key_Delete);
    QTRY_COMPARE(m_editor->document()->curve(0).placedCount(), 3);
    // Arrow keys nudge the selected point by a pixel.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf(Point(-50, 120)));
    QTRY_COMPARE(m_editor->selection()->point(), 1);
    const Point before = m_editor->document()->curve(0).definingPoint(1);
    QTest::keyClick(m_window, Qt::Key_Right, Qt::ShiftModifier);
    QTRY_VERIFY(std::abs(m_editor->document()->curve(0).definingPoint(1).x() - (before.x() + 10 / m_canvas->zoom())) <
                1e-9);
    // On the curve but away from its points: the curve is chosen, and Delete removes it (T23).
    const Point onCurve = m_editor->document()->curve(0).segment(0).eval(0.3);
    QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf(onCurve));
    QTRY_COMPARE(m_editor->selection()->curveRow(), 0);
    QCOMPARE(m_editor->selection()->point(), -1);
    QTest::keyClick(m_window, Qt::Key_Delete);
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
}

// The side panel's switches show their handle on every backend (Material's handle shadow is a
// shader effect the software backend cannot draw, which used to take the handle with it).
void TestScenarios::switchHandlesShow()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        QVariantList{QVariantList{-150, 0}, QVariantList{-50, 120}, QVariantList{50, 120}, QVariantList{150, 0}}));
    m_editor->selection()->selectRow(0);
    for (const char *name : {"visibleSwitch", "lockSwitch"}) {
        QQuickItem *control = nullptr;
        QTRY_VERIFY((control = kontur::test::findVisibleItem(m_window, QString::fromLatin1(name))) &&
                    control->isVisible());
        auto *indicator = control->property("indicator").value<QQuickItem *>();
        QVERIFY(indicator);
        auto *handle = indicator->property("handle").value<QQuickItem *>();
        QVERIFY(handle);
        const QColor expected = handle->property("color").value<QColor>();
        // The pixel under the handle's middle, wherever its slide has taken it by now.
        QColor seen;
        const auto seenDistance = [&] {
            const QImage shot = m_window->grabWindow();
            const QPoint at =
                (handle->mapToScene(QPointF(handle->width() / 2, handle->height() / 2)) * shot.devicePixelRatio())
                    .toPoint();
            seen = shot.pixelColor(at);
            return std::abs(seen.red() - expected.red()) + std::abs(seen.green() - expected.green()) +
                   std::abs(seen.blue() - expected.blue());
        };
        QTRY_VERIFY2(
            seenDistance() < 40,
            qPrintable(
                QStringLiteral("%1: handle %2, seen %3").arg(QLatin1String(name), expected.name(), seen.name())));
    }
}

void TestScenarios::backgroundUnderTheCurves()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("pattern.png"));
    QVERIFY(kontur::test::loadPlainPicture(m_canvas, file, QSize(200, 100), QColor(40, 160, 90)));
    const QPoint middle = sceneOf(Point(0, 0)); // the picture is centred on the world origin
    QImage shot = m_window->grabWindow();
    const QRgb pixel = shot.pixel(middle * shot.devicePixelRatio());
    QVERIFY2(qGreen(pixel) > 140 && qRed(pixel) < 70, qPrintable(QString::number(pixel, 16)));
    // Hidden and shown again (T25).
    m_editor->background()->setVisible(false);
    QVERIFY(kontur::test::settled(m_window));
    shot = m_window->grabWindow();
    QCOMPARE(QColor(shot.pixel(middle * shot.devicePixelRatio())), QColor(Qt::white));
    m_editor->background()->setVisible(true);
    m_editor->background()->setOpacity(0.5);
    QVERIFY(kontur::test::settled(m_window));
    shot = m_window->grabWindow();
    const QRgb half = shot.pixel(middle * shot.devicePixelRatio());
    QVERIFY2(qRed(half) > 120 && qRed(half) < 170, qPrintable(QString::number(half, 16))); // 40 over white at 50 %
    // A file that is no picture is refused with the seed's message 1 and changes nothing.
    const QString text = dir.filePath(QStringLiteral("notes.png"));
    QFile notes(text);
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.write("not a picture");
    notes.close();
    QVERIFY(!m_editor->background()->load(QUrl::fromLocalFile(text)));
    QCOMPARE(m_editor->message().id, kontur::Message::FileUploadError);
    QCOMPARE(m_editor->background()->file(), QFileInfo(file).absoluteFilePath());
    m_canvas->setProperty("showGrid", true);
}

void TestScenarios::t01_mainWindowShows()
{
    QVERIFY(m_window->isExposed());
    QVERIFY(m_window->title().contains(QStringLiteral("Kontur")));
    for (const char *name : {"canvas", "sidePanel", "newBezierButton", "fileMenuButton", "messageLine"})
        QVERIFY2(item(QString::fromLatin1(name)) && item(QString::fromLatin1(name))->isVisible(), name);
}

void TestScenarios::t27_zoomScalesBackgroundAndCurvesTogether()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("pattern.png"));
    QVERIFY(kontur::test::loadPlainPicture(m_canvas, file, QSize(200, 100), QColor(200, 40, 40)));
    // The picture spans world x in [-100, 100]; x = 90 lies inside it at any zoom, x = 110 outside.
    const auto colourAt = [&](const Point &world) {
        if (!kontur::test::settled(m_window))
            return QColor();
        const QImage shot = m_window->grabWindow();
        return QColor(shot.pixel(sceneOf(world) * shot.devicePixelRatio()));
    };
    for (const char *button : {"zoomInButton", "zoomInButton", "zoomOutButton"}) {
        const double before = m_canvas->zoom();
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QString::fromLatin1(button))));
        QTRY_VERIFY(m_canvas->zoom() != before);
        QCOMPARE(colourAt(Point(90, 0)), QColor(200, 40, 40));
        QCOMPARE(colourAt(Point(110, 0)), QColor(Qt::white));
    }
    m_editor->background()->clear();
    m_canvas->setProperty("showGrid", true);
}

void TestScenarios::t28_resetAllAsksFirst()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                         QVariantList{QVariantList{0, 0}, QVariantList{10, 10}}));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("resetButton"))));
    QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("resetDialog"));
    QTRY_VERIFY(dialog->property("opened").toBool());
    // The question is the seed's message 4; "No" keeps everything.
    QVERIFY(dialog->property("visible").toBool());
    QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
    QTRY_VERIFY(!dialog->property("visible").toBool());
    QCOMPARE(m_editor->document()->curveCount(), 1);
    // "Yes" removes every curve, as one undo step.
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("resetButton"))));
    QTRY_VERIFY(dialog->property("opened").toBool());
    // The standard button's text as Qt's own translations give it (the process locale may be lv or ru).
    const QString yesText = QCoreApplication::translate("QPlatformTheme", "&Yes").remove(QLatin1Char('&'));
    QQuickItem *yes = nullptr;
    std::function<void(QQuickItem *)> find = [&](QQuickItem *it) {
        const QString text = it->property("text").toString().remove(QLatin1Char('&'));
        if (!yes && it->isVisible() && it->inherits("QQuickAbstractButton") &&
            (text == yesText || text == QStringLiteral("Yes")))
            yes = it;
        for (QQuickItem *child : it->childItems())
            find(child);
    };
    find(m_window->contentItem());
    if (!yes) {
        QStringList texts;
        std::function<void(QQuickItem *)> list = [&](QQuickItem *it) {
            if (it->isVisible() && it->inherits("QQuickAbstractButton"))
                texts << it->property("text").toString();
            for (QQuickItem *child : it->childItems())
                list(child);
        };
        list(m_window->contentItem());
        QFAIL(qPrintable(QStringLiteral("no Yes button among: ") + texts.join(QStringLiteral(", "))));
    }
    QVERIFY(dialog->property("opened").toBool()); // its opening transition is over (waited above)
    QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(yes));
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
    QTRY_VERIFY(!dialog->property("visible").toBool());
    m_editor->undo();
    QCOMPARE(m_editor->document()->curveCount(), 1);
}

void TestScenarios::layoutAtTabletAndDesktopSizes_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addRow("tablet portrait") << QSize(800, 1280);
    QTest::addRow("tablet landscape") << QSize(1280, 800);
    QTest::addRow("laptop") << QSize(1280, 720);
    QTest::addRow("projector") << QSize(1920, 1080);
}

void TestScenarios::layoutAtTabletAndDesktopSizes()
{
    QFETCH(QSize, size);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    QVERIFY(kontur::test::settled(m_window));
    const QRectF window(QPointF(0, 0), QSizeF(size));
    const auto rectOf = [](QQuickItem *it) { return it->mapRectToScene(it->boundingRect()); };
    const QRectF canvas = rectOf(m_canvas);
    QVERIFY(window.contains(canvas));
    QVERIFY(canvas.width() >= 360 && canvas.height() >= 360);
    QQuickItem *panel = item(QStringLiteral("sidePanel"));
    QVERIFY(panel);
    QQuickItem *sheet = item(QStringLiteral("bottomSheet"));
    QVERIFY(sheet);
    if (sheet->isVisible()) {
        // Portrait: the panel is a sheet over the canvas's bottom, and the canvas keeps 60 % of the
        // window above it.
        const QRectF over = rectOf(sheet);
        QVERIFY(window.contains(over));
        QVERIFY(sheet->isAncestorOf(panel));
        QCOMPARE(over.bottom(), canvas.bottom());
        QVERIFY2((canvas.height() - over.height()) * canvas.width() >= 0.6 * size.width() * size.height(),
                 qPrintable(QStringLiteral("sheet %1 of canvas %2").arg(over.height()).arg(canvas.height())));
    } else if (panel->isVisible()) {
        const QRectF side = rectOf(panel);
        QVERIFY(window.contains(side));
        QVERIFY2(!side.intersects(canvas), "the panel covers the canvas");
    }
    // The message line and the canvas do not overlap (the tool bar's buttons: tst_toolbar_window).
    QQuickItem *messageLine = item(QStringLiteral("messageLine"));
    QVERIFY(messageLine && messageLine->isVisible());
    QVERIFY(!rectOf(messageLine).intersects(canvas));
    QVERIFY(window.contains(rectOf(messageLine)));
    // Touch targets: the tool bar's buttons are at least 44 px tall.
    QQuickItem *newBezier = item(QStringLiteral("newBezierButton"));
    QVERIFY(newBezier->height() >= 44);
    m_window->resize(1280, 800);
}

void TestScenarios::longestTranslationsFit_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("size");
    for (const char *code : {"lv", "sk", "bg", "ru", "en"}) {
        QTest::addRow("%s portrait", code) << QString::fromLatin1(code) << QSize(800, 1280);
        QTest::addRow("%s laptop", code) << QString::fromLatin1(code) << QSize(1280, 720);
    }
}

void TestScenarios::longestTranslationsFit()
{
    QFETCH(QString, language);
    QFETCH(QSize, size);
    // A curve selected, so that the panel shows its settings, table and info.
    QVERIFY(m_editor->placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Composite),
        QVariantList{QVariantList{0, 0}, QVariantList{50, 80}, QVariantList{120, 10}}));
    auto *lang = m_engine->findChild<kontur::Language *>();
    QVERIFY(lang->setCurrent(language));
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    QVERIFY(kontur::test::settled(m_window));
    const QString shot = QStringLiteral("layout-%1-%2x%3").arg(language).arg(size.width()).arg(size.height());
    saveShot(shot);
    // No visible text is cut short, except the one-line summaries of list rows, which elide long
    // curve names on purpose.
    QStringList truncated;
    std::function<void(QQuickItem *, bool)> walk = [&](QQuickItem *it, bool inList) {
        if (!it->isVisible())
            return;
        inList = inList || it->inherits("QQuickListView");
        if (!inList && it->inherits("QQuickText") && it->property("truncated").toBool())
            truncated << it->property("text").toString();
        for (QQuickItem *child : it->childItems())
            walk(child, inList);
    };
    walk(m_window->contentItem(), false);
    QVERIFY2(truncated.isEmpty(), qPrintable(truncated.join(QStringLiteral(" | "))));
    // Nothing in the panel reaches past its edge (the panel clips; what is clipped cannot be seen).
    QQuickItem *panel = item(QStringLiteral("sidePanel"));
    if (panel->isVisible()) {
        const QRectF bounds = panel->mapRectToScene(panel->boundingRect()).adjusted(-1, -1, 1, 1);
        QStringList outside;
        std::function<void(QQuickItem *)> check = [&](QQuickItem *it) {
            if (!it->isVisible() || it->inherits("QQuickListView") || it->inherits("QQuickFlickable"))
                return;
            const QRectF r = it->mapRectToScene(it->boundingRect());
            if (it->inherits("QQuickText") && !it->property("text").toString().isEmpty() &&
                (r.right() > bounds.right() || r.left() < bounds.left()))
                outside << it->property("text").toString();
            for (QQuickItem *child : it->childItems())
                check(child);
        };
        for (QQuickItem *child : panel->childItems())
            check(child);
        QVERIFY2(outside.isEmpty(), qPrintable(outside.join(QStringLiteral(" | "))));
    }
    // The message line shows all of its lines.
    QQuickItem *line = item(QStringLiteral("messageLine"));
    const QRectF lineRect = line->mapRectToScene(line->boundingRect());
    QVERIFY2(lineRect.bottom() <= size.height() + 1, qPrintable(QStringLiteral("line %1..%2, implicit %3, parent %4")
                                                                    .arg(lineRect.top())
                                                                    .arg(lineRect.bottom())
                                                                    .arg(line->implicitHeight())
                                                                    .arg(line->parentItem()->height())));
    // No button or one-line text is wider than its room, and no controls of a row or column overlap,
    // in the window and in the menus of the tool bar.
    const QStringList found = misfits(m_window->contentItem());
    QVERIFY2(found.isEmpty(), qPrintable(found.join(QStringLiteral(" | "))));
    checkMenu("fileMenuButton", shot + QStringLiteral("-file-menu"));
    checkMenu("newCurveMenuButton", shot + QStringLiteral("-new-curve-menu"));
    checkMenu("languageMenuButton", shot + QStringLiteral("-language-menu"));
    // On a tablet held upright the panel is a bottom sheet: raised to its full height, it fits too.
    if (QQuickItem *sheet = item(QStringLiteral("bottomSheet")); sheet->isVisible()) {
        QVERIFY(QMetaObject::invokeMethod(sheet, "setStop", Q_ARG(QVariant, 2)));
        QTRY_VERIFY(std::abs(sheet->height() - sheet->property("fullHeight").toDouble()) < 0.5);
        saveShot(shot + QStringLiteral("-panel"));
        QQuickItem *content = sheet;
        QStringList inDrawer = misfits(content);
        std::function<void(QQuickItem *, bool)> cut = [&](QQuickItem *it, bool inList) {
            if (!it->isVisible())
                return;
            inList = inList || it->inherits("QQuickListView");
            if (!inList && it->inherits("QQuickText") && it->property("truncated").toBool())
                inDrawer << it->property("text").toString() + QStringLiteral(" (cut)");
            for (QQuickItem *child : it->childItems())
                cut(child, inList);
        };
        cut(content, false);
        QVERIFY(QMetaObject::invokeMethod(sheet, "setStop", Q_ARG(QVariant, 0)));
        QTRY_VERIFY(std::abs(sheet->height() - sheet->property("peekStop").toDouble()) < 0.5);
        QVERIFY2(inDrawer.isEmpty(), qPrintable(inDrawer.join(QStringLiteral(" | "))));
    }
    QVERIFY(lang->setCurrent(QStringLiteral("en")));
    m_window->resize(1280, 800);
}

void TestScenarios::dialogsSpeakTheLanguage_data()
{
    QTest::addColumn<QString>("language");
    for (const char *code : {"lv", "sk", "bg", "ru"})
        QTest::addRow("%s", code) << QString::fromLatin1(code);
}

void TestScenarios::dialogsSpeakTheLanguage()
{
    // Every dialog Kontur shows, opened after a switch to the language: no text is left in English.
    // Each has Kontur's own buttons and labels (the file dialogs are FileBrowserDialog, no longer Qt's,
    // whose labels Debian's Qt translations lacked in every language).
    QFETCH(QString, language);
    auto *lang = m_engine->findChild<kontur::Language *>();
    QVERIFY(lang->setCurrent(language));
    QVERIFY(kontur::test::settled(m_window));
    const QStringList english{QStringLiteral("Open"),
                              QStringLiteral("Save"),
                              QStringLiteral("Cancel"),
                              QStringLiteral("Discard"),
                              QStringLiteral("Yes"),
                              QStringLiteral("No"),
                              QStringLiteral("Close without Saving"),
                              QStringLiteral("File name"),
                              QStringLiteral("Filter")};
    const auto englishShown = [&] {
        QStringList shown;
        std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
            if (!it->isVisible() || it->opacity() == 0.0)
                return;
            QString text = it->property("text").toString();
            text.remove(QLatin1Char('&'));
            if ((it->inherits("QQuickText") || it->inherits("QQuickAbstractButton")) && english.contains(text))
                shown << text;
            for (QQuickItem *child : it->childItems())
                walk(child);
        };
        walk(m_window->contentItem());
        shown.removeDuplicates();
        return shown;
    };
    // The popups shown (dialogs, and the popup a file dialog creates to show itself); tool tips
    // come and go with the pointer, and the side panel is a drawer docked beside the canvas.
    const auto shownPopups = [&] {
        QList<QObject *> shown;
        for (QObject *object : m_window->findChildren<QObject *>())
            if (object->inherits("QQuickPopup") && !object->inherits("QQuickToolTip") &&
                object->objectName() != QLatin1String("panelDrawer") && object->property("visible").toBool())
                shown << object;
        return shown;
    };
    const auto anyPopupShown = [&] { return !shownPopups().isEmpty(); };
    // Every popup shown has finished its opening transition; with `needOne`, one at least is shown.
    const auto popupsSettled = [&](bool needOne) {
        const QList<QObject *> shown = shownPopups();
        return (!needOne || !shown.isEmpty()) &&
               std::all_of(shown.begin(), shown.end(), [](QObject *p) { return p->property("opened").toBool(); });
    };
    QStringList dialogs;
    QStringList failures;
    // Chosen first: opening a dialog creates and deletes objects of its own.
    QList<QPointer<QObject>> candidates;
    for (QObject *object : m_window->findChildren<QObject *>())
        if (kontur::test::isFileDialog(object) || (object->inherits("QQuickDialog") && !object->objectName().isEmpty()))
            candidates << object;
    for (const QPointer<QObject> &object : candidates) {
        if (!object)
            continue;
        const bool fileDialog = kontur::test::isFileDialog(object);
        dialogs << object->property("title").toString();
        QVERIFY(QMetaObject::invokeMethod(object, "open"));
        if (fileDialog)
            QTRY_VERIFY(object->property("visible").toBool());
        else
            QTRY_VERIFY(object->property("opened").toBool());
        // Every popup shown has finished opening (a file dialog's own popup comes a moment after
        // the dialog turns visible, and its texts with it).
        QTRY_VERIFY(popupsSettled(fileDialog));
        const QStringList shown = englishShown();
        if (!shown.isEmpty())
            failures << QStringLiteral("%1: %2").arg(object->property("title").toString(),
                                                     shown.join(QStringLiteral(", ")));
        saveShot(QStringLiteral("dialog-%1-%2").arg(language).arg(dialogs.size()));
        QVERIFY(QMetaObject::invokeMethod(object, fileDialog ? "reject" : "close"));
        QTRY_VERIFY(!object->property("visible").toBool());
        QTRY_VERIFY(!anyPopupShown()); // closed, its closing transition over
    }
    QVERIFY2(dialogs.size() >= 8, qPrintable(dialogs.join(QStringLiteral(", "))));
    QVERIFY(lang->setCurrent(QStringLiteral("en")));
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QStringLiteral(" | "))));
}

QTEST_MAIN(TestScenarios)
#include "tst_scenarios.moc"
