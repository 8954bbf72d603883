// ShownMessage: the one message an object shows (the message line's, a tool's refusal, a dialog's
// problem), held as a Message whose text is made when read. It calls its owner's `announce` when the
// message changes and again after each language switch (LanguageWatch), so that the owner's NOTIFY
// signal makes QML read `message.text` anew, in the new language. Every object that tells the user
// something holds one; none keeps a translated string.
#pragma once

#include "models/text/languagewatch.h"
#include "models/text/messages.h"

#include <functional>
#include <utility>

namespace kontur {

class ShownMessage
{
public:
    // `owner` owns the language watch; `announce` emits the owner's NOTIFY signal of its message.
    ShownMessage(QObject *owner, std::function<void()> announce)
        : m_announce(std::move(announce))
    {
        new LanguageWatch(owner, [this] { m_announce(); });
    }
    Q_DISABLE_COPY_MOVE(ShownMessage)
    ~ShownMessage() = default;

    [[nodiscard]] const Message &message() const { return m_message; }
    [[nodiscard]] bool isEmpty() const { return m_message.isEmpty(); }
    // Shows `message` (None clears); announces only a change.
    void show(Message message)
    {
        if (message == m_message)
            return;
        m_message = std::move(message);
        m_announce();
    }
    void clear() { show(Message()); }

private:
    Message m_message;
    std::function<void()> m_announce;
};

} // namespace kontur
