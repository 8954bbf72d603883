// A piece's seam allowance while a knot of the piece is dragged (issue #45): the GUI thread computes
// no offset during the drag (the allowance follows on the Document's worker thread), the allowance
// is exactly the offset of the final piece once its last job has landed, undo and redo bring both
// back exactly without an offset on this thread, and edits outside a drag stay exact at once.
// Drags go through EditController::beginDrag / dragTo / endDrag, the canvas's path. Arrow-key nudges
// (CurveCommands::nudgeSelected) and seam width steps (SeamWidths::stepWidth) follow on the worker
// too, one undo step each, their undo and redo as well.
#include "../wavypiece.h"
#include "io/seam.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/seamwidths.h"
#include "models/document/document.h"
#include "models/document/selection.h"

#include <QDir>

#include <QtTest>

#include <cmath>
#include <memory>
#include <numbers>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;

namespace {

// The piece with its linked 10 mm allowance (and, with `chain`, an allowance of that allowance), as
// a file brings them: the document computes the allowances when it resolves their links.
void open(EditController &editor, int knots, bool chain = false)
{
    Curve outline = kontur::test::wavyPiece(knots);
    outline.piece = kontur::io::PieceMarks{}; // a garment piece: its seams may have widths of their own
    const kontur::geo::OffsetOptions options = kontur::io::defaultSeamOptions(QStringLiteral("mm"));
    Curve allowance = *Curve::makeOffset(outline, options);
    allowance.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
    std::vector<Curve> curves{outline, allowance};
    if (chain) {
        Curve second = allowance;
        second.seam = kontur::SeamLink{kontur::CurveId::None, options, 1};
        curves.push_back(second);
    }
    editor.replaceDocument(std::move(curves), {}, QStringLiteral("mm"), false);
}

// Whether `allowance` is exactly (bit for bit) what the synchronous computation gives for `source`
// as it is now: a fresh offset of it (computed here, on this thread).
bool exactFor(const Curve &allowance, const Curve &source)
{
    const auto fresh = Curve::makeOffset(source, kontur::allowanceOptions(source, allowance.seam->options));
    return fresh.ok() && fresh->composite().isClosed() == allowance.composite().isClosed() &&
           fresh->composite().controlPoints() == allowance.composite().controlPoints();
}

// Drags knot `knot` of curve 0 by `steps` steps of (0.5, 0.25) mm, as the canvas sends them.
void drag(EditController &editor, int knot, int steps)
{
    const Point start = editor.document()->curve(0).definingPoint(3 * knot);
    QVERIFY(editor.beginDrag(QPointF(start.x(), start.y()), 1e-6));
    QVERIFY(editor.isDragging());
    for (int s = 1; s <= steps; ++s)
        editor.dragTo(QPointF(start.x() + 0.5 * s, start.y() + 0.25 * s));
}

// Once undo has given a state whose allowance was never made (the edits coalesced): it is made on the
// worker, with no offset on this thread, and exact. Then redo: remembered, exact at once, `redone`.
void settlesThenRedoes(EditController &editor, const Curve &redone)
{
    kontur::Document &document = *editor.document();
    QVERIFY(!document.allowancesSettled());
    QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
    QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
    QVERIFY(exactFor(document.curve(1), document.curve(0)));
    kontur::geo::detail::resetOffsetWork();
    editor.redo();
    QVERIFY(document.allowancesSettled());
    QVERIFY(document.curve(1).sameState(redone));
    QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
}

// The threads of this process (Linux).
int threadCount()
{
    return static_cast<int>(
        QDir(QStringLiteral("/proc/self/task")).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size());
}

} // namespace

class TestAllowanceDrag : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The drag computes no offset on this thread, ends with the exact allowance of the final piece,
    // and undo and redo bring back both exactly, still without an offset here (remembered ones).
    void dragEndsExact()
    {
        EditController editor;
        open(editor, 600);
        const kontur::Document &document = *editor.document();
        QVERIFY(document.allowancesSettled());
        const Curve piece0 = document.curve(0), allowance0 = document.curve(1);
        QVERIFY(exactFor(allowance0, piece0));
        kontur::geo::detail::resetOffsetWork();

        drag(editor, 150, 30);
        // The first step left the allowance stale and its worker running; nothing landed yet, as
        // a result lands only through this thread's event loop.
        QVERIFY(!document.allowancesSettled());
        QVERIFY(document.curve(1).sameState(allowance0));
        QVERIFY(!document.curve(0).sameState(piece0));
        // The finger rests: the worker catches up with it (results of states the drag passed may
        // land first), still during the drag.
        QTRY_VERIFY(document.allowancesSettled());
        QVERIFY(editor.isDragging());
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
        kontur::geo::detail::resetOffsetWork(); // exactFor's own offset
        const Point at = document.curve(0).definingPoint(450);
        for (int s = 1; s <= 20; ++s)
            editor.dragTo(QPointF(at.x() + 0.1 * s, at.y() - 0.2 * s));
        editor.endDrag();
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0}); // none on this thread
        QTRY_VERIFY(document.allowancesSettled());
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        const Curve piece1 = document.curve(0), allowance1 = document.curve(1);
        QVERIFY(!piece1.sameState(piece0));
        // The memo's pre-filter tells the states apart, and finds the old one again below.
        QVERIFY(piece1.geometryHash() != piece0.geometryHash());
        QVERIFY(exactFor(allowance1, piece1));
        QVERIFY(!allowance1.sameState(allowance0));
        QCOMPARE(editor.undoStack()->count(), 1); // the whole drag

        kontur::geo::detail::resetOffsetWork();
        editor.undo();
        // Exact at once: the allowance before the drags was remembered, not computed again.
        QVERIFY(document.allowancesSettled());
        QVERIFY(document.curve(0).sameState(piece0));
        QCOMPARE(document.curve(0).geometryHash(), piece0.geometryHash());
        QVERIFY(document.curve(1).sameState(allowance0));
        editor.redo();
        QVERIFY(document.allowancesSettled());
        QVERIFY(document.curve(0).sameState(piece1));
        QVERIFY(document.curve(1).sameState(allowance1));
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
    }

    // Released before the worker has caught up (a long piece): stale until the final state's job
    // lands, exact after; an undo right after the release is exact at once, and the job still
    // running then is dropped when it ends, whichever state it was of.
    void releaseBeforeTheWorker()
    {
        EditController editor;
        open(editor, 4'000);
        const kontur::Document &document = *editor.document();
        const Curve piece0 = document.curve(0), allowance0 = document.curve(1);

        drag(editor, 1000, 12);
        editor.endDrag();
        QVERIFY(!document.allowancesSettled());
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QVERIFY(exactFor(document.curve(1), document.curve(0)));

        const Curve piece1 = document.curve(0), allowance1 = document.curve(1);
        drag(editor, 2000, 12);
        editor.endDrag();
        QVERIFY(!document.allowancesSettled());
        editor.undo();
        QVERIFY(document.curve(0).sameState(piece1));
        QVERIFY(document.curve(1).sameState(allowance1)); // exact at once
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QVERIFY(document.curve(1).sameState(allowance1)); // the dropped job landed nothing
        editor.undo();
        QVERIFY(document.curve(0).sameState(piece0));
        QVERIFY(document.curve(1).sameState(allowance0));
    }

    // Edits outside a drag (a typed coordinate) keep the allowance exact at once, as before.
    void typedEditExactAtOnce()
    {
        EditController editor;
        open(editor, 300);
        const kontur::Document &document = *editor.document();
        QVERIFY(editor.commands()->applyEdits(
            static_cast<int>(document.idAt(0)),
            {QVariantMap{{QStringLiteral("row"), 0}, {QStringLiteral("x"), QStringLiteral("260")}}}));
        QVERIFY(document.allowancesSettled());
        QCOMPARE(document.curve(0).definingPoint(0).x(), 260.0);
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
    }

    // What is written is exact: settleAllowances() right after a release makes it so at once.
    void settleAfterRelease()
    {
        EditController editor;
        open(editor, 2'000);
        kontur::Document &document = *editor.document();
        drag(editor, 500, 10);
        editor.endDrag();
        document.settleAllowances();
        QVERIFY(document.allowancesSettled());
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
    }

    // An allowance of an allowance follows too, after the allowance it is made from.
    void chainFollows()
    {
        EditController editor;
        open(editor, 400, true);
        const kontur::Document &document = *editor.document();
        QCOMPARE(document.curveCount(), 3);
        QVERIFY(exactFor(document.curve(2), document.curve(1)));
        const Curve piece0 = document.curve(0), first0 = document.curve(1), second0 = document.curve(2);
        kontur::geo::detail::resetOffsetWork();
        drag(editor, 14, 15); // on a bulge, outwards: both allowances change there
        editor.endDrag();
        QVERIFY(!document.curve(0).sameState(piece0));
        QTRY_VERIFY(document.allowancesSettled());
        QVERIFY(!document.curve(1).sameState(first0));
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
        QVERIFY(exactFor(document.curve(2), document.curve(1)));
        QVERIFY(!document.curve(2).sameState(second0));
        editor.undo();
        QVERIFY(document.curve(2).sameState(second0));

        // Settled at once for writing: the first allowance, then the one made from it.
        drag(editor, 14, 10);
        editor.endDrag();
        editor.document()->settleAllowances();
        QVERIFY(document.allowancesSettled());
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
        QVERIFY(exactFor(document.curve(2), document.curve(1)));
    }

    // Arrow-key nudges of a knot (a held key): no offset on this thread, one undo step each, the
    // steps coalesce on the worker, and the allowance is exact once settled; undo and redo too.
    void nudgesFollowOnTheWorker()
    {
        EditController editor;
        open(editor, 2'000);
        const kontur::Document &document = *editor.document();
        const Curve piece0 = document.curve(0), allowance0 = document.curve(1);
        const int knot = 3 * 500;
        editor.selection()->select(document.idAt(0), knot);
        const int start = editor.undoStack()->count();
        kontur::geo::detail::resetOffsetWork();
        for (int i = 0; i < 12; ++i)
            QVERIFY(editor.commands()->nudgeSelected(QPointF(0.5, i % 3 == 0 ? -0.25 : 0.25)));
        QCOMPARE(editor.undoStack()->count(), start + 12);
        QVERIFY((document.curve(0).definingPoint(knot) - piece0.definingPoint(knot) - Point(6.0, 1.0)).norm() <= 1e-9);
        // Nothing landed yet (a result lands through this thread's event loop only).
        QVERIFY(!document.allowancesSettled());
        QVERIFY(document.curve(1).sameState(allowance0));
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        const Curve piece1 = document.curve(0), allowance1 = document.curve(1);
        QVERIFY(exactFor(allowance1, piece1));
        QVERIFY(!allowance1.sameState(allowance0));

        // Undo of the last nudge: a state whose allowance was never made (the nudges coalesced).
        kontur::geo::detail::resetOffsetWork();
        editor.undo();
        QVERIFY((document.curve(0).definingPoint(knot) - piece0.definingPoint(knot) - Point(5.5, 0.75)).norm() <= 1e-9);
        settlesThenRedoes(editor, allowance1);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(document.curve(0).sameState(piece1));
        // Undo of every nudge, one at a time: the first state is remembered, exact at once at the end.
        while (editor.undoStack()->index() > start)
            editor.undo();
        QVERIFY(document.curve(0).sameState(piece0));
        QVERIFY(document.curve(1).sameState(allowance0));
        QTRY_VERIFY(document.allowancesSettled()); // the jobs of the states passed, cancelled
        QVERIFY(document.curve(1).sameState(allowance0));
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
    }

    // Steps of a seam's width (− / + tapped fast): as the nudges. And what is written is exact.
    void widthStepsFollowOnTheWorker()
    {
        EditController editor;
        open(editor, 2'000);
        kontur::Document &document = *editor.document();
        const Curve allowance0 = document.curve(1);
        kontur::SeamWidths seams;
        seams.setEditor(&editor);
        editor.selection()->select(document.idAt(0), -1);
        QVERIFY(seams.seamCount() > 0);
        QVERIFY(seams.selectSeam(0));
        QCOMPARE(seams.width().value_or(-1), 10.0);
        const int start = editor.undoStack()->count();
        kontur::geo::detail::resetOffsetWork();
        for (int i = 0; i < 5; ++i)
            QVERIFY(seams.stepWidth(1));
        QVERIFY(seams.stepWidth(-1));
        QCOMPARE(seams.width().value_or(-1), 30.0);
        QCOMPARE(editor.undoStack()->count(), start + 6);
        QVERIFY(!document.allowancesSettled());
        QVERIFY(document.curve(1).sameState(allowance0));
        QTRY_VERIFY_WITH_TIMEOUT(document.allowancesSettled(), 60'000);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QVERIFY(seams.message().isEmpty());
        const Curve allowance1 = document.curve(1);
        QVERIFY(exactFor(allowance1, document.curve(0)));
        QVERIFY(!allowance1.sameState(allowance0));

        // Undo of the last step (35 mm, never made: the steps coalesced), then redo (remembered).
        kontur::geo::detail::resetOffsetWork();
        editor.undo();
        QCOMPARE(seams.width().value_or(-1), 35.0);
        settlesThenRedoes(editor, allowance1);
        if (QTest::currentTestFailed())
            return;

        // Stepped, then written at once: settleAllowances makes it exact first.
        QVERIFY(seams.stepWidth(1));
        QVERIFY(seams.stepWidth(1));
        document.settleAllowances();
        QVERIFY(document.allowancesSettled());
        QCOMPARE(seams.width().value_or(-1), 40.0);
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
        // Back to the start, one step at a time: the first state remembered, exact at once.
        kontur::geo::detail::resetOffsetWork();
        while (editor.undoStack()->index() > start)
            editor.undo();
        QVERIFY(document.curve(1).sameState(allowance0));
        QVERIFY(document.curve(0).piece->seamWidths.empty());
        QTRY_VERIFY(document.allowancesSettled());
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
    }

    // A nudge during a drag (a key pressed while the finger rests) leaves the drag's live edit on:
    // the release ends it, and the allowance is exact after.
    void nudgeDuringADrag()
    {
        EditController editor;
        open(editor, 300);
        const kontur::Document &document = *editor.document();
        drag(editor, 20, 5);
        kontur::geo::detail::resetOffsetWork();
        QVERIFY(editor.commands()->nudgeSelected(QPointF(1.0, 0.0)));
        QVERIFY(editor.isDragging());
        const Point at = document.curve(0).definingPoint(3 * 20);
        editor.dragTo(QPointF(at.x() + 0.5, at.y() + 0.5));
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        editor.endDrag();
        QTRY_VERIFY(document.allowancesSettled());
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QVERIFY(exactFor(document.curve(1), document.curve(0)));
    }

    // The editor (and its document) destroyed mid-drag, the worker busy: cancelled and joined.
    void destroyedWhileFollowing()
    {
        const int threads = threadCount();
        auto editor = std::make_unique<EditController>();
        open(*editor, 8'000);
        drag(*editor, 10, 3);
        QVERIFY(!editor->document()->allowancesSettled());
        QCOMPARE(threadCount(), threads + 1);
        editor.reset();
        // Joined: QThread::wait() returns as the thread's function ends, the kernel task a moment later.
        QTRY_COMPARE(threadCount(), threads);
    }
};

QTEST_GUILESS_MAIN(TestAllowanceDrag)
#include "tst_allowancedrag.moc"
