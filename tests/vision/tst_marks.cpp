// The marks on a piece (vision/marks.h) against flat synthetic scenes with known marks (synthflat.h):
// a bodice with a grainline, two V notches, a slit and a drill hole, on white and kraft paper, with and
// without a pencil line along its edge. Positions in mm against the truth: notches within 1 mm along
// the edge and 5° of their direction, the grainline's angle within 0.5°, drill holes within 0.3 mm; the outline bridges
// the V notches as the seam line does; a "place on fold" bracket gives the centre front as the fold, corner
// to corner within 1 mm, and a bracket at a curved edge none; nothing is found where nothing is marked, and a
// dart is no notch.
#include "../segmentends.h"
#include "synthflat.h"
#include "vision/marks.h"
#include "vision/outline.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace kontur;
using geo::Point;
using Kind = test::FlatNotch::Kind;

namespace {

struct Scene
{
    test::FlatScene flat;
    test::FlatPiece piece;
};

// A bodice about 90 × 150 mm: V notches in the middle of the side seam and 60 % along the lower
// armhole, a slit 30 % along the hem, a drill hole 15 mm beside the grainline's middle.
Scene bodiceScene(std::uint64_t seed, const test::FlatSceneOptions &base, bool marks = true,
                  std::optional<test::FlatPiece::FoldBracket> fold = std::nullopt)
{
    std::mt19937_64 rng(seed);
    test::FlatPiece piece = test::bodicePiece(rng, Point(85, 105), 0.6, 3.0);
    std::vector<double> start{0.0};
    for (int i = 0; i < piece.knotCount(); ++i)
        start.push_back(start.back() + test::compositeLength(std::vector<Point>(piece.control.begin() + 3 * i,
                                                                                piece.control.begin() + 3 * i + 4)));
    if (marks) {
        piece.notches = {{.at = (start[1] + start[2]) / 2, .kind = Kind::V},
                         {.at = start[2] + 0.6 * (start[3] - start[2]), .kind = Kind::V},
                         {.at = 0.3 * start[1], .kind = Kind::Slit}};
        const Point grainMid = 0.5 * (piece.grain[0] + piece.grain[1]);
        const Point across = (piece.grain[1] - piece.grain[0]).normalized();
        piece.drillHoles = {grainMid + 15.0 * Point(-across.y(), across.x())};
    }
    piece.foldBracket = fold;
    test::FlatSceneOptions o = base;
    o.sizeMm = Point(170, 210);
    o.seed = seed;
    Scene s{test::renderFlatScene({piece}, o), piece};
    return s;
}

// The unit square to a closed composite's edge at a place, into the piece.
Point inwardAt(const test::FlatPiece &piece, const test::CompositePlace &place)
{
    const std::vector<Point> pts = test::sampleComposite(piece.control, 50);
    double area = 0.0;
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
        area += pts[j].x() * pts[i].y() - pts[i].x() * pts[j].y();
    return (area > 0.0 ? 1.0 : -1.0) * Point(-place.tangent.y(), place.tangent.x());
}

double angleBetween(const Point &a, const Point &b)
{
    return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b))) * 180.0 / std::numbers::pi;
}

// A "place on fold" bracket over the middle half of the bodice's centre front, its arrows `gap` mm
// short of the edge.
test::FlatPiece::FoldBracket centreFrontBracket(std::uint64_t seed, double gap)
{
    std::mt19937_64 rng(seed);
    const test::FlatPiece piece = test::bodicePiece(rng, Point(85, 105), 0.6, 3.0);
    const Point a = piece.foldEnds[0], b = piece.foldEnds[1];
    return {.from = a + 0.25 * (b - a), .to = a + 0.75 * (b - a), .inset = 10.0, .gap = gap};
}

// The largest distance of a found fold's ends from the truth's, either way round, and its angle.
std::pair<double, double> foldError(const std::array<Point, 2> &found, const Point (&truth)[2])
{
    const double ends = test::endsOff(found[0], found[1], truth[0], truth[1]);
    const Point d = found[1] - found[0], t = truth[1] - truth[0];
    return {ends, std::min(angleBetween(d, t), angleBetween(d, Point(-t)))};
}

} // namespace

class TestMarks final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void findsEveryMark_data();
    void findsEveryMark();
    void nothingWhereNothingIsMarked_data();
    void nothingWhereNothingIsMarked();
    void aDartIsNoNotch();
    void aBracketAtACurveIsNoFold();
    void badInputIsAnError();
};

void TestMarks::findsEveryMark_data()
{
    QTest::addColumn<quint64>("seed");
    QTest::addColumn<bool>("kraft");
    QTest::addColumn<bool>("pencil");
    QTest::addColumn<bool>("yUp");
    for (quint64 seed = 1; seed <= 6; ++seed)
        QTest::addRow("seed %llu", seed) << seed << (seed % 2 == 0) << (seed % 3 != 0) << (seed != 4);
}

void TestMarks::findsEveryMark()
{
    QFETCH(quint64, seed);
    QFETCH(bool, kraft);
    QFETCH(bool, pencil);
    QFETCH(bool, yUp);
    test::FlatSceneOptions o;
    o.kraft = kraft;
    o.pencil = pencil;
    o.yUp = yUp;
    // The fold's arrows end 0.8 to 3.3 mm short of the edge.
    const Scene s = bodiceScene(seed, o, true, centreFrontBracket(seed, 0.3 + 0.5 * static_cast<double>(seed)));
    const auto traced = vision::traceOutlines(s.flat.image, s.flat.mapping);
    QVERIFY(traced.ok());
    QCOMPARE(traced->size(), std::size_t(1));
    const vision::Outline &outline = traced->front();
    // The outline runs across the V notches as the seam line does.
    const double h =
        test::hausdorff(test::sampleComposite(outline.control, 100), test::sampleComposite(s.piece.control, 100));
    QVERIFY2(h < 0.3, qPrintable(QString("outline %1 mm from the truth").arg(h)));

    const auto marks = vision::findPieceMarks(s.flat.image, s.flat.mapping, outline);
    QVERIFY(marks.ok());
    QCOMPARE(marks->notches.size(), s.piece.notches.size());
    double worstAt = 0.0, worstAngle = 0.0;
    for (const test::FlatNotch &truth : s.piece.notches) {
        const test::CompositePlace place = test::placeOnComposite(s.piece.control, truth.at);
        const auto nearest =
            std::min_element(marks->notches.begin(), marks->notches.end(), [&](const auto &a, const auto &b) {
                return (a.at - place.point).norm() < (b.at - place.point).norm();
            });
        const double off = (nearest->at - place.point).norm();
        worstAt = std::max(worstAt, off);
        QVERIFY2(off <= 1.0, qPrintable(QString("a notch %1 mm from its place").arg(off)));
        QCOMPARE(nearest->kind, truth.kind == Kind::V ? vision::FoundNotch::Kind::V : vision::FoundNotch::Kind::Slit);
        // Square to the seam, into the piece.
        const double angle = angleBetween(nearest->into, inwardAt(s.piece, place));
        worstAngle = std::max(worstAngle, angle);
        QVERIFY2(angle <= 5.0, qPrintable(QString("a notch at (%2, %3) %1° off the square into the piece")
                                              .arg(angle)
                                              .arg(place.point.x())
                                              .arg(place.point.y())));
    }

    QVERIFY(marks->grainline.has_value());
    const auto &g = *marks->grainline;
    const Point truthDir = s.piece.grain[1] - s.piece.grain[0];
    const double grainAngle =
        std::min(angleBetween(g[1] - g[0], truthDir), angleBetween(g[1] - g[0], Point(-truthDir)));
    QVERIFY2(grainAngle <= 0.5, qPrintable(QString("the grainline %1° off").arg(grainAngle)));
    const double endOff = test::endsOff(g[0], g[1], s.piece.grain[0], s.piece.grain[1]);
    QVERIFY2(endOff <= 0.6, qPrintable(QString("a grainline end %1 mm off").arg(endOff)));
    QVERIFY(g[1].y() > g[0].y()); // arrowheads at both ends: it points up

    QCOMPARE(marks->drillHoles.size(), std::size_t(1));
    const double holeOff = (marks->drillHoles.front() - s.piece.drillHoles.front()).norm();
    QVERIFY2(holeOff <= 0.3, qPrintable(QString("the drill hole %1 mm off").arg(holeOff)));

    // The fold is the whole centre front, corner to corner.
    QVERIFY(marks->fold.has_value());
    const auto [foldEnds, foldAngle] = foldError(*marks->fold, s.piece.foldEnds);
    QVERIFY2(foldEnds <= 1.0, qPrintable(QString("a fold end %1 mm off").arg(foldEnds)));
    QVERIFY2(foldAngle <= 0.5, qPrintable(QString("the fold %1° off").arg(foldAngle)));
    qInfo("notches within %.2f mm and %.1f°, grainline %.3f° and %.2f mm, drill hole %.2f mm, fold %.3f° and %.2f mm, "
          "outline %.2f mm",
          worstAt, worstAngle, grainAngle, endOff, holeOff, foldAngle, foldEnds, h);
}

void TestMarks::nothingWhereNothingIsMarked_data()
{
    QTest::addColumn<quint64>("seed");
    QTest::addColumn<double>("lineWidth");
    QTest::addColumn<double>("lineInset");
    QTest::addRow("pencil on the edge") << quint64(11) << 0.0 << 0.0;
    QTest::addRow("kraft, pencil") << quint64(12) << 0.0 << 0.0;
    QTest::addRow("line on the edge") << quint64(13) << 0.6 << 0.0;
    QTest::addRow("line inside the edge") << quint64(14) << 1.0 << 1.0;
}

void TestMarks::nothingWhereNothingIsMarked()
{
    QFETCH(quint64, seed);
    QFETCH(double, lineWidth);
    QFETCH(double, lineInset);
    test::FlatSceneOptions o;
    o.grainline = false;
    o.pencil = lineWidth == 0.0;
    o.kraft = seed % 2 == 0;
    o.edgeLineWidthMm = lineWidth;
    o.edgeLineInsetMm = lineInset;
    const Scene s = bodiceScene(seed, o, false);
    const auto traced = vision::traceOutlines(s.flat.image, s.flat.mapping);
    QVERIFY(traced.ok());
    QCOMPARE(traced->size(), std::size_t(1));
    const auto marks = vision::findPieceMarks(s.flat.image, s.flat.mapping, traced->front());
    QVERIFY(marks.ok());
    QCOMPARE(marks->notches.size(), std::size_t(0));
    QCOMPARE(marks->drillHoles.size(), std::size_t(0));
    QVERIFY(!marks->grainline);
    QVERIFY(!marks->fold);

    // A grainline without arrowheads is still one; it points up.
    test::FlatSceneOptions withGrain = o;
    withGrain.grainline = true;
    withGrain.grainArrows = false;
    const Scene g = bodiceScene(seed, withGrain, false);
    const auto tracedG = vision::traceOutlines(g.flat.image, g.flat.mapping);
    QVERIFY(tracedG.ok() && tracedG->size() == 1);
    const auto marksG = vision::findPieceMarks(g.flat.image, g.flat.mapping, tracedG->front());
    QVERIFY(marksG.ok() && marksG->grainline);
    const auto &line = *marksG->grainline;
    QVERIFY(line[1].y() > line[0].y());
    const Point truthDir = g.piece.grain[1] - g.piece.grain[0];
    QVERIFY(std::min(angleBetween(line[1] - line[0], truthDir), angleBetween(line[1] - line[0], Point(-truthDir))) <=
            0.5);
    QCOMPARE(marksG->notches.size(), std::size_t(0));
}

void TestMarks::aDartIsNoNotch()
{
    // A V 20 mm wide and 40 mm deep in the side seam is a dart, a seam: the outline follows it.
    std::mt19937_64 rng(21);
    test::FlatPiece piece = test::bodicePiece(rng, Point(85, 105), 0.6, 3.0);
    const double side =
        test::compositeLength(std::vector<Point>(piece.control.begin(), piece.control.begin() + 4)) +
        0.5 * test::compositeLength(std::vector<Point>(piece.control.begin() + 3, piece.control.begin() + 7));
    piece.notches = {{.at = side, .kind = Kind::V, .width = 20.0, .depth = 40.0}};
    test::FlatSceneOptions o;
    o.sizeMm = Point(170, 210);
    o.pencil = false;
    const auto flat = test::renderFlatScene({piece}, o);
    const auto traced = vision::traceOutlines(flat.image, flat.mapping);
    QVERIFY(traced.ok() && traced->size() == 1);
    QCOMPARE(traced->front().notches.size(), std::size_t(0));
    // The outline goes into the dart. Its last few millimetres, narrower than 3 mm, the segmentation's
    // closing fills (edges.h, segmentPieces): the outline stops short of the tip by about 3 mm over
    // the dart's tan(angle / 2), 4–6 mm here.
    const test::CompositePlace mouth = test::placeOnComposite(piece.control, side);
    const Point tip = mouth.point + 40.0 * inwardAt(piece, mouth);
    const double reach = test::directedDistance({tip}, test::sampleComposite(traced->front().control, 100));
    QVERIFY2(reach < 6.0, qPrintable(QString("%1 mm").arg(reach)));
    const auto marks = vision::findPieceMarks(flat.image, flat.mapping, traced->front());
    QVERIFY(marks.ok());
    QCOMPARE(marks->notches.size(), std::size_t(0));
}

void TestMarks::aBracketAtACurveIsNoFold()
{
    // A bracket over the hem, which bows by some 4 mm: a fold is straight, so there is none, and the
    // bracket's bar, a straight line 67 mm long well inside the piece, is no grainline either.
    std::mt19937_64 rng(31);
    const test::FlatPiece piece = test::bodicePiece(rng, Point(85, 105), 0.6, 3.0);
    const Point a = piece.control[0], b = piece.control[3];
    test::FlatSceneOptions o;
    o.pencil = false;
    o.grainline = false;
    const Scene s = bodiceScene(
        31, o, false,
        test::FlatPiece::FoldBracket{.from = a + 0.1 * (b - a), .to = a + 0.9 * (b - a), .inset = 8.0, .gap = 1.0});
    const auto traced = vision::traceOutlines(s.flat.image, s.flat.mapping);
    QVERIFY(traced.ok() && traced->size() == 1);
    const auto marks = vision::findPieceMarks(s.flat.image, s.flat.mapping, traced->front());
    QVERIFY(marks.ok());
    QVERIFY(!marks->fold);
    QVERIFY2(!marks->grainline, "the bracket's bar taken for the grainline");
    QCOMPARE(marks->notches.size(), std::size_t(0));
    QCOMPARE(marks->drillHoles.size(), std::size_t(0));
}

void TestMarks::badInputIsAnError()
{
    vision::Outline outline;
    outline.control = {Point(0, 0), Point(1, 0), Point(2, 0), Point(3, 0)};
    outline.closed = false;
    const auto mapping = vision::PixelMapping::uniform(0.125, Point(0, 0));
    QVERIFY(!vision::findPieceMarks(cv::Mat(), mapping, outline).ok());
    QVERIFY(!vision::findPieceMarks(cv::Mat(64, 64, CV_8U, cv::Scalar(200)), mapping, outline).ok());
}

QTEST_GUILESS_MAIN(TestMarks)
#include "tst_marks.moc"
