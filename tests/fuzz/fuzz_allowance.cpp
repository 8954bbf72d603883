// libFuzzer target: a document's seam allowances (the "seamAllowance" settings of .kontur, with any
// values) and the offsets they ask for. An allowance whose source draws must give an offset or a
// typed error within the offset's work budget, and an offset it gives is finite everywhere.
#include "geometry/offset.h"
#include "io/document.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    kontur::io::Limits limits;
    limits.maxPoints = 2'000;
    limits.maxCurves = 16;
    limits.maxFileBytes = 1 << 18;
    const auto doc = kontur::io::documentFromJson(
        QByteArrayView(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), {}, limits);
    if (!doc.ok())
        return 0;
    const int count = static_cast<int>(doc->curves.size());
    for (const auto &curve : doc->curves) {
        const auto seam = kontur::io::seamFromSettings(curve.settings, count);
        if (!seam)
            continue;
        const auto source = kontur::io::curveShape(doc->curves[static_cast<std::size_t>(seam->source)]);
        if (!source.ok())
            continue;
        kontur::geo::detail::resetOffsetWork();
        const auto offset = kontur::geo::offsetCurve(*source, seam->options);
        // The budget is checked between steps: one step's own work may pass it a little.
        if (kontur::geo::detail::offsetWork() > 2 * kontur::geo::kOffsetBudget)
            __builtin_trap();
        if (!offset.ok())
            continue;
        for (const auto &segment : offset->curve.segments())
            for (const auto &p : segment.controlPoints())
                if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
                    __builtin_trap();
    }
    return 0;
}
