// Run-time language switching: QTranslator from the embedded .qm files, QLocale default,
// QQmlEngine::retranslate().
#include "app/language.h"

#include <QCoreApplication>
#include <QLocale>
#include <QQmlEngine>
#include <QSettings>

namespace kontur {

namespace {
struct Entry
{
    const char *code;
    const char *nativeName; // shown untranslated: people look for their own language's name
};
constexpr Entry kLanguages[] = {
    {"en", "English"}, {"lv", "Latviešu"}, {"sk", "Slovenčina"}, {"bg", "Български"}, {"ru", "Русский"},
};

} // namespace

Language::Language(QQmlEngine *engine)
    : QObject(engine)
    , m_engine(engine)
{
}

Language::~Language()
{
    if (m_translator)
        QCoreApplication::removeTranslator(m_translator.get());
    if (m_qtTranslator)
        QCoreApplication::removeTranslator(m_qtTranslator.get());
}

Language *Language::create(QQmlEngine *qmlEngine, QJSEngine *)
{
    auto *language = qmlEngine->findChild<Language *>(QString(), Qt::FindDirectChildrenOnly);
    if (!language)
        language = new Language(qmlEngine);
    // The engine's parent-child tree owns it; QML must not delete it.
    QJSEngine::setObjectOwnership(language, QJSEngine::CppOwnership);
    return language;
}

QStringList Language::codes()
{
    QStringList list;
    for (const Entry &e : kLanguages)
        list << QString::fromLatin1(e.code);
    return list;
}

bool Language::isSupported(const QString &code)
{
    return codes().contains(code);
}

QString Language::systemDefault()
{
    // The user's last choice, else a classroom default from /etc/xdg/Kontur/kontur.conf (QSettings
    // falls back to the system scope by itself), else the system locale's language, else English.
    const QString chosen = QSettings().value(QStringLiteral("language")).toString();
    if (isSupported(chosen))
        return chosen;
    return systemTranslationCode();
}

void Language::remember(const QString &code)
{
    if (isSupported(code))
        QSettings().setValue(QStringLiteral("language"), code);
}

bool Language::setCurrent(const QString &code)
{
    if (!isSupported(code))
        return false;
    if (code == m_current && m_translator)
        return true;
    // Numbers shown in the UI follow the language (decimal comma in lv, sk, bg, ru). Set first:
    // installing a translator tells the models at once (QEvent::LanguageChange, LanguageWatch),
    // and the texts they give then must already have the new number format.
    const QLocale previous;
    QLocale::setDefault(QLocale(code));
    // English's translator holds only its plural forms; without it English still works.
    std::unique_ptr<QTranslator> translator = installTranslator(code);
    if (code != QLatin1String("en") && !translator) {
        QLocale::setDefault(previous);
        return false;
    }
    if (m_translator)
        QCoreApplication::removeTranslator(m_translator.get());
    if (m_qtTranslator)
        QCoreApplication::removeTranslator(m_qtTranslator.get());
    m_translator = std::move(translator);
    m_qtTranslator = installQtTranslator(code);
    m_current = code;
    if (m_engine)
        m_engine->retranslate();
    Q_EMIT currentChanged();
    return true;
}

QVariantList Language::available() const
{
    QVariantList list;
    for (const Entry &e : kLanguages)
        list << QVariantMap{{QStringLiteral("code"), QString::fromLatin1(e.code)},
                            {QStringLiteral("name"), QString::fromUtf8(e.nativeName)}};
    return list;
}

} // namespace kontur
