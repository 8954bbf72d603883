// FilePaths: what Kontur's file dialog (qml/FileBrowserDialog.qml) asks about paths: what a path
// typed into its path field names, the file a save answer writes, the folder's breadcrumbs and a
// name filter's patterns. Decisions on paths only (nothing is written), as free functions tested
// without a window, and a QML singleton that hands them to the dialog as URLs.
#pragma once

#include <QObject>
#include <QQmlEngine>
#include <QString>
#include <QStringList>
#include <QUrl>
#include <QVariantList>
#include <QVariantMap>

namespace kontur {

// The absolute, clean local path that `typed` names in a dialog showing `folder` (a local path): a
// file: URL is its path, "~" the home folder, a relative path is taken from `folder`; surrounding
// spaces are dropped. Empty when nothing is typed or a URL is not local.
[[nodiscard]] QString typedPath(const QString &typed, const QString &folder);

// The patterns of a name filter as Qt's file dialogs write them: "Images (*.png *.jpg)" is
// {"*.png", "*.jpg"}; a filter without parentheses is its patterns itself ("*.txt *.csv").
[[nodiscard]] QStringList filterPatterns(const QString &filter);

// The folders from the root down to `folder` (a clean absolute local path), as {name, path}: "/" is
// the root's name.
struct Crumb
{
    QString name;
    QString path;
};
[[nodiscard]] QList<Crumb> crumbsOf(const QString &folder);

class FilePaths final : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_SINGLETON
    Q_DISABLE_COPY_MOVE(FilePaths)

public:
    // What a typed path names: a folder, an existing file, a new file in an existing folder, or
    // nothing (its folder does not exist); a folder that cannot be listed is Unreadable.
    enum class Kind { Folder, File, NewFile, Missing, Unreadable };
    Q_ENUM(Kind)

    explicit FilePaths(QObject *parent = nullptr);

    // `typed` in the dialog showing `folder`: {kind (Kind), url (what it names), folder (the url's
    // folder, or the url itself for a folder), path (the local path, for messages)}.
    Q_INVOKABLE QVariantMap resolve(const QString &typed, const QUrl &folder) const;
    // The file a save dialog writes for the name `typed` in `folder`, with `suffix` ("dxf", no dot;
    // empty for none) appended as DocumentFiles appends it (savepath.h: "a.svg" saved as DXF is
    // "a.svg.dxf"); empty when `typed` names no file.
    Q_INVOKABLE QUrl saveTarget(const QString &typed, const QUrl &folder, const QString &suffix) const;
    Q_INVOKABLE bool exists(const QUrl &file) const;
    // The folder's path as the path field shows it (native separators).
    Q_INVOKABLE QString displayPath(const QUrl &folder) const;
    // The folder above `folder`; empty at the root.
    Q_INVOKABLE QUrl parentFolder(const QUrl &folder) const;
    // crumbsOf as a list of {name, url}.
    Q_INVOKABLE QVariantList crumbs(const QUrl &folder) const;
    Q_INVOKABLE QStringList patterns(const QString &filter) const { return filterPatterns(filter); }
    Q_INVOKABLE QString fileName(const QUrl &file) const;
    // Where a dialog opened without a folder starts.
    Q_INVOKABLE QUrl homeFolder() const;
};

} // namespace kontur
