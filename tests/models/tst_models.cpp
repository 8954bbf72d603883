// The model layer: placing a curve, dragging a point, undo; the item models notify only what changed.
#include "models/curvelistmodel.h"
#include "models/document.h"
#include "models/editcontroller.h"
#include "models/pointlistmodel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

using kontur::EditController;
using kontur::PointListModel;

class TestModels final : public QObject
{
    Q_OBJECT

private:
    // Places a cubic through the controller as four taps would.
    static void placeCurve(EditController &editor, std::array<QPointF, 4> points)
    {
        editor.setMode(EditController::Mode::Place);
        for (const QPointF &p : points)
            editor.tap(p, 1.0);
        editor.setMode(EditController::Mode::Select);
    }

private Q_SLOTS:
    void fourTapsMakeACurve();
    void draggingOnePointNotifiesOnlyThatRow();
    void dragIsOneUndoStep();
    void undoRemovesTheCurveAndKeepsModelsConsistent();
    void hitTestPicksTheNearestPointWithinTheRadius();
    void placementCanBeCancelledAndTakenBack();
    void nonFiniteInputIsIgnored();
};

void TestModels::fourTapsMakeACurve()
{
    EditController editor;
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy inserted(editor.curves(), &QAbstractItemModel::rowsInserted);

    editor.setMode(EditController::Mode::Place);
    editor.tap({0, 0}, 1.0);
    editor.tap({10, 20}, 1.0);
    editor.tap({30, 20}, 1.0);
    QCOMPARE(editor.pendingCount(), 3);
    QCOMPARE(editor.curves()->rowCount(), 0);
    editor.tap({40, 0}, 1.0);

    QCOMPARE(editor.pendingCount(), 0);
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(editor.curves()->rowCount(), 1);
    QCOMPARE(editor.selectedCurve(), 0);
    const QModelIndex row = editor.curves()->index(0);
    QCOMPARE(row.data(kontur::CurveListModel::PointCountRole).toInt(), 4);
    QCOMPARE(row.data(kontur::CurveListModel::SelectedRole).toBool(), true);
    QCOMPARE(editor.points()->rowCount(), 4);
    QCOMPARE(editor.points()->index(3).data(PointListModel::XRole).toDouble(), 40.0);
    QCOMPARE(editor.points()->index(1).data(PointListModel::YRole).toDouble(), 20.0);
    QCOMPARE(editor.points()->index(2).data(PointListModel::LabelRole).toString(), QStringLiteral("C2"));
    QCOMPARE(editor.points()->index(2).data(PointListModel::PointRoleRole).toInt(),
             static_cast<int>(kontur::PointRole::ControlPoint));
    // Still placing: the next taps start the next curve.
    QCOMPARE(editor.mode(), EditController::Mode::Place);
}

void TestModels::draggingOnePointNotifiesOnlyThatRow()
{
    EditController editor;
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 20), QPointF(30, 20), QPointF(40, 0)});
    placeCurve(editor, {QPointF(100, 0), QPointF(110, 20), QPointF(130, 20), QPointF(140, 0)});
    editor.selectCurve(0);
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);

    QSignalSpy changed(editor.points(), &QAbstractItemModel::dataChanged);
    QSignalSpy reset(editor.points(), &QAbstractItemModel::modelReset);
    QSignalSpy curvesReset(editor.curves(), &QAbstractItemModel::modelReset);
    QSignalSpy curvesChanged(editor.curves(), &QAbstractItemModel::dataChanged);

    QVERIFY(editor.beginDrag({10.5, 19.5}, 2.0));
    QCOMPARE(editor.selectedPoint(), 1);
    editor.dragTo({12.5, 24.5});
    editor.dragTo({15.5, 29.5});
    editor.endDrag();

    QCOMPARE(reset.count(), 0);
    QCOMPARE(curvesReset.count(), 0);
    // The curve's row hears of it (its length changed), with the derived roles only.
    QCOMPARE(curvesChanged.count(), 2);
    for (const auto &args : curvesChanged) {
        QCOMPARE(args.at(0).value<QModelIndex>().row(), 0);
        QCOMPARE(args.at(1).value<QModelIndex>().row(), 0);
        QVERIFY(!args.at(2).value<QList<int>>().contains(kontur::CurveListModel::NameRole));
        QVERIFY(args.at(2).value<QList<int>>().contains(kontur::CurveListModel::LengthRole));
    }
    QCOMPARE(changed.count(), 2);
    for (const auto &args : changed) {
        const auto topLeft = args.at(0).value<QModelIndex>();
        const auto bottomRight = args.at(1).value<QModelIndex>();
        QCOMPARE(topLeft.row(), 1);
        QCOMPARE(bottomRight.row(), 1);
        const auto roles = args.at(2).value<QList<int>>();
        QCOMPARE(roles, (QList<int>{PointListModel::XRole, PointListModel::YRole}));
    }
    // The grab offset is kept: the point moved by the pointer's displacement, not to the pointer.
    QCOMPARE(editor.points()->index(1).data(PointListModel::XRole).toDouble(), 15.0);
    QCOMPARE(editor.points()->index(1).data(PointListModel::YRole).toDouble(), 30.0);
    // The other curve is untouched.
    QCOMPARE(editor.document()->curve(1).definingPoint(1), kontur::geo::Point(110, 20));
}

void TestModels::dragIsOneUndoStep()
{
    EditController editor;
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 20), QPointF(30, 20), QPointF(40, 0)});
    const kontur::Curve before = editor.document()->curve(0);
    QVERIFY(editor.beginDrag({30, 20}, 1.0));
    for (int i = 1; i <= 20; ++i)
        editor.dragTo({30.0 + i, 20.0 - i});
    editor.endDrag();
    const kontur::Curve after = editor.document()->curve(0);
    QCOMPARE(after.definingPoint(2), kontur::geo::Point(50, 0));

    editor.undo();
    QVERIFY(editor.document()->curve(0).sameState(before));
    editor.redo();
    QVERIFY(editor.document()->curve(0).sameState(after));

    // A second drag is a second undo step.
    QVERIFY(editor.beginDrag({50, 0}, 1.0));
    editor.dragTo({60, 0});
    editor.endDrag();
    editor.undo();
    QVERIFY(editor.document()->curve(0).sameState(after));
    editor.undo();
    QVERIFY(editor.document()->curve(0).sameState(before));
}

void TestModels::undoRemovesTheCurveAndKeepsModelsConsistent()
{
    EditController editor;
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 20), QPointF(30, 20), QPointF(40, 0)});
    QVERIFY(editor.canUndo());
    QSignalSpy removed(editor.curves(), &QAbstractItemModel::rowsRemoved);
    editor.undo();
    QCOMPARE(removed.count(), 1);
    QCOMPARE(editor.curves()->rowCount(), 0);
    QCOMPARE(editor.points()->rowCount(), 0);
    QCOMPARE(editor.selectedCurve(), -1);
    QVERIFY(!editor.canUndo());
    QVERIFY(editor.canRedo());
    editor.redo();
    QCOMPARE(editor.curves()->rowCount(), 1);
}

void TestModels::hitTestPicksTheNearestPointWithinTheRadius()
{
    EditController editor;
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 0), QPointF(20, 0), QPointF(30, 0)});
    QCOMPARE(editor.hitTest({11, 1}, 5.0), (kontur::PointRef{0, 1}));
    QCOMPARE(editor.hitTest({16, 0}, 5.0), (kontur::PointRef{0, 2}));
    QVERIFY(!editor.hitTest({15, 30}, 5.0).isValid());
    // A tap away from every point in select mode clears the selection.
    editor.tap({15, 30}, 5.0);
    QCOMPARE(editor.selectedCurve(), -1);
    editor.tap({29, 1}, 5.0);
    QCOMPARE(editor.selectedCurve(), 0);
    QCOMPARE(editor.selectedPoint(), 3);
}

void TestModels::placementCanBeCancelledAndTakenBack()
{
    EditController editor;
    editor.setMode(EditController::Mode::Place);
    editor.tap({0, 0}, 1.0);
    editor.tap({1, 1}, 1.0);
    QVERIFY(editor.canUndo());
    editor.undo(); // takes back the last placed point
    QCOMPARE(editor.pendingCount(), 1);
    editor.cancelPlacement();
    QCOMPARE(editor.pendingCount(), 0);
    QVERIFY(!editor.canUndo());
    editor.tap({0, 0}, 1.0);
    editor.setMode(EditController::Mode::Select); // leaving the mode drops unfinished points
    QCOMPARE(editor.pendingCount(), 0);
    QCOMPARE(editor.document()->curveCount(), 0);
}

void TestModels::nonFiniteInputIsIgnored()
{
    EditController editor;
    editor.setMode(EditController::Mode::Place);
    editor.tap({qQNaN(), 0}, 1.0);
    editor.tap({0, qInf()}, 1.0);
    QCOMPARE(editor.pendingCount(), 0);
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 0), QPointF(20, 0), QPointF(30, 0)});
    QVERIFY(editor.beginDrag({0, 0}, 1.0));
    editor.dragTo({qQNaN(), 5});
    editor.endDrag();
    QCOMPARE(editor.document()->curve(0).definingPoint(0), kontur::geo::Point(0, 0));
}

QTEST_GUILESS_MAIN(TestModels)
#include "tst_models.moc"
