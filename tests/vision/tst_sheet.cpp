// The sheet finder on synthetic photos whose truth the test makes itself (synthphoto.h): corners
// within 0.3 photo px, finger hints, snapping, the calibration error's size, refusal, rectification.
#include "synthphoto.h"

#include "vision/edgefit.h"
#include "vision/sheet.h"
#include "vision/tracephoto.h"

#include <QTest>

#include <opencv2/imgproc.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <random>

using namespace kontur;
using namespace kontur::vision;
using kontur::vision::test::makeSynthPhoto;
using kontur::vision::test::randomSynthOptions;
using kontur::vision::test::SynthOptions;
using kontur::vision::test::SynthPhoto;

Q_DECLARE_METATYPE(kontur::vision::test::SynthOptions)

namespace {

double maxCornerError(const Sheet &sheet, const SynthPhoto &photo)
{
    double e = 0;
    for (int i = 0; i < 4; ++i)
        e = std::max(e, (sheet.corners[i] - photo.sheetCorners[i]).norm());
    return e;
}

// The world points (sheet mm) of the photo's four corners, by the true homography.
std::vector<geo::Point> photoCornersInWorld(const SynthPhoto &photo)
{
    const Homography inv = photo.worldToPhoto.inverse();
    const double w = photo.image.cols - 1.0, h = photo.image.rows - 1.0;
    return {apply(inv, {0, 0}), apply(inv, {w, 0}), apply(inv, {w, h}), apply(inv, {0, h})};
}

geo::Point offsetBy(const geo::Point &p, double distance, std::mt19937 &rng)
{
    const double a = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    return p + distance * geo::Point(std::cos(a), std::sin(a));
}

} // namespace

class TestSheet final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void homographyMapsFourPoints();
    void parsesSheetSizes();
    void cornersOverSeeds();
    void strongWoodGrain();
    void fingerHintsFindTheSameCorners();
    void harderPhotos_data();
    void harderPhotos();
    void realPhotoConditions_data();
    void realPhotoConditions();
    void refusesOtherProportions();
    void knownFocalLengthTellsLetterFromA4();
    void bowedEdgesAreFittedWhole();
    void lineShareTellsAPrintedLineFromAnEdge();
    void cornerHintChoosesOrientationAndCorner();
    void snapsCornerFromFifteenPixels();
    void snapRefusesAlongAnEdge();
    void errorEstimateGrowsWithNoise();
    void refusesWithoutSheet();
    void rectifyMapsSheetToRectangle();
    void twelveMegapixelPhoto();
};

void TestSheet::homographyMapsFourPoints()
{
    const std::array<geo::Point, 4> from{geo::Point(0, 0), geo::Point(210, 0), geo::Point(210, 297),
                                         geo::Point(0, 297)};
    const std::array<geo::Point, 4> to{geo::Point(812.3, 401.7), geo::Point(1390.1, 420.2), geo::Point(1502.8, 1130.4),
                                       geo::Point(655.5, 1101.9)};
    const auto h = homographyFrom4(from, to);
    QVERIFY(h.has_value());
    for (int i = 0; i < 4; ++i)
        QVERIFY((apply(*h, from[i]) - to[i]).norm() < 1e-9);
    QVERIFY(!homographyFrom4(from, {to[0], to[1], to[0] + 0.5 * (to[1] - to[0]), to[3]}).has_value());
}

void TestSheet::parsesSheetSizes()
{
    QCOMPARE(*parseSheetSize("A4"), geo::Point(210, 297));
    QCOMPARE(*parseSheetSize("letter"), geo::Point(215.9, 279.4));
    QCOMPARE(*parseSheetSize("10x15cm"), geo::Point(100, 150));
    QVERIFY((*parseSheetSize("8.5x11in") - geo::Point(215.9, 279.4)).norm() < 1e-9);
    QCOMPARE(*parseSheetSize("200x300mm"), geo::Point(200, 300));
    QVERIFY(!parseSheetSize("a5x").ok());
    QVERIFY(!parseSheetSize("0x10").ok());
    QVERIFY(!parseSheetSize("").ok());
}

// 50 random photos (KONTUR_SHEET_SEEDS=N for another number): tilt 20–45°, blur, noise, vignetting,
// wood-grain table, white or kraft piece beside. The corners, and the calibration error the user is
// shown (the largest at the photo's far corners) against the true error there.
void TestSheet::cornersOverSeeds()
{
    double worst = 0, worstRatio = 0;
    int within3 = 0;
    std::vector<double> shownRatio; // true largest far-side error / the one shown
    const int seeds = qEnvironmentVariableIntValue("KONTUR_SHEET_SEEDS") > 0
                          ? qEnvironmentVariableIntValue("KONTUR_SHEET_SEEDS")
                          : 50;
    for (int seed = 1; seed <= seeds; ++seed) {
        const SynthOptions o = randomSynthOptions(seed);
        const SynthPhoto photo = makeSynthPhoto(o);
        const auto sheet = findSheet(photo.image, {});
        QVERIFY2(
            sheet.ok(),
            qPrintable(QStringLiteral("seed %1: %2").arg(seed).arg(sheet.ok() ? "" : sheet.error().message.c_str())));
        QCOMPARE(sheet->sizeMm, geo::Point(210, 297));
        const double e = maxCornerError(*sheet, photo);
        worst = std::max(worst, e);
        QVERIFY2(e < 0.3, qPrintable(QStringLiteral("seed %1: corner error %2 px").arg(seed).arg(e)));

        // The far side: the photo's corners mapped by the found sheet against the truth.
        const std::vector<geo::Point> far = photoCornersInWorld(photo);
        const std::vector<double> estimate = calibrationErrorMm(*sheet, far);
        double ratio = 0, trueFar = 0;
        for (std::size_t i = 0; i < far.size(); ++i) {
            const geo::Point found = apply(sheet->photoToSheet, apply(photo.worldToPhoto, far[i]));
            ratio = std::max(ratio, (found - far[i]).norm() / estimate[i]);
            trueFar = std::max(trueFar, (found - far[i]).norm());
        }
        worstRatio = std::max(worstRatio, ratio);
        within3 += ratio < 3.0;
        const double shown = calibrationErrorAtPhotoCornersMm(*sheet, photo.image.size());
        QVERIFY(std::isfinite(shown) && shown > 0);
        shownRatio.push_back(trueFar / shown);
        qInfo("seed %d tilt %.1f blur %.2f noise %.1f vignetting %.2f: corner error %.3f px, far-side estimate "
              "%.3f mm, true/estimate %.2f",
              seed, o.tiltDeg, o.blurSigmaPx, o.noiseSigma, o.vignetting, e,
              *std::max_element(estimate.begin(), estimate.end()), ratio);
    }
    qInfo("largest corner error over %d photos: %.3f px; true far-side error < 3x estimate in %d of them "
          "(largest ratio %.2f)",
          seeds, worst, within3, worstRatio);
    QVERIFY(within3 >= seeds * 8 / 10);
    // The error shown brackets the true one: it is a one-sigma estimate, so the true error lies within a
    // factor of 3 of it in nine photos of ten or more, and half of the time within a factor of 2.
    std::sort(shownRatio.begin(), shownRatio.end());
    const auto bracketed = std::count_if(shownRatio.begin(), shownRatio.end(),
                                         [](double r) { return r >= 1.0 / 3.0 && r <= 3.0; });
    const double median = shownRatio[shownRatio.size() / 2];
    qInfo("true / shown calibration error: %.2f to %.2f, median %.2f; within a factor of 3 in %d of %d", shownRatio.front(),
          shownRatio.back(), median, static_cast<int>(bracketed), seeds);
    QVERIFY(bracketed * 10 >= seeds * 9);
    QVERIFY(median >= 0.5 && median <= 2.0);
}

// The known limit: a strong wood grain running along an edge moves the gradient maximum by g sigma^2 / C
// (background slope g, blur sigma, step C; docs/vision.md). At the strongest grain of the generator the
// corners stay within 0.45 px (0.3 px for the 0.3-1 range of the photos above).
void TestSheet::strongWoodGrain()
{
    double worst = 0;
    for (int seed = 1; seed <= 12; ++seed) {
        SynthOptions o = randomSynthOptions(seed);
        o.tableTexture = 1.0;
        const SynthPhoto photo = makeSynthPhoto(o);
        const auto sheet = findSheet(photo.image, {});
        QVERIFY(sheet.ok());
        worst = std::max(worst, maxCornerError(*sheet, photo));
    }
    qInfo("strongest grain: largest corner error over 12 photos %.3f px", worst);
    QVERIFY(worst < 0.45);
}

void TestSheet::fingerHintsFindTheSameCorners()
{
    std::mt19937 rng(7);
    for (int seed = 31; seed <= 36; ++seed) {
        const SynthPhoto photo = makeSynthPhoto(randomSynthOptions(seed));
        const auto plain = findSheet(photo.image, {});
        QVERIFY(plain.ok());
        SheetOptions options;
        // 30 px off each corner, given in a shuffled order.
        std::array<geo::Point, 4> hints;
        for (int i = 0; i < 4; ++i)
            hints[i] = offsetBy(photo.sheetCorners[(i + 2) % 4], 30, rng);
        std::swap(hints[0], hints[3]);
        options.cornerHints = hints;
        const auto hinted = findSheet(photo.image, options);
        QVERIFY2(hinted.ok(), hinted.ok() ? "" : hinted.error().message.c_str());
        QVERIFY(maxCornerError(*hinted, photo) < 0.3);
        for (int i = 0; i < 4; ++i)
            QVERIFY((hinted->corners[i] - plain->corners[i]).norm() < 0.05);
    }
}

void TestSheet::harderPhotos_data()
{
    QTest::addColumn<int>("seed");
    QTest::addColumn<double>("gapMm");
    QTest::addColumn<double>("jpegStep");
    QTest::addColumn<bool>("colour");
    QTest::addRow("white piece 3 mm from the sheet") << 101 << 3.0 << 0.0 << false;
    QTest::addRow("white piece 1 mm from the sheet") << 102 << 1.0 << 0.0 << false;
    QTest::addRow("JPEG-like quantisation") << 103 << 30.0 << 12.0 << false;
    QTest::addRow("colour photo") << 104 << 30.0 << 0.0 << true;
}

void TestSheet::harderPhotos()
{
    QFETCH(int, seed);
    QFETCH(double, gapMm);
    QFETCH(double, jpegStep);
    QFETCH(bool, colour);
    SynthOptions o = randomSynthOptions(seed);
    o.gapMm = gapMm;
    o.whitePiece = gapMm < 10 || o.whitePiece;
    o.jpegStep = jpegStep;
    const SynthPhoto photo = makeSynthPhoto(o);
    cv::Mat image = photo.image;
    if (colour)
        cv::cvtColor(photo.image, image, cv::COLOR_GRAY2BGR);
    const auto sheet = findSheet(image, {});
    QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
    const double e = maxCornerError(*sheet, photo);
    qInfo("corner error %.3f px", e);
    QVERIFY(e < 0.3);
}

// What the public real photos showed (docs/vision.md, "Real photos"), each as a synthetic photo with its
// truth: the sheet is found, its corners within 0.5 px (the conditions cost the edge fit some precision;
// the labelled real photos are judged at 2 px).
void TestSheet::realPhotoConditions_data()
{
    QTest::addColumn<SynthOptions>("options");
    const auto base = [](int seed) {
        SynthOptions o = randomSynthOptions(static_cast<std::uint32_t>(seed));
        o.colour = true;
        return o;
    };
    {
        SynthOptions o = base(201); // the white A4 on light wood: barely brighter in grey
        o.tableLevel = 172;
        QTest::addRow("light wood, colour") << o;
        o.size = cv::Size(4000, 3000);
        o.supersample = 2;
        QTest::addRow("light wood, 12 MP") << o;
        o.size = cv::Size(1632, 1224);
        o.printedText = true;
        o.jpegStep = 14;
        QTest::addRow("light wood, printed text, JPEG") << o;
    }
    {
        SynthOptions o = base(202); // a white desk: no threshold parts it from the sheet
        o.colour = false;
        o.tableLevel = 205;
        o.tableTexture = 0.15;
        QTest::addRow("white desk, low contrast") << o;
    }
    {
        SynthOptions o = base(203);
        o.tableLevel = 45;
        o.tableTint = cv::Vec3d(0.9, 0.95, 1.05);
        o.printedText = true;
        QTest::addRow("dark table, printed text") << o;
    }
    {
        SynthOptions o = base(204); // a card box lying on the sheet, over its right edge
        o.tableLevel = 165;
        o.objectMm = Eigen::AlignedBox2d(geo::Point(120, 90), geo::Point(260, 200));
        o.gapMm = 70;
        QTest::addRow("box on the sheet, over an edge") << o;
        o.objectMm = Eigen::AlignedBox2d(geo::Point(40, 60), geo::Point(170, 230));
        QTest::addRow("box on the sheet, inside") << o;
    }
    {
        SynthOptions o = base(205); // a hand's shadow over the lower part of the sheet and the table
        o.shadowDepth = 0.45;
        o.shadowFromMm = geo::Point(-50, 190);
        o.shadowToMm = geo::Point(300, 260);
        QTest::addRow("shadow over an edge") << o;
    }
    {
        SynthOptions o = base(206); // glare from a lamp, on the sheet near its edge
        o.printedText = true;
        o.glareLevels = 90;
        o.glareSigmaPx = 70;
        const SynthPhoto plain = makeSynthPhoto(o);
        o.glareAtPx = 0.5 * (plain.sheetCorners[1] + plain.sheetCorners[2]) + geo::Point(-60, 0);
        QTest::addRow("glare near an edge") << o;
    }
    {
        SynthOptions o = base(207); // a blue cloth
        o.tableLevel = 120;
        o.tableTint = cv::Vec3d(1.45, 0.9, 0.45);
        o.tableTexture = 0.4;
        QTest::addRow("blue cloth") << o;
    }
    {
        SynthOptions o = base(208); // grid paper: a printed line every 5 mm, 10 mm from the edges
        o.gridMm = 5;
        o.tableLevel = 150;
        QTest::addRow("grid paper") << o;
    }
    {
        SynthOptions o = base(209); // a cropped photo seen nearly square on: its centre is not the camera's
        o.tiltDeg = 6;
        o.yawDeg = 2;
        o.principalShift = geo::Point(0.05, -0.05);
        QTest::addRow("cropped, nearly square on") << o;
    }
}

void TestSheet::realPhotoConditions()
{
    QFETCH(SynthOptions, options);
    const SynthPhoto photo = makeSynthPhoto(options);
    const auto sheet = findSheet(photo.image, {});
    QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
    const double e = maxCornerError(*sheet, photo);
    qInfo("corner error %.3f px", e);
    QVERIFY(e < 0.5);
}

// A lens's barrel distortion bows a sheet's straight edges outwards (real phone photos: 3–6 px over a
// side). The edge is fitted whole: each corner is where the total-least-squares lines through its two
// bowed edges (5–95 % of each) meet, computed here from the true, distorted edges; not where the tangent
// to one part of the bow meets the next edge (before: several px along it), and the sheet is not taken
// for a curled one.
void TestSheet::bowedEdgesAreFittedWhole()
{
    for (const std::uint32_t seed : {401u, 402u, 403u}) {
        SynthOptions o = randomSynthOptions(seed);
        o.radialK1 = 0.1;
        o.withPiece = false;
        const SynthPhoto photo = makeSynthPhoto(o);
        const std::array<geo::Point, 4> world{geo::Point(0, 0), geo::Point(o.sheetMm.x(), 0), o.sheetMm,
                                              geo::Point(0, o.sheetMm.y())};
        std::array<EdgeLine, 4> lines;
        double bow = 0;
        for (int i = 0; i < 4; ++i) {
            std::vector<geo::Point> pts;
            for (int k = 0; k <= 200; ++k) {
                const geo::Point w = world[i] + (0.05 + 0.9 * k / 200.0) * (world[(i + 1) % 4] - world[i]);
                pts.push_back(test::lensDistorted(o, apply(photo.worldToPhoto, w)));
            }
            geo::Point c = geo::Point::Zero();
            for (const auto &p : pts)
                c += p / static_cast<double>(pts.size());
            Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
            for (const auto &p : pts)
                scatter += (p - c) * (p - c).transpose();
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
            lines[i].point = c;
            lines[i].direction = eig.eigenvectors().col(1);
            double lo = INFINITY, hi = -INFINITY;
            for (const auto &p : pts) {
                const geo::Point d = p - c;
                const double off = d.x() * lines[i].direction.y() - d.y() * lines[i].direction.x();
                lo = std::min(lo, off);
                hi = std::max(hi, off);
            }
            bow = std::max(bow, hi - lo);
        }
        const auto sheet = findSheet(photo.image, {});
        QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
        double e = 0, tips = 0;
        for (int i = 0; i < 4; ++i) {
            const auto expected = intersect(lines[(i + 3) % 4], lines[i]);
            QVERIFY(expected.has_value());
            e = std::max(e, (sheet->corners[i] - *expected).norm());
            tips = std::max(tips, (sheet->corners[i] - photo.sheetCorners[i]).norm());
        }
        qInfo("seed %u: edges bow up to %.1f px; corners %.3f px from the whole edges' lines, %.1f px from the "
              "paper's tips",
              seed, bow, e, tips);
        QVERIFY(bow > 2.5);
        QVERIFY(e < 1.0);
    }
}

// An edge seen from the paper: beyond a sheet's edge the table stays dark; beyond a printed line (3 px
// wide) the paper is white again; a piece lying 2 px beyond the edge along a third of it is a third.
void TestSheet::lineShareTellsAPrintedLineFromAnEdge()
{
    EdgeLine edge;
    edge.point = geo::Point(100, 100);
    edge.direction = geo::Point(0, 1);
    edge.outward = geo::Point(1, 0);
    const geo::Point from(100, 20), to(100, 180);
    cv::Mat sheet(200, 200, CV_8UC1, cv::Scalar(100));
    sheet.colRange(0, 100).setTo(230);
    cv::GaussianBlur(sheet, sheet, cv::Size(0, 0), 1.0);
    QCOMPARE(lineShare(sheet, edge, from, to, 10, 2), 0.0);
    cv::Mat line(200, 200, CV_8UC1, cv::Scalar(230));
    line.colRange(100, 103).setTo(90);
    cv::GaussianBlur(line, line, cv::Size(0, 0), 1.0);
    QCOMPARE(lineShare(line, edge, from, to, 10, 2), 1.0);
    cv::Mat piece(200, 200, CV_8UC1, cv::Scalar(100));
    piece.colRange(0, 100).setTo(230);
    piece(cv::Rect(102, 0, 98, 73)).setTo(220); // rows 0–72: profiles at y = 20..72 of 20..180
    cv::GaussianBlur(piece, piece, cv::Size(0, 0), 1.0);
    const double share = lineShare(piece, edge, from, to, 10, 2);
    qInfo("piece beside a third of the edge: %.2f", share);
    QVERIFY(share > 0.25 && share < 0.4);
}

// A rectangle of other proportions is not the sheet, whatever the camera: a dollar bill (156 × 66 mm,
// 2.35 : 1) is not A4, and an A4 sheet is not a Letter one (1.41 against 1.29 : 1). The error says
// the proportions seen.
void TestSheet::refusesOtherProportions()
{
    for (const std::uint32_t seed : {301u, 302u, 303u}) {
        SynthOptions o = randomSynthOptions(seed);
        o.sheetMm = geo::Point(156.1, 66.3);
        o.withPiece = false;
        const SynthPhoto bill = makeSynthPhoto(o);
        const auto asA4 = findSheet(bill.image, {});
        QVERIFY(!asA4.ok());
        QCOMPARE(asA4.error().code, ErrorCode::WrongProportions);
        qInfo("seen %.3f : 1", asA4.error().seenAspect);
        QVERIFY(std::abs(asA4.error().seenAspect - 156.1 / 66.3) < 0.05);
        // Four hinted corners of it are refused as well.
        SheetOptions hinted;
        hinted.cornerHints = bill.sheetCorners;
        QCOMPARE(findSheet(bill.image, hinted).error().code, ErrorCode::WrongProportions);
        // Said to be a bill, it is one.
        SheetOptions billSize;
        billSize.sizeMm = o.sheetMm;
        const auto asBill = findSheet(bill.image, billSize);
        QVERIFY2(asBill.ok(), asBill.ok() ? "" : asBill.error().message.c_str());
        QVERIFY(maxCornerError(*asBill, bill) < 0.3);
    }
    const SynthPhoto a4 = makeSynthPhoto(randomSynthOptions(304));
    SheetOptions letter;
    letter.sizeMm = *parseSheetSize("letter");
    const auto asLetter = findSheet(a4.image, letter);
    QVERIFY(!asLetter.ok());
    QCOMPARE(asLetter.error().code, ErrorCode::WrongProportions);
    QVERIFY(std::abs(asLetter.error().seenAspect - 297.0 / 210.0) < 0.03);
    // The image of a true rectangle: no skew left for the focal length that explains it.
    const SeenRectangle seen = seenRectangle(a4.sheetCorners, a4.image.size());
    QVERIFY(seen.skew < 0.01);
    QVERIFY(std::abs(seen.aspect - 297.0 / 210.0) < 0.01);
}

// A sheet seen without yaw (the camera tilted straight towards it: its near and far edges parallel in
// the photo) does not tell the camera's focal length, and with it unknown the proportions it can have
// span a wide range: a Letter sheet passes for A4. The focal length a phone writes into the photo's
// EXIF (SheetOptions::focalPx) tells them apart; a focal length the corners contradict (a cropped
// photo) is not used.
void TestSheet::knownFocalLengthTellsLetterFromA4()
{
    int refusedWithout = 0;
    for (const double tilt : {20.0, 30.0, 40.0}) {
        for (const bool isLetter : {true, false}) {
            SynthOptions o = randomSynthOptions(static_cast<std::uint32_t>(500 + tilt));
            o.tiltDeg = tilt;
            o.yawDeg = 0;
            o.rollDeg = 0;
            o.withPiece = false;
            o.sheetMm = isLetter ? geo::Point(215.9, 279.4) : geo::Point(210, 297);
            const SynthPhoto photo = makeSynthPhoto(o);
            const double focal = 0.75 * o.size.width; // the synthetic camera's
            const SeenRectangle free = seenRectangle(photo.sheetCorners, photo.image.size());
            const SeenRectangle known = seenRectangle(photo.sheetCorners, photo.image.size(), focal);
            qInfo("%s at %.0f deg: proportions %.3f-%.3f, with the focal length %.3f-%.3f", isLetter ? "Letter" : "A4",
                  tilt, free.aspectLow, free.aspectHigh, known.aspectLow, known.aspectHigh);
            QVERIFY(known.focalUsed);
            QVERIFY(free.aspectHigh / free.aspectLow > 1.1);     // the ambiguity
            QVERIFY(known.aspectHigh / known.aspectLow < 1.06); // resolved, to within A4 against Letter
            SheetOptions a4;
            refusedWithout += findSheet(photo.image, a4).ok() ? 0 : 1;
            a4.focalPx = focal;
            const auto sheet = findSheet(photo.image, a4);
            if (isLetter) {
                QVERIFY(!sheet.ok());
                QCOMPARE(sheet.error().code, ErrorCode::WrongProportions);
                QVERIFY(std::abs(sheet.error().seenAspect - 279.4 / 215.9) < 0.03);
            } else {
                QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
                QVERIFY(maxCornerError(*sheet, photo) < 0.5);
            }
        }
    }
    qInfo("refused without the focal length: %d of 6", refusedWithout);
    // Seen with yaw, the sheet's corners tell the focal length themselves: one 40 % off (a photo cropped
    // after it was taken) contradicts them and is not used. (Without yaw nothing can contradict it;
    // picture.h trusts EXIF only for a picture of a camera's full-frame proportions.)
    SynthOptions o = randomSynthOptions(520);
    o.tiltDeg = 35;
    o.yawDeg = 12;
    o.withPiece = false;
    const SynthPhoto photo = makeSynthPhoto(o);
    const double focal = 0.75 * o.size.width;
    QVERIFY(!seenRectangle(photo.sheetCorners, photo.image.size(), 1.4 * focal).focalUsed);
    QVERIFY(seenRectangle(photo.sheetCorners, photo.image.size(), focal).focalUsed);
    SheetOptions a4;
    a4.focalPx = 1.4 * focal;
    const auto sheet = findSheet(photo.image, a4);
    QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
}

void TestSheet::cornerHintChoosesOrientationAndCorner()
{
    SynthOptions o = randomSynthOptions(41);
    o.sheetMm = {297, 210}; // landscape
    const SynthPhoto photo = makeSynthPhoto(o);
    SheetOptions options;
    options.sizeMm = {210, 297};
    options.cornerHint = photo.sheetCorners[2] + geo::Point(12, -9);
    const auto sheet = findSheet(photo.image, options);
    QVERIFY(sheet.ok());
    QCOMPARE(sheet->sizeMm, geo::Point(297, 210));
    QCOMPARE(sheet->hintedCorner, 2);
    QVERIFY(maxCornerError(*sheet, photo) < 0.3);
}

void TestSheet::snapsCornerFromFifteenPixels()
{
    std::mt19937 rng(11);
    double worst = 0;
    for (int seed = 51; seed <= 56; ++seed) {
        const SynthPhoto photo = makeSynthPhoto(randomSynthOptions(seed));
        for (const auto &truth : photo.sheetCorners) {
            const auto snapped = snapCorner(photo.image, offsetBy(truth, 15, rng), 20);
            QVERIFY2(snapped.ok(), snapped.ok() ? "" : snapped.error().message.c_str());
            worst = std::max(worst, (*snapped - truth).norm());
        }
    }
    qInfo("largest snap error over 24 corners: %.3f px", worst);
    QVERIFY(worst < 0.3);
}

void TestSheet::snapRefusesAlongAnEdge()
{
    const SynthPhoto photo = makeSynthPhoto(randomSynthOptions(57));
    const geo::Point middleOfTop = 0.5 * (photo.sheetCorners[0] + photo.sheetCorners[1]);
    const auto snapped = snapCorner(photo.image, middleOfTop, 15);
    QVERIFY(!snapped.ok());
    QCOMPARE(snapped.error().code, ErrorCode::NoCornerFound);
    const geo::Point middleOfSheet =
        0.25 * (photo.sheetCorners[0] + photo.sheetCorners[1] + photo.sheetCorners[2] + photo.sheetCorners[3]);
    QVERIFY(!snapCorner(photo.image, middleOfSheet, 15).ok());
}

void TestSheet::errorEstimateGrowsWithNoise()
{
    SynthOptions o = randomSynthOptions(61);
    double previous = 0;
    for (const double noise : {1.0, 8.0, 20.0}) {
        o.noiseSigma = noise;
        const SynthPhoto photo = makeSynthPhoto(o);
        const auto sheet = findSheet(photo.image, {});
        QVERIFY(sheet.ok());
        const double estimate = calibrationErrorAtPhotoCornersMm(*sheet, photo.image.size());
        qInfo("noise %.0f levels: far-side estimate %.3f mm", noise, estimate);
        QVERIFY(std::isfinite(estimate));
        QVERIFY(estimate > previous);
        previous = estimate;
    }
}

void TestSheet::refusesWithoutSheet()
{
    for (const bool white : {true, false}) {
        SynthOptions o = randomSynthOptions(71);
        o.withSheet = false;
        o.whitePiece = white;
        const auto sheet = findSheet(makeSynthPhoto(o).image, {});
        QVERIFY(!sheet.ok());
        QCOMPARE(sheet.error().code, ErrorCode::NoSheetFound);
    }
    const auto blank = findSheet(cv::Mat(600, 800, CV_8UC1, cv::Scalar(128)), {});
    QVERIFY(!blank.ok());
    QCOMPARE(blank.error().code, ErrorCode::NoSheetFound);
    QCOMPARE(findSheet(cv::Mat(), {}).error().code, ErrorCode::InvalidImage);
    QCOMPARE(findSheet(cv::Mat(10, 10, CV_32F), {}).error().code, ErrorCode::InvalidImage);
}

// Rectified by the true homography (the found one carries the finder's error) with rectifyWorld (the
// app's and the command line's warp), the sheet's edges measured in the rectified image (pixel → mm by
// the patch's mapping) lie on the sheet's rectangle.
void TestSheet::rectifyMapsSheetToRectangle()
{
    // A plain table and little noise: this checks the maps' pixel conventions (half a pixel is 0.08 mm
    // here), not the edge finder.
    SynthOptions o = randomSynthOptions(81);
    o.tableTexture = 0;
    o.noiseSigma = 0.5;
    const SynthPhoto photo = makeSynthPhoto(o);
    const auto rectified = rectifyWorld(photo.image, photo.worldToPhoto, {-15, -15}, {225, 312}, 6, false);
    QVERIFY(rectified.ok());
    QCOMPARE(rectified->image.cols, 1440);
    const PixelMapping &toMm = rectified->mapping;
    const std::array<geo::Point, 4> rect{geo::Point(0, 0), geo::Point(210, 0), geo::Point(210, 297),
                                         geo::Point(0, 297)};
    SheetOptions options;
    std::array<geo::Point, 4> hints;
    for (int i = 0; i < 4; ++i)
        hints[i] = toMm.toPixel(rect[i]) + geo::Point(3, -2);
    options.cornerHints = hints;
    options.hintRadiusPx = 10;
    const auto sheet = findSheet(rectified->image, options);
    QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
    double worst = 0;
    for (int i = 0; i < 4; ++i)
        worst = std::max(worst, (toMm.toMm(sheet->corners[i]) - rect[i]).norm());
    qInfo("rectified sheet corners within %.4f mm of the rectangle", worst);
    QVERIFY(worst < 0.05);
}

// A 12-megapixel photo (4000 x 3000); the time is printed, not asserted (benchmarks own timing).
void TestSheet::twelveMegapixelPhoto()
{
    SynthOptions o = randomSynthOptions(91, {4000, 3000});
    o.supersample = 2;
    o.blurSigmaPx = 1.8;
    const SynthPhoto photo = makeSynthPhoto(o);
    const auto start = std::chrono::steady_clock::now();
    const auto sheet = findSheet(photo.image, {});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    QVERIFY(sheet.ok());
    const double e = maxCornerError(*sheet, photo);
    qInfo("12 MP: corner error %.3f px, findSheet %.0f ms", e, ms);
    QVERIFY(e < 0.3);
}

QTEST_GUILESS_MAIN(TestSheet)
#include "tst_sheet.moc"
