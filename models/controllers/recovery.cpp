#include "models/controllers/recovery.h"

#include "io/document.h"
#include "models/document/documentio.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>
#include <cmath>

namespace kontur {

Recovery::Recovery(QObject *parent)
    : QObject(parent)
{
    QSettings settings;
    // Whole labs set it in kontur.conf, scripts in the environment: a bad value (0 made the timer
    // fire continuously, a negative one turned autosave off) is clamped and said.
    QString note;
    if (const QVariant stored = settings.value(QStringLiteral("autosaveSeconds")); stored.isValid()) {
        m_autosaveSeconds = autosaveSecondsFrom(
            stored.toString(), QStringLiteral("autosaveSeconds in ") + QDir::toNativeSeparators(settings.fileName()),
            note);
        if (!note.isEmpty())
            m_autosaveGiven = stored.toString();
    }
    if (const QByteArray env = qgetenv("KONTUR_AUTOSAVE_SECONDS"); !env.isEmpty()) {
        QString envNote;
        m_autosaveSeconds =
            autosaveSecondsFrom(QString::fromLocal8Bit(env), QStringLiteral("KONTUR_AUTOSAVE_SECONDS"), envNote);
        // The environment wins over the file, and so does what is said about it.
        note = envNote;
        m_autosaveGiven = envNote.isEmpty() ? QString() : QString::fromLocal8Bit(env);
    }
    m_autosaveNote = note;
    if (!note.isEmpty())
        qWarning("kontur: %s", qPrintable(note));
    // This instance's recovery copy: a name of its own (process id and a random part).
    m_ownRecovery = QDir(recoveryFolder())
                        .filePath(QStringLiteral("%1-%2.kontur")
                                      .arg(QCoreApplication::applicationPid())
                                      .arg(QUuid::createUuid().toString(QUuid::Id128).left(8)));
    findOrphans();
    m_autosave.setSingleShot(false);
    connect(&m_autosave, &QTimer::timeout, this, [this] { (void)autosaveNow(); });
    updateTimer();
}

Recovery::~Recovery() = default;

void Recovery::setEditor(EditController *editor)
{
    if (editor == m_editor)
        return;
    m_editor = editor;
    if (m_editor && !m_autosaveNote.isEmpty())
        m_editor->showMessage(Message::AutosaveSettingClamped, {m_autosaveGiven, m_autosaveSeconds});
    Q_EMIT editorChanged();
}

void Recovery::setFiles(DocumentFiles *files)
{
    if (files == m_files)
        return;
    disconnect(m_workGone);
    m_files = files;
    if (m_files)
        m_workGone = connect(m_files, &DocumentFiles::unsavedWorkGone, this, &Recovery::discardOwnRecovery);
    Q_EMIT filesChanged();
}

int Recovery::autosaveSecondsFrom(const QString &text, const QString &source, QString &note)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        note = QStringLiteral("%1 = \"%2\" is not a number of seconds; autosaving every %3 seconds")
                   .arg(source, text)
                   .arg(kDefaultAutosaveSeconds);
        return kDefaultAutosaveSeconds;
    }
    const int seconds =
        static_cast<int>(std::clamp(std::round(value), double(kMinAutosaveSeconds), double(kMaxAutosaveSeconds)));
    if (seconds != value)
        note = QStringLiteral("%1 = %2 is outside %3 to %4 seconds (or not whole); autosaving every %5 seconds")
                   .arg(source, text)
                   .arg(kMinAutosaveSeconds)
                   .arg(kMaxAutosaveSeconds)
                   .arg(seconds);
    return seconds;
}

QString Recovery::recoveryFolder()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QDir(dir).filePath(QStringLiteral("recovery"));
}

QString Recovery::recoveryPath()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QDir(dir).filePath(QStringLiteral("recovery.kontur"));
}

QStringList Recovery::recoveryFiles()
{
    QStringList files;
    const QDir folder(recoveryFolder());
    for (const QString &name : folder.entryList({QStringLiteral("*.kontur")}, QDir::Files, QDir::Name))
        files.append(folder.filePath(name));
    // The one copy of versions before per-instance copies.
    const QString legacy = recoveryPath();
    if (QFileInfo::exists(legacy))
        files.append(legacy);
    return files;
}

void Recovery::findOrphans()
{
    const QStringList before = m_orphans;
    for (const QString &file : recoveryFiles()) {
        if (file == m_ownRecovery || m_orphanLocks.count(file) > 0)
            continue;
        auto lock = std::make_unique<QLockFile>(file + QStringLiteral(".lock"));
        // Stale only when its process is gone (not by age: a live instance keeps it for days).
        lock->setStaleLockTime(0);
        if (!lock->tryLock(0))
            continue; // a running instance's copy
        m_orphans.append(file);
        m_orphanLocks.emplace(file, std::move(lock));
    }
    if (m_orphans != before)
        Q_EMIT recoveryChanged();
}

void Recovery::setAutosaveSeconds(int seconds)
{
    seconds = std::clamp(seconds, kMinAutosaveSeconds, kMaxAutosaveSeconds);
    if (seconds == m_autosaveSeconds)
        return;
    m_autosaveSeconds = seconds;
    QSettings().setValue(QStringLiteral("autosaveSeconds"), seconds);
    updateTimer();
    Q_EMIT autosaveSecondsChanged();
}

void Recovery::updateTimer()
{
    m_autosave.start(m_autosaveSeconds * 1000);
}

bool Recovery::autosaveNow()
{
    if (!m_editor || !m_editor->isModified())
        return false;
    QDir().mkpath(recoveryFolder());
    if (!m_ownLock) {
        auto lock = std::make_unique<QLockFile>(m_ownRecovery + QStringLiteral(".lock"));
        lock->setStaleLockTime(0);
        if (!lock->tryLock(0))
            return false;
        m_ownLock = std::move(lock);
    }
    return io::saveDocument(m_ownRecovery, toDocumentData(*m_editor->document())).ok();
}

bool Recovery::recover()
{
    if (!m_editor || !m_files || !hasRecovery())
        return false;
    if (!m_files->openRecovered(m_orphans.front()))
        return false;
    // The work is this instance's now: in its own copy before the orphan goes.
    if (autosaveNow())
        discardRecovery();
    return true;
}

void Recovery::discardRecovery()
{
    if (!hasRecovery())
        return;
    const QString orphan = m_orphans.takeFirst();
    QFile::remove(orphan);
    m_orphanLocks.erase(orphan); // unlocks and removes the lock file
    Q_EMIT recoveryChanged();
}

void Recovery::discardOwnRecovery()
{
    QFile::remove(m_ownRecovery);
}

void Recovery::closing()
{
    m_autosave.stop();
    discardOwnRecovery();
    m_ownLock.reset();
    m_orphanLocks.clear(); // not answered: offered again next time
    if (!m_orphans.isEmpty()) {
        m_orphans.clear();
        Q_EMIT recoveryChanged();
    }
}

} // namespace kontur
