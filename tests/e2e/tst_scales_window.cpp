// Numbers at every scale in the real window (issue #17): documents with coordinates around 1e7 and
// around 1e150 open, the window keeps drawing, the curve list shows finite lengths of the right
// magnitude, the coordinates table shows sensible text; a number typed into the table (1e300)
// becomes exactly that double while the untouched axis keeps every digit; nothing is lost on save.
#include "windowtest.h"

#include "../curveids.h"
#include "app/curvecanvas.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"

#include <QElapsedTimer>
#include <QFile>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

using kontur::CurveCanvas;
using kontur::EditController;
using kontur::geo::Point;

namespace {

// A document of two curves as Kontur writes it (docs/file-formats.md §2): a composite curve by its
// control vector (knot, handle, handle, knot, …) and a cubic Bézier curve, at `s` times the unit
// shape, shifted by `shift`.
struct Shape
{
    std::vector<Point> composite;
    std::vector<Point> bezier;
};

Shape shapeAt(double s, double shift)
{
    Shape shape;
    for (const Point &p : {Point(0.123456789, 0.987654321), Point(1, 2), Point(3, 2.5), Point(4, 0.5), Point(5, -1.5),
                           Point(7, -1), Point(8, 1)})
        shape.composite.push_back(Point(shift + s * p.x(), shift + s * p.y()));
    for (const Point &p : {Point(0, -2), Point(2.000000001, 1.23456789), Point(6, 3), Point(8, -2)})
        shape.bezier.push_back(Point(shift + s * p.x(), shift + s * p.y()));
    return shape;
}

QByteArray number(double v)
{
    return QByteArray::number(v, 'g', 17);
}

QByteArray pointsJson(const std::vector<Point> &points)
{
    QByteArray out;
    for (std::size_t i = 0; i < points.size(); ++i)
        out += (i ? ", [" : "[") + number(points[i].x()) + ", " + number(points[i].y()) + "]";
    return out;
}

QByteArray documentJson(const Shape &shape)
{
    return "{\n  \"format\": \"kontur\",\n  \"version\": 1,\n  \"units\": \"mm\",\n  \"curves\": [\n"
           "    {\"kind\": \"composite\", \"name\": \"Outline\", \"color\": \"#1f77b4\", \"visible\": true, "
           "\"locked\": false, \"closed\": false, \"points\": [" +
           pointsJson(shape.composite) +
           "], \"nodeTypes\": [\"smooth\", \"corner\", \"smooth\"], \"settings\": {}},\n"
           "    {\"kind\": \"bezier\", \"name\": \"Arc\", \"color\": \"#d62728\", \"visible\": true, "
           "\"locked\": false, \"closed\": false, \"points\": [" +
           pointsJson(shape.bezier) + "], \"settings\": {}}\n  ]\n}\n";
}

} // namespace

class TestScalesWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QQuickItem *item(const QString &name) const { return kontur::test::findVisibleItem(m_window, name); }
    // Opens the document of `shape` written as JSON by hand, as the File menu does.
    bool open(const Shape &shape, const QString &name);
    // The window draws a new frame when asked: the GUI thread is not stuck (an arc length asked to an
    // accuracy doubles cannot resolve froze the app for minutes).
    void keepsDrawing();
    // The texts the curve list shows (its delegates' second lines).
    QStringList listTexts() const;
    void type(const QString &field, const QString &text);
    void verifyDocument(const Shape &shape) const;
    void verifyListAndTable(double magnitude);

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanupTestCase() { m_engine.reset(); }
    void documentAt_data();
    void documentAt();
    void typed1e300();
};

void TestScalesWindow::initTestCase()
{
    QVERIFY(start(QSize(1280, 800)));
    QVERIFY(m_dir.isValid());
}

void TestScalesWindow::init()
{
    m_files->newDocument();
    QTRY_COMPARE(m_editor->document()->curveCount(), 0);
}

bool TestScalesWindow::open(const Shape &shape, const QString &name)
{
    const QString path = m_dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(documentJson(shape)) < 0)
        return false;
    file.close();
    return m_files->open(QUrl::fromLocalFile(path));
}

void TestScalesWindow::keepsDrawing()
{
    QSignalSpy frames(m_window, &QQuickWindow::frameSwapped);
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < 3; ++i) {
        const qsizetype before = frames.count();
        m_window->update();
        QTRY_VERIFY_WITH_TIMEOUT(frames.count() > before, 30000);
    }
    // For a person reading the log (no timed assertion: a loaded machine is slower).
    qInfo("3 frames in %lld ms", static_cast<long long>(clock.elapsed()));
}

QStringList TestScalesWindow::listTexts() const
{
    QStringList texts;
    QList<QQuickItem *> all;
    QQuickItem *list = item(QStringLiteral("curveList"));
    if (!list)
        return texts;
    std::function<void(QQuickItem *)> collect = [&](QQuickItem *it) {
        const QString text = it->property("text").toString();
        if (it->isVisible() && text.contains(QStringLiteral(" · ")))
            texts << text;
        for (QQuickItem *child : it->childItems())
            collect(child);
    };
    collect(list);
    return texts;
}

void TestScalesWindow::type(const QString &field, const QString &text)
{
    kontur::test::typeIntoTable(m_window, field, text);
    QTRY_COMPARE(kontur::test::findVisibleItem(m_window, field)->property("text").toString(), text);
}

void TestScalesWindow::verifyDocument(const Shape &shape) const
{
    const kontur::Document &document = *m_editor->document();
    QCOMPARE(document.curveCount(), 2);
    QCOMPARE(document.curve(0).definingPoints(), shape.composite);
    QCOMPARE(document.curve(1).definingPoints(), shape.bezier);
}

void TestScalesWindow::verifyListAndTable(double magnitude)
{
    // The list's lengths: finite, of the shape's size (the composite's polygon is about 12 units
    // long, the Bézier curve's chord 8: between 8 and 20 units either way).
    for (int row = 0; row < 2; ++row) {
        const double length =
            m_editor->curves()->data(m_editor->curves()->index(row), kontur::CurveListModel::LengthRole).toDouble();
        QVERIFY2(std::isfinite(length) && length > 8 * magnitude && length < 20 * magnitude,
                 qPrintable(QString::number(length, 'g', 17)));
    }
    QStringList texts;
    QTRY_VERIFY_WITH_TIMEOUT((texts = listTexts()).size() == 2, 10000);
    for (const QString &text : texts) {
        QVERIFY2(text.contains(QStringLiteral("length ")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("inf"), Qt::CaseInsensitive) && !text.contains(QStringLiteral("nan")),
                 qPrintable(text));
    }
    // The table: no "inf", and every cell's text fits its cell.
    for (int row = 0; row < 4; ++row) {
        for (const char *axis : {"x", "y"}) {
            QQuickItem *cell = nullptr;
            QTRY_VERIFY((cell = item(QStringLiteral("%1%2").arg(QLatin1String(axis)).arg(row))) && cell->isVisible());
            const QString text = cell->property("text").toString();
            QVERIFY2(!text.isEmpty() && !text.contains(QStringLiteral("inf"), Qt::CaseInsensitive), qPrintable(text));
            const double room =
                cell->width() - cell->property("leftPadding").toDouble() - cell->property("rightPadding").toDouble();
            QVERIFY2(cell->property("contentWidth").toDouble() <= room,
                     qPrintable(QStringLiteral("%1 does not fit %2 px").arg(text).arg(room)));
        }
    }
}

void TestScalesWindow::documentAt_data()
{
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("shift");
    QTest::addColumn<double>("magnitude");
    // Micrometre CAD exports: a shape of a few hundred units, 1e7 from the origin.
    QTest::addRow("around 1e7") << 100.0 << 1e7 << 100.0;
    QTest::addRow("around 1e100") << 1e100 << 0.0 << 1e100;
    QTest::addRow("around 1e150") << 1e150 << 0.0 << 1e150;
}

void TestScalesWindow::documentAt()
{
    QFETCH(double, scale);
    QFETCH(double, shift);
    QFETCH(double, magnitude);
    const Shape shape = shapeAt(scale, shift);
    QVERIFY2(open(shape, QStringLiteral("scale.kontur")), qPrintable(m_editor->messageText()));
    QVERIFY2(m_editor->message().isEmpty(), qPrintable(m_editor->messageText()));
    verifyDocument(shape);
    m_editor->selection()->selectRow(1);
    keepsDrawing();
    verifyListAndTable(magnitude);
    // Fit shows the whole drawing (8 × 5.5 times the scale) within the zoom range (1e-140 … 1e140):
    // it spans at least half the canvas's width or height and fits inside it.
    QVERIFY(QMetaObject::invokeMethod(m_canvas, "fitToView"));
    keepsDrawing();
    const double spanX = 8.0 * scale, spanY = 5.5 * scale;
    const double z = m_canvas->zoom();
    if (scale <= 1e130) {
        QVERIFY2(spanX * z <= m_canvas->width() && spanY * z <= m_canvas->height(), qPrintable(QString::number(z)));
        QVERIFY2(spanX * z >= 0.5 * m_canvas->width() || spanY * z >= 0.5 * m_canvas->height(),
                 qPrintable(QString::number(z)));
    } else {
        QCOMPARE(z, CurveCanvas::minimumZoom()); // as far out as the view goes
    }
    screenshot(QStringLiteral("scales-%1.png")
                   .arg(QString::fromLatin1(QTest::currentDataTag()).section(QLatin1Char(' '), -1)));
    // Saved and opened again: every number as given.
    const QString saved = m_dir.filePath(QStringLiteral("saved.kontur"));
    QVERIFY(m_files->saveAs(QUrl::fromLocalFile(saved)));
    QVERIFY(m_files->open(QUrl::fromLocalFile(saved)));
    verifyDocument(shape);
    keepsDrawing();
}

void TestScalesWindow::typed1e300()
{
    const Shape shape = shapeAt(100.0, 1e7);
    QVERIFY2(open(shape, QStringLiteral("typed.kontur")), qPrintable(m_editor->messageText()));
    m_editor->selection()->selectRow(1);
    keepsDrawing();
    // X of the Bézier curve's second point typed on the keyboard, then OK.
    type(QStringLiteral("x1"), QStringLiteral("1e300"));
    QQuickItem *ok = item(QStringLiteral("applyCoordinatesButton"));
    QTRY_VERIFY(ok && ok->isEnabled());
    kontur::test::ensureVisible(ok);
    QTRY_VERIFY(
        QRectF(QPointF(0, 0), m_window->size()).contains(ok->mapToScene(QPointF(ok->width() / 2, ok->height() / 2))));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(ok));
    QTRY_COMPARE(m_editor->document()->curve(1).definingPoint(1).x(), 1e300);
    // The untouched Y keeps every digit (the table shows 10,000,123).
    QCOMPARE(m_editor->document()->curve(1).definingPoint(1).y(), shape.bezier[1].y());
    QCOMPARE(m_editor->document()->curve(0).definingPoints(), shape.composite);
    QVERIFY(m_editor->message().isEmpty());
    keepsDrawing();
    // Shown in exponent form (English writes a capital E), not as 301 digits nor "inf".
    QTRY_COMPARE(item(QStringLiteral("x1"))->property("text").toString(), QStringLiteral("1E+300"));
    // The list: the Bézier curve now runs out to x = max 3t(1 - t)² · 1e300 = 4/9 · 1e300 and back
    // (the rest of it is within 1e7 of the origin): 8/9 · 1e300 long.
    const double length =
        m_editor->curves()->data(m_editor->curves()->index(1), kontur::CurveListModel::LengthRole).toDouble();
    QVERIFY2(std::abs(length - 8.888888888888889e299) <= 1e-9 * 8.888888888888889e299,
             qPrintable(QString::number(length, 'g', 17)));
    QStringList texts;
    QTRY_VERIFY_WITH_TIMEOUT((texts = listTexts()).size() == 2, 10000);
    QVERIFY2(texts[1].contains(QStringLiteral("length 8.89E+299")), qPrintable(texts[1]));
    // Fit the view to it all: the canvas keeps drawing at 1e300.
    QVERIFY(QMetaObject::invokeMethod(m_canvas, "fitToView"));
    keepsDrawing();
    screenshot(QStringLiteral("scales-1e300.png"));
    // One undo takes it back exactly.
    m_editor->undo();
    verifyDocument(shape);
}

QTEST_MAIN(TestScalesWindow)
#include "tst_scales_window.moc"
