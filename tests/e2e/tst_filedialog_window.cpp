// Kontur's own file dialog (qml/FileBrowserDialog.qml) in the real window, by finger and by mouse as a
// user on a tablet without a keyboard walks it: one tap opens a folder, the breadcrumbs and Up go back,
// the path field goes to a typed folder and picks a typed file, a path that leads nowhere is said and
// loses nothing typed, a file far down the list is scrolled into view and picked by one tap and
// accepted by a second; in save mode the name starts as suggested, the format's extension is
// appended, an existing file is replaced only after a question (not in Append, which appends), and
// Enter saves, Escape cancels. At 800 × 1280, 1280 × 800 and 1920 × 1080 the dialog fits the window
// and every control is at least the touch minimum tall.
#include "windowtest.h"

#include "app/language.h"
#include "io/dxf.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QtTest>

class TestFileDialogWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *dialogItem(const QString &name) const { return kontur::test::fileDialogItem(m_window, name); }
    QObject *fileActions() const { return m_window->findChild<QObject *>(QStringLiteral("fileActions")); }
    // A tap by a finger (or a click) on the middle of `it`, once it stands still in view.
    void tapItem(QQuickItem *it, bool touch)
    {
        QVERIFY(kontur::test::standsStill(m_window, it));
        const QPoint at = kontur::test::centerOf(it);
        if (touch)
            tap(at);
        else
            QTest::mouseClick(m_window, Qt::LeftButton, {}, at);
    }
    // The dialog that `action` opens, once it is open and its list has been read.
    QObject *openByAction(const QString &action, const QString &dialogName)
    {
        QObject *trigger = m_window->findChild<QObject *>(action);
        QObject *dialog = m_window->findChild<QObject *>(dialogName);
        if (!trigger || !dialog || !QMetaObject::invokeMethod(trigger, "trigger"))
            return nullptr;
        return QTest::qWaitFor([&] { return dialog->property("opened").toBool() && dialogItem("fileDialogList"); })
                   ? dialog
                   : nullptr;
    }
    // Types `text` into `field` as a user does: a tap, select all, the keys, and Enter when asked.
    void typeInto(QQuickItem *field, const QString &text, bool touch, bool enter)
    {
        QVERIFY(field);
        tapItem(field, touch);
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        for (const QChar c : text)
            QTest::keyClick(m_window, c.toLatin1());
        QCOMPARE(field->property("text").toString(), text);
        if (enter)
            QTest::keyClick(m_window, Qt::Key_Return);
    }
    static QString folderOf(const QObject *dialog) { return dialog->property("currentFolder").toUrl().toLocalFile(); }
    void closed(QObject *dialog) { QTRY_VERIFY(!dialog->property("visible").toBool()); }
    // Every visible control under `root` shorter than the touch minimum (48 px).
    static QStringList shortControls(QQuickItem *root)
    {
        QStringList found;
        std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
            if (!it->isVisible())
                return;
            const bool control = it->inherits("QQuickAbstractButton") || it->inherits("QQuickComboBox") ||
                                 it->inherits("QQuickTextField");
            if (control && it->height() < 47.5)
                found << QStringLiteral("%1 %2").arg(it->objectName(), QString::number(it->height()));
            for (QQuickItem *child : it->childItems())
                walk(child);
        };
        walk(root);
        return found;
    }

    QString m_photos;

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase() { m_engine.reset(); }
    void foldersByOneTap_data();
    void foldersByOneTap();
    void pathField_data() { foldersByOneTap_data(); }
    void pathField();
    void saveAppendsSuffixAndAsks_data() { foldersByOneTap_data(); }
    void saveAppendsSuffixAndAsks();
    void keyboard();
    void fitsEveryWindow_data();
    void fitsEveryWindow();
    void followsARotation();
};

void TestFileDialogWindow::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
    // A folder of photos, more than a list shows at once, with a folder of old ones and a note.
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("photos/old")));
    m_photos = m_dir.filePath(QStringLiteral("photos"));
    QImage picture(40, 30, QImage::Format_RGB32);
    picture.fill(Qt::white);
    for (int i = 1; i <= 40; ++i)
        QVERIFY(picture.save(QDir(m_photos).filePath(QStringLiteral("photo-%1.png").arg(i, 2, 10, QLatin1Char('0')))));
    QFile note(QDir(m_photos).filePath(QStringLiteral("note.txt")));
    QVERIFY(note.open(QIODevice::WriteOnly));
    note.write("not a picture\n");
}

void TestFileDialogWindow::foldersByOneTap_data()
{
    QTest::addColumn<bool>("touch");
    QTest::addRow("touch") << true;
    QTest::addRow("mouse") << false;
}

// Load background image: the folder last used is m_dir; one tap opens photos, the breadcrumb and Up
// go back (Up from photos/old); the filter shows pictures only; the last photo, far below, is scrolled to, picked by one
// tap and loaded by a second.
void TestFileDialogWindow::foldersByOneTap()
{
    QFETCH(bool, touch);
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_files->rememberFolder(QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("any.png"))));
    QVERIFY(QMetaObject::invokeMethod(fileActions(), "loadBackground"));
    QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("backgroundDialog"));
    QVERIFY(dialog);
    QTRY_VERIFY(dialog->property("opened").toBool());
    QCOMPARE(folderOf(dialog), m_dir.path());
    QCOMPARE(dialogItem("fileDialogPath")->property("text").toString(), QDir::toNativeSeparators(m_dir.path()));

    tapItem(kontur::test::fileDialogRow(m_window, QStringLiteral("photos")), touch);
    QTRY_COMPARE(folderOf(dialog), m_photos);
    QTRY_COMPARE(dialogItem("fileDialogPath")->property("text").toString(), QDir::toNativeSeparators(m_photos));
    // Folders first; the note is not a picture and is not listed.
    QVERIFY(kontur::test::fileDialogRow(m_window, QStringLiteral("old")));
    QVERIFY(!dialogItem(QStringLiteral("fileDialogRow_note.txt")));
    QCOMPARE(dialogItem("fileDialogList")->property("count").toInt(), 41);
    screenshot(touch ? QStringLiteral("filedialog-photos-touch.png") : QStringLiteral("filedialog-photos-mouse.png"));

    // The breadcrumbs: the one before the last is m_dir.
    QQuickItem *crumbs = dialogItem("fileDialogCrumbs");
    QVERIFY(crumbs);
    const int count = crumbs->property("count").toInt();
    QVERIFY(count >= 3);
    tapItem(dialogItem(QStringLiteral("fileDialogCrumb%1").arg(count - 2)), touch);
    QTRY_COMPARE(folderOf(dialog), m_dir.path());
    // Up, from a folder of the test's own: the temporary folder's parent is shared with tests running
    // beside this one, whose folders come and go under the finger.
    tapItem(kontur::test::fileDialogRow(m_window, QStringLiteral("photos")), touch);
    QTRY_COMPARE(folderOf(dialog), m_photos);
    tapItem(kontur::test::fileDialogRow(m_window, QStringLiteral("old")), touch);
    QTRY_COMPARE(folderOf(dialog), QDir(m_photos).filePath(QStringLiteral("old")));
    tapItem(dialogItem("fileDialogUp"), touch);
    QTRY_COMPARE(folderOf(dialog), m_photos);

    // The last photo: below the fold, brought into view, picked by one tap (not yet loaded), loaded
    // by the second.
    QQuickItem *last = kontur::test::fileDialogRow(m_window, QStringLiteral("photo-40.png"));
    QVERIFY(last);
    tapItem(last, touch);
    QTRY_VERIFY(last->property("highlighted").toBool());
    QVERIFY(dialog->property("visible").toBool());
    QVERIFY(m_editor->document()->background().file.isEmpty());
    QVERIFY(dialogItem("fileDialogAccept")->isEnabled());
    tapItem(last, touch);
    closed(dialog);
    const QString photo = QDir(m_photos).filePath(QStringLiteral("photo-40.png"));
    QTRY_COMPARE(m_editor->document()->background().file, photo);
    // The next dialog starts there.
    QCOMPARE(m_files->startFolder(), QUrl::fromLocalFile(m_photos));
}

// The path field: a typed folder is gone to; a path that leads nowhere is said, and neither the
// folder nor what was typed is lost; a typed file's path opens it.
void TestFileDialogWindow::pathField()
{
    QFETCH(bool, touch);
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("px"), false);
    m_files->rememberFolder(QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("any.png"))));
    QObject *dialog = openByAction(QStringLiteral("importAction"), QStringLiteral("importDialog"));
    QVERIFY(dialog);
    QCOMPARE(folderOf(dialog), m_dir.path());
    // Two filters: the chooser shows.
    QVERIFY(dialogItem("fileDialogFilter"));
    QVERIFY(!dialogItem("fileDialogName")); // open mode: no name field

    QQuickItem *path = dialogItem("fileDialogPath");
    typeInto(path, m_photos + QStringLiteral("/old"), touch, true);
    QTRY_COMPARE(folderOf(dialog), m_photos + QStringLiteral("/old"));
    QTRY_COMPARE(path->property("text").toString(), QDir::toNativeSeparators(m_photos + QStringLiteral("/old")));
    QVERIFY(!dialogItem("fileDialogMessage"));

    // Nowhere: the message names the path; the folder and the typed text stay.
    const QString nowhere = m_dir.filePath(QStringLiteral("no-such-folder/x"));
    typeInto(path, nowhere, touch, false);
    tapItem(dialogItem("fileDialogGo"), touch);
    QQuickItem *message = nullptr;
    QTRY_VERIFY((message = dialogItem("fileDialogMessage")));
    QVERIFY2(message->property("text").toString().contains(nowhere), qPrintable(message->property("text").toString()));
    QCOMPARE(folderOf(dialog), m_photos + QStringLiteral("/old"));
    QCOMPARE(path->property("text").toString(), nowhere);
    QVERIFY(dialog->property("visible").toBool());
    screenshot(touch ? QStringLiteral("filedialog-nowhere-touch.png") : QStringLiteral("filedialog-nowhere-mouse.png"));

    // A relative folder from the one shown ("..") clears the message.
    typeInto(path, QStringLiteral(".."), touch, true);
    QTRY_COMPARE(folderOf(dialog), m_photos);
    QTRY_VERIFY(!dialogItem("fileDialogMessage"));

    // A file's path: its folder shown, and the file taken (a points file imported).
    const QString points =
        m_dir.filePath(touch ? QStringLiteral("points-touch.txt") : QStringLiteral("points-mouse.txt"));
    {
        QFile file(points);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 0\n10 20\n30 0\n");
    }
    const int before = m_editor->document()->curveCount();
    typeInto(path, points, touch, false);
    tapItem(dialogItem("fileDialogAccept"), touch);
    closed(dialog);
    QTRY_COMPARE(m_editor->document()->curveCount(), before + 1);
}

// Export DXF: the name offered is the document's with .dxf; a name typed without the extension gets
// it; an existing file is replaced only after Replace (Cancel keeps it and the dialog); a tap on a
// file fills the name field. Append to a points file asks nothing: it appends.
void TestFileDialogWindow::saveAppendsSuffixAndAsks()
{
    QFETCH(bool, touch);
    const QString sub = touch ? QStringLiteral("save-touch") : QStringLiteral("save-mouse");
    QVERIFY(QDir(m_dir.path()).mkpath(sub));
    const QDir folder(m_dir.filePath(sub));
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
    QVERIFY(addBezier({{0, 0}, {10, 20}, {20, 20}, {30, 0}}));
    QVERIFY(m_files->saveAs(QUrl::fromLocalFile(folder.filePath(QStringLiteral("bodice.kontur")))));

    QObject *dialog = openByAction(QStringLiteral("exportDxfAction"), QStringLiteral("dxfDialog"));
    QVERIFY(dialog);
    QCOMPARE(dialog->property("fileMode").toInt(), 2); // as FileDialog.SaveFile
    QCOMPARE(folderOf(dialog), folder.path());
    QQuickItem *name = dialogItem("fileDialogName");
    QVERIFY(name);
    QCOMPARE(name->property("text").toString(), QStringLiteral("bodice.dxf"));
    QCOMPARE(dialogItem("fileDialogAccept")->property("text").toString(), QStringLiteral("Export"));
    QVERIFY(!dialogItem("fileDialogFilter")); // one filter: no chooser
    screenshot(touch ? QStringLiteral("filedialog-save-touch.png") : QStringLiteral("filedialog-save-mouse.png"));
    typeInto(name, QStringLiteral("front"), touch, false);
    tapItem(dialogItem("fileDialogAccept"), touch);
    closed(dialog);
    const QString front = folder.filePath(QStringLiteral("front.dxf"));
    QTRY_VERIFY(QFileInfo::exists(front));
    QVERIFY(kontur::io::readDxf(front).ok());

    // "front" again: it exists. Cancel keeps the old file and the dialog; Replace writes it.
    QFile old(front);
    QVERIFY(old.open(QIODevice::WriteOnly | QIODevice::Truncate));
    old.write("old");
    old.close();
    dialog = openByAction(QStringLiteral("exportDxfAction"), QStringLiteral("dxfDialog"));
    QVERIFY(dialog);
    // A tap on the file in the list fills the name field.
    tapItem(kontur::test::fileDialogRow(m_window, QStringLiteral("front.dxf")), touch);
    name = dialogItem("fileDialogName");
    QTRY_COMPARE(name->property("text").toString(), QStringLiteral("front.dxf"));
    tapItem(dialogItem("fileDialogAccept"), touch);
    QObject *question = m_window->findChild<QObject *>(QStringLiteral("fileDialogOverwrite"));
    QVERIFY(question);
    QTRY_VERIFY(question->property("opened").toBool());
    screenshot(touch ? QStringLiteral("filedialog-replace-touch.png") : QStringLiteral("filedialog-replace-mouse.png"));
    QVERIFY(QMetaObject::invokeMethod(question, "reject"));
    QTRY_VERIFY(!question->property("visible").toBool());
    QVERIFY(dialog->property("visible").toBool());
    QCOMPARE(QFileInfo(front).size(), 3);
    typeInto(name, QStringLiteral("front"), touch, false);
    tapItem(dialogItem("fileDialogAccept"), touch);
    QTRY_VERIFY(question->property("opened").toBool());
    // The question's Replace button (a button of its button box).
    QQuickItem *replace = nullptr;
    std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
        if (it->inherits("QQuickAbstractButton") && it->property("text").toString() == QLatin1String("Replace"))
            replace = it;
        for (QQuickItem *child : it->childItems())
            walk(child);
    };
    walk(question->property("footer").value<QQuickItem *>());
    QVERIFY(replace);
    tapItem(replace, touch);
    closed(dialog);
    QTRY_VERIFY(QFileInfo(front).size() > 3);
    QVERIFY(kontur::io::readDxf(front).ok());

    // Append to a points file: an existing file is appended to without a question.
    m_editor->selection()->selectRow(0);
    const QString points = folder.filePath(QStringLiteral("points.txt"));
    {
        QFile file(points);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 0\n1 1\n");
    }
    const qint64 size = QFileInfo(points).size();
    dialog = openByAction(QStringLiteral("appendAction"), QStringLiteral("appendDialog"));
    QVERIFY(dialog);
    tapItem(kontur::test::fileDialogRow(m_window, QStringLiteral("points.txt")), touch);
    QTRY_COMPARE(dialogItem("fileDialogName")->property("text").toString(), QStringLiteral("points.txt"));
    tapItem(dialogItem("fileDialogAccept"), touch);
    closed(dialog); // at once: no question (the question is the dialog's: made and gone with it)
    QTRY_VERIFY(QFileInfo(points).size() > size);
}

// The keyboard: Enter in the name field saves (the extension appended), Escape cancels and writes
// nothing.
void TestFileDialogWindow::keyboard()
{
    m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
    QVERIFY(addBezier({{0, 0}, {10, 20}, {20, 20}, {30, 0}}));
    QVERIFY(m_files->saveAs(QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("keys.kontur")))));
    QObject *dialog = openByAction(QStringLiteral("exportSvgAction"), QStringLiteral("svgDialog"));
    QVERIFY(dialog);
    QQuickItem *name = dialogItem("fileDialogName");
    QTRY_VERIFY(name->hasActiveFocus()); // the name field has the keys from the start
    QCOMPARE(name->property("selectedText").toString(), QStringLiteral("keys")); // the name, not the extension
    for (const QChar c : QStringLiteral("typed"))
        QTest::keyClick(m_window, c.toLatin1());
    QCOMPARE(name->property("text").toString(), QStringLiteral("typed.svg"));
    QTest::keyClick(m_window, Qt::Key_Escape);
    closed(dialog);
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("typed.svg"))));

    dialog = openByAction(QStringLiteral("exportSvgAction"), QStringLiteral("svgDialog"));
    QVERIFY(dialog);
    name = dialogItem("fileDialogName");
    QTRY_VERIFY(name->hasActiveFocus());
    QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
    for (const QChar c : QStringLiteral("entered"))
        QTest::keyClick(m_window, c.toLatin1());
    QTest::keyClick(m_window, Qt::Key_Return);
    closed(dialog);
    QTRY_VERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("entered.svg"))));
}

void TestFileDialogWindow::fitsEveryWindow_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    for (const char *language : {"en", "lv", "ru"}) {
        QTest::addRow("800x1280 %s", language) << QSize(800, 1280) << QString::fromLatin1(language);
        QTest::addRow("1280x800 %s", language) << QSize(1280, 800) << QString::fromLatin1(language);
        QTest::addRow("1920x1080 %s", language) << QSize(1920, 1080) << QString::fromLatin1(language);
    }
}

// Open (three filters) and Save as (a name field) at each size, in English, Latvian and Russian:
// inside the window, every control at least 48 px tall, the buttons in the language.
void TestFileDialogWindow::fitsEveryWindow()
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    auto *lang = m_engine->findChild<kontur::Language *>();
    QVERIFY(lang && lang->setCurrent(language));
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    m_files->newDocument(); // unnamed: the dialogs start in the folder last used
    m_files->rememberFolder(QUrl::fromLocalFile(QDir(m_photos).filePath(QStringLiteral("any.png"))));
    const QString tag = QStringLiteral("%1-%2x%3").arg(language).arg(size.width()).arg(size.height());
    const QStringList english{QStringLiteral("Open"), QStringLiteral("Save"), QStringLiteral("Cancel"),
                              QStringLiteral("Go")};
    for (const auto &[action, name] :
         {std::pair{"openAction", "openDialog"}, std::pair{"saveAsAction", "saveDialog"}}) {
        QObject *dialog = openByAction(QString::fromLatin1(action), QString::fromLatin1(name));
        QVERIFY2(dialog, action);
        auto *popup = dialog->property("contentItem").value<QQuickItem *>()->parentItem();
        QVERIFY(popup);
        QTRY_VERIFY(dialog->property("opened").toBool());
        const QRectF inScene = popup->mapRectToScene(popup->boundingRect());
        QVERIFY2(QRectF(QPointF(0, 0), m_window->size()).contains(inScene), qPrintable(QStringLiteral("%1: %2,%3 %4x%5")
                                                                                           .arg(tag)
                                                                                           .arg(inScene.x())
                                                                                           .arg(inScene.y())
                                                                                           .arg(inScene.width())
                                                                                           .arg(inScene.height())));
        QQuickItem *content = dialogItem(QStringLiteral("fileBrowserContent"));
        QVERIFY(content);
        QVERIFY(kontur::test::fileDialogRow(m_window, QStringLiteral("old")));
        const QStringList small = shortControls(content);
        QVERIFY2(small.isEmpty(), qPrintable(small.join(QStringLiteral(", "))));
        for (const char *button : {"fileDialogAccept", "fileDialogCancel", "fileDialogGo"}) {
            const QString text = dialogItem(QString::fromLatin1(button))->property("text").toString();
            QVERIFY2(language == QLatin1String("en") || !english.contains(text), qPrintable(text));
        }
        screenshot(QStringLiteral("filedialog-%1-%2.png").arg(QString::fromLatin1(name), tag));
        QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
        closed(dialog);
    }
    QVERIFY(lang->setCurrent(QStringLiteral("en")));
    m_window->resize(1280, 800);
}

// A tablet turned while the dialog shows: it is fitted to the window's new shape at once.
void TestFileDialogWindow::followsARotation()
{
    m_window->resize(800, 1280);
    QTRY_COMPARE(m_window->size(), QSize(800, 1280));
    QObject *dialog = openByAction(QStringLiteral("saveAsAction"), QStringLiteral("saveDialog"));
    QVERIFY(dialog);
    auto *popup = dialog->property("contentItem").value<QQuickItem *>()->parentItem();
    QVERIFY(popup);
    const auto inWindow = [&] {
        return QRectF(QPointF(0, 0), m_window->size()).contains(popup->mapRectToScene(popup->boundingRect()));
    };
    QTRY_VERIFY(inWindow());
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
    QTRY_VERIFY(inWindow());
    QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
    closed(dialog);
}

QTEST_MAIN(TestFileDialogWindow)
#include "tst_filedialog_window.moc"
