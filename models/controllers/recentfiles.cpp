#include "models/controllers/recentfiles.h"

#include <QFileInfo>
#include <QSettings>

namespace kontur {

RecentFiles::RecentFiles(QObject *parent)
    : QObject(parent)
    , m_paths(QSettings().value(QStringLiteral("recentFiles")).toStringList())
{
}

void RecentFiles::add(const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_paths.removeAll(absolute);
    m_paths.prepend(absolute);
    while (m_paths.size() > kCount)
        m_paths.removeLast();
    QSettings().setValue(QStringLiteral("recentFiles"), m_paths);
    Q_EMIT pathsChanged();
}

} // namespace kontur
