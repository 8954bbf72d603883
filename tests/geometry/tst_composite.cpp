// The composite curve (docs/requirements.md 1.2, 1.4): construction oracles, incremental building, the three
// edits and node types with their exact invariants, knot insertion / deletion, closing, degenerate
// knots, and the continuity report (G1-only and C2 joints) of the piecewise form.
#include "geometry/arclength.h"
#include "geometry/composite.h"
#include "geometry/piecewise.h"
#include "testutil.h"

#include <QtTest>

#include <numbers>

#include <cmath>

using kontur::geo::Bezier;
using kontur::geo::CompositeCurve;
using kontur::geo::Continuity;
using kontur::geo::HandleMove;
using kontur::geo::NodeType;
using kontur::geo::Point;
using namespace kontur::test;

Q_DECLARE_METATYPE(std::vector<Point>)

namespace {

double cross(const Point &a, const Point &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

bool allFinite(const std::vector<Point> &pts)
{
    for (const auto &p : pts)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            return false;
    return true;
}

// Indices of control points changed between two states.
std::vector<int> changed(const std::vector<Point> &a, const std::vector<Point> &b)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] != b[i])
            out.push_back(static_cast<int>(i));
    return out;
}

bool inRange(int segment, const kontur::geo::SegmentRange &r, int segmentCount)
{
    for (int k = 0; k < r.count; ++k)
        if ((r.first + k) % segmentCount == segment)
            return true;
    return false;
}

} // namespace

class TestComposite final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void fromPieces();
    void construction_data();
    void construction();
    void incrementalEqualsBatch();
    void degenerateKnots_data();
    void degenerateKnots();
    void freeMoveKeepsCollinearityAndDistance();
    void freeMoveOntoKnot();
    void constrainedMove();
    void knotMove();
    void nodeTypes();
    void endHandlesMoveFreely();
    void editsTouchOnlyReportedSegments();
    void insertKeepsShape();
    void deleteKnot();
    void closeCurve();
    void closeMergesCoincidentEnds();
    void degenerateJointIsNotSmooth();
    void continuityOfSeedCurveIsG1();
    void continuityOfConstructedJoints();
    void piecewiseQueries();
};

void TestComposite::construction_data()
{
    QTest::addColumn<std::vector<Point>>("knots");
    QTest::addColumn<std::vector<Point>>("expected");
    // By hand from docs/requirements.md 1.2: p0 (0,0), p1 (3,0), p2 (3,4); l1 = 3, l2 = 4, p2 - p0 = (3,4).
    // c2 = p1 - ½·3/7·(3,4) = (33/14, -6/7); c4 = p1 + ½·4/7·(3,4) = (27/7, 8/7).
    // c1 mirrors c2 across x = 3/2: (9/14, -6/7); c5 mirrors c4 across y = 2: (27/7, 20/7).
    QTest::addRow("three knots") << std::vector<Point>{{0, 0}, {3, 0}, {3, 4}}
                                 << std::vector<Point>{{0, 0}, {9.0 / 14, -6.0 / 7}, {33.0 / 14, -6.0 / 7},
                                                       {3, 0}, {27.0 / 7, 8.0 / 7},  {27.0 / 7, 20.0 / 7},
                                                       {3, 4}};
    // Two knots: m = (1,0); c1 = p0 + R60 (1,0) = (1/2, √3/2); c2 = p1 + R60 (-1,0) = (3/2, -√3/2).
    const double h = std::sqrt(3.0) / 2;
    QTest::addRow("two knots S") << std::vector<Point>{{0, 0}, {2, 0}}
                                 << std::vector<Point>{{0, 0}, {0.5, h}, {1.5, -h}, {2, 0}};
    // Evenly spaced collinear knots: handles at thirds, the straight line.
    QTest::addRow("collinear") << std::vector<Point>{{0, 0}, {3, 0}, {6, 0}, {9, 0}}
                               << std::vector<Point>{{0, 0},   {1.5, 0}, {1.5, 0}, {3, 0},   {4.5, 0},
                                                     {4.5, 0}, {6, 0},   {7.5, 0}, {7.5, 0}, {9, 0}};
    QTest::addRow("one knot") << std::vector<Point>{{5, 5}} << std::vector<Point>{{5, 5}};
}

void TestComposite::construction()
{
    QFETCH(std::vector<Point>, knots);
    QFETCH(std::vector<Point>, expected);
    const CompositeCurve curve(knots);
    const auto &c = curve.controlPoints();
    QCOMPARE(c.size(), expected.size());
    if (knots.size() >= 2)
        QCOMPARE(c.size(), 3 * knots.size() - 2);
    for (std::size_t i = 0; i < c.size(); ++i)
        QVERIFY2((c[i] - expected[i]).norm() < 1e-14, qPrintable(QString::number(i) + str(c[i])));
}

void TestComposite::incrementalEqualsBatch()
{
    std::mt19937_64 rng(41);
    const auto knots = randomPoints(rng, 12);
    CompositeCurve building;
    for (std::size_t i = 0; i < knots.size(); ++i) {
        const auto r = building.appendKnot(knots[i]);
        QVERIFY(r.ok());
        // Segments appear from the 3rd knot on; the last one waits for "Done".
        QCOMPARE(building.visibleSegmentCount(), std::max(0, static_cast<int>(i) - 1));
        const CompositeCurve batch(std::span<const Point>(knots.data(), i + 1));
        for (std::size_t k = 0; k < batch.controlPoints().size(); ++k)
            QVERIFY((building.controlPoints()[k] - batch.controlPoints()[k]).norm() < 1e-12);
    }
    building.finish();
    QCOMPARE(building.visibleSegmentCount(), 11);
}

void TestComposite::degenerateKnots_data()
{
    QTest::addColumn<std::vector<Point>>("knots");
    QTest::addRow("all equal") << std::vector<Point>(5, Point(1, 1));
    QTest::addRow("two equal") << std::vector<Point>{{1, 1}, {1, 1}};
    QTest::addRow("coincident pair") << std::vector<Point>{{0, 0}, {0, 0}, {3, 1}, {4, 4}};
    QTest::addRow("coincident end") << std::vector<Point>{{0, 0}, {2, 0}, {3, 1}, {3, 1}};
    QTest::addRow("back and forth") << std::vector<Point>{{0, 0}, {2, 0}, {0, 0}, {2, 0}};
}

void TestComposite::degenerateKnots()
{
    QFETCH(std::vector<Point>, knots);
    CompositeCurve curve(knots);
    QVERIFY(allFinite(curve.controlPoints()));
    for (int i = 1; i + 1 < static_cast<int>(curve.controlPoints().size()); ++i) {
        if (CompositeCurve::isKnotIndex(i))
            continue;
        QVERIFY(curve.moveHandle(i, curve.controlPoints()[i] + Point(1, 1), HandleMove::Free).ok());
        QVERIFY(curve.moveHandle(i, curve.knot(curve.knotOfControl(i)), HandleMove::Free).ok());
        QVERIFY(curve.moveHandle(i, Point(3, 3), HandleMove::Constrained).ok());
        QVERIFY(allFinite(curve.controlPoints()));
    }
    const auto box = curve.toPiecewise().boundingBox();
    QVERIFY(allFinite({box.min(), box.max()}));
    for (const auto &j : curve.toPiecewise().continuity())
        QVERIFY(std::isfinite(j.angle) && std::isfinite(j.c1Jump) && std::isfinite(j.curvatureJump));
}

void TestComposite::freeMoveKeepsCollinearityAndDistance()
{
    std::mt19937_64 rng(42);
    for (int trial = 0; trial < 100; ++trial) {
        CompositeCurve curve(randomPoints(rng, 6));
        const int k = 1 + trial % 4;
        const bool outgoing = trial % 2 == 0;
        const int h = outgoing ? curve.outHandleIndex(k) : curve.inHandleIndex(k);
        const int o = outgoing ? curve.inHandleIndex(k) : curve.outHandleIndex(k);
        const Point knot = curve.knot(k);
        const double oppositeLength = (curve.controlPoints()[o] - knot).norm();
        const Point pointer = randomPoints(rng, 1)[0];
        QVERIFY(curve.moveHandle(h, pointer, HandleMove::Free).ok());
        QCOMPARE(curve.controlPoints()[h], pointer);
        const Point a = curve.controlPoints()[h] - knot, b = curve.controlPoints()[o] - knot;
        // Opposite directions and the opposite handle's own distance kept (docs/requirements.md 1.4).
        QVERIFY(std::abs(cross(a, b)) <= 1e-12 * a.norm() * b.norm() + 1e-12);
        QVERIFY(a.dot(b) < 0);
        QVERIFY(std::abs(b.norm() - oppositeLength) <= 1e-12 * std::max(1.0, oppositeLength));
        QCOMPARE(curve.knot(k), knot);
    }
}

void TestComposite::freeMoveOntoKnot()
{
    // The seed crashed here once: dragging a handle onto its knot divides by zero.
    CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}, {6, 4}});
    const Point opposite = curve.controlPoints()[curve.inHandleIndex(1)];
    QVERIFY(curve.moveHandle(curve.outHandleIndex(1), curve.knot(1), HandleMove::Free).ok());
    QCOMPARE(curve.controlPoints()[curve.outHandleIndex(1)], curve.knot(1));
    QCOMPARE(curve.controlPoints()[curve.inHandleIndex(1)], opposite);
    QVERIFY(allFinite(curve.controlPoints()));
}

void TestComposite::constrainedMove()
{
    std::mt19937_64 rng(43);
    for (int trial = 0; trial < 100; ++trial) {
        CompositeCurve curve(randomPoints(rng, 5));
        const int k = 1 + trial % 3;
        const int h = trial % 2 ? curve.outHandleIndex(k) : curve.inHandleIndex(k);
        const int o = trial % 2 ? curve.inHandleIndex(k) : curve.outHandleIndex(k);
        const Point knot = curve.knot(k);
        const Point opposite = curve.controlPoints()[o];
        const Point pointer = randomPoints(rng, 1)[0];
        QVERIFY(curve.moveHandle(h, pointer, HandleMove::Constrained).ok());
        // r = knot + (knot - opposite)/|knot - opposite| · |pointer - knot|; the opposite stays.
        const Point expected = knot + (knot - opposite).normalized() * (pointer - knot).norm();
        QVERIFY((curve.controlPoints()[h] - expected).norm() < 1e-12 * 100);
        QCOMPARE(curve.controlPoints()[o], opposite);
    }
}

void TestComposite::knotMove()
{
    std::mt19937_64 rng(44);
    for (int trial = 0; trial < 50; ++trial) {
        CompositeCurve curve(randomPoints(rng, 5));
        const int k = trial % 5;
        const auto before = curve.controlPoints();
        const Point to = randomPoints(rng, 1)[0];
        const Point delta = to - curve.knot(k);
        const auto range = curve.moveKnot(k, to);
        QVERIFY(range.ok());
        QCOMPARE(curve.knot(k), to);
        for (int idx : {curve.inHandleIndex(k), curve.outHandleIndex(k)})
            if (idx >= 0)
                QVERIFY((curve.controlPoints()[idx] - (before[idx] + delta)).norm() < 1e-12);
        // Only the knot's own segments change.
        for (int idx : changed(before, curve.controlPoints()))
            QVERIFY(std::abs(idx - 3 * k) <= 1);
    }
}

void TestComposite::nodeTypes()
{
    CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}, {6, 4}});
    const int in = curve.inHandleIndex(1), out = curve.outHandleIndex(1);
    const Point k = curve.knot(1);
    // Symmetric: the opposite handle mirrors the dragged one.
    QVERIFY(curve.setNodeType(1, NodeType::Symmetric).ok());
    QVERIFY(std::abs((curve.controlPoints()[in] - k).norm() - (curve.controlPoints()[out] - k).norm()) < 1e-12);
    QVERIFY(curve.moveHandle(out, Point(5, 1), HandleMove::Free).ok());
    QVERIFY((curve.controlPoints()[in] - (2 * k - Point(5, 1))).norm() < 1e-12);
    QVERIFY(curve.moveHandle(out, Point(4, 0), HandleMove::Constrained).ok());
    QVERIFY((curve.controlPoints()[in] + curve.controlPoints()[out] - 2 * k).norm() < 1e-12);
    // Corner: independent handles.
    QVERIFY(curve.setNodeType(1, NodeType::Corner).ok());
    const Point inBefore = curve.controlPoints()[in];
    QVERIFY(curve.moveHandle(out, Point(3, 2), HandleMove::Free).ok());
    QCOMPARE(curve.controlPoints()[in], inBefore);
    // Corner constrained keeps the handle's own direction: (0, 2) from the knot, length 5.
    QVERIFY(curve.moveHandle(out, Point(6, 4), HandleMove::Constrained).ok());
    QVERIFY((curve.controlPoints()[out] - Point(3, 5)).norm() < 1e-12);
    // Back to smooth: collinear again, lengths kept.
    const double la = (curve.controlPoints()[in] - k).norm(), lb = (curve.controlPoints()[out] - k).norm();
    QVERIFY(curve.setNodeType(1, NodeType::Smooth).ok());
    const Point a = curve.controlPoints()[in] - k, b = curve.controlPoints()[out] - k;
    QVERIFY(std::abs(cross(a, b)) < 1e-12 && a.dot(b) < 0);
    QVERIFY(std::abs(a.norm() - la) < 1e-12 && std::abs(b.norm() - lb) < 1e-12);
    QCOMPARE(curve.nodeType(1), NodeType::Smooth);
    QVERIFY(!curve.setNodeType(9, NodeType::Smooth).ok());
}

void TestComposite::endHandlesMoveFreely()
{
    CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}});
    const auto before = curve.controlPoints();
    for (HandleMove mode : {HandleMove::Free, HandleMove::Constrained}) {
        QVERIFY(curve.moveHandle(1, Point(-1, 7), mode).ok());
        QCOMPARE(curve.controlPoints()[1], Point(-1, 7));
        QVERIFY(curve.moveHandle(5, Point(9, 9), mode).ok());
        QCOMPARE(curve.controlPoints()[5], Point(9, 9));
    }
    for (int i : {0, 2, 3, 4, 6})
        QCOMPARE(curve.controlPoints()[i], before[i]);
    QVERIFY(!curve.moveHandle(3, Point(0, 0), HandleMove::Free).ok()); // a knot, not a handle
    QVERIFY(!curve.moveHandle(99, Point(0, 0), HandleMove::Free).ok());
    QVERIFY(!curve.moveKnot(-1, Point(0, 0)).ok());
}

void TestComposite::editsTouchOnlyReportedSegments()
{
    std::mt19937_64 rng(45);
    for (bool closed : {false, true}) {
        CompositeCurve curve(randomPoints(rng, 8));
        if (closed)
            QVERIFY(curve.close().ok());
        std::uniform_int_distribution<int> pick(0, static_cast<int>(curve.controlPoints().size()) - 1);
        for (int step = 0; step < 300; ++step) {
            const auto before = curve.controlPoints();
            const int ci = pick(rng);
            const auto range = curve.moveControlPoint(ci, randomPoints(rng, 1)[0],
                                                      step % 2 ? HandleMove::Free : HandleMove::Constrained);
            QVERIFY(range.ok());
            for (int idx : changed(before, curve.controlPoints())) {
                // A control point belongs to segment idx/3 (and a knot also to the one before).
                const int n = curve.segmentCount();
                const bool ok = inRange(std::min(idx / 3, n - 1), *range, n) ||
                                (idx % 3 == 0 && inRange((idx / 3 - 1 + n) % n, *range, n));
                QVERIFY2(ok, qPrintable(QStringLiteral("control %1 outside the reported range").arg(idx)));
            }
            if (closed)
                QCOMPARE(curve.controlPoints().front(), curve.controlPoints().back());
        }
    }
}

void TestComposite::insertKeepsShape()
{
    std::mt19937_64 rng(46);
    CompositeCurve curve(randomPoints(rng, 5));
    const auto before = curve.toPiecewise();
    QVERIFY(curve.insertKnot(2, 0.3).ok());
    QCOMPARE(curve.knotCount(), 6);
    QCOMPARE(curve.controlPoints().size(), std::size_t(16));
    // Old segment 2 is now segments 2 (t in [0, 0.3]) and 3 (t in [0.3, 1]).
    for (int k = 0; k <= 10; ++k) {
        const double u = k / 10.0;
        QVERIFY((curve.segment(2).eval(u) - before.segments()[2].eval(0.3 * u)).norm() < 1e-12 * 100);
        QVERIFY((curve.segment(3).eval(u) - before.segments()[2].eval(0.3 + 0.7 * u)).norm() < 1e-12 * 100);
        QVERIFY((curve.segment(4).eval(u) - before.segments()[3].eval(u)).norm() == 0.0);
    }
    QCOMPARE(curve.nodeType(3), NodeType::Smooth);
    QVERIFY(!curve.insertKnot(0, 0.0).ok());
    QVERIFY(!curve.insertKnot(7, 0.5).ok());
}

void TestComposite::deleteKnot()
{
    CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}, {6, 4}, {9, 0}});
    const auto before = curve.controlPoints();
    QVERIFY(curve.deleteKnot(2).ok());
    QCOMPARE(curve.knotCount(), 4);
    // Segment 1 joins knots 1 and 3 with their outer handles.
    const auto s = curve.segmentPoints(1);
    QCOMPARE(s[0], before[3]);
    QCOMPARE(s[1], before[4]);
    QCOMPARE(s[2], before[8]);
    QCOMPARE(s[3], before[9]);
    QVERIFY(curve.deleteKnot(0).ok());
    QVERIFY(curve.deleteKnot(curve.knotCount() - 1).ok());
    QCOMPARE(curve.knotCount(), 2);
    QCOMPARE(curve.controlPoints().size(), std::size_t(4));
    const auto refused = curve.deleteKnot(0);
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error().code, kontur::geo::ErrorCode::TooFewPoints);
}

void TestComposite::closeMergesCoincidentEnds()
{
    // Issue #17: a last knot on the first one is the closing already; no segment of length zero.
    CompositeCurve curve(std::vector<Point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}});
    QVERIFY(curve.close().ok());
    QCOMPARE(curve.knotCount(), 4);
    QCOMPARE(curve.segmentCount(), 4);
    QCOMPARE(curve.controlPoints().size(), std::size_t(13));
    // The same handles as the square closed without the duplicate (see closeCurve).
    QCOMPARE(curve.controlPoints()[1], Point(1, -1));
    QCOMPARE(curve.controlPoints()[11], Point(-1, 1));
    for (int s = 0; s < curve.segmentCount(); ++s) {
        const auto p = curve.segmentPoints(s);
        QVERIFY(p[0] != p[3]);
    }
    // Three knots with the last on the first are 2 distinct knots: too few to close, and unchanged.
    CompositeCurve three(std::vector<Point>{{0, 0}, {4, 0}, {0, 0}});
    const auto refused = three.close();
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error().code, kontur::geo::ErrorCode::TooFewPoints);
    QCOMPARE(three.knotCount(), 3);
    QVERIFY(!three.isClosed());
}

void TestComposite::degenerateJointIsNotSmooth()
{
    // Issue #17: handles on their knot at a right-angle corner: B' and B'' vanish on both sides, so
    // the derivatives "match", but the curve turns by 90°: G0 only, not C2.
    const Bezier left({Point(0, 0), Point(1, 0), Point(1, 0), Point(1, 0)});
    const Bezier right({Point(1, 0), Point(1, 0), Point(1, 0), Point(1, 1)});
    const auto j = kontur::geo::jointContinuity(left, right);
    QVERIFY(j.g0);
    QVERIFY(!j.g1 && !j.c1 && !j.g2 && !j.c2);
    QCOMPARE(j.level, kontur::geo::Continuity::G0);
    QVERIFY(std::abs(j.angle - std::numbers::pi / 2) < 1e-15);
    // The same zero-length handles on a straight joint: the tangent comes from the next control
    // point, G1 holds, and then C1 and C2 (both derivatives vanish) may be claimed.
    const Bezier straight({Point(1, 0), Point(1, 0), Point(1, 0), Point(2, 0)});
    const auto s = kontur::geo::jointContinuity(left, straight);
    QVERIFY(s.g1 && s.c1);
    QCOMPARE(s.level, kontur::geo::Continuity::C2);
    // At 1e-170 (squares underflow) the same answers.
    const Bezier tinyLeft = left.transformed(Eigen::Matrix2d::Identity() * 1e-170, Point(0, 0));
    const Bezier tinyRight = right.transformed(Eigen::Matrix2d::Identity() * 1e-170, Point(0, 0));
    QCOMPARE(kontur::geo::jointContinuity(tinyLeft, tinyRight).level, kontur::geo::Continuity::G0);
}

void TestComposite::closeCurve()
{
    const std::vector<Point> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    CompositeCurve curve(square);
    QVERIFY(curve.close().ok());
    QVERIFY(curve.isClosed());
    QCOMPARE(curve.segmentCount(), 4);
    QCOMPARE(curve.controlPoints().size(), std::size_t(13));
    QCOMPARE(curve.controlPoints().back(), curve.controlPoints().front());
    // Every knot is interior now: handles by the construction rule with wrapped neighbours, written
    // out: equal neighbour distances (4 and 4) put them at p ∓ (next - prev)/4.
    const std::array<std::pair<Point, Point>, 4> handles = {{{Point(-1, 1), Point(1, -1)},
                                                             {Point(3, -1), Point(5, 1)},
                                                             {Point(5, 3), Point(3, 5)},
                                                             {Point(1, 5), Point(-1, 3)}}};
    for (int k = 0; k < 4; ++k) {
        QVERIFY((curve.controlPoints()[curve.inHandleIndex(k)] - handles[k].first).norm() < 1e-14);
        QVERIFY((curve.controlPoints()[curve.outHandleIndex(k)] - handles[k].second).norm() < 1e-14);
    }
    for (const auto &j : curve.toPiecewise().continuity())
        QVERIFY(j.g1);
    QCOMPARE(curve.toPiecewise().continuity().size(), std::size_t(4));
    // Moving knot 0 moves the repeated last point too.
    QVERIFY(curve.moveKnot(0, Point(-1, -1)).ok());
    QCOMPARE(curve.controlPoints().back(), Point(-1, -1));
    // Deleting knot 0 of a closed curve merges the closing segment with segment 0.
    QVERIFY(curve.deleteKnot(0).ok());
    QCOMPARE(curve.knotCount(), 3);
    QCOMPARE(curve.controlPoints().size(), std::size_t(10));
    QCOMPARE(curve.controlPoints().back(), curve.controlPoints().front());
    QVERIFY(!curve.deleteKnot(0).ok());
    QVERIFY(!curve.close().ok());
    QVERIFY(!curve.appendKnot(Point(1, 1)).ok());
    CompositeCurve two(std::vector<Point>{{0, 0}, {1, 0}});
    QVERIFY(!two.close().ok());
}

void TestComposite::continuityOfSeedCurveIsG1()
{
    // docs/requirements.md 1.2: the seed calls its composite curve C²; with unequal knot spacing it is only G¹.
    const CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}, {10, 4}});
    const auto joints = curve.toPiecewise().continuity();
    QCOMPARE(joints.size(), std::size_t(2));
    for (const auto &j : joints) {
        QVERIFY(j.g0 && j.g1);
        QVERIFY(!j.c1 && !j.c2);
        QCOMPARE(j.level, Continuity::G1);
        QVERIFY(j.c1Jump > 0.1);
        QVERIFY(j.angle < 1e-12);
    }
    QCOMPARE(QString::fromLatin1(kontur::geo::nameOf(joints[0].level)), QStringLiteral("G1"));
}

void TestComposite::continuityOfConstructedJoints()
{
    const Bezier c({{0, 0}, {1, 3}, {4, 3}, {6, -1}});
    // Split at 1/2: the halves join C² in their own parameters (both scaled by 1/2).
    {
        const auto [l, r] = c.split(0.5);
        const auto j = kontur::geo::jointContinuity(l, r);
        QCOMPARE(j.level, Continuity::C2);
        QVERIFY(j.g1 && j.c1 && j.g2 && j.c2);
    }
    // Split at 0.3: the same geometry (G²) but the derivatives scale by 0.3 and 0.7: not C¹.
    {
        const auto [l, r] = c.split(0.3);
        const auto j = kontur::geo::jointContinuity(l, r);
        QVERIFY(j.g2 && !j.c1 && !j.c2);
        QCOMPARE(j.level, Continuity::G2);
    }
    // A corner: G0 only, with the angle measured.
    {
        const Bezier a({{0, 0}, {1, 0}, {2, 0}, {3, 0}});
        const Bezier b({{3, 0}, {3, 1}, {3, 2}, {3, 3}});
        const auto j = kontur::geo::jointContinuity(a, b);
        QCOMPARE(j.level, Continuity::G0);
        QVERIFY(std::abs(j.angle - M_PI / 2) < 1e-14);
    }
    // A gap.
    {
        const Bezier a({{0, 0}, {1, 0}});
        const Bezier b({{1, 1}, {2, 1}});
        const auto j = kontur::geo::jointContinuity(a, b);
        QCOMPARE(j.level, Continuity::None);
        QCOMPARE(j.gap, 1.0);
    }
    // A handle on its knot: the tangent comes from the next control point, still G1.
    {
        const Bezier a({{0, 0}, {1, 0}, {2, 0}, {2, 0}});
        const Bezier b({{2, 0}, {3, 0}, {4, 1}, {5, 1}});
        const auto j = kontur::geo::jointContinuity(a, b);
        QVERIFY(j.g1);
    }
    // Equally spaced composite knots give C1 joints.
    const CompositeCurve even(std::vector<Point>{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
    for (const auto &j : even.toPiecewise().continuity())
        QVERIFY(j.c1);
}

void TestComposite::piecewiseQueries()
{
    const CompositeCurve curve(std::vector<Point>{{0, 0}, {3, 0}, {3, 4}, {10, 4}});
    const auto pw = curve.toPiecewise();
    // The control points by docs/requirements.md 1.2, and the length by composite Simpson's rule with 40000
    // intervals per segment, both computed independently of the library and written out.
    const std::array<Point, 10> expected = {
        Point(0, 0), Point(0.642857142857143, -0.8571428571428571), Point(2.357142857142857, -0.8571428571428571),
        Point(3, 0), Point(3.857142857142857, 1.1428571428571428),  Point(1.7272727272727273, 3.2727272727272725),
        Point(3, 4), Point(5.227272727272727, 5.2727272727272725),  Point(7.772727272727273, 5.2727272727272725),
        Point(10, 4)};
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY((curve.controlPoints()[i] - expected[i]).norm() < 1e-14);
    QVERIFY(std::abs(pw.length(1e-11) - 15.0053833731444) < 1e-10);
    const auto box = pw.boundingBox();
    for (int k = 0; k <= 300; ++k)
        QVERIFY(box.contains(pw.eval(k / 100.0)));
    const auto n = pw.nearest(Point(3, 2));
    QVERIFY(n.distance < 0.5);
    QVERIFY((pw.segments()[n.segment].eval(n.t) - n.point).norm() < 1e-12);
    double sampled = 1e300;
    for (int k = 0; k <= 3000; ++k)
        sampled = std::min(sampled, (pw.eval(k / 1000.0) - Point(3, 2)).norm());
    QVERIFY(n.distance <= sampled + 1e-12);
    std::vector<Point> poly;
    pw.flatten(0.01, poly);
    QCOMPARE(poly.front(), Point(0, 0));
    QCOMPARE(poly.back(), Point(10, 4));
}

// Exact pieces as a composite curve (split at t, splines made editable): elevation keeps the curve,
// joints are typed by their continuity, and what no composite curve can be is refused.
void TestComposite::fromPieces()
{
    using kontur::geo::compositeFromPieces;
    const Bezier line({Point(0, 0), Point(3, 3)});
    const Bezier quadratic({Point(3, 3), Point(4.5, 4.5), Point(9, 3)});         // starts at (3, 3)/unit: C1
    const Bezier cubic({Point(9, 3), Point(10, 2), Point(12, 2), Point(13, 3)}); // (9, -3) against (3, -3)
    const Bezier last({Point(13, 3), Point(15, 5)});                             // (3, 3) against (2, 2): G1
    const std::vector<Bezier> pieces{line, quadratic, cubic, last};
    auto c = compositeFromPieces(pieces, false);
    QVERIFY(c.ok());
    QCOMPARE(c->knotCount(), 5);
    QCOMPARE(c->segmentCount(), 4);
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k <= 10; ++k)
            QVERIFY((c->segment(i).eval(k / 10.0) - pieces[static_cast<std::size_t>(i)].eval(k / 10.0)).norm() < 1e-12);
    QCOMPARE(c->nodeType(1), NodeType::Symmetric);
    QCOMPARE(c->nodeType(2), NodeType::Corner);
    QCOMPARE(c->nodeType(3), NodeType::Smooth);
    // Degree 4 is no cubic; pieces that do not meet are no curve.
    QCOMPARE(compositeFromPieces(std::vector<Bezier>{Bezier(std::vector<Point>(5, Point(1, 1)))}, false).error().code,
             kontur::geo::ErrorCode::InvalidArgument);
    QVERIFY(!compositeFromPieces(std::vector<Bezier>{line, cubic}, false).ok());
    QCOMPARE(compositeFromPieces(std::vector<Bezier>{}, false).error().code, kontur::geo::ErrorCode::TooFewPoints);
    // Closed: three pieces round a triangle, the last ending where the first begins.
    const std::vector<Bezier> triangle{Bezier({Point(0, 0), Point(4, 0)}), Bezier({Point(4, 0), Point(0, 3)}),
                                       Bezier({Point(0, 3), Point(0, 0)})};
    auto closed = compositeFromPieces(triangle, true);
    QVERIFY(closed.ok());
    QVERIFY(closed->isClosed());
    QCOMPARE(closed->knotCount(), 3);
    QCOMPARE(closed->nodeType(0), NodeType::Corner);
    QVERIFY(!compositeFromPieces(std::vector<Bezier>(triangle.begin(), triangle.begin() + 2), true).ok());
}

QTEST_APPLESS_MAIN(TestComposite)
#include "tst_composite.moc"
