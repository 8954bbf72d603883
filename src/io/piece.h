// A garment piece's own marks as a pattern maker gives them (issue "pattern pieces"): size, how many
// to cut, the material, the fold (mirror) line, the grainline, notches and drill holes. They belong to
// a closed curve, the piece's sew line; its name is the curve's name. In a .kontur document they are
// the "piece" object of the curve's "settings" (docs/file-formats.md), in an ASTM D6673 (AAMA) DXF the
// standard's layers (io/dxf.h). Positions are in the document's units, in the world (y up).
#pragma once

#include "geometry/piecewise.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace kontur::io {

inline constexpr const char *kPieceKey = "piece";

// A straight segment from `a` to `b` (the grainline points from a to b).
struct Segment
{
    geo::Point a = geo::Point::Zero();
    geo::Point b = geo::Point::Zero();
    friend bool operator==(const Segment &, const Segment &) = default;
};

enum class NotchKind { Slit, V, Castle };
[[nodiscard]] const char *notchKindId(NotchKind kind); // "slit", "v", "castle"
[[nodiscard]] std::optional<NotchKind> notchKindFromId(const QString &id);

struct Notch
{
    // Where it lies: the arc length along the piece's curve from its start, in the document's units.
    double position = 0.0;
    NotchKind kind = NotchKind::Slit;
    // Its direction against the square to the seam, in degrees (0: square, the usual notch), counter-
    // clockwise; within (-90, 90).
    double angle = 0.0;
    friend bool operator==(const Notch &, const Notch &) = default;
};

struct PieceMarks
{
    QString size;
    int quantity = 1; // "cut N"; at least 1
    QString material;
    std::optional<Segment> fold;      // cut on fold along this line (the mirror line)
    std::optional<Segment> grainline; // none: the piece has no grain of its own yet
    std::vector<Notch> notches;       // by position
    std::vector<geo::Point> drillHoles;
    // The seam allowance per seam (geometry/seams.h: the outline between two corner knots, numbered
    // from the first corner at or after the curve's start): seam k's width in the document's units,
    // none where the seam has the allowance's own width. Trailing nones are not kept.
    std::vector<std::optional<double>> seamWidths;
    // The seams that are hems (by number, ascending): their allowance's corners are turned back
    // (geo::OffsetOptions::hems) rather than mitred.
    std::vector<int> hems;
    friend bool operator==(const PieceMarks &, const PieceMarks &) = default;
};

// {"size": "38", "quantity": 2, "material": "…", "fold": [[x, y], [x, y]], "grainline": …,
//  "notches": [{"at": 120.5, "kind": "v", "angle": 0}], "drillHoles": [[x, y]],
//  "seamWidths": [30, null, 10], "hems": [0]}; empty members left out.
[[nodiscard]] QJsonObject pieceToJson(const PieceMarks &piece);
// The piece in a curve's settings, if it holds one. Members that are malformed are left out (a
// notch of an unknown kind, a quantity below 1 read as 1), so that nothing Kontur writes is refused.
[[nodiscard]] std::optional<PieceMarks> pieceFromSettings(const QJsonObject &settings);

// Where arc length `s` (wrapped around a closed curve, clamped on an open one) lies on `curve`:
// the point and the unit tangent there.
struct CurvePlace
{
    geo::Point point = geo::Point::Zero();
    geo::Point tangent = geo::Point(1, 0);
};
[[nodiscard]] CurvePlace placeAtLength(const geo::PiecewiseBezier &curve, double s);
// The arc length from the curve's start to the point nearest `p`.
[[nodiscard]] double lengthAtNearest(const geo::PiecewiseBezier &curve, const geo::Point &p);
// Where the line through `from` along `direction` meets `curve`, found from the curve's point nearest
// to `from` by Newton steps on the cross product (direction × (curve − from) = 0), segment to segment;
// nothing when it does not meet within a few segments of there. A notch is carried square across from
// the sew line to the cut line (AAMA) and back this way, which the nearest point on a flattened cut
// line (its chords' feet lie off the curve's) would not do.
[[nodiscard]] std::optional<geo::Point> meetAlong(const geo::PiecewiseBezier &curve, const geo::Point &from,
                                                  const geo::Point &direction);
// The notch's direction into the piece (a unit vector) at a place of a closed curve: the square to
// the seam towards the curve's inside, turned counter-clockwise by the notch's angle (degrees).
[[nodiscard]] geo::Point notchDirection(const geo::PiecewiseBezier &curve, const CurvePlace &place, double angle);
// The signed area of a closed curve's flattening (positive counter-clockwise).
[[nodiscard]] double signedArea(const geo::PiecewiseBezier &curve);

} // namespace kontur::io
