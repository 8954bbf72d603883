// The save and export dialogs in the real window, driven as a user does with Kontur's own file
// dialog (qml/FileBrowserDialog.qml): File → Export DXF twice and Save as. Each opens on the
// document's name with the format's extension ("bodice.dxf"), not on what was typed the last time;
// its accept button reads Export or Save and is enabled from the start; a name typed with the wrong
// extension is written with the right one appended, and an absolute path typed is taken as it is.
// The units dialog asks once which units a DXF without $INSUNITS is in.
#include "windowtest.h"

#include "io/document.h"
#include "io/dxf.h"

#include <QFileInfo>
#include <QSettings>
#include <QtTest>

class TestDialogsWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    // The dialog the action `action` opens (objectName `dialogName`), shown.
    QObject *openByAction(const QString &action, const QString &dialogName)
    {
        QObject *trigger = m_window->findChild<QObject *>(action);
        QObject *dialog = m_window->findChild<QObject *>(dialogName);
        if (!trigger || !dialog || !QMetaObject::invokeMethod(trigger, "trigger"))
            return nullptr;
        return QTest::qWaitFor([dialog] { return dialog->property("visible").toBool(); }) ? dialog : nullptr;
    }
    QQuickItem *nameField() const { return kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogName")); }
    QQuickItem *acceptButton() const
    {
        return kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogAccept"));
    }
    // Types `text` into the name field as a user does (click, select all, keys) and clicks the accept
    // button (reading `accept`) with the mouse, without Enter: the field's text must count all the same.
    void typeAndAccept(QObject *dialog, const QString &text, const QString &accept)
    {
        QQuickItem *field = nameField();
        QVERIFY(field);
        QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(field));
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        for (const QChar c : text)
            QTest::keyClick(m_window, c.toLatin1());
        QCOMPARE(field->property("text").toString(), text);
        QQuickItem *ok = acceptButton();
        QVERIFY(ok);
        QCOMPARE(ok->property("text").toString(), accept);
        QVERIFY(ok->isEnabled());
        QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(ok));
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(start(QSize(1280, 800))); }
    void cleanupTestCase() { m_engine.reset(); }
    void exportTwiceAndSaveAs();
    void unitlessDxfAsksOnce();
};

void TestDialogsWindow::exportTwiceAndSaveAs()
{
    QVERIFY(m_editor->placement()->createFromCoordinates(
        0, QVariantList{QVariantList{0.0, 0.0}, QVariantList{10.0, 20.0}, QVariantList{30.0, 0.0}}));
    const QString bodice = m_dir.filePath(QStringLiteral("bodice.kontur"));
    QVERIFY(m_files->saveAs(QUrl::fromLocalFile(bodice)));

    // First export: the document's name with .dxf, the button reads Export and is enabled.
    QObject *dialog = openByAction(QStringLiteral("exportDxfAction"), QStringLiteral("dxfDialog"));
    QVERIFY(dialog);
    QCOMPARE(dialog->property("fileMode").toInt(), 2); // as FileDialog.SaveFile
    QCOMPARE(dialog->property("acceptLabel").toString(), QStringLiteral("Export"));
    QCOMPARE(dialog->property("selectedFile").toUrl(),
             QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("bodice.dxf"))));
    QTRY_VERIFY(nameField());
    QCOMPARE(nameField()->property("text").toString(), QStringLiteral("bodice.dxf"));
    QCOMPARE(acceptButton()->property("text").toString(), QStringLiteral("Export"));
    QVERIFY(acceptButton()->isEnabled());
    screenshot(QStringLiteral("export-dxf-dialog.png"));
    // A DXF named .svg: written as a.svg.dxf, and no a.svg.
    typeAndAccept(dialog, QStringLiteral("a.svg"), QStringLiteral("Export"));
    const QString aDxf = m_dir.filePath(QStringLiteral("a.svg.dxf"));
    QTRY_VERIFY(QFileInfo::exists(aDxf));
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("a.svg"))));
    QVERIFY(kontur::io::readDxf(aDxf).ok());

    // Second export: the fresh default name again, not "a.svg"; typing replaces it.
    dialog = openByAction(QStringLiteral("exportDxfAction"), QStringLiteral("dxfDialog"));
    QVERIFY(dialog);
    QTRY_VERIFY(nameField());
    QCOMPARE(nameField()->property("text").toString(), QStringLiteral("bodice.dxf"));
    typeAndAccept(dialog, QStringLiteral("b"), QStringLiteral("Export"));
    QTRY_VERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("b.dxf"))));
    QVERIFY(kontur::io::readDxf(m_dir.filePath(QStringLiteral("b.dxf"))).ok());

    // Save as with an absolute path typed into another folder: not joined to the dialog's folder.
    QVERIFY(QDir(m_dir.path()).mkdir(QStringLiteral("elsewhere")));
    const QString elsewhere = m_dir.filePath(QStringLiteral("elsewhere/copy"));
    dialog = openByAction(QStringLiteral("saveAsAction"), QStringLiteral("saveDialog"));
    QVERIFY(dialog);
    QCOMPARE(dialog->property("acceptLabel").toString(), QStringLiteral("Save"));
    QTRY_VERIFY(nameField());
    QCOMPARE(nameField()->property("text").toString(), QStringLiteral("bodice.kontur"));
    typeAndAccept(dialog, elsewhere, QStringLiteral("Save"));
    QTRY_VERIFY(QFileInfo::exists(elsewhere + QStringLiteral(".kontur")));
    QVERIFY(kontur::io::openDocument(elsewhere + QStringLiteral(".kontur")).ok());
    QCOMPARE(m_files->fileUrl(), QUrl::fromLocalFile(elsewhere + QStringLiteral(".kontur")));

    // Both documents saved are the File menu's recent files; choosing the first one opens it again
    // (nothing unsaved: no question).
    QObject *copy =
        m_window->findChild<QObject *>(QStringLiteral("openRecent:") + elsewhere + QStringLiteral(".kontur"));
    QObject *first = m_window->findChild<QObject *>(QStringLiteral("openRecent:") + bodice);
    QVERIFY(copy && first);
    QVERIFY(QMetaObject::invokeMethod(first, "trigger"));
    QTRY_COMPARE(m_files->fileUrl(), QUrl::fromLocalFile(bodice));
}

// A DXF that does not say its units, dropped on the window: the units dialog asks (mm, cm, in, px);
// cm chosen with the mouse, the drawing comes in converted into the document's mm, with the skipped
// text said in the message line; the next such file is not asked about again, and the message's
// button changes the units, reading that file again in them.
void TestDialogsWindow::unitlessDxfAsksOnce()
{
    QSettings().remove(QStringLiteral("unitlessUnits"));
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
    const QString path = m_dir.filePath(QStringLiteral("unitless.dxf"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0\nSECTION\n2\nENTITIES\n0\nTEXT\n1\nFront\n0\nLINE\n10\n0\n20\n0\n11\n2\n21\n0\n"
                   "0\nENDSEC\n0\nEOF\n");
    }
    QObject *fileActions = m_window->findChild<QObject *>(QStringLiteral("fileActions"));
    QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("unitsDialog"));
    QVERIFY(fileActions && dialog);
    QVERIFY(QMetaObject::invokeMethod(fileActions, "openDropped", Q_ARG(QVariant, QUrl::fromLocalFile(path))));
    QTRY_VERIFY(dialog->property("opened").toBool());
    QCOMPARE(m_editor->document()->curveCount(), 0); // nothing before the answer
    QQuickItem *cm = kontur::test::findVisibleItem(m_window, QStringLiteral("units_cm"));
    QVERIFY(cm);
    QVERIFY(kontur::test::clickInView(m_window, cm));
    QTRY_VERIFY(cm->property("checked").toBool());
    screenshot(QStringLiteral("units-dialog.png"));
    QQuickItem *accept = kontur::test::findVisibleItem(m_window, QStringLiteral("unitsAccept"));
    QVERIFY(accept);
    QVERIFY(kontur::test::clickInView(m_window, accept));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QTRY_VERIFY(!dialog->property("visible").toBool());
    // 2 cm is 20 mm.
    QCOMPARE(m_editor->document()->curve(0).toPiecewise().segments().back().endPoint(), kontur::geo::Point(20, 0));
    QCOMPARE(m_editor->message().id, kontur::Message::FileImportedUnitless);
    QVERIFY(m_editor->messageText().contains(QStringLiteral("1 text")));
    QCOMPARE(QSettings().value(QStringLiteral("unitlessUnits/dxf")).toString(), QStringLiteral("cm"));
    // Asked once: the next drop imports at once, in the remembered unit.
    QVERIFY(QMetaObject::invokeMethod(fileActions, "openDropped", Q_ARG(QVariant, QUrl::fromLocalFile(path))));
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QVERIFY(!dialog->property("visible").toBool());

    // The message offers to change them: its button opens the dialog on cm; inches chosen, the file
    // just dropped is read again in them (2 in = 50.8 mm), the first one stays.
    QQuickItem *change = nullptr;
    QTRY_VERIFY((change = kontur::test::findVisibleItem(m_window, QStringLiteral("messageChangeUnits"))));
    QVERIFY(kontur::test::clickInView(m_window, change));
    QTRY_VERIFY(dialog->property("opened").toBool());
    QQuickItem *inches = kontur::test::findVisibleItem(m_window, QStringLiteral("units_in"));
    QVERIFY(inches);
    QVERIFY(kontur::test::findVisibleItem(m_window, QStringLiteral("units_cm"))->property("checked").toBool());
    QVERIFY(kontur::test::clickInView(m_window, inches));
    QTRY_VERIFY(inches->property("checked").toBool());
    accept = kontur::test::findVisibleItem(m_window, QStringLiteral("unitsAccept"));
    QVERIFY(accept);
    QVERIFY(kontur::test::clickInView(m_window, accept));
    QTRY_VERIFY(!dialog->property("visible").toBool());
    QCOMPARE(QSettings().value(QStringLiteral("unitlessUnits/dxf")).toString(), QStringLiteral("in"));
    QTRY_COMPARE(m_editor->document()->curve(1).toPiecewise().segments().back().endPoint(),
                 kontur::geo::Point(50.8, 0));
    QCOMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(m_editor->document()->curve(0).toPiecewise().segments().back().endPoint(), kontur::geo::Point(20, 0));
    QCOMPARE(m_editor->message().args.value(2).toString(), QStringLiteral("in"));
    QSettings().remove(QStringLiteral("unitlessUnits"));
}

QTEST_MAIN(TestDialogsWindow)
#include "tst_dialogs_window.moc"
