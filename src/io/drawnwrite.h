// What every writer of a drawing (DXF, AAMA DXF, SVG) checks, in one place: that each coordinate is a
// finite number, and that the file holds no more than the readers take (`Limits`), so that nothing
// Kontur writes is refused when read. Each check's error is the same for every format.
#pragma once

#include "geometry/result.h"
#include "io/drawncurve.h"
#include "io/error.h"
#include "io/limits.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <span>

namespace kontur::io {

// A count of what a drawing holds, with the word its error says it in ("entities", "segments").
struct DrawnCount
{
    qint64 count = 0;
    const char *what = "";
};

// NumberOutOfRange for `path` when a coordinate of one of `curves` is not a finite number ("nan" or
// "inf" is no number in a file): "the drawing cannot be written: a coordinate of "<name>" is not a
// finite number", naming the first such curve.
[[nodiscard]] std::optional<Error> nonFiniteCoordinate(const QString &path, std::span<const DrawnCurve> curves);

// `code` for `path` when `counted` passes `most`: "the drawing cannot be written: <count> <what>; a
// file holds at most <most>".
[[nodiscard]] std::optional<Error> tooMany(const QString &path, DrawnCount counted, qint64 most, ErrorCode code);

// Writes the drawing's text `bytes` to `path` atomically, unless a value derived from the coordinates
// passed the largest number while it was made (`nonFinite`, NonFiniteWatch), or it holds more `items`
// (entities, curves) than a file may (TooManyCurves), or more `points` or bytes (TooManyPoints,
// FileTooLarge: "<points> <what> in <bytes> bytes; a file holds at most …").
[[nodiscard]] Result<Ok> writeDrawing(const QString &path, const QByteArray &bytes, bool nonFinite, DrawnCount items,
                                      DrawnCount points, const Limits &limits);

} // namespace kontur::io
