// A seam allowance per seam set by touch and mouse in the real window (issue #44): a 200 × 300 mm
// rectangle piece with a 10 mm allowance; the piece bar's Seam allowance tool; a finger taps the hem
// (the bottom seam) and + three times by finger makes it 25 mm, a mouse click on + makes it 30 mm;
// the mouse chooses the right seam, types 15 and steps − back to 10; the allowance is then exactly
// the rectangle grown by 30 at the hem and 10 elsewhere; the chosen seam is highlighted on screen;
// the hem's corners turned back by a finger (a rectangle's are then the same); undo step by step
// gives the 10 mm allowance back. Then a long wavy piece (issue #45): arrow keys nudge a knot chosen
// by a click, + is tapped and clicked, and the allowance, made on the worker meanwhile (no offset on
// the GUI thread), ends exactly the offset of the piece.
#include "windowtest.h"

#include "../straightpiece.h"
#include "../wavypiece.h"

#include "app/curvecanvas.h"
#include "app/language.h"
#include "app/piecepainter.h"
#include "geometry/offset.h"
#include "io/seam.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/seamwidths.h"
#include "models/document/document.h"
#include "models/document/selection.h"

#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

#include <cmath>

using kontur::Curve;
using kontur::EditController;
using kontur::PiecePainter;
using kontur::SeamWidths;
using kontur::geo::Point;

class TestSeamWidthsWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findVisibleItem(m_window, name); }
    QPoint sceneOf(const Point &world) const
    {
        return m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y()))).toPoint();
    }
    const Curve &allowance() const { return m_editor->document()->curve(1); }
    // Whether every knot of the allowance lies on the boundary of the box [lo, hi] and each corner of
    // the box is a knot (within `eps`).
    bool allowanceIs(const Point &lo, const Point &hi, double eps) const
    {
        const kontur::geo::PiecewiseBezier a = allowance().toPiecewise();
        for (const Point &corner : {lo, Point(hi.x(), lo.y()), hi, Point(lo.x(), hi.y())}) {
            bool found = false;
            for (const auto &s : a.segments())
                found = found || (s.startPoint() - corner).norm() <= eps;
            if (!found)
                return false;
        }
        for (const auto &s : a.segments())
            for (int j = 0; j <= 4; ++j) {
                const Point p = s.eval(j / 4.0);
                const double edge = std::min({std::abs(p.x() - lo.x()), std::abs(p.x() - hi.x()),
                                              std::abs(p.y() - lo.y()), std::abs(p.y() - hi.y())});
                if (edge > eps || p.x() < lo.x() - eps || p.x() > hi.x() + eps || p.y() < lo.y() - eps ||
                    p.y() > hi.y() + eps)
                    return false;
            }
        return true;
    }
    bool tapButton(const QString &name, bool mouse)
    {
        QQuickItem *button = item(name);
        if (!button || !button->isVisible() || !button->isEnabled())
            return false;
        kontur::test::ensureVisible(button);
        if (mouse)
            QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(button));
        else
            tap(kontur::test::centerOf(button));
        return true;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(start(QSize(1280, 800))); }

    void seamWidthsByTouchAndMouse()
    {
        // A 200 × 300 mm rectangle of straight sides, counter-clockwise from the origin: seam 0 is the
        // bottom (the hem), 1 the right side, 2 the top, 3 the left side.
        std::optional<Curve> outline = kontur::test::rectangleOutline(QStringLiteral("Back"));
        QVERIFY(outline);
        outline->piece = kontur::io::PieceMarks{};
        // Its 10 mm allowance, linked to it as a file links it (by the source's index).
        const kontur::geo::OffsetOptions options = kontur::io::defaultSeamOptions(QStringLiteral("mm"));
        Curve seam = *Curve::makeOffset(*outline, options);
        seam.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
        m_editor->replaceDocument({*outline, seam}, kontur::Background{}, QStringLiteral("mm"), false);
        QVERIFY(allowanceIs({-10, -10}, {210, 310}, 1e-9));
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->curve(0).id(), -1);
        auto *seams = m_window->findChild<SeamWidths *>(QStringLiteral("seamWidths"));
        auto *painter = m_window->findChild<PiecePainter *>(QStringLiteral("piecePainter"));
        QVERIFY(seams && painter);
        QTRY_COMPARE(seams->seamCount(), 4);

        QTRY_VERIFY(item(QStringLiteral("pieceButton")));
        QVERIFY(tapButton(QStringLiteral("pieceButton"), false));
        QTRY_VERIFY(item(QStringLiteral("pieceBar")) && item(QStringLiteral("pieceBar"))->isVisible());
        m_canvas->fitToView();
        m_canvas->zoomBy(0.7, QPointF(m_canvas->width() / 2, m_canvas->height() / 2));
        QTRY_VERIFY(m_canvas->zoom() > 0.5);

        // --- a finger: the tool, the hem, + three times; the mouse: + once ---
        QTRY_VERIFY(item(QStringLiteral("pieceSeamTool")));
        QVERIFY(tapButton(QStringLiteral("pieceSeamTool"), false));
        QTRY_COMPARE(painter->tool(), PiecePainter::Tool::Seam);
        const int start = m_editor->undoStack()->count();
        // Beside the hem on screen, before and after it is chosen: redder (the highlight's orange).
        const QPoint beside = sceneOf({100, 0}) + QPoint(0, 3);
        const auto redness = [&] {
            const QColor c = m_window->grabWindow().pixelColor(beside);
            return c.red() - c.blue();
        };
        const int before = redness();
        tap(sceneOf({100, 0}) + QPoint(0, 2));
        QTRY_COMPARE(seams->seam(), 0);
        QTRY_VERIFY(item(QStringLiteral("pieceSeamWider")));
        QCOMPARE(seams->widthText(), QStringLiteral("10"));
        for (int i = 0; i < 3; ++i)
            QVERIFY(tapButton(QStringLiteral("pieceSeamWider"), false));
        QTRY_COMPARE(seams->width().value_or(0), 25.0);
        QVERIFY(tapButton(QStringLiteral("pieceSeamWider"), true));
        QTRY_COMPARE(seams->width().value_or(0), 30.0);
        QVERIFY(seams->ownWidth());
        QCOMPARE(m_editor->undoStack()->count(), start + 4);
        QTRY_VERIFY(allowanceIs({-10, -30}, {210, 310}, 1e-9));

        // The chosen seam is drawn wide in the highlight colour.
        QVERIFY2(redness() >= before + 60, qPrintable(QStringLiteral("%1 → %2").arg(before).arg(redness())));
        kontur::test::screenshot(m_window, QStringLiteral("seamwidths.png"));

        // --- the mouse: the right seam; 15 typed, − once: back to 10 (its own width now) ---
        QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf({200, 150}) + QPoint(2, 0));
        QTRY_COMPARE(seams->seam(), 1);
        QCOMPARE(seams->widthText(), QStringLiteral("10"));
        QVERIFY(!seams->ownWidth());
        QQuickItem *field = item(QStringLiteral("pieceSeamWidth"));
        QVERIFY(field);
        kontur::test::ensureVisible(field);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(field));
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        for (const char c : {'1', '5'})
            QTest::keyClick(m_window, c);
        QTest::keyClick(m_window, Qt::Key_Return);
        QTRY_COMPARE(seams->width().value_or(0), 15.0);
        QTRY_VERIFY(allowanceIs({-10, -30}, {215, 310}, 1e-9));
        QVERIFY(tapButton(QStringLiteral("pieceSeamNarrower"), true));
        QTRY_COMPARE(seams->width().value_or(0), 10.0);
        QTRY_VERIFY(allowanceIs({-10, -30}, {210, 310}, 1e-9));
        // The piece holds the widths: the hem 30, the right side its own 10.
        const auto widths = m_editor->document()->curve(0).piece->seamWidths;
        QCOMPARE(widths.size(), std::size_t(2));
        QCOMPARE(widths[0].value_or(0), 30.0);
        QCOMPARE(widths[1].value_or(0), 10.0);

        // --- a finger: the hem again, its corners turned back (on a rectangle: the same corners) ---
        tap(sceneOf({100, 0}) + QPoint(0, -2));
        QTRY_COMPARE(seams->seam(), 0);
        QVERIFY(!seams->hem());
        QVERIFY(tapButton(QStringLiteral("pieceSeamHem"), false));
        QTRY_VERIFY(seams->hem());
        QCOMPARE(m_editor->document()->curve(0).piece->hems, std::vector<int>{0});
        QTRY_VERIFY(allowanceIs({-10, -30}, {210, 310}, 1e-9));

        // --- undo, step by step, back to 10 mm all round ---
        const int steps = m_editor->undoStack()->count() - start;
        QCOMPARE(steps, 7);
        for (int i = 0; i < steps; ++i)
            m_editor->undo();
        QTRY_VERIFY(allowanceIs({-10, -10}, {210, 310}, 1e-9));
        QVERIFY(m_editor->document()->curve(0).piece->seamWidths.empty());
        m_editor->redo();
        QTRY_VERIFY(allowanceIs({-10, -15}, {210, 310}, 1e-9));

        QVERIFY(tapButton(QStringLiteral("pieceDone"), false));
        QTRY_COMPARE(painter->tool(), PiecePainter::Tool::None);
    }

    // The seam's row in English, Latvian and Russian at 1280 × 800, 1920 × 1080 and 800 × 1280: each
    // control inside the window, over no other, its label not cut.
    void seamRowFitsEverySizeAndLanguage()
    {
        auto *language = m_engine->findChild<kontur::Language *>();
        auto *seams = m_window->findChild<SeamWidths *>(QStringLiteral("seamWidths"));
        QVERIFY(language && seams);
        QVERIFY(tapButton(QStringLiteral("pieceButton"), false));
        QTRY_VERIFY(item(QStringLiteral("pieceSeamTool")));
        QVERIFY(tapButton(QStringLiteral("pieceSeamTool"), false));
        tap(sceneOf({100, 0}) + QPoint(0, -2));
        QTRY_COMPARE(seams->seam(), 0);
        QTRY_VERIFY(seams->ownWidth()); // "As the piece" shown too
        const QStringList names{QStringLiteral("pieceSeamTool"),  QStringLiteral("pieceSeamNarrower"),
                                QStringLiteral("pieceSeamWidth"), QStringLiteral("pieceSeamWider"),
                                QStringLiteral("pieceSeamHem"),   QStringLiteral("pieceSeamReset"),
                                QStringLiteral("pieceDone")};
        for (const QSize size : {QSize(1280, 800), QSize(1920, 1080), QSize(800, 1280)})
            for (const QString &code : {QStringLiteral("en"), QStringLiteral("lv"), QStringLiteral("ru")}) {
                QVERIFY(language->setCurrent(code));
                m_window->resize(size);
                QTRY_COMPARE(m_window->size(), size);
                const auto problem = [&]() -> QString {
                    QList<QRectF> seen;
                    for (const QString &name : names) {
                        QQuickItem *it = item(name);
                        if (!it)
                            return name + QStringLiteral(" missing");
                        const QRectF r = it->mapRectToScene(it->boundingRect());
                        if (!QRectF(QPointF(0, 0), QSizeF(size)).contains(r))
                            return name + QStringLiteral(" outside the window");
                        for (const QRectF &other : seen)
                            if (other.intersects(r))
                                return name + QStringLiteral(" overlaps another control");
                        seen << r;
                        if (it->inherits("QQuickAbstractButton") &&
                            it->width() + 0.5 < it->property("implicitWidth").toDouble())
                            return name + QStringLiteral(" cut");
                    }
                    return {};
                };
                QTRY_VERIFY2(
                    problem().isEmpty(),
                    qPrintable(
                        QStringLiteral("%1 %2x%3: %4").arg(code).arg(size.width()).arg(size.height()).arg(problem())));
                kontur::test::screenshot(
                    m_window, QStringLiteral("seamrow-%1-%2x%3.png").arg(code).arg(size.width()).arg(size.height()));
            }
        QVERIFY(language->setCurrent(QStringLiteral("en")));
        m_window->resize(QSize(1280, 800));
    }

    // A held arrow key and fast taps on + on a long piece: each an undo step, the allowance made on
    // the worker (none on this thread), exact once settled; undo exact too.
    void nudgesAndStepsEndExact()
    {
        Curve outline = kontur::test::wavyPiece(600);
        outline.piece = kontur::io::PieceMarks{};
        const kontur::geo::OffsetOptions options = kontur::io::defaultSeamOptions(QStringLiteral("mm"));
        Curve seam = *Curve::makeOffset(outline, options);
        seam.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
        // Last: the tests before work on the rectangle. The seam tool they leave open is ended.
        auto *painter = m_window->findChild<PiecePainter *>(QStringLiteral("piecePainter"));
        QVERIFY(painter);
        if (item(QStringLiteral("pieceDone")))
            QVERIFY(tapButton(QStringLiteral("pieceDone"), false));
        QTRY_COMPARE(painter->tool(), PiecePainter::Tool::None);
        m_editor->replaceDocument({outline, seam}, kontur::Background{}, QStringLiteral("mm"), false);
        const kontur::Document &document = *m_editor->document();
        const auto exact = [&] {
            const Curve &piece = document.curve(0);
            const auto fresh = Curve::makeOffset(piece, kontur::allowanceOptions(piece, allowance().seam->options));
            return fresh.ok() && fresh->composite().controlPoints() == allowance().composite().controlPoints();
        };
        m_editor->setMode(EditController::Mode::Select);
        m_canvas->fitToView();
        QTRY_VERIFY(m_canvas->zoom() > 0);
        const int start = m_editor->undoStack()->count();
        kontur::geo::detail::resetOffsetWork();

        // --- a click on a knot, then the arrow keys: 4 × right, 3 × up ---
        const int knot = 3 * 75; // at the top of the piece
        const Point at = document.curve(0).definingPoint(knot);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, sceneOf(at));
        QTRY_VERIFY(m_editor->selection()->point() >= 0);
        const int row = m_editor->selection()->point();
        const Point before = document.curve(0).definingPoint(row);
        for (int i = 0; i < 4; ++i)
            QTest::keyClick(m_window, Qt::Key_Right);
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(m_window, Qt::Key_Up);
        QCOMPARE(m_editor->undoStack()->count(), start + 7);
        const Point moved = document.curve(0).definingPoint(row) - before;
        QVERIFY2(std::abs(moved.x() * m_canvas->zoom() - 4) < 1e-6 && std::abs(moved.y() * m_canvas->zoom() - 3) < 1e-6,
                 qPrintable(QStringLiteral("%1, %2").arg(moved.x()).arg(moved.y())));
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QVERIFY(exact());
        kontur::geo::detail::resetOffsetWork();

        // --- the piece bar's seam tool: the outline tapped (one seam round it), + by finger and mouse ---
        auto *seams = m_window->findChild<SeamWidths *>(QStringLiteral("seamWidths"));
        QVERIFY(seams);
        QTRY_VERIFY(item(QStringLiteral("pieceButton")));
        QVERIFY(tapButton(QStringLiteral("pieceButton"), false));
        QTRY_VERIFY(item(QStringLiteral("pieceSeamTool")));
        QVERIFY(tapButton(QStringLiteral("pieceSeamTool"), false));
        tap(sceneOf(document.curve(0).definingPoint(3 * 300)));
        QTRY_COMPARE(seams->seam(), 0);
        QTRY_VERIFY(item(QStringLiteral("pieceSeamWider")));
        const int stepsFrom = m_editor->undoStack()->count();
        for (int i = 0; i < 3; ++i)
            QVERIFY(tapButton(QStringLiteral("pieceSeamWider"), false));
        QVERIFY(tapButton(QStringLiteral("pieceSeamWider"), true));
        QTRY_COMPARE(seams->width().value_or(0), 30.0);
        QCOMPARE(m_editor->undoStack()->count(), stepsFrom + 4);
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QVERIFY(exact());
        kontur::test::screenshot(m_window, QStringLiteral("seamwidths-wavy.png"));

        // --- undo of the last step and of the last nudge: exact once settled ---
        m_editor->undo();
        QTRY_COMPARE(seams->width().value_or(0), 25.0);
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QVERIFY(exact());
        while (m_editor->undoStack()->count() > 0 && m_editor->undoStack()->index() > start + 6)
            m_editor->undo();
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QVERIFY(exact());
        QVERIFY(tapButton(QStringLiteral("pieceDone"), false));
    }
};

QTEST_MAIN(TestSeamWidthsWindow)
#include "tst_seamwidths_window.moc"
