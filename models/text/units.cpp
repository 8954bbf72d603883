// Lengths with their units; see units.h.
#include "models/text/units.h"

#include "models/text/numbers.h"

#include <QLocale>

namespace kontur {

int decimalsFor(const QString &unit)
{
    if (unit == QLatin1String("mm"))
        return 2;
    if (unit == QLatin1String("cm") || unit == QLatin1String("in"))
        return 3;
    return 1;
}

QString formatLength(double value, const QString &unit)
{
    // Number and unit symbol with a space between them in all four languages (SI style).
    return QStringLiteral("%1 %2").arg(fixedNumber(value, decimalsFor(unit)), unit);
}

} // namespace kontur
