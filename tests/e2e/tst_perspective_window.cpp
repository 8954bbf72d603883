// The perspective calibration (issue #22) in the real window: a photo of an A4 sheet with a centimetre
// grid, taken at an angle, is calibrated from the Trace menu's key (Shift+K) by four touch taps in a
// scrambled order and the Apply button; the picture is then drawn rectified (checked in the pixels, on
// both render paths); one undo step; a corner refined by a
// mouse drag and by a finger drag, each one undo step, with the magnifier shown during the drag.
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/trace/tracecontroller.h"

#include <QImage>
#include <QPainter>
#include <QPolygonF>
#include <QQuickItem>
#include <QQuickWindow>
#include <QScreen>
#include <QtTest>

#include <algorithm>
#include <array>

using kontur::TraceController;
using kontur::geo::Point;

namespace {

constexpr double kPxPerMm = 3.0;

// An A4 sheet (210 × 297 mm): black centimetre lines, grey millimetre lines.
QImage sheet()
{
    QImage image(int(210 * kPxPerMm) + 1, int(297 * kPxPerMm) + 1, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    for (int i = 0; i <= 297; ++i) {
        p.setPen(QPen(i % 10 == 0 ? Qt::black : QColor(190, 190, 190), i % 10 == 0 ? 4.0 : 1.0));
        if (i <= 210)
            p.drawLine(QPointF(i * kPxPerMm, 0), QPointF(i * kPxPerMm, image.height()));
        p.drawLine(QPointF(0, i * kPxPerMm), QPointF(image.width(), i * kPxPerMm));
    }
    return image;
}

// The sheet's corners in the photo, top-left first, clockwise.
std::array<QPointF, 4> photoQuad()
{
    return {QPointF(300, 120), QPointF(720, 140), QPointF(860, 1000), QPointF(160, 960)};
}

QImage photo()
{
    const std::array<QPointF, 4> q = photoQuad();
    const QPolygonF from{QList<QPointF>{QPointF(0, 0), QPointF(210 * kPxPerMm, 0),
                                        QPointF(210 * kPxPerMm, 297 * kPxPerMm), QPointF(0, 297 * kPxPerMm)}};
    QTransform t;
    [[maybe_unused]] const bool ok = QTransform::quadToQuad(from, QPolygonF(QList<QPointF>(q.begin(), q.end())), t);
    QImage image(1000, 1100, QImage::Format_RGB32);
    image.fill(QColor(120, 90, 60));
    QPainter p(&image);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.setTransform(t);
    p.drawImage(QPointF(0, 0), sheet());
    return image;
}

} // namespace

class TestPerspectiveWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QPoint scene(QPointF canvasPoint) const { return m_canvas->mapToScene(canvasPoint).toPoint(); }
    QPoint sceneOf(const Point &world) const { return scene(m_canvas->toScreen(QPointF(world.x(), world.y()))); }
    bool barLaidOut() const
    {
        const QQuickItem *bar = item(QStringLiteral("traceBar"));
        if (!bar || !bar->isVisible() || bar->height() <= 0)
            return false;
        const QRectF canvas = m_canvas->mapRectToScene(m_canvas->boundingRect());
        return canvas.bottom() <= bar->mapRectToScene(bar->boundingRect()).top() + 0.5;
    }
    // The handle `index`'s corner dragged from where it is to `to` (world) by the mouse or a finger;
    // the magnifier is looked at halfway.
    void dragCorner(int index, const Point &to, bool touch, const QString &shotName);

    TraceController *m_trace = nullptr;

private Q_SLOTS:
    void initTestCase();
    void calibrateByTouchThenRefine();
    void cleanupTestCase() { m_engine.reset(); }
};

void TestPerspectiveWindow::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
    m_trace = m_window->findChild<TraceController *>(QStringLiteral("trace"));
    QVERIFY(m_trace);
}

void TestPerspectiveWindow::dragCorner(int index, const Point &to, bool touch, const QString &shotName)
{
    const Point from = m_trace->perspective()->handles().at(std::size_t(index));
    const int steps = 20;
    if (touch)
        QTest::touchEvent(m_window, m_touch).press(0, sceneOf(from));
    else
        QTest::mousePress(m_window, Qt::LeftButton, {}, sceneOf(from));
    for (int i = 1; i <= steps; ++i) {
        const QPoint at = sceneOf(from + (to - from) * (double(i) / steps));
        if (touch)
            QTest::touchEvent(m_window, m_touch).move(0, at);
        else
            QTest::mouseMove(m_window, at);
        if (i == steps / 2) {
            QTRY_VERIFY(m_trace->perspective()->cornerDragging());
            QQuickItem *painter = item(QStringLiteral("tracePainter"));
            QVERIFY(painter);
            const QPointF loupe = painter->property("loupeCentre").toPointF();
            const double radius = painter->property("loupeRadius").toDouble();
            // The magnifier stands clear of the finger, inside the canvas.
            const QPointF finger = m_canvas->toScreen(m_trace->perspective()->cornerDragPoint());
            QVERIFY2(QLineF(loupe, finger).length() > radius,
                     qPrintable(QStringLiteral("%1,%2").arg(loupe.x()).arg(loupe.y())));
            QVERIFY(kontur::test::settled(m_window));
            const QImage shot = m_window->grabWindow();
            // Its rim is drawn: dark grey pixels on the circle.
            const QPoint rim = scene(loupe + QPointF(0, -radius));
            const QColor c =
                shot.pixelColor(int(rim.x() * shot.devicePixelRatio()), int(rim.y() * shot.devicePixelRatio()));
            QVERIFY2(c.lightness() < 130, qPrintable(c.name()));
            screenshot(shotName);
        }
    }
    const QPoint end = sceneOf(to);
    if (touch)
        QTest::touchEvent(m_window, m_touch).release(0, end);
    else
        QTest::mouseRelease(m_window, Qt::LeftButton, {}, end);
    QTRY_VERIFY(!m_trace->perspective()->cornerDragging());
}

void TestPerspectiveWindow::calibrateByTouchThenRefine()
{
    const QString file = m_dir.filePath(QStringLiteral("sheet-photo.png"));
    QVERIFY(photo().save(file));
    QVERIFY(m_editor->background()->load(QUrl::fromLocalFile(file)));
    m_canvas->fitToView();
    QTest::keyClick(m_window, Qt::Key_K, Qt::ShiftModifier);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Perspective);
    QTRY_VERIFY(barLaidOut());
    m_canvas->fitToView();
    QVERIFY(kontur::test::settled(m_window));

    // The four corners tapped by a finger in a scrambled order; the third one 8 px off, to refine.
    const kontur::Background bg = m_editor->document()->background();
    const std::array<QPointF, 4> q = photoQuad();
    for (int i : {2, 0, 3, 1}) {
        const QPointF offset = i == 1 ? QPointF(8, 8) : QPointF();
        const QPoint at = sceneOf(bg.toWorld(q[i] + offset));
        QTest::touchEvent(m_window, m_touch).press(0, at);
        QTest::touchEvent(m_window, m_touch).release(0, at);
    }
    QTRY_COMPARE(m_trace->perspective()->marks(), 4);
    QVERIFY(!m_trace->perspective()->landscape());
    screenshot(QStringLiteral("perspective-marked.png"));
    const int steps = m_editor->undoStack()->index();
    QQuickItem *apply = item(QStringLiteral("traceApplyPerspective"));
    QVERIFY(apply && apply->isVisible() && apply->isEnabled());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(apply)); // A4, as marked
    QTRY_VERIFY(m_editor->document()->background().perspective);
    QCOMPARE(m_editor->undoStack()->index(), steps + 1);
    QCOMPARE(m_editor->document()->units(), QStringLiteral("mm"));
    const kontur::Background &after = m_editor->document()->background();
    QCOMPARE(after.rectWidth, 210.0);
    QCOMPARE(after.rectHeight, 297.0);
    // Taps land within a pixel or so of the corners (screen rounding).
    QVERIFY(QLineF(after.corners[0], q[0]).length() <= 3.0);
    QVERIFY(QLineF(after.corners[1], q[1] + QPointF(8, 8)).length() <= 3.0);

    // The finger's mark is refined: dragged with the mouse onto where the real corner shows.
    const Point realCorner = after.toWorld(q[1]);
    dragCorner(1, realCorner, false, QStringLiteral("perspective-loupe-mouse.png"));
    QCOMPARE(m_editor->undoStack()->index(), steps + 2);
    QVERIFY2(QLineF(m_editor->document()->background().corners[1], q[1]).length() <= 3.0,
             qPrintable(QStringLiteral("%1,%2")
                            .arg(m_editor->document()->background().corners[1].x())
                            .arg(m_editor->document()->background().corners[1].y())));
    // And the bottom-left one by a finger, a little, and back in one more step.
    const kontur::Background beforeTouch = m_editor->document()->background();
    const Point corner3 = m_trace->perspective()->handles().at(3);
    dragCorner(3, corner3 + Point(4, 3), true, QStringLiteral("perspective-loupe-touch.png"));
    QCOMPARE(m_editor->undoStack()->index(), steps + 3);
    QVERIFY(!(m_editor->document()->background() == beforeTouch));
    m_editor->undo();
    QVERIFY(m_editor->document()->background() == beforeTouch);

    // Drawn rectified: the sheet fills its rectangle, the centimetre crossings dark, the cells light.
    m_canvas->fitToView();
    QVERIFY(kontur::test::settled(m_window));
    screenshot(QStringLiteral("perspective-rectified.png"));
    if (!qEnvironmentVariableIsEmpty("KONTUR_SCREENSHOT_DIR"))
        m_window->screen()
            ->grabWindow(m_window->winId())
            .save(qEnvironmentVariable("KONTUR_SCREENSHOT_DIR") + QStringLiteral("/perspective-rectified-screen.png"));
    const kontur::Background &now = m_editor->document()->background();
    const Point tl(now.rectOrigin.x(), now.rectOrigin.y());
    {
        const QImage shot = m_window->grabWindow();
        const double dpr = shot.devicePixelRatio();
        int dark = 0, light = 0, crossings = 0;
        for (int i = 1; i < 21; ++i) {
            for (int j = 1; j < 29; j += 3) {
                const QPoint cross = sceneOf(tl + Point(10.0 * i, -10.0 * j));
                const QPoint cell = sceneOf(tl + Point(10.0 * i - 5, -10.0 * j + 5));
                // Halfway along a horizontal and a vertical line: dark too (a shift along either fails).
                const QPoint across = sceneOf(tl + Point(10.0 * i - 5, -10.0 * j));
                const QPoint down = sceneOf(tl + Point(10.0 * i, -10.0 * j + 5));
                ++crossings;
                // The taps were whole screen pixels (about 0.8 mm here): the darkest pixel within one.
                const auto darkestNear = [&](QPoint p) {
                    int least = 255;
                    for (int dx = -1; dx <= 1; ++dx)
                        for (int dy = -1; dy <= 1; ++dy)
                            least = std::min(least,
                                             shot.pixelColor(int(p.x() * dpr) + dx, int(p.y() * dpr) + dy).lightness());
                    return least;
                };
                if (darkestNear(cross) < 110 && darkestNear(across) < 110 && darkestNear(down) < 110)
                    ++dark;
                if (shot.pixelColor(int(cell.x() * dpr), int(cell.y() * dpr)).lightness() > 200)
                    ++light;
            }
        }
        QVERIFY2(dark >= crossings * 9 / 10 && light >= crossings * 9 / 10,
                 qPrintable(QStringLiteral("%1 dark, %2 light of %3").arg(dark).arg(light).arg(crossings)));
    }

    // The whole calibration is one undo step; clearing another.
    m_trace->perspective()->clearPerspective();
    QVERIFY(!m_editor->document()->background().perspective);
    m_editor->undo();
    QVERIFY(m_editor->document()->background().perspective);
    while (m_editor->undoStack()->index() > steps)
        m_editor->undo();
    // Back to the loaded picture's placement, in pixels.
    QVERIFY(!m_editor->document()->background().perspective);
    QCOMPARE(m_editor->document()->units(), QStringLiteral("px"));
}

QTEST_MAIN(TestPerspectiveWindow)
#include "tst_perspective_window.moc"
