// Recovery: the recovery copy written while there are unsaved changes (every autosaveSeconds), and
// the copies of instances that crashed, offered at the next start. A recovered copy is opened by
// DocumentFiles (`files`), and this instance's own copy is removed when DocumentFiles says the
// unsaved work is gone (saved, or given up for a new document) and when the application closes.
#pragma once

#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"

#include <QLockFile>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

#include <map>
#include <memory>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class Recovery : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // Opens a recovered copy as the document; its unsavedWorkGone removes this instance's copy.
    Q_PROPERTY(kontur::DocumentFiles *files READ files WRITE setFiles NOTIFY filesChanged)
    // A recovery copy of an instance that ended without closing (a crash) is waiting to be offered.
    Q_PROPERTY(bool hasRecovery READ hasRecovery NOTIFY recoveryChanged)
    Q_PROPERTY(int autosaveSeconds READ autosaveSeconds WRITE setAutosaveSeconds NOTIFY autosaveSecondsChanged)

public:
    explicit Recovery(QObject *parent = nullptr);
    ~Recovery() override;
    Q_DISABLE_COPY_MOVE(Recovery)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] DocumentFiles *files() const { return m_files; }
    void setFiles(DocumentFiles *files);
    [[nodiscard]] bool hasRecovery() const { return !m_orphans.isEmpty(); }
    [[nodiscard]] int autosaveSeconds() const { return m_autosaveSeconds; }
    void setAutosaveSeconds(int seconds);
    // The range autosaveSeconds is kept in, and its default.
    static constexpr int kMinAutosaveSeconds = 1, kMaxAutosaveSeconds = 3600, kDefaultAutosaveSeconds = 30;
    // The autosave interval from a setting's text (kontur.conf or KONTUR_AUTOSAVE_SECONDS): a whole
    // number in range as it is; a number out of range clamped; anything else the default. `note`
    // gets an English sentence saying what was wrong and what is used (empty when nothing was).
    [[nodiscard]] static int autosaveSecondsFrom(const QString &text, const QString &source, QString &note);
    // Why the autosave setting was not used as it was given (empty when it was); also on stderr.
    [[nodiscard]] QString autosaveNote() const { return m_autosaveNote; }

    // Recovery copies: one per running instance, <folder>/<id>.kontur, beside a lock file
    // (QLockFile, <id>.kontur.lock) held while the instance runs. A copy whose lock nobody holds is
    // an orphan of an instance that crashed; each one is offered (and its lock taken, so that no
    // other instance offers it too). A live instance's copy is never offered or removed.
    [[nodiscard]] static QString recoveryFolder();
    // The single recovery copy of versions before per-instance copies (offered as an orphan).
    [[nodiscard]] static QString recoveryPath();
    // Every recovery copy in the folder, live or not (also the single recovery.kontur of older versions).
    [[nodiscard]] static QStringList recoveryFiles();
    // This instance's own copy (written by autosaveNow).
    [[nodiscard]] QString ownRecoveryPath() const { return m_ownRecovery; }
    // The orphaned copies taken to be offered, the first one next.
    [[nodiscard]] QStringList orphanedRecoveries() const { return m_orphans; }

    // The first orphaned recovery copy: open it (unsaved, through `files`; it becomes this instance's
    // own copy) or throw it away. The others stay offered (hasRecovery).
    Q_INVOKABLE bool recover();
    Q_INVOKABLE void discardRecovery();
    // Writes the recovery copy now when there are unsaved changes (the timer calls this).
    Q_INVOKABLE bool autosaveNow();
    // Called when the application closes normally: its own recovery copy is removed; orphans not
    // yet answered stay for the next start.
    Q_INVOKABLE void closing();

Q_SIGNALS:
    void editorChanged();
    void filesChanged();
    void recoveryChanged();
    void autosaveSecondsChanged();

private:
    void updateTimer();
    // Takes the lock of every recovery copy nobody holds (orphans) into m_orphans.
    void findOrphans();
    // Removes this instance's own copy (the work is saved, or there is none).
    void discardOwnRecovery();

    QPointer<EditController> m_editor;
    QPointer<DocumentFiles> m_files;
    QMetaObject::Connection m_workGone;
    QTimer m_autosave;
    int m_autosaveSeconds = kDefaultAutosaveSeconds;
    QString m_autosaveNote;
    QString m_autosaveGiven; // the bad setting's text, for the message line
    QString m_ownRecovery;
    std::unique_ptr<QLockFile> m_ownLock;
    QStringList m_orphans;
    std::map<QString, std::unique_ptr<QLockFile>> m_orphanLocks;
};

} // namespace kontur
