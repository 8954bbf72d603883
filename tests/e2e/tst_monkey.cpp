// Random input in the real window, as a careless user would give it: taps and drags on the canvas,
// clicks on whatever button, switch, list row or menu entry is shown and enabled (tool bar, side
// panel, menus, dialogs), random text typed into the fields shown (numbers such as 1e308, -0, 1e-300,
// words, nothing), undo, redo, Escape; at 800×1280, 1280×800 and 1920×1080 with resizes and language
// switches in between. It fails on a crash, on any Qt warning or critical message, on an exception,
// and on an action that keeps the window's thread busy for longer than a few seconds of its processor
// time (a watchdog thread stops a frozen window). Processor time, not the clock: on a machine busy with
// other work an action takes longer by the clock, and that is no fault of the window's.
// File dialogs are answered with Cancel at once: the test never writes where it was not asked to.
// KONTUR_MONKEY_SECONDS sets the run's length (60 by default), KONTUR_MONKEY_SEED repeats a run,
// KONTUR_MONKEY_FREEZE_SECONDS the longest an action may keep the window's thread busy (5 by default).
#include "messagerecorder.h"
#include "windowtest.h"

#include "app/language.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/placement.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"

#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QtTest>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include <pthread.h>
#include <time.h>

using kontur::CurveKind;

namespace {

// What the watchdog thread knows: when the last action began (by the clock and by the window thread's
// processor time), and what it was.
std::atomic<qint64> g_actionStartMs{-1};
std::atomic<qint64> g_actionStartCpuMs{-1};
std::mutex g_actionMutex;
std::string g_action;
clockid_t g_windowClock = CLOCK_MONOTONIC; // the window thread's processor time, once initTestCase has run

qint64 nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// The processor time the window's thread has used (ms); readable from any thread.
qint64 windowCpuMs()
{
    timespec t{};
    clock_gettime(g_windowClock, &t);
    return qint64(t.tv_sec) * 1000 + t.tv_nsec / 1'000'000;
}

} // namespace

class TestMonkey final : public QObject, private kontur::test::MainWindowTest
{
    Q_OBJECT

private:
    QRandomGenerator m_random;
    quint32 m_seed = 0;
    int m_actions = 0;
    qint64 m_freezeMs = 5000;
    QStringList m_recent; // the last actions, for the report of a failure
    kontur::Language *m_language = nullptr;
    std::atomic<bool> m_stopWatchdog{false};
    std::thread m_watchdog;

    int below(int n) { return n <= 0 ? 0 : int(m_random.bounded(quint32(n))); }
    double uniform() { return m_random.generateDouble(); }
    static QRectF rectOf(const QQuickItem *it) { return it->mapRectToScene(it->boundingRect()); }
    QQuickItem *item(const QString &name) const { return kontur::test::findItem(m_window, name); }
    QString where() const
    {
        return QStringLiteral("seed %1, action %2 (KONTUR_MONKEY_SEED=%1 repeats the run); last actions: %3")
            .arg(m_seed)
            .arg(m_actions)
            .arg(m_recent.join(QStringLiteral(" → ")));
    }
    void note(const QString &action)
    {
        m_recent << action;
        if (m_recent.size() > 12)
            m_recent.removeFirst();
        const std::lock_guard lock(g_actionMutex);
        g_action = QStringLiteral("%1 (seed %2, action %3)").arg(action).arg(m_seed).arg(m_actions).toStdString();
    }

    // The items under `root` a finger may press now: shown, enabled, inside the window, and not the
    // canvas's (taps there are an action of their own), nor a file dialog's, nor Quit.
    QList<QQuickItem *> pressable() const
    {
        QList<QQuickItem *> found;
        std::function<void(QQuickItem *)> walk = [&](QQuickItem *it) {
            if (!it->isVisible() || !it->isEnabled() || it->opacity() <= 0.01 || it == m_canvas)
                return;
            if (it->objectName() == QLatin1String("fileBrowserContent")) // a file dialog's (FileBrowserDialog)
                return;
            const bool control = it->inherits("QQuickAbstractButton") || it->inherits("QQuickComboBox") ||
                                 it->inherits("QQuickSpinBox") || it->inherits("QQuickSlider") ||
                                 it->inherits("QQuickTextInput");
            if (control && !it->objectName().contains(QLatin1String("quitAction")) && it->width() > 1 &&
                it->height() > 1 && kontur::test::insideWindow(m_window, rectOf(it).center().toPoint()))
                found << it;
            for (QQuickItem *child : it->childItems())
                walk(child);
        };
        walk(m_window->contentItem());
        return found;
    }
    QList<QObject *> visibleFileDialogs() const
    {
        QList<QObject *> shown;
        for (QObject *object : m_window->findChildren<QObject *>())
            if (kontur::test::isFileDialog(object) && object->property("visible").toBool())
                shown << object;
        return shown;
    }
    QPoint randomCanvasPoint()
    {
        const QRectF input =
            rectOf(item(QStringLiteral("canvasInput"))).intersected(QRectF(QPointF(0, 0), m_window->size()));
        if (input.width() < 4 || input.height() < 4)
            return rectOf(m_canvas).center().toPoint();
        return QPoint(int(input.left() + 2 + uniform() * (input.width() - 4)),
                      int(input.top() + 2 + uniform() * (input.height() - 4)));
    }
    // A tap held a random while, as fingers do.
    void tapHere(QPoint at) { tap(at, 10 + below(40)); }
    // A drag within the window (Qt Test warns of a mouse outside it): the end kept, the way shortened.
    void dragWithin(QPoint from, QPoint by, bool mouse)
    {
        const QPoint to(std::clamp(from.x() + by.x(), 1, m_window->width() - 2),
                        std::clamp(from.y() + by.y(), 1, m_window->height() - 2));
        drag(from, to - from, mouse, 6, 8);
    }
    QString randomText()
    {
        static const QStringList texts = {QStringLiteral("1e308"),
                                          QStringLiteral("-0"),
                                          QStringLiteral("1e-300"),
                                          QStringLiteral("abc"),
                                          QString(),
                                          QStringLiteral("-1e308"),
                                          QStringLiteral("0"),
                                          QStringLiteral("12,5"),
                                          QStringLiteral("3.25"),
                                          QStringLiteral("-7"),
                                          QStringLiteral("1e12"),
                                          QStringLiteral("nan"),
                                          QStringLiteral("inf"),
                                          QStringLiteral("42"),
                                          QStringLiteral("1e-9"),
                                          QStringLiteral("  5  ")};
        if (below(4) == 0) { // random digits and signs
            QString text;
            const QString alphabet = QStringLiteral("0123456789.,-+eE ");
            for (int i = below(12); i >= 0; --i)
                text += alphabet[below(int(alphabet.size()))];
            return text;
        }
        return texts[below(int(texts.size()))];
    }
    void typeInto(QQuickItem *field, const QString &text)
    {
        kontur::test::ensureVisible(field);
        field->forceActiveFocus();
        QTest::keyClick(m_window, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(m_window, Qt::Key_Backspace);
        for (const QChar c : text)
            QTest::keyClick(m_window, c.toLatin1());
        if (below(3) != 0)
            QTest::keyClick(m_window, Qt::Key_Return);
    }

    void randomAction();
    void startWatchdog();

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void randomInput();
};

void TestMonkey::startWatchdog()
{
    m_freezeMs = qEnvironmentVariableIsSet("KONTUR_MONKEY_FREEZE_SECONDS")
                     ? qint64(qEnvironmentVariableIntValue("KONTUR_MONKEY_FREEZE_SECONDS")) * 1000
                     : 5000;
    // The window's thread may be stuck in a loop that never returns to the test (it burns processor
    // time), or wait for something that never comes (a minute by the clock): the watchdog reports the
    // action and the seed from its own thread and ends the process.
    if (pthread_getcpuclockid(pthread_self(), &g_windowClock) != 0)
        g_windowClock = CLOCK_MONOTONIC;
    m_watchdog = std::thread([this] {
        while (!m_stopWatchdog) {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            const qint64 started = g_actionStartMs, startedCpu = g_actionStartCpuMs;
            if (started < 0 || startedCpu < 0)
                continue;
            const qint64 busy = windowCpuMs() - startedCpu, waited = nowMs() - started;
            if (busy > m_freezeMs * 4 || waited > std::max<qint64>(60'000, m_freezeMs * 12)) {
                const std::lock_guard lock(g_actionMutex);
                std::fprintf(stderr, "FROZEN: the window did not answer for %lld ms (%lld ms busy) during %s\n",
                             static_cast<long long>(waited), static_cast<long long>(busy), g_action.c_str());
                std::fflush(stderr);
                std::abort();
            }
        }
    });
}

void TestMonkey::initTestCase()
{
    kontur::test::recordMessages();
    QVERIFY(start(QSize(1280, 800)));
    m_language = m_engine->findChild<kontur::Language *>();
    QVERIFY(m_language);
    bool given = false;
    m_seed = static_cast<quint32>(qEnvironmentVariableIntValue("KONTUR_MONKEY_SEED", &given));
    if (!given)
        m_seed = QRandomGenerator::global()->generate();
    m_random.seed(m_seed);
    qInfo("monkey seed %u (KONTUR_MONKEY_SEED=%u repeats the run)", m_seed, m_seed);
    // Quit is taken away for the run: a tap where an open menu's last entry lies, or Up and Enter in a
    // menu, would otherwise end it (its entries stay shown, disabled).
    QObject *quit = nullptr;
    for (QObject *object : m_window->findChildren<QObject *>())
        if (object->objectName() == QLatin1String("quitAction") && object->inherits("QQuickAction"))
            quit = object;
    QVERIFY(quit && quit->setProperty("enabled", false));
    startWatchdog();
    const QStringList messages = kontur::test::takeMessages();
    QVERIFY2(messages.isEmpty(), qPrintable(messages.join(QStringLiteral(" | "))));
}

void TestMonkey::cleanupTestCase()
{
    m_stopWatchdog = true;
    if (m_watchdog.joinable())
        m_watchdog.join();
    m_engine.reset();
}

// One random action, as a user might do it.
void TestMonkey::randomAction()
{
    const int kind = below(100);
    if (kind < 18) {
        const QPoint at = randomCanvasPoint();
        note(QStringLiteral("tap canvas at %1,%2").arg(at.x()).arg(at.y()));
        tapHere(at);
    } else if (kind < 28) {
        const QPoint from = randomCanvasPoint();
        const QPoint by(below(300) - 150, below(300) - 150);
        const bool mouse = below(2) == 0;
        note(QStringLiteral("%1 drag from %2,%3 by %4,%5")
                 .arg(mouse ? QStringLiteral("mouse") : QStringLiteral("finger"))
                 .arg(from.x())
                 .arg(from.y())
                 .arg(by.x())
                 .arg(by.y()));
        dragWithin(from, by, mouse);
    } else if (kind < 34) {
        // New points where the canvas has room: a curve to work on.
        note(QStringLiteral("new Bézier by taps"));
        m_editor->startPlacing(static_cast<int>(CurveKind::Bezier));
        for (int i = 0; i < 4; ++i) {
            tapHere(randomCanvasPoint());
        }
    } else if (kind < 70) {
        const QList<QQuickItem *> candidates = pressable();
        QList<QQuickItem *> clickable;
        for (QQuickItem *it : candidates)
            if (!it->inherits("QQuickTextInput"))
                clickable << it;
        if (clickable.isEmpty())
            return;
        QQuickItem *target = clickable[below(int(clickable.size()))];
        const QString name = QStringLiteral("%1 %2 \"%3\"")
                                 .arg(QString::fromLatin1(target->metaObject()->className()), target->objectName(),
                                      target->property("text").toString());
        if (target->objectName().contains(QLatin1String("quitAction")) ||
            target->property("text").toString().contains(QLatin1String("Quit")))
            return;
        note(QStringLiteral("click %1").arg(name));
        kontur::test::ensureVisible(target);
        const QRectF r = rectOf(target);
        if (!kontur::test::insideWindow(m_window, r.center().toPoint()))
            return;
        if (below(3) == 0)
            tapHere(r.center().toPoint());
        else
            QTest::mouseClick(m_window, Qt::LeftButton, {}, r.center().toPoint());
    } else if (kind < 80) {
        QList<QQuickItem *> fields;
        for (QQuickItem *it : pressable())
            if (it->inherits("QQuickTextInput") && !it->property("readOnly").toBool())
                fields << it;
        if (fields.isEmpty())
            return;
        QQuickItem *field = fields[below(int(fields.size()))];
        const QString text = randomText();
        note(QStringLiteral("type \"%1\" into %2")
                 .arg(text, field->parentItem() ? field->parentItem()->objectName() : field->objectName()));
        typeInto(field, text);
    } else if (kind < 86) {
        const bool redo = below(2) == 0;
        note(redo ? QStringLiteral("redo") : QStringLiteral("undo"));
        QTest::keyClick(m_window, Qt::Key_Z, redo ? Qt::ControlModifier | Qt::ShiftModifier : Qt::ControlModifier);
    } else if (kind < 92) {
        note(QStringLiteral("Escape"));
        QTest::keyClick(m_window, Qt::Key_Escape);
    } else if (kind < 95) {
        static const QList<Qt::Key> keys = {Qt::Key_Delete, Qt::Key_Left, Qt::Key_Up,
                                            Qt::Key_Return, Qt::Key_Tab,  Qt::Key_Space};
        const Qt::Key key = keys[below(int(keys.size()))];
        note(QStringLiteral("key %1").arg(int(key), 0, 16));
        QTest::keyClick(m_window, key);
    } else if (kind < 98) {
        const QStringList codes = kontur::Language::codes();
        const QString code = codes[below(int(codes.size()))];
        note(QStringLiteral("language %1").arg(code));
        QVERIFY(m_language->setCurrent(code));
    } else {
        const QSize size(400 + below(1600), 400 + below(1000));
        note(QStringLiteral("resize to %1x%2").arg(size.width()).arg(size.height()));
        m_window->resize(size);
    }
}

void TestMonkey::randomInput()
{
    const int seconds =
        qEnvironmentVariableIsSet("KONTUR_MONKEY_SECONDS") ? qEnvironmentVariableIntValue("KONTUR_MONKEY_SECONDS") : 60;
    const QList<QSize> sizes = {QSize(800, 1280), QSize(1280, 800), QSize(1920, 1080)};
    QVERIFY(m_dir.isValid());
    for (int phase = 0; phase < sizes.size(); ++phase) {
        const QSize size = sizes[phase];
        note(QStringLiteral("phase at %1x%2").arg(size.width()).arg(size.height()));
        m_window->resize(size);
        QTRY_COMPARE(m_window->size(), size);
        QElapsedTimer phaseTime;
        phaseTime.start();
        while (phaseTime.elapsed() < qint64(seconds) * 1000 / sizes.size()) {
            // Back to the phase's size after a resize elsewhere, now and then.
            if (m_window->size() != size && below(4) == 0) {
                note(QStringLiteral("resize back to %1x%2").arg(size.width()).arg(size.height()));
                m_window->resize(size);
            }
            ++m_actions;
            QElapsedTimer took;
            took.start();
            const qint64 cpuBefore = windowCpuMs();
            g_actionStartCpuMs = cpuBefore;
            g_actionStartMs = nowMs();
            try {
                randomAction();
                QVERIFY2(kontur::test::settled(m_window), "no frame after the action"); // the window caught up
                // A file dialog is cancelled at once: nothing is written or read by chance.
                for (QObject *dialog : visibleFileDialogs()) {
                    note(QStringLiteral("cancel file dialog \"%1\"").arg(dialog->property("title").toString()));
                    QVERIFY(QMetaObject::invokeMethod(dialog, "reject"));
                }
            } catch (const std::exception &e) {
                QFAIL(qPrintable(QStringLiteral("exception %1; %2").arg(QString::fromUtf8(e.what()), where())));
            }
            g_actionStartMs = -1;
            g_actionStartCpuMs = -1;
            if (QTest::currentTestFailed())
                QFAIL(qPrintable(where()));
            const qint64 busy = windowCpuMs() - cpuBefore;
            QVERIFY2(busy < m_freezeMs, qPrintable(QStringLiteral("an action kept the window busy for %1 ms (%2 ms by "
                                                                  "the clock); %3")
                                                       .arg(busy)
                                                       .arg(took.elapsed())
                                                       .arg(where())));
            QStringList messages = kontur::test::takeMessages();
            // Where first, then each message once: a message repeated for every frame would push the
            // place out of QTest's message length.
            const qsizetype count = messages.size();
            messages.removeDuplicates();
            QVERIFY2(messages.isEmpty(), qPrintable(where() + QStringLiteral("; %1 message(s): ").arg(count) +
                                                    messages.mid(0, 5).join(QStringLiteral(" | "))));
            QVERIFY2(m_window->isVisible(), qPrintable(where()));
            // The recovery copy of a crash is no part of this run: the folders stay the test's own.
            if (m_actions % 50 == 0)
                QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryFolder()));
        }
    }
    qInfo("monkey: %d actions in %d s at 3 sizes, seed %u, %lld curves at the end", m_actions, seconds, m_seed,
          static_cast<long long>(m_editor->document()->curveCount()));
}

QTEST_MAIN(TestMonkey)
#include "tst_monkey.moc"
