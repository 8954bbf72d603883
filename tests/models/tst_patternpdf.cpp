// The pattern PDF (issue 22), measured on paper: the PDF is rasterized with pdftoppm at 300 dpi and
// the pixels are measured. The 10 cm test square on page 1 is 10 cm ± 0.3 mm; the page count
// (pdfinfo) is the tiling's for a 120 × 80 cm pattern on A4 and Letter; a line in the overlap of
// two pages is on both at the places the overlap says; the document read back from the PDF is the
// one written; a PDF Kontur did not write is refused; the app (PrintController, DocumentFiles) and
// kontur-cli write and read the same PDF, every kind of curve included.
#include "../curveids.h"
#include "../ownfolders.h"
#include "../skipsuite.h"
#include "io/document.h"
#include "io/pdf.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/printcontroller.h"
#include "models/controllers/recovery.h"
#include "models/document/documentio.h"
#include "print/patternpdf.h"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace kontur;
using kontur::test::idAt;

namespace {

constexpr double kDpi = 300.0;
constexpr double kMmPerPixel = 25.4 / kDpi;

io::CurveRecord line(double x0, double y0, double x1, double y1, const QString &color)
{
    io::CurveRecord c;
    c.kind = QStringLiteral("bezier");
    c.name = QStringLiteral("line");
    c.color = color;
    c.points = {geo::Point(x0, y0), geo::Point(x1, y1)};
    return c;
}

// A 120 cm × 80 cm rectangle outline of four lines (cm), and a curve inside.
io::DocumentData pattern120x80()
{
    io::DocumentData doc;
    doc.units = QStringLiteral("cm");
    doc.curves = {line(0, 0, 120, 0, QStringLiteral("#000000")), line(120, 0, 120, 80, QStringLiteral("#000000")),
                  line(120, 80, 0, 80, QStringLiteral("#000000")), line(0, 80, 0, 0, QStringLiteral("#000000"))};
    io::CurveRecord s;
    s.kind = QStringLiteral("composite");
    s.name = QStringLiteral("Sleeve");
    s.color = QStringLiteral("#1f77b4");
    s.points = {geo::Point(10, 10), geo::Point(30, 40), geo::Point(60, 40), geo::Point(80, 10)};
    s.nodeTypes = {QStringLiteral("smooth"), QStringLiteral("smooth")};
    doc.curves.push_back(s);
    return doc;
}

bool havePoppler()
{
    return !QStandardPaths::findExecutable(QStringLiteral("pdftoppm")).isEmpty() &&
           !QStandardPaths::findExecutable(QStringLiteral("pdfinfo")).isEmpty();
}

int pdfPages(const QString &pdf)
{
    QProcess p;
    p.start(QStringLiteral("pdfinfo"), {pdf});
    if (!p.waitForFinished(60000) || p.exitCode() != 0)
        return -1;
    const auto m =
        QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(QString::fromUtf8(p.readAllStandardOutput()));
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

// Page `page` (1-based) at 300 dpi.
QImage rasterize(const QString &pdf, int page, const QString &dir)
{
    const QString prefix = dir + QStringLiteral("/page%1").arg(page);
    QProcess p;
    p.start(QStringLiteral("pdftoppm"), {QStringLiteral("-r"), QString::number(kDpi), QStringLiteral("-f"),
                                         QString::number(page), QStringLiteral("-l"), QString::number(page),
                                         QStringLiteral("-png"), QStringLiteral("-singlefile"), pdf, prefix});
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return {};
    return QImage(prefix + QStringLiteral(".png")).convertToFormat(QImage::Format_RGB32);
}

// How much of a pixel the square's grey covers (0 white … 1 the square's grey), for a neutral pixel.
double squareCoverage(QRgb c)
{
    constexpr double paper = 255.0, grey = 190.0;
    if (std::abs(qRed(c) - qGreen(c)) > 6 || std::abs(qGreen(c) - qBlue(c)) > 6)
        return 0.0;
    return std::clamp((paper - qRed(c)) / (paper - grey), 0.0, 1.0);
}

// The length of the grey run through `from` along (dx, dy), with the edge pixels counted by their
// coverage (anti-aliasing), in pixels.
double runLength(const QImage &img, QPoint from, int dx, int dy)
{
    double length = 0.0;
    for (int dir : {-1, 1}) {
        QPoint p = from + (dir > 0 ? QPoint(dx, dy) : QPoint());
        while (img.rect().contains(p)) {
            const double c = squareCoverage(img.pixel(p));
            length += c;
            if (c < 0.999 && c > 0.0) { // an edge pixel ends the run
                break;
            }
            if (c == 0.0)
                break;
            p += dir * QPoint(dx, dy);
        }
    }
    return length;
}

bool isRed(QRgb c)
{
    return qRed(c) > 180 && qGreen(c) < 90 && qBlue(c) < 90;
}

// The mean x (pixels) of red pixels and their first and last rows.
struct RedExtent
{
    double meanX = -1.0;
    int top = -1, bottom = -1;
};
RedExtent redExtent(const QImage &img)
{
    RedExtent e;
    double sum = 0.0;
    long n = 0;
    for (int y = 0; y < img.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(img.constScanLine(y));
        for (int x = 0; x < img.width(); ++x)
            if (isRed(row[x])) {
                sum += x;
                ++n;
                if (e.top < 0)
                    e.top = y;
                e.bottom = y;
            }
    }
    if (n > 0)
        e.meanX = sum / n + 0.5;
    return e;
}

} // namespace

class TstPatternPdf final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        if (!havePoppler())
            kontur::test::skipWholeSuite("pdftoppm and pdfinfo (poppler-utils, in packaging/bootstrap) are not installed");
        QVERIFY(m_dir.isValid());
    }

    void testSquare_data()
    {
        QTest::addColumn<bool>("letter");
        QTest::addRow("A4") << false;
        QTest::addRow("Letter") << true;
    }
    void testSquare()
    {
        QFETCH(bool, letter);
        geo::TilingOptions options;
        options.paper = letter ? geo::kPaperLetter : geo::kPaperA4;
        const QString pdf =
            m_dir.filePath(letter ? QStringLiteral("square-letter.pdf") : QStringLiteral("square-a4.pdf"));
        QVERIFY(writePatternPdf(pdf, pattern120x80(), options, QStringLiteral("Test")).ok());
        const QImage page = rasterize(pdf, 1, m_dir.path());
        QVERIFY(!page.isNull());
        // The page's own size: A4 2480 × 3508 px at 300 dpi (portrait or landscape as the tiling chose).
        const auto plan = planPrint(pattern120x80(), options);
        QVERIFY(plan.ok());
        QCOMPARE(page.width(), qRound(plan->tiling.pageWidth / kMmPerPixel));
        // The square: the first row, from the top, with a run of over 9 cm of its grey.
        QPoint inside(-1, -1);
        for (int y = 0; y < page.height() && inside.y() < 0; ++y) {
            int run = 0;
            for (int x = 0; x < page.width(); ++x) {
                run = squareCoverage(page.pixel(x, y)) > 0.999 ? run + 1 : 0;
                if (run > 90.0 / kMmPerPixel) {
                    // 1 cm inside its corner, above the label in its middle.
                    inside = QPoint(x - run + 1 + int(10.0 / kMmPerPixel), y + int(10.0 / kMmPerPixel));
                    break;
                }
            }
        }
        QVERIFY2(inside.y() >= 0, "no test square on page 1");
        const double width = runLength(page, inside, 1, 0) * kMmPerPixel;
        const double height = runLength(page, inside, 0, 1) * kMmPerPixel;
        qInfo("test square: %.3f mm × %.3f mm", width, height);
        QVERIFY2(std::abs(width - 100.0) <= 0.3, qPrintable(QString::number(width)));
        QVERIFY2(std::abs(height - 100.0) <= 0.3, qPrintable(QString::number(height)));
    }

    void pageCount_data()
    {
        QTest::addColumn<bool>("letter");
        QTest::addColumn<int>("orientation");
        QTest::addColumn<int>("pages"); // by hand (tst_tiling): the tiles and page 1
        QTest::addRow("A4 auto") << false << int(geo::PageOrientation::Auto) << 21 + 1;
        QTest::addRow("A4 landscape") << false << int(geo::PageOrientation::Landscape) << 25 + 1;
        QTest::addRow("Letter auto") << true << int(geo::PageOrientation::Auto) << 25 + 1;
        QTest::addRow("Letter portrait") << true << int(geo::PageOrientation::Portrait) << 28 + 1;
    }
    void pageCount()
    {
        QFETCH(bool, letter);
        QFETCH(int, orientation);
        QFETCH(int, pages);
        geo::TilingOptions options;
        options.paper = letter ? geo::kPaperLetter : geo::kPaperA4;
        options.orientation = static_cast<geo::PageOrientation>(orientation);
        const auto plan = planPrint(pattern120x80(), options);
        QVERIFY(plan.ok());
        QCOMPARE(plan->pdfPageCount(), pages);
        const QString pdf = m_dir.filePath(QStringLiteral("count.pdf"));
        QVERIFY(writePatternPdf(pdf, pattern120x80(), options, QStringLiteral("Count")).ok());
        QCOMPARE(pdfPages(pdf), pages);
    }

    // A red vertical line in the strip pages A1 and A2 share: on A1 at the page's x = margin + its
    // pattern x, on A2 one step (printable width less the overlap) further left; the same rows.
    void acrossPages()
    {
        io::DocumentData doc;
        doc.units = QStringLiteral("mm");
        // The box: x 0 … 300, y 0 … 200 → pattern 310 × 210 mm (5 mm padding), A4 portrait: 2 × 1 pages.
        doc.curves = {line(0, 0, 300, 0, QStringLiteral("#000000")),
                      line(180, 20, 180, 200, QStringLiteral("#ff0000"))};
        geo::TilingOptions options;
        const auto plan = planPrint(doc, options);
        QVERIFY(plan.ok());
        QCOMPARE(plan->tiling.columns, 2);
        QCOMPARE(plan->tiling.rows, 1);
        QVERIFY(!plan->tiling.landscape);
        const QString pdf = m_dir.filePath(QStringLiteral("across.pdf"));
        QVERIFY(writePatternPdf(pdf, doc, options, QStringLiteral("Across")).ok());
        const QImage a1 = rasterize(pdf, 2, m_dir.path());
        const QImage a2 = rasterize(pdf, 3, m_dir.path());
        QVERIFY(!a1.isNull() && !a2.isNull());
        const RedExtent r1 = redExtent(a1), r2 = redExtent(a2);
        QVERIFY2(r1.meanX > 0 && r2.meanX > 0, "the line is missing on a page");
        // Pattern x of the line: 180 − 0 + 5 = 185 mm; A2 starts at 190 − 10 = 180 mm.
        const double x1 = r1.meanX * kMmPerPixel, x2 = r2.meanX * kMmPerPixel;
        qInfo("line at %.3f mm on A1, %.3f mm on A2", x1, x2);
        QVERIFY2(std::abs(x1 - (10.0 + 185.0)) <= 0.2, qPrintable(QString::number(x1)));
        QVERIFY2(std::abs(x2 - (10.0 + 185.0 - 180.0)) <= 0.2, qPrintable(QString::number(x2)));
        QVERIFY(std::abs((x1 - x2) - plan->tiling.stepX()) <= 0.2);
        // Same rows on both (pattern y 5 … 185 → page 15 … 195 mm, plus the round caps).
        QVERIFY(std::abs(r1.top - r2.top) <= 1);
        QVERIFY(std::abs(r1.bottom - r2.bottom) <= 1);
        QVERIFY(std::abs(r1.top * kMmPerPixel - 15.0) <= 0.4);
        QVERIFY(std::abs(r1.bottom * kMmPerPixel - 195.0) <= 0.4);
    }

    void roundTrip()
    {
        io::DocumentData doc = pattern120x80();
        doc.curves[1].visible = false; // kept in the document, not printed
        doc.curves[2].locked = true;
        io::BackgroundRecord b;
        b.file = m_dir.filePath(QStringLiteral("scan.png"));
        b.opacity = 0.5;
        b.scale = 0.1;
        b.calibrated = true;
        b.bx = 100;
        b.distance = 10;
        doc.background = b;
        const QString pdf = m_dir.filePath(QStringLiteral("roundtrip.pdf"));
        QVERIFY(writePatternPdf(pdf, doc, {}, QStringLiteral("Round <trip> & \"back\"")).ok());
        // Qt writes the XMP stream uncompressed: the packet is in the bytes as written.
        QFile f(pdf);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        QVERIFY(bytes.contains("<kontur:document>"));
        QVERIFY(bytes.contains(io::kPdfNamespace));
        const auto back = io::openPdfDocument(pdf);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(back.error().toString()));
        QCOMPARE(back->curves.size(), doc.curves.size());
        QVERIFY(*back == doc);
        // And saved as .kontur, byte for byte what the document saves as.
        QCOMPARE(io::documentToJson(*back), io::documentToJson(doc));
    }

    void notKontur()
    {
        // A PDF of another program (here Qt's, without Kontur's packet) and a file that is no PDF.
        const QString other = m_dir.filePath(QStringLiteral("other.pdf"));
        {
            QPdfWriter writer(other);
            QPainter p(&writer);
            p.drawText(QPointF(100, 100), QStringLiteral("Hello"));
        }
        const auto a = io::openPdfDocument(other);
        QVERIFY(!a.ok());
        QCOMPARE(a.error().code, io::ErrorCode::NotKonturPdf);
        const auto b = io::documentFromPdf("not a pdf at all");
        QVERIFY(!b.ok());
        QCOMPARE(b.error().code, io::ErrorCode::NotKonturPdf);
        // A damaged packet.
        const auto c = io::documentFromPdf("%PDF-1.4 urn:kontur:pattern-pdf:1 <kontur:document>@@@</kontur:document>");
        QVERIFY(!c.ok());
        QCOMPARE(c.error().code, io::ErrorCode::NotKonturPdf);
        QCOMPARE(QString::fromLatin1(io::codeName(c.error().code)), QStringLiteral("not-kontur-pdf"));
    }

    void nothingToPrint()
    {
        io::DocumentData doc = pattern120x80();
        for (auto &c : doc.curves)
            c.visible = false;
        const auto plan = planPrint(doc, {});
        QVERIFY(!plan.ok());
        QCOMPARE(plan.error().code, io::ErrorCode::NoPaths);
        QVERIFY(!writePatternPdf(m_dir.filePath(QStringLiteral("none.pdf")), doc, {}, {}).ok());
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("none.pdf"))));
        // px: 96 per inch, so 96 px print as 25.4 mm.
        QCOMPARE(mmPerUnit(QStringLiteral("px")), 25.4 / 96.0);
        QCOMPARE(mmPerUnit(QStringLiteral("pt")), 25.4 / 72.0);
    }

    // The app's way: a curve of every kind printed through PrintController opens again through
    // DocumentFiles (Open: the same document; Import: its curves added); another PDF is refused
    // with the translated reason; nothing visible leaves the dialog with its reason and no pages.
    void appOpensWhatItPrints()
    {
        QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath()));
        EditController editor;
        for (int k = 0; k < kKindCount; ++k) {
            const auto kind = static_cast<CurveKind>(k);
            std::vector<geo::Point> points;
            const int n = traitsOf(kind).placementCount > 0 ? traitsOf(kind).placementCount : 6;
            for (int i = 0; i < n; ++i)
                points.emplace_back(20.0 * i, 10.0 * std::sin(i) + 0.1 * k);
            QVERIFY2(editor.placement()->createFromCoordinates(k, kontur::test::rowsOf(points)),
                     qPrintable(editor.messageText()));
        }
        // In mm (a new document starts in px).
        editor.replaceDocument(std::vector<Curve>(editor.document()->curves()), Background{}, QStringLiteral("mm"),
                               true);
        QCOMPARE(editor.document()->units(), QStringLiteral("mm"));
        PrintController printer;
        printer.setEditor(&editor);
        QVERIFY(printer.ready());
        QCOMPARE(printer.pdfPageCount(), printer.pageCount() + 1);
        const QString pdf = m_dir.filePath(QStringLiteral("every-kind.pdf"));
        QVERIFY(printer.print(QUrl::fromLocalFile(pdf)));
        QCOMPARE(editor.message().id, Message::FileSaved);
        QCOMPARE(pdfPages(pdf), printer.pdfPageCount());
        const io::DocumentData printed = toDocumentData(*editor.document());

        EditController other;
        kontur::DocumentFiles files;
        files.setEditor(&other);
        QVERIFY(files.open(QUrl::fromLocalFile(pdf)));
        QVERIFY(toDocumentData(*other.document()) == printed);
        QVERIFY(files.fileUrl().isEmpty()); // Save asks for a .kontur name
        QVERIFY(files.importFile(QUrl::fromLocalFile(pdf), int(CurveKind::Composite)));
        QCOMPARE(other.document()->curveCount(), 2 * kKindCount);

        const QString plain = m_dir.filePath(QStringLiteral("plain-app.pdf"));
        {
            QPdfWriter writer(plain);
            QPainter painter(&writer);
            painter.drawLine(0, 0, 100, 100);
        }
        QVERIFY(!files.open(QUrl::fromLocalFile(plain)));
        QCOMPARE(other.message().id, Message::FileReadError);
        QVERIFY2(other.messageText().contains(QStringLiteral("not printed by Kontur")),
                 qPrintable(other.messageText()));
        QCOMPARE(other.document()->curveCount(), 2 * kKindCount);

        for (int row = 0; row < editor.document()->curveCount(); ++row)
            QVERIFY(editor.commands()->setCurveVisible(kontur::test::idAt(editor, row), false));
        printer.refresh();
        QVERIFY(!printer.ready());
        QCOMPARE(printer.pageCount(), 0);
        QCOMPARE(printer.problem().text(), QStringLiteral("Nothing to print: no curve is visible."));
    }

    // kontur-cli convert doc.kontur out.pdf (Letter, 15 mm) writes the same tiling, and
    // convert out.pdf back.kontur gives the document again.
    void cli()
    {
        const QString in = m_dir.filePath(QStringLiteral("cli.kontur"));
        const QString pdf = m_dir.filePath(QStringLiteral("cli.pdf"));
        const QString back = m_dir.filePath(QStringLiteral("back.kontur"));
        QVERIFY(io::saveDocument(in, pattern120x80()).ok());
        QProcess p;
        p.start(QStringLiteral(KONTUR_CLI),
                {QStringLiteral("convert"), in, pdf, QStringLiteral("--paper"), QStringLiteral("letter"),
                 QStringLiteral("--overlap"), QStringLiteral("15"), QStringLiteral("--orientation"),
                 QStringLiteral("portrait")});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        geo::TilingOptions options;
        options.paper = geo::kPaperLetter;
        options.overlap = 15.0;
        options.orientation = geo::PageOrientation::Portrait;
        const auto plan = planPrint(pattern120x80(), options);
        QVERIFY(plan.ok());
        QCOMPARE(pdfPages(pdf), plan->pdfPageCount());
        p.start(QStringLiteral(KONTUR_CLI), {QStringLiteral("convert"), pdf, back});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const auto read = io::openDocument(back);
        QVERIFY(read.ok());
        QVERIFY(*read == pattern120x80());
        // A PDF Kontur did not write: exit 1 with the code.
        const QString other = m_dir.filePath(QStringLiteral("plain.pdf"));
        {
            QPdfWriter writer(other);
            QPainter painter(&writer);
            painter.drawLine(0, 0, 100, 100);
        }
        p.start(QStringLiteral(KONTUR_CLI), {QStringLiteral("convert"), other, back});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 1);
        QVERIFY(p.readAllStandardError().contains("not-kontur-pdf"));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_MAIN(TstPatternPdf)
#include "tst_patternpdf.moc"
