// Helpers shared by the window tests: items by objectName, and where to touch them.
#pragma once

#include "../ownfolders.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "models/controllers/backgroundcontroller.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/recovery.h"

#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QList>
#include <QMouseEvent>
#include <QPoint>
#include <QPointingDevice>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSignalSpy>
#include <QSize>
#include <QString>
#include <QTemporaryDir>
#include <QTest>
#include <QtQuickTest/quicktest.h>

#include <algorithm>
#include <memory>
#include <utility>

namespace kontur::test {

// The main window as a user starts it, in English at `size`, shown and exposed, over data and
// settings folders of the process's own (ownfolders.h): no recovery copy or setting from another run
// reaches it, and no autosave is written while the tests run. nullptr when it could not be loaded
// or shown, or the folders are not the process's own.
inline QQuickWindow *startMainWindow(QQmlApplicationEngine &engine, QSize size)
{
    if (!inOwnFolders(Recovery::recoveryFolder()) || !Recovery::recoveryFiles().isEmpty())
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
// the canvas's editor and (when asked) the document's files. False when any of them is missing.
inline bool startMainParts(std::unique_ptr<QQmlApplicationEngine> &engine, QSize size, QQuickWindow *&window,
                           CurveCanvas *&canvas, EditController *&editor, DocumentFiles **files = nullptr)
{
    engine = std::make_unique<QQmlApplicationEngine>();
    window = startActiveMainWindow(*engine, size);
    canvas = window ? window->findChild<CurveCanvas *>(QStringLiteral("canvas")) : nullptr;
    editor = canvas ? canvas->controller() : nullptr;
    if (files)
        *files = window ? window->findChild<DocumentFiles *>(QStringLiteral("files")) : nullptr;
    return editor && (!files || *files);
}

// Time as part of a gesture: how long a finger rests (a long press) or how fast it moves. The one
// place where the window tests let the clock run for its own sake; nothing waits here for a state.
inline void gestureTime(int ms)
{
    if (ms > 0)
        QTest::qWait(ms); // time itself is what is tested: the gesture's duration or speed
}

// What a window test drives, declared once: a test class derives from it after QObject and starts
// the window with start(). The engine and its main window, the canvas, the canvas's editor, the
// document's files and the exporter, a touch screen and a folder of its own for files.
struct MainWindowTest
{
    std::unique_ptr<QQmlApplicationEngine> m_engine;
    QQuickWindow *m_window = nullptr;
    CurveCanvas *m_canvas = nullptr;
    EditController *m_editor = nullptr;
    DocumentFiles *m_files = nullptr;
    Exporter *m_exporter = nullptr;
    QPointingDevice *m_touch = nullptr;
    QTemporaryDir m_dir;

    // The active main window at `size` with its parts; false when any is missing.
    bool start(QSize size)
    {
        m_touch = QTest::createTouchDevice();
        if (!startMainParts(m_engine, size, m_window, m_canvas, m_editor, &m_files))
            return false;
        m_exporter = m_window->findChild<Exporter *>(QStringLiteral("exporter"));
        return m_exporter && m_dir.isValid();
    }
    void screenshot(const QString &name) const;

    // Each touch gets an id of its own, as a touch screen gives them (QTest would reuse 0, which a
    // handler of an earlier pinch may still hold in Qt 6.4).
    int m_nextTouchId = 100;
    // A finger (or with `mouse`, the left button) dragged from `from` by `by` in `steps` moves,
    // `stepMs` apart (0: as fast as the events go; the canvas takes no speed from a drag).
    void drag(QPoint from, QPoint by, bool mouse, int steps = 10, int stepMs = 0)
    {
        const int id = m_nextTouchId++;
        if (mouse)
            QTest::mousePress(m_window, Qt::LeftButton, {}, from);
        else
            QTest::touchEvent(m_window, m_touch).press(id, from);
        for (int step = 1; step <= steps; ++step) {
            gestureTime(stepMs);
            const QPoint at = from + by * step / steps;
            if (mouse) {
                QMouseEvent move(QEvent::MouseMove, at, m_window->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                                 Qt::NoModifier);
                QGuiApplication::sendEvent(m_window, &move);
            } else {
                QTest::touchEvent(m_window, m_touch).move(id, at);
            }
        }
        gestureTime(stepMs);
        if (mouse)
            QTest::mouseRelease(m_window, Qt::LeftButton, {}, from + by);
        else
            QTest::touchEvent(m_window, m_touch).release(id, from + by);
    }
    // A finger's tap, held `holdMs` (0: released at once; longer than Qt's long press is a press and hold).
    void tap(QPoint at, int holdMs = 0)
    {
        const int id = m_nextTouchId++;
        QTest::touchEvent(m_window, m_touch).press(id, at);
        gestureTime(holdMs);
        QTest::touchEvent(m_window, m_touch).release(id, at);
    }
    // A cubic Bézier curve from typed coordinates, as the panel's table makes one.
    bool addBezier(const QList<QPointF> &points)
    {
        QVariantList list;
        for (const QPointF &p : points)
            list << QVariant(QVariantList{p.x(), p.y()});
        return m_editor->placement()->createFromCoordinates(static_cast<int>(geo::CurveKind::Bezier), list);
    }
};

// A picture of the window for a person to look at, when KONTUR_SCREENSHOT_DIR names a folder.
inline void screenshot(QQuickWindow *window, const QString &name)
{
    if (!qEnvironmentVariableIsEmpty("KONTUR_SCREENSHOT_DIR"))
        window->grabWindow().save(qEnvironmentVariable("KONTUR_SCREENSHOT_DIR") + QLatin1Char('/') + name);
}

inline void MainWindowTest::screenshot(const QString &name) const
{
    kontur::test::screenshot(m_window, name);
}

// The darkest grey level (0 black .. 255 white) of a grabbed window picture within `radius` pixels of
// a window position (scaled by the picture's device pixel ratio).
inline int darkestNear(const QImage &image, QPointF windowPos, int radius = 1)
{
    const QPoint c = (windowPos * image.devicePixelRatio()).toPoint();
    int best = 255;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p = c + QPoint(dx, dy);
            if (image.rect().contains(p))
                best = std::min(best, qGray(image.pixel(p)));
        }
    return best;
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

// Whether a click at `at` lands in the window. Qt Test refuses a mouse event at x == width or
// y == height ("occurs outside target window"), which QRectF::contains would let through: a button
// flush with the right edge has its middle at x == width once rounded.
inline bool insideWindow(const QQuickWindow *window, QPoint at)
{
    return QRect(QPoint(0, 0), window->size()).contains(at);
}

// A click at the middle of `it` after it is scrolled into view (ensureVisible): where it lies depends
// on the fonts' metrics (a panel is taller with Roboto than with DejaVu), so a test never clicks
// where it merely was on the machine it was written on. False when it is still not inside the window.
inline bool clickInView(QQuickWindow *window, QQuickItem *it)
{
    ensureVisible(it);
    const QRectF inScene = it->mapRectToScene(it->boundingRect());
    if (!insideWindow(window, inScene.center().toPoint()))
        return false;
    QTest::mouseClick(window, Qt::LeftButton, {}, inScene.center().toPoint());
    return true;
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

// Types `text` into the coordinates table's cell `field` ("x1", "y0", …) from the keyboard, as a user
// does: the row brought into view (the table makes only the rows it shows), focus, select all, the
// keys, and Enter when asked. An empty text clears the cell.
// The window has caught up with the last change: a frame drawn after it, and no item waiting for
// its polish (layouts, flows); what a user sees once the window is still. False after 5 s.
inline bool settled(QQuickWindow *window)
{
    QSignalSpy frame(window, &QQuickWindow::frameSwapped);
    window->update();
    return frame.wait(5000) && QQuickTest::qWaitForPolish(window, 5000);
}

// `it` brought into view, shown, enabled and standing still there (not while it slides in, as a bar
// does when its tool starts: the same place on two looks in a row), its middle inside the window.
inline bool standsStill(QQuickWindow *window, QQuickItem *it)
{
    if (!it)
        return false;
    ensureVisible(it);
    if (!QTest::qWaitFor([it] { return it->isVisible() && it->isEnabled() && it->width() > 0; }))
        return false;
    QPoint last(-1, -1);
    if (!QTest::qWaitFor([&] {
            const QPoint now = centerOf(it);
            return std::exchange(last, now) == now;
        }))
        return false;
    return insideWindow(window, centerOf(it));
}

inline void typeIntoTable(QQuickWindow *window, const QString &field, const QString &text, bool enter = false)
{
    QQuickItem *list = findVisibleItem(window, QStringLiteral("pointList"));
    QVERIFY(list);
    QVERIFY(QMetaObject::invokeMethod(list, "positionViewAtIndex", Q_ARG(int, field.mid(1).toInt()),
                                      Q_ARG(int, 4 /* ListView.Contain */)));
    QQuickItem *input = nullptr;
    QTRY_VERIFY2((input = findVisibleItem(window, field)) && input->isVisible(), qPrintable(field));
    ensureVisible(input);
    input->forceActiveFocus();
    QTRY_VERIFY(input->hasActiveFocus());
    QTest::keyClick(window, Qt::Key_A, Qt::ControlModifier);
    if (text.isEmpty()) // clearing the field is an edit too
        QTest::keyClick(window, Qt::Key_Backspace);
    for (const QChar c : text) // QTest::keyClicks takes widgets only
        QTest::keyClick(window, c.toLatin1());
    if (enter)
        QTest::keyClick(window, Qt::Key_Return);
}

// Kontur's file dialog (qml/FileBrowserDialog.qml): a Dialog of the QML type FileBrowserDialog.
inline bool isFileDialog(const QObject *object)
{
    return QByteArray(object->metaObject()->className()).startsWith("FileBrowserDialog");
}

// The file dialog titled `title` (English), shown or not; nullptr when there is none.
inline QObject *fileDialogTitled(const QQuickWindow *window, const QString &title)
{
    for (QObject *object : window->findChildren<QObject *>())
        if (isFileDialog(object) && object->property("title").toString() == title)
            return object;
    return nullptr;
}

// The item called `name` in the file dialog that is shown (its content exists only while it shows).
inline QQuickItem *fileDialogItem(const QQuickWindow *window, const QString &name)
{
    QList<QQuickItem *> found;
    collectItems(window->contentItem(), name, found);
    for (QQuickItem *it : found)
        if (it->isVisible())
            return it;
    return nullptr;
}

// The row of the file or folder `fileName` in the shown file dialog's list, scrolled into view first
// (the list makes only the rows it shows, and where a row lies depends on the fonts); nullptr when
// the folder has none.
inline QQuickItem *fileDialogRow(const QQuickWindow *window, const QString &fileName)
{
    QQuickItem *list = fileDialogItem(window, QStringLiteral("fileDialogList"));
    if (!list)
        return nullptr;
    auto *model = list->property("model").value<QObject *>();
    if (!model || !QTest::qWaitFor([model] { return model->property("status").toInt() == 1; })) // Ready
        return nullptr;
    QString folder = model->property("folder").toUrl().toLocalFile();
    const QUrl url = QUrl::fromLocalFile(folder + QLatin1Char('/') + fileName);
    int index = -1;
    if (!QTest::qWaitFor([&] {
            QMetaObject::invokeMethod(model, "indexOf", Q_RETURN_ARG(int, index), Q_ARG(QUrl, url));
            return index >= 0;
        }))
        return nullptr;
    QMetaObject::invokeMethod(list, "positionViewAtIndex", Q_ARG(int, index), Q_ARG(int, 4 /* ListView.Contain */));
    QQuickItem *row = nullptr;
    return QTest::qWaitFor([&] { return (row = fileDialogItem(window, QStringLiteral("fileDialogRow_") + fileName)); })
               ? row
               : nullptr;
}

// A plain picture of `size` in `colour`, written to `file` and loaded as the background, as the file
// dialog's choice would be; the grid is hidden so that the picture shows as it is.
inline bool loadPlainPicture(CurveCanvas *canvas, const QString &file, QSize size, const QColor &colour)
{
    QImage picture(size, QImage::Format_RGB32);
    picture.fill(colour);
    if (!picture.save(file) || !canvas->controller()->background()->load(QUrl::fromLocalFile(file)))
        return false;
    canvas->setProperty("showGrid", false);
    return true;
}

} // namespace kontur::test
