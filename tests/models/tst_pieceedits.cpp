// Finishing a traced piece (PieceEdits, geometry/compositeedit.h): extend by a stroke, join, close at a
// corner, make line, delete knot and node type, simplify. Each edit is one undo step that restores the
// exact curves (every double) and redoes the same result; shapes are checked against the mathematics
// (points on a chord, distances measured by the nearest point on each Bézier segment).
#include "geometry/compositeedit.h"
#include "geometry/nearest.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/pieceedits.h"
#include "models/document/commands.h"
#include "models/trace/tracecontroller.h"

#include <QAbstractItemModelTester>
#include <QLocale>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using kontur::Curve;
using kontur::CurveId;
using kontur::CurveKind;
using kontur::EditController;
using kontur::PieceEdits;
using kontur::TraceController;
using kontur::geo::CompositeCurve;
using kontur::geo::NodeType;
using kontur::geo::Point;

namespace {

Curve composite(std::vector<Point> control, std::vector<NodeType> types, bool closed = false)
{
    auto made = CompositeCurve::fromParts(std::move(control), std::move(types), closed);
    Q_ASSERT(made.ok());
    made->finish();
    return *Curve::makeComposite(std::move(*made));
}

// A straight cubic from a to b (handles at thirds).
void appendLine(std::vector<Point> &control, const Point &b)
{
    const Point a = control.back();
    control.push_back((2.0 * a + b) / 3.0);
    control.push_back((a + 2.0 * b) / 3.0);
    control.push_back(b);
}

// The distance from p to the curve: the least over its segments' exact nearest points.
double distanceToCurve(const Curve &curve, const Point &p)
{
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s < curve.segmentCount(); ++s)
        best = std::min(best, kontur::geo::nearest(curve.segment(s), p).distance);
    return best;
}

// The largest distance from `samples` points per segment of `from` to the curve `to`.
double oneSidedDistance(const Curve &from, const Curve &to, int samples)
{
    double worst = 0.0;
    for (int s = 0; s < from.segmentCount(); ++s)
        for (int i = 0; i <= samples; ++i)
            worst = std::max(worst, distanceToCurve(to, from.segment(s).eval(static_cast<double>(i) / samples)));
    return worst;
}

bool sameControl(const Curve &a, const Curve &b)
{
    return a.composite() == b.composite();
}

CurveId add(EditController &editor, Curve curve)
{
    return editor.commands()->appendCurve(std::move(curve));
}

const Curve &curveOf(EditController &editor, CurveId id)
{
    return *editor.document()->find(id);
}

} // namespace

class TestPieceEdits final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void closeAtCornerMergesTheEnds();
    void closeOfNearlyMeetingSmoothEndsIsSmooth();
    void closeOfDistantEndsKeepsTheConstruction();
    void makeLineStraightensOneSegment();
    void nodeTypeAndDeleteKnotBySelection();
    void simplifyKeepsWithinTolerance();
    void simplifyKeepsCorners();
    void simplifyRefusesWhatCannotBeSimpler();
    void simplifyTextReadsTheLocalesComma();
    void joinKeepsBothShapes();
    void joinWithAGapAddsALine();
    void strokeFromAnEndExtendsTheCurve();
    void strokeToTheStartExtendsBeforeIt();
    void strokeFarAwayIsANewCurve();
    void randomCurvesKeepTheirUntouchedParts();
};

// A square traced in one stroke that ends 1e-10 from its start: closing merges the two ends into one
// Corner knot; no segment is added; undo and redo are exact.
void TestPieceEdits::closeAtCornerMergesTheEnds()
{
    EditController editor;
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    PieceEdits edits;
    edits.setEditor(&editor);
    std::vector<Point> control{Point(0, 0)};
    appendLine(control, Point(10, 0));
    appendLine(control, Point(10, 10));
    appendLine(control, Point(0, 10));
    appendLine(control, Point(0, 1e-10));
    const CurveId id = add(editor, composite(control, {NodeType::Smooth, NodeType::Corner, NodeType::Corner,
                                                       NodeType::Corner, NodeType::Smooth}));
    const Curve before = curveOf(editor, id);
    QVERIFY(edits.canClose());
    QSignalSpy changed(editor.document(), &kontur::Document::curveChanged);
    const int steps = editor.undoStack()->count();
    QVERIFY(edits.closeSelected(0.5));
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    QCOMPARE(changed.count(), 1);
    const Curve after = curveOf(editor, id);
    QVERIFY(after.isClosed());
    QCOMPARE(after.composite().knotCount(), 4);
    QCOMPARE(after.segmentCount(), 4);
    QCOMPARE(after.composite().nodeType(0), NodeType::Corner);
    QVERIFY(distanceToCurve(after, Point(0, 0)) <= 1e-9);
    QVERIFY(distanceToCurve(after, Point(0, 1e-10)) <= 1e-9);
    // The three first sides are the very same cubics.
    for (int s = 0; s < 3; ++s)
        QVERIFY(after.segment(s).controlPoints() == before.segment(s).controlPoints());
    // The joint keeps its angle: the last side still arrives along -y, the first leaves along +x.
    const auto last = after.composite().segmentPoints(3);
    QVERIFY(std::abs((last[3] - last[2]).normalized().dot(Point(0, -1)) - 1.0) <= 1e-12);
    // Today's close (the construction rule with a smooth joint) bulges; this does not: the curve
    // stays within the square.
    QVERIFY(after.bounds().min().x() >= -1e-9 && after.bounds().min().y() >= -1e-9);

    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
    QVERIFY(sameControl(curveOf(editor, id), before));
    editor.redo();
    QVERIFY(curveOf(editor, id).sameState(after));
}

// A circle drawn round and ended 0.8 units past its start, nearly tangent: merged (no short segment)
// and Smooth, with its two handles collinear.
void TestPieceEdits::closeOfNearlyMeetingSmoothEndsIsSmooth()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    std::vector<Point> knots;
    const int n = 12;
    for (int i = 0; i <= n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        knots.emplace_back(50.0 * std::cos(a), 50.0 * std::sin(a) + (i == n ? 0.8 : 0.0));
    }
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    const Curve before = curveOf(editor, id);
    QVERIFY(edits.closeCurve(static_cast<int>(id), 2.0));
    const Curve &after = curveOf(editor, id);
    QVERIFY(after.isClosed());
    QCOMPARE(after.composite().knotCount(), n);
    QCOMPARE(after.composite().nodeType(0), NodeType::Smooth);
    const auto &c = after.composite().controlPoints();
    const Point in = c[c.size() - 2] - c[0], out = c[1] - c[0];
    QVERIFY(std::abs(in.normalized().dot(out.normalized()) + 1.0) <= 1e-12);
    // Segments away from the joint are untouched.
    for (int s = 1; s + 1 < n - 1; ++s)
        QVERIFY(after.segment(s).controlPoints() == before.segment(s).controlPoints());
    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
}

// Ends farther apart than the merge distance: closed as before, by a constructed segment.
void TestPieceEdits::closeOfDistantEndsKeepsTheConstruction()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    const std::vector<Point> knots{Point(0, 0), Point(10, 0), Point(10, 10), Point(0, 10)};
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    QVERIFY(edits.closeCurve(static_cast<int>(id), 1.0));
    CompositeCurve expected = Curve::make(CurveKind::Composite, knots).composite();
    QVERIFY(expected.close().ok());
    QVERIFY(curveOf(editor, id).composite().controlPoints() == expected.controlPoints());
    QCOMPARE(curveOf(editor, id).composite().knotCount(), 4);
    // A closed curve cannot be closed again.
    QVERIFY(!edits.canClose());
}

// Make line on the segment a selected knot begins: the segment lies on its chord, its knots become
// corners, the neighbouring segments are the same cubics; a later free drag of the neighbour's handle
// leaves the line straight (the corner's handles are independent).
void TestPieceEdits::makeLineStraightensOneSegment()
{
    EditController editor;
    QAbstractItemModelTester pointsTester(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    PieceEdits edits;
    edits.setEditor(&editor);
    const std::vector<Point> knots{Point(0, 0), Point(30, 20), Point(70, 25), Point(100, 0), Point(130, 40)};
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    const Curve before = curveOf(editor, id);
    editor.selection()->select(id, before.rowOfKnot(1));
    QCOMPARE(edits.selectedSegment(), 1);
    QVERIFY(edits.canMakeLine());
    QSignalSpy rows(editor.points(), &QAbstractItemModel::dataChanged);
    QVERIFY(edits.makeSelectedLine());
    QVERIFY(rows.count() >= 1);
    const Curve after = curveOf(editor, id);
    const Point p0 = knots[1], p1 = knots[2];
    const Point chord = p1 - p0;
    const double length = chord.norm();
    for (int i = 0; i <= 64; ++i) {
        const Point q = after.segment(1).eval(i / 64.0) - p0;
        const double off = std::abs(chord.x() * q.y() - chord.y() * q.x()) / length;
        QVERIFY2(off <= 1e-12 * length, qPrintable(QString::number(off)));
    }
    QCOMPARE(after.composite().nodeType(1), NodeType::Corner);
    QCOMPARE(after.composite().nodeType(2), NodeType::Corner);
    for (int s : {0, 2, 3})
        QVERIFY(after.segment(s).controlPoints() == before.segment(s).controlPoints());
    // A handle selected names its own segment: the incoming handle of knot 3 is segment 2's.
    editor.selection()->select(id, 3 * 3 - 1);
    QCOMPARE(edits.selectedSegment(), 2);

    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
    QVERIFY(sameControl(curveOf(editor, id), before));
    editor.redo();
    QVERIFY(curveOf(editor, id).sameState(after));

    // Dragging knot 1's incoming handle freely leaves the line alone (shown once knot 1 is selected).
    editor.selection()->select(id, after.rowOfKnot(1));
    QVERIFY(editor.beginDrag(QPointF(after.row(2).position.x(), after.row(2).position.y()), 0.01));
    editor.dragTo(QPointF(5, 30));
    editor.endDrag();
    QVERIFY(curveOf(editor, id).segment(1).controlPoints() == after.segment(1).controlPoints());
    QVERIFY(curveOf(editor, id).row(2).position != after.row(2).position);
}

void TestPieceEdits::nodeTypeAndDeleteKnotBySelection()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    QSignalSpy state(&edits, &PieceEdits::stateChanged);
    const std::vector<Point> knots{Point(0, 0), Point(30, 20), Point(70, 25), Point(100, 0)};
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    const Curve before = curveOf(editor, id);
    QVERIFY(!edits.canEditKnot());                           // the curve, not a point, is selected
    editor.selection()->select(id, before.rowOfKnot(2) + 1); // knot 2's outgoing handle
    QVERIFY(state.count() >= 1);
    QVERIFY(edits.canEditKnot());
    QVERIFY(edits.setSelectedNodeType(static_cast<int>(NodeType::Corner)));
    QCOMPARE(curveOf(editor, id).composite().nodeType(2), NodeType::Corner);
    QCOMPARE(editor.selection()->nodeType(), static_cast<int>(NodeType::Corner));
    const Curve cornered = curveOf(editor, id);
    QVERIFY(edits.canDeleteKnot());
    QVERIFY(edits.deleteSelectedKnot());
    QCOMPARE(curveOf(editor, id).composite().knotCount(), 3);
    QVERIFY(curveOf(editor, id).composite().knot(2) == knots[3]);
    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(cornered));
    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
    // An open curve keeps two knots.
    const CurveId two = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(5, 5)}));
    editor.selection()->select(two, 0);
    QVERIFY(!edits.canDeleteKnot());
    QVERIFY(!edits.deleteSelectedKnot());
    QCOMPARE(curveOf(editor, two).composite().knotCount(), 2);
}

// A wave with a knot every 0.2 units of x (61 knots): far fewer knots within 0.05, measured here
// both ways by exact nearest points on 64 samples per segment.
void TestPieceEdits::simplifyKeepsWithinTolerance()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    std::vector<Point> knots;
    for (int i = 0; i <= 60; ++i) {
        const double x = 0.2 * i;
        knots.emplace_back(x, 2.0 * std::sin(x));
    }
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    const Curve before = curveOf(editor, id);
    const double tolerance = 0.05;
    QVERIFY(edits.simplify(static_cast<int>(id), tolerance));
    const Curve after = curveOf(editor, id);
    QVERIFY2(after.composite().knotCount() <= 12, qPrintable(QString::number(after.composite().knotCount())));
    QVERIFY(after.composite().knot(0) == knots.front());
    QVERIFY(after.composite().knot(after.composite().knotCount() - 1) == knots.back());
    const double there = oneSidedDistance(before, after, 64), back = oneSidedDistance(after, before, 64);
    QVERIFY2(there <= tolerance && back <= tolerance, qPrintable(QStringLiteral("%1 %2").arg(there).arg(back)));
    qInfo("simplify: 61 -> %d knots, distance %.4f / %.4f (tolerance %.2f)", after.composite().knotCount(), there, back,
          tolerance);
    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
    QVERIFY(sameControl(curveOf(editor, id), before));
    editor.redo();
    QVERIFY(curveOf(editor, id).sameState(after));
}

// A closed outline with two corners and dense knots on its arcs: the corners stay, as corners,
// exactly where they were.
void TestPieceEdits::simplifyKeepsCorners()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    // A half disc: the arc from (50, 0) round to (-50, 0) in 30 knots, then the straight diameter.
    std::vector<Point> knots;
    for (int i = 0; i <= 30; ++i) {
        const double a = std::numbers::pi * i / 30;
        knots.emplace_back(50.0 * std::cos(a), 50.0 * std::sin(a));
    }
    knots.emplace_back(0.0, 0.0);
    Curve made = Curve::make(CurveKind::Composite, knots);
    CompositeCurve shape = made.composite();
    QVERIFY(shape.close().ok());
    auto line0 = kontur::geo::makeSegmentLine(shape, 30);
    QVERIFY(line0.ok());
    auto line1 = kontur::geo::makeSegmentLine(*line0, 31);
    QVERIFY(line1.ok());
    line1->setNodeTypeOnly(31, NodeType::Smooth); // the diameter's midpoint: straight through
    const CurveId id = add(editor, *Curve::makeComposite(*line1));
    const Curve before = curveOf(editor, id);
    QVERIFY(edits.simplify(static_cast<int>(id), 0.1));
    const Curve &after = curveOf(editor, id);
    const CompositeCurve &c = after.composite();
    QVERIFY(c.isClosed());
    QVERIFY(c.knotCount() < 12);
    int corners = 0;
    for (int k = 0; k < c.knotCount(); ++k) {
        if (c.nodeType(k) != NodeType::Corner)
            continue;
        ++corners;
        QVERIFY(c.knot(k) == knots[30] || c.knot(k) == knots[0]);
    }
    QCOMPARE(corners, 2);
    QVERIFY(oneSidedDistance(before, after, 64) <= 0.1);
    QVERIFY(oneSidedDistance(after, before, 64) <= 0.1);
}

void TestPieceEdits::simplifyRefusesWhatCannotBeSimpler()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(10, 10), Point(20, 0)}));
    const Curve before = curveOf(editor, id);
    QSignalSpy message(&edits, &PieceEdits::messageChanged);
    const int steps = editor.undoStack()->count();
    // A tolerance far below the bend: no curve of two knots stays within it.
    QVERIFY(!edits.simplify(static_cast<int>(id), 1e-3));
    QCOMPARE(editor.undoStack()->count(), steps);
    QVERIFY(curveOf(editor, id).sameState(before));
    QVERIFY(!edits.message().isEmpty());
    QVERIFY(message.count() >= 1);
    QVERIFY(!edits.simplify(static_cast<int>(id), 0.0));
    QVERIFY(!edits.simplify(static_cast<int>(id), std::nan("")));
}

void TestPieceEdits::simplifyTextReadsTheLocalesComma()
{
    const QLocale saved;
    QLocale::setDefault(QLocale(QLocale::Latvian, QLocale::Latvia));
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    std::vector<Point> knots;
    for (int i = 0; i <= 40; ++i)
        knots.emplace_back(i, 0.001 * std::sin(i)); // nearly straight: one segment is enough at 0,5
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, knots));
    QVERIFY(!edits.simplifyText(static_cast<int>(id), QStringLiteral("nulle")));
    QVERIFY(!edits.simplifyText(static_cast<int>(id), QStringLiteral("-0,5")));
    QCOMPARE(curveOf(editor, id).composite().knotCount(), 41);
    QVERIFY(edits.simplifyText(static_cast<int>(id), QStringLiteral("0,5")));
    QCOMPARE(curveOf(editor, id).composite().knotCount(), 2);
    QVERIFY(edits.suggestedToleranceText().contains(QLatin1Char(',')));
    QLocale::setDefault(saved);
}

// Two strokes meeting at a right angle: one curve, the first part the very same control points, the
// second the same cubics after the shared knot, a Corner there; undo brings back both curves and ids.
void TestPieceEdits::joinKeepsBothShapes()
{
    EditController editor;
    QAbstractItemModelTester curvesTester(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    PieceEdits edits;
    edits.setEditor(&editor);
    const CurveId a = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(20, 5), Point(40, 0)}));
    // b ends on a's end (it is joined reversed) and leaves it upwards.
    const CurveId b = add(editor, Curve::make(CurveKind::Composite, {Point(60, 40), Point(45, 20), Point(40, 0)}));
    const Curve beforeA = curveOf(editor, a), beforeB = curveOf(editor, b);
    editor.selection()->select(a);
    QVERIFY(edits.canJoin());
    QSignalSpy removed(editor.curves(), &QAbstractItemModel::rowsRemoved);
    const int steps = editor.undoStack()->count();
    QVERIFY(edits.joinSelected(1.0));
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    QCOMPARE(removed.count(), 1);
    QCOMPARE(editor.document()->curveCount(), 1);
    QVERIFY(editor.document()->find(b) == nullptr);
    QCOMPARE(editor.selection()->curveIdValue(), static_cast<int>(a));
    const Curve joined = curveOf(editor, a);
    QCOMPARE(joined.name, beforeA.name);
    const CompositeCurve &c = joined.composite();
    QCOMPARE(c.knotCount(), 5);
    QCOMPARE(c.nodeType(2), NodeType::Corner);
    for (int s = 0; s < 2; ++s)
        QVERIFY(joined.segment(s).controlPoints() == beforeA.segment(s).controlPoints());
    // b's segments, run backwards.
    for (int s = 0; s < 2; ++s) {
        std::vector<Point> back = beforeB.segment(1 - s).controlPoints();
        std::reverse(back.begin(), back.end());
        QVERIFY(joined.segment(2 + s).controlPoints() == back);
    }
    editor.undo();
    QCOMPARE(editor.document()->curveCount(), 2);
    QVERIFY(curveOf(editor, a).sameState(beforeA));
    QVERIFY(curveOf(editor, b).sameState(beforeB));
    QCOMPARE(editor.document()->indexOf(b), 1);
    editor.redo();
    QVERIFY(curveOf(editor, a).sameState(joined));
    QCOMPARE(editor.document()->curveCount(), 1);
}

void TestPieceEdits::joinWithAGapAddsALine()
{
    EditController editor;
    PieceEdits edits;
    edits.setEditor(&editor);
    const CurveId a = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(20, 5), Point(40, 0)}));
    const CurveId b = add(editor, Curve::make(CurveKind::Composite, {Point(50, 0), Point(70, -5), Point(90, 0)}));
    const Curve beforeB = curveOf(editor, b);
    QVERIFY(edits.joinCurves(static_cast<int>(a), static_cast<int>(b), 1.0));
    const CompositeCurve &c = curveOf(editor, a).composite();
    QCOMPARE(c.knotCount(), 6);
    QCOMPARE(c.nodeType(2), NodeType::Corner);
    QCOMPARE(c.nodeType(3), NodeType::Corner);
    const auto gap = c.segmentPoints(2);
    QVERIFY(gap[0] == Point(40, 0) && gap[3] == Point(50, 0));
    QVERIFY(gap[1].y() == 0.0 && gap[2].y() == 0.0);
    for (int s = 0; s < 2; ++s)
        QVERIFY(curveOf(editor, a).segment(3 + s).controlPoints() == beforeB.segment(s).controlPoints());
}

// A freehand stroke that begins near an open curve's last knot continues that curve: one undo step,
// the old segments the very same cubics, no new curve.
void TestPieceEdits::strokeFromAnEndExtendsTheCurve()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Freehand);
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(50, 10), Point(100, 0)}));
    const Curve before = curveOf(editor, id);
    const int steps = editor.undoStack()->count();
    trace.freehand()->beginStroke(QPointF(100.5, 0.5), 0.0);
    for (int i = 1; i <= 50; ++i)
        trace.freehand()->extendStroke(QPointF(100.5, 0.5 + 2.0 * i)); // straight up: a corner at the joint
    QVERIFY(trace.freehand()->endStroke(2.0));
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    const Curve after = curveOf(editor, id);
    QVERIFY(after.composite().knotCount() > before.composite().knotCount());
    for (int s = 0; s < before.segmentCount(); ++s)
        QVERIFY(after.segment(s).controlPoints() == before.segment(s).controlPoints());
    QCOMPARE(after.composite().nodeType(2), NodeType::Corner);
    QVERIFY(distanceToCurve(after, Point(100.5, 100.5)) <= 1.0);
    editor.undo();
    QVERIFY(curveOf(editor, id).sameState(before));
    editor.redo();
    QVERIFY(curveOf(editor, id).sameState(after));
}

// A stroke that ends on the curve's first knot: it comes before the curve, which keeps its direction.
void TestPieceEdits::strokeToTheStartExtendsBeforeIt()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Freehand);
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(50, 10), Point(100, 0)}));
    const Curve before = curveOf(editor, id);
    trace.freehand()->beginStroke(QPointF(-100, 0), 0.0);
    for (int i = 1; i <= 50; ++i)
        trace.freehand()->extendStroke(QPointF(-100 + 2.0 * i, 0.0));
    QVERIFY(trace.freehand()->endStroke(2.0));
    QCOMPARE(editor.document()->curveCount(), 1);
    const Curve &after = curveOf(editor, id);
    const int added = after.segmentCount() - before.segmentCount();
    QVERIFY(added >= 1);
    QVERIFY(after.composite().knot(0) == Point(-100, 0));
    for (int s = 0; s < before.segmentCount(); ++s)
        QVERIFY(after.segment(added + s).controlPoints() == before.segment(s).controlPoints());
}

void TestPieceEdits::strokeFarAwayIsANewCurve()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Freehand);
    const CurveId id = add(editor, Curve::make(CurveKind::Composite, {Point(0, 0), Point(50, 10), Point(100, 0)}));
    const Curve before = curveOf(editor, id);
    trace.freehand()->beginStroke(QPointF(105, 0), 0.0);
    for (int i = 1; i <= 50; ++i)
        trace.freehand()->extendStroke(QPointF(105, 2.0 * i));
    QVERIFY(trace.freehand()->endStroke(2.0)); // 5 units from the end: beyond the radius
    QCOMPARE(editor.document()->curveCount(), 2);
    QVERIFY(curveOf(editor, id).sameState(before));
}

// Over random composite curves (random knots, node types and handle drags): make line leaves every
// other segment as it was and puts its own on the chord; a join keeps the first curve's control
// points and, at a merged joint, the second's after its first handle; reversing twice is the
// identity; closing at a merge keeps all but the last segment.
void TestPieceEdits::randomCurvesKeepTheirUntouchedParts()
{
    std::mt19937 random(32);
    std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
    std::uniform_int_distribution<int> typeOf(0, 2);
    const auto randomCurve = [&](int n) {
        std::vector<Point> knots;
        for (int i = 0; i < n; ++i)
            knots.emplace_back(coordinate(random), coordinate(random));
        CompositeCurve c = Curve::make(CurveKind::Composite, knots).composite();
        for (int k = 0; k < n; ++k)
            c.setNodeTypeOnly(k, static_cast<NodeType>(typeOf(random)));
        for (int i = 0; i < n; ++i) {
            const int handle = 3 * std::uniform_int_distribution<int>(0, n - 2)(random) + 1;
            (void)c.moveHandle(handle, Point(coordinate(random), coordinate(random)), kontur::geo::HandleMove::Free);
        }
        return c;
    };
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 2 + trial % 9;
        const CompositeCurve a = randomCurve(n);
        const int s = trial % a.segmentCount();
        auto line = kontur::geo::makeSegmentLine(a, s);
        QVERIFY(line.ok());
        for (int t = 0; t < a.segmentCount(); ++t) {
            if (t != s) {
                QVERIFY(line->segmentPoints(t) == a.segmentPoints(t));
                continue;
            }
            const auto c = line->segmentPoints(t);
            const Point chord = c[3] - c[0];
            for (int i = 1; i < 3; ++i) {
                const Point q = c[static_cast<std::size_t>(i)] - c[0];
                QVERIFY(std::abs(chord.x() * q.y() - chord.y() * q.x()) <= 1e-12 * chord.squaredNorm());
            }
        }
        auto twice = kontur::geo::reversed(*kontur::geo::reversed(a));
        QVERIFY(twice.ok() && twice->controlPoints() == a.controlPoints());

        CompositeCurve b = randomCurve(2 + (trial * 7) % 6);
        // Half the trials start b exactly on a's end (merged), half far away (a line between).
        const bool merge = trial % 2 == 0;
        if (merge)
            QVERIFY(b.moveKnot(0, a.knot(a.knotCount() - 1)).ok());
        auto joined = kontur::geo::joinComposites(a, b, {merge ? 1e-9 : 0.0, 30.0});
        QVERIFY(joined.ok());
        const std::size_t m = a.controlPoints().size();
        QVERIFY(std::equal(a.controlPoints().begin(), a.controlPoints().end(), joined->controlPoints().begin()));
        const auto &jc = joined->controlPoints();
        const auto &bc = b.controlPoints();
        const std::size_t offset = merge ? m - 1 : m + 2;
        QCOMPARE(jc.size(), offset + bc.size());
        for (std::size_t i = 2; i < bc.size(); ++i)
            QVERIFY(jc[offset + i] == bc[i]);
        QCOMPARE(joined->knotCount(), a.knotCount() + b.knotCount() - (merge ? 1 : 0));

        if (n >= 4) {
            CompositeCurve ring = a;
            QVERIFY(ring.moveKnot(n - 1, a.knot(0)).ok());
            auto closed = kontur::geo::closeJoined(ring, {1e-9, 30.0});
            QVERIFY(closed.ok() && closed->isClosed());
            QCOMPARE(closed->knotCount(), n - 1);
            for (int t = 0; t + 1 < ring.segmentCount(); ++t)
                if (closed->nodeType(0) == NodeType::Corner || (t > 0 && t + 2 < ring.segmentCount()))
                    QVERIFY(closed->segmentPoints(t) == ring.segmentPoints(t));
        }
    }
}

QTEST_MAIN(TestPieceEdits)
#include "tst_pieceedits.moc"
