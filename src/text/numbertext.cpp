// Parsing typed numbers and formatting shown ones.
#include "text/numbertext.h"

#include <QLocale>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {

bool isSpace(QChar c)
{
    return c == QLatin1Char(' ') || c == QChar(0x00A0) || c == QChar(0x202F) || c == QChar(0x2009);
}

// The typed text as QLocale reads it: a typographic minus as "-", and the integer part's groups of
// thousands joined where they are separated by spaces (plain, no-break, narrow no-break) as
// "12 345 678" — QLocale itself takes only its own separator, and not at all below 10 000 in the
// languages whose CLDR data groups only from five digits on (Latvian, Bulgarian).
QString normalized(QString text)
{
    text = text.trimmed();
    text.replace(QChar(0x2212), QLatin1Char('-'));
    const qsizetype start = (!text.isEmpty() && (text[0] == QLatin1Char('-') || text[0] == QLatin1Char('+'))) ? 1 : 0;
    qsizetype end = start;
    while (end < text.size() && (text[end].isDigit() || isSpace(text[end])))
        ++end;
    const QString integer = text.mid(start, end - start);
    if (!integer.isEmpty() && isSpace(integer.back()))
        return text; // "1 " before something else: not a grouped number
    QStringList groups;
    QString group;
    for (const QChar c : integer) {
        if (isSpace(c)) {
            groups.append(group);
            group.clear();
        } else {
            group.append(c);
        }
    }
    groups.append(group);
    if (groups.size() < 2 || groups.front().isEmpty() || groups.front().size() > 3)
        return text;
    for (qsizetype g = 1; g < groups.size(); ++g)
        if (groups[g].size() != 3)
            return text;
    return text.left(start) + groups.join(QString()) + text.mid(end);
}

} // namespace

Parsed parseNumber(const QString &text, const QLocale &locale, double &out)
{
    if (text.trimmed().isEmpty())
        return Parsed::NotValid;
    bool overflow = false;
    for (const QLocale &each : {locale, QLocale::c()}) {
        bool ok = false;
        out = each.toDouble(normalized(text), &ok);
        if (ok)
            return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
        // QLocale answers infinity with ok == false for a number too large for a double.
        overflow = overflow || std::isinf(out);
    }
    return overflow ? Parsed::TooLarge : Parsed::NotValid;
}

Parsed parseNumber(const QVariant &value, double &out)
{
    if (value.typeId() == QMetaType::Double || value.typeId() == QMetaType::Int) {
        out = value.toDouble();
        return std::isfinite(out) ? Parsed::Number : Parsed::NotValid;
    }
    return parseNumber(value.toString(), QLocale(), out);
}

Parsed parseNumberList(const QString &text, const QLocale &locale, std::vector<double> &out, QString *badToken)
{
    out.clear();
    // A comma separates numbers only where it is not the decimal separator.
    const bool commaIsDecimal = locale.decimalPoint() == QStringLiteral(",");
    static const QRegularExpression withComma(QStringLiteral("[\\s;,]+"));
    static const QRegularExpression withoutComma(QStringLiteral("[\\s;]+"));
    const QStringList tokens = text.split(commaIsDecimal ? withoutComma : withComma, Qt::SkipEmptyParts);
    for (const QString &token : tokens) {
        double v = 0.0;
        const Parsed parsed = parseNumber(token, locale, v);
        if (parsed != Parsed::Number) {
            if (badToken)
                *badToken = token;
            return parsed;
        }
        out.push_back(v);
    }
    return Parsed::Number;
}

std::vector<ListToken> numberListTokens(const QString &text, const QLocale &locale)
{
    // The same separators as parseNumberList: a comma separates only where it is not the decimal one.
    const bool commaIsDecimal = locale.decimalPoint() == QStringLiteral(",");
    static const QRegularExpression withComma(QStringLiteral("[^\\s;,]+"));
    static const QRegularExpression withoutComma(QStringLiteral("[^\\s;]+"));
    std::vector<ListToken> tokens;
    auto it = (commaIsDecimal ? withoutComma : withComma).globalMatch(text);
    while (it.hasNext()) {
        const QRegularExpressionMatch match = it.next();
        ListToken token;
        token.start = match.capturedStart();
        token.length = match.capturedLength();
        const QString typed = match.captured();
        token.isNumber = parseNumber(typed, locale, token.value) == Parsed::Number;
        token.decimals = token.isNumber ? shownDecimals(typed, locale) : 0;
        tokens.push_back(token);
    }
    return tokens;
}

int shownDecimals(const QString &token, const QLocale &locale)
{
    QString mantissa = token;
    int exponent = 0;
    const qsizetype e = token.indexOf(QLatin1Char('e'), 0, Qt::CaseInsensitive);
    if (e >= 0) {
        mantissa = token.left(e);
        exponent = token.mid(e + 1).replace(QChar(0x2212), QLatin1Char('-')).toInt();
    }
    qsizetype point = mantissa.lastIndexOf(locale.decimalPoint());
    if (point < 0)
        point = mantissa.lastIndexOf(QLatin1Char('.'));
    int decimals = 0;
    if (point >= 0) {
        for (qsizetype i = point + 1; i < mantissa.size() && mantissa[i].isDigit(); ++i)
            ++decimals;
    }
    return std::clamp(decimals - exponent, 0, 17);
}

double stepFor(const ListToken &token, int maxDecimals)
{
    return std::pow(10.0, -std::min(token.decimals, std::max(0, maxDecimals)));
}

QString stepListNumber(const QString &text, const QLocale &locale, int index, int direction, int maxDecimals)
{
    const std::vector<ListToken> tokens = numberListTokens(text, locale);
    if (index < 0 || index >= static_cast<int>(tokens.size()) || !tokens[index].isNumber || direction == 0)
        return {};
    const ListToken &token = tokens[index];
    const double stepped = token.value + (direction > 0 ? 1.0 : -1.0) * stepFor(token, maxDecimals);
    if (!std::isfinite(stepped))
        return {};
    QString result = text;
    result.replace(token.start, token.length,
                   fixedNumber(stepped, token.decimals, locale, {.grouping = false, .trailingZeros = true}));
    return result;
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

QString fixedNumber(double value, int decimals, const QLocale &locale, NumberStyle style)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    decimals = std::clamp(decimals, 0, 17);
    // -0.0004 at 3 decimals reads as 0,000, not -0,000.
    if (std::abs(value) < 0.5 * std::pow(10.0, -decimals))
        value = 0.0;
    QLocale shown = locale;
    if (!style.grouping)
        shown.setNumberOptions(shown.numberOptions() | QLocale::OmitGroupSeparator);
    QString text = shown.toString(value, 'f', decimals);
    if (!style.trailingZeros && decimals > 0) {
        const QString point = shown.decimalPoint();
        if (text.contains(point)) {
            while (text.endsWith(shown.zeroDigit()))
                text.chop(shown.zeroDigit().size());
            if (text.endsWith(point))
                text.chop(point.size());
        }
    }
    return text;
}

QString significantNumber(double value, int digits, const QLocale &locale)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    QLocale shown = locale;
    shown.setNumberOptions(shown.numberOptions() | QLocale::OmitLeadingZeroInExponent);
    return shown.toString(value, 'g', std::clamp(digits, 1, 17));
}

} // namespace kontur
