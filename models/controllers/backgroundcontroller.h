// BackgroundController: the background picture under the curves (seed: "Upload background"):
// loading, showing or hiding, opacity and removal. Every change is one undo step pushed through the
// EditController that owns it (QML: `editor.background.visible` …); a refused file is reported with
// the seed's message 1 on the editor's message line.
#pragma once

#include "models/document/document.h"
#include "models/text/messages.h"

#include <QObject>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class BackgroundController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("EditController owns the background")
    Q_PROPERTY(QString file READ file NOTIFY changed)
    Q_PROPERTY(bool visible READ visible WRITE setVisible NOTIFY changed)
    Q_PROPERTY(double opacity READ opacity WRITE setOpacity NOTIFY changed)

public:
    explicit BackgroundController(EditController *editor);
    Q_DISABLE_COPY_MOVE(BackgroundController)

    [[nodiscard]] QString file() const;
    [[nodiscard]] bool visible() const;
    void setVisible(bool visible);
    [[nodiscard]] double opacity() const;
    // Clamped to [0, 1].
    void setOpacity(double opacity);
    // The whole background as one undo step; nothing when it is the same.
    void setBackground(const Background &background);
    // Loads a picture; it is placed centred on the world origin at one world unit per pixel. Message
    // 1 when the file is no readable image or too large (picture/picture.h); nothing changes then.
    Q_INVOKABLE bool load(const QUrl &file);
    Q_INVOKABLE void clear();

Q_SIGNALS:
    void changed();
    // The message line's text: the editor shows it (an empty message clears it).
    void report(const kontur::Message &message);

private:
    [[nodiscard]] const Background &current() const;

    EditController *m_editor;
};

} // namespace kontur
