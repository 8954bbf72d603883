// The whole path of `kontur-cli trace` (vision::tracePhoto) on synthetic phone photos with ground
// truth (synthphoto.h): the sheet found, the photo rectified, the piece outlined in mm with y up;
// one closed outline (the grainline, the pencil line along the armhole and side seam and the sheet not
// traced), within 0.5 mm of the truth everywhere (Hausdorff) with at most the truth's knots + 30 %.
// Also rectifyWorld's pixel mapping against the homography.
#include "synthflat.h"
#include "synthphoto.h"
#include "vision/tracephoto.h"

#include <QTest>

#include <opencv2/imgproc.hpp>

using namespace kontur;
using geo::Point;

namespace {

// The truth in the traced frame: the sheet's mm with y up.
std::vector<Point> truthOutline(const vision::test::SynthPhoto &photo)
{
    std::vector<Point> out;
    for (const Point &p : photo.pieceOutline)
        out.emplace_back(p.x(), -p.y());
    return out;
}

} // namespace

class TestTracePhoto : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void rectifyWorldMapsPixelsThroughTheHomography()
    {
        // A photo whose pixel (x, y) has grey level x mod 256: the patch's pixel at a world point must
        // show the level of the photo pixel that the homography gives for that point.
        cv::Mat photo(300, 400, CV_8UC1);
        for (int y = 0; y < photo.rows; ++y)
            for (int x = 0; x < photo.cols; ++x)
                photo.at<uchar>(y, x) = static_cast<uchar>((x * 7 + y * 3) % 256 / 2);
        vision::Homography h;
        h << 2.0, 0.3, 50.0, -0.1, -1.8, 250.0, 0.0005, 0.0002, 1.0; // world (y up) → photo
        const auto patch = vision::rectifyWorld(photo, h, Point(10, 10), Point(60, 90), 4.0, true);
        QVERIFY(patch);
        QCOMPARE(patch->pxPerUnit, 4.0);
        QCOMPARE(patch->image.cols, 200);
        QCOMPARE(patch->image.rows, 320);
        // Row 0 is the top (y = 90), pixel centres at integers.
        QVERIFY((patch->mapping.toMm(Point(0, 0)) - Point(10.125, 89.875)).norm() < 1e-12);
        for (const Point &px : {Point(20, 30), Point(150, 17), Point(99, 250)}) {
            const Point p = vision::apply(h, patch->mapping.toMm(px));
            const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
            // Away from integer positions the bilinear sample lies between neighbours' levels.
            const int a = photo.at<uchar>(y, x);
            const int got = patch->image.at<uchar>(static_cast<int>(px.y()), static_cast<int>(px.x()));
            QVERIFY2(std::abs(got - a) <= 6, qPrintable(QStringLiteral("%1 vs %2").arg(got).arg(a)));
        }
        // A box that would be too large is taken at a lower scale, not refused.
        const auto big = vision::rectifyWorld(photo, h, Point(0, 0), Point(1000, 500), 8.0, true, 1000);
        QVERIFY(big);
        QCOMPARE(big->image.cols, 1000);
        QCOMPARE(big->pxPerUnit, 1.0);
        QVERIFY(!vision::rectifyWorld(photo, h, Point(0, 0), Point(0, 5), 8.0, true));
    }

    // Eight phone photos of 8 megapixels (the piece at about 6–9 px/mm): every outline within 0.5 mm of
    // the truth, with few knots. The knot count is a count of the stroke fit's splits, which a kink below
    // the corner angle (the waist's 8° turn into its straight part) can make one more or one fewer for a
    // change of a thousandth of a pixel in the sheet's corners; so at most 130 % of the truth's on
    // average over the photos, 150 % in any one.
    void tracesThePieceWithinHalfAMillimetre()
    {
        int knots = 0, truthKnots = 0;
        for (quint32 seed = 1; seed <= 8; ++seed) {
            const auto photo =
                vision::test::makeSynthPhoto(vision::test::randomSynthOptions(seed, cv::Size(3264, 2448)));
            const auto traced = vision::tracePhoto(photo.image);
            QVERIFY2(traced, traced ? "" : traced.error().message.c_str());
            // One piece: not the sheet, not the grainline.
            QCOMPARE(traced->outlines.size(), std::size_t(1));
            const vision::Outline &o = traced->outlines.front();
            QVERIFY(o.closed);
            const auto ours = test::sampleComposite(o.control, 100);
            const auto truth = truthOutline(photo);
            const double h = test::hausdorff(ours, truth);
            qInfo("seed %u: Hausdorff %.3f mm (ours→truth %.3f, truth→ours %.3f), %d knots (truth %d), "
                  "calibration error %.2f mm, %.1f px/mm",
                  seed, h, test::directedDistance(ours, truth), test::directedDistance(truth, ours), o.knotCount(),
                  photo.pieceKnots, traced->calibrationErrorMm, traced->pxPerMm);
            QVERIFY2(h <= 0.5, qPrintable(QString::number(h)));
            QVERIFY2(o.knotCount() <= photo.pieceKnots * 3 / 2, qPrintable(QString::number(o.knotCount())));
            knots += o.knotCount();
            truthKnots += photo.pieceKnots;
            // The sheet's corners as the truth has them.
            for (std::size_t i = 0; i < 4; ++i)
                QVERIFY((traced->sheet.corners[i] - photo.sheetCorners[i]).norm() < 0.3);
        }
        qInfo("%d knots for %d", knots, truthKnots);
        QVERIFY(10 * knots <= 13 * truthKnots);
    }

    void refusesAPhotoWithoutASheet()
    {
        auto options = vision::test::randomSynthOptions(4);
        options.withSheet = false;
        const auto traced = vision::tracePhoto(vision::test::makeSynthPhoto(options).image);
        QVERIFY(!traced);
        QCOMPARE(traced.error().code, vision::ErrorCode::NoSheetFound);
    }
};

QTEST_GUILESS_MAIN(TestTracePhoto)
#include "tst_tracephoto.moc"
