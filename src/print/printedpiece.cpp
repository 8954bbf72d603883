// A piece's marks on the pattern PDF (see printedpiece.h).
#include "print/printedpiece.h"

#include "geometry/arclength.h"
#include "geometry/seams.h"
#include "io/piece.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>

#include <cmath>
#include <numbers>

namespace kontur {

namespace {

QPointF unit(const QPointF &v)
{
    const double n = std::hypot(v.x(), v.y());
    return n > 0 ? v / n : QPointF(1, 0);
}

QPointF turned(const QPointF &v, double degrees)
{
    const double r = degrees * std::numbers::pi / 180.0;
    return {v.x() * std::cos(r) - v.y() * std::sin(r), v.x() * std::sin(r) + v.y() * std::cos(r)};
}

void arrowHead(QPainterPath &path, const QPointF &tip, const QPointF &back)
{
    constexpr double length = 4.0;
    const QPointF d = unit(back - tip) * length;
    path.moveTo(tip + turned(d, 25));
    path.lineTo(tip);
    path.lineTo(tip + turned(d, -25));
}

// A width as a pattern prints it: to a hundredth, without trailing zeros (3, 1.25, 0.33), in the UI
// language's format.
QString shortNumber(double value)
{
    return QLocale().toString(std::round(value * 100.0) / 100.0, 'g', 12);
}

// The labels of the seams whose width differs from the allowance's own `width`.
std::vector<PrintedPiece::SeamLabel> seamLabels(const geo::PiecewiseBezier &own, const io::PieceMarks &marks,
                                                double width, const QString &units,
                                                const std::function<QPointF(const geo::Point &)> &map)
{
    std::vector<PrintedPiece::SeamLabel> out;
    const std::vector<geo::SeamSpan> seams = geo::seamSpans(own);
    std::vector<double> starts; // the arc length at each segment's start
    double s = 0.0;
    for (const geo::Bezier &b : own.segments()) {
        starts.push_back(s);
        s += geo::arcLength(b, 1e-9);
    }
    const double total = s;
    for (std::size_t k = 0; k < seams.size() && k < marks.seamWidths.size(); ++k) {
        const auto w = marks.seamWidths[k];
        if (!w || std::abs(*w - width) <= 1e-9 * std::max(*w, width))
            continue;
        const geo::SeamSpan &seam = seams[k];
        const int last = (seam.first + seam.count - 1) % own.segmentCount();
        double end = starts[static_cast<std::size_t>(last)] +
                     geo::arcLength(own.segments()[static_cast<std::size_t>(last)], 1e-9);
        const double begin = starts[static_cast<std::size_t>(seam.first)];
        if (end < begin)
            end += total; // the seam runs on through the curve's start
        const io::CurvePlace place = io::placeAtLength(own, (begin + end) / 2);
        const geo::Point inward = io::notchDirection(own, place, 0.0);
        out.push_back({map(geo::Point(place.point - inward * (*w / 2))), seamWidthText(*w, units)});
    }
    return out;
}

} // namespace

QString seamWidthText(double width, const QString &units)
{
    const double perCm = io::unitsPerCentimetre(units);
    if (units == QLatin1String("in"))
        //: A seam's allowance width printed beside it on the pattern, in inches.
        return QCoreApplication::translate("kontur::print", "%1 in").arg(shortNumber(width));
    if (perCm > 0)
        //: A seam's allowance width printed beside it on the pattern, in centimetres ("3 cm").
        return QCoreApplication::translate("kontur::print", "%1 cm").arg(shortNumber(width / perCm));
    return shortNumber(width);
}

QString placeOnFoldText()
{
    //: Printed along a pattern piece's fold line: the piece is laid with this edge on the fabric's fold.
    return QCoreApplication::translate("kontur::print", "Place on fold");
}

std::vector<PrintedPiece> printedPieces(const std::vector<io::CurveRecord> &curves, const QString &units,
                                        const std::function<QPointF(const geo::Point &)> &map)
{
    std::vector<PrintedPiece> out;
    const int n = static_cast<int>(curves.size());
    for (int i = 0; i < n; ++i) {
        const io::CurveRecord &c = curves[static_cast<std::size_t>(i)];
        const auto marks = io::pieceFromSettings(c.settings);
        if (!c.visible || !marks)
            continue;
        const auto own = io::curveShape(c);
        if (!own || own->isEmpty())
            continue;
        geo::PiecewiseBezier cut = *own;
        PrintedPiece piece;
        for (int k = 0; k < n; ++k) {
            const io::CurveRecord &a = curves[static_cast<std::size_t>(k)];
            const auto seam = io::seamFromSettings(a.settings, n);
            if (a.visible && seam && seam->source == i)
                if (auto shape = io::curveShape(a); shape && !shape->isEmpty() && shape->isClosed()) {
                    cut = *shape;
                    piece.seamLabels = seamLabels(*own, *marks, seam->options.distance, units, map);
                    break;
                }
        }
        // Pattern millimetres have y down: a direction in the document maps with y negated.
        const auto dirOf = [](const geo::Point &d) { return unit(QPointF(d.x(), -d.y())); };
        for (const io::Notch &notch : marks->notches) {
            const io::CurvePlace place = io::placeAtLength(*own, notch.position);
            const geo::Point at = cut.nearest(place.point).point;
            const QPointF p = map(at);
            const QPointF in = dirOf(io::notchDirection(*own, place, notch.angle));
            const QPointF along(-in.y(), in.x());
            switch (notch.kind) {
            case io::NotchKind::Slit:
                piece.marks.moveTo(p - in * kNotchOutsideMm);
                piece.marks.lineTo(p + in * kNotchDepthMm);
                break;
            case io::NotchKind::V:
                piece.marks.moveTo(p - in * kNotchOutsideMm + along * 2.0);
                piece.marks.lineTo(p + in * kNotchDepthMm);
                piece.marks.lineTo(p - in * kNotchOutsideMm - along * 2.0);
                break;
            case io::NotchKind::Castle:
                piece.marks.moveTo(p - in * kNotchOutsideMm + along * 1.5);
                piece.marks.lineTo(p + in * kNotchDepthMm + along * 1.5);
                piece.marks.lineTo(p + in * kNotchDepthMm - along * 1.5);
                piece.marks.lineTo(p - in * kNotchOutsideMm - along * 1.5);
                break;
            }
        }
        if (marks->grainline) {
            const QPointF a = map(marks->grainline->a), b = map(marks->grainline->b);
            piece.marks.moveTo(a);
            piece.marks.lineTo(b);
            arrowHead(piece.marks, a, b);
            arrowHead(piece.marks, b, a);
        }
        for (const geo::Point &h : marks->drillHoles) {
            const QPointF p = map(h);
            piece.marks.addEllipse(p, kDrillHoleRadiusMm, kDrillHoleRadiusMm);
            piece.marks.moveTo(p - QPointF(2 * kDrillHoleRadiusMm, 0));
            piece.marks.lineTo(p + QPointF(2 * kDrillHoleRadiusMm, 0));
            piece.marks.moveTo(p - QPointF(0, 2 * kDrillHoleRadiusMm));
            piece.marks.lineTo(p + QPointF(0, 2 * kDrillHoleRadiusMm));
        }
        const geo::Box box = own->boundingBox();
        if (marks->fold) {
            const QPointF a = map(marks->fold->a), b = map(marks->fold->b);
            piece.fold.moveTo(a);
            piece.fold.lineTo(b);
            // The text beside the middle, towards the piece's centre.
            const QPointF middle = (a + b) / 2, centre = map(box.center());
            const QPointF d = unit(b - a);
            QPointF normal(-d.y(), d.x());
            if (QPointF::dotProduct(normal, centre - middle) < 0)
                normal = -normal;
            piece.foldTextAt = middle + normal * 8.0;
        }
        QStringList lines;
        if (!c.name.isEmpty())
            lines << c.name;
        if (!marks->size.isEmpty())
            //: A pattern piece's size on the printed pattern (a garment size such as 38 or M).
            lines << QCoreApplication::translate("kontur::print", "Size %1").arg(marks->size);
        const int quantity = marks->quantity;
        if (marks->fold)
            //: How many pieces to cut, printed on the pattern piece; the piece lies on the fabric's fold.
            lines << QCoreApplication::translate("kontur::print", "Cut %n on fold", "", quantity);
        else
            //: How many pieces to cut, printed on the pattern piece ("Cut 2").
            lines << QCoreApplication::translate("kontur::print", "Cut %n", "", quantity);
        if (!marks->material.isEmpty())
            lines << marks->material;
        piece.label = lines.join(QLatin1Char('\n'));
        // The label in the middle of the piece, beside the grainline rather than on it.
        QPointF at = map(box.center());
        if (marks->grainline) {
            const QPointF a = map(marks->grainline->a), b = map(marks->grainline->b);
            const QPointF d = unit(b - a);
            if (std::abs(d.y()) > std::abs(d.x()))
                at.setX((a.x() + b.x()) / 2 + 25.0);
            else
                at.setY((a.y() + b.y()) / 2 + 15.0);
        }
        piece.labelAt = at;
        out.push_back(std::move(piece));
    }
    return out;
}

} // namespace kontur
