// libFuzzer target: the points text parser must answer a record list or a typed error for any bytes,
// and what it reads must survive being written and read again.
#include "io/pointstext.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    kontur::io::Limits limits;
    limits.maxPoints = 10'000;
    limits.maxCurves = 100;
    auto r = kontur::io::parsePointsText(
        QByteArrayView(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), {}, limits);
    if (!r.ok()) {
        (void)r.error().toString();
        return 0;
    }
    QByteArray again;
    for (const auto &rec : *r)
        again += kontur::io::formatPointsRecord(rec.curve) + '\n';
    auto back = kontur::io::parsePointsText(again, {}, limits);
    if (!back.ok() || back->size() != r->size())
        __builtin_trap();
    return 0;
}
