// Seam allowance (issue #22) in the real window: Trace menu → "Seam allowance…" opens the dialog with
// the document's unit; a typed width and Add, by touch and by mouse, make one linked allowance at that
// distance (drawn beside its curve); changing its settings is one more undo step; undo takes each
// back.
#include "windowtest.h"

#include "app/curvecanvas.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/selection.h"
#include "models/trace/seamallowance.h"

#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;

class TestSeamWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    static QPoint centerOf(const QQuickItem *it) { return kontur::test::centerOf(it); }

    // A closed piece in millimetres, selected.
    void pieceSelected()
    {
        Curve c = Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}, {40, 120}, {-10, 60}});
        QVERIFY(c.close().ok());
        c.name = QStringLiteral("Front");
        m_editor->replaceDocument({c}, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor->setMode(EditController::Mode::Select);
        m_editor->selection()->select(m_editor->document()->idAt(0));
        m_canvas->fitToView();
        QTest::qWait(20);
    }

    // Trace menu → Seam allowance…: the dialog is open.
    void openDialog()
    {
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("traceMenuButton"))));
        QQuickItem *entry = nullptr;
        QTRY_VERIFY((entry = item(QStringLiteral("traceSeamAllowance"))) && entry->isVisible() && entry->width() > 0);
        QVERIFY(entry->isEnabled());
        QVERIFY(kontur::test::clickMenuItem(m_window, entry));
        QTRY_VERIFY(item(QStringLiteral("seamAdd")) && item(QStringLiteral("seamAdd"))->isVisible());
        QTRY_VERIFY(item(QStringLiteral("seamDistance"))->width() > 0);
    }

    void typeWidth(const QString &text)
    {
        QQuickItem *field = item(QStringLiteral("seamDistance"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(field));
        QTRY_VERIFY(field->hasActiveFocus());
        QTest::keySequence(m_window, QKeySequence::SelectAll);
        for (const QChar c : text)
            QTest::keyClick(m_window, c.toLatin1());
        QCOMPARE(field->property("text").toString(), text);
    }

    void tap(QQuickItem *it)
    {
        QTest::touchEvent(m_window, m_touch).press(0, centerOf(it));
        QTest::touchEvent(m_window, m_touch).release(0, centerOf(it));
    }

    // The largest |distance(allowance point, source) − d|.
    double worstError(double d) const
    {
        const auto a = m_editor->document()->curve(1).toPiecewise();
        const auto s = m_editor->document()->curve(0).toPiecewise();
        double worst = 0.0;
        for (int i = 0; i < a.segmentCount(); ++i)
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, std::abs(s.nearest(a.segments()[i].eval((k + 0.5) / 4)).distance - d));
        return worst;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(start(QSize(1280, 800))); }
    void cleanup()
    {
        if (QQuickItem *close = item(QStringLiteral("seamClose")); close && close->isVisible())
            QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(close));
        QObject *dialog = m_window->findChild<QObject *>(QStringLiteral("seamAllowanceDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }

    void addByTouchThenUndo()
    {
        pieceSelected();
        openDialog();
        QCOMPARE(item(QStringLiteral("seamDistance"))->property("text").toString(), QStringLiteral("10"));
        typeWidth(QStringLiteral("12"));
        tap(item(QStringLiteral("seamAdd")));
        QTRY_COMPARE(m_editor->document()->curveCount(), 2);
        QVERIFY(m_editor->document()->curve(1).seam);
        QCOMPARE(m_editor->document()->curve(1).seam->options.distance, 12.0);
        QVERIFY(worstError(12.0) <= 0.05);
        QCOMPARE(m_editor->undoStack()->count(), 1);
        // The allowance is selected: the button applies its settings now.
        QTRY_COMPARE(item(QStringLiteral("seamAdd"))->property("text").toString(), QStringLiteral("Apply"));
        screenshot(QStringLiteral("seam-allowance-touch.png"));
        m_editor->undo();
        QCOMPARE(m_editor->document()->curveCount(), 1);
    }

    void addByMouseChangeAndUndo()
    {
        pieceSelected();
        openDialog();
        typeWidth(QStringLiteral("8"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("seamAdd"))));
        QTRY_COMPARE(m_editor->document()->curveCount(), 2);
        QVERIFY(worstError(8.0) <= 0.05);
        const Curve created = m_editor->document()->curve(1);
        // Change it to 15 mm: one more undo step; undo gives the 8 mm allowance back exactly.
        typeWidth(QStringLiteral("15"));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, centerOf(item(QStringLiteral("seamAdd"))));
        QTRY_COMPARE(m_editor->document()->curve(1).seam->options.distance, 15.0);
        QCOMPARE(m_editor->undoStack()->count(), 2);
        QVERIFY(worstError(15.0) <= 0.05);
        screenshot(QStringLiteral("seam-allowance-mouse.png"));
        m_editor->undo();
        QVERIFY(m_editor->document()->curve(1).sameState(created));
        m_editor->undo();
        QCOMPARE(m_editor->document()->curveCount(), 1);
    }

    void cleanupTestCase() { m_engine.reset(); }
};

QTEST_MAIN(TestSeamWindow)
#include "tst_seam_window.moc"
