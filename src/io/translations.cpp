// Translation loading shared by the app and kontur-cli.
#include "io/translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

namespace kontur {

QStringList translationCodes()
{
    return {QStringLiteral("en"), QStringLiteral("lv"), QStringLiteral("sk"), QStringLiteral("bg"),
            QStringLiteral("ru")};
}

QString systemTranslationCode()
{
    const QStringList codes = translationCodes();
    for (const QString &name : QLocale::system().uiLanguages()) {
        const QString code = name.section(QLatin1Char('-'), 0, 0).section(QLatin1Char('_'), 0, 0);
        if (codes.contains(code))
            return code;
    }
    return QStringLiteral("en");
}

QString requestedLanguage(const QStringList &args)
{
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--lang") && i + 1 < args.size())
            return args[i + 1];
        if (args[i].startsWith(QLatin1String("--lang=")))
            return args[i].mid(7);
    }
    return {};
}

std::unique_ptr<QTranslator> installTranslator(const QString &code)
{
    // English has a translator too: only the plural forms of its "%n point(s)" sources.
    if (!translationCodes().contains(code))
        return nullptr;
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(QStringLiteral(":/i18n/kontur_%1.qm").arg(code)))
        return nullptr;
    QCoreApplication::installTranslator(translator.get());
    return translator;
}

std::unique_ptr<QTranslator> installQtTranslator(const QString &code)
{
    // Debian's qt6-translations-l10n has qt_lv, qt_sk, qt_bg and qt_ru (qtbase and qtdeclarative);
    // without that package these few strings stay English.
    if (code == QLatin1String("en") || !translationCodes().contains(code))
        return nullptr;
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(QLocale(code), QStringLiteral("qt"), QStringLiteral("_"),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        return nullptr;
    QCoreApplication::installTranslator(translator.get());
    return translator;
}

} // namespace kontur
