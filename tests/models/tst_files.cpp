// Keeping work: documents save and open exactly, points records are appended and never truncate
// (seed T09), imports add curves, a failed read changes nothing, exports write what they say. The
// recovery copy and the recent files: tst_betweenruns.cpp.
#include "../curveids.h"
#include "../ownfolders.h"
#include "filldocument.h"
#include "io/document.h"
#include "io/dxf.h"
#include "io/pointstext.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/piecemarks.h"
#include "models/controllers/recovery.h" // its folders, for ownfolders.h
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/document/selection.h"
#include "models/trace/seamallowance.h"

#include <QDir>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using kontur::CurveKind;
using kontur::DocumentFiles;
using kontur::EditController;
using kontur::Exporter;
using kontur::Recovery;
using kontur::geo::Point;
using kontur::test::fill;
using kontur::test::rowsOf;

class TestFiles final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The settings (and any recovery copy) are this process's own (ownfolders.h), not shared with the
    // runs of this test under other locales at the same time.
    void initTestCase() { QVERIFY(kontur::test::inOwnFolders(Recovery::recoveryPath())); }
    void saveAndOpenEveryKindExactly();
    void t09_appendingNeverTruncates();
    void failedReadChangesNothing();
    void importsAddCurvesAsOneStep();
    void dxfOfEveryKind();
    void unitlessDxfAsksOnceAndSaysWhatIsSkipped();
    void unitlessUnitsChangeTheNextImport();
    void svgSkippedContentIsSaid();
    void aamaExportWritesPieces();
    void aamaExportWithoutClosedCurve();
};

void TestFiles::saveAndOpenEveryKindExactly()
{
    QTemporaryDir dir;
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    kontur::RecentFiles recent;
    files.setRecent(&recent);
    fill(editor);
    QVERIFY(editor.isModified());
    const QString path = dir.filePath(QStringLiteral("all.kontur"));
    QVERIFY(files.saveAs(QUrl::fromLocalFile(path)));
    QVERIFY(!editor.isModified());
    QCOMPARE(files.displayName(), QStringLiteral("all.kontur"));
    QCOMPARE(recent.paths().value(0), path);

    EditController reopened;
    DocumentFiles reopenedFiles;
    reopenedFiles.setEditor(&reopened);
    QVERIFY(reopenedFiles.open(QUrl::fromLocalFile(path)));
    QCOMPARE(reopened.document()->curveCount(), editor.document()->curveCount());
    for (int c = 0; c < editor.document()->curveCount(); ++c)
        QVERIFY2(reopened.document()->curve(c).sameState(editor.document()->curve(c)), qPrintable(QString::number(c)));
    QVERIFY(reopened.document()->background() == editor.document()->background());
    QVERIFY(!reopened.isModified());
    QVERIFY(!reopened.canUndo());

    // save → open → save is byte-identical.
    const QString again = dir.filePath(QStringLiteral("again.kontur"));
    QVERIFY(reopenedFiles.saveAs(QUrl::fromLocalFile(again)));
    QFile a(path), b(again);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(b.readAll(), a.readAll());
}

void TestFiles::t09_appendingNeverTruncates()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("points.txt"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("# my own notes\n1 2\n3 4\n");
    }
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::LeastSquares),
                                                      rowsOf({{0, 0}, {1, 2}, {2, 3}, {3, 2}, {4, 0}})));
    QVERIFY(exporter.appendPoints(QUrl::fromLocalFile(path)));
    QVERIFY(exporter.appendPoints(QUrl::fromLocalFile(path)));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY(text.startsWith("# my own notes\n1 2\n3 4\n"));
    QCOMPARE(text.count("curve least-squares"), 2);
    // The records read back as curves: the hand-written list and the two appended ones.
    const auto records = kontur::io::readPointsText(path);
    QVERIFY(records.ok());
    QCOMPARE(records->size(), std::size_t(3));
    QCOMPARE(records->at(1).curve.points, editor.document()->curve(0).placedPoints());
}

void TestFiles::failedReadChangesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.kontur"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            R"({"format": "kontur", "version": 1, "units": "px", "curves": [{"kind": "bezier", "points": [[0, 0], [1, "x"]]}]})");
    }
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier), rowsOf({{0, 0}, {5, 5}})));
    QVERIFY(!files.open(QUrl::fromLocalFile(path)));
    QCOMPARE(editor.message().id, kontur::Message::FileReadError);
    QVERIFY2(editor.messageText().contains(QStringLiteral("curves[0].points[1][1]")), qPrintable(editor.messageText()));
    QCOMPARE(editor.document()->curveCount(), 1);
    QVERIFY(editor.canUndo());
    // A failed write leaves the old file as it was.
    QVERIFY(!files.saveAs(QUrl::fromLocalFile(dir.filePath(QStringLiteral("missing/folder/x.kontur")))));
    QCOMPARE(editor.message().id, kontur::Message::FileWriteError);
}

void TestFiles::importsAddCurvesAsOneStep()
{
    QTemporaryDir dir;
    const QString list = dir.filePath(QStringLiteral("list.txt"));
    const QString svg = dir.filePath(QStringLiteral("shape.svg"));
    {
        QFile file(list);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0;0\n10;20\n30;25\n50;0\n");
        QFile image(svg);
        QVERIFY(image.open(QIODevice::WriteOnly));
        image.write(
            R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 C 10 20 30 20 40 0 S 70 -20 80 0"/></svg>)");
    }
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(files.importFile(QUrl::fromLocalFile(list), static_cast<int>(CurveKind::NaturalSpline)));
    QCOMPARE(editor.document()->curve(0).kind(), CurveKind::NaturalSpline);
    QCOMPARE(editor.document()->curve(0).placedCount(), 4);
    QVERIFY(files.importFile(QUrl::fromLocalFile(svg), static_cast<int>(CurveKind::Composite)));
    const kontur::Curve &imported = editor.document()->curve(1);
    QCOMPARE(imported.kind(), CurveKind::Composite);
    QCOMPARE(imported.segmentCount(), 2);
    // SVG has y down, the world y up.
    QVERIFY((imported.segment(0).controlPoints()[1] - Point(10, -20)).norm() < 1e-12);
    QCOMPARE(editor.message().id, kontur::Message::FileImported);
    editor.undo();
    QCOMPARE(editor.document()->curveCount(), 1);
}

// Every kind exported as DXF splines (issue 22) opens again as the same shapes in the same units
// (cubic pieces bit for bit, one piece of a higher degree as a Bézier curve, several as cubics within
// 1e-6); the polylines stay within 0.05 mm; an import into a document in cm is scaled and one undo step.
void TestFiles::dxfOfEveryKind()
{
    QTemporaryDir dir;
    EditController editor;
    fill(editor);
    std::vector<kontur::Curve> all = editor.document()->curves();
    editor.replaceDocument(all, kontur::Background{}, QStringLiteral("mm"), false);
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    const QString exact = dir.filePath(QStringLiteral("pattern.dxf"));
    const QString flat = dir.filePath(QStringLiteral("pattern-flat.dxf"));
    QVERIFY(exporter.exportDxf(QUrl::fromLocalFile(exact), false));
    QCOMPARE(editor.message().id, kontur::Message::FileSaved);
    QVERIFY(exporter.exportDxf(QUrl::fromLocalFile(flat), true));
    std::vector<const kontur::Curve *> visible;
    for (const kontur::Curve &c : editor.document()->curves())
        if (c.visible)
            visible.push_back(&c);

    EditController reader;
    DocumentFiles opener;
    opener.setEditor(&reader);
    QVERIFY2(opener.open(QUrl::fromLocalFile(exact)), qPrintable(reader.messageText()));
    QCOMPARE(reader.document()->units(), QStringLiteral("mm"));
    QCOMPARE(static_cast<std::size_t>(reader.document()->curveCount()), visible.size());
    for (std::size_t i = 0; i < visible.size(); ++i) {
        const kontur::geo::PiecewiseBezier a = visible[i]->toPiecewise();
        const kontur::geo::PiecewiseBezier b = reader.document()->curve(static_cast<int>(i)).toPiecewise();
        bool cubic = true;
        for (const auto &s : a.segments())
            cubic = cubic && s.degree() <= 3;
        if (cubic || a.segmentCount() == 1) {
            QCOMPARE(b.segmentCount(), a.segmentCount());
            for (int s = 0; s < a.segmentCount(); ++s) {
                const auto &sa = a.segments()[static_cast<std::size_t>(s)];
                const auto &sb = b.segments()[static_cast<std::size_t>(s)];
                if (sa.degree() == sb.degree())
                    QCOMPARE(sb.controlPoints(), sa.controlPoints());
                else // a line or quadratic of a composite curve, elevated: the same curve
                    QCOMPARE(sb.controlPoints(), sa.elevated(sb.degree() - sa.degree()).controlPoints());
            }
        }
        for (int k = 0; k <= 64; ++k) {
            const Point p = a.eval(a.segmentCount() * k / 64.0);
            QVERIFY2(b.nearest(p).distance < 2e-6, qPrintable(QString::number(i)));
        }
    }
    QVERIFY(opener.open(QUrl::fromLocalFile(flat)));
    for (std::size_t i = 0; i < visible.size(); ++i) {
        const kontur::geo::PiecewiseBezier a = visible[i]->toPiecewise();
        const kontur::geo::PiecewiseBezier b = reader.document()->curve(static_cast<int>(i)).toPiecewise();
        for (int k = 0; k <= 256; ++k)
            QVERIFY(b.nearest(a.eval(a.segmentCount() * k / 256.0)).distance <= 0.05);
    }

    // Into a document in centimetres: a tenth of the numbers, one undo step for all curves.
    reader.replaceDocument({}, kontur::Background{}, QStringLiteral("cm"), false);
    QVERIFY(reader.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier), rowsOf({{0, 0}, {5, 5}})));
    QVERIFY(opener.importFile(QUrl::fromLocalFile(exact), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(static_cast<std::size_t>(reader.document()->curveCount()), visible.size() + 1);
    const kontur::geo::PiecewiseBezier first = visible.front()->toPiecewise();
    const kontur::geo::PiecewiseBezier scaled = reader.document()->curve(1).toPiecewise();
    QVERIFY((scaled.segments().back().endPoint() - first.segments().back().endPoint() / 10).norm() < 1e-12);
    QCOMPARE(reader.message().id, kontur::Message::FileImported);
    reader.undo();
    QCOMPARE(reader.document()->curveCount(), 1);
}

// A DXF without $INSUNITS: the UI asks once (needsUnits), the choice is remembered for DXF files and
// used by Open and Import; what the file held that is not drawn (a text, a 3D face) is said in the
// message; the drawing, all in a block, comes in.
void TestFiles::unitlessDxfAsksOnceAndSaysWhatIsSkipped()
{
    QSettings().remove(QStringLiteral("unitlessUnits"));
    QTemporaryDir dir;
    const QString unitless = dir.filePath(QStringLiteral("unitless.dxf"));
    const QString declared = dir.filePath(QStringLiteral("declared.dxf"));
    {
        QFile file(unitless);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n10\n0\n20\n0\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n"
                   "0\nENDBLK\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nTEXT\n1\nSleeve\n0\n3DFACE\n10\n0\n20\n0\n"
                   "0\nINSERT\n2\nB\n10\n0\n20\n0\n41\n2\n42\n2\n0\nENDSEC\n0\nEOF\n");
        QFile other(declared);
        QVERIFY(other.open(QIODevice::WriteOnly));
        other.write("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
                    "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC\n0\nEOF\n");
    }
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(files.needsUnits(QUrl::fromLocalFile(unitless)));
    QVERIFY(!files.needsUnits(QUrl::fromLocalFile(declared)));
    files.rememberUnits(QUrl::fromLocalFile(unitless), QStringLiteral("in"));
    QVERIFY(!files.needsUnits(QUrl::fromLocalFile(unitless))); // asked once
    QVERIFY2(files.open(QUrl::fromLocalFile(unitless)), qPrintable(editor.messageText()));
    QCOMPARE(editor.document()->units(), QStringLiteral("in"));
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.document()->curve(0).toPiecewise().segments().back().endPoint(), Point(2, 0));
    // Read in the remembered units, which the message says (offering to change them), with what was skipped.
    QCOMPARE(editor.message().id, kontur::Message::FileImportedUnitless);
    QVERIFY(editor.message().offersUnits());
    QCOMPARE(editor.message().args.value(2).toString(), QStringLiteral("in"));
    QCOMPARE(editor.message().args.value(3).toList(), (QVariantList{1, 0, 1, 0, 0, 0}));
    QVERIFY2(editor.messageText().contains(QStringLiteral("1 text")), qPrintable(editor.messageText()));
    // Into a document in mm: the remembered inches converted.
    editor.replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
    QVERIFY(files.importFile(QUrl::fromLocalFile(unitless), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(editor.document()->curve(0).toPiecewise().segments().back().endPoint(), Point(50.8, 0));
    QCOMPARE(editor.message().id, kontur::Message::FileImportedUnitless);
    // A file that names its units says nothing of them.
    QVERIFY(files.importFile(QUrl::fromLocalFile(declared), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(editor.message().id, kontur::Message::FileImported);
    QVERIFY(!editor.message().offersUnits());
    files.rememberUnits(QUrl::fromLocalFile(unitless), QStringLiteral("furlong")); // not a choice: kept
    QCOMPARE(QSettings().value(QStringLiteral("unitlessUnits/dxf")).toString(), QStringLiteral("in"));
    QSettings().remove(QStringLiteral("unitlessUnits"));
}

// The units of DXF files that name none can be changed later (the setting dxfUnitlessUnits, offered by
// the message after such a file was read): each import uses the units set last (2 units as 20 mm,
// then 50.8 mm); changed right after a read, the file is read again in the new units as one undo
// step (an import) or as the document (an open); changed after something else was done, nothing is
// read again and the message says the units apply from the next import on.
void TestFiles::unitlessUnitsChangeTheNextImport()
{
    QSettings().remove(QStringLiteral("unitlessUnits"));
    QTemporaryDir dir;
    const QString unitless = dir.filePath(QStringLiteral("plain.dxf"));
    {
        QFile file(unitless);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n2\n21\n0\n0\nENDSEC\n0\nEOF\n");
    }
    const QUrl url = QUrl::fromLocalFile(unitless);
    const int composite = static_cast<int>(CurveKind::Composite);
    EditController editor;
    editor.replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
    DocumentFiles files;
    files.setEditor(&editor);
    QSignalSpy changed(&files, &DocumentFiles::dxfUnitlessUnitsChanged);
    QCOMPARE(files.dxfUnitlessUnits(), QStringLiteral("px"));
    const auto end = [&](int curve) {
        return editor.document()->curve(curve).toPiecewise().segments().back().endPoint();
    };

    files.setDxfUnitlessUnits(QStringLiteral("cm"));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(QSettings().value(QStringLiteral("unitlessUnits/dxf")).toString(), QStringLiteral("cm"));
    QVERIFY(!files.needsUnits(url)); // chosen: not asked any more
    QVERIFY(files.importFile(url, composite));
    QCOMPARE(end(0), Point(20, 0));
    QCOMPARE(editor.message().id, kontur::Message::FileImportedUnitless);
    QCOMPARE(editor.message().args.value(2).toString(), QStringLiteral("cm"));
    files.setDxfUnitlessUnits(QStringLiteral("in"));
    files.setDxfUnitlessUnits(QStringLiteral("in"));      // the same: no change
    files.setDxfUnitlessUnits(QStringLiteral("furlong")); // not a choice: ignored
    QCOMPARE(changed.count(), 2);
    QCOMPARE(files.dxfUnitlessUnits(), QStringLiteral("in"));
    QVERIFY(files.importFile(url, composite));
    QCOMPARE(end(1), Point(50.8, 0));
    QCOMPARE(editor.document()->curve(0).toPiecewise().segments().back().endPoint(), Point(20, 0)); // kept

    // Changed right after the import: that import read again in mm, still one step to undo.
    const int steps = editor.undoStack()->count();
    files.changeUnitlessUnits(QStringLiteral("mm"));
    QCOMPARE(changed.count(), 3);
    QCOMPARE(editor.document()->curveCount(), 2);
    QCOMPARE(end(1), Point(2, 0));
    QCOMPARE(editor.undoStack()->count(), steps);
    QCOMPARE(editor.message().id, kontur::Message::FileImportedUnitless);
    QCOMPARE(editor.message().args.value(2).toString(), QStringLiteral("mm"));
    editor.undo();
    QCOMPARE(editor.document()->curveCount(), 1);
    // Something done since (here: that undo): nothing is read again, the message says so.
    files.changeUnitlessUnits(QStringLiteral("cm"));
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.message().id, kontur::Message::UnitlessUnitsChanged);
    QCOMPARE(editor.message().args.value(0).toString(), QStringLiteral("cm"));
    QVERIFY(files.importFile(url, composite));
    QCOMPARE(end(1), Point(20, 0));

    // Opened as the document: opened again in the new units.
    QVERIFY(files.open(url));
    QCOMPARE(editor.document()->units(), QStringLiteral("cm"));
    QCOMPARE(editor.message().id, kontur::Message::FileImportedUnitless);
    files.changeUnitlessUnits(QStringLiteral("in"));
    QCOMPARE(editor.document()->units(), QStringLiteral("in"));
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(end(0), Point(2, 0));
    // A new document since: nothing is read again.
    files.newDocument();
    files.changeUnitlessUnits(QStringLiteral("mm"));
    QCOMPARE(editor.document()->curveCount(), 0);
    QCOMPARE(editor.message().id, kontur::Message::UnitlessUnitsChanged);
    QSettings().remove(QStringLiteral("unitlessUnits"));
}

// An SVG's text and image are not drawn, and the message line says so as for a DXF: the path comes
// in, "not drawn: 1 text, 1 image".
void TestFiles::svgSkippedContentIsSaid()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("labelled.svg"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"(<svg xmlns="http://www.w3.org/2000/svg"><text x="1" y="2">Front</text>)"
                   R"(<image href="photo.png" width="10" height="10"/><path d="M0 0 C 10 20 30 20 40 0"/></svg>)");
    }
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(files.importFile(QUrl::fromLocalFile(path), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.message().id, kontur::Message::FileImportedSkipped);
    QCOMPARE(editor.message().args.value(2).toList(), (QVariantList{1, 0, 0, 1, 0, 0}));
    // (No English translation is loaded here: the source's plural forms read "1 text(s)".)
    QVERIFY2(editor.messageText().contains(QStringLiteral("not drawn: 1 text")) &&
                 editor.messageText().contains(QStringLiteral(", 1 image")),
             qPrintable(editor.messageText()));
    // Opened as a new document: the same.
    editor.clearMessage();
    QVERIFY(files.open(QUrl::fromLocalFile(path)));
    QCOMPARE(editor.message().id, kontur::Message::FileImportedSkipped);
    // A drawing of nothing but text and a picture is refused, and the refusal says what it held.
    const QString only = dir.filePath(QStringLiteral("labels.svg"));
    {
        QFile file(only);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"(<svg xmlns="http://www.w3.org/2000/svg"><text x="1" y="2">Front</text>)"
                   R"(<text x="1" y="9">Back</text><image href="photo.png" width="10" height="10"/></svg>)");
    }
    QVERIFY(!files.importFile(QUrl::fromLocalFile(only), static_cast<int>(CurveKind::Composite)));
    QCOMPARE(editor.message().id, kontur::Message::FileReadError);
    QCOMPARE(editor.messageText(), QStringLiteral("Could not read “labels.svg”: the drawing holds no shapes Kontur can "
                                                  "draw. Not drawn: 2 text(s), 1 image(s)."));
}

// File → Export DXF for pattern software: a closed piece with its linked seam allowance (1 cm outside)
// and an open dart inside it become one ASTM D6673 piece (the bytes kontur-cli's io functions write);
// read back with the io reader it is one piece "Front" whose cut line (layer 1) is the allowance and
// whose sew line (14) is the piece: every vertex of the polylines on its curve within 1e-6 mm, every
// point of the curves within 0.05 mm of the polylines.
void TestFiles::aamaExportWritesPieces()
{
    QTemporaryDir dir;
    EditController editor;
    kontur::Curve front =
        kontur::Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}, {40, 120}, {-10, 60}});
    QVERIFY(front.close().ok());
    front.name = QStringLiteral("Front");
    kontur::Curve dart = kontur::Curve::make(CurveKind::Bezier, {{30, 20}, {45, 70}, {60, 20}});
    dart.name = QStringLiteral("Dart");
    editor.replaceDocument({front, dart}, kontur::Background{}, QStringLiteral("mm"), false);
    editor.selection()->select(editor.document()->idAt(0));
    kontur::SeamAllowance seam;
    seam.setEditor(&editor);
    QVERIFY(seam.create(QStringLiteral("10"), kontur::SeamAllowance::Outside, kontur::SeamAllowance::Round,
                        QStringLiteral("30")));
    QTRY_VERIFY_WITH_TIMEOUT(!seam.busy(), 60'000);
    QCOMPARE(editor.document()->curveCount(), 3);
    const kontur::Curve &allowance = editor.document()->curve(2);
    QVERIFY(allowance.seam && allowance.isClosed());

    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(exporter.hasPieces());
    // A name typed without the extension gets it, as in every export.
    QVERIFY(exporter.exportAamaDxf(QUrl::fromLocalFile(dir.filePath(QStringLiteral("pieces")))));
    const QString path = dir.filePath(QStringLiteral("pieces.dxf"));
    // Written, but the piece has no grainline of its own: none is invented, and the user is told.
    QCOMPARE(editor.message().id, kontur::Message::PiecesWithoutGrainline);
    QCOMPARE(editor.message().args.value(0).toString(), QStringLiteral("pieces.dxf"));
    QCOMPARE(editor.message().args.value(1).toString(), QStringLiteral("Front"));
    QVERIFY(editor.messageText().contains(QStringLiteral("Front")));

    // The very bytes kontur-cli convert --aama writes (the same io functions, polylines by default).
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    const auto pieces = kontur::io::aamaPieces(kontur::toDocumentData(*editor.document()).curves);
    QVERIFY(pieces.ok());
    kontur::io::DxfExportOptions options;
    options.units = QStringLiteral("mm");
    options.flavour = kontur::io::DxfFlavour::Polyline;
    QCOMPARE(bytes, kontur::io::exportAamaDxf(*pieces, options));
    QCOMPARE(bytes.count("\nINSERT\n"), 1);           // the piece, inserted once
    QVERIFY(bytes.contains("\nPiece Name: Front\n")); // its name on layer 1

    const auto read = kontur::io::readDxf(path);
    QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
    QCOMPARE(read->units, QStringLiteral("mm"));
    QStringList names;
    for (const auto &c : read->curves) {
        names << c.name;
        QCOMPARE(c.piece, QStringLiteral("Front"));
    }
    QCOMPARE(names, (QStringList{QStringLiteral("Front cut line"), QStringLiteral("Front sew line"),
                                 QStringLiteral("Front internal line")}));
    const std::vector<std::pair<int, const kontur::Curve *>> lines{
        {1, &allowance}, {14, &editor.document()->curve(0)}, {8, &editor.document()->curve(1)}};
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const auto &[layer, curve] = lines[k];
        const kontur::io::DxfImportedCurve &got = read->curves[k];
        QCOMPARE(got.aamaLayer, layer);
        QCOMPARE(got.curve.isClosed(), curve->isClosed());
        const kontur::geo::PiecewiseBezier shape = curve->toPiecewise();
        double onCurve = 0.0, offPolyline = 0.0;
        for (const kontur::geo::Bezier &b : got.curve.segments()) {
            QVERIFY(kontur::io::isStraight(b));
            onCurve = std::max({onCurve, shape.nearest(b.startPoint()).distance, shape.nearest(b.endPoint()).distance});
        }
        for (int i = 0; i <= 64 * shape.segmentCount(); ++i)
            offPolyline = std::max(offPolyline, got.curve.nearest(shape.eval(i / 64.0)).distance);
        qInfo("layer %d: %d vertices, on the curve within %.2g mm, the curve within %.3f mm", layer,
              got.curve.segmentCount(), onCurve, offPolyline);
        QVERIFY2(onCurve <= 1e-6, qPrintable(QString::number(onCurve)));
        QVERIFY2(offPolyline <= 0.05 + 1e-9, qPrintable(QString::number(offPolyline)));
    }
    // The allowance's cut line lies 1 cm outside the sew line.
    const kontur::geo::Box cut = read->curves[0].curve.boundingBox(), sew = read->curves[1].curve.boundingBox();
    QVERIFY(std::abs(sew.min().x() - cut.min().x() - 10) <= 0.05);
    QVERIFY(std::abs(cut.max().y() - sew.max().y() - 10) <= 0.05);

    // Made a piece with a grainline of its own: the export writes that one, and just says it saved.
    kontur::PieceMarkEdits marks;
    marks.setEditor(&editor);
    editor.selection()->select(editor.document()->idAt(0));
    QVERIFY(marks.makePiece());
    QVERIFY(marks.setGrainline(50, 10, 50, 100));
    QVERIFY(exporter.exportAamaDxf(QUrl::fromLocalFile(path)));
    QCOMPARE(editor.message().id, kontur::Message::FileSaved);
    const auto again = kontur::io::readDxf(path);
    QVERIFY(again.ok());
    QCOMPARE(again->curves.back().aamaLayer, 7);
    QCOMPARE(again->curves.back().curve.segments().front().startPoint(), kontur::geo::Point(50, 10));
    QCOMPARE(again->curves.back().curve.segments().back().endPoint(), kontur::geo::Point(50, 100));
}

// Without a visible closed curve there is no piece: the menu entry asks for no file and says why, the
// export itself writes nothing and says the same; the document stays as it was.
void TestFiles::aamaExportWithoutClosedCurve()
{
    QTemporaryDir dir;
    EditController editor;
    kontur::Curve open = kontur::Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}});
    kontur::Curve hidden = kontur::Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}, {40, 120}});
    QVERIFY(hidden.close().ok());
    hidden.visible = false;
    editor.replaceDocument({open, hidden}, kontur::Background{}, QStringLiteral("mm"), false);
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(!exporter.hasPieces());
    QCOMPARE(editor.message().id, kontur::Message::NoPieces);
    editor.clearMessage();
    const QString path = dir.filePath(QStringLiteral("none.dxf"));
    QVERIFY(!exporter.exportAamaDxf(QUrl::fromLocalFile(path)));
    QCOMPARE(editor.message().id, kontur::Message::NoPieces);
    QVERIFY(editor.messageText().contains(QStringLiteral("closed curve")));
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY(QDir(dir.path()).isEmpty());
    QCOMPARE(editor.document()->curveCount(), 2);
    QVERIFY(!editor.isModified());
    // Shown again, the curve makes a piece.
    QVERIFY(editor.commands()->setCurveVisible(kontur::test::idAt(editor, 1), true));
    QVERIFY(exporter.hasPieces());
    QVERIFY(exporter.exportAamaDxf(QUrl::fromLocalFile(path)));
    QVERIFY(QFileInfo::exists(path));
}

QTEST_GUILESS_MAIN(TestFiles)
#include "tst_files.moc"
