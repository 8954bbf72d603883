// Paths for Kontur's file dialog (models/controllers/filepaths.h).
#include "models/controllers/filepaths.h"

#include "models/controllers/savepath.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace kontur {

QString typedPath(const QString &typed, const QString &folder)
{
    QString path = typed.trimmed();
    if (path.isEmpty())
        return {};
    if (path.startsWith(QLatin1String("file:"), Qt::CaseInsensitive)) {
        const QUrl url(path);
        if (!url.isLocalFile())
            return {};
        path = url.toLocalFile();
    } else if (path == QLatin1String("~") || path.startsWith(QLatin1String("~/"))) {
        path = QDir::homePath() + path.mid(1);
    }
    if (!QDir::isAbsolutePath(path))
        path = QDir(folder.isEmpty() ? QDir::homePath() : folder).filePath(path);
    return QDir::cleanPath(path);
}

QStringList filterPatterns(const QString &filter)
{
    // Qt's own rule (QPlatformFileDialogHelper::cleanFilterList): the patterns between the last
    // parentheses, separated by spaces.
    static const QRegularExpression inParentheses(QStringLiteral("\\(([^()]*)\\)\\s*$"));
    const QRegularExpressionMatch match = inParentheses.match(filter);
    const QString patterns = match.hasMatch() ? match.captured(1) : filter;
    return patterns.split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QList<Crumb> crumbsOf(const QString &folder)
{
    // From the path's text alone: the folders need not exist (nor be readable) to be named.
    QList<Crumb> crumbs;
    if (folder.isEmpty())
        return crumbs;
    QString path = QDir::cleanPath(QDir::fromNativeSeparators(folder));
    while (true) {
        const QString parent = QFileInfo(path).path();
        const bool root = parent == path;
        crumbs.prepend({root ? QDir::toNativeSeparators(path) : QFileInfo(path).fileName(), path});
        if (root)
            break;
        path = parent;
    }
    return crumbs;
}

FilePaths::FilePaths(QObject *parent)
    : QObject(parent)
{
}

QVariantMap FilePaths::resolve(const QString &typed, const QUrl &folder) const
{
    const QString path = typedPath(typed, folder.toLocalFile());
    const QFileInfo info(path);
    Kind kind = Kind::Missing;
    if (path.isEmpty())
        kind = Kind::Missing;
    else if (info.isDir())
        kind = info.isReadable() && info.isExecutable() ? Kind::Folder : Kind::Unreadable;
    else if (info.exists())
        kind = Kind::File;
    else if (!info.fileName().isEmpty() && QFileInfo(info.absolutePath()).isDir())
        kind = Kind::NewFile;
    const QUrl url = path.isEmpty() ? QUrl() : QUrl::fromLocalFile(path);
    const bool folderItself = kind == Kind::Folder || kind == Kind::Unreadable;
    return {{QStringLiteral("kind"), static_cast<int>(kind)},
            {QStringLiteral("url"), url},
            {QStringLiteral("folder"), folderItself || path.isEmpty() ? url : QUrl::fromLocalFile(info.absolutePath())},
            {QStringLiteral("path"), path.isEmpty() ? typed.trimmed() : QDir::toNativeSeparators(path)}};
}

QUrl FilePaths::saveTarget(const QString &typed, const QUrl &folder, const QString &suffix) const
{
    const QString path = typedPath(typed, folder.toLocalFile());
    if (path.isEmpty() || QFileInfo(path).isDir())
        return {};
    if (suffix.isEmpty())
        return QUrl::fromLocalFile(path);
    const QString target = savePathFor(QUrl::fromLocalFile(path), suffix);
    return target.isEmpty() ? QUrl() : QUrl::fromLocalFile(target);
}

bool FilePaths::exists(const QUrl &file) const
{
    return file.isLocalFile() && QFileInfo::exists(file.toLocalFile());
}

QString FilePaths::displayPath(const QUrl &folder) const
{
    return folder.isLocalFile() ? QDir::toNativeSeparators(folder.toLocalFile()) : folder.toString();
}

QUrl FilePaths::parentFolder(const QUrl &folder) const
{
    QDir dir(folder.toLocalFile());
    if (!folder.isLocalFile() || dir.isRoot() || !dir.cdUp())
        return {};
    return QUrl::fromLocalFile(dir.absolutePath());
}

QVariantList FilePaths::crumbs(const QUrl &folder) const
{
    QVariantList list;
    if (!folder.isLocalFile())
        return list;
    for (const Crumb &crumb : crumbsOf(folder.toLocalFile()))
        list << QVariantMap{{QStringLiteral("name"), crumb.name},
                            {QStringLiteral("url"), QUrl::fromLocalFile(crumb.path)}};
    return list;
}

QString FilePaths::fileName(const QUrl &file) const
{
    return QFileInfo(file.isLocalFile() ? file.toLocalFile() : file.toString()).fileName();
}

QUrl FilePaths::homeFolder() const
{
    return QUrl::fromLocalFile(QDir::homePath());
}

} // namespace kontur
