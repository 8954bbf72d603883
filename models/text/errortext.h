// Why a file could not be read or written, or why the geometry refused a curve, as the message line says
// it: chosen by the error's code and place, not by the file layer's English sentence (which stays for
// logs and kontur-cli). A detail is a plain map, so a message holding it is translated when shown.
#pragma once

#include "geometry/result.h"
#include "io/error.h"

#include <QString>
#include <QVariantMap>

namespace kontur {

// The detail of a file error: its code and where it happened (line and column, or the place in a
// document such as curves[3].points[7]).
[[nodiscard]] QVariantMap errorDetail(const io::Error &error);
// The detail of a geometry error in the `curve`-th curve of a file (1-based; 0 for no curve number).
[[nodiscard]] QVariantMap errorDetail(const geo::Error &error, int curve = 0);
// What a file held that is not drawn, in the current language ("12 texts, 1 3D object"): the counts
// in the order of io::SkippedKind (src/io/skipped.h), its one list of kinds.
[[nodiscard]] QString skippedList(const QVariantList &counts);
// The same as a sentence to append to a message ("Not drawn: 2 texts, 1 image."); empty for none.
[[nodiscard]] QString notDrawn(const QVariantList &counts);
// A detail as a sentence in the current language: an error's map, or a Message (made in the current
// language). A plain string (a reason the system gave) is returned as it is.
[[nodiscard]] QString detailText(const QVariant &detail);

} // namespace kontur
