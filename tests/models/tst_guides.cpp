// Curve::guides(): which rows each kind joins by guide lines, written out per kind from its row
// layout (docs/requirements.md 1: defining points first, then derived ones).
#include "models/document/curve.h"

#include <QTest>

#include <utility>
#include <vector>

using namespace kontur;

namespace {

using Pairs = std::vector<std::pair<int, int>>;

std::vector<geo::Point> points(int n)
{
    std::vector<geo::Point> out;
    for (int i = 0; i < n; ++i)
        out.emplace_back(10.0 * i, (i % 2 == 0) ? 0.0 : 7.0 + i);
    return out;
}

} // namespace

class TestGuides : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void controlPolygons()
    {
        // Bézier: the control polygon through all control points.
        const Curve bezier = Curve::make(CurveKind::Bezier, points(4));
        QCOMPARE(bezier.guides(), (Pairs{{0, 1}, {1, 2}, {2, 3}}));
        // B-spline: the control polygon of its 5 control points; rows after them are not in it.
        const Curve bspline = Curve::make(CurveKind::BSpline, points(5));
        QCOMPARE(bspline.guides(), (Pairs{{0, 1}, {1, 2}, {2, 3}, {3, 4}}));
        // A single control point has no polygon.
        QCOMPARE(Curve::make(CurveKind::Bezier, points(1)).guides(), Pairs{});
    }

    void fittedCubics()
    {
        // 4 knots, then the fitted cubic's 4 control points (rows 4–7): their polygon.
        const Curve interpolating = Curve::make(CurveKind::Interpolating, points(4));
        QCOMPARE(interpolating.rowCount(), 8);
        QCOMPARE(interpolating.guides(), (Pairs{{4, 5}, {5, 6}, {6, 7}}));
        // 6 knots, then the closest cubic's control points (rows 6–9).
        const Curve leastSquares = Curve::make(CurveKind::LeastSquares, points(6));
        QCOMPARE(leastSquares.rowCount(), 10);
        QCOMPARE(leastSquares.guides(), (Pairs{{6, 7}, {7, 8}, {8, 9}}));
    }

    void compositeHandles()
    {
        // Rows: knot 0, handles 1 and 2, knot 3, handles 4 and 5, knot 6. Each handle to its knot.
        Curve open = Curve::make(CurveKind::Composite, points(3));
        QCOMPARE(open.rowCount(), 7);
        QCOMPARE(open.guides(), (Pairs{{1, 0}, {2, 3}, {4, 3}, {5, 6}}));
        // Closed: two more handles (7, 8); the last one belongs to knot 0 again.
        QVERIFY(open.close().ok());
        QCOMPARE(open.rowCount(), 9);
        QCOMPARE(open.guides(), (Pairs{{1, 0}, {2, 3}, {4, 3}, {5, 6}, {7, 6}, {8, 0}}));
    }

    void tangentEnds()
    {
        // Clamped and global B-spline: 4 knots, then the start tangent's end (row 4, from knot 0)
        // and the end tangent's end (row 5, from knot 3).
        for (CurveKind kind : {CurveKind::ClampedSpline, CurveKind::GlobalBSpline}) {
            const Curve curve = Curve::make(kind, points(4));
            QCOMPARE(curve.guides(), (Pairs{{0, 4}, {3, 5}}));
        }
        // Hermite: one tangent end per knot, rows 3, 4, 5 for knots 0, 1, 2.
        const Curve hermite = Curve::make(CurveKind::HermiteSpline, points(3));
        QCOMPARE(hermite.guides(), (Pairs{{0, 3}, {1, 4}, {2, 5}}));
    }

    void noGuides()
    {
        // Kinds whose points are all on the curve draw no guide lines.
        for (CurveKind kind : {CurveKind::NaturalSpline, CurveKind::NotAKnotSpline, CurveKind::PeriodicSpline,
                               CurveKind::CatmullRom, CurveKind::Polynomial, CurveKind::FunctionSpline}) {
            const Curve curve = Curve::make(kind, points(5));
            QVERIFY2(curve.guides().empty(), qPrintable(QString::number(static_cast<int>(kind))));
        }
    }
};

QTEST_GUILESS_MAIN(TestGuides)
#include "tst_guides.moc"
