// From a phone photo to a pattern piece in the real window, by touch and by mouse: a synthetic photo
// with ground truth (tests/vision/synthphoto.h: an A4 sheet and a bodice piece on a wooden table, seen
// at an angle) is loaded by the first start's Trace a picture, which finds the sheet at once; Apply
// (A4), Trace outline, a tap inside the piece, Seam allowance → Add, File → Export DXF for pattern
// software, File → Print pattern → Print to PDF, each saved under the name and in the folder offered
// (the photo's). The taps are counted (at most 20; a file dialog takes one, the picture's two), the sheet's corners
// must be found within 0.3 photo px, the traced outline is compared with the truth in mm (Hausdorff within 0.5 mm), and
// the DXF and PDF must be written with the piece and its allowance.
#include "windowtest.h"

#include "matimage.h"
#include "synthflat.h"
#include "synthphoto.h"

#include "app/curvecanvas.h"
#include "io/dxf.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/printcontroller.h"
#include "models/document/document.h"
#include "models/trace/tracecontroller.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QQuickItem>
#include <QQuickWindow>
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
    QCOMPARE(m_editor->message().id, kontur::Message::OutlineTraced);
    const kontur::Curve &traced = m_editor->document()->curve(0);
    QVERIFY(traced.isClosed());
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
    // The traced piece has no grainline yet: none is written, and the message says so.
    QCOMPARE(m_editor->message().id, kontur::Message::PiecesWithoutGrainline);
    const auto pieces = kontur::io::readDxf(aama);
    QVERIFY(pieces.ok());
    std::map<int, kontur::geo::PiecewiseBezier> byLayer;
    for (const kontur::io::DxfImportedCurve &c : pieces->curves) {
        QVERIFY(!c.piece.isEmpty());
        QCOMPARE(c.piece, pieces->curves.front().piece);
        byLayer.emplace(c.aamaLayer, c.curve);
    }
    QVERIFY(byLayer.count(1) && byLayer.count(14) && !byLayer.count(7));
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
    answerDialog(QStringLiteral("Export DXF"), [&] { return m_files->exportDxf(QUrl::fromLocalFile(dxf), false); });
    QTRY_VERIFY(QFile::exists(dxf));
    QFile written(dxf);
    QVERIFY(written.open(QIODevice::ReadOnly));
    QCOMPARE(written.readAll().count("\nSPLINE\n"), 2);
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
