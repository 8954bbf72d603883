// A garment piece's marks as the pattern PDF prints them (io/piece.h), in pattern millimetres (y
// down): the grainline as a double-headed arrow, each notch as a mark across the cut line (a slit a
// line, a V two, a castle a notch's three sides), drill holes as a circle with a cross, the fold line
// dash-dotted with "Place on fold", and the label (name, size, "Cut 2", the material) in the middle;
// where the seams' allowance widths differ (issue #44), each seam of a width other than the
// allowance's own gets a small label ("3 cm") in its allowance, beside the seam's middle.
#pragma once

#include "io/records.h"

#include <QPainterPath>
#include <QPointF>
#include <QString>

#include <functional>
#include <vector>

namespace kontur {

inline constexpr double kNotchOutsideMm = 2.0; // how far a notch mark reaches out of the cut line
inline constexpr double kNotchDepthMm = 5.0;   // and into the piece
inline constexpr double kDrillHoleRadiusMm = 1.5;

struct PrintedPiece
{
    QPainterPath marks; // grainline, notches, drill holes: solid lines
    QPainterPath fold;  // the fold line: dash-dotted
    QPointF labelAt;    // the label's centre
    QString label;      // lines: name, size, "Cut 2 on fold", material
    QPointF foldTextAt; // "Place on fold" beside the fold line's middle, inside the piece
    struct SeamLabel
    {
        QPointF at;   // its centre: halfway across the seam's allowance at the seam's middle
        QString text; // the width: "3 cm" (metric documents), "1.25 in" (inch ones)
    };
    std::vector<SeamLabel> seamLabels;
};

// The printed marks of each visible piece of `curves` (those with a "piece" in their settings);
// `map` takes document units to pattern millimetres. The cut line is the piece's seam allowance
// when a visible one follows it, else the piece itself. Texts are translated (context "kontur::print");
// `units` are the document's (for the seams' widths).
[[nodiscard]] std::vector<PrintedPiece> printedPieces(const std::vector<io::CurveRecord> &curves, const QString &units,
                                                      const std::function<QPointF(const geo::Point &)> &map);
// A seam's allowance width as printed: in centimetres for metric documents (`units` a metric unit),
// in inches for "in", else in the document's units; translated.
[[nodiscard]] QString seamWidthText(double width, const QString &units);
// "Place on fold", translated.
[[nodiscard]] QString placeOnFoldText();

} // namespace kontur
