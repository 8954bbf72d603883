// libFuzzer target: DXF import (group pairs, sections, every entity kind, B-spline decomposition,
// bulges and arcs) must answer curves or a typed error for any bytes, within the limits; what it
// reads also becomes records (the app's path) without a crash.
#include "io/dxf.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const char *text = reinterpret_cast<const char *>(data);
    kontur::io::DxfImportOptions options;
    options.limits.maxPoints = 20'000;
    options.limits.maxCurves = 1'000;
    options.arcTolerance = 1e-3;
    auto r = kontur::io::importDxf(QByteArrayView(text, static_cast<qsizetype>(size)), {}, options);
    if (r.ok())
        for (const auto &c : r->curves)
            (void)kontur::io::recordFromDxfCurve(c.curve, 1e-3).ok();
    return 0;
}
