// libFuzzer target: SVG import (XML, transforms, path data, arcs) must answer curves or a typed error
// for any bytes, within the limits; the first bytes also go to the path data parser alone.
#include "io/svg.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const char *text = reinterpret_cast<const char *>(data);
    kontur::io::SvgPathOptions pathOptions;
    pathOptions.maxSegments = 20'000;
    (void)kontur::io::parseSvgPathData(std::string_view(text, size), pathOptions);
    kontur::io::SvgImportOptions options;
    options.limits.maxPoints = 20'000;
    options.limits.maxCurves = 1'000;
    options.path.arcTolerance = 1e-3;
    auto r = kontur::io::importSvg(QByteArrayView(text, static_cast<qsizetype>(size)), {}, options);
    (void)r.ok();
    return 0;
}
