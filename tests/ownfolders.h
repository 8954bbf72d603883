// Data and settings folders of the test process's own, so that tests running at the same time share
// nothing: the variants of one test binary (locales, software and OpenGL backends) and other builds'
// tests on the same machine. QStandardPaths' test mode would not do: it puts every process under the
// same ~/.qttest, and so one run's recovery copy or QSettings reached another (tst_files under three
// locales failed once in 750 parallel runs). Include this in exactly one file of a test executable.
#pragma once

#include <QDir>
#include <QString>
#include <QTemporaryDir>
#include <QtGlobal>

#include <cstdio>
#include <cstdlib>

namespace kontur::test {

// The process's folder; XDG_DATA_HOME and XDG_CONFIG_HOME point below it. Removed at exit.
inline const QTemporaryDir &ownFolders()
{
    static const QTemporaryDir dir(QDir::tempPath() + QStringLiteral("/kontur-test-XXXXXX"));
    return dir;
}

// True when the folders Kontur writes to (the recovery copy, QSettings) are the process's own.
inline bool inOwnFolders(const QString &path)
{
    return path.startsWith(ownFolders().path() + QLatin1Char('/'));
}

namespace detail {

// Before main(): QSettings takes its folder once, at its first use, and nothing may read the user's
// settings before the test sets the folders.
inline void setOwnFolders()
{
    const QTemporaryDir &dir = ownFolders();
    if (!dir.isValid()) {
        std::fputs("cannot create a temporary folder for the test's data and settings\n", stderr);
        std::abort();
    }
    qputenv("XDG_DATA_HOME", dir.filePath(QStringLiteral("data")).toLocal8Bit());
    qputenv("XDG_CONFIG_HOME", dir.filePath(QStringLiteral("config")).toLocal8Bit());
}
Q_CONSTRUCTOR_FUNCTION(setOwnFolders)

} // namespace detail

} // namespace kontur::test
