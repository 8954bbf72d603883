// The window's shell in the real window: a message shown before a language switch is in the new
// language after it (and the other translated texts of the models with it); a shortcut and its tool
// bar button run the same Action; the PNG export writes a picture of the canvas's size or reports
// why it could not; the side panel is one, docked beside the canvas on wide windows and pinned
// tablets, in the bottom sheet on narrow ones (tst_layout_window tests the layouts in depth); the
// unsaved-changes question answers through the shared ConfirmDialog.
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"

#include <QImage>
#include <QImageReader>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <memory>

using kontur::CurveCanvas;
using kontur::CurveKind;
using kontur::EditController;
using kontur::Message;

class TestShellWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QString bannerText() const { return item(QStringLiteral("messageText"))->property("text").toString(); }
    bool addBezier(double shift)
    {
        return m_editor->placement()->createFromCoordinates(
            static_cast<int>(CurveKind::Bezier),
            QVariantList{QVariantList{shift, 0}, QVariantList{shift + 50, 80}, QVariantList{shift + 100, 80},
                         QVariantList{shift + 150, 0}});
    }

    kontur::Language *m_language = nullptr;

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanupTestCase() { m_engine.reset(); }
    void messageFollowsLanguageSwitch();
    void shortcutAndButtonShareTheAction();
    void pngExportWritesCanvasSize();
    void pngExportReportsUnwritablePath();
    void fileErrorDetailsAreTranslated();
    void onePanelDocksOnWideWindows();
    void unsavedChangesAskFirst();
};

void TestShellWindow::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
    m_language = m_engine->findChild<kontur::Language *>();
    QVERIFY(m_language);
    QVERIFY(m_dir.isValid());
}

void TestShellWindow::init()
{
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
    m_files->newDocument();
    m_editor->clearMessage();
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
}

// Texts from i18n/kontur_lv.ts, written out.
void TestShellWindow::messageFollowsLanguageSwitch()
{
    m_editor->showMessage(Message::FileSaved, {QStringLiteral("pattern.kontur")});
    QTRY_VERIFY(item(QStringLiteral("messageBanner"))->isVisible());
    QCOMPARE(bannerText(), QStringLiteral("Saved “pattern.kontur”."));
    screenshot(QStringLiteral("shell-message-en.png"));
    // The switch itself updates the banner: no wait.
    QVERIFY(m_language->setCurrent(QStringLiteral("lv")));
    QCOMPARE(bannerText(), QStringLiteral("Fails „pattern.kontur“ saglabāts."));
    screenshot(QStringLiteral("shell-message-lv.png"));
    // A number in a message takes the new language's format with it (decimal comma).
    m_editor->showMessage(Message::OutOfRange);
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    QVERIFY2(bannerText().contains(QStringLiteral("(about 1.8E+308)")), qPrintable(bannerText()));
    QVERIFY(m_language->setCurrent(QStringLiteral("lv")));
    QCOMPARE(bannerText(), QStringLiteral("Pārāk liela vērtība: koordinātas pārsniegtu lielāko skaitli, ko Kontur "
                                          "var glabāt (aptuveni 1,8E+308). Nekas netika mainīts."));
    // The other translated texts of the editor follow as well: the question before "Reset all" and
    // the kind names of the New curve menu.
    QCOMPARE(m_editor->property("resetQuestion").toString(),
             QStringLiteral("Vai vēlaties visu notīrīt? Visas līknes tiks noņemtas."));
    const QVariantList kinds = m_editor->placement()->property("kinds").toList();
    QVERIFY(!kinds.isEmpty());
    QCOMPARE(kinds.at(static_cast<int>(CurveKind::Bezier)).toMap().value(QStringLiteral("name")).toString(),
             QStringLiteral("Bezjē līkne"));
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    QCOMPARE(kinds.size(), m_editor->placement()->property("kinds").toList().size());
    QCOMPARE(m_editor->placement()
                 ->property("kinds")
                 .toList()
                 .at(static_cast<int>(CurveKind::Bezier))
                 .toMap()
                 .value(QStringLiteral("name")),
             QStringLiteral("Bézier curve"));
}

void TestShellWindow::shortcutAndButtonShareTheAction()
{
    QVERIFY(addBezier(0));
    QVERIFY(addBezier(200));
    QVERIFY(addBezier(400));
    QCOMPARE(m_editor->document()->curveCount(), 3);
    auto *undo = m_window->findChild<QObject *>(QStringLiteral("undoAction"));
    auto *redo = m_window->findChild<QObject *>(QStringLiteral("redoAction"));
    QVERIFY(undo && redo);
    QSignalSpy undone(undo, SIGNAL(triggered(QObject *)));
    QSignalSpy redone(redo, SIGNAL(triggered(QObject *)));
    // Ctrl+Z and the Undo button: the same Action, one undo step each.
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(undone.count(), 1);
    QQuickItem *undoButton = item(QStringLiteral("undoButton"));
    QVERIFY(undoButton && undoButton->isEnabled());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(undoButton));
    QTRY_COMPARE(m_editor->document()->curveCount(), 1);
    QCOMPARE(undone.count(), 2);
    // Redo by its platform key, by Ctrl+Shift+Z (the same key on Linux: once, not twice or never)
    // and by the button.
    QTest::keySequence(m_window, QKeySequence(QKeySequence::Redo));
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QCOMPARE(redone.count(), 1);
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_COMPARE(m_editor->document()->curveCount(), 3);
    QCOMPARE(redone.count(), 2);
    QVERIFY(!m_editor->canRedo());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(undoButton));
    QTRY_COMPARE(m_editor->document()->curveCount(), 2);
    QQuickItem *redoButton = item(QStringLiteral("redoButton"));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(redoButton));
    QTRY_COMPARE(m_editor->document()->curveCount(), 3);
    QCOMPARE(redone.count(), 3);
    // Nothing to undo: the Action and its button are disabled together.
    while (m_editor->canUndo())
        m_editor->undo();
    QTRY_VERIFY(!undoButton->isEnabled());
    QVERIFY(!undo->property("enabled").toBool());
    const int before = undone.count();
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(kontur::test::settled(m_window)); // a frame after the key: an undo would show by now
    QCOMPARE(undone.count(), before);
}

void TestShellWindow::pngExportWritesCanvasSize()
{
    QVERIFY(addBezier(-75));
    const double zoom = m_canvas->zoom();
    const QSize canvasSize = m_canvas->size().toSize();
    QVERIFY(!canvasSize.isEmpty());
    // No suffix given: ".png" is added.
    QVERIFY(m_exporter->exportPng(m_canvas, QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("picture"))), 1.0));
    QTRY_COMPARE(m_editor->message().id, Message::FileSaved);
    QCOMPARE(m_editor->message().args.value(0).toString(), QStringLiteral("picture.png"));
    QImageReader reader(m_dir.filePath(QStringLiteral("picture.png")));
    QCOMPARE(reader.format(), QByteArray("png"));
    const QImage picture = reader.read();
    QCOMPARE(picture.size(), canvasSize);
    // The curve is in it: the pixel under its middle is dark, a corner is the background.
    const QPointF mid = m_canvas->toScreen(QPointF(0, 60));
    QVERIFY(qGray(picture.pixel(mid.toPoint())) < 128);
    QCOMPARE(QColor(picture.pixel(2, 2)), QColor(Qt::white));

    // Twice the size, of the whole document: the view is back as it was afterwards, drawn as before.
    m_editor->clearMessage();
    m_canvas->zoomIn();
    m_canvas->zoomIn();
    const double zoomed = m_canvas->zoom();
    const QPointF center = m_canvas->center();
    QVERIFY(zoomed != zoom);
    QVERIFY(
        m_exporter->exportPng(m_canvas, QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("whole.png"))), 2.0, true));
    QVERIFY(!m_canvas->isLayered()); // drawn directly for the picture
    QTRY_COMPARE(m_editor->message().id, Message::FileSaved);
    QCOMPARE(QImage(m_dir.filePath(QStringLiteral("whole.png"))).size(), canvasSize * 2);
    QCOMPARE(m_canvas->zoom(), zoomed);
    QCOMPARE(m_canvas->center(), center);
    QVERIFY(m_canvas->isLayered());
}

void TestShellWindow::pngExportReportsUnwritablePath()
{
    QVERIFY(addBezier(-75));
    const QString path = m_dir.filePath(QStringLiteral("no such folder/picture.png"));
    QVERIFY(m_exporter->exportPng(m_canvas, QUrl::fromLocalFile(path), 2.0));
    QTRY_COMPARE(m_editor->message().id, Message::FileWriteError);
    QCOMPARE(m_editor->message().args.value(0).toString(), QStringLiteral("picture.png"));
    QVERIFY(!m_editor->message().args.value(1).toString().isEmpty());
    QVERIFY(bannerText().startsWith(QStringLiteral("Could not write “picture.png”: ")));
    QVERIFY(!QFile::exists(path));
    QVERIFY(m_canvas->isLayered());
    // No grab at all: nothing is started.
    QVERIFY(!m_exporter->exportPng(nullptr, QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("x.png")))));
    QVERIFY(!m_exporter->exportPng(m_canvas, QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("x.png"))), 0.0));
}

// Why a file was not read is said in the message's language, chosen by the error's code and place (the
// file layer's English sentence is for logs and kontur-cli), and follows a language switch.
void TestShellWindow::fileErrorDetailsAreTranslated()
{
    const QString csv = m_dir.filePath(QStringLiteral("bad.csv"));
    {
        QFile file(csv);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("x,y\n1,2\n3,abc\n");
    }
    QVERIFY(!m_files->importFile(QUrl::fromLocalFile(csv), static_cast<int>(CurveKind::Bezier)));
    QTRY_COMPARE(m_editor->message().id, Message::FileReadError);
    QCOMPARE(bannerText(), QStringLiteral("Could not read “bad.csv”: line 3, column 3: a number was expected here."));
    QVERIFY(m_language->setCurrent(QStringLiteral("lv")));
    QCOMPARE(bannerText(), QStringLiteral("Nevarēja nolasīt failu „bad.csv“: 3. rinda, 3. kolonna: šeit bija gaidīts skaitlis."));
    // A damaged document: the place is the document's own (curves[0].points[1][1]).
    const QString doc = m_dir.filePath(QStringLiteral("broken.kontur"));
    {
        QFile file(doc);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "kontur", "version": 1, "units": "px", "curves": [{"kind": "bezier", "points": )"
                   R"([[0, 0], [1, "x"]]}]})");
    }
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    QVERIFY(!m_files->open(QUrl::fromLocalFile(doc)));
    QTRY_COMPARE(m_editor->message().args.value(0).toString(), QStringLiteral("broken.kontur"));
    QCOMPARE(bannerText(), QStringLiteral("Could not read “broken.kontur”: at curves[0].points[1][1]: a value of the "
                                          "wrong type (a number, a text or a list where another belongs)."));
    // In every other language: translated around the place, nothing of the English detail left.
    for (const QString &code : {QStringLiteral("lv"), QStringLiteral("sk"), QStringLiteral("bg"), QStringLiteral("ru")}) {
        QVERIFY(m_language->setCurrent(code));
        const QString text = bannerText();
        QVERIFY2(text.contains(QStringLiteral("curves[0].points[1][1]")), qPrintable(code + QLatin1Char(' ') + text));
        for (const char *english : {"wrong type", "Could not", "number", "where another"})
            QVERIFY2(!text.contains(QLatin1String(english)), qPrintable(code + QLatin1Char(' ') + text));
    }
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
    // A curve the geometry refuses: its number in the file and why, translated.
    const QString list = m_dir.filePath(QStringLiteral("same.txt"));
    {
        QFile file(list);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("curve natural uniform\n0 0\n0 0\n0 0\n");
    }
    QVERIFY(!m_files->importFile(QUrl::fromLocalFile(list), static_cast<int>(CurveKind::Bezier)));
    QTRY_COMPARE(m_editor->message().args.value(0).toString(), QStringLiteral("same.txt"));
    QCOMPARE(bannerText(), QStringLiteral("Could not read “same.txt”: curve 1: all its points are at the same place."));
    QVERIFY(m_language->setCurrent(QStringLiteral("ru")));
    QCOMPARE(bannerText(), QStringLiteral("Не удалось прочитать файл «same.txt»: кривая 1: все её точки находятся в одном месте."));
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
}

void TestShellWindow::onePanelDocksOnWideWindows()
{
    QVERIFY(addBezier(0));
    m_editor->selection()->selectRow(0);
    QList<QQuickItem *> panels = m_window->findChildren<QQuickItem *>(QStringLiteral("sidePanel"));
    kontur::test::collectItems(m_window->contentItem(), QStringLiteral("sidePanel"), panels);
    panels.removeAll(nullptr);
    std::sort(panels.begin(), panels.end());
    panels.erase(std::unique(panels.begin(), panels.end()), panels.end());
    QCOMPARE(panels.size(), 1);
    QQuickItem *panel = panels.first();
    QObject *drawer = m_window->findChild<QObject *>(QStringLiteral("panelDrawer"));
    QVERIFY(drawer);
    QQuickItem *sheet = item(QStringLiteral("bottomSheet"));
    QVERIFY(sheet);
    QQuickItem *panelButton = item(QStringLiteral("panelButton"));

    // Wide (docked) and landscape tablet (the drawer, pinned at first): beside the canvas, not modal,
    // the canvas ending where it begins.
    for (const QSize size : {QSize(1920, 1080), QSize(1280, 800)}) {
        m_window->resize(size);
        QTRY_COMPARE(m_window->size(), size);
        QTRY_VERIFY(panel->isVisible());
        QTRY_COMPARE(drawer->property("position").toDouble(), 1.0);
        QVERIFY(!drawer->property("modal").toBool());
        QVERIFY(!sheet->isVisible());
        const auto side = [&] { return panel->mapRectToScene(panel->boundingRect()); };
        QTRY_VERIFY2(side().right() <= size.width() + 0.5 && side().right() >= size.width() - 1.5,
                     qPrintable(QStringLiteral("panel %1..%2").arg(side().left()).arg(side().right())));
        const QRectF canvas = m_canvas->mapRectToScene(m_canvas->boundingRect());
        QVERIFY2(!side().intersects(canvas), "the panel covers the canvas");
        QVERIFY(side().top() >= canvas.top());
        QCOMPARE(side().bottom(), canvas.bottom());
        screenshot(QStringLiteral("shell-%1x%2.png").arg(size.width()).arg(size.height()));
    }
    // The Panel button hides and shows it there; the canvas takes the room.
    m_window->resize(1920, 1080);
    QTRY_COMPARE(m_window->size(), QSize(1920, 1080));
    QTRY_COMPARE(m_canvas->width(), 1920.0 - drawer->property("width").toDouble());
    const double docked = m_canvas->width();
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(panelButton));
    QTRY_VERIFY(!panel->isVisible());
    QTRY_COMPARE(m_canvas->width(), double(m_window->width()));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(panelButton));
    QTRY_VERIFY(panel->isVisible());
    QTRY_COMPARE(m_canvas->width(), docked);
    // Narrow: the same panel in the bottom sheet over the canvas's bottom; the canvas keeps the width.
    m_window->resize(640, 900);
    QTRY_COMPARE(m_window->size(), QSize(640, 900));
    QTRY_VERIFY(sheet->isVisible());
    QVERIFY(sheet->isAncestorOf(panel));
    QVERIFY(panel->isVisible());
    QVERIFY(!drawer->property("visible").toBool());
    QCOMPARE(m_canvas->width(), 640.0);
    const QRectF canvas = m_canvas->mapRectToScene(m_canvas->boundingRect());
    QTRY_COMPARE(sheet->mapRectToScene(sheet->boundingRect()).bottom(), canvas.bottom());
    screenshot(QStringLiteral("shell-640x900-sheet.png"));
    // The panel toggle never goes into the overflow menu: it is on the bar, inside the window. It
    // lowers the sheet away and brings it back.
    QVERIFY(panelButton->isVisible());
    QTRY_VERIFY(kontur::test::centerOf(panelButton).x() < m_window->width());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(panelButton));
    QTRY_VERIFY(!sheet->isVisible());
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(panelButton));
    QTRY_VERIFY(sheet->isVisible());
    QTRY_VERIFY(panel->isVisible());
    // Wide again: docked again.
    m_window->resize(1920, 1080);
    QTRY_COMPARE(m_window->size(), QSize(1920, 1080));
    QTRY_VERIFY(!sheet->isVisible());
    QTRY_VERIFY(panel->isVisible());
    QTRY_COMPARE(drawer->property("position").toDouble(), 1.0);
}

// Ctrl+N with unsaved changes asks first: Cancel keeps the document, "Don't save" goes on with the
// new document and closes the question.
void TestShellWindow::unsavedChangesAskFirst()
{
    QVERIFY(addBezier(0));
    QVERIFY(m_editor->isModified());
    QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("unsavedDialog"));
    QVERIFY(dialog);
    QTest::keyClick(m_window, Qt::Key_N, Qt::ControlModifier);
    QTRY_VERIFY(dialog->property("opened").toBool());
    QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
    QTRY_VERIFY(!dialog->property("visible").toBool());
    QCOMPARE(m_editor->document()->curveCount(), 1);
    QTest::keyClick(m_window, Qt::Key_N, Qt::ControlModifier);
    QTRY_VERIFY(dialog->property("opened").toBool());
    // The buttons of the question: Save, Don't save, Cancel (Kontur's own, in this order of roles).
    QQuickItem *dontSave = nullptr;
    QStringList texts;
    std::function<void(QQuickItem *)> find = [&](QQuickItem *it) {
        if (it->isVisible() && it->inherits("QQuickAbstractButton")) {
            texts << it->property("text").toString();
            if (it->property("text").toString() == QStringLiteral("Don’t save"))
                dontSave = it;
        }
        for (QQuickItem *child : it->childItems())
            find(child);
    };
    find(dialog->property("footer").value<QQuickItem *>());
    QVERIFY2(dontSave, qPrintable(texts.join(QStringLiteral(", "))));
    QCOMPARE(texts.size(), 3);
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(dontSave));
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
    QTRY_VERIFY(!dialog->property("visible").toBool());
    QVERIFY(!m_editor->isModified());
    // The recovery question has two answers only.
    QObject *recovery = m_window->findChild<QObject *>(QStringLiteral("recoveryDialog"));
    QVERIFY(recovery);
    int buttons = 0;
    std::function<void(QQuickItem *)> count = [&](QQuickItem *it) {
        buttons += it->inherits("QQuickAbstractButton") ? 1 : 0;
        for (QQuickItem *child : it->childItems())
            count(child);
    };
    count(recovery->property("footer").value<QQuickItem *>());
    QCOMPARE(buttons, 2);
}

QTEST_MAIN(TestShellWindow)
#include "tst_shell_window.moc"
