// Crash recovery end to end: the real app is started on a points file (unsaved work), killed
// without warning once its recovery copy exists, and the next start's FileController brings the
// work back.
#include "models/controllers/editcontroller.h"
#include "models/controllers/filecontroller.h"

#include <QProcess>
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
    const QString recovery = kontur::FileController::recoveryPath();
    QVERIFY(!QFileInfo::exists(recovery));

    QProcess app;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("QT_QUICK_BACKEND"), QStringLiteral("software"));
    env.insert(QStringLiteral("KONTUR_AUTOSAVE_SECONDS"), QStringLiteral("1"));
    app.setProcessEnvironment(env);
    app.start(QStringLiteral(KONTUR_APP), {QStringLiteral("--lang"), QStringLiteral("en"), points});
    QVERIFY(app.waitForStarted(10000));
    // Opening a points file makes an unsaved document; the copy appears within a second or two.
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(recovery), 20000);
    app.kill(); // no chance to clean up, as in a crash
    QVERIFY(app.waitForFinished(10000));
    QVERIFY(QFileInfo::exists(recovery));

    kontur::EditController editor;
    kontur::FileController files;
    files.setEditor(&editor);
    QVERIFY(files.hasRecovery());
    QVERIFY(files.recover());
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.document()->curve(0).placedCount(), 5);
    QCOMPARE(editor.document()->curve(0).definingPoint(3), kontur::geo::Point(20, 35));
    QVERIFY(editor.isModified());
}

QTEST_GUILESS_MAIN(TestRecovery)
#include "tst_recovery.moc"
