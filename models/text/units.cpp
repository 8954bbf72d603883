// Lengths with their units; see units.h.
#include "models/text/units.h"

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

QString formatNumber(double value, int decimals)
{
    // QML's Number.toLocaleString(locale, "f", n), which the bar used: group separators included.
    return QLocale().toString(value, 'f', decimals);
}

QString formatLength(double value, const QString &unit)
{
    // Number and unit symbol with a space between them in all four languages (SI style).
    return QStringLiteral("%1 %2").arg(formatNumber(value, decimalsFor(unit)), unit);
}

} // namespace kontur
