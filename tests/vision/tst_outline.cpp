// The outline tracer against flat synthetic scenes with a known outline (synthflat.h): Hausdorff
// distance, knots, corners, grainlines not traced, the piece under a seed, strokes snapped to edges.
#include "synthflat.h"
#include "vision/lineband.h"
#include "vision/loop.h"
#include "vision/outline.h"

#include <QTest>

#include <opencv2/core.hpp>

#include <cmath>
#include <numbers>

using namespace kontur;
using geo::Point;

namespace {

struct Case
{
    test::FlatScene scene;
    std::optional<geo::Box> sheet;
};

Case makeScene(std::uint64_t seed, double pxPerMm, test::Backdrop backdrop, test::PieceLook look, int count = 1)
{
    std::mt19937_64 rng(seed);
    // Each piece in a slot 155 mm wide (a bodice of 60 × 100 to 75 × 125 mm, turned any way), the
    // card to the right of them.
    std::uniform_real_distribution<double> scale(0.4, 0.5);
    std::vector<test::FlatPiece> pieces;
    for (int i = 0; i < count; ++i)
        pieces.push_back(test::bodicePiece(rng, Point(80.0 + 155.0 * i, 85.0), scale(rng)));
    test::FlatSceneOptions o;
    o.sizeMm = Point(155.0 * count + 5.0 + (backdrop == test::Backdrop::Table ? 110.0 : 0.0), 170.0);
    o.pxPerMm = pxPerMm;
    o.backdrop = backdrop;
    o.look = look;
    o.seed = seed;
    o.yUp = seed % 3 != 0;
    std::uniform_real_distribution<double> blur(0.7, 1.3);
    o.blurPx = blur(rng);
    Case c;
    if (backdrop == test::Backdrop::Table) // a reference card beside the pieces, to be ignored
        c.sheet = geo::Box(Point(o.sizeMm.x() - 110.0, 20.0), Point(o.sizeMm.x() - 10.0, 150.0));
    o.sheet = c.sheet;
    c.scene = test::renderFlatScene(pieces, o);
    return c;
}

std::vector<Point> samples(const vision::Outline &o)
{
    return test::sampleComposite(o.control, 100);
}
std::vector<Point> samples(const test::FlatPiece &p)
{
    return test::sampleComposite(p.control, 100);
}

} // namespace

class TestOutline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void tracesPieces_data()
    {
        QTest::addColumn<quint64>("seed");
        QTest::addColumn<double>("pxPerMm");
        QTest::addColumn<int>("backdrop");
        QTest::addColumn<int>("look");
        const double scales[] = {5.0, 6.5, 8.0, 10.0};
        for (quint64 seed = 1; seed <= 8; ++seed) {
            const double px = scales[seed % 4];
            const auto backdrop = static_cast<int>(seed % 2 ? test::Backdrop::Table : test::Backdrop::WhiteSheet);
            const auto look = static_cast<int>(seed % 4 == 2 ? test::PieceLook::Drawn : test::PieceLook::Paper);
            QTest::addRow("seed %llu, %.1f px/mm, %s, %s", seed, px, backdrop == 0 ? "table" : "white sheet",
                          look == 0 ? "paper" : "drawn")
                << seed << px << backdrop << look;
        }
    }
    void tracesPieces()
    {
        QFETCH(quint64, seed);
        QFETCH(double, pxPerMm);
        QFETCH(int, backdrop);
        QFETCH(int, look);
        const Case c =
            makeScene(seed, pxPerMm, static_cast<test::Backdrop>(backdrop), static_cast<test::PieceLook>(look));
        vision::OutlineOptions options;
        options.ignoreRect = c.sheet;
        const auto traced = vision::traceOutlines(c.scene.image, c.scene.mapping, options);
        QVERIFY(traced.ok());
        // One outline for the piece: neither the card nor the grainline is traced.
        QCOMPARE(static_cast<int>(traced->size()), 1);
        const vision::Outline &o = traced->front();
        const test::FlatPiece &truth = c.scene.pieces.front();
        QVERIFY(o.closed);
        // Counter-clockwise in the output frame, whichever way its y goes.
        const auto pts = samples(o);
        double area = 0.0;
        for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
            area += pts[j].x() * pts[i].y() - pts[i].x() * pts[j].y();
        QVERIFY(area > 0.0);
        QCOMPARE(o.control.front(), o.control.back());
        QCOMPARE(static_cast<int>(o.corner.size()), o.segmentCount() + 1);
        QCOMPARE(static_cast<int>(o.line.size()), o.segmentCount());
        const double h = test::hausdorff(samples(o), samples(truth));
        qInfo("Hausdorff %.3f mm, %d knots (truth %d), max fit error %.3f mm", h, o.knotCount(), truth.knotCount(),
              o.maxError);
        QVERIFY2(h <= 0.5, qPrintable(QString::number(h)));
        QVERIFY(o.knotCount() <= static_cast<int>(1.3 * truth.knotCount()));
        // Every true corner is a corner knot within 0.5 mm, and the outline starts at one.
        QVERIFY(o.corner.front());
        for (int k = 0; k < truth.knotCount(); ++k) {
            if (!truth.corner[static_cast<std::size_t>(k)])
                continue;
            const Point t = truth.control[static_cast<std::size_t>(3 * k)];
            double best = 1e300;
            for (int j = 0; j < o.segmentCount(); ++j)
                if (o.corner[static_cast<std::size_t>(j)])
                    best = std::min(best, (o.control[static_cast<std::size_t>(3 * j)] - t).norm());
            QVERIFY2(best <= 0.5, qPrintable(QStringLiteral("corner %1 missed by %2 mm").arg(k).arg(best)));
        }
        // The three straight seams come out as lines.
        int lines = 0;
        for (bool l : o.line)
            lines += l;
        QVERIFY(lines >= 3);
    }

    // A printed pattern cut out: a dark line 0.3–1 mm wide along the whole outline, its outer side 0–1 mm
    // inside the paper's edge, on white and on kraft paper on a wooden table, at the tracer's default
    // scale (8 px/mm). The outline is the paper's edge against the table, not the line's inner side: half
    // of it within 0.07 mm, nine tenths within 0.2 mm; the corners, where the line's two sides meet in
    // the blur, within 0.4 mm (0.16–0.36 mm; docs/vision.md, "A line along the edge").
    void followsThePaperEdgeBeyondALine_data()
    {
        QTest::addColumn<double>("width");
        QTest::addColumn<double>("inset");
        QTest::addColumn<bool>("kraft");
        for (const double width : {0.3, 0.6, 1.0})
            for (const double inset : {0.0, 0.5, 1.0})
                for (const bool kraft : {false, true})
                    QTest::addRow("%.1f mm line %.1f mm inside, %s", width, inset, kraft ? "kraft" : "white")
                        << width << inset << kraft;
    }
    void followsThePaperEdgeBeyondALine()
    {
        QFETCH(double, width);
        QFETCH(double, inset);
        QFETCH(bool, kraft);
        std::mt19937_64 rng(static_cast<quint64>(1000 * width + 10 * inset) + (kraft ? 7 : 0));
        test::FlatSceneOptions o;
        o.sizeMm = Point(160.0, 170.0);
        o.pxPerMm = 8.0;
        o.backdrop = test::Backdrop::Table;
        o.pencil = false;
        o.kraft = kraft;
        o.edgeLineWidthMm = width;
        o.edgeLineInsetMm = inset;
        o.seed = static_cast<std::uint64_t>(100 * width + 10 * inset);
        const test::FlatScene scene = test::renderFlatScene({test::bodicePiece(rng, Point(80.0, 85.0), 0.45)}, o);
        const auto traced = vision::traceOutlines(scene.image, scene.mapping, {});
        QVERIFY(traced.ok());
        QCOMPARE(static_cast<int>(traced->size()), 1);
        std::vector<double> d = test::distances(samples(traced->front()), samples(scene.pieces.front()));
        std::sort(d.begin(), d.end());
        const double median = d[d.size() / 2], ninety = d[d.size() * 9 / 10];
        const double h = test::hausdorff(samples(traced->front()), samples(scene.pieces.front()));
        qInfo("to the paper's edge: median %.3f mm, 90 %% %.3f mm, Hausdorff %.3f mm; %d knots", median, ninety, h,
              traced->front().knotCount());
        // On the very edge, even a line 2.4 px wide (0.3 mm), as narrow as the blur: within 0.25 mm.
        // A line inside the edge leaves a strip of paper beyond it that vanishes near an acute tip:
        // within 0.4 mm. docs/vision.md, "A line along the edge".
        QVERIFY2(median <= 0.07 && ninety <= 0.2 && h <= (inset == 0.0 ? 0.25 : 0.4), qPrintable(QString::number(h)));
    }

    // The line model against profiles made from it (paper 215, line 41, table 94: the renderer's ink on
    // white paper and a wooden table), with noise of 0.1 level (a mean over about a thousand profiles of
    // a photo's noise): the paper's edge to 0.1 px, and the steepest rise's shift as the model's own
    // derivative puts it. (A line as narrow as the blur is the model's weakest case: its width, depth
    // and blur trade off, and at 1 level of noise its edge is off by up to a pixel.) A plain step is
    // no line.
    void lineBandRecoversTheModel_data()
    {
        QTest::addColumn<double>("width");
        QTest::addColumn<double>("blur");
        for (const double width : {2.4, 4.8, 8.0})
            for (const double blur : {1.0, 1.5})
                QTest::addRow("%.1f px line, blur %.1f px", width, blur) << width << blur;
    }
    void lineBandRecoversTheModel()
    {
        QFETCH(double, width);
        QFETCH(double, blur);
        const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
        const double paper = 215.0, line = 41.0, table = 94.0, a = 0.2;
        const auto model = [&](double u, double e) {
            return paper + (line - paper) * cdf((u - a) / blur) + (table - line) * cdf((u - e) / blur);
        };
        std::mt19937_64 rng(static_cast<quint64>(10 * width + blur));
        std::normal_distribution<double> noise(0.0, 0.1);
        vision::detail::MeanProfile profile;
        profile.from = -4.0;
        for (int i = 0; i < 60; ++i)
            profile.value.push_back(model(profile.from + i * profile.step, a + width) + noise(rng));
        const auto band = vision::detail::fitLineBand(profile, paper, table, 0.25 * (paper - table));
        QVERIFY(band);
        QVERIFY2(std::abs(band->outer - (a + width)) < 0.1, qPrintable(QString::number(band->outer)));
        double rise = 0.0, steepest = 0.0;
        for (double u = a + width - 3.0; u < a + width + 4.0; u += 0.001)
            if (const double slope = model(u + 0.0005, a + width) - model(u - 0.0005, a + width); slope > steepest)
                steepest = slope, rise = u;
        QVERIFY2(std::abs(band->riseShift - (rise - a - width)) < 0.1, qPrintable(QString::number(band->riseShift)));
        if (width < 3.0 && blur > 1.2) // the bias the shift corrects: half a pixel and more
            QVERIFY(band->riseShift > 0.5);

        vision::detail::MeanProfile step = profile;
        for (std::size_t i = 0; i < step.value.size(); ++i)
            step.value[i] =
                paper + (table - paper) * cdf((step.from + static_cast<double>(i) * step.step) / blur) + noise(rng);
        QVERIFY(!vision::detail::fitLineBand(step, paper, table, 0.25 * (paper - table)));
    }

    void seedPicksItsPiece()
    {
        const Case c = makeScene(42, 6.0, test::Backdrop::WhiteSheet, test::PieceLook::Paper, 2);
        for (std::size_t i = 0; i < 2; ++i) {
            const test::FlatPiece &piece = c.scene.pieces[i];
            // The grainline's middle lies inside the piece.
            const Point seed = 0.5 * (piece.grain[0] + piece.grain[1]);
            const auto o = vision::traceOutlineAt(c.scene.image, c.scene.mapping, seed);
            QVERIFY(o.ok());
            QVERIFY(test::hausdorff(samples(*o), samples(piece)) <= 0.5);
            QVERIFY(test::hausdorff(samples(*o), samples(c.scene.pieces[1 - i])) > 20.0);
        }
        // A tap just outside a piece, 2 mm beyond the middle of its side seam, picks it too.
        const test::FlatPiece &first = c.scene.pieces.front();
        const Point mid = first.segment(1).eval(0.5), tangent = first.segment(1).derivative(0.5).normalized();
        const auto beside =
            vision::traceOutlineAt(c.scene.image, c.scene.mapping, mid + 2.0 * Point(tangent.y(), -tangent.x()));
        QVERIFY(beside.ok());
        QVERIFY(test::hausdorff(samples(*beside), samples(first)) <= 0.5);
        const auto all = vision::traceOutlines(c.scene.image, c.scene.mapping);
        QVERIFY(all.ok());
        QCOMPARE(static_cast<int>(all->size()), 2);
    }

    void snapsStrokeToEdge_data()
    {
        QTest::addColumn<quint64>("seed");
        for (quint64 seed = 11; seed <= 16; ++seed)
            QTest::addRow("seed %llu", seed) << seed;
    }
    void snapsStrokeToEdge()
    {
        QFETCH(quint64, seed);
        const Case c = makeScene(seed, seed % 2 ? 6.0 : 9.0,
                                 seed % 3 ? test::Backdrop::Table : test::Backdrop::WhiteSheet, test::PieceLook::Paper);
        const test::FlatPiece &piece = c.scene.pieces.front();
        // A hand stroke along the side seam, the armhole and the shoulder, 1–2 mm off the edge (to
        // either side) with a slow wobble and jitter.
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> off(1.0, 2.0), phase(0.0, 6.28), jitter(-0.15, 0.15);
        const double side = seed % 2 ? 1.0 : -1.0, base = off(rng), ph = phase(rng);
        const std::vector<Point> edge =
            test::sampleComposite(std::vector<Point>(piece.control.begin() + 3, piece.control.begin() + 16), 60);
        std::vector<Point> stroke;
        for (std::size_t i = 1; i + 1 < edge.size(); ++i) {
            const Point d = edge[i + 1] - edge[i - 1];
            const Point out = Point(d.y(), -d.x()).normalized();
            const double o = side * (base + 0.4 * std::sin(ph + 0.05 * static_cast<double>(i)));
            const Point q = edge[i] + o * out;
            // Inside a convex corner the offset points loop back (a swallowtail); a hand cuts the
            // corner instead: points nearer to the edge than the offset are left out.
            if (test::directedDistance({q}, edge) >= 0.9 * std::abs(o))
                stroke.push_back(q + Point(jitter(rng), jitter(rng)));
        }
        const auto snapped = vision::snapStrokeToEdges(c.scene.image, c.scene.mapping, stroke, 3.0);
        QVERIFY(snapped.ok());
        QVERIFY(!snapped->closed);
        const double d = test::directedDistance(samples(*snapped), edge);
        qInfo("snapped stroke: %.3f mm from the edge, %d knots", d, snapped->knotCount());
        QVERIFY2(d <= 0.3, qPrintable(QString::number(d)));
        // It follows the whole stroke: its ends are near the ends of the traced part of the edge.
        QVERIFY((snapped->control.front() - edge.front()).norm() < 3.0);
        QVERIFY((snapped->control.back() - edge.back()).norm() < 3.0);
    }

    void loopWrapsAndCountsOn()
    {
        const vision::detail::Loop loop({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
        QCOMPARE(loop.size(), std::size_t(4));
        QCOMPARE(loop.total(), 40.0);
        QCOMPARE(loop.arc(2), 20.0);
        QCOMPARE(loop.arc(6), 60.0); // point 2 a lap on
        QCOMPARE(loop.point(6), Point(10, 10));
        QCOMPARE(loop.at(5.0), Point(5, 0));
        QCOMPARE(loop.at(-5.0), Point(0, 5));
        QCOMPARE(loop.at(45.0), Point(5, 0));
        QCOMPARE(loop.at(35.0), Point(0, 5)); // on the closing segment
        QCOMPARE(loop.between(-10.0, 10.0), (std::vector<Point>{{0, 10}, {0, 0}, {10, 0}}));
        QCOMPARE(loop.between(35.0, 45.0), (std::vector<Point>{{0, 0}}));
        QCOMPARE(loop.ahead(1, 15.0), std::size_t(3));  // arc 30: the first at or past 10 + 15
        QCOMPARE(loop.ahead(3, 100.0), std::size_t(7)); // a lap at most
    }

    void outlinePolygonIsAPixelApart()
    {
        // A 12 mm square, y up, 0.25 mm a pixel: each side's control polygon is 48 px long.
        vision::Outline square;
        const std::vector<Point> corners{{0, 0}, {12, 0}, {12, 12}, {0, 12}};
        square.control.push_back(corners[0]);
        for (std::size_t k = 0; k < 4; ++k) {
            const Point a = corners[k], b = corners[(k + 1) % 4];
            square.control.insert(square.control.end(), {a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
        }
        square.corner.assign(5, true);
        square.closed = true;
        const auto mapping = vision::PixelMapping::uniform(0.25, Point(-5, 20), true);
        const vision::OutlineSamples s = vision::sampleOutline(square, mapping);
        QCOMPARE(s.px.size(), std::size_t(4 * 48));
        QCOMPARE(s.segment.size(), s.px.size());
        QCOMPARE(s.t.size(), s.px.size());
        QCOMPARE(s.px.front(), mapping.toPixel(corners[0]));
        for (std::size_t k = 0; k < s.px.size(); ++k) {
            QCOMPARE(s.segment[k], static_cast<int>(k / 48));
            QCOMPARE(s.t[k], static_cast<double>(k % 48) / 48.0);
            // A pixel to the next, the last to the first too (the first is not repeated).
            QVERIFY(std::abs((s.px[(k + 1) % s.px.size()] - s.px[k]).norm() - 1.0) < 1e-9);
        }
        QCOMPARE(vision::outlinePolygon(square, mapping), s.px);

        // A circle of 10 mm (four quarter arcs), 0.1 mm a pixel: under a pixel apart, on the circle.
        vision::Outline circle;
        const double h = 4.0 * (std::numbers::sqrt2 - 1.0) / 3.0 * 10.0;
        circle.control = {{10, 0},   {10, h},   {h, 10},  {0, 10},  {-h, 10}, {-10, h}, {-10, 0},
                          {-10, -h}, {-h, -10}, {0, -10}, {h, -10}, {10, -h}, {10, 0}};
        circle.corner.assign(5, false);
        circle.closed = true;
        const auto fine = vision::PixelMapping::uniform(0.1, Point(-20, -20));
        const std::vector<Point> px = vision::outlinePolygon(circle, fine);
        const Point centre = fine.toPixel(Point(0, 0));
        for (std::size_t k = 0; k < px.size(); ++k) {
            const double gap = (px[(k + 1) % px.size()] - px[k]).norm();
            QVERIFY2(gap > 0.8 && gap <= 1.0, qPrintable(QString::number(gap)));
            QVERIFY(std::abs((px[k] - centre).norm() - 100.0) < 0.05);
        }
    }

    void refusesWhatItCannotTrace()
    {
        const cv::Mat blank(200, 300, CV_8UC3, cv::Scalar(230, 230, 230));
        const auto map = vision::PixelMapping::uniform(0.2, Point(0, 0));
        QVERIFY(!vision::traceOutlines(cv::Mat(), map).ok());
        QVERIFY(!vision::traceOutlines(blank, vision::PixelMapping::uniform(0.0, Point(0, 0))).ok());
        const auto none = vision::traceOutlines(blank, map);
        QVERIFY(none.ok());
        QVERIFY(none->empty());
        QVERIFY(!vision::traceOutlineAt(blank, map, Point(10, 10)).ok());
        const std::vector<Point> stroke{{5, 5}, {30, 8}, {50, 20}};
        QVERIFY(!vision::snapStrokeToEdges(blank, map, stroke, 2.0).ok());
    }
};

QTEST_GUILESS_MAIN(TestOutline)
#include "tst_outline.moc"
