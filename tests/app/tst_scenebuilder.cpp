// The scene builder without a window: the display lists for small documents at a given view,
// checked against coordinates worked out by hand from the view (item x = w/2 + (x − cx)·zoom,
// item y = h/2 − (y − cy)·zoom).
#include "app/scenebuilder.h"
#include "geometry/composite.h"
#include "models/document/curve.h"

#include <QTest>

#include <algorithm>
#include <vector>

using namespace kontur;

namespace {

// A 400 × 300 item at zoom 2 centred on the world origin: (0, 0) is at (200, 150).
SceneInput inputFor(const std::vector<Curve> &curves)
{
    SceneInput input;
    input.curves = &curves;
    input.view = {2.0, QPointF(0, 0), QSizeF(400, 300)};
    return input;
}

SceneStyle noGrid()
{
    SceneStyle style;
    style.showGrid = false;
    return style;
}

std::vector<QPointF> pointsOf(const Stroke &stroke)
{
    return stroke.points;
}

} // namespace

class TestSceneBuilder final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void gridAtZoomOne()
    {
        // 100 × 100 at zoom 1: the step is 50 (the smallest of 1, 2, 5 × 10^k ≥ 40 px), lines at
        // world −50, 0, 50 (item 0, 50, 100), then the two axes through the origin.
        QCOMPARE(gridStepAt(1.0), 50.0);
        QCOMPARE(gridStepAt(0.5), 100.0);
        QCOMPARE(gridStepAt(3.0), 20.0);
        ScreenLists lists;
        SceneInput input;
        input.view = {1.0, QPointF(0, 0), QSizeF(100, 100)};
        const SceneStyle style;
        buildScene(input, style, lists);
        const auto &grid = lists.grid.strokes;
        QCOMPARE(grid.size(), std::size_t(8));
        const std::vector<std::vector<QPointF>> expected{
            {{0, 0}, {0, 100}},     {{50, 0}, {50, 100}}, {{100, 0}, {100, 100}}, // x = −50, 0, 50
            {{0, 100}, {100, 100}}, {{0, 50}, {100, 50}}, {{0, 0}, {100, 0}},     // y = −50, 0, 50
            {{50, 0}, {50, 100}},   {{0, 50}, {100, 50}}};                        // the axes
        for (std::size_t i = 0; i < expected.size(); ++i) {
            QCOMPARE(pointsOf(grid[i]), expected[i]);
            QCOMPARE(grid[i].color, i < 6 ? style.grid : style.axis);
        }
        // Nothing else without curves.
        QVERIFY(lists.guides.strokes.empty() && lists.top.discs.empty() && lists.live.strokes.empty());
    }

    void bezierSegmentGuidesAndMarkers()
    {
        // A Bézier line from (0, 0) to (100, 0): item (200, 150) to (400, 150).
        const std::vector<Curve> curves{Curve::make(CurveKind::Bezier, {geo::Point(0, 0), geo::Point(100, 0)})};
        const SceneStyle style = noGrid();
        ScreenLists lists;
        buildScene(inputFor(curves), style, lists);
        QVERIFY(lists.grid.strokes.empty());
        // The control polygon is a guide.
        QCOMPARE(lists.guides.strokes.size(), std::size_t(1));
        QCOMPARE(pointsOf(lists.guides.strokes[0]), (std::vector<QPointF>{{200, 150}, {400, 150}}));
        QCOMPARE(lists.guides.strokes[0].color, style.polygon);
        // Control points: a white disc with a red ring each; no filled knot dots.
        QCOMPARE(lists.top.discs.size(), std::size_t(2));
        QCOMPARE(lists.top.rings.size(), std::size_t(2));
        for (std::size_t i = 0; i < 2; ++i) {
            const QPointF at(200.0 + 200.0 * static_cast<double>(i), 150.0);
            QCOMPARE(lists.top.discs[i].center, at);
            QCOMPARE(lists.top.discs[i].color, QColor(Qt::white));
            QCOMPARE(lists.top.rings[i].center, at);
            QCOMPARE(lists.top.rings[i].color, style.controlPoint);
            QCOMPARE(lists.top.rings[i].radius, 4.5F);
        }
        // On GPU backends the curve itself is not in the lists (a stroke node draws it).
        QVERIFY(lists.live.strokes.empty());
    }

    void knotsAreDotsTangentEndsAreDiamonds()
    {
        // Hermite spline: knots (0, 0), (50, 0), (100, 0) as filled dots in the curve colour; the
        // tangent ends (0, 20), (50, 20), (100, 20) as diamonds (item y 110), each joined by a
        // guide to its knot.
        const auto hermite = Curve::restore(
            CurveKind::HermiteSpline, {geo::Point(0, 0), geo::Point(50, 0), geo::Point(100, 0)},
            {geo::Point(0, 20), geo::Point(50, 20), geo::Point(100, 20)}, 0, geo::Parameterization::Uniform);
        QVERIFY(hermite.ok());
        const std::vector<Curve> curves{hermite.value()};
        const SceneStyle style = noGrid();
        ScreenLists lists;
        buildScene(inputFor(curves), style, lists);
        std::vector<QPointF> knotDots;
        for (const Disc &disc : lists.top.discs)
            if (disc.color == style.curve)
                knotDots.push_back(disc.center);
        QCOMPARE(knotDots, (std::vector<QPointF>{{200, 150}, {300, 150}, {400, 150}}));
        QCOMPARE(lists.top.overlay.size(), std::size_t(3));
        QCOMPARE(lists.guides.strokes.size(), std::size_t(3));
        const double r = 4.5 * 1.3; // a diamond's half diagonal
        for (std::size_t k = 0; k < 3; ++k) {
            const QPointF end(200.0 + 100.0 * static_cast<double>(k), 110.0);
            const Stroke &diamond = lists.top.overlay[k];
            QCOMPARE(diamond.color, style.tangent);
            QVERIFY(diamond.closed);
            QCOMPARE(pointsOf(diamond), (std::vector<QPointF>{end + QPointF(0, -r), end + QPointF(r, 0),
                                                              end + QPointF(0, r), end + QPointF(-r, 0)}));
            QCOMPARE(pointsOf(lists.guides.strokes[k]), (std::vector<QPointF>{knotDots[k], end}));
            QCOMPARE(lists.guides.strokes[k].color, style.polygon);
        }
        QVERIFY(lists.top.rings.empty());
    }

    void compositeHandlesOnlyAroundTheSelectedKnot_data()
    {
        QTest::addColumn<bool>("closed");
        QTest::addColumn<int>("selectedRow"); // -1: the curve is not selected
        QTest::addColumn<QList<int>>("knotsWithHandles");
        QTest::newRow("not selected") << false << -1 << QList<int>{};
        QTest::newRow("knot 10") << false << 30 << QList<int>{9, 10, 11};
        QTest::newRow("a handle of knot 10") << false << 31 << QList<int>{9, 10, 11};
        QTest::newRow("first knot, open") << false << 0 << QList<int>{0, 1};
        QTest::newRow("first knot, closed") << true << 0 << QList<int>{35, 0, 1};
    }

    void compositeHandlesOnlyAroundTheSelectedKnot()
    {
        // A traced curve of 36 knots (35 segments open, 36 closed): its knots are always drawn, its
        // handles (white discs with red rings, each with a guide to its knot) only those of the
        // selected knot and its neighbours; today's 100 rings made such a curve unreadable.
        QFETCH(bool, closed);
        QFETCH(int, selectedRow);
        QFETCH(QList<int>, knotsWithHandles);
        std::vector<geo::Point> knots;
        for (int k = 0; k < 36; ++k)
            knots.emplace_back(2.0 * k, k % 2 == 0 ? 0.0 : 10.0);
        geo::CompositeCurve composite(knots);
        if (closed)
            QVERIFY(composite.close().ok());
        auto made = Curve::makeComposite(std::move(composite));
        QVERIFY(made.ok());
        const std::vector<Curve> curves{made.value()};
        const Curve &curve = curves.front();
        SceneInput input = inputFor(curves);
        input.selectedCurve = selectedRow >= 0 ? 0 : -1;
        input.selectedPoint = selectedRow;
        const SceneStyle style = noGrid();
        ScreenLists lists;
        buildScene(input, style, lists);

        const auto at = [&](int row) {
            const geo::Point p = curve.row(row).position;
            return QPointF(200.0 + 2.0 * p.x(), 150.0 - 2.0 * p.y());
        };
        std::vector<QPointF> expectedRings;
        for (int r = 0; r < curve.rowCount(); ++r) {
            if (curve.isKnotRow(r))
                continue;
            if (knotsWithHandles.contains(curve.knotOfRow(r)))
                expectedRings.push_back(at(r));
        }
        std::vector<QPointF> rings;
        for (const Ring &ring : lists.top.rings)
            rings.push_back(ring.center);
        std::sort(rings.begin(), rings.end(),
                  [](QPointF a, QPointF b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
        std::sort(expectedRings.begin(), expectedRings.end(),
                  [](QPointF a, QPointF b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
        QCOMPARE(rings, expectedRings);
        // Every knot is a dot in the curve's colour.
        const auto dots = std::count_if(lists.top.discs.begin(), lists.top.discs.end(),
                                        [&](const Disc &d) { return d.color == style.curve; });
        QCOMPARE(dots, 36);
        // A guide from each shown handle to its knot, and none to a hidden one.
        std::size_t guidePoints = 0;
        for (const Stroke &guide : lists.guides.strokes) {
            for (const QPointF &p : guide.points)
                QVERIFY(std::find(expectedRings.begin(), expectedRings.end(), p) != expectedRings.end() ||
                        std::any_of(lists.top.discs.begin(), lists.top.discs.end(),
                                    [&](const Disc &d) { return d.color == style.curve && d.center == p; }));
            guidePoints += guide.points.size();
        }
        QCOMPARE(guidePoints == 0, expectedRings.empty());
    }

    void selectedCurveOnTopInSoftware()
    {
        // Two Bézier lines; the second is selected, with its point 1 (world (100, 20): item
        // (400, 110)). Its world flattening (0, 20), (50, 20), (50.1, 20), (100, 20) shows at
        // y = 110 with the point 0.2 px after (300, 110) left out (under a quarter pixel).
        const std::vector<Curve> curves{Curve::make(CurveKind::Bezier, {geo::Point(0, 0), geo::Point(100, 0)}),
                                        Curve::make(CurveKind::Bezier, {geo::Point(0, 20), geo::Point(100, 20)})};
        const std::vector<geo::Point> flat{geo::Point(0, 20), geo::Point(50, 20), geo::Point(50.1, 20),
                                           geo::Point(100, 20)};
        SceneInput input = inputFor(curves);
        input.software = true;
        input.selectedCurve = 1;
        input.selectedPoint = 1;
        input.selectedFlat = &flat;
        const SceneStyle style = noGrid();
        ScreenLists lists;
        buildScene(input, style, lists);
        // Software: halo, both control polygons, then the selected line last, over everything else.
        const auto &live = lists.live.strokes;
        QCOMPARE(live.size(), std::size_t(4));
        const std::vector<QPointF> line{{200, 110}, {300, 110}, {400, 110}};
        QCOMPARE(pointsOf(live.front()), line);
        QCOMPARE(live.front().width, 2.0F + 6.0F);
        QCOMPARE(live.front().color.alpha(), 77); // the accent at 30 %
        QCOMPARE(pointsOf(live[1]), (std::vector<QPointF>{{200, 150}, {400, 150}}));
        QCOMPARE(pointsOf(live[2]), (std::vector<QPointF>{{200, 110}, {400, 110}}));
        QCOMPARE(pointsOf(live.back()), line);
        QCOMPARE(live.back().color, curves[1].color);
        QCOMPARE(live.back().width, 2.0F);
        QVERIFY(lists.guides.strokes.empty());
        // The selected point gets the accent disc under its marker.
        QCOMPARE(lists.top.discs.size(), std::size_t(5));
        QCOMPARE(lists.top.discs[3].center, QPointF(400, 110));
        QCOMPARE(lists.top.discs[3].color, style.accent);
        QCOMPARE(lists.top.discs[3].radius, 4.5F + 4.0F);
    }

    void placementPreview()
    {
        // Placing a Bézier curve: the points so far as control points with their polygon, the
        // preview line (a straight segment flattens to its ends) and the dashed rubber band to
        // the pointer: 6 px dashes, 4 px gaps from (400, 150) towards (400, 170).
        const std::vector<Curve> none;
        const std::vector<geo::Point> pending{geo::Point(0, 0), geo::Point(100, 0)};
        SceneInput input = inputFor(none);
        input.pendingPoints = &pending;
        input.pendingSegments = {geo::Bezier({geo::Point(0, 0), geo::Point(100, 0)})};
        input.placementKind = CurveKind::Bezier;
        input.hover = geo::Point(100, -10);
        const SceneStyle style = noGrid();
        ScreenLists lists;
        buildScene(input, style, lists);
        const auto &strokes = lists.top.strokes;
        QCOMPARE(strokes.size(), std::size_t(4));
        QCOMPARE(pointsOf(strokes[0]), (std::vector<QPointF>{{200, 150}, {400, 150}}));
        QCOMPARE(strokes[0].color, style.polygon);
        QCOMPARE(pointsOf(strokes[1]), (std::vector<QPointF>{{200, 150}, {400, 150}}));
        QCOMPARE(strokes[1].color, style.curve);
        QCOMPARE(pointsOf(strokes[2]), (std::vector<QPointF>{{400, 150}, {400, 156}}));
        QCOMPARE(pointsOf(strokes[3]), (std::vector<QPointF>{{400, 160}, {400, 166}}));
        QCOMPARE(lists.top.rings.size(), std::size_t(2));
    }

    void rubberBandFromFarOutOfViewIsClipped()
    {
        // The last point placed 10^12 px off screen (zoomed far in), the pointer in view: only the
        // band's visible part is dashed (the view and 50 px around it), not 10^11 dashes.
        const std::vector<Curve> none;
        const std::vector<geo::Point> pending{geo::Point(-5e11, 0)};
        SceneInput input = inputFor(none);
        input.pendingPoints = &pending;
        input.placementKind = CurveKind::Bezier;
        input.hover = geo::Point(50, 0); // (300, 150) on screen
        ScreenLists lists;
        buildScene(input, noGrid(), lists);
        std::size_t dashes = 0;
        for (const Stroke &stroke : lists.top.strokes) {
            if (stroke.points.size() != 2 || stroke.points.front().y() != 150)
                continue;
            ++dashes;
            for (const QPointF &p : stroke.points)
                QVERIFY(p.x() >= -50.0 - 1e-6 && p.x() <= 300.0 + 1e-6);
        }
        QVERIFY2(dashes >= 30 && dashes <= 36, qPrintable(QString::number(dashes))); // 350 px / 10 px
        // A band wholly out of view: nothing.
        input.hover = geo::Point(-4e11, 0);
        buildScene(input, noGrid(), lists);
        for (const Stroke &stroke : lists.top.strokes)
            QVERIFY(stroke.points.size() != 2 || stroke.points.front().y() != 150 || stroke.points.front().x() > -51);
    }
};

QTEST_GUILESS_MAIN(TestSceneBuilder)
#include "tst_scenebuilder.moc"
