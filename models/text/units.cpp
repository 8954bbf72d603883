// Lengths with their units; see units.h.
#include "models/text/units.h"

#include "models/text/numbers.h"

#include <QCoreApplication>
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
    return withUnit(fixedNumber(value, decimalsFor(unit)), unit);
}

QString withUnit(const QString &number, const QString &unit)
{
    // One pattern per unit, so that each language writes its own symbol and the form a decimal number
    // takes (ru "дюйма", sk "palca"); number and symbol with a space between them (SI style).
    if (unit == QLatin1String("mm"))
        //: A length in millimetres; %1 is a decimal number (12,35).
        return QCoreApplication::translate("units", "%1 mm").arg(number);
    if (unit == QLatin1String("cm"))
        //: A length in centimetres; %1 is a decimal number (1,235).
        return QCoreApplication::translate("units", "%1 cm").arg(number);
    if (unit == QLatin1String("in"))
        //: A length in inches; %1 is a decimal number with three decimals (0,500), so the unit takes the
        //: form it has after a fraction.
        return QCoreApplication::translate("units", "%1 in").arg(number);
    if (unit == QLatin1String("px"))
        //: A length in pixels of the picture; %1 is a decimal number (30,0).
        return QCoreApplication::translate("units", "%1 px").arg(number);
    if (unit == QLatin1String("pt"))
        //: A length in typographic points (1/72 inch); %1 is a decimal number (2,3).
        return QCoreApplication::translate("units", "%1 pt").arg(number);
    return QStringLiteral("%1 %2").arg(number, unit);
}

QString unitName(const QString &unit)
{
    if (unit == QLatin1String("mm"))
        //: The unit millimetres, alone: in a list of units and in headings such as "X, mm".
        return QCoreApplication::translate("units", "mm");
    if (unit == QLatin1String("cm"))
        //: The unit centimetres, alone: in a list of units and in headings such as "X, cm".
        return QCoreApplication::translate("units", "cm");
    if (unit == QLatin1String("in"))
        //: The unit inches, alone: in a list of units (mm, cm, in) and in headings such as "X, in".
        return QCoreApplication::translate("units", "in");
    if (unit == QLatin1String("px"))
        //: The unit pixels (of the picture), alone: in headings such as "X, px".
        return QCoreApplication::translate("units", "px");
    if (unit == QLatin1String("pt"))
        //: The unit typographic points (1/72 inch), alone: in headings such as "X, pt".
        return QCoreApplication::translate("units", "pt");
    return unit;
}

QString Numbers::unit(const QString &code, const QString &language)
{
    Q_UNUSED(language)
    return unitName(code);
}

QString Numbers::shownLength(double value, int decimals, const QString &code, const QString &language)
{
    Q_UNUSED(language) // displayNumber writes in the default locale, as formatLength does
    return withUnit(displayNumber(value, decimals), code);
}

QString Numbers::length(double value, const QString &code, const QString &language)
{
    // formatLength writes in the default locale, which the Language singleton keeps at `language`.
    Q_UNUSED(language)
    return formatLength(value, code);
}

} // namespace kontur
