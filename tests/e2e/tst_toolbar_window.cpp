// The responsive tool bar (issue #19) in the real window, at the window sizes of phones, tablets and
// desktops (KONTUR_TOOLBAR_SIZES, physical pixels; QT_SCALE_FACTOR as the environment gives it) and
// in every language: every action of the registry (AppActions) is reachable in at most two taps —
// on the bar, or in a menu that one tap on the bar opens (a tool bar menu or the overflow menu) —
// and a command taken that way does what it says; no control of the bar is cut off by the window or
// lies over another; every control of the bar and of its menus is at least Theme.touchMinimum
// (48 device-independent pixels) in both dimensions (menu items: tall); every button and menu
// item of the window has an accessible name. One window, resized, serves every size and language.
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/teaching/teachingcontroller.h"

#include <QAccessible>
#include <QGuiApplication>
#include <QHash>
#include <QJSValue>
#include <QMetaProperty>
#include <QPointingDevice>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSet>
#include <QStyleHints>
#include <QtTest>

#include <functional>
#include <memory>

using kontur::CurveCanvas;
using kontur::EditController;
using kontur::TeachingController;

namespace {

constexpr double kTouchMinimum = 48.0;

QList<QQuickItem *> menuItems(QObject *menu)
{
    QList<QQuickItem *> items;
    const int count = menu->property("count").toInt();
    for (int i = 0; i < count; ++i) {
        QQuickItem *it = nullptr;
        QMetaObject::invokeMethod(menu, "itemAt", Q_RETURN_ARG(QQuickItem *, it), Q_ARG(int, i));
        if (it)
            items << it;
    }
    return items;
}

// The objects of a QML list or array property.
QList<QObject *> objects(const QVariant &value)
{
    QList<QObject *> list;
    const QVariantList values =
        value.canConvert<QJSValue>() ? value.value<QJSValue>().toVariant().toList() : value.toList();
    for (const QVariant &v : values)
        if (auto *object = v.value<QObject *>())
            list << object;
    return list;
}

// The name a screen reader is told for `it`: its Accessible.name, else (for a control) its text. Qt
// gives a control its text as its name itself, but only once a screen reader has made accessibility
// active, which the offscreen platform never does.
QString accessibleName(QQuickItem *it)
{
    if (QAccessible::isActive()) {
        QAccessibleInterface *accessible = QAccessible::queryAccessibleInterface(it);
        return accessible ? accessible->text(QAccessible::Name) : QString();
    }
    for (QObject *child : it->children())
        if (child->inherits("QQuickAccessibleAttached") && !child->property("name").toString().isEmpty())
            return child->property("name").toString();
    return it->property("text").toString();
}

QString describe(const QObject *it)
{
    const QString text = it->property("text").toString();
    return it->objectName() + QLatin1Char('"') + text + QLatin1Char('"');
}

} // namespace

class TestToolbarWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    // A finger's tap on the middle of `it`.
    void tap(QQuickItem *it)
    {
        scrollTo(it);
        const QPoint at = kontur::test::centerOf(it);
        QTest::touchEvent(m_window, m_touch).press(0, at);
        QTest::touchEvent(m_window, m_touch).release(0, at);
    }
    // A long menu scrolls, as a finger would, until its item `it` is in view (its list lays out
    // only the items in view).
    static void scrollTo(QQuickItem *it)
    {
        QObject *menu = it->property("menu").value<QObject *>();
        if (!menu)
            return;
        auto *list = menu->property("contentItem").value<QQuickItem *>();
        const int index = static_cast<int>(menuItems(menu).indexOf(it));
        if (list && index >= 0)
            QMetaObject::invokeMethod(list, "positionViewAtIndex", Q_ARG(int, index), Q_ARG(int, 1 /* Center */));
    }
    // The buttons of the bar that are shown, with the action each one triggers.
    QList<QQuickItem *> barButtons() const
    {
        QList<QQuickItem *> buttons;
        std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
            if (!it->isVisible())
                return;
            if (it->inherits("QQuickAbstractButton")) {
                buttons << it;
                return;
            }
            for (QQuickItem *child : it->childItems())
                walk(child);
        };
        walk(m_bar);
        return buttons;
    }
    // Opens `menu` with a tap on `button` and answers its items once it has opened.
    QList<QQuickItem *> openMenu(QQuickItem *button, QObject *menu)
    {
        tap(button);
        if (!QTest::qWaitFor([menu] { return menu->property("opened").toBool(); }))
            return {};
        return menuItems(menu);
    }
    static bool closeMenu(QObject *menu)
    {
        QMetaObject::invokeMethod(menu, "close");
        return QTest::qWaitFor([menu] { return !menu->property("visible").toBool(); });
    }

    QQuickItem *m_bar = nullptr;
    QObject *m_actions = nullptr;
    kontur::Language *m_language = nullptr;

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase() { m_engine.reset(); }
    void everyActionWithinTwoTaps_data();
    void everyActionWithinTwoTaps();
    void longPressShowsTheToolTip();
};

void TestToolbarWindow::initTestCase()
{
    // As with a screen reader: the controls then give their texts as their accessible names.
    QAccessible::setActive(true);
    QVERIFY(start(QSize(1280, 800)));
    m_language = m_engine->findChild<kontur::Language *>();
    m_bar = item(QStringLiteral("toolBar"));
    m_actions = m_window->findChild<QObject *>(QStringLiteral("appActions"));
    QVERIFY(m_language && m_bar && m_actions);
    // The menus open and close at once: their fading is not what this test looks at, and 25 window
    // states × 6 menus of it would take most of its time.
    int menus = 0;
    for (QObject *menu : m_window->findChildren<QObject *>()) {
        if (menu->inherits("QQuickMenu")) {
            for (const char *transition : {"enter", "exit"}) {
                const QMetaProperty property =
                    menu->metaObject()->property(menu->metaObject()->indexOfProperty(transition));
                QVERIFY(property.write(menu, QVariant(property.metaType()))); // a null transition
            }
            ++menus;
        }
    }
    QVERIFY(menus >= 6);
}

void TestToolbarWindow::everyActionWithinTwoTaps_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QString sizes = qEnvironmentVariable("KONTUR_TOOLBAR_SIZES");
    if (sizes.isEmpty())
        sizes = QStringLiteral("360x640,800x1280,1280x800,1024x768,1920x1080");
    for (const QString &size : sizes.split(QLatin1Char(','))) {
        const QStringList wh = size.split(QLatin1Char('x'));
        for (const char *language : {"en", "lv", "sk", "bg", "ru"})
            QTest::addRow("%s-%s", qPrintable(size), language)
                << QSize(wh.value(0).toInt(), wh.value(1).toInt()) << QString::fromLatin1(language);
    }
}

void TestToolbarWindow::everyActionWithinTwoTaps()
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    // The sizes are a screen's pixels; the window is sized in device-independent ones.
    const double scale = m_window->devicePixelRatio();
    const QSize logical(qRound(size.width() / scale), qRound(size.height() / scale));
    QVERIFY(m_language->setCurrent(language));
    for (QObject *menu : m_window->findChildren<QObject *>())
        if (menu->inherits("QQuickMenu") && menu->property("visible").toBool())
            QVERIFY(closeMenu(menu));
    m_window->resize(logical);
    QTRY_COMPARE(m_window->size(), logical);
    QTRY_COMPARE(m_bar->width(), double(logical.width()));
    QVERIFY(kontur::test::settled(m_window)); // the bar arranges itself on the next polish
    const QString shot =
        QStringLiteral("toolbar-%1x%2@%3-%4").arg(size.width()).arg(size.height()).arg(scale).arg(language);
    screenshot(shot + QStringLiteral(".png"));

    // The bar: inside the window, nothing over anything else, every button a finger's size.
    const QList<QQuickItem *> buttons = barButtons();
    QVERIFY(buttons.size() >= 4); // undo, redo, the tool and the panel toggle at least
    QList<QQuickItem *> controls = buttons;
    if (QQuickItem *readout = item(QStringLiteral("zoomReadout")); readout && readout->isVisible())
        controls << readout;
    for (qsizetype i = 0; i < controls.size(); ++i) {
        const QRectF r = controls[i]->mapRectToScene(controls[i]->boundingRect());
        QVERIFY2(r.left() >= -0.5 && r.right() <= logical.width() + 0.5 && r.top() >= -0.5 &&
                     r.bottom() <= m_bar->height() + 0.5,
                 qPrintable(describe(controls[i]) + QStringLiteral(" is cut off: %1,%2 %3×%4 in %5×%6")
                                                        .arg(r.x())
                                                        .arg(r.y())
                                                        .arg(r.width())
                                                        .arg(r.height())
                                                        .arg(logical.width())
                                                        .arg(m_bar->height())));
        if (controls[i]->inherits("QQuickAbstractButton"))
            QVERIFY2(r.width() >= kTouchMinimum && r.height() >= kTouchMinimum,
                     qPrintable(describe(controls[i]) + QStringLiteral(" %1×%2").arg(r.width()).arg(r.height())));
        for (qsizetype j = i + 1; j < controls.size(); ++j) {
            const QRectF other = controls[j]->mapRectToScene(controls[j]->boundingRect());
            QVERIFY2(r.intersected(other).width() < 0.5,
                     qPrintable(describe(controls[i]) + QStringLiteral(" overlaps ") + describe(controls[j])));
        }
    }
    // Undo, redo, the tool in use and the panel toggle never overflow.
    for (const char *pinned : {"undoButton", "redoButton", "selectButton", "panelButton"})
        QVERIFY2(item(QString::fromLatin1(pinned))->isVisible(), pinned);

    // Where each action is: one tap (a button of the bar), or two (an item of a menu a button opens).
    QHash<QObject *, QQuickItem *> oneTap;
    QHash<QObject *, QPair<QQuickItem *, QQuickItem *>> twoTaps; // the button, then the item
    QSet<QObject *> menus;
    for (QQuickItem *button : buttons) {
        if (QObject *action = button->property("action").value<QObject *>())
            oneTap.insert(action, button);
        QObject *menu = button->property("menu").value<QObject *>();
        if (!menu)
            continue;
        menus << menu;
        const QList<QQuickItem *> items = openMenu(button, menu);
        QVERIFY2(!items.isEmpty(), qPrintable(describe(button) + QStringLiteral(": its menu did not open")));
        const QRectF box = menu->property("contentItem")
                               .value<QQuickItem *>()
                               ->mapRectToScene(QRectF(0, 0, menu->property("width").toDouble(), 1));
        QVERIFY2(box.left() >= -0.5 && box.right() <= logical.width() + 0.5,
                 qPrintable(describe(button) + QStringLiteral(": its menu is wider than the window")));
        for (QQuickItem *it : items) {
            if (!it->isVisible() || !it->inherits("QQuickMenuItem"))
                continue;
            QVERIFY2(it->height() >= kTouchMinimum && it->width() >= kTouchMinimum,
                     qPrintable(describe(it) + QStringLiteral(" is %1 px tall").arg(it->height())));
            if (QObject *action = it->property("action").value<QObject *>())
                twoTaps.insert(action, {button, it});
        }
        if (button->objectName() == QLatin1String("overflowButton"))
            screenshot(shot + QStringLiteral("-overflow.png"));
        if (button->objectName() == QLatin1String("newCurveMenuButton"))
            screenshot(shot + QStringLiteral("-newcurve.png")); // the kinds' names and icons
        QVERIFY(closeMenu(menu));
    }
    const QList<QObject *> all = objects(m_actions->property("all"));
    QVERIFY(all.size() >= 50);
    for (QObject *action : all) {
        // A menu's entries are in the registry themselves; the menu only opens (on the bar, or as
        // a section of the overflow menu).
        if (!action->property("relevant").toBool() || !action->property("entries").isNull())
            continue;
        QVERIFY2(oneTap.contains(action) || twoTaps.contains(action),
                 qPrintable(describe(action) + QStringLiteral(" cannot be reached in two taps")));
        QVERIFY2(!action->property("text").toString().isEmpty(), qPrintable(action->objectName()));
        QVERIFY2(!action->property("iconName").toString().isEmpty(), qPrintable(action->objectName()));
    }

    // Two commands taken the way a user finds them: the grid (a button, or in the overflow menu),
    // and the de Casteljau construction (in the Teaching menu, or in the overflow menu's section).
    QObject *grid = nullptr;
    QObject *deCasteljau = nullptr;
    for (QObject *action : all) {
        if (action->objectName() == QLatin1String("gridAction"))
            grid = action;
        if (action->objectName() == QLatin1String("teachingDeCasteljau"))
            deCasteljau = action;
    }
    QVERIFY(grid && deCasteljau);
    const bool showGrid = m_canvas->property("showGrid").toBool();
    if (oneTap.contains(grid)) {
        tap(oneTap.value(grid));
    } else {
        const auto [button, entry] = twoTaps.value(grid);
        QObject *menu = button->property("menu").value<QObject *>();
        QVERIFY(!openMenu(button, menu).isEmpty());
        tap(entry);
        QTRY_VERIFY(!menu->property("visible").toBool());
    }
    QTRY_COMPARE(m_canvas->property("showGrid").toBool(), !showGrid);
    m_canvas->setProperty("showGrid", showGrid);

    auto *teaching = m_window->findChild<TeachingController *>(QStringLiteral("teaching"));
    QVERIFY(teaching);
    QCOMPARE(teaching->property("view").toInt(), 0);
    const auto [button, entry] = twoTaps.value(deCasteljau);
    QObject *menu = button->property("menu").value<QObject *>();
    QVERIFY(!openMenu(button, menu).isEmpty());
    tap(entry);
    QTRY_VERIFY(!menu->property("visible").toBool());
    QTRY_COMPARE(teaching->property("view").toInt(), static_cast<int>(TeachingController::View::DeCasteljau));
    teaching->setProperty("view", 0);

    // Every button and menu item of the window has a name for a screen reader.
    QList<QQuickItem *> named;
    std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
        if (it->inherits("QQuickAbstractButton"))
            named << it;
        for (QQuickItem *child : it->childItems())
            walk(child);
    };
    walk(m_window->contentItem());
    // The popups' layer too: the side panel's drawer lives there.
    if (auto *overlay = m_window->property("overlay").value<QQuickItem *>())
        walk(overlay);
    for (QObject *menu : std::as_const(menus))
        for (QQuickItem *it : menuItems(menu))
            walk(it);
    for (QQuickItem *it : std::as_const(named))
        QVERIFY2(!accessibleName(it).isEmpty(), qPrintable(describe(it) + QStringLiteral(" has no accessible name")));
}

// A long press on a bar button shows its tool tip (a finger has no hover) and does not run the
// action; a tap does.
void TestToolbarWindow::longPressShowsTheToolTip()
{
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    // Whatever the tests before left open is closed, and the bar laid out for the window's width.
    for (QObject *menu : m_window->findChildren<QObject *>())
        if (menu->inherits("QQuickMenu") && menu->property("visible").toBool())
            QVERIFY(closeMenu(menu));
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
    QTRY_COMPARE(m_bar->width(), 1280.0);
    QQuickItem *grid = item(QStringLiteral("gridButton"));
    QTRY_VERIFY(grid && grid->isVisible());
    // Time itself: this press must not be the second tap of a double tap with one before it.
    kontur::test::gestureTime(QGuiApplication::styleHints()->mouseDoubleClickInterval() + 20);
    const bool shown = m_canvas->property("showGrid").toBool();
    const QPoint at = kontur::test::centerOf(grid);
    QTest::touchEvent(m_window, m_touch).press(0, at);
    QTRY_VERIFY(grid->property("held").toBool()); // the finger rests until the press and hold answers
    // The attached tool tips share one ToolTip, which the engine owns.
    QObject *tip = nullptr;
    const auto findTip = [&] {
        tip = nullptr;
        QList<QObject *> all = m_window->findChildren<QObject *>();
        all += m_engine->findChildren<QObject *>();
        for (QObject *o : all)
            if (o->inherits("QQuickToolTip") && o->property("visible").toBool())
                tip = o;
        return tip != nullptr;
    };
    QTRY_VERIFY(findTip());
    QCOMPARE(tip->property("text").toString(), QStringLiteral("Show or hide the grid and the axes (G)"));
    QTest::touchEvent(m_window, m_touch).release(0, at);
    QVERIFY(kontur::test::settled(m_window)); // a frame after the release: a run would show by now
    QCOMPARE(m_canvas->property("showGrid").toBool(), shown); // the long press ran nothing
    // Time itself: the tap below must not make a double tap with the release above.
    kontur::test::gestureTime(QGuiApplication::styleHints()->mouseDoubleClickInterval() + 20);
    tap(grid);
    QTRY_COMPARE(m_canvas->property("showGrid").toBool(), !shown);
    tap(grid);
    QTRY_COMPARE(m_canvas->property("showGrid").toBool(), shown);
}

QTEST_MAIN(TestToolbarWindow)
#include "tst_toolbar_window.moc"
