// Save dialogs' answers as local paths with the format's extension (models/controllers/savepath.h).
#include "models/controllers/savepath.h"

#include <QDir>
#include <QFileInfo>

namespace kontur {

namespace {

// The path a URL stands for: a file: URL's local path, a scheme-less URL's text (Qt 6.4's dialog
// makes its answer so); empty for any other scheme.
QString pathOf(const QUrl &file)
{
    if (file.isLocalFile())
        return file.toLocalFile();
    if (!file.scheme().isEmpty() && file.scheme().size() > 1) // one letter: a Windows drive
        return {};
    return file.toString();
}

} // namespace

QString savePathFor(const QUrl &file, const QString &extension, const QString &baseFolder)
{
    QString path = pathOf(file);
    if (path.isEmpty())
        return {};
    // A file: URL typed after the dialog's folder ("/home/a/file:///tmp/x.dxf").
    if (const qsizetype at = path.indexOf(QLatin1String("/file:")); at >= 0)
        path = QUrl::fromUserInput(path.mid(at + 1)).toLocalFile();
    // An absolute path typed after the folder ("/home/a" + "/" + "/tmp/x.dxf"): a clean folder path
    // has no empty segment, so the first "//" is where the typed one begins.
    if (const qsizetype at = path.indexOf(QLatin1String("//")); at >= 0)
        path = path.mid(at + 1);
    if (!QDir::isAbsolutePath(path))
        path = QDir(baseFolder.isEmpty() ? QDir::currentPath() : baseFolder).filePath(path);
    // No name typed: the answer is the folder itself.
    if (path.endsWith(QLatin1Char('/')) || QFileInfo(path).isDir())
        return {};
    const QFileInfo info(QDir::cleanPath(path));
    QString name = info.fileName();
    while (name.endsWith(QLatin1Char('.'))) // "a." is "a", not "a..dxf"
        name.chop(1);
    if (name.isEmpty())
        return {};
    if (QFileInfo(name).suffix().compare(extension, Qt::CaseInsensitive) != 0)
        name += QLatin1Char('.') + extension;
    return info.dir().filePath(name);
}

QString suggestedFileName(const QUrl &documentFile, const QString &extension, const QString &untitled)
{
    const QString base = documentFile.isEmpty() ? untitled : QFileInfo(pathOf(documentFile)).completeBaseName();
    return (base.isEmpty() ? untitled : base) + QLatin1Char('.') + extension;
}

} // namespace kontur
