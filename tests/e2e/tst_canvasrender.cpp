// The canvas's drawing in the real window, on the software backend and on OpenGL (see
// CMakeLists.txt): strokes keep their width in pixels at any zoom, curves are where the geometry
// says after zooming far in (re-flattened to a quarter pixel), during a pinch (the software layer
// shown transformed) and after it settles, and a drag redraws the dragged curve while the others
// stay. Also the software layer's fast stroke against QPainter's own wide pen.
#include "windowtest.h"

#include "../curveids.h"
#include "app/application.h"
#include "app/curvecanvas.h"
#include "app/displaylist.h"
#include "app/strokenode.h"
#include "geometry/polyline.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"

#include <QGuiApplication>
#include <QPainter>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickItemGrabResult>
#include <QQuickWindow>
#include <QtTest>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <random>

using kontur::CurveCanvas;
using kontur::EditController;

class TestCanvasRender final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QPointF scene(QPointF canvasPos) const { return m_canvas->mapToScene(canvasPos); }
    QPointF sceneOfWorld(const kontur::geo::Point &p) const { return scene(m_canvas->toScreen(QPointF(p.x(), p.y()))); }
    QImage grab()
    {
        m_canvas->update();
        if (!kontur::test::settled(m_window))
            return {};
        return m_window->grabWindow();
    }
    // The view has settled: the layer of curves is drawn for the current view (unscaled and centred
    // on the canvas). During a gesture on a large drawing the cached layer is shown moved and scaled
    // instead, until the canvas's settle timer draws it anew.
    bool layerAtView() const
    {
        const auto *layer = m_canvas->findChild<QQuickItem *>(QStringLiteral("canvasLayer"));
        if (!layer)
            return false;
        const QPointF centre = layer->mapToItem(m_canvas, QPointF(layer->width() / 2, layer->height() / 2));
        return layer->scale() == 1.0 &&
               QLineF(centre, QPointF(m_canvas->width() / 2, m_canvas->height() / 2)).length() < 1e-6;
    }
    // Samples of the curve about every 7 px on screen that lie on the canvas, away from the point
    // markers (drawn over the curve), each have a dark pixel within `radius`.
    void verifyCurveAt(const QImage &image, int curveIndex, int radius, const char *when)
    {
        const kontur::Curve &curve = m_editor->document()->curve(curveIndex);
        const QRectF onCanvas = m_canvas->mapRectToScene(m_canvas->boundingRect()).adjusted(4, 4, -4, -4);
        std::vector<QPointF> markers;
        for (const kontur::geo::Point &p : curve.definingPoints())
            markers.push_back(sceneOfWorld(p));
        int checked = 0;
        for (int s = 0; s < curve.segmentCount(); ++s) {
            const kontur::geo::Bezier segment = curve.segment(s);
            QPointF last(-1e9, -1e9);
            for (int k = 0; k <= 20000; ++k) {
                const QPointF at = sceneOfWorld(segment.eval(k / 20000.0));
                if (!onCanvas.contains(at) || QLineF(at, last).length() < 7.0)
                    continue;
                last = at;
                if (std::any_of(markers.begin(), markers.end(),
                                [&](QPointF m) { return QLineF(m, at).length() < 12.0; }))
                    continue;
                ++checked;
                const int dark = kontur::test::darkestNear(image, at, radius);
                QVERIFY2(dark < 110, qPrintable(QStringLiteral("%1: no curve pixel at segment %2, t=%3 (%4, %5): %6")
                                                    .arg(QLatin1String(when))
                                                    .arg(s)
                                                    .arg(k / 20000.0)
                                                    .arg(at.x())
                                                    .arg(at.y())
                                                    .arg(dark)));
            }
        }
        QVERIFY2(checked >= 8,
                 qPrintable(QStringLiteral("%1: only %2 samples on the canvas").arg(QLatin1String(when)).arg(checked)));
    }
    // Dark pixels (gray < 128) in the column through window x, within ±range of window y.
    static int darkRun(const QImage &image, QPointF windowPos, int range)
    {
        const qreal dpr = image.devicePixelRatio();
        const QPoint c = (windowPos * dpr).toPoint();
        int count = 0;
        for (int dy = -range; dy <= range; ++dy)
            if (image.rect().contains(c + QPoint(0, dy)) && qGray(image.pixel(c + QPoint(0, dy))) < 128)
                ++count;
        return count;
    }
    void newDocument()
    {
        m_editor->commands()->resetAll();
        QCOMPARE(m_editor->document()->curveCount(), 0);
        m_canvas->resetView();
    }
    int addCurve(const QVariantList &rows, kontur::CurveKind kind = kontur::CurveKind::Bezier)
    {
        if (!m_editor->placement()->createFromCoordinates(static_cast<int>(kind), rows))
            return -1;
        return m_editor->document()->curveCount() - 1;
    }

private Q_SLOTS:
    void initTestCase();
    void flattenedWithinTheTolerance();
    void fastStrokeCoversLikeAWidePen();
    void strokeWidthIndependentOfZoom();
    void reflattenedWhenZoomedFarIn();
    void curvesFollowAPinchAndSettle();
    void dragRedrawsTheDraggedCurveOnly();
    void everyCurveDrawnWhateverIsSelected();
    void insertFlattensOneCurve();
    void pngExportDrawsLinesAtItsScale();
    void gridWhereTheViewSays();
    void cleanupTestCase();
};

void TestCanvasRender::initTestCase()
{
    QVERIFY(start(QSize(1100, 720)));
    QTRY_VERIFY(m_canvas->width() > 400 && m_canvas->height() > 400);
    const QByteArray expected = qgetenv("KONTUR_EXPECT_GRAPHICS_API");
    QTRY_VERIFY(!m_canvas->graphicsApi().isEmpty());
    if (!expected.isEmpty())
        QCOMPARE(m_canvas->graphicsApi(), QString::fromLatin1(expected));
    // How the other curves are kept: a texture, a painted picture (OpenGL on the processor) or
    // the software backend's painter.
    const QByteArray layer = qgetenv("KONTUR_EXPECT_LAYER");
    if (!layer.isEmpty())
        QTRY_COMPARE(m_canvas->layerKind(), QString::fromLatin1(layer));
    m_canvas->setProperty("showGrid", false);
}

void TestCanvasRender::flattenedWithinTheTolerance()
{
    // Random curves of degree 2 to 8: every point of the curve lies within the tolerance of the
    // polyline (the canvas flattens to 1/8 px for zooms up to twice that: a quarter pixel), and
    // the polyline's vertices lie on the curve.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> where(-100.0, 100.0);
    std::uniform_int_distribution<int> degrees(2, 8);
    std::uniform_real_distribution<double> tolerances(0.01, 0.5);
    for (int round = 0; round < 100; ++round) {
        std::vector<kontur::geo::Point> control;
        const int degree = degrees(rng);
        for (int i = 0; i <= degree; ++i)
            control.emplace_back(where(rng), where(rng));
        const kontur::geo::Bezier curve(control);
        const double tolerance = tolerances(rng);
        std::vector<kontur::geo::Point> line;
        kontur::flattenWithin(curve, tolerance, line);
        QVERIFY(line.size() >= 2);
        QVERIFY((line.front() - control.front()).norm() < 1e-9);
        QVERIFY((line.back() - control.back()).norm() < 1e-9);
        double worst = 0.0;
        for (int k = 0; k <= 1000; ++k) {
            const kontur::geo::Point p = curve.eval(k / 1000.0);
            worst = std::max(worst, (p - kontur::geo::nearestOnPolyline(line, p, false).point).norm());
        }
        QVERIFY2(worst <= tolerance * (1.0 + 1e-9) + 1e-12,
                 qPrintable(
                     QStringLiteral("round %1, degree %2: %3 > %4").arg(round).arg(degree).arg(worst).arg(tolerance)));
    }
}

void TestCanvasRender::fastStrokeCoversLikeAWidePen()
{
    // Random curves: the ink (summed coverage) of the fast stroke is that of QPainter's 2 px
    // pen within 10 %, and it lies where the pen's does (few fast-stroke pixels far from the pen's).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> where(20.0, 180.0);
    for (int round = 0; round < 20; ++round) {
        // A random cubic flattened to a quarter pixel, as the canvas draws curves.
        std::vector<kontur::geo::Point> control, flat{};
        for (int i = 0; i < 4; ++i)
            control.emplace_back(where(rng), where(rng));
        flat.push_back(control.front());
        kontur::geo::flatten(kontur::geo::Bezier(control), 0.25, flat);
        std::vector<QPointF> line;
        for (const kontur::geo::Point &p : flat)
            line.emplace_back(p.x(), p.y());
        QImage reference(200, 200, QImage::Format_ARGB32_Premultiplied);
        reference.fill(Qt::transparent);
        QImage fast = reference;
        {
            QPainter p(&reference);
            p.setRenderHint(QPainter::Antialiasing, true);
            p.setPen(QPen(Qt::black, 2.0, Qt::SolidLine, Qt::FlatCap, Qt::BevelJoin));
            p.drawPolyline(line.data(), static_cast<int>(line.size()));
        }
        {
            QPainter p(&fast);
            p.setRenderHint(QPainter::Antialiasing, true);
            kontur::paintFastStroke(line, Qt::black, 2.0, false, p);
        }
        double inkReference = 0.0, inkFast = 0.0, stray = 0.0;
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 200; ++x) {
                const int a = qAlpha(fast.pixel(x, y));
                inkReference += qAlpha(reference.pixel(x, y));
                inkFast += a;
                // Far from the pen's ink: no reference coverage in the 3×3 neighbourhood.
                bool near = false;
                for (int dy = -1; dy <= 1 && !near; ++dy)
                    for (int dx = -1; dx <= 1 && !near; ++dx)
                        near = reference.rect().contains(x + dx, y + dy) && qAlpha(reference.pixel(x + dx, y + dy)) > 0;
                if (!near)
                    stray += a;
            }
        QVERIFY2(std::abs(inkFast / inkReference - 1.0) < 0.1,
                 qPrintable(QStringLiteral("round %1: ink %2 vs %3").arg(round).arg(inkFast).arg(inkReference)));
        QVERIFY2(stray < 0.02 * inkReference,
                 qPrintable(QStringLiteral("round %1: stray ink %2").arg(round).arg(stray)));
    }
}

void TestCanvasRender::strokeWidthIndependentOfZoom()
{
    newDocument();
    // A straight horizontal curve through the world origin; nothing selected (no halo).
    const int c = addCurve(
        {QVariantList{-150.0, 0.0}, QVariantList{-50.0, 0.0}, QVariantList{50.0, 0.0}, QVariantList{150.0, 0.0}});
    QVERIFY(c >= 0);
    m_editor->selection()->selectRow(-1);
    const auto thickness = [&] {
        const QImage image = grab();
        // A column a little off the centre, away from the axis crossing and the points.
        return darkRun(image, sceneOfWorld(kontur::geo::Point(20.0 / m_canvas->zoom(), 0.0)), 12);
    };
    const int atOne = thickness();
    QVERIFY2(atOne >= 1 && atOne <= 3, qPrintable(QString::number(atOne)));
    for (int i = 0; i < 6; ++i)
        m_canvas->zoomIn(); // about 3.8×
    QTRY_VERIFY(m_canvas->zoom() > 3.5);
    const int zoomedIn = thickness();
    QVERIFY2(std::abs(zoomedIn - atOne) <= 1, qPrintable(QStringLiteral("%1 vs %2").arg(zoomedIn).arg(atOne)));
    for (int i = 0; i < 12; ++i)
        m_canvas->zoomOut(); // about 0.26×
    const int zoomedOut = thickness();
    QVERIFY2(std::abs(zoomedOut - atOne) <= 1, qPrintable(QStringLiteral("%1 vs %2").arg(zoomedOut).arg(atOne)));
}

void TestCanvasRender::reflattenedWhenZoomedFarIn()
{
    newDocument();
    const int c = addCurve({QVariantList{-200.0, -100.0}, QVariantList{-100.0, 150.0}, QVariantList{100.0, 150.0},
                            QVariantList{200.0, -100.0}});
    QVERIFY(c >= 0);
    m_editor->selection()->selectRow(-1);
    verifyCurveAt(grab(), c, 1, "at 100 %");
    // Far in, about a point of the arch: a flattening made for 100 % would be off by many pixels
    // between its vertices; the drawn curve must still pass within a pixel of every sample.
    const kontur::geo::Point p = m_editor->document()->curve(c).segment(0).eval(0.3);
    m_canvas->restoreView(300.0, QPointF(p.x(), p.y()));
    verifyCurveAt(grab(), c, 1, "at 30000 %");
    m_canvas->restoreView(1.0, QPointF());
    verifyCurveAt(grab(), c, 1, "back at 100 %");
}

void TestCanvasRender::curvesFollowAPinchAndSettle()
{
    // Twice: a small drawing (drawn sharp at every step) and a large one (more than 2,000 Bézier
    // segments, with a long curve out of sight: the cached layer shown moved and scaled).
    for (const bool large : {false, true}) {
        newDocument();
        std::vector<int> curves;
        for (int k = 0; k < 3; ++k)
            curves.push_back(addCurve({QVariantList{-250.0, -150.0 + 100 * k}, QVariantList{-80.0, 20.0 + 100 * k},
                                       QVariantList{80.0, -120.0 + 100 * k}, QVariantList{250.0, 0.0 + 100 * k}}));
        if (large) {
            QVariantList knots;
            for (int k = 0; k <= 2100; ++k)
                knots << QVariant(QVariantList{5000.0 + 3.0 * k, 5000.0 + (k % 2) * 4.0});
            QVERIFY(addCurve(knots, kontur::CurveKind::Composite) >= 0);
        }
        m_editor->selection()->selectRow(-1);
        verifyCurveAt(grab(), curves[1], 1, "before");
        // A pinch in steps, grabbed at once.
        const QPointF centroid(m_canvas->width() * 0.4, m_canvas->height() * 0.55);
        m_canvas->pinchStarted(centroid);
        for (int step = 1; step <= 5; ++step)
            m_canvas->pinchUpdated(1.0 + 0.08 * step, centroid + QPointF(4.0 * step, -3.0 * step));
        const QImage during = grab();
        for (int c : curves)
            verifyCurveAt(during, c, large ? 2 : 1, large ? "during the pinch, cached" : "during the pinch, sharp");
        m_canvas->pinchEnded();
        // Settled: drawn sharp at the new view.
        QTRY_VERIFY(layerAtView());
        const QImage settled = grab();
        for (int c : curves)
            verifyCurveAt(settled, c, 1, "settled");
    }
}

void TestCanvasRender::dragRedrawsTheDraggedCurveOnly()
{
    newDocument();
    const int a = addCurve({QVariantList{-250.0, 100.0}, QVariantList{-100.0, 200.0}, QVariantList{100.0, 200.0},
                            QVariantList{250.0, 100.0}});
    const int b = addCurve({QVariantList{-250.0, -150.0}, QVariantList{-100.0, -50.0}, QVariantList{100.0, -50.0},
                            QVariantList{250.0, -150.0}});
    QVERIFY(a >= 0 && b >= 0);
    const kontur::geo::Point handle = m_editor->document()->curve(a).definingPoint(1);
    const QPointF before = sceneOfWorld(m_editor->document()->curve(a).segment(0).eval(0.35));
    m_editor->selection()->selectRow(a);
    QVERIFY(m_editor->beginDrag(QPointF(handle.x(), handle.y()), 1e-6));
    for (int step = 1; step <= 6; ++step) {
        m_editor->dragTo(QPointF(handle.x() + 10.0 * step, handle.y() - 40.0 * step));
        const QImage frame = grab();
        verifyCurveAt(frame, a, 1, "dragged curve");
        verifyCurveAt(frame, b, 1, "other curve");
    }
    m_editor->endDrag();
    // Where the dragged curve was is blank again (the old picture of it is gone).
    const QImage after = grab();
    QVERIFY2(kontur::test::darkestNear(after, before, 0) > 160,
             qPrintable(QString::number(kontur::test::darkestNear(after, before, 0))));
    verifyCurveAt(after, a, 1, "after the drag");
    verifyCurveAt(after, b, 1, "other curve after the drag");
}

// The canvas's flattenings follow the document's rows: adding, deleting or moving a curve in a large
// drawing flattens at most the curve added, not every curve again (they were all flattened once).
void TestCanvasRender::insertFlattensOneCurve()
{
    newDocument();
    for (int k = 0; k < 600; ++k) {
        const double x = -300.0 + k;
        QVERIFY(addCurve({QVariantList{x, -200.0}, QVariantList{x + 40.0, -60.0}, QVariantList{x - 40.0, 60.0},
                          QVariantList{x, 200.0}}) >= 0);
    }
    m_editor->selection()->clear();
    (void)grab();
    QTRY_VERIFY(layerAtView());
    (void)grab();
    const auto flattenedBy = [&](const std::function<void()> &change) {
        const std::uint64_t before = m_canvas->flattenings();
        change();
        (void)grab();
        // The settle timer has drawn the layer anew, if it had to; a layer that never settles gives a
        // count no change can give, so the comparison below fails.
        if (!QTest::qWaitFor([&] { return layerAtView(); }))
            return std::numeric_limits<std::uint64_t>::max();
        (void)grab();
        return m_canvas->flattenings() - before;
    };
    QCOMPARE(flattenedBy([] {}), std::uint64_t{0});
    QCOMPARE(flattenedBy([&] {
                 QVERIFY(addCurve({QVariantList{0.0, 0.0}, QVariantList{50.0, 80.0}, QVariantList{100.0, 0.0}}) >= 0);
                 m_editor->selection()->clear();
             }),
             std::uint64_t{1});
    QCOMPARE(flattenedBy([&] { m_editor->undo(); }), std::uint64_t{0});
    QCOMPARE(flattenedBy([&] {
                 m_editor->commands()->moveCurve(kontur::test::idAt(*m_editor, 10), 400);
                 m_editor->selection()->clear();
             }),
             std::uint64_t{0});
}

// The selected curve is drawn apart from the others (over the cached layer): selecting, hiding
// and deleting curves must leave each visible curve drawn exactly once, and nothing of the others.
void TestCanvasRender::everyCurveDrawnWhateverIsSelected()
{
    newDocument();
    // 70 curves: more than one chunk of stroke nodes on GPU backends.
    std::vector<int> curves;
    for (int k = 0; k < 70; ++k) {
        const double x = -300.0 + 9.0 * k;
        curves.push_back(addCurve({QVariantList{x, -200.0}, QVariantList{x + 40.0, -60.0}, QVariantList{x - 40.0, 60.0},
                                   QVariantList{x, 200.0}}));
        QVERIFY(curves.back() >= 0);
    }
    const auto blankWhereItWas = [&](int c, const QImage &image) {
        // The middle of the curve, away from its neighbours (9 world units apart at 100 %).
        const QPointF at = sceneOfWorld(m_editor->document()->curve(c).segment(0).eval(0.5));
        return kontur::test::darkestNear(image, at, 0) > 160;
    };
    for (int selected : {0, 64, 65, 69, -1, 3}) {
        m_editor->selection()->selectRow(selected);
        const QImage image = grab();
        for (int c : {0, 3, 63, 64, 65, 69})
            verifyCurveAt(image, c, 1, qPrintable(QStringLiteral("selected %1").arg(selected)));
    }
    // Hidden: gone from the picture, whether selected or in the layer.
    QVERIFY(m_editor->commands()->setCurveVisible(kontur::test::idAt(*m_editor, 3), false));
    QVERIFY(m_editor->commands()->setCurveVisible(kontur::test::idAt(*m_editor, 64), false));
    m_editor->selection()->selectRow(3);
    QImage image = grab();
    QVERIFY(blankWhereItWas(3, image));
    QVERIFY(blankWhereItWas(64, image));
    verifyCurveAt(image, 65, 1, "beside a hidden curve");
    QVERIFY(m_editor->commands()->setCurveVisible(kontur::test::idAt(*m_editor, 64), true));
    verifyCurveAt(grab(), 64, 1, "shown again");
    // Deleted: the picture of the curves after it moves along.
    const QPointF lastBefore = sceneOfWorld(m_editor->document()->curve(69).segment(0).eval(0.5));
    QVERIFY(m_editor->commands()->deleteCurve(kontur::test::idAt(*m_editor, 69)));
    m_editor->selection()->selectRow(-1);
    image = grab();
    QVERIFY2(kontur::test::darkestNear(image, lastBefore, 0) > 160, "a deleted curve is still drawn");
    verifyCurveAt(image, 68, 1, "after a delete");
}

// The PNG export grabs the canvas at 1, 2 or 4 times its size: every curve must be drawn as a
// line of the scaled width there, not as the on-screen cache's pixels enlarged.
void TestCanvasRender::pngExportDrawsLinesAtItsScale()
{
    newDocument();
    const int line = addCurve(
        {QVariantList{-200.0, 40.0}, QVariantList{-70.0, 40.0}, QVariantList{70.0, 40.0}, QVariantList{200.0, 40.0}});
    QVERIFY(addCurve({QVariantList{-200.0, -100.0}, QVariantList{-70.0, -20.0}, QVariantList{70.0, -180.0},
                      QVariantList{200.0, -100.0}}) >= 0);
    m_editor->selection()->selectRow(-1); // both curves in the cache
    verifyCurveAt(grab(), line, 1, "on screen");
    constexpr int scale = 4;
    m_canvas->setLayered(false);
    const QSharedPointer<QQuickItemGrabResult> result = m_canvas->grabToImage(m_canvas->size().toSize() * scale);
    QVERIFY(result);
    QSignalSpy ready(result.data(), &QQuickItemGrabResult::ready);
    QVERIFY(ready.wait(5000));
    m_canvas->setLayered(true);
    const QImage image = result->image();
    QCOMPARE(image.size(), m_canvas->size().toSize() * scale);
    // Across the horizontal line: the width times 4, plus at most a pixel of fringe each side.
    const double width = m_canvas->property("curveWidth").toDouble() * scale;
    const QPointF at = m_canvas->toScreen(QPointF(30.0, 40.0)) * scale;
    int ink = 0;
    for (int dy = -30; dy <= 30; ++dy)
        if (qGray(image.pixel(at.toPoint() + QPoint(0, dy))) < 200)
            ++ink;
    QVERIFY2(ink >= width - 1 && ink <= width + 2,
             qPrintable(QStringLiteral("%1 px of ink across a %2 px line").arg(ink).arg(width)));
    verifyCurveAt(grab(), line, 1, "on screen again");
}

void TestCanvasRender::gridWhereTheViewSays()
{
    // The grid's lines at x = k·step, under a curve, on every path (with a painted layer the grid
    // is in the picture); switched off, none; a pan moves them with the world.
    newDocument();
    QVERIFY(addCurve({QVariantList{-200.0, -300.0}, QVariantList{-100.0, -250.0}, QVariantList{100.0, -250.0},
                      QVariantList{200.0, -300.0}}) >= 0);
    QVERIFY(addCurve({QVariantList{-200.0, 300.0}, QVariantList{-100.0, 250.0}, QVariantList{100.0, 250.0},
                      QVariantList{200.0, 300.0}}) >= 0);
    m_editor->selection()->selectRow(0);
    const QColor gridColor = m_canvas->property("gridColor").value<QColor>();
    const QColor background = m_window->color();
    QVERIFY(gridColor != background);
    const auto near = [](QRgb pixel, const QColor &color) {
        return std::abs(qRed(pixel) - color.red()) <= 12 && std::abs(qGreen(pixel) - color.green()) <= 12 &&
               std::abs(qBlue(pixel) - color.blue()) <= 12;
    };
    // Rows of the canvas at a third and two thirds of its height (no curve there); the vertical
    // grid lines cross them where the view puts world x = k·step.
    const auto gridColumnsMatch = [&](const QImage &image, bool expectGrid) {
        const double step = m_canvas->gridStep();
        int lines = 0;
        for (const double rowFraction : {0.33, 0.66}) {
            const double y = m_canvas->height() * rowFraction;
            const double left = m_canvas->toWorld(QPointF(0, y)).x();
            const double right = m_canvas->toWorld(QPointF(m_canvas->width(), y)).x();
            for (double x = std::ceil(left / step) * step; x < right; x += step) {
                const double sx = m_canvas->toScreen(QPointF(x, 0)).x();
                const double betweenX = sx + step * m_canvas->zoom() / 2.0;
                if (sx < 3 || betweenX > m_canvas->width() - 3 || std::abs(x) < step / 2)
                    continue; // the axis has a colour of its own; the panel lies beyond the canvas
                const QPointF on = scene(QPointF(sx, y));
                const QPointF between = scene(QPointF(sx + m_canvas->gridStep() * m_canvas->zoom() / 2.0, y));
                const qreal dpr = image.devicePixelRatio();
                const QRgb onPixel = image.pixel((on * dpr).toPoint());
                const QRgb offPixel = image.pixel((between * dpr).toPoint());
                QVERIFY2(
                    near(offPixel, background),
                    qPrintable(
                        QStringLiteral("not background between lines at %1, %2").arg(between.x()).arg(between.y())));
                // A line one pixel wide at a fractional position covers one or two of the three
                // pixels around it.
                bool onGrid = false;
                for (int dx = -1; dx <= 1; ++dx) {
                    const QRgb pixel = image.pixel((on * dpr).toPoint() + QPoint(dx, 0));
                    onGrid = onGrid || near(pixel, gridColor) || qGray(pixel) < qGray(background.rgb()) - 3;
                }
                QVERIFY2(onGrid == expectGrid, qPrintable(QStringLiteral("grid line at world x %1 (window %2, %3): %4")
                                                              .arg(x)
                                                              .arg(on.x())
                                                              .arg(on.y())
                                                              .arg(QColor(onPixel).name())));
                ++lines;
            }
        }
        QVERIFY2(lines >= 4, qPrintable(QStringLiteral("only %1 grid lines checked").arg(lines)));
    };
    m_canvas->setProperty("showGrid", true);
    QTRY_VERIFY(m_canvas->property("showGrid").toBool());
    gridColumnsMatch(grab(), true);
    if (QTest::currentTestFailed())
        return;
    // Panned by a third of a grid step: the lines move with the world.
    m_canvas->panBy(QPointF(m_canvas->gridStep() * m_canvas->zoom() / 3.0, 0));
    QTRY_VERIFY(layerAtView()); // settled: drawn anew at the new view
    gridColumnsMatch(grab(), true);
    if (QTest::currentTestFailed())
        return;
    m_canvas->setProperty("showGrid", false);
    gridColumnsMatch(grab(), false);
}

void TestCanvasRender::cleanupTestCase()
{
    m_engine.reset();
}

QTEST_MAIN(TestCanvasRender)
#include "tst_canvasrender.moc"
