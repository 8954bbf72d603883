// Language: the user interface language, switchable at run time without a restart.
// One instance per QML engine; QML sees it as the singleton `Language`.
#pragma once

// installTranslator() and installQtTranslator(), shared with kontur-cli.
#include "io/translations.h"

#include <QObject>
#include <QPointer>
#include <QTranslator>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <memory>

class QQmlEngine;
class QJSEngine;

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class Language : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON
    Q_PROPERTY(QString current READ current WRITE setCurrent NOTIFY currentChanged)
    Q_PROPERTY(QVariantList available READ available CONSTANT)

public:
    // Attaches a Language to `engine` (its parent), so that QML's singleton is this object.
    explicit Language(QQmlEngine *engine);
    ~Language() override;
    Q_DISABLE_COPY_MOVE(Language)

    static Language *create(QQmlEngine *qmlEngine, QJSEngine *jsEngine);

    // The codes Kontur is translated to, English (the source language) first.
    [[nodiscard]] static QStringList codes();
    [[nodiscard]] static bool isSupported(const QString &code);
    // The language of the system locale if Kontur has it, else English.
    [[nodiscard]] static QString systemDefault();
    // Remembers the user's choice for the next start (QSettings, per user).
    Q_INVOKABLE static void remember(const QString &code);

    [[nodiscard]] QString current() const { return m_current; }
    // Switches translator and number format, then re-evaluates every qsTr() binding.
    // Unknown codes are refused (returns false) and change nothing.
    bool setCurrent(const QString &code);
    [[nodiscard]] QVariantList available() const;

Q_SIGNALS:
    void currentChanged();

private:
    QPointer<QQmlEngine> m_engine;
    std::unique_ptr<QTranslator> m_translator;
    std::unique_ptr<QTranslator> m_qtTranslator;
    QString m_current = QStringLiteral("en");
};

} // namespace kontur
