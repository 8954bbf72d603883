// The English summary of what a file held that Kontur does not draw.
#include "io/skipped.h"

#include <QStringList>

namespace kontur::io {

QString skippedSummary(const SkippedCounts &counts, const char *otherOne, const char *otherMany)
{
    static const char *const names[kSkippedKinds - 1][2] = {
        {"text", "texts"},
        {"dimension", "dimensions"},
        {"3D object", "3D objects"},
        {"image", "images"},
        {"spline given only by fit points or weights", "splines given only by fit points or weights"},
    };
    QStringList parts;
    for (std::size_t k = 0; k < kSkippedKinds; ++k) {
        const int n = counts[k];
        if (n <= 0)
            continue;
        const char *name = k + 1 < kSkippedKinds ? names[k][n == 1 ? 0 : 1] : (n == 1 ? otherOne : otherMany);
        parts << QStringLiteral("%1 %2").arg(n).arg(QLatin1String(name));
    }
    return parts.join(QStringLiteral(", "));
}

} // namespace kontur::io
