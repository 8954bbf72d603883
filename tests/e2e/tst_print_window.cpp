// Print pattern… in the real window (issue 22): by mouse at 800 × 1280 (File menu, Letter chosen in
// the dialog, Print to PDF) and by touch at 1280 × 800 (orientation Landscape, overlap raised with
// the spin box's + button, Print). The dialog shows the page count the tiling gives before anything
// is written; the PDF written has those pages plus the first one, and opens again as the document.
#include "windowtest.h"

#include "../skipsuite.h"

#include "io/document.h"
#include "io/pdf.h"
#include "models/controllers/printcontroller.h"
#include "print/patternpdf.h"

#include <QGuiApplication>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStyleHints>
#include <QtTest>

using kontur::PrintController;

namespace {

// A 60 × 40 cm rectangle in cm.
kontur::io::DocumentData rectangle()
{
    kontur::io::DocumentData doc;
    doc.units = QStringLiteral("cm");
    const double xs[] = {0, 60, 60, 0, 0}, ys[] = {0, 0, 40, 40, 0};
    for (int i = 0; i < 4; ++i) {
        kontur::io::CurveRecord c;
        c.kind = QStringLiteral("bezier");
        c.name = QStringLiteral("edge %1").arg(i + 1);
        c.points = {kontur::geo::Point(xs[i], ys[i]), kontur::geo::Point(xs[i + 1], ys[i + 1])};
        doc.curves.push_back(c);
    }
    return doc;
}

int pdfPages(const QString &pdf)
{
    QProcess p;
    p.start(QStringLiteral("pdfinfo"), {pdf});
    if (!p.waitForFinished(60000) || p.exitCode() != 0)
        return -1;
    const auto m =
        QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(QString::fromUtf8(p.readAllStandardOutput()));
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

} // namespace

class TestPrintWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QObject *object(const QString &name) const { return m_window->findChild<QObject *>(name); }
    PrintController *printer() const { return m_window->findChild<PrintController *>(QStringLiteral("printer")); }

    void tap(QPoint at, bool touch)
    {
        if (touch) {
            QTest::touchEvent(m_window, m_touch).press(0, at);
            QTest::touchEvent(m_window, m_touch).release(0, at);
        } else {
            QTest::mouseClick(m_window, Qt::LeftButton, {}, at);
        }
    }
    void tapItem(QQuickItem *it, bool touch)
    {
        QVERIFY(it);
        QTRY_VERIFY(it->isVisible() && it->width() > 0);
        tap(kontur::test::centerOf(it), touch);
    }
    // Chooses entry `index` of the ChoiceBox `name`: tap the box, then the entry in its list.
    void choose(const QString &name, int index, bool touch)
    {
        QQuickItem *box = item(name);
        QVERIFY(box);
        tapItem(box, touch);
        auto *popup = box->property("popup").value<QObject *>();
        QVERIFY(popup);
        QTRY_VERIFY(popup->property("opened").toBool());
        auto *list = popup->property("contentItem").value<QQuickItem *>();
        QVERIFY(list);
        QQuickItem *entry = nullptr;
        QVERIFY(QMetaObject::invokeMethod(list, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, entry), Q_ARG(int, index)));
        tapItem(entry, touch);
        QTRY_VERIFY(!popup->property("visible").toBool());
    }
    // The File menu's Print pattern… entry.
    void openFromMenu(bool touch)
    {
        tapItem(item(QStringLiteral("fileMenuButton")), touch);
        QQuickItem *entry = nullptr;
        QTRY_VERIFY((entry = item(QStringLiteral("printAction"))) && entry->isVisible() && entry->width() > 0);
        if (touch) {
            QObject *menu = entry->property("menu").value<QObject *>();
            QTRY_VERIFY(menu->property("opened").toBool());
            tapItem(entry, true);
            QTRY_VERIFY(!menu->property("visible").toBool());
        } else {
            QVERIFY(kontur::test::clickMenuItem(m_window, entry));
        }
        QTRY_VERIFY(object(QStringLiteral("printDialog"))->property("opened").toBool());
    }
    // Print to PDF…, then the file dialog's answer `file`.
    void printTo(const QString &file, bool touch)
    {
        tapItem(item(QStringLiteral("printDialogPrint")), touch);
        QObject *dialog = object(QStringLiteral("pdfDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->property("visible").toBool());
        // The file's path typed into the dialog's name field (select all first), then a tap on Save.
        QQuickItem *name = nullptr;
        QTRY_VERIFY((name = kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogName"))));
        tapItem(name, touch);
        QTRY_VERIFY(name->hasActiveFocus());
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        for (const QChar c : file)
            QTest::keyClick(m_window, c.toLatin1());
        QCOMPARE(name->property("text").toString(), file);
        tapItem(kontur::test::fileDialogItem(m_window, QStringLiteral("fileDialogAccept")), touch);
        QTRY_VERIFY(!dialog->property("visible").toBool());
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (QStandardPaths::findExecutable(QStringLiteral("pdfinfo")).isEmpty())
            kontur::test::skipWholeSuite("pdfinfo (poppler-utils, in packaging/bootstrap) is not installed");
    }
    void cleanup() { m_engine.reset(); }

    void printByMouseAndTouch_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("touch");
        QTest::addRow("mouse 800x1280") << QSize(800, 1280) << false;
        QTest::addRow("touch 1280x800") << QSize(1280, 800) << true;
    }
    void printByMouseAndTouch()
    {
        QFETCH(QSize, size);
        QFETCH(bool, touch);
        QVERIFY(start(size));
        const QString source = m_dir.filePath(QStringLiteral("rect.kontur"));
        QVERIFY(kontur::io::saveDocument(source, rectangle()).ok());
        QVERIFY(m_files->open(QUrl::fromLocalFile(source)));
        PrintController *p = printer();
        QVERIFY(p);
        p->setPaper(PrintController::A4);
        p->setOrientation(PrintController::Auto);
        p->setOverlap(10);

        openFromMenu(touch);
        screenshot(
            QStringLiteral("print-dialog-%1.png").arg(touch ? QStringLiteral("touch") : QStringLiteral("mouse")));
        // 60 × 40 cm (610 × 410 mm with the padding) on A4: portrait 4 × 2 = 8, landscape 3 × 3 = 9.
        QCOMPARE(p->pageCount(), 8);
        QVERIFY(!p->landscape());
        QVERIFY(
            item(QStringLiteral("printSummary"))->property("text").toString().startsWith(QStringLiteral("8 pages")));

        kontur::geo::TilingOptions expected;
        if (touch) {
            choose(QStringLiteral("printOrientation"), 2, true); // Landscape
            QCOMPARE(p->orientation(), PrintController::Landscape);
            QTRY_COMPARE(p->pageCount(), 9);
            // The spin box's + button, five times: 15 mm.
            QQuickItem *spin = item(QStringLiteral("printOverlap"));
            QVERIFY(spin);
            auto *up = spin->property("up").value<QObject *>();
            auto *indicator = up ? up->property("indicator").value<QQuickItem *>() : nullptr;
            QVERIFY(indicator);
            // Each tap one step: taps apart by more than the double-tap time, as a finger taps.
            for (int i = 1; i <= 5; ++i) {
                kontur::test::gestureTime(QGuiApplication::styleHints()->mouseDoubleClickInterval() + 50);
                tapItem(indicator, true);
                QTRY_COMPARE(p->overlap(), 10.0 + i);
            }
            expected.orientation = kontur::geo::PageOrientation::Landscape;
            expected.overlap = 15.0;
        } else {
            choose(QStringLiteral("printPaper"), 1, false); // Letter
            QCOMPARE(p->paper(), PrintController::Letter);
            expected.paper = kontur::geo::kPaperLetter;
        }
        const auto plan = kontur::planPrint(rectangle(), expected);
        QVERIFY(plan.ok());
        QTRY_COMPARE(p->pageCount(), plan->tiling.pageCount());
        QVERIFY(item(QStringLiteral("printSummary"))
                    ->property("text")
                    .toString()
                    .startsWith(QStringLiteral("%1 pages").arg(plan->tiling.pageCount())));
        screenshot(
            QStringLiteral("print-dialog-%1-set.png").arg(touch ? QStringLiteral("touch") : QStringLiteral("mouse")));

        const QString pdf = m_dir.filePath(touch ? QStringLiteral("touch.pdf") : QStringLiteral("mouse.pdf"));
        printTo(pdf, touch);
        QTRY_VERIFY(QFile::exists(pdf));
        QCOMPARE(pdfPages(pdf), plan->pdfPageCount());
        // The PDF opens as the document it was printed from.
        const auto back = kontur::io::openPdfDocument(pdf);
        QVERIFY(back.ok());
        QVERIFY(*back == rectangle());
        QVERIFY(m_files->open(QUrl::fromLocalFile(pdf)));
        QCOMPARE(m_editor->document()->units(), QStringLiteral("cm"));
        QCOMPARE(m_editor->document()->curves().size(), std::size_t(4));
        m_engine.reset();
    }
};

QTEST_MAIN(TestPrintWindow)
#include "tst_print_window.moc"
