// Tracing a pattern (issue #10) in the model layer: calibration maps two known picture points to the
// typed distance exactly and is one undo step; an SVG export of a calibrated 100 mm line is 100 mm
// long in the file; a freehand stroke becomes one composite curve with its corners (one undo step);
// seam length, straight measure and deviation; the background lock is saved and undoable. Over 600
// lines because each tracing tool's oracles are written out.
#include "../curveids.h"
#include "../ownfolders.h"
#include "io/document.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/text/numbers.h"
#include "models/text/units.h"
#include "models/trace/tracecontroller.h"
#include "picture/picture.h"

#include <QImageWriter>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using kontur::Background;
using kontur::CalibrationTool;
using kontur::CurveKind;
using kontur::EditController;
using kontur::FreehandTool;
using kontur::MeasureTool;
using kontur::SeamTool;
using kontur::TraceController;
using kontur::geo::Point;

namespace {

Background picture()
{
    Background bg;
    bg.file = QStringLiteral("/nonexistent/pattern.png"); // only its placement matters here
    bg.origin = QPointF(-200, 150);
    bg.scale = 1.0;
    return bg;
}

double distance(const Point &a, const Point &b)
{
    return (a - b).norm();
}

} // namespace

class TestTrace final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void placingAndTracingEndEachOther();
    void calibrationMapsMarksToTypedDistance_data();
    void calibrationMapsMarksToTypedDistance();
    void calibrationIsOneUndoStepAndCarriesCurves();
    void calibrationByTapsAndTypedText();
    void calibrationRefusals();
    void svgOfCalibrated100mmLineIs100mm();
    void freehandStrokeIsOneCompositeCurve();
    void shortStrokeIsNoCurve();
    void toleranceNeverBelowThePointersPixelSteps();
    void seamMeasureAndDeviation();
    void snapping();
    void lockIsSavedAndUndoable();
    void backgroundMoveIsOneUndoStep();
    void backgroundDragIsOneCommandFromItsFirstStep();
    void lengthsWithTheirUnitsDecimals_data();
    void lengthsWithTheirUnitsDecimals();
    void listLengthsCarryTheirUnit();
    void textsFollowALanguageSwitch();
    void pictureIsPlacedAsShown();
};

void TestTrace::initTestCase()
{
    // Settings and recent files go to the process's own folders (ownfolders.h).
    QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath()));
    QLocale::setDefault(QLocale::c());
}

void TestTrace::calibrationMapsMarksToTypedDistance_data()
{
    QTest::addColumn<QPointF>("a");
    QTest::addColumn<QPointF>("b");
    QTest::addColumn<double>("distance");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<int>("align");
    QTest::addRow("horizontal 400 px = 100 mm")
        << QPointF(10, 20) << QPointF(410, 20) << 100.0 << "mm" << int(CalibrationTool::NoAlign);
    QTest::addRow("slanted, 25.4 cm") << QPointF(13.5, 77.25) << QPointF(301.125, 250.5) << 25.4 << "cm"
                                      << int(CalibrationTool::NoAlign);
    QTest::addRow("slanted, aligned horizontally")
        << QPointF(13.5, 77.25) << QPointF(301.125, 250.5) << 7.0 << "in" << int(CalibrationTool::Horizontal);
    QTest::addRow("slanted, aligned vertically")
        << QPointF(50, 40) << QPointF(90, 640) << 600.0 << "mm" << int(CalibrationTool::Vertical);
}

void TestTrace::calibrationMapsMarksToTypedDistance()
{
    QFETCH(QPointF, a);
    QFETCH(QPointF, b);
    QFETCH(double, distance);
    QFETCH(QString, unit);
    QFETCH(int, align);
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QVERIFY(
        trace.calibration()->calibrateImagePoints(a, b, distance, unit, static_cast<CalibrationTool::Align>(align)));
    const Background &bg = editor.document()->background();
    QCOMPARE(editor.document()->units(), unit);
    QVERIFY(bg.calibrated);
    QCOMPARE(bg.calibrationDistance, distance);
    const Point wa = bg.toWorld(a), wb = bg.toWorld(b);
    QVERIFY2(std::abs(::distance(wa, wb) - distance) <= 1e-12 * distance,
             qPrintable(QString::number(::distance(wa, wb), 'g', 17)));
    if (align == CalibrationTool::Horizontal)
        QVERIFY(std::abs(wb.y() - wa.y()) <= 1e-12 * distance);
    if (align == CalibrationTool::Vertical)
        QVERIFY(std::abs(wb.x() - wa.x()) <= 1e-12 * distance);
    // World and picture coordinates are inverse maps.
    const QPointF back = bg.toImage(wb);
    QVERIFY(std::hypot(back.x() - b.x(), back.y() - b.y()) <= 1e-9);
    // The default tolerance follows the units.
    QCOMPARE(trace.freehand()->tolerance(), FreehandTool::defaultTolerance(unit));
}

void TestTrace::calibrationIsOneUndoStepAndCarriesCurves()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    // A curve traced on the picture in pixels: its knots sit on picture points.
    const QPointF knotImage(110, 70);
    const Point knotWorld = editor.document()->background().toWorld(knotImage);
    editor.commands()->addCurves({kontur::Curve::make(CurveKind::Composite, {knotWorld, Point(50, 0), Point(80, -40)})},
                                 QStringLiteral("add"));
    editor.commands()->addCurves(
        {kontur::Curve::make(CurveKind::NaturalSpline, {Point(0, 0), Point(30, 10), Point(60, 0)})},
        QStringLiteral("add"));
    const std::vector<kontur::Curve> before = editor.document()->curves();
    const Background bgBefore = editor.document()->background();
    const int steps = editor.undoStack()->count();
    // The view is told how the world was mapped: on the calibration, its undo and its redo.
    QSignalSpy mapped(&trace, &TraceController::worldMapped);

    QVERIFY(trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(300, 400), 50.0, QStringLiteral("mm"),
                                                      CalibrationTool::Horizontal));
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    QCOMPARE(mapped.count(), 1);
    const double k = mapped.at(0).at(0).toDouble();
    const double theta = mapped.at(0).at(1).toDouble();
    QVERIFY(std::abs(k - 0.1) <= 1e-12);
    // The traced knot is still on its picture point.
    const Background &bg = editor.document()->background();
    const Point moved = editor.document()->curve(0).composite().knot(0);
    QVERIFY2(distance(moved, bg.toWorld(knotImage)) <= 1e-9, qPrintable(QString::number(moved.x())));
    // 500 px became 50 mm: every length scaled by 0.1.
    QVERIFY(std::abs(editor.document()->curve(1).length() - 0.1 * before[1].length()) <= 1e-9);

    editor.undo();
    QCOMPARE(mapped.count(), 2);
    QVERIFY(std::abs(mapped.at(1).at(0).toDouble() - 1.0 / k) <= 1e-9);
    QCOMPARE(mapped.at(1).at(1).toDouble(), -theta);
    QCOMPARE(editor.document()->units(), QStringLiteral("px"));
    QVERIFY(editor.document()->background() == bgBefore);
    for (std::size_t i = 0; i < before.size(); ++i)
        QVERIFY(editor.document()->curves()[i].sameState(before[i]));
    editor.redo();
    QCOMPARE(mapped.count(), 3);
    QCOMPARE(mapped.at(2).at(0).toDouble(), k);
    QCOMPARE(editor.document()->units(), QStringLiteral("mm"));
    QVERIFY(distance(editor.document()->curve(0).composite().knot(0), moved) == 0.0);
}

void TestTrace::calibrationByTapsAndTypedText()
{
    QLocale::setDefault(QLocale(QLocale::Latvian));
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    trace.setTool(TraceController::Tool::Calibrate);
    const Background &bg = editor.document()->background();
    trace.tap(QPointF(bg.toWorld(QPointF(10, 10)).x(), bg.toWorld(QPointF(10, 10)).y()), 1.0);
    trace.tap(QPointF(bg.toWorld(QPointF(10, 260)).x(), bg.toWorld(QPointF(10, 260)).y()), 1.0);
    QCOMPARE(trace.calibration()->points(), 2);
    QCOMPARE(trace.calibration()->imageDistance(), 250.0);
    // A decimal comma in Latvian.
    QVERIFY(trace.calibration()->calibrate(QStringLiteral("12,5"), QStringLiteral("cm"), CalibrationTool::NoAlign));
    QCOMPARE(editor.document()->units(), QStringLiteral("cm"));
    const Background &after = editor.document()->background();
    QVERIFY(std::abs(distance(after.toWorld(after.calibrationA), after.toWorld(after.calibrationB)) - 12.5) <= 1e-12);
    QCOMPARE(trace.calibration()->points(), 0);
    QLocale::setDefault(QLocale::c());
}

void TestTrace::calibrationRefusals()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    // No picture.
    QVERIFY(!trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(1, 0), 1.0, QStringLiteral("mm"),
                                                       CalibrationTool::NoAlign));
    QVERIFY(!trace.message().isEmpty());
    editor.background()->setBackground(picture());
    const int steps = editor.undoStack()->count();
    QVERIFY(!trace.calibration()->calibrateImagePoints(QPointF(5, 5), QPointF(5, 5), 1.0, QStringLiteral("mm"),
                                                       CalibrationTool::NoAlign));
    QVERIFY(!trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(1, 0), 1.0, QStringLiteral("furlong"),
                                                       CalibrationTool::NoAlign));
    trace.setTool(TraceController::Tool::Calibrate);
    QVERIFY(!trace.calibration()->calibrate(QStringLiteral("10"), QStringLiteral("mm"), 0)); // no points marked
    trace.tap(QPointF(0, 0), 1.0);
    trace.tap(QPointF(10, 0), 1.0);
    QVERIFY(!trace.calibration()->calibrate(QStringLiteral("ten"), QStringLiteral("mm"), 0));
    QVERIFY(!trace.calibration()->calibrate(QStringLiteral("-3"), QStringLiteral("mm"), 0));
    QCOMPARE(trace.calibration()->points(), 2); // nothing lost on bad input
    trace.setBackgroundLocked(true);
    QVERIFY(!trace.calibration()->calibrate(QStringLiteral("10"), QStringLiteral("mm"), 0));
    QCOMPARE(editor.undoStack()->count(), steps + 1); // only the lock
    QCOMPARE(editor.document()->units(), QStringLiteral("px"));
}

void TestTrace::svgOfCalibrated100mmLineIs100mm()
{
    QTemporaryDir dir;
    EditController editor;
    TraceController trace;
    kontur::DocumentFiles files;
    files.setEditor(&editor);
    kontur::Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    // 378 picture pixels are 100 mm (a scan at 96 dpi, roughly).
    QVERIFY(trace.calibration()->calibrateImagePoints(QPointF(20, 30), QPointF(398, 30), 100.0, QStringLiteral("mm"),
                                                      CalibrationTool::NoAlign));
    const Background &bg = editor.document()->background();
    const Point a = bg.toWorld(bg.calibrationA);
    const Point b = bg.toWorld(bg.calibrationB);
    // The line traced between the two marks, with a second curve so the box has height.
    editor.commands()->addCurves({kontur::Curve::make(CurveKind::Bezier, {a, b})}, QStringLiteral("line"));
    editor.commands()->addCurves({kontur::Curve::make(CurveKind::Bezier, {a, Point(a + Point(0, 30))})},
                                 QStringLiteral("line"));
    const QString path = dir.filePath(QStringLiteral("line.svg"));
    QVERIFY(exporter.exportSvg(QUrl::fromLocalFile(path)));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString svg = QString::fromUtf8(file.readAll());
    const auto width = QRegularExpression(QStringLiteral("width=\"([-0-9.e+]+)mm\"")).match(svg);
    const auto viewBox =
        QRegularExpression(QStringLiteral("viewBox=\"([-0-9.e+]+) ([-0-9.e+]+) ([-0-9.e+]+) ([-0-9.e+]+)\""))
            .match(svg);
    QVERIFY2(width.hasMatch() && viewBox.hasMatch(), qPrintable(svg));
    const double mmPerUnit = width.captured(1).toDouble() / viewBox.captured(3).toDouble();
    const auto line =
        QRegularExpression(QStringLiteral("d=\"M ?([-0-9.e+]+)[ ,]([-0-9.e+]+) ?L ?([-0-9.e+]+)[ ,]([-0-9.e+]+)\""))
            .match(svg);
    QVERIFY2(line.hasMatch(), qPrintable(svg));
    const double dx = line.captured(3).toDouble() - line.captured(1).toDouble();
    const double dy = line.captured(4).toDouble() - line.captured(2).toDouble();
    QVERIFY2(std::abs(std::hypot(dx, dy) * mmPerUnit - 100.0) <= 1e-9, qPrintable(svg));
}

void TestTrace::freehandStrokeIsOneCompositeCurve()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Freehand);
    QCOMPARE(trace.freehand()->tolerance(), 1.0); // px
    // An L: 200 px right, then 150 px up, sampled every 2 px.
    trace.freehand()->beginStroke(QPointF(0, 0), 0.0);
    for (int i = 1; i <= 100; ++i)
        trace.freehand()->extendStroke(QPointF(2.0 * i, 0.3 * std::sin(i)));
    for (int i = 1; i <= 75; ++i)
        trace.freehand()->extendStroke(QPointF(200 + 0.3 * std::sin(i), 2.0 * i));
    QVERIFY(trace.freehand()->isDrawing());
    QCOMPARE(trace.freehand()->stroke().size(), std::size_t(176));
    const int steps = editor.undoStack()->count();
    QVERIFY(trace.freehand()->endStroke(0.0));
    QVERIFY(!trace.freehand()->isDrawing());
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.kind(), CurveKind::Composite);
    QCOMPARE(curve.segmentCount(), 2);
    QCOMPARE(trace.freehand()->lastSegmentCount(), 2);
    QCOMPARE(curve.composite().nodeType(1), kontur::geo::NodeType::Corner);
    // The corner knot is where the two (jittery) sides meet: within the jitter of (200, 0).
    QVERIFY(distance(curve.composite().knot(1), Point(200, 0)) <= 0.5);
    editor.undo();
    QCOMPARE(editor.document()->curveCount(), 0);
}

void TestTrace::shortStrokeIsNoCurve()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.freehand()->beginStroke(QPointF(0, 0), 0.0);
    trace.freehand()->extendStroke(QPointF(0.5, 0));
    QVERIFY(!trace.freehand()->endStroke(0.0));
    QCOMPARE(editor.document()->curveCount(), 0);
    QVERIFY(!trace.message().isEmpty());
    // Cancel drops the stroke.
    trace.freehand()->beginStroke(QPointF(0, 0), 0.0);
    trace.freehand()->extendStroke(QPointF(50, 0));
    trace.freehand()->cancelStroke();
    QVERIFY(!trace.freehand()->endStroke(0.0));
    QCOMPARE(editor.document()->curveCount(), 0);
}

// The freehand fit never follows a pointer's own pixel steps: at 256 % with 0.5 mm typed, a smooth
// stroke along three cubics, as a pointer reports it (whole screen pixels), is fitted within
// 1.5 px = 0.586 mm as the three cubics drawn; the typed tolerance stays 0.5 mm.
void TestTrace::toleranceNeverBelowThePointersPixelSteps()
{
    const double zoom = 2.56; // screen pixels per mm
    const std::vector<kontur::geo::Bezier> cubics{
        kontur::geo::Bezier({Point(0, 0), Point(20, 40), Point(40, 40), Point(60, 30)}),
        kontur::geo::Bezier({Point(60, 30), Point(80, 20), Point(100, -10), Point(120, 0)}),
        kontur::geo::Bezier({Point(120, 0), Point(140, 10), Point(160, 50), Point(180, 40)})};
    std::vector<QPointF> pointer; // what the pointer reports, in world units
    for (const auto &cubic : cubics)
        for (int i = 0; i <= 400; ++i) {
            const Point p = cubic.eval(i / 400.0);
            pointer.emplace_back(std::round(p.x() * zoom) / zoom, std::round(p.y() * zoom) / zoom);
        }
    const auto strokeSegments = [&](double pixelSize, double pixelSizeAtEnd) {
        EditController editor;
        TraceController trace;
        trace.setEditor(&editor);
        trace.setTool(TraceController::Tool::Freehand);
        trace.freehand()->setTolerance(0.5);
        trace.freehand()->setPixelSize(pixelSize);
        trace.freehand()->beginStroke(pointer.front(), 0.0);
        trace.freehand()->setPixelSize(pixelSizeAtEnd); // a zoom during the stroke does not change its fit
        for (const QPointF &p : pointer)
            trace.freehand()->extendStroke(p);
        if (!trace.freehand()->endStroke(0.0))
            return -1;
        return editor.document()->curve(0).segmentCount();
    };
    const int withoutFloor = strokeSegments(0.0, 0.0);
    const int atThisZoom = strokeSegments(1.0 / zoom, 0.0);
    qInfo("pixel-quantized three-cubic stroke: %d segments without the floor, %d with it", withoutFloor, atThisZoom);
    // The three drawn with the floor, and no more without it (6 and 5 before three neighbouring
    // pieces were refitted as two with their join moved; 15 and 10 before pairs were merged).
    QVERIFY2(atThisZoom == 3 && withoutFloor >= atThisZoom && withoutFloor <= 8,
             qPrintable(QStringLiteral("%1 → %2").arg(withoutFloor).arg(atThisZoom)));
    QCOMPARE(strokeSegments(1.0 / zoom, 1.0), atThisZoom);

    TraceController trace;
    QSignalSpy spy(trace.freehand(), &FreehandTool::effectiveToleranceChanged);
    trace.freehand()->setTolerance(0.5);
    trace.freehand()->setPixelSize(1.0 / zoom);
    QCOMPARE(trace.freehand()->tolerance(), 0.5);
    QCOMPARE(trace.freehand()->effectiveTolerance(), 1.5 / zoom);
    trace.freehand()->setPixelSize(0.1); // zoomed in: the typed tolerance is in effect again
    QCOMPARE(trace.freehand()->effectiveTolerance(), 0.5);
    QCOMPARE(spy.count(), 3);
}

void TestTrace::seamMeasureAndDeviation()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    // A composite through collinear knots is straight: the seam from knot 1 to knot 3 is 20 + 30.
    editor.commands()->addCurves(
        {kontur::Curve::make(CurveKind::Composite, {Point(0, 0), Point(10, 0), Point(30, 0), Point(60, 0)})},
        QStringLiteral("add"));
    trace.setTool(TraceController::Tool::Seam);
    trace.tap(QPointF(10, 0), 2.0);
    QCOMPARE(trace.seam()->knots(), 1);
    trace.tap(QPointF(60, 0), 2.0);
    QCOMPARE(trace.seam()->knots(), 2);
    QVERIFY(std::abs(trace.seam()->length() - 50.0) <= SeamTool::kLengthAccuracy);
    QCOMPARE(trace.seam()->segments().size(), std::size_t(2));
    // A tap beside every knot: a message, nothing measured.
    trace.tap(QPointF(20, 30), 2.0);
    QVERIFY(!trace.message().isEmpty());

    trace.setTool(TraceController::Tool::Measure);
    trace.tap(QPointF(0, 0), 0.0);
    trace.tap(QPointF(30, 40), 0.0);
    QCOMPARE(trace.measure()->distance(), 50.0);

    // Deviation: the same straight seam moved 2.5 up.
    editor.commands()->addCurves(
        {kontur::Curve::make(CurveKind::Composite, {Point(0, 2.5), Point(10, 2.5), Point(30, 2.5), Point(60, 2.5)})},
        QStringLiteral("add"));
    trace.setTool(TraceController::Tool::Deviation);
    trace.tap(QPointF(45, 0.2), 1.0);
    QCOMPARE(trace.deviation()->curves(), 1);
    trace.tap(QPointF(45, 2.6), 1.0);
    QVERIFY(trace.deviation()->hasResult());
    QVERIFY(std::abs(trace.deviation()->maximum() - 2.5) <= 1e-9);
    QVERIFY(std::abs(trace.deviation()->mean() - 2.5) <= 1e-9);
    QVERIFY(trace.deviation()->compare(kontur::test::idAt(editor, 0), kontur::test::idAt(editor, 0)) == false);
    QVERIFY(trace.deviation()->compare(kontur::test::idAt(editor, 1), kontur::test::idAt(editor, 1)) == false);
    QVERIFY(trace.deviation()->compare(0, kontur::test::idAt(editor, 1)) == false); // 0: no curve
    // Self-comparison through the API of two equal curves: 0.
    editor.commands()->addCurves({editor.document()->curve(0)}, QStringLiteral("copy"));
    QVERIFY(trace.deviation()->compare(kontur::test::idAt(editor, 0), kontur::test::idAt(editor, 2)));
    QVERIFY(trace.deviation()->maximum() <= 1e-12);
}

void TestTrace::snapping()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.commands()->addCurves({kontur::Curve::make(CurveKind::Composite, {Point(0, 0), Point(10, 0), Point(30, 5)})},
                                 QStringLiteral("add"));
    trace.setProperty("gridStep", 25.0);
    QCOMPARE(trace.snap(QPointF(10.5, 0.5), 2.0), QPointF(10.5, 0.5)); // off
    trace.setSnapping(true);
    QCOMPARE(trace.snap(QPointF(10.5, 0.5), 2.0), QPointF(10, 0));   // a knot
    QCOMPARE(trace.snap(QPointF(49.5, 24.2), 2.0), QPointF(50, 25)); // a grid crossing
    QCOMPARE(trace.snap(QPointF(40, 12), 2.0), QPointF(40, 12));     // nothing near
}

void TestTrace::lockIsSavedAndUndoable()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    QVERIFY(trace.calibration()->calibrateImagePoints(QPointF(0, 0), QPointF(100, 0), 10.0, QStringLiteral("cm"),
                                                      CalibrationTool::NoAlign));
    trace.setBackgroundLocked(true);
    QVERIFY(trace.backgroundLocked());
    const kontur::io::DocumentData data = kontur::toDocumentData(*editor.document());
    const QByteArray json = kontur::io::documentToJson(data);
    QVERIFY(json.contains("\"locked\":true") || json.contains("\"locked\": true"));
    const auto read = kontur::io::documentFromJson(json);
    QVERIFY(read.ok());
    QCOMPARE(read->units, QStringLiteral("cm"));
    const Background restored = kontur::fromRecord(*read->background);
    QVERIFY(restored == editor.document()->background());
    editor.undo();
    QVERIFY(!trace.backgroundLocked());
    // Documents without the member read as unlocked.
    QVERIFY(!kontur::fromRecord(kontur::io::BackgroundRecord{}).locked);
}

void TestTrace::placingAndTracingEndEachOther()
{
    // One tool at a time: a new curve's taps are its points, a tracing tool's are the tool's.
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Freehand);
    editor.startPlacing(static_cast<int>(kontur::CurveKind::Bezier));
    QCOMPARE(editor.mode(), EditController::Mode::Place);
    QCOMPARE(trace.tool(), TraceController::Tool::None);
    trace.setTool(TraceController::Tool::Measure);
    QCOMPARE(editor.mode(), EditController::Mode::Select);
    QCOMPARE(trace.tool(), TraceController::Tool::Measure);
}

QTEST_MAIN(TestTrace)
void TestTrace::backgroundMoveIsOneUndoStep()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    QVERIFY(!trace.backgroundMove()->begin()); // no picture
    QVERIFY(!trace.message().isEmpty());
    editor.background()->setBackground(picture());
    const Background start = editor.document()->background();
    const int steps = editor.undoStack()->count();
    // A drag in three moves: the picture follows live, and the whole drag is one undo step.
    QVERIFY(trace.backgroundMove()->begin());
    trace.backgroundMove()->moveBy(QPointF(1.5, -2.0));
    QCOMPARE(editor.document()->background().origin, start.origin + QPointF(1.5, -2.0));
    trace.backgroundMove()->moveBy(QPointF(0.25, 0.5));
    trace.backgroundMove()->moveBy(QPointF(3.0, 0.0));
    trace.backgroundMove()->end();
    const QPointF moved = start.origin + QPointF(4.75, -1.5);
    QCOMPARE(editor.document()->background().origin, moved);
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    // Only the position changed: scale, rotation and calibration stay.
    Background expected = start;
    expected.origin = moved;
    QVERIFY(editor.document()->background() == expected);
    editor.undo();
    QVERIFY(editor.document()->background() == start);
    editor.redo();
    QCOMPARE(editor.document()->background().origin, moved);
    // A drag that ends where it began adds no step; a locked picture does not move.
    QVERIFY(trace.backgroundMove()->begin());
    trace.backgroundMove()->moveBy(QPointF(2.0, 2.0));
    trace.backgroundMove()->moveBy(QPointF(-2.0, -2.0));
    trace.backgroundMove()->end();
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    trace.setBackgroundLocked(true);
    QVERIFY(!trace.backgroundMove()->begin());
    trace.backgroundMove()->moveBy(QPointF(9.0, 9.0));
    trace.backgroundMove()->end();
    QCOMPARE(editor.document()->background().origin, moved);
}

void TestTrace::backgroundDragIsOneCommandFromItsFirstStep()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    editor.background()->setBackground(picture());
    const Background start = editor.document()->background();
    const int steps = editor.undoStack()->count();
    QSignalSpy changed(editor.document(), &kontur::Document::backgroundChanged);
    // Beginning a drag changes nothing: the document changes only by the first step's command.
    QVERIFY(trace.backgroundMove()->begin());
    QCOMPARE(changed.count(), 0);
    QVERIFY(editor.document()->background() == start);
    QCOMPARE(editor.undoStack()->count(), steps);
    for (int i = 0; i < 100; ++i) {
        trace.backgroundMove()->moveBy(QPointF(0.5, -0.25));
        QCOMPARE(editor.undoStack()->count(), steps + 1); // one command from the first step on
    }
    trace.backgroundMove()->end();
    QCOMPARE(changed.count(), 100); // the picture followed every step
    QCOMPARE(editor.undoStack()->count(), steps + 1);
    // 100 × (0.5, −0.25) from (−200, 150): exact in binary.
    QCOMPARE(editor.document()->background().origin, QPointF(-150.0, 125.0));
    editor.undo();
    QVERIFY(editor.document()->background() == start);
    QCOMPARE(editor.document()->background().origin, QPointF(-200.0, 150.0));
    editor.redo();
    QCOMPARE(editor.document()->background().origin, QPointF(-150.0, 125.0));
    // The next drag is an undo step of its own: it does not merge into the last one.
    QVERIFY(trace.backgroundMove()->begin());
    trace.backgroundMove()->moveBy(QPointF(1.0, 0.0));
    trace.backgroundMove()->end();
    QCOMPARE(editor.undoStack()->count(), steps + 2);
    editor.undo();
    QCOMPARE(editor.document()->background().origin, QPointF(-150.0, 125.0));
}

void TestTrace::lengthsWithTheirUnitsDecimals_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    // 0.01 mm, 0.001 cm and in, 0.1 of pixels and points; the decimal separator of the language.
    QTest::addRow("mm") << QStringLiteral("C") << QStringLiteral("mm") << 12.345678 << QStringLiteral("12.35 mm");
    QTest::addRow("cm") << QStringLiteral("C") << QStringLiteral("cm") << 1.2345678 << QStringLiteral("1.235 cm");
    QTest::addRow("in") << QStringLiteral("C") << QStringLiteral("in") << 0.5 << QStringLiteral("0.500 in");
    QTest::addRow("px") << QStringLiteral("C") << QStringLiteral("px") << 30.0 << QStringLiteral("30.0 px");
    QTest::addRow("pt") << QStringLiteral("C") << QStringLiteral("pt") << 2.26 << QStringLiteral("2.3 pt");
    QTest::addRow("lv mm") << QStringLiteral("lv") << QStringLiteral("mm") << 12.345678 << QStringLiteral("12,35 mm");
    QTest::addRow("sk cm") << QStringLiteral("sk") << QStringLiteral("cm") << 1.2345678 << QStringLiteral("1,235 cm");
}

void TestTrace::lengthsWithTheirUnitsDecimals()
{
    QFETCH(QString, language);
    QFETCH(QString, unit);
    QFETCH(double, value);
    QFETCH(QString, text);
    QLocale::setDefault(QLocale(language));
    QCOMPARE(kontur::formatLength(value, unit), text);
    QLocale::setDefault(QLocale::c());
}

// The curve list's lengths: as the list shows numbers (at most one decimal, no grouping, an exponent
// beyond 1e9), with the unit's pattern.
void TestTrace::listLengthsCarryTheirUnit()
{
    QLocale::setDefault(QLocale(QStringLiteral("lv")));
    const QString lv = kontur::Numbers::shownLength(1036.94, 1, QStringLiteral("mm"), QStringLiteral("lv"));
    QLocale::setDefault(QLocale::c());
    QCOMPARE(lv, QStringLiteral("1036,9 mm"));
    QCOMPARE(kontur::Numbers::shownLength(8.888888888888889e299, 1, QStringLiteral("px"), QStringLiteral("C")),
             QStringLiteral("8.89e+299 px"));
    QCOMPARE(kontur::Numbers::shownLength(3.26, 1, QStringLiteral("cm"), QStringLiteral("C")),
             QStringLiteral("3.3 cm"));
}

void TestTrace::textsFollowALanguageSwitch()
{
    EditController editor;
    TraceController trace;
    trace.setEditor(&editor);
    trace.setTool(TraceController::Tool::Measure);
    trace.tap(QPointF(0, 0), 1.0);
    trace.tap(QPointF(3, 4), 1.0);
    QCOMPARE(trace.measure()->distanceText(), QStringLiteral("5.0 px"));
    QVERIFY(!trace.freehand()->setToleranceText(QStringLiteral("x")));
    const QString message = trace.message().text();
    QCOMPARE(message, QStringLiteral("The tolerance must be a positive number."));
    QSignalSpy texts(trace.measure(), &MeasureTool::textsChanged);
    QSignalSpy messages(&trace, &TraceController::messageChanged);
    QSignalSpy hints(&trace, &TraceController::hintChanged);
    // A switch sends LanguageChange several times (installTranslator, removeTranslator): the tools'
    // texts with numbers are announced once, after the last; the message (a ShownMessage) on each.
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    QLocale::setDefault(QLocale(QStringLiteral("lv")));
    QVERIFY(texts.wait());
    QCOMPARE(texts.count(), 1);
    QCOMPARE(messages.count(), 2);
    QCOMPARE(hints.count(), 1);
    QCOMPARE(trace.message().text(), message); // no translator here: the English text, asked for again
    QCOMPARE(trace.measure()->distanceText(), QStringLiteral("5,0 px"));
    QLocale::setDefault(QLocale::c());
}

void TestTrace::pictureIsPlacedAsShown()
{
    QTemporaryDir dir;
    // 200 × 100 pixels stored, to be shown turned a quarter (EXIF orientation 6): 100 × 200 as shown,
    // which is how the canvas draws it, so it is centred on the world origin with that size.
    QImage image(200, 100, QImage::Format_RGB32);
    image.fill(QColor(40, 160, 90));
    const QString turned = dir.filePath(QStringLiteral("turned.jpg"));
    QImageWriter writer(turned);
    writer.setTransformation(QImageIOHandler::TransformationRotate90);
    QVERIFY2(writer.write(image), qPrintable(writer.errorString()));
    QCOMPARE(kontur::readImage(turned).image.size(), QSize(100, 200));
    QCOMPARE(kontur::readImageSize(turned).size, QSize(100, 200));
    EditController editor;
    QVERIFY(editor.background()->load(QUrl::fromLocalFile(turned)));
    QCOMPARE(editor.document()->background().origin, QPointF(-50.0, 100.0));
    QCOMPARE(editor.background()->file(), QFileInfo(turned).absoluteFilePath());
    // Refused with a typed reason, and with the seed's message 1 in the editor; nothing changes.
    QCOMPARE(kontur::readImage(dir.filePath(QStringLiteral("none.png"))).error, kontur::ImageError::NotAFile);
    QCOMPARE(kontur::readImageSize(dir.path()).error, kontur::ImageError::NotAFile);
    const QString text = dir.filePath(QStringLiteral("notes.png"));
    QFile notes(text);
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.write("not a picture");
    notes.close();
    QCOMPARE(kontur::readImage(text).error, kontur::ImageError::NotAnImage);
    QVERIFY(!editor.background()->load(QUrl::fromLocalFile(text)));
    QCOMPARE(editor.message().id, kontur::Message::FileUploadError);
    QCOMPARE(editor.background()->file(), QFileInfo(turned).absoluteFilePath());
    QCOMPARE(editor.undoStack()->count(), 1);
}

#include "tst_trace.moc"
