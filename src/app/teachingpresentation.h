// Presentation: the projector mode of the teaching views (issue #9) — larger lines, points and fonts.
// QML sees it as the singleton `Presentation`; the Theme scales its sizes by `factor`. The choice is
// remembered per user (QSettings key "presentation").
#pragma once

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class Presentation : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON
    Q_PROPERTY(bool enabled READ isEnabled WRITE setEnabled NOTIFY enabledChanged)
    // How much larger lines, points and fonts are drawn: 1, or 1.75 in presentation mode.
    Q_PROPERTY(double factor READ factor NOTIFY enabledChanged)

public:
    explicit Presentation(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(Presentation)

    [[nodiscard]] bool isEnabled() const { return m_enabled; }
    // Switches and remembers the choice.
    void setEnabled(bool enabled);
    [[nodiscard]] double factor() const { return m_enabled ? 1.75 : 1.0; }
    Q_INVOKABLE void toggle() { setEnabled(!m_enabled); }

Q_SIGNALS:
    void enabledChanged();

private:
    bool m_enabled = false;
};

} // namespace kontur
