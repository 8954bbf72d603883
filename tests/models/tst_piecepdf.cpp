// A pattern piece's marks on the tiled PDF, measured on paper (pdftoppm at 300 dpi): the grainline
// arrow, notches across the cut line (a slit a line, a V two arms), a drill hole's ring, "Place on
// fold" beside the fold, the label with the size and "Cut 2". Each is looked for where the piece's
// marks put it, and is absent from the same piece printed without marks. A piece whose hem allowance
// (30 mm) differs from the others' (10 mm) gets "3 cm" printed in the hem's allowance, and nothing
// beside the seams of the allowance's own width.
#include "io/piece.h"
#include "io/seam.h"
#include "print/patternpdf.h"

#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace kontur;

namespace {

constexpr double kDpi = 300.0;
constexpr double kMmPerPixel = 25.4 / kDpi;

// A 150 × 200 mm rectangle, counter-clockwise from the origin, straight Bézier sides.
io::DocumentData piece(bool withMarks)
{
    io::DocumentData doc;
    doc.units = QStringLiteral("mm");
    io::CurveRecord c;
    c.kind = QStringLiteral("composite");
    c.name = QStringLiteral("Front");
    c.closed = true;
    const std::vector<geo::Point> corners{{0, 0}, {150, 0}, {150, 200}, {0, 200}};
    for (std::size_t k = 0; k < 4; ++k) {
        const geo::Point a = corners[k], b = corners[(k + 1) % 4];
        c.points.insert(c.points.end(), {a, a + (b - a) / 3, a + (b - a) * 2 / 3});
        c.nodeTypes.push_back(QStringLiteral("corner"));
    }
    if (withMarks) {
        io::PieceMarks m;
        m.size = QStringLiteral("38");
        m.quantity = 2;
        m.grainline = io::Segment{{75, 30}, {75, 170}};
        m.fold = io::Segment{{0, 200}, {0, 0}};
        m.notches = {{75, io::NotchKind::Slit, 0}, {250, io::NotchKind::V, 0}};
        m.drillHoles = {{40, 150}};
        c.settings.insert(QLatin1String(io::kPieceKey), io::pieceToJson(m));
    }
    doc.curves.push_back(c);
    return doc;
}

// The rectangle with a 10 mm allowance linked to it (its shape the rectangle grown by 30 at the hem
// and 10 elsewhere, as the app computes it when the hem is 30); `hem` the hem's own width, if any.
io::DocumentData withAllowance(std::optional<double> hem)
{
    io::DocumentData doc = piece(false);
    io::PieceMarks m;
    if (hem)
        m.seamWidths = {hem};
    doc.curves[0].settings.insert(QLatin1String(io::kPieceKey), io::pieceToJson(m));
    io::CurveRecord a;
    a.kind = QStringLiteral("composite");
    a.name = QStringLiteral("Front allowance");
    a.closed = true;
    const std::vector<geo::Point> corners{{-10, -30}, {160, -30}, {160, 210}, {-10, 210}};
    for (std::size_t k = 0; k < 4; ++k) {
        const geo::Point p = corners[k], q = corners[(k + 1) % 4];
        a.points.insert(a.points.end(), {p, p + (q - p) / 3, p + (q - p) * 2 / 3});
        a.nodeTypes.push_back(QStringLiteral("corner"));
    }
    io::SeamSettings seam;
    seam.source = 0;
    seam.options = io::defaultSeamOptions(QStringLiteral("mm"));
    a.settings.insert(QLatin1String(io::kSeamKey), io::seamToJson(seam));
    doc.curves.push_back(a);
    return doc;
}

QImage rasterize(const QString &pdf, int page, const QString &dir)
{
    const QString prefix = dir + QStringLiteral("/piece%1").arg(page);
    QProcess p;
    p.start(QStringLiteral("pdftoppm"), {QStringLiteral("-r"), QString::number(kDpi), QStringLiteral("-f"),
                                         QString::number(page), QStringLiteral("-l"), QString::number(page),
                                         QStringLiteral("-png"), QStringLiteral("-singlefile"), pdf, prefix});
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return {};
    return QImage(prefix + QStringLiteral(".png")).convertToFormat(QImage::Format_RGB32);
}

} // namespace

class TestPiecePdf final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void marksOnPaper()
    {
        if (QStandardPaths::findExecutable(QStringLiteral("pdftoppm")).isEmpty())
            QSKIP("pdftoppm (poppler-utils, in packaging/bootstrap) is not installed");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        geo::TilingOptions options;
        const auto plan = planPrint(piece(true), options);
        QVERIFY(plan.ok());
        QCOMPARE(plan->tiling.pageCount(), 1);
        QImage pages[2];
        for (bool marks : {false, true}) {
            const QString pdf = dir.filePath(marks ? QStringLiteral("marks.pdf") : QStringLiteral("plain.pdf"));
            QVERIFY(writePatternPdf(pdf, piece(marks), options, QStringLiteral("Front")).ok());
            pages[marks ? 1 : 0] = rasterize(pdf, 2, dir.path());
            QVERIFY(!pages[marks ? 1 : 0].isNull());
        }
        // A document point (mm, y up) on the page: the tile's margin, the padding, y down.
        const double margin = plan->tiling.margin;
        const auto pixel = [&](double x, double y) {
            return QPoint(qRound((margin + x - plan->minX + kPrintPaddingMm) / kMmPerPixel),
                          qRound((margin + plan->maxY - y + kPrintPaddingMm) / kMmPerPixel));
        };
        // Dark anywhere within `r` mm of (x, y).
        const auto dark = [&](const QImage &img, double x, double y, double r = 0.15) {
            const QPoint c = pixel(x, y);
            const int n = static_cast<int>(std::ceil(r / kMmPerPixel));
            for (int dy = -n; dy <= n; ++dy)
                for (int dx = -n; dx <= n; ++dx)
                    if (img.rect().contains(c + QPoint(dx, dy)) && qGray(img.pixel(c + QPoint(dx, dy))) < 128)
                        return true;
            return false;
        };
        const auto onlyWithMarks = [&](double x, double y, double r, const char *what) {
            QVERIFY2(dark(pages[1], x, y, r), what);
            QVERIFY2(!dark(pages[0], x, y, r), what);
        };
        // The outline is on both.
        QVERIFY(dark(pages[0], 100, 0) && dark(pages[1], 100, 0));
        onlyWithMarks(75, 100, 0.15, "grainline");
        const double s = 2.0 * std::sin(25 * std::numbers::pi / 180), c = 2.0 * std::cos(25 * std::numbers::pi / 180);
        onlyWithMarks(75 - s, 170 - c, 0.15, "grainline arrow head, left");
        onlyWithMarks(75 + s, 170 - c, 0.15, "grainline arrow head, right");
        onlyWithMarks(75, -1.0, 0.15, "slit notch outside the cut line");
        onlyWithMarks(75, 3.0, 0.15, "slit notch inside");
        QVERIFY2(!dark(pages[1], 60, -1.0), "nothing outside the cut line but the notch");
        onlyWithMarks(151.9, 98.05, 0.2, "V notch, one arm");
        onlyWithMarks(151.9, 101.95, 0.2, "V notch, the other arm");
        QVERIFY2(!dark(pages[1], 151.5, 100.0, 0.1), "a V is open outside the cut line");
        onlyWithMarks(40 + 1.5 / std::sqrt(2.0), 150 + 1.5 / std::sqrt(2.0), 0.15, "drill hole ring");
        onlyWithMarks(42.5, 150, 0.1, "drill hole cross");
        // Texts: some ink where each is centred.
        onlyWithMarks(8, 100, 3.0, "Place on fold");
        onlyWithMarks(100, 100, 4.0, "the label");
    }

    // The hem's width (30 mm, the allowance's own 10) printed as "3 cm" halfway across the hem's
    // allowance under the hem's middle; the same shapes without the hem's own width print none.
    void seamWidthsOnPaper()
    {
        if (QStandardPaths::findExecutable(QStringLiteral("pdftoppm")).isEmpty())
            QSKIP("pdftoppm (poppler-utils, in packaging/bootstrap) is not installed");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        geo::TilingOptions options;
        const auto plan = planPrint(withAllowance(30.0), options);
        QVERIFY(plan.ok());
        QCOMPARE(plan->tiling.pageCount(), 1);
        QImage pages[2];
        for (bool own : {false, true}) {
            const QString pdf = dir.filePath(own ? QStringLiteral("own.pdf") : QStringLiteral("same.pdf"));
            const io::DocumentData doc = own ? withAllowance(30.0) : withAllowance(std::nullopt);
            QVERIFY(writePatternPdf(pdf, doc, options, QStringLiteral("Front")).ok());
            pages[own ? 1 : 0] = rasterize(pdf, 2, dir.path());
            QVERIFY(!pages[own ? 1 : 0].isNull());
            if (own && !QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty()) {
                QProcess p;
                p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
                QVERIFY(p.waitForFinished(120000));
                const QString text = QString::fromUtf8(p.readAllStandardOutput());
                QVERIFY2(text.count(QStringLiteral("3 cm")) == 1, qPrintable(text));
                QVERIFY2(!text.contains(QStringLiteral("1 cm")), qPrintable(text));
            }
        }
        const auto inkNear = [&](const QImage &img, double x, double y, double r) {
            const double margin = plan->tiling.margin;
            const QPoint c(qRound((margin + x - plan->minX + kPrintPaddingMm) / kMmPerPixel),
                           qRound((margin + plan->maxY - y + kPrintPaddingMm) / kMmPerPixel));
            const int n = static_cast<int>(std::ceil(r / kMmPerPixel));
            int dark = 0;
            for (int dy = -n; dy <= n; ++dy)
                for (int dx = -n; dx <= n; ++dx)
                    if (img.rect().contains(c + QPoint(dx, dy)) && qGray(img.pixel(c + QPoint(dx, dy))) < 128)
                        ++dark;
            return dark;
        };
        // Both print the outline and the allowance (30 below the hem in both).
        QVERIFY(inkNear(pages[0], 75, -30, 0.2) > 0 && inkNear(pages[1], 75, -30, 0.2) > 0);
        QVERIFY2(inkNear(pages[1], 75, -15, 3.0) > 10, "the hem's width");
        QCOMPARE(inkNear(pages[0], 75, -15, 3.0), 0);
        // Nothing beside the sides and the top, whose width is the allowance's own.
        for (const QPointF &p : {QPointF(155, 100), QPointF(75, 205), QPointF(-5, 100)})
            QCOMPARE(inkNear(pages[1], p.x(), p.y(), 2.0), 0);
    }
};

QTEST_MAIN(TestPiecePdf)
#include "tst_piecepdf.moc"
