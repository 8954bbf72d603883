// Every kind of message follows a language switch on screen: with an edit refusal in the message
// line, a tracing tool's note in the trace bar, a piece edit's note in the simplify dialog, a piece's
// marks' note in the piece bar, a print
// problem in the print dialog and a file error in the message line, the language is switched
// en → lv → ru → en, and the text each label shows is compared with its translation in that language
// (i18n/kontur_lv.ts, kontur_ru.ts). Each is one Message (models/text/messages.h) held in a
// ShownMessage, made into text when read.
#include "windowtest.h"

#include "../straightpiece.h"

#include "app/language.h"
#include "models/controllers/pieceedits.h"
#include "models/controllers/piecemarks.h"
#include "models/controllers/printcontroller.h"
#include "models/document/document.h"
#include "models/trace/freehandtool.h"
#include "models/trace/tracecontroller.h"

#include <QFile>
#include <QKeySequence>
#include <QtTest>

#include <cmath>
#include <vector>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::Message;
using kontur::PieceEdits;
using kontur::PieceMarkEdits;
using kontur::PrintController;
using kontur::TraceController;

namespace {

// The texts a label shows in English, Latvian and Russian.
struct Texts
{
    QString en, lv, ru;
};

} // namespace

class TestMessagesWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    kontur::Language *m_language = nullptr;

    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QString shown(const QString &name) const
    {
        QQuickItem *label = item(name);
        return label ? label->property("text").toString() : QStringLiteral("<no %1>").arg(name);
    }
    // The label `name` shows `texts` in each language after a switch to it, and is visible.
    void followsSwitch(const QString &name, const Texts &texts)
    {
        QTRY_COMPARE(shown(name), texts.en);
        QVERIFY(item(name)->isVisible());
        QVERIFY(m_language->setCurrent(QStringLiteral("lv")));
        QTRY_COMPARE(shown(name), texts.lv);
        QVERIFY(m_language->setCurrent(QStringLiteral("ru")));
        QTRY_COMPARE(shown(name), texts.ru);
        QVERIFY(item(name)->isVisible());
        screenshot(QStringLiteral("messages-%1-ru.png").arg(name));
        QVERIFY(m_language->setCurrent(QStringLiteral("en")));
        QTRY_COMPARE(shown(name), texts.en);
    }
    // A finger's tap on `it`, scrolled into view first; false when it is not in the window.
    bool tapInView(QQuickItem *it)
    {
        if (!it)
            return false;
        kontur::test::ensureVisible(it);
        const QRectF inScene = it->mapRectToScene(it->boundingRect());
        if (!kontur::test::insideWindow(m_window, inScene.center().toPoint()))
            return false;
        tap(inScene.center().toPoint());
        return true;
    }
    // A wavy open composite curve "Wave" of 40 knots, selected.
    void wave()
    {
        std::vector<kontur::geo::Point> knots;
        for (int i = 0; i < 40; ++i)
            knots.emplace_back(3.0 * i, 20.0 * std::sin(0.1 * i));
        Curve curve = Curve::make(CurveKind::Composite, knots);
        curve.name = QStringLiteral("Wave");
        m_editor->replaceDocument({curve}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->idAt(0));
        QVERIFY(kontur::test::settled(m_window));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(start(QSize(1280, 800)));
        m_language = m_engine->findChild<kontur::Language *>();
        QVERIFY(m_language);
    }
    void init() { QVERIFY(m_language->setCurrent(QStringLiteral("en"))); }
    void cleanupTestCase() { m_engine.reset(); }

    // A refusal of the piece edits (no simpler curve within the tolerance), in the simplify dialog.
    void pieceEditNote()
    {
        wave();
        QQuickItem *simplify = item(QStringLiteral("panel_pieceSimplify"));
        QVERIFY(simplify && simplify->isEnabled());
        QVERIFY(tapInView(simplify)); // by touch; the other controls by mouse
        QQuickItem *field = nullptr;
        QTRY_VERIFY((field = item(QStringLiteral("simplifyTolerance"))) && field->isVisible() && field->width() > 0);
        QVERIFY(kontur::test::clickInView(m_window, field));
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keySequence(m_window, QKeySequence::SelectAll);
        for (const char c : QByteArray("0.000001"))
            QTest::keyClick(m_window, c);
        QCOMPARE(field->property("text").toString(), QStringLiteral("0.000001"));
        QVERIFY(tapInView(item(QStringLiteral("simplifyApply"))));
        auto *edits = m_window->findChild<PieceEdits *>(QStringLiteral("pieceEdits"));
        QVERIFY(edits);
        QTRY_COMPARE(edits->message().id, Message::NotSimpler);
        followsSwitch(QStringLiteral("simplifyMessage"),
                      {QStringLiteral("No curve with fewer knots stays within that tolerance."),
                       QStringLiteral("Nav līknes ar mazāk mezgla punktiem, kas iekļautos šajā precizitātē."),
                       QStringLiteral("Ни одна кривая с меньшим числом узлов не укладывается в этот допуск.")});
        if (QTest::currentTestFailed())
            return;
        QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("simplifyDialog"));
        QVERIFY(dialog);
        QTest::keyClick(m_window, Qt::Key_Escape);
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }

    // An edit refused by the editor's rules (a locked curve), in the message line.
    void editRefusal()
    {
        wave();
        const int id = m_editor->selection()->curveIdValue();
        QVERIFY(m_editor->commands()->setCurveLocked(id, true));
        auto *edits = m_window->findChild<PieceEdits *>(QStringLiteral("pieceEdits"));
        QVERIFY(!edits->simplifyText(id, QStringLiteral("0.2")));
        QTRY_COMPARE(m_editor->message().id, Message::CurveLocked);
        followsSwitch(QStringLiteral("messageText"),
                      {QStringLiteral("“Wave” is locked: unlock it to change it."),
                       QStringLiteral("„Wave“ ir bloķēta: atbloķējiet to, lai mainītu."),
                       QStringLiteral("«Wave» заблокирована: разблокируйте её, чтобы изменить.")});
        if (QTest::currentTestFailed())
            return;
        m_editor->clearMessage();
    }

    // A file that could not be read, with the place and the reason, in the message line.
    void fileError()
    {
        const QString csv = m_dir.filePath(QStringLiteral("bad.csv"));
        {
            QFile file(csv);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write("x,y\n1,2\n3,abc\n");
        }
        QVERIFY(!m_files->importFile(QUrl::fromLocalFile(csv), static_cast<int>(CurveKind::Bezier)));
        QTRY_COMPARE(m_editor->message().id, Message::FileReadError);
        followsSwitch(QStringLiteral("messageText"),
                      {QStringLiteral("Could not read “bad.csv”: line 3, column 3: a number was expected here."),
                       QStringLiteral("Nevarēja nolasīt failu „bad.csv“: 3. rinda, 3. kolonna: šeit bija gaidīts "
                                      "skaitlis."),
                       QStringLiteral("Не удалось прочитать файл «bad.csv»: строка 3, столбец 3: здесь ожидалось "
                                      "число.")});
        if (QTest::currentTestFailed())
            return;
        m_editor->clearMessage();
    }

    // A tracing tool's note (a tolerance that is not a positive number), in the trace bar.
    void traceNote()
    {
        auto *trace = m_window->findChild<TraceController *>(QStringLiteral("trace"));
        QVERIFY(trace);
        trace->setTool(TraceController::Tool::Freehand);
        QVERIFY(!trace->freehand()->setToleranceText(QStringLiteral("x")));
        QCOMPARE(trace->message().id, Message::ToleranceNotPositive);
        followsSwitch(QStringLiteral("traceHint"), {QStringLiteral("The tolerance must be a positive number."),
                                                    QStringLiteral("Precizitātei jābūt pozitīvam skaitlim."),
                                                    QStringLiteral("Допуск должен быть положительным числом.")});
        if (QTest::currentTestFailed())
            return;
        trace->setTool(TraceController::Tool::None);
    }

    // A refusal of the piece's marks (a quantity that is no whole number), in the piece bar.
    void pieceBarNote()
    {
        std::optional<Curve> outline = kontur::test::rectangleOutline(QStringLiteral("Front"));
        QVERIFY(outline);
        outline->piece = kontur::io::PieceMarks{};
        m_editor->replaceDocument({*outline}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->idAt(0), -1);
        auto *marks = m_window->findChild<PieceMarkEdits *>(QStringLiteral("pieceMarks"));
        QVERIFY(marks);
        QTRY_VERIFY(marks->isPiece());
        QQuickItem *button = nullptr;
        QTRY_VERIFY((button = item(QStringLiteral("pieceButton"))) && button->isVisible());
        QVERIFY(kontur::test::standsStill(m_window, button));
        QVERIFY(kontur::test::clickInView(m_window, button));
        QTRY_VERIFY(item(QStringLiteral("pieceBar")) && item(QStringLiteral("pieceBar"))->isVisible());
        QVERIFY(!marks->setQuantityText(QStringLiteral("x")));
        QCOMPARE(marks->message().id, Message::BadQuantity);
        followsSwitch(QStringLiteral("pieceMessage"),
                      {QStringLiteral("Type how many to cut: a whole number from 1 up."),
                       QStringLiteral("Ierakstiet, cik piegriezt: veselu skaitli no 1."),
                       QStringLiteral("Введите, сколько кроить: целое число от 1.")});
        if (QTest::currentTestFailed())
            return;
        QQuickItem *done = item(QStringLiteral("pieceDone"));
        QVERIFY(done && kontur::test::clickInView(m_window, done));
        QTRY_VERIFY(!item(QStringLiteral("pieceBar")) || !item(QStringLiteral("pieceBar"))->isVisible());
    }

    // Why the document cannot be printed (nothing visible), in the print dialog opened from the menu.
    void printProblem()
    {
        m_editor->replaceDocument({}, kontur::Background{}, QStringLiteral("mm"), false);
        QVERIFY(kontur::test::clickInView(m_window, item(QStringLiteral("fileMenuButton"))));
        QQuickItem *entry = nullptr;
        QTRY_VERIFY((entry = item(QStringLiteral("printAction"))) && entry->isVisible() && entry->width() > 0);
        QVERIFY(kontur::test::clickMenuItem(m_window, entry));
        QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("printDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->property("opened").toBool());
        auto *printer = m_window->findChild<PrintController *>(QStringLiteral("printer"));
        QVERIFY(printer);
        QCOMPARE(printer->problem().id, Message::NothingToPrint);
        followsSwitch(QStringLiteral("printSummary"), {QStringLiteral("Nothing to print: no curve is visible."),
                                                       QStringLiteral("Nav ko drukāt: neviena līkne nav redzama."),
                                                       QStringLiteral("Нечего печатать: нет видимых кривых.")});
        if (QTest::currentTestFailed())
            return;
        QVERIFY(kontur::test::clickInView(m_window, item(QStringLiteral("printDialogCancel"))));
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }
};

QTEST_MAIN(TestMessagesWindow)
#include "tst_messages_window.moc"
