// LanguageWatch: tells its owner when the application's language changes, so that properties
// holding translated text announce themselves again (their NOTIFY signals) and QML reads them anew.
// QCoreApplication::installTranslator() and removeTranslator() send QEvent::LanguageChange to the
// application object synchronously, so the texts follow as soon as a translator is switched.
#pragma once

#include <QCoreApplication>
#include <QEvent>
#include <QObject>

#include <functional>
#include <utility>

namespace kontur {

class LanguageWatch final : public QObject
{
public:
    // Owned by `owner` (its QObject parent); calls `changed` on each LanguageChange.
    LanguageWatch(QObject *owner, std::function<void()> changed)
        : QObject(owner)
        , m_changed(std::move(changed))
    {
        if (QCoreApplication *app = QCoreApplication::instance())
            app->installEventFilter(this);
    }
    Q_DISABLE_COPY_MOVE(LanguageWatch)

protected:
    // A filter on the application sees every event of the thread: only its own LanguageChange counts.
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::LanguageChange && watched == QCoreApplication::instance())
            m_changed();
        return false;
    }

private:
    std::function<void()> m_changed;
};

} // namespace kontur
