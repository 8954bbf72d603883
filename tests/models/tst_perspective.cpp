// The perspective calibration of the background picture (issue #22) in the model layer: a synthetic
// millimetre grid photographed at an angle (warped by a known homography) comes back rectified with
// every crossing within 0.2 mm, through Kontur's own picture → world transform and in the pixels of
// a rectified drawing; the corners in any of their 24 orders; one undo step with the units; the
// refinement drag of a corner; clearing; the interplay with the two-point calibration, the lock and
// the background move; the .kontur round trip and documents written before it.
#include "../ownfolders.h"
#include "io/document.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/trace/perspective.h"
#include "models/trace/tracecontroller.h"

#include <QImage>
#include <QPainter>
#include <QPolygonF>
#include <QSignalSpy>
#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>

using kontur::Background;
using kontur::CalibrationTool;
using kontur::EditController;
using kontur::PerspectiveTool;
using kontur::TraceController;
using kontur::geo::Point;
using Quad = kontur::perspective::Quad;

namespace {

// The paper: 150 × 200 mm at 4 px per mm, a line every millimetre, every centimetre a thicker one.
constexpr double kPaperWidth = 150.0, kPaperHeight = 200.0, kPxPerMm = 4.0;

QImage paper()
{
    QImage image(int(kPaperWidth * kPxPerMm) + 1, int(kPaperHeight * kPxPerMm) + 1, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing); // lines centred on their coordinate
    for (int i = 0; i <= int(kPaperWidth); ++i) {
        p.setPen(QPen(i % 10 == 0 ? Qt::black : QColor(170, 170, 170), i % 10 == 0 ? 3.0 : 1.0));
        p.drawLine(QPointF(i * kPxPerMm, 0), QPointF(i * kPxPerMm, image.height()));
    }
    for (int j = 0; j <= int(kPaperHeight); ++j) {
        p.setPen(QPen(j % 10 == 0 ? Qt::black : QColor(170, 170, 170), j % 10 == 0 ? 3.0 : 1.0));
        p.drawLine(QPointF(0, j * kPxPerMm), QPointF(image.width(), j * kPxPerMm));
    }
    return image;
}

// Where the paper's corners are in the photo: a sheet seen from above its bottom edge, leaning away.
Quad photoQuad()
{
    return {QPointF(250, 100), QPointF(700, 120), QPointF(820, 860), QPointF(150, 820)};
}

// The known homography paper pixels → photo pixels.
QTransform paperToPhoto()
{
    const QPolygonF from{QList<QPointF>{QPointF(0, 0), QPointF(kPaperWidth * kPxPerMm, 0),
                                        QPointF(kPaperWidth * kPxPerMm, kPaperHeight * kPxPerMm),
                                        QPointF(0, kPaperHeight * kPxPerMm)}};
    const Quad q = photoQuad();
    QTransform t;
    [[maybe_unused]] const bool ok = QTransform::quadToQuad(from, QPolygonF(QList<QPointF>(q.begin(), q.end())), t);
    return t;
}

QImage photo()
{
    QImage image(1000, 900, QImage::Format_RGB32);
    image.fill(QColor(90, 70, 50)); // the table
    QPainter p(&image);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.setTransform(paperToPhoto());
    p.drawImage(QPointF(0, 0), paper());
    return image;
}

Background picture()
{
    Background bg;
    bg.file = QStringLiteral("/nonexistent/photo.png"); // only the placement matters here
    bg.origin = QPointF(-500, 450);
    bg.scale = 1.0;
    return bg;
}

double distance(const Point &a, const Point &b)
{
    return (a - b).norm();
}

} // namespace

class TestPerspective final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cornersInAny24Orders();
    void notAQuadrilateralIsRefused();
    void gridComesBackWithinATenthOfAMillimetre();
    void rectifiedPixelsShowTheGrid();
    void orientationFromTheMarksOrChosen();
    void oneUndoStepWithTheUnits();
    void presetsKeepARealDocumentUnit();
    void tapsThenApply();
    void refinementDragIsOneUndoStep();
    void clearingReturnsToThePreviousPlacement();
    void twoPointCalibrationLockAndMove();
    void saveAndOpenRoundTrip();
    void documentsWithoutItStillOpen();
    void drawnPartStopsBeforeTheHorizon();
};

void TestPerspective::initTestCase()
{
    QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath()));
    QLocale::setDefault(QLocale::c());
}

void TestPerspective::cornersInAny24Orders()
{
    const Quad q = photoQuad();
    std::array<int, 4> order{0, 1, 2, 3};
    int permutations = 0;
    do {
        const Quad given{q[order[0]], q[order[1]], q[order[2]], q[order[3]]};
        const auto ordered = kontur::perspective::orderCorners(given);
        QVERIFY(ordered);
        QVERIFY2(*ordered == q,
                 qPrintable(QStringLiteral("order %1%2%3%4").arg(order[0]).arg(order[1]).arg(order[2]).arg(order[3])));
        ++permutations;
    } while (std::next_permutation(order.begin(), order.end()));
    QCOMPARE(permutations, 24);
    // A sheet turned 45° (a diamond): its top corner is the top-left, then clockwise on the screen.
    const Quad diamond{QPointF(100, 0), QPointF(200, 100), QPointF(100, 200), QPointF(0, 100)};
    const auto d = kontur::perspective::orderCorners({diamond[2], diamond[0], diamond[3], diamond[1]});
    QVERIFY(d);
    QCOMPARE((*d)[1], QPointF(200, 100)); // clockwise: right after the start
    QCOMPARE((*d)[3], QPointF(0, 100));
}

void TestPerspective::notAQuadrilateralIsRefused()
{
    using kontur::perspective::orderCorners;
    // One point inside the triangle of the others, three on a line, two equal.
    QVERIFY(!orderCorners({QPointF(0, 0), QPointF(100, 0), QPointF(50, 100), QPointF(50, 30)}));
    QVERIFY(!orderCorners({QPointF(0, 0), QPointF(50, 0), QPointF(100, 0), QPointF(50, 80)}));
    QVERIFY(!orderCorners({QPointF(0, 0), QPointF(0, 0), QPointF(100, 0), QPointF(50, 80)}));

    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    const int steps = editor.undoStack()->count();
    QVERIFY(!trace.perspective()->calibratePerspectiveImage(
        {QPointF(0, 0), QPointF(100, 0), QPointF(50, 100), QPointF(50, 30)}, 100, 100, QStringLiteral("mm"),
        PerspectiveTool::AutoOrientation));
    QVERIFY(!trace.message().isEmpty());
    QVERIFY(!trace.perspective()->calibratePerspectiveImage(photoQuad(), 0.0, 100, QStringLiteral("mm"),
                                                            PerspectiveTool::AutoOrientation));
    QVERIFY(!trace.perspective()->calibratePerspectiveImage(photoQuad(), 150, 200, QStringLiteral("px"),
                                                            PerspectiveTool::AutoOrientation));
    QCOMPARE(editor.undoStack()->count(), steps);
    QVERIFY(!editor.document()->background().perspective);
}

void TestPerspective::gridComesBackWithinATenthOfAMillimetre()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    const Quad q = photoQuad();
    // Given in a scrambled order.
    QVERIFY(trace.perspective()->calibratePerspectiveImage({q[2], q[0], q[3], q[1]}, kPaperHeight, kPaperWidth,
                                                           QStringLiteral("mm"), PerspectiveTool::AutoOrientation));
    const Background &bg = editor.document()->background();
    QVERIFY(bg.perspective);
    QCOMPARE(bg.rectWidth, kPaperWidth); // portrait, as marked
    QCOMPARE(bg.rectHeight, kPaperHeight);
    QCOMPARE(editor.document()->units(), QStringLiteral("mm"));
    const QTransform g = paperToPhoto();
    const Point topLeft(bg.rectOrigin.x(), bg.rectOrigin.y());
    double worst = 0.0;
    for (int i = 0; i <= int(kPaperWidth); ++i) {
        for (int j = 0; j <= int(kPaperHeight); ++j) {
            const QPointF inPhoto = g.map(QPointF(i * kPxPerMm, j * kPxPerMm));
            const Point world = bg.toWorld(inPhoto);
            const Point expected = topLeft + Point(i, -j);
            worst = std::max(worst, distance(world, expected));
            // And back: the world point is that photo pixel.
            const QPointF back = bg.toImage(expected);
            QVERIFY(QLineF(back, inPhoto).length() <= 1e-6);
        }
    }
    QVERIFY2(worst <= 0.2, qPrintable(QString::number(worst)));
    // The exact homography reproduces them to rounding, far inside the 0.2 mm asked.
    QVERIFY2(worst <= 1e-9, qPrintable(QString::number(worst)));
}

void TestPerspective::rectifiedPixelsShowTheGrid()
{
    // The photo drawn through Kontur's picture → world transform (as the software renderer and the
    // magnifier do, with QPainter) at 10 px per mm: the centimetre lines lie where they belong.
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QVERIFY(trace.perspective()->calibratePerspectiveImage(photoQuad(), kPaperWidth, kPaperHeight, QStringLiteral("mm"),
                                                           PerspectiveTool::Portrait));
    const Background &bg = editor.document()->background();
    QVERIFY(bg.placedInPerspective());
    const QTransform h = kontur::perspective::toQTransform(bg.imageToWorld());
    constexpr double pxPerMm = 10.0;
    // world → drawing: the rectangle's top-left at (0, 0), y down.
    const QTransform toDrawing(pxPerMm, 0, 0, -pxPerMm, -bg.rectOrigin.x() * pxPerMm, bg.rectOrigin.y() * pxPerMm);
    QImage drawing(int(kPaperWidth * pxPerMm), int(kPaperHeight * pxPerMm), QImage::Format_RGB32);
    drawing.fill(Qt::white);
    {
        QPainter p(&drawing);
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.setTransform(h * toDrawing);
        p.drawImage(QPointF(0, 0), photo());
    }
    // Along rows halfway between centimetre lines, the darkness-weighted centre of each vertical
    // centimetre line, and likewise down columns for the horizontal ones.
    double worst = 0.0;
    int lines = 0;
    const auto darkness = [&](int x, int y) { return 255.0 - qGray(drawing.pixel(x, y)); };
    for (int row = 1; row < int(kPaperHeight / 10); ++row) {
        const int y = int((row * 10 - 5) * pxPerMm);
        for (int col = 1; col < int(kPaperWidth / 10); ++col) {
            const double expected = col * 10 * pxPerMm;
            double sum = 0.0, weighted = 0.0;
            for (int x = int(expected - 24); x <= int(expected + 24); ++x) {
                const double d = std::max(0.0, darkness(x, y) - 120.0); // the thick black line only
                sum += d;
                weighted += d * (x + 0.5); // a pixel's centre
            }
            QVERIFY(sum > 0.0);
            worst = std::max(worst, std::abs(weighted / sum - expected) / pxPerMm);
            ++lines;
        }
    }
    for (int col = 1; col < int(kPaperWidth / 10); ++col) {
        const int x = int((col * 10 - 5) * pxPerMm);
        for (int row = 1; row < int(kPaperHeight / 10); ++row) {
            const double expected = row * 10 * pxPerMm;
            double sum = 0.0, weighted = 0.0;
            for (int y = int(expected - 24); y <= int(expected + 24); ++y) {
                const double d = std::max(0.0, darkness(x, y) - 120.0);
                sum += d;
                weighted += d * (y + 0.5);
            }
            QVERIFY(sum > 0.0);
            worst = std::max(worst, std::abs(weighted / sum - expected) / pxPerMm);
            ++lines;
        }
    }
    QVERIFY(lines > 500);
    QVERIFY2(worst <= 0.2, qPrintable(QString::number(worst)));
}

void TestPerspective::orientationFromTheMarksOrChosen()
{
    // The photo quad looks portrait; a landscape rectangle of the same sides gets turned to fit it.
    QVERIFY(!kontur::perspective::looksLandscape(photoQuad()));
    const Quad wide{QPointF(0, 0), QPointF(400, 10), QPointF(390, 200), QPointF(5, 210)};
    QVERIFY(kontur::perspective::looksLandscape(wide));
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QVERIFY(trace.perspective()->calibratePerspectiveImage(wide, 210, 297, QStringLiteral("mm"),
                                                           PerspectiveTool::AutoOrientation));
    QCOMPARE(editor.document()->background().rectWidth, 297.0);
    QCOMPARE(editor.document()->background().rectHeight, 210.0);
    editor.undo();
    QVERIFY(trace.perspective()->calibratePerspectiveImage(wide, 210, 297, QStringLiteral("mm"),
                                                           PerspectiveTool::Portrait));
    QCOMPARE(editor.document()->background().rectWidth, 210.0);
    QCOMPARE(editor.document()->background().rectHeight, 297.0);
}

void TestPerspective::oneUndoStepWithTheUnits()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    editor.commands()->addCurves(
        {kontur::Curve::make(kontur::CurveKind::NaturalSpline, {Point(0, 0), Point(30, 10), Point(60, 0)})},
        QStringLiteral("add"));
    const double lengthBefore = editor.document()->curve(0).length();
    const Background before = editor.document()->background();
    const int steps = editor.undoStack()->count();
    QSignalSpy mapped(&trace, &TraceController::worldMapped);
    QVERIFY(trace.perspective()->calibratePerspectiveImage(photoQuad(), kPaperWidth, kPaperHeight, QStringLiteral("mm"),
                                                           PerspectiveTool::AutoOrientation));
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    QCOMPARE(editor.undoStack()->undoText(), QStringLiteral("Calibrate perspective"));
    QCOMPARE(mapped.count(), 1);
    // The world is scaled so that the marked quadrilateral's area is the sheet's: the view and the
    // curves follow (the picture stays about where it was on the screen).
    const double k = mapped.at(0).at(0).toDouble();
    QVERIFY(std::abs(editor.document()->curve(0).length() - k * lengthBefore) <= 1e-9);
    const Quad q = photoQuad();
    const double photoArea = std::abs(QLineF(q[0], q[2]).dx() * QLineF(q[1], q[3]).dy() -
                                      QLineF(q[0], q[2]).dy() * QLineF(q[1], q[3]).dx()) /
                             2.0;
    QVERIFY(std::abs(k * k * photoArea - kPaperWidth * kPaperHeight) <= 1e-6 * kPaperWidth * kPaperHeight);
    editor.undo();
    QVERIFY(editor.document()->background() == before);
    QCOMPARE(editor.document()->units(), QStringLiteral("px"));
    QVERIFY(std::abs(editor.document()->curve(0).length() - lengthBefore) <= 1e-9);
    editor.redo();
    QVERIFY(editor.document()->background().perspective);
    QCOMPARE(editor.document()->units(), QStringLiteral("mm"));
}

void TestPerspective::presetsKeepARealDocumentUnit()
{
    double a = 0, b = 0;
    QVERIFY(PerspectiveTool::rectangleSize(PerspectiveTool::Letter, QStringLiteral("in"), a, b));
    QCOMPARE(a, 8.5);
    QCOMPARE(b, 11.0);
    QVERIFY(PerspectiveTool::rectangleSize(PerspectiveTool::A4, QStringLiteral("cm"), a, b));
    QVERIFY(std::abs(a - 21.0) <= 1e-12 && std::abs(b - 29.7) <= 1e-12);
    QVERIFY(PerspectiveTool::rectangleSize(PerspectiveTool::Mat1in, QStringLiteral("mm"), a, b));
    QCOMPARE(a, 25.4);
    QVERIFY(!PerspectiveTool::rectangleSize(PerspectiveTool::CustomRectangle, QStringLiteral("mm"), a, b));
    QCOMPARE(PerspectiveTool::rectangleUnit(PerspectiveTool::Letter), QStringLiteral("in"));
    QCOMPARE(PerspectiveTool::rectangleUnit(PerspectiveTool::A4), QStringLiteral("mm"));
}

void TestPerspective::tapsThenApply()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    trace.setTool(TraceController::Tool::Perspective);
    QVERIFY(!trace.perspective()->calibratePerspective(PerspectiveTool::Letter, PerspectiveTool::AutoOrientation, {},
                                                       {}, {}));
    QVERIFY(!trace.message().isEmpty());
    const Background &bg = editor.document()->background();
    const Quad q = photoQuad();
    for (int i : {3, 1, 0, 2}) {
        const Point w = bg.toWorld(q[i]);
        trace.tap(QPointF(w.x(), w.y()), 1.0);
    }
    QCOMPARE(trace.perspective()->marks(), 4);
    QVERIFY(!trace.perspective()->landscape());
    // A Letter sheet, in inches (the document had no real unit yet).
    QVERIFY(trace.perspective()->calibratePerspective(PerspectiveTool::Letter, PerspectiveTool::AutoOrientation, {}, {},
                                                      {}));
    QCOMPARE(trace.perspective()->marks(), 0);
    QCOMPARE(editor.document()->units(), QStringLiteral("in"));
    QCOMPARE(editor.document()->background().rectWidth, 8.5);
    QCOMPARE(editor.document()->background().rectHeight, 11.0);
    QCOMPARE(editor.document()->background().corners, q);
    // Typed sides in the UI language's format, a custom size.
    QLocale::setDefault(QLocale(QLocale::Latvian));
    for (int i : {0, 1, 2, 3}) {
        const Point w = editor.document()->background().toWorld(q[i]);
        trace.tap(QPointF(w.x(), w.y()), 0.01);
    }
    QVERIFY(!trace.perspective()->calibratePerspective(PerspectiveTool::CustomRectangle,
                                                       PerspectiveTool::AutoOrientation, QStringLiteral("abc"),
                                                       QStringLiteral("2"), QStringLiteral("cm")));
    QVERIFY(trace.perspective()->calibratePerspective(PerspectiveTool::CustomRectangle,
                                                      PerspectiveTool::AutoOrientation, QStringLiteral("15,5"),
                                                      QStringLiteral("20"), QStringLiteral("cm")));
    QLocale::setDefault(QLocale::c());
    QCOMPARE(editor.document()->units(), QStringLiteral("cm"));
    QCOMPARE(editor.document()->background().rectWidth, 15.5);
    QCOMPARE(editor.document()->background().rectHeight, 20.0);
    QCOMPARE(editor.document()->background().corners, q);
}

void TestPerspective::refinementDragIsOneUndoStep()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    // The bottom-right corner marked 6 px off in the picture.
    Quad marked = photoQuad();
    marked[2] += QPointF(6, -4);
    QVERIFY(trace.perspective()->calibratePerspectiveImage(marked, kPaperWidth, kPaperHeight, QStringLiteral("mm"),
                                                           PerspectiveTool::Portrait));
    trace.setTool(TraceController::Tool::Perspective);
    const Background before = editor.document()->background();
    const std::vector<Point> handles = trace.perspective()->handles();
    QCOMPARE(handles.size(), std::size_t(4));
    QVERIFY(distance(handles[2], before.toWorld(marked[2])) <= 1e-9);
    // The user drags that handle onto where the sheet's real corner shows now.
    const Point real = before.toWorld(photoQuad()[2]);
    const int steps = editor.undoStack()->count();
    QVERIFY(
        !trace.perspective()->beginCornerDrag(QPointF(handles[2].x() + 50, handles[2].y()), 2.0)); // not on a corner
    QVERIFY(trace.perspective()->beginCornerDrag(QPointF(handles[2].x() + 0.5, handles[2].y()), 2.0));
    QVERIFY(trace.perspective()->cornerDragging());
    for (int s = 1; s <= 10; ++s) {
        const Point at = handles[2] + (real - handles[2]) * (s / 10.0);
        trace.perspective()->dragCornerTo(QPointF(at.x(), at.y()));
    }
    // Nothing changes in the document until the finger lifts.
    QVERIFY(editor.document()->background() == before);
    trace.perspective()->endCornerDrag();
    QVERIFY(!trace.perspective()->cornerDragging());
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    const Background &after = editor.document()->background();
    QVERIFY(QLineF(after.corners[2], photoQuad()[2]).length() <= 1e-6);
    // The sheet is now exactly rectified: its far corner at the rectangle's corner.
    const Point corner(after.rectOrigin.x() + kPaperWidth, after.rectOrigin.y() - kPaperHeight);
    QVERIFY(distance(after.toWorld(photoQuad()[2]), corner) <= 1e-6);
    editor.undo();
    QVERIFY(editor.document()->background() == before);
    // A drop that would fold the quadrilateral is refused, and nothing changes.
    QVERIFY(trace.perspective()->beginCornerDrag(QPointF(handles[2].x(), handles[2].y()), 2.0));
    trace.perspective()->dragCornerTo(QPointF(handles[0].x() + 1, handles[0].y() - 1));
    trace.perspective()->endCornerDrag();
    QVERIFY(editor.document()->background() == before);
    QVERIFY(!trace.message().isEmpty());
}

void TestPerspective::clearingReturnsToThePreviousPlacement()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QSignalSpy mapped(&trace, &TraceController::worldMapped);
    QVERIFY(trace.perspective()->calibratePerspectiveImage(photoQuad(), kPaperWidth, kPaperHeight, QStringLiteral("mm"),
                                                           PerspectiveTool::Portrait));
    const double k = mapped.at(0).at(0).toDouble();
    const int steps = editor.undoStack()->count();
    trace.perspective()->clearPerspective();
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    const Background &bg = editor.document()->background();
    QVERIFY(!bg.perspective);
    // The similarity placement from before, in the new units (the world was scaled by k).
    QCOMPARE(bg.origin, picture().origin * k);
    QCOMPARE(bg.scale, k);
    QCOMPARE(bg.rotation, 0.0);
    QCOMPARE(editor.document()->units(), QStringLiteral("mm"));
    editor.undo();
    QVERIFY(editor.document()->background().perspective);
}

void TestPerspective::twoPointCalibrationLockAndMove()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    // A two-point calibration first: the perspective one replaces its placement, its marks stay.
    QVERIFY(trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(300, 400), 50.0, QStringLiteral("mm"),
                                                      CalibrationTool::NoAlign));
    QVERIFY(trace.perspective()->calibratePerspectiveImage(photoQuad(), kPaperWidth, kPaperHeight, QStringLiteral("mm"),
                                                           PerspectiveTool::Portrait));
    QVERIFY(editor.document()->background().calibrated);
    // While it is set, a two-point calibration is refused (with a message).
    const int steps = editor.undoStack()->count();
    QVERIFY(!trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(300, 400), 50.0, QStringLiteral("mm"),
                                                       CalibrationTool::NoAlign));
    QVERIFY(!trace.message().isEmpty());
    QCOMPARE(editor.undoStack()->count(), steps);
    // Moving the background moves the rectified picture.
    const Point before = editor.document()->background().toWorld(QPointF(400, 400));
    trace.setTool(TraceController::Tool::MoveBackground);
    QVERIFY(trace.backgroundMove()->begin());
    trace.backgroundMove()->moveBy(QPointF(10, -5));
    trace.backgroundMove()->end();
    const Point after = editor.document()->background().toWorld(QPointF(400, 400));
    QVERIFY(distance(after - before, Point(10, -5)) <= 1e-9);
    // Locked: neither a new calibration, nor a refinement, nor clearing.
    trace.setBackgroundLocked(true);
    const int locked = editor.undoStack()->count();
    QVERIFY(!trace.perspective()->calibratePerspectiveImage(photoQuad(), 100, 100, QStringLiteral("mm"),
                                                            PerspectiveTool::AutoOrientation));
    trace.setTool(TraceController::Tool::Perspective);
    const std::vector<Point> handles = trace.perspective()->handles();
    QVERIFY(!trace.perspective()->beginCornerDrag(QPointF(handles[0].x(), handles[0].y()), 1.0));
    trace.perspective()->clearPerspective();
    QVERIFY(editor.document()->background().perspective);
    QCOMPARE(editor.undoStack()->count(), locked);
}

void TestPerspective::saveAndOpenRoundTrip()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QVERIFY(trace.perspective()->calibratePerspectiveImage(photoQuad(), 8.5, 11.0, QStringLiteral("in"),
                                                           PerspectiveTool::AutoOrientation));
    const QByteArray json = kontur::io::documentToJson(kontur::toDocumentData(*editor.document()));
    QVERIFY(json.contains("\"perspective\""));
    QVERIFY(json.contains("\"corners\""));
    const auto read = kontur::io::documentFromJson(json);
    QVERIFY2(read.ok(), qPrintable(read.ok() ? QString() : read.error().message));
    QCOMPARE(read->units, QStringLiteral("in"));
    const Background restored = kontur::fromRecord(*read->background);
    QVERIFY(restored == editor.document()->background());
    // The same transform after reopening: a grid crossing lands where it did.
    const QPointF p(500, 500);
    QCOMPARE(restored.toWorld(p), editor.document()->background().toWorld(p));
    // Written again, byte for byte the same.
    QCOMPARE(kontur::io::documentToJson(*read), json);
    // Bad members are reported with their place.
    QByteArray bad = json;
    bad.replace("\"width\": 8.5", "\"width\": -1");
    QVERIFY(!kontur::io::documentFromJson(bad).ok() ||
            !kontur::io::validateDocument(*kontur::io::documentFromJson(bad)));
}

void TestPerspective::documentsWithoutItStillOpen()
{
    // A document of the version before (tests/data/fuzz/document/background.kontur's shape).
    const QByteArray old = R"({"format": "kontur", "version": 1, "units": "mm", "curves": [],
        "background": {"file": "a.png", "opacity": 0.5, "scale": 2,
                       "calibration": {"a": [0, 0], "b": [1, 1], "distance": 3}}})";
    const auto read = kontur::io::documentFromJson(old);
    QVERIFY(read.ok());
    const Background bg = kontur::fromRecord(*read->background);
    QVERIFY(!bg.perspective);
    QVERIFY(bg.calibrated);
    QCOMPARE(bg.scale, 2.0);
    // And one without a perspective calibration is written without the member.
    QVERIFY(!kontur::io::documentToJson(*read).contains("perspective"));
    // A perspective member with three corners is an error, not a silent loss.
    const QByteArray three = R"({"format": "kontur", "version": 1, "units": "mm", "curves": [],
        "background": {"file": "a.png", "perspective": {"corners": [[0,0],[1,0],[1,1]],
                       "width": 1, "height": 1, "origin": [0, 0]}}})";
    QVERIFY(!kontur::io::documentFromJson(three).ok());
}

void TestPerspective::drawnPartStopsBeforeTheHorizon()
{
    // A steep view: the paper's far edge much shorter than its near one; the horizon crosses the
    // photo above the paper. The part drawn keeps the paper and stops short of the horizon.
    const Quad steep{QPointF(450, 300), QPointF(550, 300), QPointF(900, 800), QPointF(100, 800)};
    const auto h = kontur::Background::homography(steep, 100, 100, QPointF(0, 0));
    QVERIFY(h);
    const QRectF drawn = kontur::perspective::drawnRect(*h, steep, QSizeF(1000, 1000));
    QVERIFY(drawn.contains(QRectF(100, 300, 800, 500)));
    QVERIFY(drawn.top() > 0.0);       // the horizon is cut off
    QCOMPARE(drawn.bottom(), 1000.0); // the near side reaches the edge
    const auto w = [&](QPointF p) { return h->denominator(Point(p.x(), p.y())); };
    const double w0 = w(QPointF(500, 550));
    // Here the far edge itself lies below a quarter (0.22): the limit is the far edge's own.
    const double least = std::min(0.25, w(steep[0]) / w0);
    QVERIFY(least < 0.25);
    for (const QPointF &c : {drawn.topLeft(), drawn.topRight(), drawn.bottomLeft(), drawn.bottomRight()})
        QVERIFY(w(c) / w0 >= least - 1e-9);
    // A gentler view: the whole photo is drawn.
    const Quad gentle = photoQuad();
    const auto g = kontur::Background::homography(gentle, 150, 200, QPointF(0, 0));
    QVERIFY(g);
    QCOMPARE(kontur::perspective::drawnRect(*g, gentle, QSizeF(1000, 900)), QRectF(0, 0, 1000, 900));
}

QTEST_MAIN(TestPerspective)
#include "tst_perspective.moc"
