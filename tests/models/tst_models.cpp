// The model layer: placing a curve, dragging a point, undo; the item models notify only what changed;
// whatever follows a curve (selection, coordinates table, teaching view) holds it by id.
#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/document/document.h"
#include "models/document/pointindex.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"
#include "models/teaching/teachingcontroller.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

#include <algorithm>
#include <random>

using kontur::CurveKind;
using kontur::EditController;
using kontur::PointListModel;
using kontur::geo::Point;

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
    void pointIndexAgreesWithEveryPointAtEveryRadius();
    void hiddenHandlesCannotBeGrabbed();
    void placementCanBeCancelledAndTakenBack();
    void nonFiniteInputIsIgnored();
    void selectionModelsAndTeachingFollowTheirCurveById();
    void switchingCurvesKeepsTheCommonRows();
    void nodeTypeShownFollowsAChangeMadeByTheModel();
    void rowLayoutOfEachKind();
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
    QCOMPARE(editor.placement()->pendingCount(), 3);
    QCOMPARE(editor.curves()->rowCount(), 0);
    editor.tap({40, 0}, 1.0);

    QCOMPARE(editor.placement()->pendingCount(), 0);
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(editor.curves()->rowCount(), 1);
    QCOMPARE(editor.selection()->curveRow(), 0);
    const QModelIndex row = editor.curves()->index(0);
    QCOMPARE(row.data(kontur::CurveListModel::PointCountRole).toInt(), 4);
    QCOMPARE(row.data(kontur::CurveListModel::SelectedRole).toBool(), true);
    QCOMPARE(editor.points()->rowCount(), 4);
    QCOMPARE(editor.points()->index(3).data(PointListModel::XRole).toDouble(), 40.0);
    QCOMPARE(editor.points()->index(1).data(PointListModel::YRole).toDouble(), 20.0);
    QCOMPARE(editor.points()->index(2).data(PointListModel::LabelRole).toString(), QStringLiteral("C2"));
    QCOMPARE(editor.points()->index(2).data(PointListModel::PointRoleRole).toInt(),
             static_cast<int>(kontur::PointRole::ControlPoint));
    // The curve is made: the drawing tool is left, with the new curve selected.
    QCOMPARE(editor.mode(), EditController::Mode::Select);
}

void TestModels::draggingOnePointNotifiesOnlyThatRow()
{
    EditController editor;
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 20), QPointF(30, 20), QPointF(40, 0)});
    placeCurve(editor, {QPointF(100, 0), QPointF(110, 20), QPointF(130, 20), QPointF(140, 0)});
    editor.selection()->selectRow(0);
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);

    QSignalSpy changed(editor.points(), &QAbstractItemModel::dataChanged);
    QSignalSpy reset(editor.points(), &QAbstractItemModel::modelReset);
    QSignalSpy curvesReset(editor.curves(), &QAbstractItemModel::modelReset);
    QSignalSpy curvesChanged(editor.curves(), &QAbstractItemModel::dataChanged);

    QVERIFY(editor.beginDrag({10.5, 19.5}, 2.0));
    QCOMPARE(editor.selection()->point(), 1);
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
        // The coordinates and the texts the table shows of them; nothing else of the row.
        QCOMPARE(roles,
                 (QList<int>{PointListModel::XRole, PointListModel::YRole, PointListModel::XTextRole,
                             PointListModel::YTextRole, PointListModel::XExactRole, PointListModel::YExactRole}));
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
    QCOMPARE(editor.selection()->curveRow(), -1);
    QVERIFY(!editor.canUndo());
    QVERIFY(editor.canRedo());
    editor.redo();
    QCOMPARE(editor.curves()->rowCount(), 1);
}

// The hit-test index finds what looking at every point finds (the nearest visible point within the
// radius, ties to the later curve and row), for radii far below the points' spacing (its cells are
// then a few spacings wide, not the radius), about it and far above it, also after points moved.
void TestModels::pointIndexAgreesWithEveryPointAtEveryRadius()
{
    EditController editor;
    const kontur::Document &doc = *editor.document();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> wiggle(-3.0, 3.0);
    for (int c = 0; c < 6; ++c) {
        QVariantList knots;
        for (int k = 0; k <= 30; ++k)
            knots << QVariant(QVariantList{2.0 * k + 7.0 * c, 5.0 * c + wiggle(rng)});
        QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite), knots));
    }
    QVERIFY(editor.commands()->setCurveVisible(static_cast<int>(doc.idAt(2)), false));
    // A point of curve 4 on one of curve 3, for a tie.
    const Point shared = doc.curve(3).row(9).position;
    QVERIFY(editor.commands()->applyEdits(
        static_cast<int>(doc.idAt(4)),
        QVariantList{QVariantMap{{QStringLiteral("row"), 9},
                                 {QStringLiteral("x"), QString::number(shared.x(), 'g', 17)},
                                 {QStringLiteral("y"), QString::number(shared.y(), 'g', 17)}}}));
    QCOMPARE(doc.curve(4).row(9).position, shared);

    const auto everyPoint = [&](const Point &q, double radius) {
        kontur::PointHit best;
        double bestDistance = radius;
        for (int c = 0; c < doc.curveCount(); ++c) {
            if (!doc.curve(c).visible)
                continue;
            for (int r = 0; r < doc.curve(c).rowCount(); ++r) {
                const double d = (doc.curve(c).row(r).position - q).norm();
                if (d <= bestDistance) {
                    bestDistance = d;
                    best = {c, r, d};
                }
            }
        }
        return best;
    };
    kontur::PointIndex index;
    std::uniform_real_distribution<double> x(-5.0, 100.0), y(-8.0, 33.0);
    int found = 0;
    const auto agree = [&](const Point &q, double radius) {
        const kontur::PointHit hit = index.nearest(doc, q, radius);
        const kontur::PointHit expected = everyPoint(q, radius);
        if (expected.isValid())
            ++found;
        return hit.curve == expected.curve && hit.row == expected.row && hit.distance == expected.distance;
    };
    for (const double radius : {1e-9, 1e-3, 0.5, 2.0, 40.0, 1e-9}) {
        for (int k = 0; k < 300; ++k)
            QVERIFY2(agree(Point(x(rng), y(rng)), radius), qPrintable(QString::number(radius)));
        // On every point: found at any radius (the hidden curve's never).
        for (int c = 0; c < doc.curveCount(); ++c)
            for (int r = 0; r < doc.curve(c).rowCount(); ++r)
                QVERIFY2(agree(doc.curve(c).row(r).position, radius), qPrintable(QString::number(radius)));
    }
    QCOMPARE(index.nearest(doc, shared, 1e-9).curve, 4); // the tie goes to the later curve
    QVERIFY(found > 6 * 91);

    // Points moved (as a drag does): the index follows them in place.
    const Point moved = doc.curve(1).row(4).position + Point(25.0, 11.0);
    QVERIFY(editor.commands()->applyEdits(
        static_cast<int>(doc.idAt(1)),
        QVariantList{QVariantMap{{QStringLiteral("row"), 4},
                                 {QStringLiteral("x"), QString::number(moved.x(), 'g', 17)},
                                 {QStringLiteral("y"), QString::number(moved.y(), 'g', 17)}}}));
    index.update(doc, 1, 0, doc.curve(1).rowCount() - 1);
    for (const double radius : {1e-9, 0.5, 40.0}) {
        QVERIFY(agree(moved, radius));
        for (int k = 0; k < 300; ++k)
            QVERIFY(agree(Point(x(rng), y(rng)), radius));
    }
}

void TestModels::hiddenHandlesCannotBeGrabbed()
{
    // A composite curve shows (and lets one grab) only the handles of the selected knot and its
    // neighbours: a tap on a handle of knot 4 first finds nothing there, and after knot 4 (or its
    // neighbour, knot 3) is selected it picks the handle.
    EditController editor;
    QVariantList rows;
    for (int k = 0; k < 8; ++k)
        rows << QVariant(QVariantList{20.0 * k, k % 2 == 0 ? 0.0 : 20.0});
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite), rows));
    const kontur::CurveId id = editor.document()->idAt(0);
    const kontur::Curve &curve = editor.document()->curve(0);
    const int handle = 13; // the out-handle of knot 4 (row 12)
    QCOMPARE(curve.knotOfRow(handle), 4);
    const kontur::geo::Point at = curve.row(handle).position;
    editor.selection()->clear();
    QVERIFY(!editor.hitTest(at, 0.5).isValid());
    editor.selection()->select(id, curve.rowOfKnot(2));
    QVERIFY(!editor.hitTest(at, 0.5).isValid());
    editor.selection()->select(id, curve.rowOfKnot(3));
    QCOMPARE(editor.hitTest(at, 0.5), (kontur::PointRef{id, handle}));
    editor.selection()->select(id, curve.rowOfKnot(4));
    QCOMPARE(editor.hitTest(at, 0.5), (kontur::PointRef{id, handle}));
    // A knot is always there to be grabbed.
    editor.selection()->clear();
    QCOMPARE(editor.hitTest(curve.row(curve.rowOfKnot(6)).position, 0.5), (kontur::PointRef{id, curve.rowOfKnot(6)}));
}

void TestModels::hitTestPicksTheNearestPointWithinTheRadius()
{
    EditController editor;
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 0), QPointF(20, 0), QPointF(30, 0)});
    QCOMPARE(editor.hitTest({11, 1}, 5.0), (kontur::PointRef{editor.document()->idAt(0), 1}));
    QCOMPARE(editor.hitTest({16, 0}, 5.0), (kontur::PointRef{editor.document()->idAt(0), 2}));
    QVERIFY(!editor.hitTest({15, 30}, 5.0).isValid());
    // A tap away from every point in select mode clears the selection.
    editor.tap({15, 30}, 5.0);
    QCOMPARE(editor.selection()->curveRow(), -1);
    editor.tap({29, 1}, 5.0);
    QCOMPARE(editor.selection()->curveRow(), 0);
    QCOMPARE(editor.selection()->point(), 3);
}

void TestModels::placementCanBeCancelledAndTakenBack()
{
    EditController editor;
    editor.setMode(EditController::Mode::Place);
    editor.tap({0, 0}, 1.0);
    editor.tap({1, 1}, 1.0);
    QVERIFY(editor.canUndo());
    editor.undo(); // takes back the last placed point
    QCOMPARE(editor.placement()->pendingCount(), 1);
    editor.placement()->cancel();
    QCOMPARE(editor.placement()->pendingCount(), 0);
    QVERIFY(!editor.canUndo());
    editor.tap({0, 0}, 1.0);
    editor.setMode(EditController::Mode::Select); // leaving the mode drops unfinished points
    QCOMPARE(editor.placement()->pendingCount(), 0);
    QCOMPARE(editor.document()->curveCount(), 0);
}

void TestModels::nonFiniteInputIsIgnored()
{
    EditController editor;
    editor.setMode(EditController::Mode::Place);
    editor.tap({qQNaN(), 0}, 1.0);
    editor.tap({0, qInf()}, 1.0);
    QCOMPARE(editor.placement()->pendingCount(), 0);
    placeCurve(editor, {QPointF(0, 0), QPointF(10, 0), QPointF(20, 0), QPointF(30, 0)});
    QVERIFY(editor.beginDrag({0, 0}, 1.0));
    editor.dragTo({qQNaN(), 5});
    editor.endDrag();
    QCOMPARE(editor.document()->curve(0).definingPoint(0), kontur::geo::Point(0, 0));
}

using kontur::test::rows;

void TestModels::selectionModelsAndTeachingFollowTheirCurveById()
{
    using kontur::CurveId;
    EditController editor;
    kontur::Document &doc = *editor.document();
    kontur::Placement &placement = *editor.placement();
    kontur::CurveCommands &commands = *editor.commands();
    QVERIFY(
        placement.createFromCoordinates(static_cast<int>(CurveKind::Bezier), rows({{0, 0}, {1, 2}, {3, 2}, {4, 0}})));
    QVERIFY(placement.createFromCoordinates(static_cast<int>(CurveKind::Composite),
                                            rows({{10, 0}, {12, 5}, {15, 1}, {18, 4}})));
    QVERIFY(placement.createFromCoordinates(static_cast<int>(CurveKind::Bezier), rows({{20, 0}, {21, 3}, {24, 0}})));
    const CurveId a = doc.idAt(0), b = doc.idAt(1), c = doc.idAt(2);
    QVERIFY(commands.setCurveName(static_cast<int>(a), QStringLiteral("A")));
    QVERIFY(commands.setCurveName(static_cast<int>(b), QStringLiteral("B")));
    QVERIFY(commands.setCurveName(static_cast<int>(c), QStringLiteral("C")));
    const std::vector<Point> pointsOfB = doc.curve(1).definingPoints();
    QCOMPARE(pointsOfB.size(), std::size_t{10}); // 4 knots and 6 handles

    // The teaching view's comb marks the joints of its curve: B's are its knots 1 and 2.
    kontur::TeachingController teaching;
    teaching.setEditor(&editor);
    teaching.setView(kontur::TeachingController::View::Comb);
    teaching.setCombAllCurves(false);
    const auto showsB = [&] {
        return teaching.isApplicable() && teaching.scene().labels.size() == 2 &&
               (teaching.scene().labels[0].at - Point(12, 5)).norm() < 1e-12 &&
               (teaching.scene().labels[1].at - Point(15, 1)).norm() < 1e-12;
    };
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    editor.selection()->select(b, 3); // knot 1 of B
    QCOMPARE(teaching.curve(), static_cast<int>(b));

    QSignalSpy selectionCurve(editor.selection(), &kontur::Selection::curveChanged);
    QSignalSpy selectionPoint(editor.selection(), &kontur::Selection::pointChanged);
    QSignalSpy pointsReset(editor.points(), &QAbstractItemModel::modelReset);
    QSignalSpy pointsCurve(editor.points(), &PointListModel::curveChanged);
    QSignalSpy teachingCurve(&teaching, &kontur::TeachingController::curveChanged);
    // Still B, whatever row it is at now: by name and points, in the selection, the coordinates
    // table and the teaching view, and nobody was told of another curve.
    const auto stillB = [&](int row) {
        QCOMPARE(editor.selection()->curveId(), b);
        QCOMPARE(editor.selection()->curveRow(), row);
        QCOMPARE(doc.indexOf(b), row);
        QCOMPARE(editor.selection()->curve()->name, QStringLiteral("B"));
        QVERIFY(editor.selection()->curve()->definingPoints() == pointsOfB);
        QCOMPARE(editor.selection()->point(), 3);
        QCOMPARE(editor.selection()->knot(), 1);
        QCOMPARE(editor.points()->curve(), b);
        QCOMPARE(editor.points()->rowCount(), 10);
        QCOMPARE(editor.points()->index(3).data(PointListModel::XRole).toDouble(), 12.0);
        QCOMPARE(editor.points()->index(3).data(PointListModel::YRole).toDouble(), 5.0);
        QCOMPARE(editor.curves()->index(row).data(kontur::CurveListModel::SelectedRole).toBool(), true);
        for (int r = 0; r < doc.curveCount(); ++r)
            if (r != row)
                QCOMPARE(editor.curves()->index(r).data(kontur::CurveListModel::SelectedRole).toBool(), false);
        QCOMPARE(teaching.curve(), static_cast<int>(b));
        QVERIFY(showsB());
        QCOMPARE(selectionCurve.count(), 0);
        QCOMPARE(selectionPoint.count(), 0);
        QCOMPARE(pointsReset.count(), 0);
        QCOMPARE(pointsCurve.count(), 0);
        QCOMPARE(teachingCurve.count(), 0);
    };

    // Another curve inserted above B, then undone and redone.
    editor.push(kontur::CurvePresenceCommand::add(&doc, 0, kontur::Curve::make(CurveKind::Bezier, {{-5, 0}, {-4, 1}})));
    QCOMPARE(doc.curveCount(), 4);
    stillB(2);
    editor.undo();
    stillB(1);
    editor.redo();
    stillB(2);
    // Another curve deleted above B.
    QVERIFY(commands.deleteCurve(static_cast<int>(a)));
    stillB(1);
    editor.undo();
    stillB(2);
    editor.redo();
    stillB(1);
    // Another curve moved above B (C from the end to the top), and B itself moved.
    QVERIFY(commands.moveCurve(static_cast<int>(c), 0));
    QCOMPARE(doc.idAt(0), c);
    stillB(2);
    editor.undo();
    stillB(1);
    editor.redo();
    stillB(2);
    QVERIFY(commands.moveCurve(static_cast<int>(b), 0));
    stillB(0);
    editor.undo();
    stillB(2);
    // The list's arrows: one place up or down by id, nothing past the ends.
    QVERIFY(commands.moveCurveBy(static_cast<int>(b), -1));
    stillB(1);
    QVERIFY(commands.moveCurveBy(static_cast<int>(b), 1));
    stillB(2);
    QVERIFY(!commands.moveCurveBy(static_cast<int>(b), 1));
    stillB(2);
    QVERIFY(!commands.moveCurveBy(0, -1));
    editor.undo();
    editor.undo();
    stillB(2);
    // The curve inserted first, deleted and brought back.
    QCOMPARE(doc.curveCount(), 3);
    const CurveId inserted = doc.idAt(1);
    QVERIFY(commands.deleteCurve(static_cast<int>(inserted)));
    stillB(1);
    editor.undo();
    stillB(2);

    // Deleting the selected curve clears the selection and empties the coordinates table; the
    // teaching view keeps B's id but shows nothing.
    QVERIFY(commands.deleteCurve(static_cast<int>(b)));
    QVERIFY(!doc.contains(b));
    QVERIFY(!editor.selection()->hasCurve());
    QCOMPARE(editor.selection()->curveId(), CurveId::None);
    QCOMPARE(editor.selection()->curveRow(), -1);
    QCOMPARE(editor.selection()->point(), -1);
    QCOMPARE(editor.selection()->nodeType(), -1);
    QCOMPARE(selectionCurve.count(), 1);
    QCOMPARE(editor.points()->curve(), CurveId::None);
    QCOMPARE(editor.points()->rowCount(), 0);
    QCOMPARE(teaching.curve(), static_cast<int>(b));
    QVERIFY(!teaching.isApplicable());
    QVERIFY(teaching.scene().labels.empty());
    for (int r = 0; r < doc.curveCount(); ++r)
        QCOMPARE(editor.curves()->index(r).data(kontur::CurveListModel::SelectedRole).toBool(), false);

    // Undoing the delete brings back B with its id at its row, but selects nothing: a selection is
    // the user's choice, never made by undo. The teaching view, which still held B's id, shows B
    // again; the coordinates table follows the selection and stays empty.
    editor.undo();
    QCOMPARE(doc.indexOf(b), 2);
    QCOMPARE(doc.find(b)->name, QStringLiteral("B"));
    QVERIFY(doc.find(b)->definingPoints() == pointsOfB);
    QVERIFY(!editor.selection()->hasCurve());
    QCOMPARE(editor.selection()->curveRow(), -1);
    QCOMPARE(selectionCurve.count(), 1);
    QCOMPARE(editor.points()->curve(), CurveId::None);
    QCOMPARE(editor.points()->rowCount(), 0);
    for (int r = 0; r < doc.curveCount(); ++r)
        QCOMPARE(editor.curves()->index(r).data(kontur::CurveListModel::SelectedRole).toBool(), false);
    QCOMPARE(teaching.curve(), static_cast<int>(b));
    QVERIFY(showsB());
}

// Another curve in the coordinates table: the rows both curves have stay (one dataChanged of every
// role), the rest are removed or inserted at the end, and nothing resets the model (a reset made a
// view create every delegate anew). Its data is then the new curve's, as a model showing only that
// curve has it.
void TestModels::switchingCurvesKeepsTheCommonRows()
{
    using kontur::CurveId;
    EditController editor;
    kontur::Document &doc = *editor.document();
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite),
                                                      rows({{10, 0}, {12, 5}, {15, 1}, {18, 4}})));
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{0, 0}, {1, 2}, {3, 2}, {4, 0}})));
    const CurveId composite = doc.idAt(0), bezier = doc.idAt(1);
    QCOMPARE(doc.curve(0).rowCount(), 10);
    QCOMPARE(doc.curve(1).rowCount(), 4);
    editor.selection()->clear();
    PointListModel *points = editor.points();
    QAbstractItemModelTester tester(points, QAbstractItemModelTester::FailureReportingMode::QtTest);

    QSignalSpy inserted(points, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(points, &QAbstractItemModel::rowsRemoved);
    QSignalSpy changed(points, &QAbstractItemModel::dataChanged);
    QSignalSpy reset(points, &QAbstractItemModel::modelReset);
    QSignalSpy curve(points, &PointListModel::curveChanged);
    const QList<int> every{Qt::DisplayRole,
                           PointListModel::XRole,
                           PointListModel::YRole,
                           PointListModel::PointRoleRole,
                           PointListModel::LabelRole,
                           PointListModel::EditableRole,
                           PointListModel::NodeTypeRole,
                           PointListModel::XTextRole,
                           PointListModel::YTextRole,
                           PointListModel::XExactRole,
                           PointListModel::YExactRole};
    // Every role the model names (and the display role): none is left stale.
    QList<int> named = points->roleNames().keys();
    QList<int> listed(every.begin() + 1, every.end());
    std::sort(named.begin(), named.end());
    std::sort(listed.begin(), listed.end());
    QCOMPARE(named, listed);
    const auto clearSpies = [&] {
        for (QSignalSpy *spy : {&inserted, &removed, &changed, &reset, &curve})
            spy->clear();
    };
    const auto rangeIs = [](const QList<QVariant> &args, int first, int last) {
        return args.at(1).toInt() == first && args.at(2).toInt() == last;
    };
    const auto changedIs = [&](int first, int last) {
        return changed.count() == 1 && changed.at(0).at(0).value<QModelIndex>().row() == first &&
               changed.at(0).at(1).value<QModelIndex>().row() == last &&
               changed.at(0).at(2).value<QList<int>>() == every;
    };
    // Every role of every row as a model that has only ever shown `id` has it.
    const auto showsOnly = [&](CurveId id) {
        PointListModel fresh(&doc);
        fresh.setCurve(id);
        if (points->curve() != id || points->rowCount() != doc.curve(doc.indexOf(id)).rowCount() ||
            points->rowCount() != fresh.rowCount())
            return false;
        for (int r = 0; r < points->rowCount(); ++r) {
            if (points->index(r).data(PointListModel::XRole).toDouble() !=
                doc.curve(doc.indexOf(id)).row(r).position.x())
                return false;
            for (const int role : every)
                if (points->index(r).data(role) != fresh.index(r).data(role))
                    return false;
        }
        return true;
    };

    // None to the composite curve: its ten rows come.
    editor.selection()->selectCurve(static_cast<int>(composite));
    QCOMPARE(inserted.count(), 1);
    QVERIFY(rangeIs(inserted.at(0), 0, 9));
    QCOMPARE(removed.count(), 0);
    QCOMPARE(changed.count(), 0);
    QVERIFY(showsOnly(composite));

    // Ten rows to four: rows 4 to 9 go, rows 0 to 3 are announced anew (knots and handles become
    // control points, the node types go).
    clearSpies();
    editor.selection()->selectCurve(static_cast<int>(bezier));
    QCOMPARE(removed.count(), 1);
    QVERIFY(rangeIs(removed.at(0), 4, 9));
    QCOMPARE(inserted.count(), 0);
    QVERIFY(changedIs(0, 3));
    QCOMPARE(reset.count(), 0);
    QCOMPARE(curve.count(), 1);
    QVERIFY(showsOnly(bezier));
    QCOMPARE(points->index(3).data(PointListModel::LabelRole).toString(), QStringLiteral("C3"));
    QCOMPARE(points->index(0).data(PointListModel::NodeTypeRole).toInt(), -1);

    // Four rows to ten: rows 4 to 9 come, rows 0 to 3 are announced anew.
    clearSpies();
    editor.selection()->selectCurve(static_cast<int>(composite));
    QCOMPARE(inserted.count(), 1);
    QVERIFY(rangeIs(inserted.at(0), 4, 9));
    QCOMPARE(removed.count(), 0);
    QVERIFY(changedIs(0, 3));
    QCOMPARE(reset.count(), 0);
    QCOMPARE(curve.count(), 1);
    QVERIFY(showsOnly(composite));

    // The same number of rows: only dataChanged.
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{5, 5}, {6, 7}, {8, 7}, {9, 5}})));
    editor.selection()->selectCurve(static_cast<int>(bezier));
    clearSpies();
    editor.selection()->selectCurve(static_cast<int>(doc.idAt(2)));
    QCOMPARE(inserted.count() + removed.count() + reset.count(), 0);
    QVERIFY(changedIs(0, 3));
    QVERIFY(showsOnly(doc.idAt(2)));

    // Nothing selected: every row goes, nothing is announced of them.
    clearSpies();
    editor.selection()->clear();
    QCOMPARE(removed.count(), 1);
    QVERIFY(rangeIs(removed.at(0), 0, 3));
    QCOMPARE(changed.count() + inserted.count() + reset.count(), 0);
    QCOMPARE(points->rowCount(), 0);
    QCOMPARE(curve.count(), 1);
}

void TestModels::nodeTypeShownFollowsAChangeMadeByTheModel()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite),
                                                      rows({{0, 0}, {10, 10}, {20, 0}, {30, 10}})));
    const int id = kontur::test::idAt(editor, 0);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    editor.selection()->select(editor.document()->idAt(0), 6); // knot 2
    QCOMPARE(editor.selection()->knot(), 2);
    const int smooth = static_cast<int>(kontur::geo::NodeType::Smooth);
    const int corner = static_cast<int>(kontur::geo::NodeType::Corner);
    QCOMPARE(editor.selection()->nodeType(), smooth);
    QCOMPARE(editor.points()->index(6).data(PointListModel::NodeTypeRole).toInt(), smooth);

    QSignalSpy nodeType(editor.selection(), &kontur::Selection::nodeTypeChanged);
    QSignalSpy selectionChanged(editor.selection(), &kontur::Selection::changed);
    QSignalSpy dataChanged(editor.points(), &QAbstractItemModel::dataChanged);
    // The row of knot 2 was announced with its node type (an empty role list means every role).
    const auto announcedKnotRow = [&] {
        return std::any_of(dataChanged.cbegin(), dataChanged.cend(), [](const QList<QVariant> &args) {
            const int first = args.at(0).value<QModelIndex>().row();
            const int last = args.at(1).value<QModelIndex>().row();
            const auto roles = args.at(2).value<QList<int>>();
            return first <= 6 && 6 <= last && (roles.isEmpty() || roles.contains(PointListModel::NodeTypeRole));
        });
    };

    QVERIFY(editor.commands()->setNodeType(id, 2, corner));
    QCOMPARE(nodeType.count(), 1);
    QCOMPARE(selectionChanged.count(), 1);
    QCOMPARE(editor.selection()->nodeType(), corner);
    QVERIFY(announcedKnotRow());
    QCOMPARE(editor.points()->index(6).data(PointListModel::NodeTypeRole).toInt(), corner);
    // Only knots have a node type.
    QCOMPARE(editor.points()->index(5).data(PointListModel::NodeTypeRole).toInt(), -1);

    dataChanged.clear();
    editor.undo();
    QCOMPARE(nodeType.count(), 2);
    QCOMPARE(editor.selection()->nodeType(), smooth);
    QVERIFY(announcedKnotRow());
    QCOMPARE(editor.points()->index(6).data(PointListModel::NodeTypeRole).toInt(), smooth);

    dataChanged.clear();
    editor.redo();
    QCOMPARE(nodeType.count(), 3);
    QCOMPARE(editor.selection()->nodeType(), corner);
    QVERIFY(announcedKnotRow());
    QCOMPARE(editor.points()->index(6).data(PointListModel::NodeTypeRole).toInt(), corner);

    // A change of another knot's type leaves the selected knot's alone: no signal for it.
    QVERIFY(editor.commands()->setNodeType(id, 1, corner));
    QCOMPARE(nodeType.count(), 3);
    QCOMPARE(editor.selection()->nodeType(), corner);
    // A handle of knot 2 selected shows knot 2's type.
    editor.selection()->select(editor.document()->idAt(0), 7);
    QCOMPARE(editor.selection()->knot(), 2);
    QCOMPARE(editor.selection()->nodeType(), corner);
}

void TestModels::rowLayoutOfEachKind()
{
    using kontur::Curve;
    const std::vector<Point> four{{0, 0}, {10, 10}, {20, 0}, {30, 10}};
    // Open composite curve of 4 knots: rows 0..9, knot k at 3k, its handles at 3k-1 and 3k+1.
    const Curve open = Curve::make(CurveKind::Composite, four);
    QCOMPARE(open.rowCount(), 10);
    const std::vector<int> openKnots{0, 0, 1, 1, 1, 2, 2, 2, 3, 3};
    for (int r = 0; r < 10; ++r)
        QCOMPARE(open.knotOfRow(r), openKnots[static_cast<std::size_t>(r)]);
    QCOMPARE(open.knotOfRow(-1), -1);
    QCOMPARE(open.knotOfRow(10), -1);
    QCOMPARE(open.rowOfKnot(0), 0);
    QCOMPARE(open.rowOfKnot(1), 3);
    QCOMPARE(open.rowOfKnot(2), 6);
    QCOMPARE(open.rowOfKnot(3), 9);
    QCOMPARE(open.rowOfKnot(4), -1);
    QCOMPARE(open.rowOfKnot(-1), -1);
    for (int r = -1; r <= 10; ++r)
        QCOMPARE(open.isKnotRow(r), r == 0 || r == 3 || r == 6 || r == 9);

    // Closed: 12 rows; row 11 is knot 0's incoming handle (the control vector's repeated first
    // knot, index 12, is no row).
    Curve closed = Curve::make(CurveKind::Composite, four);
    QVERIFY(closed.close().ok());
    QVERIFY(closed.isClosed());
    QCOMPARE(closed.rowCount(), 12);
    const std::vector<int> closedKnots{0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 0};
    for (int r = 0; r < 12; ++r)
        QCOMPARE(closed.knotOfRow(r), closedKnots[static_cast<std::size_t>(r)]);
    QCOMPARE(closed.knotOfRow(12), -1);
    QCOMPARE(closed.rowOfKnot(3), 9);
    QCOMPARE(closed.rowOfKnot(4), -1);
    for (int r = -1; r <= 12; ++r)
        QCOMPARE(closed.isKnotRow(r), r == 0 || r == 3 || r == 6 || r == 9);

    // Bézier: every row is a control point of its own.
    const Curve bezier = Curve::make(CurveKind::Bezier, four);
    QCOMPARE(bezier.rowCount(), 4);
    for (int r = 0; r < 4; ++r) {
        QCOMPARE(bezier.knotOfRow(r), r);
        QCOMPARE(bezier.rowOfKnot(r), r);
        QVERIFY(bezier.isKnotRow(r));
    }
    QCOMPARE(bezier.knotOfRow(4), -1);
    QCOMPARE(bezier.rowOfKnot(4), -1);
    QVERIFY(!bezier.isKnotRow(4));

    // Clamped spline of 3 knots: rows 0..2 are the knots, 3 and 4 the tangent ends (no knot).
    const Curve clamped = Curve::make(CurveKind::ClampedSpline, {{0, 0}, {10, 10}, {20, 0}});
    QCOMPARE(clamped.rowCount(), 5);
    QCOMPARE(clamped.row(3).role, kontur::PointRole::TangentEnd);
    QCOMPARE(clamped.row(4).role, kontur::PointRole::TangentEnd);
    for (int r = 0; r < 3; ++r) {
        QCOMPARE(clamped.knotOfRow(r), r);
        QCOMPARE(clamped.rowOfKnot(r), r);
        QVERIFY(clamped.isKnotRow(r));
    }
    QCOMPARE(clamped.knotOfRow(3), -1);
    QCOMPARE(clamped.knotOfRow(4), -1);
    QVERIFY(!clamped.isKnotRow(3));
    QVERIFY(!clamped.isKnotRow(4));
    QCOMPARE(clamped.rowOfKnot(3), -1);

    // Interpolating cubic: the 4 rows after the knots are derived control points (no knot).
    const Curve fitted = Curve::make(CurveKind::Interpolating, four);
    QCOMPARE(fitted.rowCount(), 8);
    for (int r = 4; r < 8; ++r) {
        QCOMPARE(fitted.knotOfRow(r), -1);
        QVERIFY(!fitted.isKnotRow(r));
    }
    QCOMPARE(fitted.knotOfRow(3), 3);
}

QTEST_GUILESS_MAIN(TestModels)
#include "tst_models.moc"
