// Seam allowance (issue #22) in the real window: Trace menu → "Seam allowance…" opens the dialog with
// the document's unit; a typed width and Add, by touch and by mouse, make one linked allowance at that
// distance (drawn beside its curve); changing its settings is one more undo step; undo takes each
// back. A long allowance (a 20,000-knot piece, seconds of work) runs off the GUI thread: the window
// goes on handling events, the progress and Cancel appear, and Cancel leaves the document and the
// undo stack as they were; one let finish is one undo step. Dragging a knot of a piece with its
// allowance computes no offset on the GUI thread and ends with the exact allowance (issue #45).
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "io/seam.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/selection.h"
#include "models/text/messages.h"
#include "models/trace/seamallowance.h"
#include "../wavypiece.h"

#include <QPointer>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

#include <cmath>
#include <numbers>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;

class TestSeamWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }

    // A closed piece in millimetres, selected; with `allowance`, its linked 10 mm allowance too, as a
    // file brings it.
    void pieceSelected(bool allowance = false)
    {
        Curve c = Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}, {40, 120}, {-10, 60}});
        QVERIFY(c.close().ok());
        c.name = QStringLiteral("Front");
        std::vector<Curve> curves{c};
        if (allowance) {
            const kontur::geo::OffsetOptions options = kontur::io::defaultSeamOptions(QStringLiteral("mm"));
            Curve seam = *Curve::makeOffset(c, options);
            seam.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
            curves.push_back(seam);
        }
        m_editor->replaceDocument(curves, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->idAt(0));
        m_canvas->fitToView();
        QVERIFY(kontur::test::settled(m_window));
    }

    // A long wavy closed piece of `knots` knots in millimetres (radius 200, waves of 30 and 10),
    // selected: its inside allowance at 40 mm crosses itself often and takes seconds at 20,000 knots.
    void wavySelected(int knots)
    {
        const Curve c = kontur::test::wavyPiece(knots);
        QVERIFY(c.isClosed());
        m_editor->replaceDocument({c}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->idAt(0));
        m_canvas->fitToView();
        QVERIFY(kontur::test::settled(m_window));
    }

    // Chooses entry `index` of the side box by mouse: the box, then the entry in its list.
    void chooseSide(int index)
    {
        QQuickItem *box = item(QStringLiteral("seamSide"));
        QVERIFY(box);
        QVERIFY(kontur::test::clickInView(m_window, box));
        auto *popup = box->property("popup").value<QObject *>();
        QVERIFY(popup);
        QTRY_VERIFY(popup->property("opened").toBool());
        auto *list = popup->property("contentItem").value<QQuickItem *>();
        QQuickItem *entry = nullptr;
        QVERIFY(QMetaObject::invokeMethod(list, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, entry), Q_ARG(int, index)));
        QVERIFY(entry);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(entry));
        QTRY_VERIFY(!popup->property("visible").toBool());
        QCOMPARE(box->property("currentIndex").toInt(), index);
    }

    kontur::SeamAllowance *seamModel() const
    {
        return m_window->findChild<kontur::SeamAllowance *>(QStringLiteral("seamAllowance"));
    }

    // Trace menu → Seam allowance…: the dialog is open.
    void openDialog()
    {
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("traceMenuButton"))));
        QQuickItem *entry = nullptr;
        QTRY_VERIFY((entry = item(QStringLiteral("traceSeamAllowance"))) && entry->isVisible() && entry->width() > 0);
        QVERIFY(entry->isEnabled());
        QVERIFY(kontur::test::clickMenuItem(m_window, entry));
        QTRY_VERIFY(item(QStringLiteral("seamAdd")) && item(QStringLiteral("seamAdd"))->isVisible());
        QTRY_VERIFY(item(QStringLiteral("seamDistance"))->width() > 0);
    }

    bool dialogShown() const
    {
        return m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"))->property("visible").toBool();
    }

    void typeWidth(const QString &text)
    {
        QQuickItem *field = item(QStringLiteral("seamDistance"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(field));
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keySequence(m_window, QKeySequence::SelectAll);
        for (const QChar c : text)
            QTest::keyClick(m_window, c.toLatin1());
        QCOMPARE(field->property("text").toString(), text);
    }

    void tap(QQuickItem *it)
    {
        QTest::touchEvent(m_window, m_touch).press(0, centerOf(it));
        QTest::touchEvent(m_window, m_touch).release(0, centerOf(it));
    }

    // The largest |distance(allowance point, source) − d|.
    double worstError(double d) const
    {
        const auto a = m_editor->document()->curve(1).toPiecewise();
        const auto s = m_editor->document()->curve(0).toPiecewise();
        double worst = 0.0;
        for (int i = 0; i < a.segmentCount(); ++i)
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, std::abs(s.nearest(a.segments()[i].eval((k + 0.5) / 4)).distance - d));
        return worst;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(start(QSize(1280, 800))); }
    void cleanup()
    {
        if (!m_engine)
            return; // the window was closed by the test
        if (QQuickItem *close = item(QStringLiteral("seamClose")); close && close->isVisible())
            QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(close));
        QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }

    void addByTouchThenUndo()
    {
        pieceSelected();
        openDialog();
        QCOMPARE(item(QStringLiteral("seamDistance"))->property("text").toString(), QStringLiteral("10"));
        typeWidth(QStringLiteral("12"));
        tap(item(QStringLiteral("seamAdd")));
        QTRY_COMPARE(m_editor->document()->curveCount(), 2);
        QVERIFY(m_editor->document()->curve(1).seam);
        QCOMPARE(m_editor->document()->curve(1).seam->options.distance, 12.0);
        QVERIFY(worstError(12.0) <= 0.05);
        QCOMPARE(m_editor->undoStack()->count(), 1);
        // Add is a finished step: the dialog leaves and the message line says what was added.
        QTRY_VERIFY(!dialogShown());
        QCOMPARE(m_editor->message().id, kontur::Message::SeamAllowanceAdded);
        QVERIFY2(m_editor->message().text().contains(QStringLiteral("12.00 mm")),
                 qPrintable(m_editor->message().text()));
        // The allowance is selected: the dialog, opened again, applies its settings.
        openDialog();
        QTRY_COMPARE(item(QStringLiteral("seamAdd"))->property("text").toString(), QStringLiteral("Apply"));
        screenshot(QStringLiteral("seam-allowance-touch.png"));
        m_editor->undo();
        QCOMPARE(m_editor->document()->curveCount(), 1);
    }

    void addByMouseChangeAndUndo()
    {
        pieceSelected();
        openDialog();
        typeWidth(QStringLiteral("8"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("seamAdd"))));
        QTRY_COMPARE(m_editor->document()->curveCount(), 2);
        QVERIFY(worstError(8.0) <= 0.05);
        const Curve created = m_editor->document()->curve(1);
        // Change it to 15 mm (the dialog opened again on the selected allowance; Apply keeps it open):
        // one more undo step; undo gives the 8 mm allowance back exactly.
        QTRY_VERIFY(!dialogShown());
        openDialog();
        typeWidth(QStringLiteral("15"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("seamAdd"))));
        QTRY_COMPARE(m_editor->document()->curve(1).seam->options.distance, 15.0);
        QCOMPARE(m_editor->undoStack()->count(), 2);
        QVERIFY(worstError(15.0) <= 0.05);
        screenshot(QStringLiteral("seam-allowance-mouse.png"));
        m_editor->undo();
        QVERIFY(m_editor->document()->curve(1).sameState(created));
        m_editor->undo();
        QCOMPARE(m_editor->document()->curveCount(), 1);
    }

    // The long allowance: Add returns at once and the window keeps turning its event loop (a timer
    // of this test ticks, the progress bar moves) until Cancel, which leaves everything as it was.
    void longAllowanceCancelled()
    {
        wavySelected(20'000);
        kontur::SeamAllowance *seam = seamModel();
        QVERIFY(seam);
        openDialog();
        typeWidth(QStringLiteral("40"));
        chooseSide(1); // Inside
        const Curve before = m_editor->document()->curve(0);
        const int steps = m_editor->undoStack()->count();
        int ticks = 0;
        QTimer tick;
        tick.setInterval(20);
        connect(&tick, &QTimer::timeout, this, [&ticks] { ++ticks; });
        // What the dialog shows the moment the job starts (not what it shows when this test gets to
        // look, which depends on how long the click took): no progress and no Cancel yet.
        bool shownAtStart = true;
        QObject watching; // the connection ends with this test
        connect(seam, &kontur::SeamAllowance::busyChanged, &watching, [&] {
            if (seam->busy())
                shownAtStart = seam->progressShown();
        });
        QElapsedTimer since;
        since.start();
        QVERIFY(kontur::test::clickInView(m_window, item(QStringLiteral("seamAdd"))));
        tick.start();
        QVERIFY(seam->busy());
        QVERIFY(!item(QStringLiteral("seamAdd"))->isEnabled());
        QVERIFY(!shownAtStart); // not before it has run a moment
        QQuickItem *cancel = item(QStringLiteral("seamCancel"));
        QVERIFY(cancel);
        QTRY_VERIFY_WITH_TIMEOUT(cancel->isVisible() && cancel->width() > 0, 30'000);
        QQuickItem *bar = item(QStringLiteral("seamProgress"));
        QVERIFY(bar && bar->isVisible());
        // Under way, the bar showing it, the test's timer ticking meanwhile (the event loop turns: a
        // frame of this 20,000-knot document takes ~80 ms on the software backend, and ticks come
        // between frames). Cancel is pressed as soon as that is seen, well before the job's end.
        QTRY_VERIFY_WITH_TIMEOUT(bar->property("value").toDouble() > 0 && ticks >= 3, 30'000);
        QVERIFY2(seam->busy(), "the long allowance finished before it could be cancelled");
        qInfo("%d ticks of 20 ms in the first %lld ms of the allowance", ticks, since.elapsed());
        screenshot(QStringLiteral("seam-allowance-progress.png"));
        // The dialog stays open while it runs.
        QVERIFY(!item(QStringLiteral("seamClose"))->isEnabled());
        QTest::keyClick(m_window, Qt::Key_Escape);
        QVERIFY(m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"))->property("visible").toBool());
        QElapsedTimer clock;
        clock.start();
        QVERIFY(kontur::test::clickInView(m_window, cancel));
        QTRY_VERIFY(!seam->busy());
        qInfo("Cancel at %.0f %% took effect in %lld ms", 100 * bar->property("value").toDouble(), clock.elapsed());
        QCOMPARE(m_editor->document()->curveCount(), 1);
        QVERIFY(m_editor->document()->curve(0).sameState(before));
        QCOMPARE(m_editor->undoStack()->count(), steps);
        QCOMPARE(m_editor->message().id, kontur::Message::SeamAllowanceCancelled);
        QTRY_VERIFY(!cancel->isVisible());
        QVERIFY(item(QStringLiteral("seamAdd"))->isEnabled());
        QCOMPARE(item(QStringLiteral("seamAdd"))->property("text").toString(), QStringLiteral("Add"));
    }

    // A shorter long one let finish: one undo step, which takes it away again.
    void longAllowanceFinished()
    {
        wavySelected(4'000);
        kontur::SeamAllowance *seam = seamModel();
        openDialog();
        typeWidth(QStringLiteral("40"));
        chooseSide(1);
        const int steps = m_editor->undoStack()->count();
        int ticks = 0;
        QTimer tick;
        tick.setInterval(20);
        connect(&tick, &QTimer::timeout, this, [&ticks] { ++ticks; });
        QElapsedTimer clock;
        clock.start();
        QVERIFY(kontur::test::clickInView(m_window, item(QStringLiteral("seamAdd"))));
        tick.start();
        QVERIFY(seam->busy());
        QTRY_VERIFY_WITH_TIMEOUT(!seam->busy(), 60'000);
        qInfo("a 4,000-knot inside allowance in the window: %lld ms, %d ticks of 20 ms meanwhile", clock.elapsed(),
              ticks);
        QCOMPARE(m_editor->document()->curveCount(), 2);
        QVERIFY(m_editor->document()->curve(1).seam);
        QCOMPARE(m_editor->undoStack()->count(), steps + 1);
        QTRY_VERIFY(!dialogShown());
        m_editor->undo();
        QCOMPARE(m_editor->document()->curveCount(), 1);
        QCOMPARE(m_editor->undoStack()->count(), steps + 1);
        QCOMPARE(m_editor->undoStack()->index(), steps);
    }

    // Dragging a knot of a piece with its allowance (issue #45), by mouse and by touch: no offset is
    // computed on the GUI thread during the drag (it follows on the document's worker); after the
    // release the allowance becomes exactly the offset of the moved piece, and undo brings back both
    // at once, again without an offset here.
    void dragPieceWithAllowance()
    {
        for (const bool mouse : {true, false}) {
            pieceSelected(true);
            const kontur::Document &document = *m_editor->document();
            const Curve piece0 = document.curve(0), allowance0 = document.curve(1);
            const Point knot = piece0.definingPoint(3 * 2); // (110, 80)
            const QPoint at = m_canvas->mapToScene(m_canvas->toScreen(QPointF(knot.x(), knot.y()))).toPoint();
            kontur::geo::detail::resetOffsetWork();
            drag(at, QPoint(40, -30), mouse);
            QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
            QTRY_VERIFY(document.allowancesSettled());
            QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
            QCOMPARE(m_editor->undoStack()->count(), 1);
            const Curve piece1 = document.curve(0), allowance1 = document.curve(1);
            QVERIFY(!piece1.sameState(piece0));
            QVERIFY((piece1.definingPoint(3 * 2) - knot).norm() > 5.0);
            QVERIFY(!allowance1.sameState(allowance0));
            QVERIFY(allowance1.isClosed());
            QVERIFY(worstError(10.0) <= 0.05);
            const auto fresh = Curve::makeOffset(piece1, kontur::allowanceOptions(piece1, allowance1.seam->options));
            QVERIFY(fresh.ok());
            QVERIFY(fresh->composite().controlPoints() == allowance1.composite().controlPoints());
            if (!mouse)
                screenshot(QStringLiteral("seam-allowance-dragged.png"));
            kontur::geo::detail::resetOffsetWork();
            m_editor->undo();
            QVERIFY(document.curve(0).sameState(piece0));
            QVERIFY(document.curve(1).sameState(allowance0));
            QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        }
    }

    // Quitting mid-job: the window and its engine go while a long allowance runs; the controller
    // cancels its worker and joins it (no crash, no thread left behind: tst_seamallowance counts them).
    void quitWhileRunning()
    {
        wavySelected(20'000);
        QPointer<kontur::SeamAllowance> seam = seamModel();
        openDialog();
        typeWidth(QStringLiteral("45"));
        chooseSide(1);
        QVERIFY(kontur::test::clickInView(m_window, item(QStringLiteral("seamAdd"))));
        QVERIFY(seam->busy());
        QTRY_VERIFY_WITH_TIMEOUT(seam->progress() > 0 || !seam->busy(), 30'000); // its first progress report
        QVERIFY(seam->busy());
        QElapsedTimer clock;
        clock.start();
        m_engine.reset();
        qInfo("window closed mid-job in %lld ms", clock.elapsed());
        QVERIFY(seam.isNull());
        m_window = nullptr;
        QCoreApplication::processEvents();
    }

    void cleanupTestCase() { m_engine.reset(); }
};

QTEST_MAIN(TestSeamWindow)
#include "tst_seam_window.moc"
