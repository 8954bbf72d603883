// Presentation mode; see teachingpresentation.h.
#include "app/teachingpresentation.h"

#include <QSettings>

namespace kontur {

namespace {
const QString kKey = QStringLiteral("presentation");
}

Presentation::Presentation(QObject *parent)
    : QObject(parent)
    , m_enabled(QSettings().value(kKey, false).toBool())
{
}

void Presentation::setEnabled(bool enabled)
{
    if (m_enabled == enabled)
        return;
    m_enabled = enabled;
    QSettings().setValue(kKey, enabled);
    Q_EMIT enabledChanged();
}

} // namespace kontur
