// Seed 004's contour curve (issue 20): the pieces for 5, 7, 8, 9 and 10 points written out by hand
// from the listing of §8.1, C1 at every joint between cubics, the last piece of lower degree joined
// along the same tangent (C1 on a parameter interval of 2/3 or 1/3), and random inputs.
#include "geometry/piecewise.h"
#include "geometry/splines/contour.h"

#include <QRandomGenerator>
#include <QtTest>

using kontur::geo::Bezier;
using kontur::geo::contourJoints;
using kontur::geo::contourPieces;
using kontur::geo::ErrorCode;
using kontur::geo::Point;

namespace {

// P_i = (i, i² mod 7): no three consecutive points on a line, exact halves.
std::vector<Point> numbered(int n)
{
    std::vector<Point> p;
    for (int i = 0; i < n; ++i)
        p.emplace_back(i, (i * i) % 7);
    return p;
}

Point mid(const std::vector<Point> &p, int a, int b)
{
    return (p[static_cast<std::size_t>(a)] + p[static_cast<std::size_t>(b)]) / 2.0;
}

} // namespace

class TestContour final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void piecesByHand_data()
    {
        QTest::addColumn<int>("n");
        for (int n : {5, 7, 8, 9, 10})
            QTest::addRow("%d points", n) << n;
    }

    void piecesByHand()
    {
        QFETCH(int, n);
        const std::vector<Point> p = numbered(n);
        const auto P = [&](int i) { return p[static_cast<std::size_t>(i)]; };
        // Written out from the listing: P0 P1 P2 M23 | M23 P3 P4 M45 | … and the rest.
        std::vector<std::vector<Point>> expected;
        switch (n) {
        case 5:
            expected = {{P(0), P(1), P(2), mid(p, 2, 3)}, {mid(p, 2, 3), P(3), P(4)}};
            break;
        case 7:
            expected = {
                {P(0), P(1), P(2), mid(p, 2, 3)}, {mid(p, 2, 3), P(3), P(4), mid(p, 4, 5)}, {mid(p, 4, 5), P(5), P(6)}};
            break;
        case 8:
            expected = {{P(0), P(1), P(2), mid(p, 2, 3)},
                        {mid(p, 2, 3), P(3), P(4), mid(p, 4, 5)},
                        {mid(p, 4, 5), P(5), P(6), mid(p, 6, 7)},
                        {mid(p, 6, 7), P(7)}};
            break;
        case 9:
            expected = {{P(0), P(1), P(2), mid(p, 2, 3)},
                        {mid(p, 2, 3), P(3), P(4), mid(p, 4, 5)},
                        {mid(p, 4, 5), P(5), P(6), mid(p, 6, 7)},
                        {mid(p, 6, 7), P(7), P(8)}};
            break;
        case 10:
            expected = {{P(0), P(1), P(2), mid(p, 2, 3)},
                        {mid(p, 2, 3), P(3), P(4), mid(p, 4, 5)},
                        {mid(p, 4, 5), P(5), P(6), mid(p, 6, 7)},
                        {mid(p, 6, 7), P(7), P(8), mid(p, 8, 9)},
                        {mid(p, 8, 9), P(9)}};
            break;
        }
        const auto pieces = contourPieces(p);
        QVERIFY(pieces.ok());
        QCOMPARE(pieces->size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            QVERIFY2((*pieces)[i].controlPoints() == expected[i], qPrintable(QStringLiteral("piece %1").arg(i)));
        const std::vector<Point> joints = contourJoints(p);
        QCOMPARE(joints.size(), expected.size() - 1);
        for (std::size_t j = 0; j < joints.size(); ++j)
            QCOMPARE(joints[j], expected[j + 1].front());
    }

    void fewPointsAreOneBezier()
    {
        for (int n = 2; n <= 4; ++n) {
            const std::vector<Point> p = numbered(n);
            const auto pieces = contourPieces(p);
            QVERIFY(pieces.ok());
            QCOMPARE(pieces->size(), std::size_t(1));
            QVERIFY(pieces->front().controlPoints() == p);
            QVERIFY(contourJoints(p).empty());
        }
        QCOMPARE(contourPieces(numbered(1)).error().code, ErrorCode::TooFewPoints);
        std::vector<Point> bad = numbered(6);
        bad[4] = Point(std::nan(""), 0);
        QCOMPARE(contourPieces(bad).error().code, ErrorCode::NonFiniteInput);
        QCOMPARE(contourPieces(bad).error().index, 4);
    }

    // Over random inputs of 5..40 points: C1 between cubics; the last joint G1, with the derivative
    // ratio 2/3 (quadratic) or 1/3 (line); the curve passes through P0, every joint and P_{n-1}.
    void continuityOverRandomInputs()
    {
        QRandomGenerator rng(4004);
        for (int trial = 0; trial < 200; ++trial) {
            const int n = 5 + static_cast<int>(rng.bounded(36));
            const double scale = std::pow(10.0, rng.bounded(12.0) - 6.0); // 1e-6 .. 1e6
            std::vector<Point> p;
            for (int i = 0; i < n; ++i)
                p.emplace_back(scale * (rng.generateDouble() * 2 - 1), scale * (rng.generateDouble() * 2 - 1));
            const auto pieces = contourPieces(p);
            QVERIFY(pieces.ok());
            const kontur::geo::PiecewiseBezier curve(*pieces);
            const auto joints = curve.continuity(1e-9);
            QCOMPARE(static_cast<int>(joints.size()), curve.segmentCount() - 1);
            for (std::size_t j = 0; j + 1 < joints.size(); ++j)
                QVERIFY2(joints[j].c1, qPrintable(QStringLiteral("n = %1, joint %2").arg(n).arg(j)));
            QVERIFY(joints.back().g1);
            const Bezier &last = pieces->back();
            const Bezier &before = (*pieces)[pieces->size() - 2];
            QCOMPARE(last.degree(), n % 2 == 1 ? 2 : 1);
            const double ratio = (n % 2 == 1 ? 2.0 : 1.0) / 3.0;
            const Point d0 = last.derivative(0.0);
            const Point d1 = before.derivative(1.0);
            QVERIFY2((d0 - ratio * d1).norm() <= 1e-12 * scale, qPrintable(QStringLiteral("n = %1").arg(n)));
            QCOMPARE(pieces->front().controlPoints().front(), p.front());
            QCOMPARE(last.controlPoints().back(), p.back());
        }
    }
};

QTEST_GUILESS_MAIN(TestContour)
#include "tst_contour.moc"
