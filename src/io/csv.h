// CSV import and export of one curve's points (issue 7): a header row "x,y", then one point per row,
// decimal point, fields optionally double-quoted ("1.5"), a ';' or tab separator also accepted when
// the header uses it. Grammar in docs/file-formats.md.
#pragma once

#include "geometry/bezier.h"
#include "io/error.h"
#include "io/limits.h"

#include <QByteArrayView>
#include <QString>

#include <span>
#include <vector>

namespace kontur::io {

[[nodiscard]] Result<std::vector<geo::Point>> parseCsvPoints(QByteArrayView text, const QString &fileName = {},
                                                             const Limits &limits = {});
[[nodiscard]] Result<std::vector<geo::Point>> readCsvPoints(const QString &path, const Limits &limits = {});

// "x,y\n" and one "x,y\n" row per point, shortest round-trip numbers.
[[nodiscard]] QByteArray formatCsvPoints(std::span<const geo::Point> points);
// Replaces the file atomically. More points than readCsvPoints takes (limits.maxPoints) are refused.
[[nodiscard]] Result<Ok> writeCsvPoints(const QString &path, std::span<const geo::Point> points,
                                        const Limits &limits = {});

} // namespace kontur::io
