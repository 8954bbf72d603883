// The selected curve's row as a one-row model (SelectedCurveModel): what the side panel reads by role.
// It shows the selected curve's data, follows that curve's changes and nothing else, and keeps its
// row while the selection goes from one curve to another.
#include "models/controllers/editcontroller.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/selectedcurvemodel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

using kontur::CurveId;
using kontur::CurveListModel;
using kontur::EditController;

class TestSelectedCurve final : public QObject
{
    Q_OBJECT

private:
    static int addBezier(EditController &editor, double offset)
    {
        const QVariantList rows{QVariantList{0.0 + offset, 0.0}, QVariantList{10.0 + offset, 20.0},
                                QVariantList{30.0 + offset, 20.0}, QVariantList{40.0 + offset, 0.0}};
        if (!editor.placement()->createFromCoordinates(static_cast<int>(kontur::CurveKind::Bezier), rows))
            return 0;
        return editor.selection()->curveIdValue();
    }
    static QString shownName(const EditController &editor)
    {
        auto *model = editor.selectedCurve();
        return model->data(model->index(0), CurveListModel::NameRole).toString();
    }

private Q_SLOTS:
    void followsTheSelection();
    void announcesOnlyTheSelectedCurvesChanges();
    void holdsTheCurveThroughMovesAndEmptiesWhenItGoes();
};

void TestSelectedCurve::followsTheSelection()
{
    EditController editor;
    QAbstractItemModelTester tester(editor.selectedCurve(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(editor.selectedCurve()->rowCount(), 0);
    const int first = addBezier(editor, 0);
    const int second = addBezier(editor, 100);
    QVERIFY(first != 0 && second != 0 && first != second);
    QCOMPARE(editor.selectedCurve()->rowCount(), 1);
    QCOMPARE(shownName(editor), editor.document()->curve(1).name);

    // Another curve: the row stays, its data is announced anew.
    QSignalSpy changed(editor.selectedCurve(), &QAbstractItemModel::dataChanged);
    QSignalSpy removed(editor.selectedCurve(), &QAbstractItemModel::rowsRemoved);
    editor.selection()->selectCurve(first);
    // Every role anew (an empty role list), besides the list model's own `selected` role changes.
    QVERIFY(std::any_of(changed.begin(), changed.end(),
                        [](const QList<QVariant> &args) { return args.at(2).value<QList<int>>().isEmpty(); }));
    QCOMPARE(removed.count(), 0);
    QCOMPARE(shownName(editor), editor.document()->curve(0).name);
    QCOMPARE(editor.selectedCurve()->data(editor.selectedCurve()->index(0), CurveListModel::CurveIdRole).toInt(),
             first);

    editor.selection()->clear();
    QCOMPARE(removed.count(), 1);
    QCOMPARE(editor.selectedCurve()->rowCount(), 0);
}

void TestSelectedCurve::announcesOnlyTheSelectedCurvesChanges()
{
    EditController editor;
    QAbstractItemModelTester tester(editor.selectedCurve(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    const int first = addBezier(editor, 0);
    const int second = addBezier(editor, 100);
    editor.selection()->selectCurve(first);
    QSignalSpy changed(editor.selectedCurve(), &QAbstractItemModel::dataChanged);

    QVERIFY(editor.commands()->setCurveName(second, QStringLiteral("Back")));
    QCOMPARE(changed.count(), 0);

    QVERIFY(editor.commands()->setCurveName(first, QStringLiteral("Front")));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(shownName(editor), QStringLiteral("Front"));
    editor.undo();
    QCOMPARE(changed.count(), 2);
    QCOMPARE(shownName(editor), editor.document()->curve(0).name);
    QVERIFY(shownName(editor) != QStringLiteral("Front"));
}

void TestSelectedCurve::holdsTheCurveThroughMovesAndEmptiesWhenItGoes()
{
    EditController editor;
    QAbstractItemModelTester tester(editor.selectedCurve(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    const int first = addBezier(editor, 0);
    addBezier(editor, 100);
    QVERIFY(editor.commands()->setCurveName(first, QStringLiteral("Kept")));
    editor.selection()->selectCurve(first);
    QCOMPARE(editor.selection()->curveRow(), 0);

    // Moved below the other: the same curve, now at row 1.
    QVERIFY(editor.commands()->moveCurve(first, 1));
    QCOMPARE(editor.selection()->curveRow(), 1);
    QCOMPARE(shownName(editor), QStringLiteral("Kept"));

    // Deleted: nothing selected, no row; undo brings the curve back with its id.
    QVERIFY(editor.commands()->deleteCurve(first));
    QCOMPARE(editor.selectedCurve()->rowCount(), 0);
    QVERIFY(!editor.selection()->hasCurve());
    editor.undo();
    QCOMPARE(editor.document()->indexOf(static_cast<CurveId>(first)), 1);
    QCOMPARE(editor.document()->curve(1).name, QStringLiteral("Kept"));
}

QTEST_GUILESS_MAIN(TestSelectedCurve)
#include "tst_selectedcurve.moc"
