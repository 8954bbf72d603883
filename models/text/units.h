// The document's length units (px, mm, cm, in, pt) as the UI writes lengths: how many decimals each
// unit shows and a length with its unit in the UI language's number format (QLocale's default, which
// the Language singleton sets). One place for the rule the trace bar and the canvas label share.
#pragma once

#include <QString>

namespace kontur {

// Decimals shown for a length in `unit`: 0.01 mm, 0.001 cm or in, 0.1 of anything else (pixels,
// points): about a hundredth of a millimetre for the real units.
[[nodiscard]] int decimalsFor(const QString &unit);
// `value` with the unit's decimals and the unit in the UI language, e.g. "12.35 mm" (lv: "12,35 mm",
// ru: "12,35 мм", sk: "0,500 palca"). The codes (mm, cm, in, px, pt) stay in files and in the model.
[[nodiscard]] QString formatLength(double value, const QString &unit);
// A number already written (displayNumber, fixedNumber) with the unit in the UI language: the one
// pattern per unit that formatLength uses.
[[nodiscard]] QString withUnit(const QString &number, const QString &unit);
// The unit's name in the UI language for a list of units or a heading ("in": ru "дюймы"); an unknown
// code as it is.
[[nodiscard]] QString unitName(const QString &unit);

} // namespace kontur
