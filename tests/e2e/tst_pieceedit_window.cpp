// Finishing a traced piece by touch in the real window: a freehand stroke by finger from an open
// curve's end extends it; then, tapping knots on the canvas and the buttons of the point bar and the
// side panel: Make line (the segment is drawn on its chord), Delete knot, Corner, Close (the ends
// merged into a corner, no short segment), Undo — each checked in the document and on screen.
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "geometry/nearest.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/selection.h"
#include "models/trace/tracecontroller.h"

#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

#include <cmath>
#include <limits>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::TraceController;
using kontur::geo::NodeType;
using kontur::geo::Point;

class TestPieceEditWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findVisibleItem(m_window, name); }
    QPoint scene(QPointF canvasPoint) const { return m_canvas->mapToScene(canvasPoint).toPoint(); }
    QPoint sceneOf(const Point &world) const { return scene(m_canvas->toScreen(QPointF(world.x(), world.y()))); }
    const Curve &piece() const { return m_editor->document()->curve(0); }

    void tapAt(QPoint p)
    {
        QTest::touchEvent(m_window, m_touch).press(0, p);
        QTest::touchEvent(m_window, m_touch).release(0, p);
    }
    // Taps a button (scrolled into view first where it is in the panel); false when it is missing,
    // hidden or disabled.
    bool tapButton(const QString &name)
    {
        QQuickItem *button = item(name);
        if (!button || !button->isVisible() || !button->isEnabled() || !kontur::test::standsStill(m_window, button))
            return false;
        tapAt(kontur::test::centerOf(button));
        return true;
    }
    // Taps knot `k` of the piece on the canvas: it becomes the selected point.
    bool tapKnot(int k)
    {
        tapAt(sceneOf(piece().composite().knot(k)));
        return m_editor->selection()->point() == piece().rowOfKnot(k);
    }
    // The darkest grey within 2 px of a world point on the window's picture.
    int darkness(const Point &world) const
    {
        return kontur::test::darkestNear(m_window->grabWindow(),
                                         m_canvas->mapToScene(m_canvas->toScreen({world.x(), world.y()})), 2);
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(start(QSize(1280, 800))); }

    void finishAPieceByTouch()
    {
        // A placed open curve in mm: a curved top edge from (0, 0) over (120, 0) and out round to (120, 80).
        Curve top = Curve::make(CurveKind::Composite, {{0, 0}, {60, -30}, {120, 0}, {150, 40}, {120, 80}});
        top.name = QStringLiteral("Piece");
        m_editor->replaceDocument({top}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        QVERIFY(kontur::test::settled(m_window)); // the window shows a new document whole (later): then the view is set
        m_canvas->fitToView();
        m_canvas->zoomBy(0.6, QPointF(m_canvas->width() / 2, m_canvas->height() / 2)); // room for the rest
        QVERIFY(kontur::test::settled(m_window));
        auto *trace = m_window->findChild<TraceController *>(QStringLiteral("trace"));
        QVERIFY(trace);

        // --- extend: Freehand (T), a finger from the curve's end along the bottom and up the left side ---
        QTest::keyClick(m_window, Qt::Key_T);
        QTRY_COMPARE(trace->tool(), TraceController::Tool::Freehand);
        QVERIFY(kontur::test::settled(m_window)); // the trace bar takes its room: screen points are taken after it
        const Curve before = piece();
        std::vector<Point> path;
        for (int i = 0; i <= 60; ++i)
            path.emplace_back(120.0 - 2.0 * i, 80.0);
        for (int i = 1; i <= 39; ++i) // ends 2 mm short of the start, within a finger's reach of it
            path.emplace_back(0.0, 80.0 - 2.0 * i);
        QTest::touchEvent(m_window, m_touch).press(0, sceneOf(path.front()));
        for (std::size_t i = 1; i < path.size(); ++i) {
            QTest::touchEvent(m_window, m_touch).move(0, sceneOf(path[i]));
        }
        QTest::touchEvent(m_window, m_touch).release(0, sceneOf(path.back()));
        QTRY_VERIFY(piece().composite().knotCount() > before.composite().knotCount());
        QCOMPARE(m_editor->document()->curveCount(), 1); // no new curve: the old one goes on
        for (int s = 0; s < before.segmentCount(); ++s)
            QVERIFY(piece().segment(s).controlPoints() == before.segment(s).controlPoints());
        QTest::keyClick(m_window, Qt::Key_Escape);
        QTRY_COMPARE(trace->tool(), TraceController::Tool::None);
        QVERIFY(kontur::test::settled(m_window));
        const int steps = m_editor->undoStack()->count();

        // --- Make line: tap knot 0, then the point bar's button ---
        QVERIFY(tapKnot(0));
        QTRY_VERIFY(item(QStringLiteral("pointBar")) && item(QStringLiteral("pointBar"))->isVisible());
        const Point mid = 0.5 * (piece().composite().knot(0) + piece().composite().knot(1));
        const double bulge = kontur::geo::nearest(piece().segment(0), mid).distance * m_canvas->zoom();
        QVERIFY2(bulge > 8.0, qPrintable(QString::number(bulge))); // the arc is well away from its chord
        QVERIFY(darkness(mid) > 128);
        QVERIFY(tapButton(QStringLiteral("pointBar_pieceMakeLine")));
        QTRY_COMPARE(m_editor->undoStack()->count(), steps + 1);
        QCOMPARE(piece().composite().nodeType(0), NodeType::Corner);
        QCOMPARE(piece().composite().nodeType(1), NodeType::Corner);
        QVERIFY(kontur::geo::nearest(piece().segment(0), mid).distance <= 1e-12 * 100);
        QTRY_VERIFY(darkness(mid) < 100); // drawn on its chord now
        screenshot(QStringLiteral("pieceedit-makeline.png"));

        // --- Delete knot: tap the knot at (150, 40), then the point bar's button ---
        const int knots = piece().composite().knotCount();
        QVERIFY(tapKnot(3));
        QVERIFY(tapButton(QStringLiteral("pointBar_pieceDeleteKnot")));
        QTRY_COMPARE(piece().composite().knotCount(), knots - 1);
        for (int k = 0; k < piece().composite().knotCount(); ++k)
            QVERIFY(piece().composite().knot(k) != Point(150, 40));
        // The curve no longer goes out to that knot, and the window shows it so.
        double away = std::numeric_limits<double>::infinity();
        for (int s = 0; s < piece().segmentCount(); ++s)
            away = std::min(away, kontur::geo::nearest(piece().segment(s), Point(150, 40)).distance);
        QVERIFY2(away * m_canvas->zoom() > 6.0, qPrintable(QString::number(away)));
        QTRY_VERIFY(darkness(Point(150, 40)) > 128);

        // --- Corner from the side panel (scrolled into view): the smooth knot at (120, 0) ---
        QVERIFY(tapKnot(2));
        QCOMPARE(piece().composite().nodeType(2), NodeType::Smooth);
        QVERIFY(!item(QStringLiteral("pointBar_pieceCorner"))->property("checked").toBool());
        QVERIFY(tapButton(QStringLiteral("panel_pieceCorner")));
        QTRY_COMPARE(piece().composite().nodeType(2), NodeType::Corner);
        QTRY_VERIFY(item(QStringLiteral("pointBar_pieceCorner"))->property("checked").toBool());

        // --- Close: the stroke ended 2 mm from the start: merged into one corner knot ---
        const Curve open = piece();
        const int openKnots = open.composite().knotCount();
        QVERIFY(tapKnot(1));
        QVERIFY(tapButton(QStringLiteral("pointBar_pieceClose")));
        QTRY_VERIFY(piece().isClosed());
        QCOMPARE(piece().composite().knotCount(), openKnots - 1);
        QCOMPARE(piece().composite().nodeType(0), NodeType::Corner);
        QCOMPARE(piece().segmentCount(), openKnots - 1);
        QVERIFY(darkness(Point(0, 40)) < 100);
        screenshot(QStringLiteral("pieceedit-closed.png"));

        // --- Undo by touch: the open curve comes back exactly ---
        QVERIFY(tapButton(QStringLiteral("undoButton")));
        QTRY_VERIFY(!piece().isClosed());
        QVERIFY(piece().sameState(open));
        QCOMPARE(piece().composite().knotCount(), openKnots);
    }

    // Simplify curve… from the side panel by touch: the dialog proposes a tolerance, a typed one is
    // applied (fewer knots, one undo step); one no simpler curve can keep says so and changes nothing.
    void simplifyByTouch()
    {
        std::vector<Point> knots;
        for (int i = 0; i <= 40; ++i)
            knots.emplace_back(3.0 * i, 20.0 * std::sin(0.1 * i));
        Curve wave = Curve::make(CurveKind::Composite, knots);
        wave.name = QStringLiteral("Wave");
        m_editor->replaceDocument({wave}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        QVERIFY(kontur::test::settled(m_window));
        m_editor->selection()->select(m_editor->document()->idAt(0));
        QVERIFY(kontur::test::settled(m_window));
        const Curve before = piece();

        QVERIFY(tapButton(QStringLiteral("panel_pieceSimplify")));
        QQuickItem *field = nullptr;
        QTRY_VERIFY((field = item(QStringLiteral("simplifyTolerance"))) && field->isVisible() && field->width() > 0);
        QVERIFY(!field->property("text").toString().isEmpty()); // a proposal: a thousandth of the size
        const auto typeTolerance = [&](const QString &text) {
            tapAt(kontur::test::centerOf(field));
            QTRY_VERIFY(field->hasActiveFocus());
            QTest::keySequence(m_window, QKeySequence::SelectAll);
            for (const QChar c : text)
                QTest::keyClick(m_window, c.toLatin1());
            QCOMPARE(field->property("text").toString(), text);
        };
        // Far too tight for fewer knots: refused, said, nothing changes.
        typeTolerance(QStringLiteral("0.000001"));
        QVERIFY(tapButton(QStringLiteral("simplifyApply")));
        QTRY_VERIFY(item(QStringLiteral("simplifyMessage")) && item(QStringLiteral("simplifyMessage"))->isVisible());
        QVERIFY(piece().sameState(before));
        typeTolerance(QStringLiteral("0.2"));
        QVERIFY(tapButton(QStringLiteral("simplifyApply")));
        QTRY_VERIFY(piece().composite().knotCount() < before.composite().knotCount());
        QTRY_VERIFY(!field->isVisible());
        QVERIFY2(piece().composite().knotCount() <= 8, qPrintable(QString::number(piece().composite().knotCount())));
        for (int s = 0; s < before.segmentCount(); ++s)
            for (int i = 0; i <= 16; ++i) {
                double d = std::numeric_limits<double>::infinity();
                const Point p = before.segment(s).eval(i / 16.0);
                for (int t = 0; t < piece().segmentCount(); ++t)
                    d = std::min(d, kontur::geo::nearest(piece().segment(t), p).distance);
                QVERIFY(d <= 0.2);
            }
        screenshot(QStringLiteral("pieceedit-simplified.png"));
        QVERIFY(tapButton(QStringLiteral("undoButton")));
        QTRY_VERIFY(piece().sameState(before));
    }

    void cleanupTestCase() { m_engine.reset(); }
};

QTEST_MAIN(TestPieceEditWindow)
#include "tst_pieceedit_window.moc"
