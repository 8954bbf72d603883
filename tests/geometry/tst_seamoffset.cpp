// A seam allowance per seam (issue #44): geo::seamSpans finds a piece's seams between its corner
// knots, and geo::offsetCurve with OffsetOptions::segmentDistances offsets each seam by its own width,
// the seams' offsets mitred where two widths meet. Oracles: a rectangle grown by 1/1/3/1 is exactly
// the rectangle grown by those widths (corners to 1e-9 relative); a curved seam's offset stays at its
// width; a seam of width 0 is followed exactly; random convex curved pieces at scales 1e-3…1e4 keep
// each seam's distance both ways (every offset point of a seam lies on the allowance, every point of
// the allowance away from the corners lies at its seam's width).
#include "geometry/composite.h"
#include "geometry/offset.h"
#include "geometry/seams.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

using kontur::geo::Bezier;
using kontur::geo::OffsetJoin;
using kontur::geo::OffsetOptions;
using kontur::geo::OffsetSide;
using kontur::geo::PiecewiseBezier;
using kontur::geo::Point;
using kontur::geo::SeamSpan;

namespace {

constexpr double pi = std::numbers::pi;

Bezier line(const Point &a, const Point &b)
{
    return Bezier({a, b});
}

// w × h from (x0, y0), counter-clockwise from the lower left corner: bottom (the hem), right, top, left.
PiecewiseBezier rectangle(double x0, double y0, double w, double h)
{
    const Point a(x0, y0), b(x0 + w, y0), c(x0 + w, y0 + h), d(x0, y0 + h);
    return PiecewiseBezier({line(a, b), line(b, c), line(c, d), line(d, a)}, true);
}

// The distance from `p` to the boundary of the axis-aligned box [lo, hi].
double boxBoundaryDistance(const Point &p, const Point &lo, const Point &hi)
{
    const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
    const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
    if (dx > 0 || dy > 0)
        return std::hypot(dx, dy);
    return std::min({p.x() - lo.x(), hi.x() - p.x(), p.y() - lo.y(), hi.y() - p.y()});
}

PiecewiseBezier seamCurve(const PiecewiseBezier &src, const SeamSpan &s)
{
    std::vector<Bezier> segs;
    for (int i = 0; i < s.count; ++i)
        segs.push_back(src.segments()[static_cast<std::size_t>((s.first + i) % src.segmentCount())]);
    return PiecewiseBezier(std::move(segs));
}

struct SeamCheck
{
    double forward = 0.0;  // largest distance from a seam's offset point to the allowance
    double backward = 0.0; // largest |distance to the nearest seam − that seam's width| away from corners
    int backwardSamples = 0;
};

// Both ways, for an outside allowance of a counter-clockwise piece (its outside is on the right).
SeamCheck checkSeams(const PiecewiseBezier &src, const PiecewiseBezier &allowance, const std::vector<double> &widths,
                     double cornerMargin)
{
    const std::vector<SeamSpan> seams = kontur::geo::seamSpans(src);
    SeamCheck out;
    std::vector<Point> corners;
    for (const SeamSpan &s : seams)
        corners.push_back(src.segments()[static_cast<std::size_t>(s.first)].startPoint());
    const auto nearCorner = [&](const Point &p) {
        for (const Point &c : corners)
            if ((p - c).norm() < cornerMargin)
                return true;
        return false;
    };
    for (std::size_t k = 0; k < seams.size(); ++k)
        for (int i = 0; i < seams[k].count; ++i) {
            const Bezier &b = src.segments()[static_cast<std::size_t>((seams[k].first + i) % src.segmentCount())];
            for (int j = 1; j < 32; ++j) {
                const double t = j / 32.0;
                if (nearCorner(b.eval(t)))
                    continue; // where a wider neighbour's allowance covers it
                const Point d = b.derivative(t, 1).normalized();
                const Point q = b.eval(t) + widths[k] * Point(d.y(), -d.x());
                out.forward = std::max(out.forward, allowance.nearest(q).distance);
            }
        }
    std::vector<PiecewiseBezier> seamCurves;
    for (const SeamSpan &s : seams)
        seamCurves.push_back(seamCurve(src, s));
    for (const Bezier &b : allowance.segments())
        for (int j = 0; j <= 16; ++j) {
            const Point q = b.eval(j / 16.0);
            if (nearCorner(q))
                continue;
            double best = std::numeric_limits<double>::infinity(), err = 0.0;
            for (std::size_t k = 0; k < seams.size(); ++k) {
                const double dist = seamCurves[k].nearest(q).distance;
                if (dist < best) {
                    best = dist;
                    err = std::abs(dist - widths[k]);
                }
            }
            out.backward = std::max(out.backward, err);
            ++out.backwardSamples;
        }
    return out;
}

OffsetOptions perSeam(const PiecewiseBezier &src, const std::vector<double> &widths, double fallback, double tol)
{
    OffsetOptions o;
    o.distance = fallback;
    o.tolerance = tol;
    o.miterLimit = 3.0 * fallback;
    std::vector<std::optional<double>> given(widths.begin(), widths.end());
    o.segmentDistances = kontur::geo::segmentDistancesOf(src, given, fallback);
    return o;
}

} // namespace

class TestSeamOffset : public QObject
{
    Q_OBJECT

private slots:
    void seamsBetweenCorners()
    {
        const PiecewiseBezier rect = rectangle(0, 0, 4, 6);
        const std::vector<SeamSpan> four{{0, 1}, {1, 1}, {2, 1}, {3, 1}};
        QCOMPARE(kontur::geo::seamSpans(rect), four);
        // A rectangle whose first side is split by a smooth knot: that side is one seam of two segments,
        // and the seams are numbered from the first corner after the start.
        const Point a(0, 0), m(2, 0), b(4, 0), c(4, 6), d(0, 6);
        const PiecewiseBezier split({line(m, b), line(b, c), line(c, d), line(d, a), line(a, m)}, true);
        const std::vector<SeamSpan> wrapped{{1, 1}, {2, 1}, {3, 1}, {4, 2}};
        QCOMPARE(kontur::geo::seamSpans(split), wrapped);
        QCOMPARE(kontur::geo::seamOfSegment(wrapped, 5, 0), 3);
        QCOMPARE(kontur::geo::seamOfSegment(wrapped, 5, 4), 3);
        QCOMPARE(kontur::geo::seamOfSegment(wrapped, 5, 2), 1);
        // A circle (smooth everywhere) is one seam.
        kontur::geo::CompositeCurve circle(std::vector<Point>{{1, 0}, {0, 1}, {-1, 0}, {0, -1}});
        QVERIFY(circle.close().ok());
        QCOMPARE(kontur::geo::seamSpans(circle.toPiecewise()).size(), std::size_t(1));
        const auto d5 = kontur::geo::segmentDistancesOf(split, {std::nullopt, std::nullopt, 2.5, 0.0}, 1.0);
        QCOMPARE(d5, (std::vector<double>{0.0, 1.0, 1.0, 2.5, 0.0}));
    }

    void rectangleGrownPerSeam_data()
    {
        QTest::addColumn<double>("scale");
        for (double s : {1e-3, 1e-1, 1.0, 10.0, 1e3, 1e4})
            QTest::addRow("%g", s) << s;
    }

    // Widths 3 (hem) / 1 / 1 / 1: exactly the rectangle grown by them, its four corners exact.
    void rectangleGrownPerSeam()
    {
        QFETCH(double, scale);
        const double x0 = 7 * scale, y0 = -3 * scale, w = 40 * scale, h = 60 * scale;
        const PiecewiseBezier src = rectangle(x0, y0, w, h);
        const std::vector<double> widths{3 * scale, 1 * scale, 1 * scale, 1 * scale};
        const auto r = kontur::geo::offsetCurve(src, perSeam(src, widths, 1 * scale, 1e-4 * scale));
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        const Point lo(x0 - 1 * scale, y0 - 3 * scale), hi(x0 + w + 1 * scale, y0 + h + 1 * scale);
        const double exact = 1e-9 * (std::abs(x0) + w + h);
        for (const Point &corner : {lo, Point(hi.x(), lo.y()), hi, Point(lo.x(), hi.y())}) {
            double best = std::numeric_limits<double>::infinity();
            for (const Bezier &b : r->curve.segments())
                best = std::min(best, (b.startPoint() - corner).norm());
            QVERIFY2(best <= exact, qPrintable(QStringLiteral("corner off by %1").arg(best)));
        }
        for (const Bezier &b : r->curve.segments())
            for (int j = 0; j <= 8; ++j)
                QVERIFY(boxBoundaryDistance(b.eval(j / 8.0), lo, hi) <= exact);
        QVERIFY(r->curve.isClosed());
        QCOMPARE(r->loopsRemoved, 0);
        // Inside the allowance, every width on the wrong side gives the rectangle shrunk by them.
        OffsetOptions inside = perSeam(src, widths, 1 * scale, 1e-4 * scale);
        inside.side = OffsetSide::Inside;
        const auto in = kontur::geo::offsetCurve(src, inside);
        QVERIFY(in.ok());
        const Point ilo(x0 + 1 * scale, y0 + 3 * scale), ihi(x0 + w - 1 * scale, y0 + h - 1 * scale);
        for (const Bezier &b : in->curve.segments())
            for (int j = 0; j <= 8; ++j)
                QVERIFY(boxBoundaryDistance(b.eval(j / 8.0), ilo, ihi) <= exact);
    }

    // The miter limit grows with the wider width: a 1 cm side meeting a 3 cm hem is mitred under the
    // limit (3) a 1 cm allowance has; the same corner at widths 1/1 with limit 1.2 is bevelled.
    void miterLimitScalesWithWidth()
    {
        const PiecewiseBezier src = rectangle(0, 0, 40, 60);
        OffsetOptions o = perSeam(src, {3, 1, 1, 1}, 1.0, 1e-4); // the hem corners' tips lie √10 ≈ 3.16 from the corner
        auto r = kontur::geo::offsetCurve(src, o);
        QVERIFY(r.ok());
        QCOMPARE(r->curve.segmentCount(), 12); // four sides, each corner two miter lines
        o.miterLimit = 1.2;                    // below √2: the 1/1 corners are bevelled, the 3/1 mitred (3.6)
        r = kontur::geo::offsetCurve(src, o);
        QVERIFY(r.ok());
        QCOMPARE(r->curve.segmentCount(), 4 + 2 * 2 + 2);
    }

    // Width 0 on one seam (a fold): the allowance follows that seam exactly; a curved seam's offset
    // stays at its width.
    void zeroWidthAndCurvedSeam()
    {
        // A piece with a bulging curved top seam.
        const Point a(0, 0), b(30, 0), c(30, 40), d(0, 40);
        const PiecewiseBezier src({line(a, b), line(b, c), Bezier({c, Point(20, 52), Point(10, 48), d}), line(d, a)},
                                  true);
        const std::vector<double> widths{3.0, 1.0, 1.5, 0.0};
        const double tol = 1e-3;
        const auto r = kontur::geo::offsetCurve(src, perSeam(src, widths, 1.0, tol));
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        const SeamCheck check = checkSeams(src, r->curve, widths, 4.0);
        QVERIFY2(check.forward <= tol, qPrintable(QString::number(check.forward)));
        QVERIFY2(check.backward <= tol, qPrintable(QString::number(check.backward)));
        QVERIFY(check.backwardSamples > 50);
        // The fold seam x = 0, y in [0, 40] lies on the allowance: its points at distance 0.
        for (int j = 1; j < 20; ++j)
            QVERIFY(r->curve.nearest(Point(0, 2.0 * j)).distance <= 1e-9 * 40);
        // The hem meets the fold seam at (0, −3): the hem's offset extended to the fold.
        double best = 1e300;
        for (const Bezier &s : r->curve.segments())
            best = std::min(best, (s.startPoint() - Point(0, -3)).norm());
        QVERIFY(best <= 1e-9 * 40);
    }

    // Random pieces (convex corners, seams curved out or hollow) at scales 1e-3…1e4, each seam its own
    // width (some 0): every seam keeps its distance both ways within the tolerance.
    void randomCurvedPieces()
    {
        std::mt19937_64 rng(44);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int tested = 0;
        for (int run = 0; run < 120; ++run) {
            const double scale = std::pow(10.0, -3.0 + 7.0 * unit(rng));
            const int n = 4 + static_cast<int>(unit(rng) * 4);
            std::vector<Point> corners;
            for (int i = 0; i < n; ++i) {
                const double t = 2 * pi * (i + 0.3 * unit(rng)) / n;
                corners.push_back(scale * Point(std::cos(t), std::sin(t)));
            }
            std::vector<Bezier> segs;
            for (int i = 0; i < n; ++i) {
                const Point p = corners[static_cast<std::size_t>(i)];
                const Point q = corners[static_cast<std::size_t>((i + 1) % n)];
                const Point out = Point((q - p).y(), -(q - p).x()); // to the right: outward (ccw)
                // Out by up to 0.04 of the chord (more would turn a corner back on itself), in by up to
                // 0.15 (a hollow seam, its radius of curvature still far above the widths).
                const double bulge = -0.15 + 0.19 * unit(rng);
                segs.emplace_back(
                    std::vector<Point>{p, p + (q - p) / 3.0 + bulge * out, p + 2.0 * (q - p) / 3.0 + bulge * out, q});
            }
            const PiecewiseBezier src(segs, true);
            if (kontur::geo::seamSpans(src).size() != static_cast<std::size_t>(n))
                continue; // two seams met too smoothly to be a corner
            std::vector<double> widths;
            for (int i = 0; i < n; ++i)
                widths.push_back(unit(rng) < 0.2 ? 0.0 : scale * (0.01 + 0.05 * unit(rng)));
            const double tol = 1e-4 * scale;
            const auto r = kontur::geo::offsetCurve(src, perSeam(src, widths, 0.02 * scale, tol));
            QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
            QVERIFY(r->curve.isClosed());
            const SeamCheck check = checkSeams(src, r->curve, widths, 0.25 * scale);
            QVERIFY2(check.forward <= r->tolerance && check.backward <= r->tolerance,
                     qPrintable(QStringLiteral("run %1 scale %2: %3 %4 of %5")
                                    .arg(run)
                                    .arg(scale)
                                    .arg(check.forward)
                                    .arg(check.backward)
                                    .arg(r->tolerance)));
            ++tested;
        }
        QVERIFY2(tested >= 100, qPrintable(QString::number(tested)));
    }

    // A concave corner where a 1 cm seam meets a 3 cm seam: the overlap is cut away, the allowance
    // keeps each seam's width.
    void concaveCornerWidthsDiffer()
    {
        // An L: the inner corner at (20, 20).
        const std::vector<Point> p{{0, 0}, {40, 0}, {40, 20}, {20, 20}, {20, 40}, {0, 40}};
        std::vector<Bezier> segs;
        for (std::size_t i = 0; i < p.size(); ++i)
            segs.push_back(line(p[i], p[(i + 1) % p.size()]));
        const PiecewiseBezier src(segs, true);
        const std::vector<double> widths{1, 1, 3, 1, 1, 1};
        const auto r = kontur::geo::offsetCurve(src, perSeam(src, widths, 1.0, 1e-4));
        QVERIFY(r.ok());
        QVERIFY(r->loopsRemoved >= 1);
        // The inner corner of the allowance: the 3 cm seam y = 20 → y = 23, the 1 cm seam x = 20 → x = 21.
        double best = 1e300;
        for (const Bezier &s : r->curve.segments())
            best = std::min(best, (s.startPoint() - Point(21, 23)).norm());
        QVERIFY2(best <= 1e-6, qPrintable(QString::number(best)));
        const SeamCheck check = checkSeams(src, r->curve, widths, 4.0);
        QVERIFY(check.forward <= 1e-4 && check.backward <= 1e-4);
    }

    // A turned-back hem corner: on a rectangle it is the mitred corner; on a flared side (a skirt's
    // side 10 mm, hem 30 mm), the hem's allowance edge beside the side is the side's allowance edge
    // mirrored about the hem line, so that the hem turned up along its seam lies under the side's
    // allowance; flared so far that the mirrored edge crosses the hem's allowance, that is cut there.
    // No stretch of the allowance doubles back on itself.
    void turnedBackHem_data()
    {
        QTest::addColumn<double>("flare"); // the side's angle from the square to the hem, degrees
        // Negative: the side leans outwards (an A-line skirt, a bodice's side), so that its allowance
        // line passes P before the corner's own offset point; as straight lines (a polyline's chords,
        // as AAMA writes a sew line) the line back to it lay on the side's allowance, there and back.
        for (double degrees : {0.0, 10.0, 30.0, -10.0, -25.0})
            QTest::addRow("%g°", degrees) << degrees;
    }

    void turnedBackHem()
    {
        QFETCH(double, flare);
        const double th = flare * pi / 180;
        // Counter-clockwise: the hem along y = 0 from (0, 0) to (100, 0), the right side up and in by
        // the flare, the top, the left side down and out (mirror-symmetric).
        const double h = 120, in = h * std::tan(th);
        const Point a(0, 0), b(100, 0), c(100 - in, h), d(in, h);
        const PiecewiseBezier src({line(a, b), line(b, c), line(c, d), line(d, a)}, true);
        OffsetOptions o = perSeam(src, {30, 10, 10, 10}, 10.0, 1e-6);
        o.hems = {true, false, false, false};
        const auto r = kontur::geo::offsetCurve(src, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message.c_str());
        QVERIFY(r->curve.isClosed());
        // The right corner by hand: the side's allowance line meets y = 0 at P = (100 + 10 / cos θ, 0);
        // mirrored it runs down and inwards (by tan θ per unit) to y = −30 at Q.
        const Point p(100 + 10 / std::cos(th), 0), q(p.x() - 30 * std::tan(th), -30);
        for (const Point &corner : {p, q, Point(100 - p.x(), 0), Point(100 - q.x(), -30)}) {
            double best = 1e300;
            for (const Bezier &s : r->curve.segments())
                best = std::min(best, (s.startPoint() - corner).norm());
            QVERIFY2(best <= 1e-9 * 200,
                     qPrintable(QStringLiteral("(%1, %2) off by %3").arg(corner.x()).arg(corner.y()).arg(best)));
        }
        // Folded up about the hem line, each point of the allowance below the hem near the right side
        // lands on the side's allowance line (distance 10 from the side) or inside the hem's width.
        for (const Bezier &s : r->curve.segments())
            for (int j = 0; j <= 8; ++j) {
                const Point x = s.eval(j / 8.0);
                if (!(x.y() < -1e-9 && x.x() > 90))
                    continue;
                const Point folded(x.x(), -x.y());
                const Point side = (c - b).normalized();
                const double toSideLine = std::abs(side.x() * (folded.y() - b.y()) - side.y() * (folded.x() - b.x()));
                const bool onEdge = std::abs(toSideLine - 10) <= 1e-9 * 200;
                const bool onHemEdge = std::abs(x.y() + 30) <= 1e-9 * 200;
                QVERIFY2(onEdge || onHemEdge, qPrintable(QStringLiteral("(%1, %2)").arg(x.x()).arg(x.y())));
            }
        // No there and back: consecutive pieces never turn by half a turn.
        for (std::size_t k = 0; k < r->curve.segments().size(); ++k) {
            const Bezier &s0 = r->curve.segments()[k];
            const Bezier &s1 = r->curve.segments()[(k + 1) % r->curve.segments().size()];
            const Point t0 = (s0.endPoint() - s0.eval(0.99)).normalized(), t1 = (s1.eval(0.01) - s1.startPoint()).normalized();
            QVERIFY2(t0.dot(t1) > -0.999, qPrintable(QStringLiteral("reverses at (%1, %2)").arg(s0.endPoint().x()).arg(s0.endPoint().y())));
        }
        // Far from the corners every seam keeps its width.
        const SeamCheck check = checkSeams(src, r->curve, {30, 10, 10, 10}, 45.0);
        QVERIFY2(check.forward <= 1e-6 && check.backward <= 1e-6,
                 qPrintable(QStringLiteral("%1 %2").arg(check.forward).arg(check.backward)));
        // The same with mitred corners differs exactly where the side flares.
        o.hems.clear();
        const auto mitred = kontur::geo::offsetCurve(src, o);
        QVERIFY(mitred.ok());
        QCOMPARE(mitred->curve.nearest((p + q) / 2).distance <= 1e-9, flare == 0.0);
    }

    void refusesBadWidths()
    {
        const PiecewiseBezier src = rectangle(0, 0, 4, 6);
        OffsetOptions o;
        o.segmentDistances = {1, 1, 1};
        QCOMPARE(kontur::geo::offsetCurve(src, o).error().code, kontur::geo::ErrorCode::InvalidArgument);
        o.segmentDistances = {1, -1, 1, 1};
        QCOMPARE(kontur::geo::offsetCurve(src, o).error().code, kontur::geo::ErrorCode::InvalidArgument);
        o.segmentDistances = {1, std::nan(""), 1, 1};
        QCOMPARE(kontur::geo::offsetCurve(src, o).error().code, kontur::geo::ErrorCode::InvalidArgument);
        o.segmentDistances = {1, 1, 1e6, 1};
        QCOMPARE(kontur::geo::offsetCurve(src, o).error().code, kontur::geo::ErrorCode::OutOfProportion);
        // Cancelled before it starts: answered as cancelled, like the single width.
        kontur::geo::OffsetControl control;
        control.cancel();
        o.segmentDistances = {3, 1, 1, 1};
        QCOMPARE(kontur::geo::offsetCurve(src, o, &control).error().code, kontur::geo::ErrorCode::Cancelled);
    }
};

QTEST_APPLESS_MAIN(TestSeamOffset)
#include "tst_seamoffset.moc"
