// The classroom on a projector, checked in the real window: every control of the window and of each
// teaching view is at least 48 px in both dimensions at three window sizes; in presentation mode at
// 1920 × 1080, in all five languages, no control of a teaching view or bar lies outside it, no text
// is elided or cut, and the view's Close button is reached and closes it; the bottom sheet of a phone
// grows in three distinct steps, the drawer leaves the side panel button free, and different
// commands show different icons.
#include "windowtest.h"

#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/document/selection.h"

#include <QImageReader>
#include <QQmlApplicationEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QtTest>

#include <map>
#include <set>

namespace {

constexpr double kTouchMinimum = 48.0;
// Layouts round to half pixels.
constexpr double kSlack = 0.5;

// What a user works: buttons of every kind, sliders, spin boxes, drop-downs, text fields.
bool isControl(const QQuickItem *item)
{
    for (const char *type : {"QQuickAbstractButton", "QQuickSlider", "QQuickSpinBox", "QQuickComboBox",
                             "QQuickTextField", "QQuickRangeSlider", "QQuickDial"})
        if (item->inherits(type))
            return true;
    return false;
}

bool isShown(const QQuickItem *item)
{
    return item->isVisible() && item->opacity() > 0.01 && item->width() > 0 && item->height() > 0;
}

// Every control shown below `root`, not the parts of another control (a drop-down's text field, a
// spin box's buttons are the control's own), but the cells in a list's row.
void collectControls(QQuickItem *root, QList<QQuickItem *> &found)
{
    if (!isShown(root))
        return;
    if (isControl(root)) {
        found << root;
        // A list's row holds controls of its own (the coordinates table's cells).
        if (!root->inherits("QQuickItemDelegate"))
            return;
    }
    for (QQuickItem *child : root->childItems())
        collectControls(child, found);
}

// Every item shown below `root`.
void collectShown(QQuickItem *root, QList<QQuickItem *> &found)
{
    if (!isShown(root))
        return;
    found << root;
    for (QQuickItem *child : root->childItems())
        collectShown(child, found);
}

QRectF sceneRect(const QQuickItem *item)
{
    return item->mapRectToScene(QRectF(0, 0, item->width(), item->height()));
}

// A readable name of an item for a failure message: its object name, its text, or its type.
QString describe(const QQuickItem *item)
{
    QString name = item->objectName();
    const QString text = item->property("text").toString();
    if (!text.isEmpty())
        name += QStringLiteral(" \"%1\"").arg(text.left(40));
    if (name.isEmpty())
        for (const QQuickItem *p = item->parentItem(); p && name.isEmpty(); p = p->parentItem())
            name = QStringLiteral("in ") + p->objectName();
    return QStringLiteral("%1 %2 at %3,%4 %5×%6")
        .arg(QString::fromLatin1(item->metaObject()->className()), name)
        .arg(sceneRect(item).x())
        .arg(sceneRect(item).y())
        .arg(item->width())
        .arg(item->height());
}

// What a screen reader says for a control: its Accessible.name, else a button's text (Qt gives that
// as the name). A field, slider, spin box or drop-down has no text of its own that names it.
QString screenReaderName(const QQuickItem *item)
{
    for (const QObject *child : item->children())
        if (child->inherits("QQuickAccessibleAttached") && !child->property("name").toString().isEmpty())
            return child->property("name").toString();
    return item->inherits("QQuickAbstractButton") ? item->property("text").toString() : QString();
}

// The nearest scrolling area around `item` below `root`, or nullptr.
QQuickItem *scrollingParent(const QQuickItem *item, const QQuickItem *root)
{
    for (QQuickItem *p = item->parentItem(); p && p != root; p = p->parentItem())
        if (p->inherits("QQuickFlickable"))
            return p;
    return nullptr;
}

} // namespace

class TestPresentWindow final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    kontur::Language *m_language = nullptr;
    QObject *m_actions = nullptr;

    QQuickItem *item(const QString &name) const { return kontur::test::findVisibleItem(m_window, name); }
    QObject *action(const QString &name) const { return m_actions->findChild<QObject *>(name); }
    QObject *popup(const QString &name) const { return m_window->findChild<QObject *>(name); }
    bool presentation() const { return action(QStringLiteral("presentationItem"))->property("checked").toBool(); }
    void setPresentation(bool on)
    {
        if (presentation() != on)
            QVERIFY(QMetaObject::invokeMethod(action(QStringLiteral("presentationItem")), "trigger"));
        QTRY_COMPARE(presentation(), on);
    }
    // Closes what a view left open: the pages, the teaching view, the basis panel.
    void closeViews()
    {
        for (const char *page : {"functionSplineView", "practicumView"})
            if (QObject *p = popup(QLatin1String(page)); p && p->property("visible").toBool()) {
                QVERIFY(QMetaObject::invokeMethod(p, "close"));
                QTRY_VERIFY(!p->property("visible").toBool());
            }
        m_window->findChild<QObject *>(QStringLiteral("teaching"))->setProperty("view", 0);
        if (action(QStringLiteral("teachingBasis"))->property("checked").toBool())
            QVERIFY(QMetaObject::invokeMethod(action(QStringLiteral("teachingBasis")), "trigger"));
        QTRY_VERIFY(!item(QStringLiteral("basisPanel"))->isVisible());
        QTRY_VERIFY(!item(QStringLiteral("teachingBar"))->isVisible());
    }
    // Opens a view by its Teaching menu action and returns the item that holds it (the page, the
    // teaching bar, the basis panel) and its Close button's name.
    QQuickItem *openView(const QString &actionName, QString *closeName = nullptr)
    {
        closeViews();
        QObject *a = action(actionName);
        if (!a || !QMetaObject::invokeMethod(a, "trigger"))
            return nullptr;
        QString page;
        QString close;
        if (actionName == QLatin1String("teachingFunctionSpline") || actionName == QLatin1String("teachingRunge")) {
            page = QStringLiteral("functionSplineView");
            close = QStringLiteral("functionSplineClose");
        } else if (actionName == QLatin1String("teachingPracticum")) {
            page = QStringLiteral("practicumView");
            close = QStringLiteral("practicumClose");
        } else if (actionName == QLatin1String("teachingBasis")) {
            close = QStringLiteral("basisCloseButton");
        } else {
            close = QStringLiteral("teachingCloseButton");
        }
        if (closeName)
            *closeName = close;
        if (!page.isEmpty()) {
            QObject *p = nullptr;
            if (!QTest::qWaitFor([&] { return (p = popup(page)) && p->property("opened").toBool(); }))
                return nullptr;
            auto *content = p->property("contentItem").value<QQuickItem *>();
            return content ? content->parentItem() : nullptr;
        }
        const QString holder =
            actionName == QLatin1String("teachingBasis") ? QStringLiteral("basisPanel") : QStringLiteral("teachingBar");
        QQuickItem *it = nullptr;
        if (!QTest::qWaitFor([&] { return (it = item(holder)) && it->isVisible() && it->height() > 0; }))
            return nullptr;
        if (!kontur::test::settled(m_window)) // the bar's flow settles
            return nullptr;
        return it;
    }
    // Every control below the window's content at least 48 × 48; the failures as text.
    QStringList smallControls() const
    {
        QList<QQuickItem *> controls;
        collectControls(m_window->contentItem(), controls);
        QStringList small;
        for (QQuickItem *c : controls) {
            // Outside the window (a closed drawer beside it): not a target now.
            if (!sceneRect(c).intersects(QRectF(QPointF(0, 0), m_window->size())))
                continue;
            if (c->width() < kTouchMinimum - kSlack || c->height() < kTouchMinimum - kSlack)
                small << describe(c);
        }
        return small;
    }
    // What is wrong with the items shown below `root` (a view) in the rectangle `bounds`: a control
    // or text outside it (or outside its scrolling area's width), a text elided or wider than its
    // room, a text field's text cut at the top or bottom.
    QStringList layoutFaults(QQuickItem *root, const QRectF &bounds) const
    {
        QList<QQuickItem *> shown;
        collectShown(root, shown);
        QStringList faults;
        const QRectF window(QPointF(0, 0), m_window->size());
        for (QQuickItem *it : shown) {
            const bool text = it->inherits("QQuickText");
            const bool input = it->inherits("QQuickTextInput");
            if (!text && !input && !isControl(it))
                continue;
            QRectF r = sceneRect(it);
            if (text && it->property("wrapMode").toInt() == 0 && it->property("elide").toInt() == 3 /* ElideNone */)
                r.setWidth(std::max(r.width(), it->property("contentWidth").toDouble()));
            QRectF room = bounds.intersected(window);
            if (QQuickItem *scroll = scrollingParent(it, root)) {
                const QRectF viewport = sceneRect(scroll);
                room.setLeft(std::max(room.left(), viewport.left()));
                room.setRight(std::min(room.right(), viewport.right()));
                r.setTop(room.top()); // reached by scrolling
                r.setBottom(room.top());
            }
            if (r.left() < room.left() - kSlack || r.right() > room.right() + kSlack || r.top() < room.top() - kSlack ||
                r.bottom() > room.bottom() + kSlack)
                faults << QStringLiteral("outside: ") + describe(it);
            if (text && it->property("truncated").toBool())
                faults << QStringLiteral("elided: ") + describe(it);
            if (input) {
                const double inner =
                    it->height() - it->property("topPadding").toDouble() - it->property("bottomPadding").toDouble();
                if (it->property("contentHeight").toDouble() > inner + 1)
                    faults << QStringLiteral("cut at the top or bottom: ") + describe(it);
                // A read-only field shows a choice: all of it.
                if (it->property("readOnly").toBool() &&
                    it->property("contentWidth").toDouble() > it->width() - it->property("leftPadding").toDouble() -
                                                                  it->property("rightPadding").toDouble() + 1)
                    faults << QStringLiteral("choice cut: ") + describe(it);
            }
        }
        return faults;
    }

private Q_SLOTS:
    void initTestCase();
    void init();
    void everyControlIsFingerSized_data();
    void everyControlIsFingerSized();
    void presentationModeFits_data();
    void presentationModeFits();
    void everyControlIsNamed();
    void commandsHaveDistinctIcons();
    void elevationStepsByButtons();
    void phoneSheetGrowsInThreeSteps();
    void drawerLeavesThePanelButtonFree_data();
    void drawerLeavesThePanelButtonFree();
    void cleanupTestCase() { m_engine.reset(); }
};

void TestPresentWindow::initTestCase()
{
    QVERIFY(start(QSize(1920, 1080)));
    m_language = m_engine->findChild<kontur::Language *>();
    m_actions = m_window->findChild<QObject *>(QStringLiteral("appActions"));
    QVERIFY(m_language && m_actions);
    // A selected cubic Bézier curve, so that every view has something to show.
    QVERIFY(addBezier({{100, 400}, {250, 100}, {500, 100}, {650, 400}}));
    m_editor->selection()->selectRow(0);
}

void TestPresentWindow::init()
{
    setPresentation(false);
    QVERIFY(m_language->setCurrent(QStringLiteral("en")));
}

const QStringList kViews{QString(),
                         QStringLiteral("teachingDeCasteljau"),
                         QStringLiteral("teachingElevation"),
                         QStringLiteral("teachingCompare"),
                         QStringLiteral("teachingComb"),
                         QStringLiteral("teachingBasis"),
                         QStringLiteral("teachingFunctionSpline"),
                         QStringLiteral("teachingRunge"),
                         QStringLiteral("teachingPracticum")};

void TestPresentWindow::everyControlIsFingerSized_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addRow("800x1280") << QSize(800, 1280);
    QTest::addRow("1280x800") << QSize(1280, 800);
    QTest::addRow("1920x1080") << QSize(1920, 1080);
}

// The window and each teaching view in turn: every control shown, whatever its kind, at least 48 px
// wide and tall (the README's promise), the side panel and the tool bar included.
void TestPresentWindow::everyControlIsFingerSized()
{
    QFETCH(QSize, size);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    QStringList failures;
    int checked = 0;
    for (const QString &view : kViews) {
        if (view.isEmpty())
            closeViews();
        else
            QVERIFY2(openView(view), qPrintable(view));
        QVERIFY(kontur::test::settled(m_window));
        QList<QQuickItem *> controls;
        collectControls(m_window->contentItem(), controls);
        checked += static_cast<int>(controls.size());
        for (const QString &small : smallControls())
            failures << QStringLiteral("%1: %2").arg(view.isEmpty() ? QStringLiteral("window") : view, small);
    }
    closeViews();
    failures.removeDuplicates();
    for (const QString &failure : failures)
        qInfo("%s", qPrintable(failure));
    qInfo("%d controls checked, %d below %g px", checked, static_cast<int>(failures.size()), kTouchMinimum);
    QVERIFY2(checked > 50, "too few controls found: the walk is broken");
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
}

void TestPresentWindow::presentationModeFits_data()
{
    QTest::addColumn<QString>("language");
    for (const char *language : {"en", "lv", "sk", "bg", "ru"})
        QTest::addRow("%s", language) << QString::fromLatin1(language);
}

// Presentation mode at 1920 × 1080: the tool bar's names whole, and each teaching view and bar in
// turn inside its place, nothing elided, its Close button reached (scrolled to) and closing the view.
void TestPresentWindow::presentationModeFits()
{
    QFETCH(QString, language);
    m_window->resize(1920, 1080);
    QTRY_COMPARE(m_window->size(), QSize(1920, 1080));
    QVERIFY(m_language->setCurrent(language));
    setPresentation(true);
    QTRY_COMPARE(m_window->property("font").value<QFont>().pixelSize(), 22);
    QVERIFY(kontur::test::settled(m_window)); // the layouts settle with the larger font
    QStringList faults;
    QQuickItem *bar = item(QStringLiteral("toolBar"));
    for (const QString &fault : layoutFaults(bar, sceneRect(bar)))
        faults << QStringLiteral("tool bar: ") + fault;
    // The side panel docked beside the canvas, with the selected curve's properties and table.
    QQuickItem *panel = item(QStringLiteral("sidePanel"));
    QVERIFY(panel && panel->isVisible());
    for (const QString &fault : layoutFaults(panel, sceneRect(panel)))
        faults << QStringLiteral("side panel: ") + fault;
    for (const QString &view : kViews) {
        if (view.isEmpty())
            continue;
        QString closeName;
        QQuickItem *holder = openView(view, &closeName);
        QVERIFY2(holder, qPrintable(view));
        QVERIFY(kontur::test::settled(m_window));
        screenshot(QStringLiteral("present-%1-%2.png").arg(language, view));
        QRectF bounds = sceneRect(holder);
        for (const QString &fault : layoutFaults(holder, bounds))
            faults << view + QStringLiteral(": ") + fault;
        if (view == QLatin1String("teachingCompare")) {
            // The legend is the bar's: nothing of it over the curves.
            QQuickItem *legend = item(QStringLiteral("compareLegend"));
            QVERIFY(legend && legend->isVisible() && holder->isAncestorOf(legend));
            QVERIFY(!sceneRect(legend).intersects(sceneRect(item(QStringLiteral("canvas")))));
        }
        // Close: scrolled into view, inside the window, and it closes the view.
        QQuickItem *close = item(closeName);
        QVERIFY2(close && close->isVisible(), qPrintable(closeName));
        if (!kontur::test::clickInView(m_window, close))
            faults << view + QStringLiteral(": Close out of reach");
        else if (!QTest::qWaitFor([holder] { return !holder->isVisible(); }))
            faults << view + QStringLiteral(": Close did not close it: ") + describe(close);
    }
    setPresentation(false);
    faults.removeDuplicates();
    for (const QString &fault : faults)
        qInfo("%s", qPrintable(fault));
    QVERIFY2(faults.isEmpty(),
             qPrintable(QStringLiteral("%1 faults:\n").arg(faults.size()) + faults.join(QLatin1Char('\n'))));
}

// At 1280 × 800 with the drawer pinned and each teaching view in turn: every control shown, the
// coordinates table's cells included, has a name for a screen reader; the drawer has one too.
// The icon of `name` (a file of qml/icons, as the app's actions load it) as an ink mask at 48 px:
// how much ink each pixel has (0..1), whatever colour the style tints it with.
static std::vector<double> iconInk(const QString &name)
{
    QImageReader reader(QStringLiteral(":/qt/qml/Kontur/icons/%1.svg").arg(name));
    reader.setScaledSize(QSize(48, 48));
    const QImage image = reader.read().convertToFormat(QImage::Format_ARGB32);
    std::vector<double> ink;
    if (image.isNull())
        return ink;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ink.push_back(qAlpha(image.pixel(x, y)) / 255.0);
    return ink;
}

// Commands that do different things show different pictures: every icon the actions use is a file
// of its own that loads, and every two differ in at least a quarter of their ink at 48 px. Variants
// of one picture (Save as of Save, Zoom out of Zoom in, a symmetric knot of a smooth one) differ by
// a mark, at least 5 %. (Save and Import were once both an arrow down into a tray: that they look
// alike is judged by eye; this guards against an icon copied or swapped for another.)
void TestPresentWindow::commandsHaveDistinctIcons()
{
    std::map<QString, QStringList> users; // icon name -> the commands showing it
    const QList<QObject *> roots = m_engine->rootObjects();
    for (QObject *root : roots) {
        QList<QObject *> objects = root->findChildren<QObject *>();
        objects << root;
        for (QObject *object : std::as_const(objects)) {
            const QString icon = object->property("iconName").toString();
            if (!icon.isEmpty())
                users[icon] << object->property("text").toString();
        }
    }
    QVERIFY2(users.size() >= 20, qPrintable(QString::number(users.size())));
    for (const char *name : {"document-open-symbolic", "document-save-symbolic", "kontur-import", "kontur-export"})
        QVERIFY2(users.count(QLatin1String(name)), name);
    const std::set<std::pair<QString, QString>> variants{
        {QStringLiteral("document-save-as-symbolic"), QStringLiteral("document-save-symbolic")},
        {QStringLiteral("kontur-knot-smooth"), QStringLiteral("kontur-knot-symmetric")},
        {QStringLiteral("zoom-in-symbolic"), QStringLiteral("zoom-out-symbolic")}};
    std::map<QString, std::vector<double>> inks;
    for (const auto &[name, commands] : users) {
        inks[name] = iconInk(name);
        QVERIFY2(inks[name].size() == 48 * 48, qPrintable(name));
    }
    for (auto a = inks.begin(); a != inks.end(); ++a)
        for (auto b = std::next(a); b != inks.end(); ++b) {
            double differ = 0.0, total = 0.0;
            for (std::size_t i = 0; i < a->second.size(); ++i) {
                differ += std::abs(a->second[i] - b->second[i]);
                total += std::max(a->second[i], b->second[i]);
            }
            const double share = total > 0 ? differ / total : 0.0;
            const double least = variants.count({a->first, b->first}) ? 0.05 : 0.25;
            QVERIFY2(share >= least, qPrintable(QStringLiteral("%1 (%2) and %3 (%4): %5 of their ink differs")
                                                    .arg(a->first, users[a->first].join(QStringLiteral(", ")), b->first,
                                                         users[b->first].join(QStringLiteral(", ")))
                                                    .arg(share, 0, 'f', 2)));
        }
}

void TestPresentWindow::everyControlIsNamed()
{
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
    QTRY_VERIFY(item(QStringLiteral("x0")) && item(QStringLiteral("x0"))->isVisible());
    QStringList unnamed;
    for (const QString &view : kViews) {
        if (view.isEmpty())
            closeViews();
        else
            QVERIFY2(openView(view), qPrintable(view));
        QList<QQuickItem *> controls;
        collectControls(m_window->contentItem(), controls);
        for (QQuickItem *c : std::as_const(controls))
            if (screenReaderName(c).trimmed().isEmpty())
                unnamed << describe(c);
    }
    closeViews();
    unnamed.removeDuplicates();
    for (const QString &u : std::as_const(unnamed))
        qInfo("no name: %s", qPrintable(u));
    QVERIFY2(unnamed.isEmpty(),
             qPrintable(QString::number(unnamed.size()) + QStringLiteral(" controls without a name")));
    QCOMPARE(screenReaderName(item(QStringLiteral("drawerContent"))->parentItem()),
             QStringLiteral("Curves and settings"));
    QCOMPARE(screenReaderName(item(QStringLiteral("x1"))), QStringLiteral("C1 X, px"));
}

// The degree elevation's step buttons take one step each, and neither they nor the slider move, nor
// the readout beside them widens, as the degree grows.
void TestPresentWindow::elevationStepsByButtons()
{
    m_window->resize(1280, 800);
    QTRY_COMPARE(m_window->size(), QSize(1280, 800));
    QVERIFY(openView(QStringLiteral("teachingElevation")));
    QObject *teaching = m_window->findChild<QObject *>(QStringLiteral("teaching"));
    QQuickItem *slider = item(QStringLiteral("elevationSlider"));
    QQuickItem *less = item(QStringLiteral("elevationLessButton"));
    QQuickItem *more = item(QStringLiteral("elevationMoreButton"));
    QQuickItem *readout = item(QStringLiteral("elevationReadout"));
    QVERIFY(slider && less && more && readout);
    QCOMPARE(teaching->property("elevationStep").toInt(), 0);
    QVERIFY(!less->isEnabled());
    const QRectF sliderAt = sceneRect(slider);
    const QRectF lessAt = sceneRect(less);
    const double readoutWidth = readout->width();
    for (int step = 1; step <= 12; ++step) {
        QVERIFY(kontur::test::clickInView(m_window, more));
        QTRY_COMPARE(teaching->property("elevationStep").toInt(), step);
    }
    // As wide at "degree 3 → 15 (16 points)" as at "→ 3 (4 points)": it is as wide as its widest text.
    QCOMPARE(readout->width(), readoutWidth);
    QCOMPARE(sceneRect(slider), sliderAt);
    QCOMPARE(sceneRect(less), lessAt);
    QVERIFY(kontur::test::clickInView(m_window, less));
    QTRY_COMPARE(teaching->property("elevationStep").toInt(), 11);
    // The slider shows the step the buttons set.
    QCOMPARE(qRound(slider->property("value").toDouble()), 11);
    teaching->setProperty("elevationStep", 0);
    closeViews();
}

// At 360 × 640 the bottom sheet's peek, half and full differ (they were one height, with two rows of
// the table in it): taps on its handle raise it a step each, and at full it shows more of the panel.
void TestPresentWindow::phoneSheetGrowsInThreeSteps()
{
    m_window->setProperty("panelOpen", true);
    m_window->resize(360, 640);
    QTRY_COMPARE(m_window->size(), QSize(360, 640));
    QTRY_COMPARE(m_window->property("panelLayout").toString(), QStringLiteral("sheet"));
    QQuickItem *sheet = item(QStringLiteral("bottomSheet"));
    QQuickItem *handle = item(QStringLiteral("sheetHandle"));
    QVERIFY(sheet && handle);
    QVERIFY(QMetaObject::invokeMethod(sheet, "setStop", Q_ARG(QVariant, 0)));
    const double peek = sheet->property("peekStop").toDouble();
    const double half = sheet->property("halfStop").toDouble();
    const double full = sheet->property("fullHeight").toDouble();
    qInfo("peek %g, half %g, full %g", peek, half, full);
    // A step of the sheet is at least a row of the table.
    QVERIFY2(half - peek >= kTouchMinimum && full - half >= kTouchMinimum,
             qPrintable(QStringLiteral("%1 %2 %3").arg(peek).arg(half).arg(full)));
    // The peek still shows the selected curve's name, and the canvas keeps a third of the window.
    QTRY_VERIFY(std::abs(sheet->height() - peek) < 0.5);
    QQuickItem *canvas = item(QStringLiteral("canvas"));
    for (const double height : {half, full}) {
        QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(handle));
        QTRY_VERIFY2(std::abs(sheet->height() - height) < 0.5, qPrintable(QString::number(sheet->height())));
        QVERIFY(canvas->height() - sheet->height() >= 0.3 * m_window->height() - kSlack);
    }
    screenshot(QStringLiteral("present-sheet-360x640-full.png"));
    QTest::mouseClick(m_window, Qt::LeftButton, {}, kontur::test::centerOf(handle));
    QTRY_VERIFY(std::abs(sheet->height() - peek) < 0.5);
}

void TestPresentWindow::drawerLeavesThePanelButtonFree_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<bool>("byTouch");
    QTest::addRow("1280x800 mouse") << QSize(1280, 800) << false;
    QTest::addRow("1024x768 touch") << QSize(1024, 768) << true;
}

// The unpinned drawer slides over the canvas under the tool bar: the Side panel button stays
// uncovered, and a click on it puts the drawer away.
void TestPresentWindow::drawerLeavesThePanelButtonFree()
{
    QFETCH(QSize, size);
    QFETCH(bool, byTouch);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    QTRY_COMPARE(m_window->property("panelLayout").toString(), QStringLiteral("drawer"));
    auto *drawer = m_window->findChild<QObject *>(QStringLiteral("panelDrawer"));
    QVERIFY(drawer);
    QTRY_VERIFY(drawer->property("opened").toBool());
    // Unpinned by its Pin button, as a user does: the drawer now lies over the canvas.
    QQuickItem *pin = item(QStringLiteral("pinButton"));
    QVERIFY(pin && pin->isVisible());
    QVERIFY(m_window->property("panelPinned").toBool());
    QTRY_VERIFY(sceneRect(pin).right() <= size.width() && sceneRect(pin).right() > size.width() - 200);
    QVERIFY(kontur::test::clickInView(m_window, pin));
    QTRY_VERIFY(!m_window->property("panelPinned").toBool());
    QTRY_VERIFY(drawer->property("modal").toBool());
    QTRY_COMPARE(drawer->property("position").toDouble(), 1.0);
    auto *drawerItem = drawer->property("contentItem").value<QQuickItem *>()->parentItem();
    QQuickItem *button = item(QStringLiteral("panelButton"));
    QVERIFY(button && button->isVisible());
    // The bar laid out for the new width: the button at its right end, inside the window.
    QTRY_VERIFY(sceneRect(button).right() <= size.width() && sceneRect(button).right() > size.width() - 120);
    QVERIFY2(!sceneRect(drawerItem).intersects(sceneRect(button)),
             qPrintable(describe(drawerItem) + QStringLiteral(" covers ") + describe(button)));
    screenshot(QStringLiteral("drawer-unpinned-%1x%2.png").arg(size.width()).arg(size.height()));
    // The Side panel button puts the drawer away, by mouse and by finger.
    if (byTouch)
        tap(kontur::test::centerOf(button));
    else
        QVERIFY(kontur::test::clickInView(m_window, button));
    QTRY_VERIFY(!drawer->property("visible").toBool());
    QTRY_VERIFY(!m_window->property("panelOpen").toBool());
    // And brings it back over the canvas, still unpinned.
    QVERIFY(kontur::test::clickInView(m_window, button));
    QTRY_VERIFY(m_window->property("panelOpen").toBool());
    QTRY_VERIFY(drawer->property("opened").toBool());
    QVERIFY(!m_window->property("panelBeside").toBool());
    // Pinned again for the next test, by its button.
    QTRY_COMPARE(drawer->property("position").toDouble(), 1.0);
    QVERIFY(kontur::test::clickInView(m_window, pin));
    QTRY_VERIFY(m_window->property("panelBeside").toBool());
}

QTEST_MAIN(TestPresentWindow)
#include "tst_present_window.moc"
