// A garment piece's marks as the pattern PDF prints them (io/piece.h), in pattern millimetres (y
// down): the grainline as a double-headed arrow, each notch as a mark across the cut line (a slit a
// line, a V two, a castle a notch's three sides), drill holes as a circle with a cross, the fold line
// dash-dotted with "Place on fold", and the label (name, size, "Cut 2", the material) in the middle.
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
};

// The printed marks of each visible piece of `curves` (those with a "piece" in their settings);
// `map` takes document units to pattern millimetres. The cut line is the piece's seam allowance
// when a visible one follows it, else the piece itself. Texts are translated (context "kontur::print").
[[nodiscard]] std::vector<PrintedPiece> printedPieces(const std::vector<io::CurveRecord> &curves,
                                                      const std::function<QPointF(const geo::Point &)> &map);
// "Place on fold", translated.
[[nodiscard]] QString placeOnFoldText();

} // namespace kontur
