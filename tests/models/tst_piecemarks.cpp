// A garment piece's marks (PieceMarkEdits, io/piece.h): making a closed curve a piece, its size,
// quantity and material, grainline, fold, notches slid along the seam and drill holes. Every edit is
// one undo step that restores the marks exactly; a drag is one step; saving and opening keeps them.
#include "../straightpiece.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/piecemarks.h"
#include "models/document/commands.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using kontur::Curve;
using kontur::CurveId;
using kontur::CurveKind;
using kontur::EditController;
using kontur::PieceMarkEdits;
using kontur::geo::Point;
namespace io = kontur::io;

namespace {

// A 200 × 400 rectangle, counter-clockwise from the origin, as a closed composite curve of straight
// sides (handles at thirds, corners).
Curve rectangle()
{
    return kontur::test::straightOutline({Point(0, 0), Point(200, 0), Point(200, 400), Point(0, 400)},
                                         QStringLiteral("Front"))
        .value();
}

} // namespace

class TestPieceMarks final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyEditIsOneUndoStep();
    void notchSlidesAlongTheSeam();
    void refusalsChangeNothing();
    void deleteTheMarkUnderTheFinger();
    void savedAndOpenedAgain();
};

void TestPieceMarks::everyEditIsOneUndoStep()
{
    EditController editor;
    PieceMarkEdits marks;
    marks.setEditor(&editor);
    const CurveId id = editor.commands()->appendCurve(rectangle());
    editor.selection()->select(id, -1);
    QVERIFY(editor.document()->find(id)->isClosed());
    QVERIFY(marks.canBePiece());
    QVERIFY(!marks.isPiece());
    QSignalSpy state(&marks, &PieceMarkEdits::stateChanged);

    std::vector<std::optional<io::PieceMarks>> history{std::nullopt};
    const auto record = [&] { history.push_back(editor.document()->find(id)->piece); };
    QVERIFY(marks.makePiece());
    record();
    QVERIFY(marks.isPiece());
    QVERIFY(!state.isEmpty());
    QCOMPARE(marks.quantity(), 1);
    QVERIFY(marks.setSize(QStringLiteral(" 38 ")));
    record();
    QCOMPARE(marks.size(), QStringLiteral("38"));
    QVERIFY(marks.setQuantityText(QStringLiteral("2")));
    record();
    QVERIFY(marks.setMaterial(QStringLiteral("wool")));
    record();
    QVERIFY(marks.setGrainline(100, 50, 100, 350));
    record();
    QVERIFY(marks.foldAlongSeam(-3, 210)); // the left side, from (0, 400) to (0, 0)
    record();
    QCOMPARE(marks.addNotch(203, 100, 1), 0); // on the right side: 200 + 100 along
    record();
    QCOMPARE(marks.addDrillHole(50, 200), 0);
    record();

    const io::PieceMarks m = *editor.document()->find(id)->piece;
    QCOMPARE(m.quantity, 2);
    QCOMPARE(m.material, QStringLiteral("wool"));
    QVERIFY(m.grainline == (io::Segment{Point(100, 50), Point(100, 350)}));
    QVERIFY(m.fold.has_value());
    QVERIFY((m.fold->a - Point(0, 400)).norm() < 1e-12 && (m.fold->b - Point(0, 0)).norm() < 1e-12);
    QCOMPARE(m.notches.size(), std::size_t(1));
    QVERIFY(std::abs(m.notches[0].position - 300) < 1e-9);
    QCOMPARE(m.notches[0].kind, io::NotchKind::V);
    QCOMPARE(m.drillHoles.size(), std::size_t(1));

    // Back one step at a time to no piece, and forward again: each state exactly.
    for (std::size_t i = history.size() - 1; i > 0; --i) {
        QVERIFY(editor.document()->find(id)->piece == history[i]);
        editor.undo();
    }
    QVERIFY(!editor.document()->find(id)->piece.has_value());
    for (std::size_t i = 1; i < history.size(); ++i) {
        editor.redo();
        QVERIFY(editor.document()->find(id)->piece == history[i]);
    }
    QVERIFY(marks.removePiece());
    QVERIFY(!marks.isPiece());
    editor.undo();
    QVERIFY(editor.document()->find(id)->piece == history.back());
}

// A notch dragged along the seam in many steps is one undo step and stays on the seam: the finger
// beside the seam puts it at the nearest point (arc length measured along the sides).
void TestPieceMarks::notchSlidesAlongTheSeam()
{
    EditController editor;
    PieceMarkEdits marks;
    marks.setEditor(&editor);
    const CurveId id = editor.commands()->appendCurve(rectangle());
    editor.selection()->select(id, -1);
    QVERIFY(marks.makePiece());
    QCOMPARE(marks.addNotch(50, -2), 0);
    const int steps = editor.undoStack()->count();
    const int drag = marks.beginDrag();
    for (int i = 1; i <= 20; ++i)
        QVERIFY(marks.moveNotch(0, 50 + 7.5 * i, -4, drag)); // 4 below the bottom side, outside
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    QVERIFY(std::abs(editor.document()->find(id)->piece->notches[0].position - 200) < 1e-9); // at the corner
    QVERIFY(marks.moveNotch(0, 230, 300, marks.beginDrag()));
    QVERIFY(std::abs(editor.document()->find(id)->piece->notches[0].position - 500) < 1e-9);
    editor.undo();
    editor.undo();
    QVERIFY(std::abs(editor.document()->find(id)->piece->notches[0].position - 50) < 1e-9);
    QVERIFY(marks.setNotchAngle(0, 30));
    QCOMPARE(editor.document()->find(id)->piece->notches[0].angle, 30.0);
    QVERIFY(!marks.setNotchAngle(0, 95)); // a notch runs into the piece
    QVERIFY(marks.setNotchKind(0, 2));
    QCOMPARE(editor.document()->find(id)->piece->notches[0].kind, io::NotchKind::Castle);
}

// What is refused says why and leaves the document as it was.
void TestPieceMarks::refusalsChangeNothing()
{
    EditController editor;
    PieceMarkEdits marks;
    marks.setEditor(&editor);
    const CurveId open = editor.commands()->appendCurve(
        Curve::make(CurveKind::Bezier, {Point(0, 0), Point(1, 1), Point(2, 0), Point(3, 1)}));
    editor.selection()->select(open, -1);
    QVERIFY(!marks.canBePiece());
    QVERIFY(!marks.makePiece());
    QVERIFY(!marks.message().isEmpty());
    QVERIFY(!marks.setSize(QStringLiteral("38")));
    const CurveId id = editor.commands()->appendCurve(rectangle());
    editor.selection()->select(id, -1);
    QVERIFY(marks.makePiece());
    const int steps = editor.undoStack()->count();
    QVERIFY(!marks.setQuantityText(QStringLiteral("0")));
    QVERIFY(!marks.setQuantityText(QStringLiteral("2.5")));
    QVERIFY(!marks.setQuantity(-1));
    QVERIFY(!marks.setGrainline(10, 10, 10, 10));
    QVERIFY(!marks.setGrainline(10, 10, 10, 12, 5.0)); // shorter than the touch radius
    QCOMPARE(editor.undoStack()->count(), steps);
    QCOMPARE(editor.document()->find(id)->piece->quantity, 1);
    QVERIFY(!editor.document()->find(id)->piece->grainline);
}

// The mark nearest the finger within the radius goes, one undo step each; nothing near: a message.
void TestPieceMarks::deleteTheMarkUnderTheFinger()
{
    EditController editor;
    PieceMarkEdits marks;
    marks.setEditor(&editor);
    const CurveId id = editor.commands()->appendCurve(rectangle());
    editor.selection()->select(id, -1);
    QVERIFY(marks.makePiece());
    QVERIFY(marks.setGrainline(100, 50, 100, 350));
    marks.addNotch(100, 0);
    marks.addDrillHole(100, 200); // on the grainline: the hole is nearer than the line
    QCOMPARE(marks.markTypeAt(101, 200, 5), static_cast<int>(PieceMarkEdits::Mark::DrillHole));
    QVERIFY(marks.deleteMarkAt(101, 200, 5));
    QCOMPARE(marks.drillHoleCount(), 0);
    QVERIFY(marks.hasGrainline());
    QCOMPARE(marks.markTypeAt(101, 200, 5), static_cast<int>(PieceMarkEdits::Mark::Grainline));
    QVERIFY(marks.deleteMarkAt(98, 1, 5));
    QCOMPARE(marks.notchCount(), 0);
    QVERIFY(!marks.deleteMarkAt(150, 300, 5));
    QVERIFY(!marks.message().isEmpty());
    editor.undo();
    editor.undo();
    QCOMPARE(marks.notchCount(), 1);
    QCOMPARE(marks.drillHoleCount(), 1);
}

// Saved as .kontur (version 3) and opened again: the same marks, bit for bit.
void TestPieceMarks::savedAndOpenedAgain()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    EditController editor;
    kontur::DocumentFiles files;
    files.setEditor(&editor);
    PieceMarkEdits marks;
    marks.setEditor(&editor);
    const CurveId id = editor.commands()->appendCurve(rectangle());
    editor.selection()->select(id, -1);
    QVERIFY(marks.makePiece());
    QVERIFY(marks.setSize(QStringLiteral("M")));
    QVERIFY(marks.setGrainline(100.1, 50.3, 100.2, 350.7));
    marks.addNotch(200, 1.0 / 3.0, 2);
    marks.addDrillHole(1.0 / 7.0, 200);
    const io::PieceMarks saved = *editor.document()->find(id)->piece;
    const QUrl file = QUrl::fromLocalFile(dir.filePath(QStringLiteral("piece.kontur")));
    QVERIFY(files.saveAs(file));
    QFile f(file.toLocalFile());
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll().contains("\"version\": 3"));
    files.newDocument();
    QCOMPARE(editor.document()->curveCount(), 0);
    QVERIFY(files.open(file));
    QCOMPARE(editor.document()->curveCount(), 1);
    QVERIFY(editor.document()->curve(0).piece == saved);
}

QTEST_MAIN(TestPieceMarks)
#include "tst_piecemarks.moc"
