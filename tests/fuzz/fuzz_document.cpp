// libFuzzer target: the .kontur reader must answer a valid document or a typed error for any bytes;
// a document it accepts must save → open → save byte-identically.
#include "io/document.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    kontur::io::Limits limits;
    limits.maxPoints = 10'000;
    limits.maxCurves = 100;
    limits.maxFileBytes = 1 << 20;
    auto r = kontur::io::documentFromJson(
        QByteArrayView(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), {}, limits);
    if (!r.ok())
        return 0;
    const QByteArray first = kontur::io::documentToJson(*r);
    auto back = kontur::io::documentFromJson(first, {}, limits);
    if (!back.ok() || kontur::io::documentToJson(*back) != first)
        __builtin_trap();
    return 0;
}
