// What outlives a run. The recovery copy: autosaved unsaved work comes back after a crash, each
// running instance keeps its own copy under its own lock, a save or a new document removes it, and a
// bad autosave interval is clamped and said. The recent files, kept in the settings.
#include "../ownfolders.h"
#include "filldocument.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/recentfiles.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using kontur::CurveKind;
using kontur::DocumentFiles;
using kontur::EditController;
using kontur::Exporter;
using kontur::Recovery;
using kontur::test::fill;
using kontur::test::rowsOf;

class TestBetweenRuns final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The recovery copies and the settings are this process's own (ownfolders.h).
    void initTestCase() { QVERIFY(kontur::test::inOwnFolders(Recovery::recoveryPath())); }
    void recoveryBringsBackUnsavedWork();
    void twoInstancesKeepTheirOwnCopies();
    void savingRemovesTheRecoveryCopy();
    void badAutosaveSettingClamped_data();
    void badAutosaveSettingClamped();
    void recentFilesKeptInSettings();
};

void TestBetweenRuns::recoveryBringsBackUnsavedWork()
{
    for (const QString &file : Recovery::recoveryFiles())
        QFile::remove(file);
    std::vector<kontur::Curve> before;
    QString copy;
    {
        EditController editor;
        Recovery recovery;
        recovery.setEditor(&editor);
        QVERIFY(!recovery.hasRecovery());
        QVERIFY(!recovery.autosaveNow()); // nothing unsaved, nothing written
        fill(editor);
        QVERIFY(recovery.autosaveNow());
        copy = recovery.ownRecoveryPath();
        QVERIFY(QFileInfo::exists(copy));
        QVERIFY(!recovery.hasRecovery()); // its own live copy is no crash
        before = editor.document()->curves();
        // The process "crashes" here: no closing(), so the copy stays (its lock goes with it).
    }
    EditController editor;
    DocumentFiles document;
    document.setEditor(&editor);
    Recovery recovery;
    recovery.setEditor(&editor);
    recovery.setFiles(&document);
    QVERIFY(recovery.hasRecovery());
    QCOMPARE(recovery.orphanedRecoveries(), QStringList{copy});
    QVERIFY(recovery.recover());
    QCOMPARE(editor.document()->curveCount(), static_cast<int>(before.size()));
    for (std::size_t c = 0; c < before.size(); ++c)
        QVERIFY(editor.document()->curve(static_cast<int>(c)).sameState(before[c]));
    QVERIFY(editor.isModified()); // recovered work is not saved anywhere yet
    // The work moved into this instance's own copy; the orphan is gone.
    QVERIFY(!recovery.hasRecovery());
    QVERIFY(!QFileInfo::exists(copy));
    QVERIFY(QFileInfo::exists(recovery.ownRecoveryPath()));
    recovery.closing();
    QVERIFY(Recovery::recoveryFiles().isEmpty());
}

// Two instances with one data folder: each writes its own copy under its own lock; neither offers
// (nor discards) the other's live copy; a normal quit removes only its own; a crashed one's copy is
// offered to exactly one instance, which takes its lock. Before, both wrote recovery.kontur, the
// second offered the first's live copy as a crash and Discard deleted it.
void TestBetweenRuns::twoInstancesKeepTheirOwnCopies()
{
    for (const QString &file : Recovery::recoveryFiles())
        QFile::remove(file);
    EditController editorA, editorB;
    Recovery a, b;
    a.setEditor(&editorA);
    b.setEditor(&editorB);
    fill(editorA);
    fill(editorB);
    QVERIFY(a.autosaveNow());
    QVERIFY(b.autosaveNow());
    QVERIFY(a.ownRecoveryPath() != b.ownRecoveryPath());
    QCOMPARE(Recovery::recoveryFiles().size(), 2);
    {
        Recovery third; // started while both run
        QVERIFY(!third.hasRecovery());
        third.discardRecovery();
        third.closing();
    }
    QCOMPARE(Recovery::recoveryFiles().size(), 2);
    b.closing(); // a normal quit
    QVERIFY(QFileInfo::exists(a.ownRecoveryPath()));
    QCOMPARE(Recovery::recoveryFiles(), QStringList{a.ownRecoveryPath()});

    // Two instances crash (their locks go with them, their copies stay): both copies are offered,
    // to the first instance that starts, and not to one started next to it.
    QStringList crashed;
    for (int i = 0; i < 2; ++i) {
        EditController editor;
        Recovery gone;
        gone.setEditor(&editor);
        fill(editor);
        QVERIFY(gone.autosaveNow());
        crashed.append(gone.ownRecoveryPath());
    }
    Recovery first, second;
    QStringList offered = first.orphanedRecoveries();
    offered.sort();
    crashed.sort();
    QCOMPARE(offered, crashed);
    QVERIFY(!second.hasRecovery()); // taken by the first
    first.discardRecovery();
    QVERIFY(first.hasRecovery()); // the other one is asked about next
    first.discardRecovery();
    QVERIFY(!first.hasRecovery());
    QCOMPARE(Recovery::recoveryFiles(), QStringList{a.ownRecoveryPath()});
    a.closing();
    QVERIFY(Recovery::recoveryFiles().isEmpty());
}

// A save or a new document leaves no unsaved work: this instance's own recovery copy goes at once
// (DocumentFiles says so, Recovery removes it), so that a crash right after offers nothing.
void TestBetweenRuns::savingRemovesTheRecoveryCopy()
{
    for (const QString &file : Recovery::recoveryFiles())
        QFile::remove(file);
    QTemporaryDir dir;
    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    Recovery recovery;
    recovery.setEditor(&editor);
    recovery.setFiles(&files);
    fill(editor);
    QVERIFY(recovery.autosaveNow());
    QVERIFY(QFileInfo::exists(recovery.ownRecoveryPath()));
    QVERIFY(files.saveAs(QUrl::fromLocalFile(dir.filePath(QStringLiteral("kept.kontur")))));
    QVERIFY(!QFileInfo::exists(recovery.ownRecoveryPath()));
    QVERIFY(!recovery.autosaveNow()); // saved: nothing to keep
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier), rowsOf({{0, 0}, {5, 5}})));
    QVERIFY(recovery.autosaveNow());
    QVERIFY(QFileInfo::exists(recovery.ownRecoveryPath()));
    files.newDocument(); // the changes given up (the UI asked first)
    QVERIFY(!QFileInfo::exists(recovery.ownRecoveryPath()));
    recovery.closing();
    QVERIFY(Recovery::recoveryFiles().isEmpty());
}

void TestBetweenRuns::badAutosaveSettingClamped_data()
{
    QTest::addColumn<QString>("given");
    QTest::addColumn<int>("used");
    QTest::addColumn<bool>("said");
    QTest::addRow("zero") << QStringLiteral("0") << 1 << true;
    QTest::addRow("negative") << QStringLiteral("-5") << 1 << true;
    QTest::addRow("not a number") << QStringLiteral("soon") << 30 << true;
    QTest::addRow("nan") << QStringLiteral("nan") << 30 << true;
    QTest::addRow("huge") << QStringLiteral("1e300") << 3600 << true;
    QTest::addRow("fraction") << QStringLiteral("0.001") << 1 << true;
    QTest::addRow("fine") << QStringLiteral("45") << 45 << false;
}

// autosaveSeconds = 0 made the timer fire continuously (90 % CPU), a negative value turned
// autosave off; from kontur.conf or the environment it is now clamped to 1 … 3600 s (a text that
// is no number: 30 s) and said, on stderr and in the message line.
void TestBetweenRuns::badAutosaveSettingClamped()
{
    QFETCH(QString, given);
    QFETCH(int, used);
    QFETCH(bool, said);
    for (const bool fromEnvironment : {false, true}) {
        if (fromEnvironment) {
            QSettings().remove(QStringLiteral("autosaveSeconds"));
            qputenv("KONTUR_AUTOSAVE_SECONDS", given.toLocal8Bit());
        } else {
            qunsetenv("KONTUR_AUTOSAVE_SECONDS");
            QSettings().setValue(QStringLiteral("autosaveSeconds"), given);
        }
        if (said)
            QTest::ignoreMessage(QtWarningMsg, QRegularExpression(QStringLiteral("^kontur: .*%1.*every %2 seconds")
                                                                      .arg(QRegularExpression::escape(given))
                                                                      .arg(used)));
        EditController editor;
        Recovery recovery;
        recovery.setEditor(&editor);
        QCOMPARE(recovery.autosaveSeconds(), used);
        QCOMPARE(recovery.autosaveNote().isEmpty(), !said);
        QCOMPARE(editor.message().id == kontur::Message::AutosaveSettingClamped, said);
        if (said)
            QVERIFY(editor.messageText().contains(given));
    }
    qunsetenv("KONTUR_AUTOSAVE_SECONDS");
    QSettings().remove(QStringLiteral("autosaveSeconds"));
}

// The recent files: the latest first, each once, at most eight, kept in the settings for the next
// start; what DocumentFiles opens or saves is added, an export is not.
void TestBetweenRuns::recentFilesKeptInSettings()
{
    QSettings().remove(QStringLiteral("recentFiles"));
    QTemporaryDir dir;
    const auto named = [&](const QString &name) { return dir.filePath(name); };
    {
        kontur::RecentFiles recent;
        QVERIFY(recent.paths().isEmpty());
        QSignalSpy changed(&recent, &kontur::RecentFiles::pathsChanged);
        for (int i = 0; i < 10; ++i)
            recent.add(named(QStringLiteral("%1.kontur").arg(i)));
        QCOMPARE(changed.count(), 10);
        QCOMPARE(recent.paths().size(), kontur::RecentFiles::kCount);
        QCOMPARE(recent.paths().front(), named(QStringLiteral("9.kontur")));
        QCOMPARE(recent.paths().back(), named(QStringLiteral("2.kontur")));
        recent.add(named(QStringLiteral("5.kontur"))); // again: to the front, not twice
        QCOMPARE(recent.paths().front(), named(QStringLiteral("5.kontur")));
        QCOMPARE(recent.paths().count(named(QStringLiteral("5.kontur"))), 1);
        QCOMPARE(recent.paths().size(), 8);
    }
    kontur::RecentFiles next; // the next start
    QCOMPARE(next.paths().size(), 8);
    QCOMPARE(next.paths().front(), named(QStringLiteral("5.kontur")));

    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    files.setRecent(&next);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier), rowsOf({{0, 0}, {5, 5}})));
    QVERIFY(exporter.exportSvg(QUrl::fromLocalFile(named(QStringLiteral("out.svg")))));
    QCOMPARE(next.paths().front(), named(QStringLiteral("5.kontur")));
    QVERIFY(files.saveAs(QUrl::fromLocalFile(named(QStringLiteral("saved.kontur")))));
    QCOMPARE(next.paths().front(), named(QStringLiteral("saved.kontur")));
    files.newDocument();
    QVERIFY(files.open(QUrl::fromLocalFile(named(QStringLiteral("out.svg"))))); // imported as a new document
    QCOMPARE(next.paths().mid(0, 2),
             (QStringList{named(QStringLiteral("out.svg")), named(QStringLiteral("saved.kontur"))}));
    QSettings().remove(QStringLiteral("recentFiles"));
}

QTEST_GUILESS_MAIN(TestBetweenRuns)
#include "tst_betweenruns.moc"
