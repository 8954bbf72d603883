// Parsing typed numbers and formatting shown ones.
#include "models/numbers.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace kontur {

Parsed parseNumber(const QVariant &value, double &out)
{
    if (value.typeId() == QMetaType::Double || value.typeId() == QMetaType::Int) {
        out = value.toDouble();
        return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
    }
    const QString text = value.toString().trimmed();
    if (text.isEmpty())
        return Parsed::NotValid;
    bool overflow = false;
    for (const QLocale &locale : {QLocale(), QLocale::c()}) {
        bool ok = false;
        out = locale.toDouble(text, &ok);
        if (ok)
            return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
        // QLocale answers infinity with ok == false for a number too large for a double.
        overflow = overflow || std::isinf(out);
    }
    return overflow ? Parsed::TooLarge : Parsed::NotValid;
}

Parsed parsePoints(const QVariantList &rows, std::vector<geo::Point> &out)
{
    out.clear();
    for (const QVariant &row : rows) {
        const QVariantList xy = row.toList();
        double x = 0.0, y = 0.0;
        const Parsed px = xy.size() == 2 ? parseNumber(xy[0], x) : Parsed::NotValid;
        const Parsed py = xy.size() == 2 ? parseNumber(xy[1], y) : Parsed::NotValid;
        if (px == Parsed::NotValid || py == Parsed::NotValid)
            return Parsed::NotValid;
        if (px == Parsed::TooLarge || py == Parsed::TooLarge)
            return Parsed::TooLarge;
        out.emplace_back(x, y);
    }
    return Parsed::Number;
}

QString displayNumber(double value, int decimals)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    const QLocale locale;
    const double magnitude = std::abs(value);
    if (value == 0.0)
        return locale.toString(value, 'f', decimals);
    if (magnitude >= std::pow(10.0, -decimals) && magnitude < 1e9) {
        const int integerDigits = std::max(1, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
        return locale.toString(value, 'f', std::clamp(7 - integerDigits, 0, decimals));
    }
    // 3 significant digits and no leading zero in the exponent: -1.23E+150 fits a cell.
    QLocale shown = locale;
    shown.setNumberOptions(shown.numberOptions() | QLocale::OmitLeadingZeroInExponent);
    return shown.toString(value, 'g', 3);
}

QString exactNumber(double value)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace kontur
