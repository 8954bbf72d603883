// Numbers for QML: the singleton Numbers over the one parser and formatter in src/text/numbertext.h.
#pragma once

#include "text/numbertext.h"

#include <QObject>
#include <QString>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// The same for QML: Numbers.shown(value, decimals), Numbers.exact(value), and Numbers.fixed(value,
// decimals, language) and Numbers.significant(value, digits, language) with the language's code
// (Language.current), so that a binding follows a language switch.
class Numbers final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON

public:
    using QObject::QObject;
    Q_INVOKABLE static QString shown(double value, int decimals) { return displayNumber(value, decimals); }
    Q_INVOKABLE static QString exact(double value) { return exactNumber(value); }
    Q_INVOKABLE static QString fixed(double value, int decimals, const QString &language)
    {
        return fixedNumber(value, decimals, QLocale(language));
    }
    Q_INVOKABLE static QString significant(double value, int digits, const QString &language)
    {
        return significantNumber(value, digits, QLocale(language));
    }
    // A length unit's name in the UI language (kontur::unitName); `language` only makes a binding follow
    // a language switch.
    Q_INVOKABLE static QString unit(const QString &code, const QString &language);
    // A length with its unit's decimals and the unit in the UI language (kontur::formatLength).
    Q_INVOKABLE static QString length(double value, const QString &code, const QString &language);
    // A length as Numbers.shown writes it (at most `decimals`, an exponent beyond 1e9) with its unit:
    // the curve list's lengths.
    Q_INVOKABLE static QString shownLength(double value, int decimals, const QString &code, const QString &language);
};

} // namespace kontur
