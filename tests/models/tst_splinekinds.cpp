// The spline families as curves of a document: each passes through (or is controlled by) its
// points, tangent ends act as tangents, and every edit on them is one exact undo step.
#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"

#include <QAbstractItemModelTester>
#include <QtTest>

using kontur::CurveKind;
using kontur::EditController;
using kontur::PointRole;
using kontur::geo::Point;
using kontur::test::rowsOf;

Q_DECLARE_METATYPE(CurveKind)

namespace {

const std::vector<Point> kKnots{{0, 0}, {10, 12}, {25, 15}, {40, 5}, {55, 9}};

} // namespace

class TestSplineKinds final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void interpolatingKindsPassThroughTheirKnots_data();
    void interpolatingKindsPassThroughTheirKnots();
    void bSplineIsControlledByItsPolygon();
    void hermiteTangentEndsSetTheTangents();
    void clampedGuideVectorsFollowTheirKnots();
    void functionSplineNeedsIncreasingX();
    void polynomialIsLimited();
    void parameterizationRecomputesSplines();
};

void TestSplineKinds::interpolatingKindsPassThroughTheirKnots_data()
{
    QTest::addColumn<CurveKind>("kind");
    QTest::addColumn<bool>("closed");
    QTest::addRow("natural") << CurveKind::NaturalSpline << false;
    QTest::addRow("clamped") << CurveKind::ClampedSpline << false;
    QTest::addRow("not-a-knot") << CurveKind::NotAKnotSpline << false;
    QTest::addRow("periodic") << CurveKind::PeriodicSpline << true;
    QTest::addRow("catmull-rom") << CurveKind::CatmullRom << false;
    QTest::addRow("hermite") << CurveKind::HermiteSpline << false;
    QTest::addRow("global b-spline") << CurveKind::GlobalBSpline << false;
    QTest::addRow("polynomial") << CurveKind::Polynomial << false;
    QTest::addRow("function spline") << CurveKind::FunctionSpline << false;
}

void TestSplineKinds::interpolatingKindsPassThroughTheirKnots()
{
    QFETCH(CurveKind, kind);
    QFETCH(bool, closed);
    EditController editor;
    QAbstractItemModelTester points(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(kind), rowsOf(kKnots)));
    const kontur::Curve &curve = editor.document()->curve(0);
    QVERIFY(!curve.problem());
    QCOMPARE(curve.placedCount(), 5);
    QCOMPARE(curve.isClosed(), closed);
    // Every knot is where a segment starts (and the last where the last one ends).
    const int segments = curve.segmentCount();
    QCOMPARE(segments, closed ? 5 : 4);
    for (int i = 0; i < segments; ++i)
        QVERIFY((curve.segment(i).controlPoints().front() - kKnots[static_cast<std::size_t>(i)]).norm() < 1e-9);
    const Point end = curve.segment(segments - 1).controlPoints().back();
    QVERIFY((end - (closed ? kKnots.front() : kKnots.back())).norm() < 1e-9);
    QCOMPARE(curve.row(0).role, PointRole::Knot);

    // Moving a knot rebuilds the curve through the new position; undo restores it exactly.
    const kontur::Curve before = curve;
    QVERIFY(editor.beginDrag(QPointF(25, 15), 0.5));
    editor.dragTo(QPointF(26, 20));
    editor.endDrag();
    QVERIFY((editor.document()->curve(0).segment(2).controlPoints().front() - Point(26, 20)).norm() < 1e-9);
    editor.undo();
    QVERIFY(editor.document()->curve(0).sameState(before));
}

void TestSplineKinds::bSplineIsControlledByItsPolygon()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::BSpline), rowsOf(kKnots)));
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.order(), 4);
    QCOMPARE(curve.row(2).role, PointRole::ControlPoint);
    // Open uniform knots: the curve starts and ends at the polygon's ends.
    QVERIFY((curve.segment(0).controlPoints().front() - kKnots.front()).norm() < 1e-12);
    QVERIFY((curve.segment(curve.segmentCount() - 1).controlPoints().back() - kKnots.back()).norm() < 1e-12);
    QCOMPARE(curve.segmentCount(), 2); // n − k + 1 spans
    // Order 2 is the polygon itself (seed 003 KG-205).
    QVERIFY(editor.commands()->setCurveOrder(kontur::test::idAt(editor, 0), 2));
    QCOMPARE(editor.document()->curve(0).segmentCount(), 4);
    QVERIFY((editor.document()->curve(0).segment(1).eval(0.5) - Point(17.5, 13.5)).norm() < 1e-12);
    // Order 5 = 5 control points: the Bézier curve of the polygon. At t = 0.3 it is (14.2005, 9.3591)
    // (de Casteljau on the five points in exact fractions: 28401/2000, 93591/10000).
    QVERIFY(editor.commands()->setCurveOrder(kontur::test::idAt(editor, 0), 5));
    QCOMPARE(editor.document()->curve(0).segmentCount(), 1);
    QVERIFY((editor.document()->curve(0).segment(0).eval(0.3) - Point(14.2005, 9.3591)).norm() < 1e-12);
    QVERIFY(!editor.commands()->setCurveOrder(kontur::test::idAt(editor, 0), 6)); // more than the control points
    QVERIFY(!editor.commands()->setCurveParameterization(kontur::test::idAt(editor, 0),
                                                         kontur::Parameterizations::ChordLength));
    QCOMPARE(editor.message().id, kontur::Message::NoParameterization);
}

void TestSplineKinds::hermiteTangentEndsSetTheTangents()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::HermiteSpline), rowsOf(kKnots)));
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.rowCount(), 10); // 5 knots and 5 tangent ends
    QCOMPARE(curve.row(7).role, PointRole::TangentEnd);
    QCOMPARE(editor.points()->index(7).data(kontur::PointListModel::LabelRole).toString(), QStringLiteral("T2"));
    // The tangent end is the Bézier handle of the segment leaving its knot.
    QVERIFY((curve.segment(2).controlPoints()[1] - curve.row(7).position).norm() < 1e-9);
    const Point moved = curve.row(7).position + Point(3, -4);
    QVERIFY(editor.beginDrag(QPointF(curve.row(7).position.x(), curve.row(7).position.y()), 0.01));
    editor.dragTo(QPointF(moved.x(), moved.y()));
    editor.endDrag();
    QVERIFY((editor.document()->curve(0).segment(2).controlPoints()[1] - moved).norm() < 1e-9);
    // Dragging a knot carries its tangent end: the tangent stays.
    const Point offset = editor.document()->curve(0).row(7).position - Point(25, 15);
    QVERIFY(editor.beginDrag(QPointF(25, 15), 0.01));
    editor.dragTo(QPointF(30, 10));
    editor.endDrag();
    QVERIFY((editor.document()->curve(0).row(7).position - (Point(30, 10) + offset)).norm() < 1e-12);
    // Adding a knot adds a tangent end; deleting removes it.
    kontur::test::selectAt(editor, 0, 1);
    QVERIFY(editor.commands()->addRowAfterSelection());
    QCOMPARE(editor.document()->curve(0).rowCount(), 12);
    QVERIFY(editor.commands()->deleteSelectedRow());
    QCOMPARE(editor.document()->curve(0).rowCount(), 10);
}

void TestSplineKinds::clampedGuideVectorsFollowTheirKnots()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::ClampedSpline), rowsOf(kKnots)));
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.rowCount(), 7); // 5 knots, the start and end guide vectors
    QCOMPARE(curve.row(5).role, PointRole::TangentEnd);
    QCOMPARE(curve.row(6).number, 4);
    const Point startHandle = curve.segment(0).controlPoints()[1];
    QVERIFY((startHandle - curve.row(5).position).norm() < 1e-9);
    // The seed 003 debug case: collinear points, guide vectors along the line → a straight line.
    EditController straight;
    QVERIFY(straight.placement()->createFromCoordinates(static_cast<int>(CurveKind::ClampedSpline),
                                                        rowsOf({{0, 0}, {30, 20}, {60, 40}, {90, 60}})));
    const kontur::Curve &line = straight.document()->curve(0);
    for (int s = 0; s < line.segmentCount(); ++s) {
        const kontur::geo::Bezier segment = line.segment(s);
        for (const Point &p : segment.controlPoints())
            QVERIFY(std::abs(p.x() * 20 - p.y() * 30) < 1e-9);
    }
}

void TestSplineKinds::functionSplineNeedsIncreasingX()
{
    EditController editor;
    QVERIFY(!editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::FunctionSpline),
                                                       rowsOf({{0, 0}, {5, 1}, {3, 2}})));
    QVERIFY(!editor.message().isEmpty());
    QCOMPARE(editor.document()->curveCount(), 0);
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::FunctionSpline),
                                                      rowsOf({{1, -0.1}, {2, 1}, {3, 1.1}})));
    // A function: x(u) = u, so the curve at x = 2 is y = 1.
    const kontur::geo::Bezier second = editor.document()->curve(0).segment(1);
    QVERIFY((second.controlPoints().front() - Point(2, 1)).norm() < 1e-12);
    QVERIFY(std::abs(second.controlPoints()[1].x() - (2 + 1.0 / 3)) < 1e-12);
}

void TestSplineKinds::polynomialIsLimited()
{
    EditController editor;
    std::vector<Point> many;
    for (int i = 0; i < 65; ++i)
        many.emplace_back(i, std::sin(i));
    QVERIFY(!editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Polynomial), rowsOf(many)));
    QCOMPARE(editor.message().id, kontur::Message::TooManyPoints);
    many.pop_back();
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Polynomial), rowsOf(many)));
}

void TestSplineKinds::parameterizationRecomputesSplines()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::NaturalSpline),
                                                      rowsOf({{0, 0}, {1, 5}, {2, 6}, {10, 6}, {12, 0}})));
    const Point uniform = editor.document()->curve(0).segment(1).controlPoints()[1];
    QVERIFY(editor.commands()->setCurveParameterization(kontur::test::idAt(editor, 0),
                                                        kontur::Parameterizations::Centripetal));
    const Point centripetal = editor.document()->curve(0).segment(1).controlPoints()[1];
    QVERIFY((uniform - centripetal).norm() > 1e-6);
    editor.undo();
    QCOMPARE(editor.document()->curve(0).segment(1).controlPoints()[1], uniform);
}

QTEST_GUILESS_MAIN(TestSplineKinds)
#include "tst_splinekinds.moc"
