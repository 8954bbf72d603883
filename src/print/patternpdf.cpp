// The pattern PDF (see patternpdf.h). Coordinates: the pattern in mm with y down, its origin
// kPrintPaddingMm left of and above the curves' box; a page in mm from its top-left corner (the
// painter is scaled from the writer's dots to mm); text is drawn in the writer's own dots so that
// point sizes mean points on paper.
#include "print/patternpdf.h"

#include "io/records.h"

#include "io/pdf.h"
#include "io/shapes.h"
#include "print/printedpiece.h"
#include "text/numbertext.h"

#include <QCoreApplication>
#include <QLocale>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QSaveFile>

#include <algorithm>
#include <cmath>

namespace kontur {

double mmPerUnit(const QString &units)
{
    return io::millimetresPerUnit(units, true);
}

namespace {

io::Error printError(io::ErrorCode code, const QString &message)
{
    io::Error e;
    e.code = code;
    e.message = message;
    return e;
}

struct PrintedCurve
{
    QPainterPath path; // pattern mm
    QColor color;
};

// Segments of degree above 3 have no PDF form; they are drawn through this many points each, far
// below the width of a printed line for the curves Kontur makes (degree ≤ 100 Bézier curves).
constexpr int kHighDegreeSamples = 256;

QPainterPath patternPath(const geo::PiecewiseBezier &shape, const PrintPlan &plan)
{
    const double k = plan.mmPerUnit;
    const auto map = [&](const geo::Point &p) {
        return QPointF((p.x() - plan.minX) * k + kPrintPaddingMm, (plan.maxY - p.y()) * k + kPrintPaddingMm);
    };
    QPainterPath path;
    bool started = false;
    for (const geo::Bezier &b : shape.segments()) {
        const auto &c = b.controlPoints();
        if (!started || path.currentPosition() != map(c.front()))
            path.moveTo(map(c.front()));
        started = true;
        switch (b.degree()) {
        case 1:
            path.lineTo(map(c[1]));
            break;
        case 2:
            path.quadTo(map(c[1]), map(c[2]));
            break;
        case 3:
            path.cubicTo(map(c[1]), map(c[2]), map(c[3]));
            break;
        default:
            for (int i = 1; i <= kHighDegreeSamples; ++i)
                path.lineTo(map(b.eval(static_cast<double>(i) / kHighDegreeSamples)));
            break;
        }
    }
    if (shape.isClosed())
        path.closeSubpath();
    return path;
}

std::vector<PrintedCurve> printedCurves(const io::DocumentData &doc, const PrintPlan &plan)
{
    std::vector<PrintedCurve> out;
    for (const io::CurveRecord &c : doc.curves) {
        if (!c.visible)
            continue;
        auto shape = io::curveShape(c);
        if (shape && !shape->isEmpty())
            out.push_back({patternPath(*shape, plan), QColor(c.color)});
    }
    return out;
}

// Draws text in the writer's dots (so that point sizes are points on paper) into a rectangle in mm.
class Page final
{
public:
    Page(QPainter &painter, double dotsPerMm)
        : m_p(painter)
        , m_dpmm(dotsPerMm)
    {
    }
    void text(const QRectF &mm, int flags, const QString &text, double points, bool bold = false,
              const QColor &color = Qt::black)
    {
        m_p.save();
        m_p.resetTransform();
        QFont font = m_p.font();
        font.setPointSizeF(points);
        font.setBold(bold);
        m_p.setFont(font);
        m_p.setPen(color);
        m_p.drawText(QRectF(mm.topLeft() * m_dpmm, mm.size() * m_dpmm), flags, text);
        m_p.restore();
    }
    // The rectangle (mm) a text needs at most `width` mm wide.
    QRectF measure(double width, int flags, const QString &text, double points, bool bold = false)
    {
        m_p.save();
        m_p.resetTransform();
        QFont font = m_p.font();
        font.setPointSizeF(points);
        font.setBold(bold);
        m_p.setFont(font);
        const QRectF r = m_p.boundingRect(QRectF(0, 0, width * m_dpmm, 1e6), flags, text);
        m_p.restore();
        return QRectF(r.topLeft() / m_dpmm, r.size() / m_dpmm);
    }

private:
    QPainter &m_p;
    double m_dpmm;
};

QPen mmPen(const QColor &color, double widthMm, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(color, widthMm, style, Qt::RoundCap, Qt::RoundJoin);
    return pen;
}

const QColor kGuide(90, 90, 90);

// An alignment mark: a circle with a cross, the same on both pages that share it.
void drawMark(QPainter &p, const QPointF &at)
{
    constexpr double radius = 3.0, arm = 5.0;
    p.setPen(mmPen(kGuide, 0.15));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(at, radius, radius);
    p.drawLine(at - QPointF(arm, 0), at + QPointF(arm, 0));
    p.drawLine(at - QPointF(0, arm), at + QPointF(0, arm));
}

// The pieces' marks (printedpiece.h) on a tile whose painter is translated to the pattern; texts in
// page millimetres (`offset`: pattern to page).
void drawPieces(QPainter &p, Page &page, const std::vector<PrintedPiece> &pieces, const QPointF &offset)
{
    for (const PrintedPiece &piece : pieces) {
        p.setBrush(Qt::NoBrush);
        p.setPen(mmPen(Qt::black, kPrintLineWidthMm));
        p.drawPath(piece.marks);
        if (!piece.fold.isEmpty()) {
            p.setPen(mmPen(Qt::black, kPrintLineWidthMm, Qt::DashDotLine));
            p.drawPath(piece.fold);
            const QPointF at = piece.foldTextAt + offset;
            page.text(QRectF(at - QPointF(40, 4), QSizeF(80, 8)), Qt::AlignCenter, placeOnFoldText(), 10, true);
        }
        const QPointF at = piece.labelAt + offset;
        page.text(QRectF(at - QPointF(45, 15), QSizeF(90, 30)), Qt::AlignCenter, piece.label, 11, true);
        for (const PrintedPiece::SeamLabel &seam : piece.seamLabels) {
            const QPointF c = seam.at + offset;
            page.text(QRectF(c - QPointF(15, 3), QSizeF(30, 6)), Qt::AlignCenter, seam.text, 8);
        }
    }
}

void drawTile(QPainter &p, Page &page, const PrintPlan &plan, const std::vector<PrintedCurve> &curves,
              const std::vector<PrintedPiece> &pieces, int row, int column)
{
    const geo::Tiling &t = plan.tiling;
    const geo::TileRect r = t.tile(row, column);
    const QRectF cell(t.margin, t.margin, t.cellWidth, t.cellHeight);

    p.save();
    p.setClipRect(cell);
    p.translate(t.margin - r.x, t.margin - r.y);
    p.setBrush(Qt::NoBrush);
    for (const PrintedCurve &c : curves) {
        p.setPen(mmPen(c.color, kPrintLineWidthMm));
        p.drawPath(c.path);
    }
    drawPieces(p, page, pieces, QPointF(t.margin - r.x, t.margin - r.y));
    // Marks in the strips neighbours share (pattern coordinates, so both pages print them at the same
    // place of the pattern), and dashed lines where a right or lower neighbour's cut edge is laid.
    const double half = t.overlap / 2.0;
    for (int c : {column, column + 1}) {
        if (c < 1 || c >= t.columns)
            continue;
        const double x = c * t.stepX() + half;
        drawMark(p, {x, r.y + 0.25 * t.cellHeight});
        drawMark(p, {x, r.y + 0.75 * t.cellHeight});
    }
    for (int rr : {row, row + 1}) {
        if (rr < 1 || rr >= t.rows)
            continue;
        const double y = rr * t.stepY() + half;
        drawMark(p, {r.x + 0.25 * t.cellWidth, y});
        drawMark(p, {r.x + 0.75 * t.cellWidth, y});
    }
    p.setPen(mmPen(kGuide, 0.2, Qt::DashLine));
    if (column + 1 < t.columns)
        p.drawLine(QPointF((column + 1) * t.stepX(), r.y), QPointF((column + 1) * t.stepX(), r.y + r.height));
    if (row + 1 < t.rows)
        p.drawLine(QPointF(r.x, (row + 1) * t.stepY()), QPointF(r.x + r.width, (row + 1) * t.stepY()));
    p.restore();

    // The cut line: the edge of the printed area.
    p.setPen(mmPen(kGuide, 0.15));
    p.setBrush(Qt::NoBrush);
    p.drawRect(cell);
    // The page's name and its neighbours' in the top margin (cut away or hidden under a neighbour once
    // taped, so the pattern stays clean); printers reach 5 mm from the edge.
    const auto name = [](int rr, int cc) { return QString::fromStdString(geo::tileLabel(rr, cc)); };
    QStringList neighbours;
    if (row > 0)
        neighbours << QStringLiteral("↑ ") + name(row - 1, column);
    if (column > 0)
        neighbours << QStringLiteral("← ") + name(row, column - 1);
    if (column + 1 < t.columns)
        neighbours << QStringLiteral("→ ") + name(row, column + 1);
    if (row + 1 < t.rows)
        neighbours << QStringLiteral("↓ ") + name(row + 1, column);
    const QRectF band(t.margin, 4.5, t.cellWidth, t.margin - 5.0);
    page.text(band, Qt::AlignLeft | Qt::AlignBottom, name(row, column), 12, true);
    page.text(band, Qt::AlignRight | Qt::AlignBottom, neighbours.join(QStringLiteral("   ")), 8, false, kGuide);
}

// Page 1: title, instructions, the 10 cm test square (and a 4 in bar on Letter), the overview.
void drawFirstPage(QPainter &p, Page &page, const PrintPlan &plan, const std::vector<PrintedCurve> &curves,
                   const QString &title, const QString &units, bool letter)
{
    const geo::Tiling &t = plan.tiling;
    const QRectF cell(t.margin, t.margin, t.cellWidth, t.cellHeight);
    const int textFlags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap;
    double y = cell.top();
    const QRectF titleBox = page.measure(cell.width(), textFlags, title, 14, true);
    page.text(QRectF(cell.left(), y, cell.width(), titleBox.height()), textFlags, title, 14, true);
    y += titleBox.height() + 1.5;

    QString info = QCoreApplication::translate(
        "kontur::print", "Print at 100 % (actual size, not “fit to page”). The grey square must measure 10 cm "
                         "each way.");
    info += QLatin1Char(' ') +
            //: %1 is the number of pages, %2 × %3 their rows and columns, %4 the paper (A4 or Letter),
            //: %5 the orientation (“portrait” or “landscape”, the next messages), %6 a number of millimetres.
            QCoreApplication::translate("kontur::print",
                                        "Pages after this one: %1 (rows × columns: %2 × %3), %4 %5, overlap %6 mm.")
                .arg(t.pageCount())
                .arg(t.rows)
                .arg(t.columns)
                .arg(letter ? QStringLiteral("Letter") : QStringLiteral("A4"),
                     //: Page orientation, inserted after the paper name in the sentence above (A4 landscape).
                     t.landscape ? QCoreApplication::translate("kontur::print", "landscape")
                                 //: Page orientation, inserted after the paper name in the sentence above (A4
                                 //: portrait).
                                 : QCoreApplication::translate("kontur::print", "portrait"),
                     significantNumber(t.overlap, 6));
    info += QLatin1Char(' ') +
            QCoreApplication::translate("kontur::print",
                                        "Cut each page along the grey line at its left and top, lay it over its "
                                        "neighbours up to their dashed lines, match the circles and tape.");
    if (units == QLatin1String("px"))
        info += QLatin1Char(' ') +
                QCoreApplication::translate("kontur::print", "The drawing is in px: printed at 96 px per inch.");
    const QRectF infoBox = page.measure(cell.width(), textFlags, info, 9);
    page.text(QRectF(cell.left(), y, cell.width(), infoBox.height()), textFlags, info, 9);
    y += infoBox.height() + 4.0;

    // The test square: filled, no outline, so its printed size is its true size.
    const QRectF square(cell.left(), y, 100.0, 100.0);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(190, 190, 190));
    p.drawRect(square);
    page.text(square, Qt::AlignCenter, QCoreApplication::translate("kontur::print", "10 cm"), 16, true);
    double below = square.bottom();
    if (letter) {
        const QRectF bar(cell.left(), square.bottom() + 4.0, 101.6, 4.0);
        p.drawRect(bar);
        page.text(QRectF(bar.left(), bar.bottom() + 0.5, bar.width(), 6.0), Qt::AlignLeft | Qt::AlignTop,
                  QCoreApplication::translate("kontur::print", "4 in"), 9);
        below = bar.bottom() + 6.0;
    }

    // The overview, beside or below the square, whichever shows it larger.
    const QRectF right(square.right() + 8.0, y, cell.right() - square.right() - 8.0, cell.bottom() - y);
    const QRectF under(cell.left(), below + 6.0, cell.width(), cell.bottom() - below - 6.0);
    // The overview shows every page whole: the tiled area reaches past the pattern.
    const double tiledWidth = (t.columns - 1) * t.stepX() + t.cellWidth;
    const double tiledHeight = (t.rows - 1) * t.stepY() + t.cellHeight;
    const auto scaleIn = [&](const QRectF &area) {
        return std::min(area.width() / tiledWidth, area.height() / tiledHeight);
    };
    const QRectF area = scaleIn(right) > scaleIn(under) ? right : under;
    const double s = scaleIn(area);
    if (!(s > 0.0) || !std::isfinite(s))
        return;
    const QPointF origin(area.left() + (area.width() - s * tiledWidth) / 2.0, area.top());
    p.save();
    p.translate(origin);
    p.scale(s, s);
    p.setBrush(Qt::NoBrush);
    p.setPen(mmPen(QColor(150, 180, 220), 0.2 / s));
    for (int rr = 0; rr < t.rows; ++rr)
        for (int cc = 0; cc < t.columns; ++cc) {
            const geo::TileRect r = t.tile(rr, cc);
            p.drawRect(QRectF(r.x, r.y, r.width, r.height));
        }
    for (const PrintedCurve &c : curves) {
        p.setPen(mmPen(c.color, 0.25 / s));
        p.drawPath(c.path);
    }
    p.restore();
    // Each page's label in the part of the overview only it prints.
    const double pt = std::clamp(std::min(t.stepX(), t.stepY()) * s * 0.3 * 72.0 / 25.4, 4.0, 12.0);
    for (int rr = 0; rr < t.rows; ++rr)
        for (int cc = 0; cc < t.columns; ++cc) {
            const geo::TileRect r = t.tile(rr, cc);
            const QRectF own(origin + QPointF(r.x, r.y) * s, QSizeF(t.stepX(), t.stepY()) * s);
            page.text(own, Qt::AlignCenter, QString::fromStdString(geo::tileLabel(rr, cc)), pt, true,
                      QColor(40, 80, 150));
        }
}

} // namespace

io::Result<PrintPlan> planPrint(const io::DocumentData &doc, const geo::TilingOptions &options)
{
    PrintPlan plan;
    plan.mmPerUnit = mmPerUnit(doc.units);
    if (!(plan.mmPerUnit > 0.0))
        return printError(io::ErrorCode::InvalidValue, QStringLiteral("unknown units \"%1\"").arg(doc.units));
    geo::Box box;
    for (std::size_t i = 0; i < doc.curves.size(); ++i) {
        const io::CurveRecord &c = doc.curves[i];
        if (!c.visible)
            continue;
        auto shape = io::curveShape(c);
        if (!shape) {
            io::Error e = shape.error();
            e.path = QStringLiteral("curves[%1]").arg(i);
            return e;
        }
        if (!shape->isEmpty())
            box.extend(shape->boundingBox());
    }
    if (box.isEmpty())
        return printError(io::ErrorCode::NoPaths,
                          QStringLiteral("nothing to print: the document has no visible curve"));
    plan.minX = box.min().x();
    plan.maxY = box.max().y();
    const double width = box.sizes().x() * plan.mmPerUnit + 2.0 * kPrintPaddingMm;
    const double height = box.sizes().y() * plan.mmPerUnit + 2.0 * kPrintPaddingMm;
    auto tiling = geo::computeTiling(width, height, options);
    if (!tiling)
        return printError(io::ErrorCode::InvalidValue, QString::fromStdString(tiling.error().message));
    plan.tiling = *tiling;
    return plan;
}

io::Result<io::Ok> writePatternPdf(const QString &path, const io::DocumentData &doc, const geo::TilingOptions &options,
                                   const QString &title)
{
    auto plan = planPrint(doc, options);
    if (!plan) {
        io::Error e = plan.error();
        e.file = path;
        return e;
    }
    const geo::Tiling &t = plan->tiling;
    const bool letter =
        options.paper.width == geo::kPaperLetter.width && options.paper.height == geo::kPaperLetter.height;
    const bool a4 = options.paper.width == geo::kPaperA4.width && options.paper.height == geo::kPaperA4.height;
    const QPageSize size = a4 ? QPageSize(QPageSize::A4)
                           : letter
                               ? QPageSize(QPageSize::Letter)
                               : QPageSize(QSizeF(options.paper.width, options.paper.height), QPageSize::Millimeter);
    const auto writeFailed = [&](const QString &why) {
        io::Error e;
        e.code = io::ErrorCode::CannotWrite;
        e.file = path;
        e.message = why;
        return e;
    };

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return writeFailed(file.errorString());
    {
        QPdfWriter writer(&file);
        writer.setResolution(1200);
        writer.setCreator(QStringLiteral("Kontur"));
        writer.setTitle(title);
        writer.setDocumentXmpMetadata(io::pdfXmpPacket(doc, title, path));
        writer.setPageLayout(
            QPageLayout(size, t.landscape ? QPageLayout::Landscape : QPageLayout::Portrait, QMarginsF(0, 0, 0, 0)));
        QPainter painter;
        if (!painter.begin(&writer)) {
            file.cancelWriting();
            return writeFailed(QStringLiteral("the PDF could not be started"));
        }
        const double dotsPerMm = writer.resolution() / 25.4;
        painter.setRenderHint(QPainter::Antialiasing);
        painter.scale(dotsPerMm, dotsPerMm);
        Page page(painter, dotsPerMm);
        const std::vector<PrintedCurve> curves = printedCurves(doc, *plan);
        const double k = plan->mmPerUnit;
        const std::vector<PrintedPiece> pieces = printedPieces(doc.curves, doc.units, [&](const geo::Point &q) {
            return QPointF((q.x() - plan->minX) * k + kPrintPaddingMm, (plan->maxY - q.y()) * k + kPrintPaddingMm);
        });
        drawFirstPage(painter, page, *plan, curves, title, doc.units, letter);
        for (int row = 0; row < t.rows; ++row)
            for (int column = 0; column < t.columns; ++column) {
                writer.newPage();
                drawTile(painter, page, *plan, curves, pieces, row, column);
            }
        painter.end();
    }
    if (!file.commit())
        return writeFailed(file.errorString());
    return io::Ok{};
}

} // namespace kontur
