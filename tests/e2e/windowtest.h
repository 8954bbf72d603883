// Helpers shared by the window tests: items by objectName, and where to touch them.
#pragma once

#include "../ownfolders.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "models/editcontroller.h"
#include "models/filecontroller.h"

#include <QFile>
#include <QList>
#include <QPoint>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSize>
#include <QString>
#include <QTest>

#include <algorithm>
#include <memory>

namespace kontur::test {

// The main window as a user starts it, in English at `size`, shown and exposed, over data and
// settings folders of the process's own (ownfolders.h): no recovery copy or setting from another run
// reaches it, and no autosave is written while the tests run. nullptr when it could not be loaded
// or shown, or the folders are not the process's own.
inline QQuickWindow *startMainWindow(QQmlApplicationEngine &engine, QSize size)
{
    if (!inOwnFolders(FileController::recoveryPath()) || QFile::exists(FileController::recoveryPath()))
        return nullptr;
    qputenv("KONTUR_AUTOSAVE_SECONDS", "3600");
    QQuickWindow *window = loadMainWindow(engine, {QStringLiteral("en"), QString(), size});
    if (!window)
        return nullptr;
    window->resize(size);
    window->show();
    return QTest::qWaitForWindowExposed(window) ? window : nullptr;
}

// startMainWindow, and the window made active: shortcuts need the keyboard focus, and under Xvfb
// there is no window manager to give it. nullptr when it could not be started or activated.
inline QQuickWindow *startActiveMainWindow(QQmlApplicationEngine &engine, QSize size)
{
    QQuickWindow *window = startMainWindow(engine, size);
    if (!window)
        return nullptr;
    window->requestActivate();
    return QTest::qWaitForWindowActive(window) ? window : nullptr;
}

// A new engine with the active main window at `size`, and the parts the tests drive: its canvas,
// the canvas's editor and (when asked) the file controller. False when any of them is missing.
inline bool startMainParts(std::unique_ptr<QQmlApplicationEngine> &engine, QSize size, QQuickWindow *&window,
                           CurveCanvas *&canvas, EditController *&editor, FileController **files = nullptr)
{
    engine = std::make_unique<QQmlApplicationEngine>();
    window = startActiveMainWindow(*engine, size);
    canvas = window ? window->findChild<CurveCanvas *>(QStringLiteral("canvas")) : nullptr;
    editor = canvas ? canvas->controller() : nullptr;
    if (files)
        *files = window ? window->findChild<FileController *>(QStringLiteral("files")) : nullptr;
    return editor && (!files || *files);
}

// A picture of the window for a person to look at, when KONTUR_SCREENSHOT_DIR names a folder.
inline void screenshot(QQuickWindow *window, const QString &name)
{
    if (!qEnvironmentVariableIsEmpty("KONTUR_SCREENSHOT_DIR"))
        window->grabWindow().save(qEnvironmentVariable("KONTUR_SCREENSHOT_DIR") + QLatin1Char('/') + name);
}

// Scrolls the panel (as a finger would) until `it` is inside every scrolling area around it.
inline void ensureVisible(QQuickItem *it)
{
    for (QQuickItem *p = it->parentItem(); p; p = p->parentItem()) {
        if (!p->inherits("QQuickFlickable"))
            continue;
        const QRectF r = p->mapRectFromItem(it, it->boundingRect());
        const double contentY = p->property("contentY").toDouble();
        if (r.top() < 0 || r.bottom() > p->height())
            p->setProperty("contentY", std::max(0.0, contentY + r.center().y() - p->height() / 2));
    }
}

// Every item called `name` below `root` in the visual tree, appended to `found`.
inline void collectItems(QQuickItem *root, const QString &name, QList<QQuickItem *> &found)
{
    if (root->objectName() == name)
        found << root;
    for (QQuickItem *child : root->childItems())
        collectItems(child, name, found);
}

// The item called `name`: a QML child of the window (popups, menus and drawers are), else one in the
// window's visual tree.
inline QQuickItem *findItem(const QQuickWindow *window, const QString &name)
{
    if (auto *found = window->findChild<QQuickItem *>(name))
        return found;
    QList<QQuickItem *> found;
    collectItems(window->contentItem(), name, found);
    return found.value(0);
}

// As findItem, but where the name stands more than once, the one that is shown. (The side panel, once
// both beside the canvas and in a drawer, is one item now, in the drawer or in the bottom sheet: there
// it is the same as findItem.)
inline QQuickItem *findVisibleItem(const QQuickWindow *window, const QString &name)
{
    QList<QQuickItem *> found = window->findChildren<QQuickItem *>(name);
    collectItems(window->contentItem(), name, found);
    for (QQuickItem *it : found)
        if (it->isVisible())
            return it;
    return found.value(0);
}

// The middle of an item, in scene (window) coordinates.
inline QPoint centerOf(const QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
}

// Clicks `menuItem` once its menu has opened (the enter transition moves and fades the items, and a
// click during it may miss) and waits until the menu has closed again, so that nothing of it lies
// over the window any more. False when the item is in no menu or either wait timed out.
inline bool clickMenuItem(QQuickWindow *window, QQuickItem *menuItem)
{
    QObject *menu = menuItem->property("menu").value<QObject *>();
    if (!menu || !QTest::qWaitFor([menu] { return menu->property("opened").toBool(); }))
        return false;
    QTest::mouseClick(window, Qt::LeftButton, {}, centerOf(menuItem));
    return QTest::qWaitFor([menu] { return !menu->property("visible").toBool(); });
}

} // namespace kontur::test
