// RecentFiles: the files last opened, imported or saved, the latest first, kept in the settings
// (recentFiles) for the next start. DocumentFiles adds to it; the File menu lists it.
#pragma once

#include <QObject>
#include <QStringList>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class RecentFiles : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    // Absolute paths, the latest first, at most kCount.
    Q_PROPERTY(QStringList paths READ paths NOTIFY pathsChanged)

public:
    explicit RecentFiles(QObject *parent = nullptr);

    static constexpr int kCount = 8;

    [[nodiscard]] QStringList paths() const { return m_paths; }
    // `path` (made absolute) first, once; the oldest beyond kCount dropped; kept in the settings.
    void add(const QString &path);

Q_SIGNALS:
    void pathsChanged();

private:
    QStringList m_paths;
};

} // namespace kontur
