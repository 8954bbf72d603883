// The points text format (.txt; docs/requirements.md 1.5, issue 7; grammar in docs/file-formats.md): hand-written
// point lists ("x y", "x;y", "x,y" or tab separated, '#' comments, blank lines) and the curve records
// Kontur appends (a "curve <kind> [parameterization] [closed]" line, optional name / color / nodes /
// points / settings lines, then one point per line). A hand-written list is one record of unknown
// kind. Writing appends a record and never truncates the file (seed test T09).
#pragma once

#include "io/error.h"
#include "io/limits.h"
#include "io/records.h"

#include <QByteArrayView>
#include <QString>

#include <span>
#include <vector>

namespace kontur::io {

// What the points of a record are, as its "points" line says.
enum class PointKind {
    Unspecified, // no "points" line: the kind's own (knots for a composite curve)
    Knots,
    Control,
};

struct TextRecord
{
    // kind is empty for a hand-written list (points before any "curve" line). For known kinds the
    // record is normalised and validated: a composite curve given by its knots is built by the
    // seed's rules (docs/requirements.md 1.2) into its control vector, node types default to "smooth".
    CurveRecord curve;
    PointKind pointKind = PointKind::Unspecified; // as written in the file
    int line = 0;                                 // the record's first line
};

// Parses the text (UTF-8, with or without a byte order mark, LF or CRLF). `fileName` is only
// used in errors. Errors carry the line and column; a file without any point is NoPoints.
[[nodiscard]] Result<std::vector<TextRecord>> parsePointsText(QByteArrayView text, const QString &fileName = {},
                                                              const Limits &limits = {});
[[nodiscard]] Result<std::vector<TextRecord>> readPointsText(const QString &path, const Limits &limits = {});

// A curve record of `kind` from bare points (a hand-written list, a CSV file, typed coordinates) by
// the same rules as a text record: composite knots are built into the control vector by the seed's
// rules (pointKind Knots or Unspecified), node types default to smooth; then validated.
[[nodiscard]] Result<CurveRecord> curveFromPoints(const QString &kind, const QString &parameterization,
                                                  std::vector<geo::Point> points,
                                                  PointKind pointKind = PointKind::Unspecified, bool closed = false);

// One record as Kontur writes it. `derivedControl` (the control points of a fitted curve, say) is
// written as comments for the reader of the file; it is not read back.
[[nodiscard]] QByteArray formatPointsRecord(const CurveRecord &curve, std::span<const geo::Point> derivedControl = {});
// Appends the record at the end of `path` (creating it), separated by a blank line from what is
// there. The curve is validated first (an invalid record is not written), and a record of more points
// than a file holds, or one that would make the file larger than the reader takes, is refused.
[[nodiscard]] Result<Ok> appendPointsRecord(const QString &path, const CurveRecord &curve,
                                            std::span<const geo::Point> derivedControl = {}, const Limits &limits = {});

} // namespace kontur::io
