// The nearest point on a segment and on a polyline (geometry/polyline.h) against hand-computed
// values and, for random polylines, against the distance to each segment found another way (the
// perpendicular foot when it falls within the segment, else the nearer end).
#include "geometry/polyline.h"

#include <QtTest>

#include <cmath>
#include <random>

using kontur::geo::Point;
namespace geo = kontur::geo;

namespace {

double crossOf(const Point &a, const Point &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

double distanceToSegment(const Point &p, const Point &a, const Point &b)
{
    const Point ab = b - a;
    if (ab.norm() > 0.0 && (p - a).dot(ab) > 0.0 && (p - b).dot(a - b) > 0.0)
        return std::abs(crossOf(ab, p - a)) / ab.norm();
    return std::min((p - a).norm(), (p - b).norm());
}

} // namespace

class TestPolyline final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void segmentByHand()
    {
        const Point a(0, 0), b(10, 0);
        QCOMPARE(geo::nearestSegmentParameter(Point(5, 5), a, b), 0.5);
        QCOMPARE(geo::nearestOnSegment(Point(5, 5), a, b), Point(5, 0));
        QCOMPARE(geo::nearestOnSegment(Point(-3, 4), a, b), a);  // before the start
        QCOMPARE(geo::nearestOnSegment(Point(13, -1), a, b), b); // past the end
        QCOMPARE(geo::nearestSegmentParameter(Point(2, 7), a, a), 0.0);
        QCOMPARE(geo::nearestOnSegment(Point(2, 7), a, a), a);
    }

    void closedAndOpen()
    {
        const std::vector<Point> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
        // Beside the closing side: closed, it is the nearest; open, the two ends tie and the first wins.
        const auto closed = geo::nearestOnPolyline(square, Point(-1, 5), true);
        QCOMPARE(closed.point, Point(0, 5));
        QCOMPARE(closed.segment, std::size_t(3));
        const auto open = geo::nearestOnPolyline(square, Point(-1, 5), false);
        QCOMPARE(open.point, Point(0, 0));
        QCOMPARE(open.segment, std::size_t(0));
        const auto inside = geo::nearestOnPolyline(square, Point(7, 4), true);
        QCOMPARE(inside.point, Point(10, 4));
        QCOMPARE(inside.segment, std::size_t(1));
        const auto one = geo::nearestOnPolyline({Point(3, 4)}, Point(0, 0), false);
        QCOMPARE(one.point, Point(3, 4));
        QCOMPARE(one.segment, std::size_t(0));
        QCOMPARE(geo::nearestOnPolyline({}, Point(1, 1), true).point, Point(0, 0));
    }

    void randomPolylines()
    {
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> coord(-50.0, 50.0);
        std::uniform_int_distribution<int> count(2, 9);
        for (int trial = 0; trial < 500; ++trial) {
            std::vector<Point> pts(static_cast<std::size_t>(count(rng)));
            for (auto &q : pts)
                q = Point(coord(rng), coord(rng));
            if (trial % 5 == 0)
                pts[1] = pts[0]; // a segment of no length
            const Point p(coord(rng), coord(rng));
            const bool closed = trial % 2 == 0;
            const std::size_t n = pts.size(), segments = closed ? n : n - 1;
            double best = INFINITY;
            for (std::size_t i = 0; i < segments; ++i)
                best = std::min(best, distanceToSegment(p, pts[i], pts[(i + 1) % n]));
            const auto found = geo::nearestOnPolyline(pts, p, closed);
            QVERIFY(found.segment < segments);
            QVERIFY2(std::abs((found.point - p).norm() - best) < 1e-9, qPrintable(QString::number(trial)));
            // The point lies on its segment.
            const Point a = pts[found.segment], b = pts[(found.segment + 1) % n];
            QVERIFY(distanceToSegment(found.point, a, b) < 1e-9);
        }
    }
};

QTEST_APPLESS_MAIN(TestPolyline)
#include "tst_polyline.moc"
