// From a phone photo to a pattern piece in the real window, by touch and by mouse: a synthetic photo
// with ground truth (tests/vision/synthphoto.h: an A4 sheet and a bodice piece on a wooden table, seen
// at an angle) is loaded by the first start's Trace a picture, which finds the sheet at once; Apply
// (A4), Trace outline, a tap inside the piece, Seam allowance → Add, File → Export DXF for pattern
// software, File → Print pattern → Print to PDF, each saved under the name and in the folder offered
// (the photo's). The grainline drawn on the piece is found with it and exported. The taps are counted
// (at most 20; a file dialog takes one, the picture's two), the sheet's corners must be found within
// 0.3 photo px, the traced outline is compared with the truth in mm (Hausdorff within 0.5 mm), and the
// DXF and PDF must be written with the piece and its allowance. A piece with notches, a drill hole and a
// "place on fold" bracket as well comes out with all its marks and its fold (markedPieceByTouch). Over
// 600 lines because each case is a whole user story from the photo to the printed page, sharing the
// photo's setup and mapping.
#include "windowtest.h"

#include "../segmentends.h"

#include "matimage.h"
#include "synthflat.h"
#include "synthphoto.h"

#include "app/curvecanvas.h"
#include "io/aama.h"
#include "io/dxf.h"
#include "io/piece.h"
#include "io/seam.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/printcontroller.h"
#include "models/controllers/seamwidths.h"
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/trace/tracecontroller.h"
#include "print/patternpdf.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QQuickItem>
#include <QQuickWindow>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <utility>

using kontur::TraceController;
using kontur::geo::Point;

class TestOutlineWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QObject *fileDialog(const QString &title) const { return kontur::test::fileDialogTitled(m_window, title); }
    // A tap on a control (brought into view first, standing still) by a finger or the mouse; counted.
    void tapItem(QQuickItem *it, bool touch)
    {
        QVERIFY(kontur::test::standsStill(m_window, it));
        tapAt(kontur::test::centerOf(it), touch);
    }
    void tapAt(QPoint at, bool touch)
    {
        ++m_taps;
        if (touch)
            tap(at);
        else
            QTest::mouseClick(m_window, Qt::LeftButton, {}, at);
    }
    // A menu entry: the menu's button, then the entry once the menu is open.
    void menuEntry(const QString &button, const QString &entry, bool touch)
    {
        tapItem(item(button), touch);
        QQuickItem *it = nullptr;
        QTRY_VERIFY((it = item(entry)) && it->isVisible() && it->width() > 0);
        QObject *menu = it->property("menu").value<QObject *>();
        QVERIFY(menu);
        QTRY_VERIFY(menu->property("opened").toBool());
        tapItem(it, touch);
        QTRY_VERIFY(!menu->property("visible").toBool());
    }
    // The file dialog `title`, once open with its list read.
    QObject *shownDialog(const QString &title)
    {
        QObject *dialog = fileDialog(title);
        if (!dialog || !QTest::qWaitFor([&] {
                return dialog->property("opened").toBool() &&
                       kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogList"));
            }))
            return nullptr;
        return dialog;
    }
    // The file dialog `title` accepted as offered: one tap on its Save or Export button.
    void acceptAsOffered(QObject *dialog, bool touch)
    {
        QVERIFY(dialog);
        tapItem(kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogAccept")), touch);
        QTRY_VERIFY(!dialog->property("visible").toBool());
        overlayClear();
    }
    // The file dialog `title` cancelled (a tap on Cancel, not counted: the walk does not need it) and
    // answered by `answer`, the call its onAccepted would make.
    void answerDialog(const QString &title, const std::function<bool()> &answer)
    {
        QObject *dialog = shownDialog(title);
        QVERIFY(dialog);
        QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
        QTRY_VERIFY(!dialog->property("visible").toBool());
        overlayClear();
        QVERIFY(answer());
    }
    // Until no modal popup shows: a closing dialog's fading dim still takes the taps (a popup stays
    // visible until its exit transition ends).
    void overlayClear()
    {
        const auto modalShown = [this] {
            const QList<QObject *> all = m_window->findChildren<QObject *>();
            return std::any_of(all.cbegin(), all.cend(), [](const QObject *o) {
                return o->inherits("QQuickPopup") && o->property("modal").toBool() && o->property("visible").toBool();
            });
        };
        QTRY_VERIFY(!modalShown());
    }
    void photoToPiece(bool touch);
    // A point of the synthetic photo's sheet (mm) in the document's world, through the photo and the
    // calibration applied.
    Point worldOf(const kontur::vision::test::SynthPhoto &synth, const Point &sheetMm) const
    {
        const Point px = kontur::vision::apply(synth.worldToPhoto, sheetMm);
        return m_editor->document()->background().toWorld(QPointF(px.x(), px.y()));
    }
    QPoint sceneOf(const Point &world) const
    {
        return m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y()))).toPoint();
    }

    TraceController *m_trace = nullptr;
    int m_taps = 0;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(start(QSize(1280, 800)));
        m_trace = m_window->findChild<TraceController *>(QStringLiteral("trace"));
        QVERIFY(m_trace);
    }
    void byTouch() { photoToPiece(true); }
    void byMouse() { photoToPiece(false); }
    void freehandSnapsToTheSheetsEdge();
    void markedPieceByTouch();
    void aBanknoteIsNotTheSheet();
    void cleanupTestCase() { m_engine.reset(); }
};

// A banknote alone on the table (156 × 66 mm): Find the sheet does not take it for A4, and says what
// it saw and how to go on.
void TestOutlineWindow::aBanknoteIsNotTheSheet()
{
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    auto options = kontur::vision::test::randomSynthOptions(12, {1600, 1200});
    options.sheetMm = Point(156.1, 66.3);
    options.withPiece = false;
    const auto synth = kontur::vision::test::makeSynthPhoto(options);
    const QString photo = m_dir.filePath(QStringLiteral("banknote.png"));
    QVERIFY(kontur::vision::test::qImageOf(synth.image).save(photo));
    QVERIFY(m_editor->background()->load(QUrl::fromLocalFile(photo)));
    m_canvas->fitToView();
    menuEntry(QStringLiteral("traceMenuButton"), QStringLiteral("tracePerspective"), true);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Perspective);
    tapItem(item(QStringLiteral("traceFindSheet")), true);
    QTRY_VERIFY2(m_trace->message().text().contains(QStringLiteral("about 2.3")),
                 qPrintable(m_trace->message().text()));
    QVERIFY(m_trace->message().text().contains(QStringLiteral("1.41 : 1")));
    QCOMPARE(m_trace->perspective()->marks(), 0);
    QVERIFY(!m_editor->document()->background().perspective);
    m_trace->setTool(TraceController::Tool::None);
}

void TestOutlineWindow::photoToPiece(bool touch)
{
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_trace->setTool(TraceController::Tool::None);
    m_taps = 0;
    // The photo: 3264 × 2448 px (8 megapixels, a phone's photo), the piece at about 6–9 px/mm, in a
    // folder of its own (the dialogs after it start there, named after it).
    const auto synth =
        kontur::vision::test::makeSynthPhoto(kontur::vision::test::randomSynthOptions(touch ? 5 : 8, {3264, 2448}));
    const QString base = touch ? QStringLiteral("bodice-touch") : QStringLiteral("bodice-mouse");
    QVERIFY(QDir(m_dir.path()).mkpath(base));
    const QDir folder(m_dir.filePath(base));
    const QString photo = folder.filePath(base + QStringLiteral(".png"));
    QVERIFY(kontur::vision::test::qImageOf(synth.image).save(photo));

    // The first start's Trace a picture: the picture dialog starts in the folder last used (where the
    // phone's photos are copied); the photo picked by one tap and opened by a second. It is fitted
    // and its sheet looked for at once.
    m_files->rememberFolder(QUrl::fromLocalFile(folder.filePath(QStringLiteral("earlier.png"))));
    QQuickItem *hint = item(QStringLiteral("hintTrace"));
    QTRY_VERIFY(hint && hint->isVisible());
    tapItem(hint, touch);
    QObject *pictureDialog = shownDialog(QStringLiteral("Load background image"));
    QVERIFY(pictureDialog);
    QCOMPARE(pictureDialog->property("currentFolder").toUrl(), QUrl::fromLocalFile(folder.path()));
    QQuickItem *photoRow = kontur::test::fileDialogRow(m_window, base + QStringLiteral(".png"));
    tapItem(photoRow, touch);
    tapItem(photoRow, touch);
    QTRY_VERIFY(!pictureDialog->property("visible").toBool());
    overlayClear();
    QTRY_COMPARE(m_editor->document()->background().file, photo);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Perspective);
    QTRY_COMPARE(m_trace->perspective()->marks(), 4);

    // Apply (A4, the default).
    tapItem(item(QStringLiteral("traceApplyPerspective")), touch);
    QTRY_VERIFY(m_editor->document()->background().perspective);
    QCOMPARE(m_editor->document()->units(), QStringLiteral("mm"));
    const kontur::Background bg = m_editor->document()->background();
    for (std::size_t i = 0; i < 4; ++i) // found, not tapped: sub-pixel
        QVERIFY2((Point(bg.corners[i].x(), bg.corners[i].y()) - synth.sheetCorners[i]).norm() < 0.3,
                 qPrintable(QString::number(i)));
    QVERIFY(m_trace->perspective()->calibrationError() > 0.0);
    QQuickItem *errorLabel = item(QStringLiteral("perspectiveError"));
    QVERIFY(errorLabel);
    QTRY_VERIFY(errorLabel->isVisible());

    // Trace outline: a tap inside the piece (the truth's centroid, as the picture shows it). A traced
    // piece is a finished step: the tool leaves and the message line says so.
    tapItem(item(QStringLiteral("traceOutlineButton")), touch);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Outline);
    Point inside = Point::Zero();
    for (const Point &p : synth.pieceOutline)
        inside += p / double(synth.pieceOutline.size());
    const Point world = bg.toWorld(QPointF(kontur::vision::apply(synth.worldToPhoto, inside).x(),
                                           kontur::vision::apply(synth.worldToPhoto, inside).y()));
    m_canvas->fitToView();
    QTRY_VERIFY(m_canvas->isVisible() && m_canvas->width() > 0);
    tapAt(m_canvas->mapToScene(m_canvas->toScreen(QPointF(world.x(), world.y()))).toPoint(), touch);
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::None);
    // The grainline drawn on the piece is found with it: a pattern piece.
    QCOMPARE(m_editor->message().id, kontur::Message::OutlineTracedWithMarks);
    const kontur::Curve &traced = m_editor->document()->curve(0);
    QVERIFY(traced.isClosed());
    QVERIFY(traced.piece && traced.piece->grainline);
    // In the sheet's mm: the curve's points mapped back through the calibration and the truth's
    // homography.
    const auto toPhoto = bg.worldToImage();
    const kontur::vision::Homography photoToSheet = synth.worldToPhoto.inverse();
    std::vector<Point> sheetMm;
    for (const Point &p : kontur::test::sampleComposite(traced.composite().controlPoints(), 100))
        sheetMm.push_back(kontur::vision::apply(photoToSheet, toPhoto.map(p)));
    const double h = kontur::test::hausdorff(sheetMm, synth.pieceOutline);
    const int knots = traced.composite().knotCount();
    qInfo("%s: Hausdorff %.3f mm, %d knots (truth %d), calibration error %.2f mm", touch ? "touch" : "mouse", h, knots,
          synth.pieceKnots, m_trace->perspective()->calibrationError());
    QVERIFY2(h <= 0.5, qPrintable(QString::number(h)));
    QVERIFY2(knots <= synth.pieceKnots * 13 / 10, qPrintable(QString::number(knots)));
    screenshot(touch ? QStringLiteral("outline-touch.png") : QStringLiteral("outline-mouse.png"));

    // Seam allowance: the traced piece is selected; Add keeps 1 cm and closes the dialog.
    menuEntry(QStringLiteral("traceMenuButton"), QStringLiteral("traceSeamAllowance"), touch);
    tapItem(item(QStringLiteral("seamAdd")), touch);
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QVERIFY(m_editor->document()->curve(1).seam);
    QObject *seamDialog = m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"));
    QVERIFY(seamDialog);
    QTRY_VERIFY(!seamDialog->property("visible").toBool());
    QCOMPARE(m_editor->message().id, kontur::Message::SeamAllowanceAdded);

    // File → Export DXF for pattern software: the dialog offers the photo's folder and name; saved as
    // offered. The traced piece as an ASTM D6673 piece, its allowance the cut line (layer 1), the
    // traced curve the sew line (14), read back as one piece.
    const QString aama = folder.filePath(base + QStringLiteral(".dxf"));
    menuEntry(QStringLiteral("fileMenuButton"), QStringLiteral("exportAamaAction"), touch);
    QObject *aamaDialog = shownDialog(QStringLiteral("Export DXF for pattern software"));
    QVERIFY(aamaDialog);
    QCOMPARE(aamaDialog->property("selectedFile").toUrl(), QUrl::fromLocalFile(aama));
    QCOMPARE(aamaDialog->property("currentFolder").toUrl(), QUrl::fromLocalFile(folder.path()));
    QCOMPARE(kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogName"))->property("text").toString(),
             base + QStringLiteral(".dxf"));
    acceptAsOffered(aamaDialog, touch);
    QTRY_VERIFY(QFile::exists(aama));
    // The grainline found on the photo is written (layer 7): no word of pieces without one.
    QVERIFY(m_editor->message().id != kontur::Message::PiecesWithoutGrainline);
    const auto pieces = kontur::io::readDxf(aama);
    QVERIFY(pieces.ok());
    std::map<int, kontur::geo::PiecewiseBezier> byLayer;
    for (const kontur::io::DxfImportedCurve &c : pieces->curves) {
        QVERIFY(!c.piece.isEmpty());
        QCOMPARE(c.piece, pieces->curves.front().piece);
        byLayer.emplace(c.aamaLayer, c.curve);
    }
    QVERIFY(byLayer.count(1) && byLayer.count(14) && byLayer.count(7));
    QVERIFY(byLayer.at(1).boundingBox().contains(byLayer.at(14).boundingBox()));
    const kontur::geo::PiecewiseBezier sewn = m_editor->document()->curve(0).toPiecewise();
    for (const kontur::geo::Bezier &b : byLayer.at(14).segments())
        QVERIFY(sewn.nearest(b.startPoint()).distance <= 1e-6);

    // File → Print pattern…: Print, and the PDF dialog answered as offered (the same folder and name).
    const QString pdf = folder.filePath(base + QStringLiteral(".pdf"));
    menuEntry(QStringLiteral("fileMenuButton"), QStringLiteral("printAction"), touch);
    tapItem(item(QStringLiteral("printDialogPrint")), touch);
    QObject *pdfDialog = shownDialog(QStringLiteral("Print pattern to PDF"));
    QVERIFY(pdfDialog);
    QCOMPARE(pdfDialog->property("selectedFile").toUrl(), QUrl::fromLocalFile(pdf));
    acceptAsOffered(pdfDialog, touch);
    QTRY_VERIFY(QFile::exists(pdf));
    QObject *printDialog = m_window->findChild<QObject *>(QStringLiteral("printDialog"));
    QVERIFY(printDialog);
    QTRY_VERIFY(!printDialog->property("visible").toBool());
    overlayClear();
    QFile printed(pdf);
    QVERIFY(printed.open(QIODevice::ReadOnly));
    QVERIFY(printed.read(5) == "%PDF-");
    qInfo("%s: %d taps from the photo to the AAMA DXF and the PDF", touch ? "touch" : "mouse", m_taps);
    QVERIFY(m_taps <= 20);

    // File → Export DXF with splines too: the piece and its allowance.
    const QString dxf = m_dir.filePath(touch ? QStringLiteral("touch.dxf") : QStringLiteral("mouse.dxf"));
    menuEntry(QStringLiteral("fileMenuButton"), QStringLiteral("exportDxfAction"), touch);
    answerDialog(QStringLiteral("Export DXF"), [&] { return m_exporter->exportDxf(QUrl::fromLocalFile(dxf), false); });
    QTRY_VERIFY(QFile::exists(dxf));
    QFile written(dxf);
    QVERIFY(written.open(QIODevice::ReadOnly));
    QCOMPARE(written.readAll().count("\nSPLINE\n"), 2);
}

// A bodice with a drawn grainline, two V notches cut into its edge, a slit and a drill hole
// (synthphoto's pieceMarks), by touch: found and applied, traced by one tap into one pattern piece with
// its five marks where the photo has them (notches within 1 mm along the edge and square to it, the
// grainline within 0.5°, the drill hole within 0.5 mm); Seam allowance → Add (1 cm), then in the piece
// bar the hem tapped, + four times (3 cm) and Hem; exported to AAMA and read back by ezdxf layer by
// layer and by Kontur into an equal piece (its grainline, notches, drill hole, hem and its 3 cm, and
// its cut line linked as the 1 cm allowance); printed to PDF with the piece's label and the hem's
// width, and on paper (rasterized) its grainline with arrowhead, drill hole and notch marks.
void TestOutlineWindow::markedPieceByTouch()
{
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_trace->setTool(TraceController::Tool::None);
    auto options = kontur::vision::test::randomSynthOptions(5, {3264, 2448});
    options.pieceMarks = true;
    options.foldBracket = true;
    const auto synth = kontur::vision::test::makeSynthPhoto(options);
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("marked")));
    const QDir folder(m_dir.filePath(QStringLiteral("marked")));
    const QString photo = folder.filePath(QStringLiteral("bodice.png"));
    QVERIFY(kontur::vision::test::qImageOf(synth.image).save(photo));
    QVERIFY(m_editor->background()->load(QUrl::fromLocalFile(photo)));
    m_canvas->fitToView();
    menuEntry(QStringLiteral("traceMenuButton"), QStringLiteral("tracePerspective"), true);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Perspective);
    if (m_trace->perspective()->marks() != 4)
        tapItem(item(QStringLiteral("traceFindSheet")), true);
    QTRY_COMPARE(m_trace->perspective()->marks(), 4);
    tapItem(item(QStringLiteral("traceApplyPerspective")), true);
    QTRY_VERIFY(m_editor->document()->background().perspective);

    // Trace outline, a tap inside the piece.
    tapItem(item(QStringLiteral("traceOutlineButton")), true);
    QTRY_COMPARE(m_trace->tool(), TraceController::Tool::Outline);
    Point inside = Point::Zero();
    for (const Point &p : synth.pieceOutline)
        inside += p / double(synth.pieceOutline.size());
    m_canvas->fitToView();
    QTRY_VERIFY(m_canvas->isVisible() && m_canvas->width() > 0);
    tapAt(sceneOf(worldOf(synth, inside)), true);
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(m_editor->message().id, kontur::Message::OutlineTracedWithMarks);
    QVERIFY(m_editor->message().text().contains(QStringLiteral("3 notches")));
    QVERIFY(m_editor->message().text().contains(QStringLiteral("the fold line")));
    const kontur::Curve traced = m_editor->document()->curve(0);
    const QString pieceName = traced.name;
    QVERIFY(traced.piece.has_value());
    const kontur::io::PieceMarks found = *traced.piece;
    const kontur::geo::PiecewiseBezier outline = traced.toPiecewise();
    QCOMPARE(found.notches.size(), synth.notches.size());
    for (const auto &truth : synth.notches) {
        const Point at = worldOf(synth, truth.at);
        const auto nearest =
            std::min_element(found.notches.begin(), found.notches.end(), [&](const auto &a, const auto &b) {
                return (kontur::io::placeAtLength(outline, a.position).point - at).norm() <
                       (kontur::io::placeAtLength(outline, b.position).point - at).norm();
            });
        const double off = (kontur::io::placeAtLength(outline, nearest->position).point - at).norm();
        qInfo("notch %s %.2f mm from its place, at %.1f°", truth.v ? "V" : "slit", off, nearest->angle);
        QVERIFY2(off <= 1.0, qPrintable(QString::number(off)));
        QCOMPARE(nearest->kind, truth.v ? kontur::io::NotchKind::V : kontur::io::NotchKind::Slit);
        QCOMPARE(nearest->angle, 0.0);
    }
    QVERIFY(found.grainline.has_value());
    const Point grainTruth = worldOf(synth, synth.grainline[1]) - worldOf(synth, synth.grainline[0]);
    const Point grain = found.grainline->b - found.grainline->a;
    const double grainAngle =
        std::acos(std::min(1.0, std::abs(grain.dot(grainTruth)) / (grain.norm() * grainTruth.norm()))) * 180.0 / M_PI;
    QCOMPARE(found.drillHoles.size(), std::size_t(1));
    const double holeOff = (found.drillHoles.front() - worldOf(synth, synth.drillHoles.front())).norm();
    // The fold: the centre front, corner to corner, which the bracket points at.
    QVERIFY(found.fold.has_value() && synth.fold.has_value());
    const Point foldA = worldOf(synth, (*synth.fold)[0]), foldB = worldOf(synth, (*synth.fold)[1]);
    const double foldOff = kontur::test::endsOff(found.fold->a, found.fold->b, foldA, foldB);
    qInfo("grainline %.3f° off, drill hole %.2f mm off, fold's ends %.2f mm off", grainAngle, holeOff, foldOff);
    QVERIFY2(grainAngle <= 0.5, qPrintable(QString::number(grainAngle)));
    QVERIFY2(holeOff <= 0.5, qPrintable(QString::number(holeOff)));
    QVERIFY2(foldOff <= 1.0, qPrintable(QString::number(foldOff)));
    screenshot(QStringLiteral("marked-traced.png"));

    // Seam allowance → Add: 1 cm all round.
    menuEntry(QStringLiteral("traceMenuButton"), QStringLiteral("traceSeamAllowance"), true);
    tapItem(item(QStringLiteral("seamAdd")), true);
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QObject *seamDialog = m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"));
    QVERIFY(seamDialog);
    QTRY_VERIFY(!seamDialog->property("visible").toBool());
    overlayClear();

    // The piece bar: the hem (the seam across the bottom, left of its V notch) tapped, + four times
    // (3 cm), Hem.
    auto *seams = m_window->findChild<kontur::SeamWidths *>(QStringLiteral("seamWidths"));
    QVERIFY(seams);
    // The allowance added is selected: the piece is chosen in the side panel's list of curves.
    QQuickItem *list = item(QStringLiteral("curveList"));
    QVERIFY(list);
    QQuickItem *row = nullptr;
    QTRY_VERIFY([&] {
        const auto *content = list->property("contentItem").value<QQuickItem *>();
        for (QQuickItem *c : content ? content->childItems() : QList<QQuickItem *>{})
            if (c->property("name").toString() == pieceName)
                row = c;
        return row != nullptr;
    }());
    kontur::test::ensureVisible(row);
    tapItem(row, true);
    QTRY_COMPARE(m_editor->selection()->curveId(), m_editor->document()->curve(0).id());
    QQuickItem *pieceButton = item(QStringLiteral("pieceButton"));
    QTRY_VERIFY(pieceButton && pieceButton->isVisible());
    kontur::test::ensureVisible(pieceButton);
    tapItem(pieceButton, true);
    QTRY_VERIFY(item(QStringLiteral("pieceBar")) && item(QStringLiteral("pieceBar"))->isVisible());
    tapItem(item(QStringLiteral("pieceSeamTool")), true);
    const auto &hemCubic = synth.pieceSegments[3];
    const Point hemPoint =
        worldOf(synth, kontur::geo::Bezier({hemCubic[0], hemCubic[1], hemCubic[2], hemCubic[3]}).eval(0.3));
    tapAt(sceneOf(hemPoint), true);
    QTRY_VERIFY(seams->seam() >= 0);
    const int hem = seams->seam();
    for (int i = 0; i < 4; ++i)
        tapItem(item(QStringLiteral("pieceSeamWider")), true);
    QTRY_COMPARE(seams->width().value_or(0), 30.0);
    tapItem(item(QStringLiteral("pieceSeamHem")), true);
    QTRY_VERIFY(seams->hem());
    const kontur::io::PieceMarks edited = *m_editor->document()->curve(0).piece;
    QCOMPARE(edited.hems, std::vector<int>{hem});
    QVERIFY(edited.seamWidths.size() > std::size_t(hem) && edited.seamWidths[std::size_t(hem)].value_or(0) == 30.0);
    screenshot(QStringLiteral("marked-hem.png"));

    // File → Export DXF for pattern software, as offered.
    menuEntry(QStringLiteral("fileMenuButton"), QStringLiteral("exportAamaAction"), true);
    QObject *aamaDialog = shownDialog(QStringLiteral("Export DXF for pattern software"));
    QVERIFY(aamaDialog);
    const QString aama = aamaDialog->property("selectedFile").toUrl().toLocalFile();
    QVERIFY(aama.endsWith(QStringLiteral(".dxf")));
    acceptAsOffered(aamaDialog, true);
    QTRY_VERIFY(QFile::exists(aama));
    QVERIFY(m_editor->message().id != kontur::Message::PiecesWithoutGrainline);

    // ezdxf, layer by layer: the cut line and the piece's texts (1), the sew line (14), three notches
    // (4; the two V's kinds on 84), the grain line (7), one drill hole (13).
    QProcess ezdxf;
    ezdxf.start(QStringLiteral("/usr/bin/python3"), {QStringLiteral(KONTUR_AAMA_LAYERS_PY), aama});
    QVERIFY(ezdxf.waitForFinished(120000));
    QVERIFY2(ezdxf.exitCode() == 0, "ezdxf (python3-ezdxf, in packaging/bootstrap) must read the file");
    const QJsonObject read = QJsonDocument::fromJson(ezdxf.readAllStandardOutput()).object();
    const QJsonObject layers = read.value(QStringLiteral("layers")).toObject();
    const auto count = [&](const char *layer, const char *type) {
        return layers.value(QLatin1String(layer)).toObject().value(QLatin1String(type)).toInt();
    };
    qInfo("%s", QJsonDocument(layers).toJson(QJsonDocument::Compact).constData());
    QVERIFY(count("1", "TEXT") >= 1);
    QVERIFY(read.value(QStringLiteral("texts")).toArray().contains(QStringLiteral("Piece Name: ") + pieceName));
    QVERIFY(!layers.value(QStringLiteral("1")).toObject().isEmpty() &&
            !layers.value(QStringLiteral("14")).toObject().isEmpty());
    QCOMPARE(count("4", "POINT"), 3);
    QCOMPARE(count("84", "POINT"), 2);
    QCOMPARE(count("7", "LINE"), 1);
    QCOMPARE(count("13", "POINT"), 1);
    QVERIFY(!layers.value(QStringLiteral("6")).toObject().isEmpty()); // the mirror line: the fold
    QVERIFY(read.value(QStringLiteral("texts")).toArray().contains(QStringLiteral("Annotation: On fold")));

    // Kontur reads the same piece back: its grainline, notches and drill hole, and its cut line.
    const auto dxf = kontur::io::readDxf(aama);
    QVERIFY(dxf.ok());
    const auto records = kontur::io::dxfRecords(*dxf, aama);
    QVERIFY(records.ok());
    QCOMPARE(records->size(), std::size_t(2));
    const auto back = kontur::io::pieceFromSettings(records->front().settings);
    QVERIFY(back.has_value());
    const double tol = 1e-3;
    const auto near = [&](const Point &a, const Point &b) { return (a - b).norm() <= tol; };
    QVERIFY(back->grainline && near(back->grainline->a, edited.grainline->a) &&
            near(back->grainline->b, edited.grainline->b));
    QCOMPARE(back->notches.size(), edited.notches.size());
    for (std::size_t i = 0; i < edited.notches.size(); ++i) {
        QCOMPARE(back->notches[i].kind, edited.notches[i].kind);
        // Along the sew line as AAMA writes it, a polyline within 0.01 mm of the curve: its chords
        // shorten the arc length by a little (0.02 mm over half a metre).
        QVERIFY2(std::abs(back->notches[i].position - edited.notches[i].position) <= 0.05,
                 qPrintable(QString::number(back->notches[i].position - edited.notches[i].position)));
        QCOMPARE(back->notches[i].angle, edited.notches[i].angle);
    }
    QCOMPARE(back->drillHoles.size(), std::size_t(1));
    QVERIFY(near(back->drillHoles.front(), edited.drillHoles.front()));
    QVERIFY(back->fold && edited.fold &&
            ((near(back->fold->a, edited.fold->a) && near(back->fold->b, edited.fold->b)) ||
             (near(back->fold->a, edited.fold->b) && near(back->fold->b, edited.fold->a))));
    // The hem comes back: its seam, its 3 cm and its turned-back corners, matched on the cut line,
    // which is again the piece's 1 cm allowance (linked). The sew line as AAMA writes it is a polyline
    // of 99 chords; its chord at each corner is short, so that the corners' mirror lines are the
    // curve's (tst_io_dxf_content aamaHemComesBack does the same for a flared skirt).
    QCOMPARE(back->hems, edited.hems);
    QVERIFY(back->seamWidths.size() > std::size_t(hem) && back->seamWidths[std::size_t(hem)] == std::optional(30.0));
    const auto readSeam = kontur::io::seamFromSettings(records->back().settings, 2);
    QVERIFY(readSeam.has_value());
    QCOMPARE(readSeam->source, 0);
    QCOMPARE(readSeam->options.distance, 10.0);

    // File → Print pattern…: the PDF, as offered, with the piece's label and the hem's width.
    menuEntry(QStringLiteral("fileMenuButton"), QStringLiteral("printAction"), true);
    tapItem(item(QStringLiteral("printDialogPrint")), true);
    QObject *pdfDialog = shownDialog(QStringLiteral("Print pattern to PDF"));
    QVERIFY(pdfDialog);
    const QString pdf = pdfDialog->property("selectedFile").toUrl().toLocalFile();
    QVERIFY(pdf.endsWith(QStringLiteral(".pdf")));
    acceptAsOffered(pdfDialog, true);
    QTRY_VERIFY(QFile::exists(pdf));
    overlayClear();
    QProcess text;
    text.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
    QVERIFY(text.waitForFinished(120000));
    QVERIFY2(text.exitCode() == 0, "pdftotext (poppler-utils, in packaging/bootstrap) must read the PDF");
    const QString printed = QString::fromUtf8(text.readAllStandardOutput());
    QVERIFY2(printed.contains(pieceName) && printed.contains(QStringLiteral("3 cm")), qPrintable(printed));
    QVERIFY2(printed.contains(QStringLiteral("Cut 1 on fold")) && printed.contains(QStringLiteral("Place on fold")),
             qPrintable(printed));
    // On paper (pdftoppm at 300 dpi, the page that shows each place, as the print dialog tiled it): the
    // grainline's middle and its arrowhead's tip, the drill hole's cross and each notch's mark between
    // the sew and cut lines; 5 mm beside the grainline's middle, nothing.
    QObject *printer = m_window->findChild<QObject *>(QStringLiteral("printer"));
    QVERIFY(printer);
    kontur::geo::TilingOptions tiling;
    tiling.paper = printer->property("paper").toInt() == kontur::PrintController::Letter ? kontur::geo::kPaperLetter
                                                                                         : kontur::geo::kPaperA4;
    const int orientation = printer->property("orientation").toInt();
    tiling.orientation = orientation == kontur::PrintController::Portrait    ? kontur::geo::PageOrientation::Portrait
                         : orientation == kontur::PrintController::Landscape ? kontur::geo::PageOrientation::Landscape
                                                                             : kontur::geo::PageOrientation::Auto;
    tiling.overlap = printer->property("overlap").toDouble();
    const auto plan = kontur::planPrint(kontur::toDocumentData(*m_editor->document()), tiling);
    QVERIFY(plan.ok());
    QTemporaryDir rasters;
    std::map<int, QImage> pages;
    constexpr double kMmPerPixel = 25.4 / 300.0;
    const auto darkNear = [&](const Point &world, double radius) {
        const kontur::geo::Tiling &t = plan->tiling;
        const double u = (world.x() - plan->minX) * plan->mmPerUnit + kontur::kPrintPaddingMm;
        const double v = (plan->maxY - world.y()) * plan->mmPerUnit + kontur::kPrintPaddingMm;
        const int column = std::clamp(static_cast<int>(u / t.stepX()), 0, t.columns - 1);
        const int row = std::clamp(static_cast<int>(v / t.stepY()), 0, t.rows - 1);
        const int page = 2 + row * t.columns + column; // page 1: the test square and the overview
        if (!pages.count(page)) {
            const QString prefix = rasters.filePath(QStringLiteral("page%1").arg(page));
            QProcess raster;
            raster.start(QStringLiteral("pdftoppm"),
                         {QStringLiteral("-r"), QStringLiteral("300"), QStringLiteral("-f"), QString::number(page),
                          QStringLiteral("-l"), QString::number(page), QStringLiteral("-png"),
                          QStringLiteral("-singlefile"), pdf, prefix});
            if (!raster.waitForFinished(120000) || raster.exitCode() != 0)
                return false;
            pages[page] = QImage(prefix + QStringLiteral(".png")).convertToFormat(QImage::Format_RGB32);
        }
        const QImage &img = pages[page];
        const QPoint c(qRound((t.margin + u - column * t.stepX()) / kMmPerPixel),
                       qRound((t.margin + v - row * t.stepY()) / kMmPerPixel));
        const int n = static_cast<int>(std::ceil(radius / kMmPerPixel));
        for (int dy = -n; dy <= n; ++dy)
            for (int dx = -n; dx <= n; ++dx)
                if (img.rect().contains(c + QPoint(dx, dy)) && qGray(img.pixel(c + QPoint(dx, dy))) < 128)
                    return true;
        return false;
    };
    const Point grainA = edited.grainline->a, grainB = edited.grainline->b;
    const Point grainMiddle = (grainA + grainB) / 2,
                across = Point(grainA.y() - grainB.y(), grainB.x() - grainA.x()).normalized();
    QVERIFY2(darkNear(grainMiddle, 0.2), "the grainline");
    QVERIFY2(!darkNear(grainMiddle + 5.0 * across, 0.5), "nothing beside the grainline");
    QVERIFY2(darkNear(grainB, 0.3) || darkNear(grainA, 0.3), "the grainline's arrowhead");
    QVERIFY2(darkNear(edited.drillHoles.front(), 0.2), "the drill hole's cross");
    QCOMPARE(m_editor->document()->curveCount(), 2); // the piece and its allowance, the cut line
    const kontur::geo::PiecewiseBezier sewLine = m_editor->document()->curve(0).toPiecewise();
    const kontur::geo::PiecewiseBezier cutLine = m_editor->document()->curve(1).toPiecewise();
    for (const kontur::io::Notch &notch : edited.notches) {
        const kontur::io::CurvePlace place = kontur::io::placeAtLength(sewLine, notch.position);
        const Point into = kontur::io::notchDirection(sewLine, place, notch.angle);
        const auto cut = kontur::io::meetAlong(cutLine, place.point, into);
        QVERIFY(cut.has_value());
        // The mark (a slit, or a V open outwards) runs across the cut line, from a millimetre out to a
        // few in: ink within 0.6 mm of the point 2 mm in, where nothing else is drawn.
        QVERIFY2(darkNear(*cut + 2.0 * into, 0.6), qPrintable(QStringLiteral("notch at %1 mm").arg(notch.position)));
    }
    QTRY_VERIFY(!m_window->findChild<QObject *>(QStringLiteral("printDialog"))->property("visible").toBool());
    m_trace->setTool(TraceController::Tool::None);
}

// Freehand with Snap to edges on the calibrated photo: a mouse stroke drawn 1.5 mm below the sheet's
// top edge (wobbling by ±0.5 mm) becomes a curve on that edge, within 0.5 mm (the fit's tolerance at
// fit-to-view zoom is half the stroke's, about 0.3 mm, plus the calibration's error there); with the
// option off the same stroke stays where it was drawn.
void TestOutlineWindow::freehandSnapsToTheSheetsEdge()
{
    const kontur::Background bg = m_editor->document()->background();
    QVERIFY(bg.perspective);
    m_trace->setTool(TraceController::Tool::Freehand);
    QTRY_VERIFY(item(QStringLiteral("traceSnapEdges")));
    QVERIFY(!m_trace->freehand()->snapToEdges());
    const double top = bg.rectOrigin.y(), left = bg.rectOrigin.x();
    for (const bool snap : {true, false}) {
        if (m_trace->freehand()->snapToEdges() != snap)
            tapItem(item(QStringLiteral("traceSnapEdges")), false);
        QCOMPARE(m_trace->freehand()->snapToEdges(), snap);
        const int before = m_editor->document()->curveCount();
        const auto at = [&](double x, double y) {
            return m_canvas->mapToScene(m_canvas->toScreen(QPointF(x, y))).toPoint();
        };
        QTest::mousePress(m_window, Qt::LeftButton, {}, at(left + 40, top - 1.5));
        for (int i = 1; i <= 40; ++i)
            QTest::mouseMove(m_window, at(left + 40 + 3.0 * i, top - 1.5 + 0.5 * std::sin(i * 0.7)));
        QTest::mouseRelease(m_window, Qt::LeftButton, {}, at(left + 160, top - 1.5));
        QTRY_COMPARE(m_editor->document()->curveCount(), before + 1);
        double worst = 0.0;
        const auto &c = m_editor->document()->curve(before).composite();
        for (const Point &p : kontur::test::sampleComposite(c.controlPoints(), 20))
            worst = std::max(worst, std::abs(p.y() - top));
        qInfo("snap to edges %s: largest distance from the sheet's edge %.3f mm", snap ? "on" : "off", worst);
        if (snap)
            QVERIFY2(worst <= 0.5, qPrintable(QString::number(worst)));
        else
            QVERIFY(worst > 0.8);
        // The next stroke starts where this one did: it would continue this open curve (a stroke
        // from an open curve's end extends it), so this one is taken back first.
        m_editor->undo();
        QTRY_COMPARE(m_editor->document()->curveCount(), before);
    }
}

QTEST_MAIN(TestOutlineWindow)
#include "tst_outline_window.moc"
