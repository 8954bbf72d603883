// libFuzzer target: the CSV parser must answer points or a typed error for any bytes, and written
// points must read back identically.
#include "io/csv.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    kontur::io::Limits limits;
    limits.maxPoints = 10'000;
    auto r = kontur::io::parseCsvPoints(
        QByteArrayView(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), {}, limits);
    if (!r.ok())
        return 0;
    auto back = kontur::io::parseCsvPoints(kontur::io::formatCsvPoints(*r), {}, limits);
    if (!back.ok() || *back != *r)
        __builtin_trap();
    return 0;
}
