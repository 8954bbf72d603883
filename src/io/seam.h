// A seam allowance's link to its source curve as the files store it: the "seamAllowance" object of
// a composite curve's "settings" in a .kontur document (docs/file-formats.md). The source is named by
// its index among the document's curves; older Kontur versions read the curve as a free composite.
// Also the unit conversion the default allowance (1 cm) needs.
#pragma once

#include "geometry/offset.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace kontur::io {

inline constexpr const char *kSeamKey = "seamAllowance";

struct SeamSettings
{
    int source = -1; // the source curve's index in the document
    geo::OffsetOptions options;

    friend bool operator==(const SeamSettings &a, const SeamSettings &b)
    {
        return a.source == b.source && a.options.distance == b.options.distance && a.options.side == b.options.side &&
               a.options.join == b.options.join && a.options.miterLimit == b.options.miterLimit &&
               a.options.tolerance == b.options.tolerance;
    }
};

// {"source": 0, "distance": 10, "side": "outside", "join": "miter", "miterLimit": 30, "tolerance": 0.05}
[[nodiscard]] QJsonObject seamToJson(const SeamSettings &seam);
// The link in a curve's settings, if it holds a well-formed one (a malformed one is no link: the
// curve stays a free composite curve, as older versions read it). `curveCount` bounds the source.
[[nodiscard]] std::optional<SeamSettings> seamFromSettings(const QJsonObject &settings, int curveCount);

// How many of `unit` make a centimetre: mm 10, cm 1, in 1/2.54, pt 72/2.54, px 96/2.54 (CSS pixels);
// 0 for an unknown unit.
[[nodiscard]] double unitsPerCentimetre(const QString &unit);
// The default allowance, tolerance and miter limit in `unit`: 1 cm, 0.05 mm, 3 cm.
[[nodiscard]] geo::OffsetOptions defaultSeamOptions(const QString &unit);

} // namespace kontur::io
