// Crash recovery end to end: the real app is started on a points file (unsaved work); while it runs,
// another instance with the same data folder neither offers nor removes its recovery copy; killed
// without warning, its copy is offered to the next start, also when that start is given a file.
#include "app/application.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/recovery.h"

#include <QProcess>
#include <QQmlApplicationEngine>
#include <QQuickWindow>
#include <QTemporaryDir>
#include <QtTest>

class TestRecovery final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void killedAppLeavesItsWorkRecoverable();
};

void TestRecovery::killedAppLeavesItsWorkRecoverable()
{
    QTemporaryDir home;
    QVERIFY(home.isValid());
    const QString points = home.filePath(QStringLiteral("sleeve.txt"));
    {
        QFile file(points);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("# a sleeve cap\n0 0\n20 35\n60 48\n100 30\n120 0\n");
    }
    // The app and this test share their data folder through XDG_DATA_HOME and the same names.
    qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toLocal8Bit());
    qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("Kontur"));
    QCoreApplication::setApplicationName(QStringLiteral("kontur"));
    QVERIFY(kontur::Recovery::recoveryFiles().isEmpty());

    QProcess app;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("QT_QUICK_BACKEND"), QStringLiteral("software"));
    env.insert(QStringLiteral("KONTUR_AUTOSAVE_SECONDS"), QStringLiteral("1"));
    app.setProcessEnvironment(env);
    app.start(QStringLiteral(KONTUR_APP), {QStringLiteral("--lang"), QStringLiteral("en"), points});
    QVERIFY(app.waitForStarted(10000));
    // Opening a points file makes an unsaved document; the copy appears within a second or two.
    QTRY_VERIFY_WITH_TIMEOUT(kontur::Recovery::recoveryFiles().size() == 1, 20000);
    const QString copy = kontur::Recovery::recoveryFiles().front();

    // A second instance while the first runs: the live copy is no crash; its Discard and its normal
    // quit leave the copy alone (before, both used one file, and Discard deleted the live one).
    {
        kontur::EditController editor;
        kontur::Recovery second;
        second.setEditor(&editor);
        QVERIFY(!second.hasRecovery());
        second.discardRecovery();
        second.closing();
    }
    QVERIFY(QFileInfo::exists(copy));

    app.kill(); // no chance to clean up, as in a crash
    QVERIFY(app.waitForFinished(10000));
    QVERIFY(QFileInfo::exists(copy));

    // The next start is given a file: it opens it and still offers the crashed instance's work.
    {
        QQmlApplicationEngine engine;
        QQuickWindow *window = kontur::loadMainWindow(engine, {QStringLiteral("en"), points, QSize(1000, 700)});
        QVERIFY(window);
        window->show();
        QObject *dialog = window->findChild<QObject *>(QStringLiteral("recoveryDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->property("visible").toBool());
        auto *recovery = window->findChild<kontur::Recovery *>(QStringLiteral("recovery"));
        QVERIFY(recovery);
        QCOMPARE(recovery->orphanedRecoveries(), QStringList{copy});
        QCOMPARE(recovery->editor()->document()->curveCount(), 1); // the file given is open too
        // Quit without answering: the copy stays for the next start.
        recovery->closing();
    }
    QVERIFY(QFileInfo::exists(copy));

    kontur::EditController editor;
    kontur::DocumentFiles document;
    document.setEditor(&editor);
    kontur::Recovery recovery;
    recovery.setEditor(&editor);
    recovery.setFiles(&document);
    QVERIFY(recovery.hasRecovery());
    QVERIFY(recovery.recover());
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.document()->curve(0).placedCount(), 5);
    QCOMPARE(editor.document()->curve(0).definingPoint(3), kontur::geo::Point(20, 35));
    QVERIFY(editor.isModified());
    QVERIFY(!QFileInfo::exists(copy));
    recovery.closing();
    QVERIFY(kontur::Recovery::recoveryFiles().isEmpty());
}

QTEST_MAIN(TestRecovery)
#include "tst_recovery.moc"
