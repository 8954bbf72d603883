// Seam allowances in the model layer (issue #22): creating one is one undo step and gives a curve at
// the distance from its source; editing the source moves the allowance with it, and undo brings both
// back exactly; settings changes are one undo step each; the allowance's own points do not move
// while linked; deleting the source leaves the allowance, undo relinks it; detaching is one step;
// the link survives a save / open round trip (byte-identical on the second save).
#include "../wavypiece.h"
#include "io/document.h"
#include "io/seam.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/document/selection.h"
#include "models/text/messages.h"
#include "models/trace/seamallowance.h"

#include <QDir>
#include <QFile>
#include <QJsonObject>

#include <QtTest>

#include <cmath>
#include <numbers>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::SeamAllowance;
using kontur::geo::Point;

namespace {

// A closed composite piece in millimetres.
Curve piece()
{
    Curve c = Curve::make(CurveKind::Composite, {{0, 0}, {100, 0}, {110, 80}, {40, 120}, {-10, 60}});
    (void)c.close();
    c.name = QStringLiteral("Front");
    return c;
}

// The largest |distance(allowance point, source) − d| over samples of the allowance.
double worstDistanceError(const Curve &allowance, const Curve &source, double d)
{
    const kontur::geo::PiecewiseBezier a = allowance.toPiecewise(), s = source.toPiecewise();
    double worst = 0.0;
    for (int i = 0; i < a.segmentCount(); ++i)
        for (int k = 0; k < 8; ++k)
            worst = std::max(worst, std::abs(s.nearest(a.segments()[i].eval((k + 0.5) / 8)).distance - d));
    return worst;
}

// The threads of this process (Linux).
int threadCount()
{
    return static_cast<int>(
        QDir(QStringLiteral("/proc/self/task")).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size());
}

// create() and apply() compute on a worker thread; their end is an event on this one.
bool settled(const SeamAllowance &seam)
{
    return QTest::qWaitFor([&] { return !seam.busy(); }, 60'000);
}

} // namespace

class TestSeamAllowance final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QLocale::setDefault(QLocale::c()); }

    void createFollowUndo()
    {
        EditController editor;
        editor.replaceDocument({piece()}, {}, QStringLiteral("mm"), false);
        const kontur::CurveId source = editor.document()->idAt(0);
        editor.selection()->select(source);
        SeamAllowance seam;
        seam.setEditor(&editor);
        QVERIFY(seam.available());
        QVERIFY(!seam.isAllowance());
        QVERIFY(seam.closed());
        QCOMPARE(seam.distanceText(), QStringLiteral("10")); // 1 cm in millimetres
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")) &&
                settled(seam));
        QCOMPARE(editor.document()->curveCount(), 2);
        QCOMPARE(editor.undoStack()->count(), 1);
        const Curve &allowance = editor.document()->curve(1);
        QVERIFY(allowance.seam);
        QCOMPARE(allowance.seam->source, source);
        QVERIFY(allowance.isClosed());
        QCOMPARE(editor.selection()->curveId(), allowance.id());
        QVERIFY(seam.isAllowance());
        QVERIFY(worstDistanceError(allowance, editor.document()->curve(0), 10.0) <= 0.05);
        const Curve created = allowance;

        // Editing the source: the allowance follows; undo restores both exactly.
        QVERIFY(editor.commands()->applyEdits(static_cast<int>(source),
                                              {QVariantMap{{QStringLiteral("row"), 3},
                                                           {QStringLiteral("x"), QStringLiteral("115")},
                                                           {QStringLiteral("y"), QStringLiteral("-10")}}}));
        QCOMPARE(editor.undoStack()->count(), 2);
        QVERIFY(!editor.document()->curve(1).sameState(created));
        QVERIFY(worstDistanceError(editor.document()->curve(1), editor.document()->curve(0), 10.0) <= 0.05);
        editor.undo();
        QVERIFY(editor.document()->curve(1).sameState(created));
        editor.redo();
        QVERIFY(worstDistanceError(editor.document()->curve(1), editor.document()->curve(0), 10.0) <= 0.05);
        editor.undo();

        // A settings change is one undo step.
        editor.selection()->select(created.id());
        QVERIFY(seam.apply(QStringLiteral("15"), SeamAllowance::Inside, SeamAllowance::Miter, QStringLiteral("30")) &&
                settled(seam));
        QCOMPARE(editor.undoStack()->count(), 2);
        QCOMPARE(editor.document()->curve(1).seam->options.distance, 15.0);
        QCOMPARE(seam.side(), int(SeamAllowance::Inside));
        QVERIFY(editor.document()->curve(1).bounds().sizes().x() < editor.document()->curve(0).bounds().sizes().x());
        editor.undo();
        QVERIFY(editor.document()->curve(1).sameState(created));

        // Its own points do not move while linked.
        const int before = editor.undoStack()->count();
        QVERIFY(!editor.commands()->applyEdits(static_cast<int>(created.id()),
                                               {QVariantMap{{QStringLiteral("row"), 0},
                                                            {QStringLiteral("x"), QStringLiteral("1")},
                                                            {QStringLiteral("y"), QStringLiteral("1")}}}));
        QCOMPARE(editor.message().id, kontur::Message::SeamAllowanceFollows);
        QCOMPARE(editor.undoStack()->count(), before);
        // Bad settings: message 10, nothing pushed.
        QVERIFY(!seam.apply(QStringLiteral("-3"), SeamAllowance::Outside, SeamAllowance::Miter, QStringLiteral("30")));
        QCOMPARE(editor.message().id, kontur::Message::FillAllValues);
        QCOMPARE(editor.undoStack()->count(), before);
    }

    void deleteSourceAndDetach()
    {
        EditController editor;
        editor.replaceDocument({piece()}, {}, QStringLiteral("mm"), false);
        const kontur::CurveId source = editor.document()->idAt(0);
        editor.selection()->select(source);
        SeamAllowance seam;
        seam.setEditor(&editor);
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Miter, QStringLiteral("30")) &&
                settled(seam));
        const Curve created = editor.document()->curve(1);
        // Deleting the source leaves the allowance as it was; undo brings the source back, linked.
        QVERIFY(editor.commands()->deleteCurve(static_cast<int>(source)));
        QCOMPARE(editor.document()->curveCount(), 1);
        QVERIFY(editor.document()->curve(0).sameState(created));
        // Saved without a source, it is a free curve.
        QVERIFY(
            !kontur::toDocumentData(*editor.document()).curves[0].settings.contains(QLatin1String("seamAllowance")));
        editor.undo();
        QCOMPARE(editor.document()->curveCount(), 2);
        QVERIFY(editor.commands()->applyEdits(
            static_cast<int>(source),
            {QVariantMap{{QStringLiteral("row"), 0}, {QStringLiteral("x"), QStringLiteral("-20")}}}));
        QVERIFY(!editor.document()->curve(1).sameState(created));
        editor.undo();
        QVERIFY(editor.document()->curve(1).sameState(created));
        // Detached: one step; the source's edits no longer move it; undo links it again.
        editor.selection()->select(created.id());
        QVERIFY(seam.detach());
        QVERIFY(!editor.document()->curve(1).seam);
        const Curve detached = editor.document()->curve(1);
        QVERIFY(editor.commands()->applyEdits(
            static_cast<int>(source),
            {QVariantMap{{QStringLiteral("row"), 0}, {QStringLiteral("x"), QStringLiteral("-20")}}}));
        QVERIFY(editor.document()->curve(1).sameState(detached));
        editor.undo();
        editor.undo();
        QVERIFY(editor.document()->curve(1).seam);
        QVERIFY(editor.document()->curve(1).sameState(created));
    }

    // Widths that leave nothing or are out of all proportion are refused, with the reason in the
    // dialog's `refusal` and the message line, quickly (the work is counted); before the offset had
    // a budget a width of 1e12 froze the window.
    void refusesAbsurdWidths_data()
    {
        QTest::addColumn<QString>("width");
        QTest::addColumn<int>("side");
        QTest::addColumn<int>("message");
        QTest::addRow("1e12") << QStringLiteral("1e12") << int(SeamAllowance::Outside)
                              << int(kontur::Message::SeamAllowanceTooWide);
        QTest::addRow("1e308") << QStringLiteral("1e308") << int(SeamAllowance::Outside)
                               << int(kontur::Message::SeamAllowanceTooWide);
        QTest::addRow("nothing left") << QStringLiteral("70") << int(SeamAllowance::Inside)
                                      << int(kontur::Message::SeamAllowanceFailed);
    }
    void refusesAbsurdWidths()
    {
        QFETCH(QString, width);
        QFETCH(int, side);
        QFETCH(int, message);
        EditController editor;
        editor.replaceDocument({piece()}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        SeamAllowance seam;
        seam.setEditor(&editor);
        QSignalSpy refusal(&seam, &SeamAllowance::refusalChanged);
        QSignalSpy finished(&seam, &SeamAllowance::finished);
        // Refused on the worker thread (the work bound itself is tested with the offset).
        QVERIFY(seam.create(width, side, SeamAllowance::Round, QStringLiteral("30")) && settled(seam));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(editor.document()->curveCount(), 1);
        QCOMPARE(editor.undoStack()->count(), 0);
        QCOMPARE(int(editor.message().id), message);
        QCOMPARE(refusal.count(), 1);
        QVERIFY(!seam.refusal().isEmpty());
        QCOMPARE(seam.refusal().text(), editor.messageText());
        // A width that fits clears the refusal.
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")) &&
                settled(seam));
        QVERIFY(seam.refusal().isEmpty());
        QCOMPARE(refusal.count(), 2);
    }

    // The AAMA sew line of a traced bodice (102 chords, tests/data/offset): a 30 mm allowance with
    // mitred corners does not close where the armhole's short chords begin at a corner. Add makes
    // nothing, one message says no allowance of this width fits, the dialog shows it; round corners
    // make it, closed and within the tolerance of 30 mm. Before, an open allowance was added (727 mm
    // of about 1,200).
    void wideMitredAllowanceThatDoesNotCloseIsRefused()
    {
        QFile file(QStringLiteral(KONTUR_OFFSET_DATA "/traced-bodice-sew-line.txt"));
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        std::vector<Point> corners;
        while (!file.atEnd()) {
            const QString line = QString::fromUtf8(file.readLine()).trimmed();
            const QStringList xy = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (!line.startsWith(QLatin1Char('#')) && xy.size() == 2)
                corners.emplace_back(xy[0].toDouble(), xy[1].toDouble());
        }
        QCOMPARE(corners.size(), std::size_t(102));
        std::vector<Point> control;
        for (std::size_t i = 0; i <= corners.size(); ++i) {
            const Point a = corners[i % corners.size()];
            control.push_back(a);
            if (i == corners.size())
                break;
            const Point b = corners[(i + 1) % corners.size()];
            control.push_back(a + (b - a) / 3.0);
            control.push_back(a + 2.0 * (b - a) / 3.0);
        }
        auto composite = kontur::geo::CompositeCurve::fromParts(
            control, std::vector<kontur::geo::NodeType>(corners.size(), kontur::geo::NodeType::Corner), true);
        QVERIFY(composite.ok());
        auto sewLine = Curve::makeComposite(std::move(composite).value());
        QVERIFY(sewLine.ok());
        EditController editor;
        editor.replaceDocument({sewLine.value()}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        SeamAllowance seam;
        seam.setEditor(&editor);
        QVERIFY(seam.create(QStringLiteral("30"), SeamAllowance::Outside, SeamAllowance::Miter, QStringLiteral("30")) &&
                settled(seam));
        QCOMPARE(editor.document()->curveCount(), 1);
        QCOMPARE(editor.undoStack()->count(), 0);
        QCOMPARE(editor.message().id, kontur::Message::SeamAllowanceFailed);
        QCOMPARE(seam.refusal().text(), editor.messageText());
        QVERIFY(seam.create(QStringLiteral("30"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")) &&
                settled(seam));
        QCOMPARE(editor.document()->curveCount(), 2);
        QVERIFY(seam.refusal().isEmpty());
        const Curve &allowance = editor.document()->curve(1);
        QVERIFY(allowance.isClosed());
        QVERIFY(worstDistanceError(allowance, editor.document()->curve(0), 30.0) <= 0.05);
    }

    // A document whose allowance has absurd settings (width 1e308, tolerance 1e-300, a curve at
    // 1e150) opens at once: the allowance keeps its saved shape and the message line says so. Before,
    // opening it grew to gigabytes until it was killed.
    void absurdSavedSettingsOpen()
    {
        EditController editor;
        editor.replaceDocument({piece()}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        SeamAllowance seam;
        seam.setEditor(&editor);
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")) &&
                settled(seam));
        auto data = kontur::toDocumentData(*editor.document());
        // The same piece and allowance at 1e150, with the settings out of all proportion.
        for (auto &record : data.curves)
            for (kontur::geo::Point &p : record.points)
                p *= 1e150;
        QJsonObject link = data.curves[1].settings.value(QLatin1String(kontur::io::kSeamKey)).toObject();
        link.insert(QStringLiteral("distance"), 1e308);
        link.insert(QStringLiteral("tolerance"), 1e-300);
        data.curves[1].settings.insert(QLatin1String(kontur::io::kSeamKey), link);
        std::vector<Curve> curves;
        for (const auto &record : data.curves) {
            auto c = kontur::fromRecord(record);
            QVERIFY2(c.ok(), c.ok() ? "" : c.error().message.c_str());
            curves.push_back(std::move(c).value());
        }
        const Curve saved = curves[1];
        QVERIFY(saved.seam);
        QCOMPARE(saved.seam->options.distance, 1e308);
        EditController reopened;
        kontur::geo::detail::resetOffsetWork();
        reopened.replaceDocument(std::move(curves), {}, data.units, false);
        QVERIFY(kontur::geo::detail::offsetWork() <= kontur::geo::kOffsetBudget);
        QCOMPARE(reopened.document()->curveCount(), 2);
        QVERIFY(reopened.document()->curve(1).seam);
        // The saved shape, point for point.
        const kontur::geo::PiecewiseBezier kept = reopened.document()->curve(1).toPiecewise(),
                                           savedShape = saved.toPiecewise();
        QCOMPARE(kept.segmentCount(), savedShape.segmentCount());
        for (int i = 0; i < kept.segmentCount(); ++i)
            QVERIFY(kept.segments()[i].controlPoints() == savedShape.segments()[i].controlPoints());
        QCOMPARE(reopened.message().id, kontur::Message::SeamAllowanceKept);
        QVERIFY(reopened.messageText().contains(saved.name));

        // A tolerance of 1e-300 alone is raised to what doubles resolve: the allowance is recomputed.
        link.insert(QStringLiteral("distance"), 10e150);
        data.curves[1].settings.insert(QLatin1String(kontur::io::kSeamKey), link);
        curves.clear();
        for (const auto &record : data.curves)
            curves.push_back(kontur::fromRecord(record).value());
        EditController third;
        third.replaceDocument(std::move(curves), {}, data.units, false);
        QVERIFY(third.message().isEmpty());
        QVERIFY(worstDistanceError(third.document()->curve(1), third.document()->curve(0), 10e150) <= 1e-6 * 10e150);
    }

    // A long allowance runs on a worker thread: create() returns at once, busy() holds until it is
    // done, the progress is shown only after kShowProgressMs and grows; Cancel leaves the document
    // and the undo stack exactly as they were. Then one that is let finish is one undo step, added
    // without any offset work on this thread (the Document's recomputation of the inserted allowance
    // finds the worker's result), and undo and redo take it away and bring it back.
    void longAllowanceCancelThenFinish()
    {
        EditController editor;
        editor.replaceDocument({kontur::test::wavyPiece(20'000)}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        const Curve source = editor.document()->curve(0);
        SeamAllowance seam;
        seam.setEditor(&editor);
        QSignalSpy finished(&seam, &SeamAllowance::finished);
        QSignalSpy progress(&seam, &SeamAllowance::progressChanged);
        QVERIFY(seam.create(QStringLiteral("40"), SeamAllowance::Inside, SeamAllowance::Round, QStringLiteral("30")));
        QVERIFY(seam.busy());
        QVERIFY(!seam.progressShown());
        QCOMPARE(editor.document()->curveCount(), 1);
        // Shown once it has run that long, and well into the trimming (by the offset's own estimate).
        QTRY_VERIFY_WITH_TIMEOUT(seam.progressShown() && seam.progress() >= 0.5, 60'000);
        QVERIFY2(seam.busy(), "the long allowance finished before it could be cancelled");
        QVERIFY(progress.count() >= 2);
        // One job at a time: the others are refused with a message.
        QVERIFY(!seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")));
        QCOMPARE(editor.message().id, kontur::Message::SeamAllowanceBusy);
        QElapsedTimer timer;
        timer.start();
        seam.cancel();
        QVERIFY(settled(seam));
        qInfo("cancelled at %.0f %%: finished %lld ms after Cancel", 100 * seam.progress(), timer.elapsed());
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(editor.message().id, kontur::Message::SeamAllowanceCancelled);
        QCOMPARE(editor.document()->curveCount(), 1);
        QVERIFY(editor.document()->curve(0).sameState(source));
        QCOMPARE(editor.undoStack()->count(), 0);
        QVERIFY(!seam.progressShown());

        // A shorter one let finish.
        editor.replaceDocument({kontur::test::wavyPiece(4'000)}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        kontur::geo::detail::resetOffsetWork();
        timer.restart();
        QVERIFY(seam.create(QStringLiteral("40"), SeamAllowance::Inside, SeamAllowance::Round, QStringLiteral("30")));
        QVERIFY(settled(seam));
        qInfo("a 4,000-knot inside allowance: %lld ms", timer.elapsed());
        QCOMPARE(finished.count(), 2);
        QCOMPARE(finished.at(1).at(0).toBool(), true);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        QCOMPARE(editor.document()->curveCount(), 2);
        QCOMPARE(editor.undoStack()->count(), 1);
        const Curve added = editor.document()->curve(1);
        QVERIFY(added.seam);
        QCOMPARE(added.seam->options.side, kontur::geo::OffsetSide::Inside);
        QVERIFY(worstDistanceError(added, editor.document()->curve(0), 40.0) <= 0.05);
        editor.undo();
        QCOMPARE(editor.document()->curveCount(), 1);
        editor.redo();
        QCOMPARE(editor.document()->curveCount(), 2);
        QVERIFY(editor.document()->curve(1).sameState(added));
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});

        // Changing its settings is one more step, likewise off this thread.
        editor.selection()->select(added.id());
        QVERIFY(seam.apply(QStringLiteral("30"), SeamAllowance::Inside, SeamAllowance::Round, QStringLiteral("30")) &&
                settled(seam));
        QCOMPARE(editor.undoStack()->count(), 2);
        QCOMPARE(editor.document()->curve(1).seam->options.distance, 30.0);
        QVERIFY(worstDistanceError(editor.document()->curve(1), editor.document()->curve(0), 30.0) <= 0.05);
        QCOMPARE(kontur::geo::detail::offsetWork(), std::uint64_t{0});
        editor.undo();
        QVERIFY(editor.document()->curve(1).sameState(added));
    }

    // The curve edited while its allowance is computed: the result is of the old shape, so nothing
    // is added and the message says why; the edit stays the only undo step. (Each test asks for a
    // width of its own, though each document remembers only its own offsets: Document::allowanceOf.)
    void sourceEditedMeanwhile()
    {
        EditController editor;
        editor.replaceDocument({kontur::test::wavyPiece(4'000)}, {}, QStringLiteral("mm"), false);
        const kontur::CurveId id = editor.document()->idAt(0);
        editor.selection()->select(id);
        SeamAllowance seam;
        seam.setEditor(&editor);
        QSignalSpy finished(&seam, &SeamAllowance::finished);
        QVERIFY(seam.create(QStringLiteral("35"), SeamAllowance::Inside, SeamAllowance::Round, QStringLiteral("30")));
        QVERIFY(seam.busy());
        QVERIFY(editor.commands()->applyEdits(
            static_cast<int>(id),
            {QVariantMap{{QStringLiteral("row"), 0}, {QStringLiteral("x"), QStringLiteral("260")}}}));
        QVERIFY(settled(seam));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(editor.message().id, kontur::Message::SeamAllowanceOutdated);
        QCOMPARE(editor.document()->curveCount(), 1);
        QCOMPARE(editor.undoStack()->count(), 1);
    }

    // Destroyed mid-job (the app quitting): the worker is cancelled and joined, no thread is left.
    void destroyedWhileRunning()
    {
        EditController editor;
        editor.replaceDocument({kontur::test::wavyPiece(20'000)}, {}, QStringLiteral("mm"), false);
        editor.selection()->select(editor.document()->idAt(0));
        const int threads = threadCount();
        auto seam = std::make_unique<SeamAllowance>();
        seam->setEditor(&editor);
        QVERIFY(seam->create(QStringLiteral("45"), SeamAllowance::Inside, SeamAllowance::Round, QStringLiteral("30")));
        QCOMPARE(threadCount(), threads + 1);
        QTRY_VERIFY_WITH_TIMEOUT(seam->progress() > 0 || !seam->busy(), 30'000); // its first progress report
        QVERIFY(seam->busy());
        QElapsedTimer timer;
        timer.start();
        seam.reset();
        qInfo("destroyed mid-job in %lld ms", timer.elapsed());
        // Joined: QThread::wait() returns as the thread's function ends, the kernel task a moment later.
        QTRY_COMPARE(threadCount(), threads);
        QCOMPARE(editor.document()->curveCount(), 1);
        QCOMPARE(editor.undoStack()->count(), 0);
        QCoreApplication::processEvents(); // the worker's queued end reaches no one
    }

    void saveOpenRoundTrip()
    {
        EditController editor;
        Curve open = Curve::make(CurveKind::NaturalSpline, {{0, 0}, {40, 30}, {80, 10}, {120, 40}});
        open.name = QStringLiteral("Armhole");
        editor.replaceDocument({open, piece()}, {}, QStringLiteral("cm"), false);
        SeamAllowance seam;
        seam.setEditor(&editor);
        editor.selection()->select(editor.document()->idAt(1));
        QVERIFY(seam.create(QStringLiteral("1.5"), SeamAllowance::Outside, SeamAllowance::Bevel, QStringLiteral("3")) &&
                settled(seam));
        editor.selection()->select(editor.document()->idAt(0));
        QCOMPARE(seam.distanceText(), QStringLiteral("1.5")); // the last used settings
        QVERIFY(!seam.closed());
        QVERIFY(seam.create(QStringLiteral("1"), SeamAllowance::Left, SeamAllowance::Round, QStringLiteral("3")) &&
                settled(seam));
        QCOMPARE(editor.document()->curveCount(), 4);
        QVERIFY(!editor.document()->curve(3).isClosed());

        const QByteArray json = kontur::io::documentToJson(kontur::toDocumentData(*editor.document()));
        QVERIFY(json.contains("\"seamAllowance\""));
        auto data = kontur::io::documentFromJson(json);
        QVERIFY(data.ok());
        std::vector<Curve> curves;
        for (const auto &record : data->curves) {
            auto c = kontur::fromRecord(record);
            QVERIFY(c.ok());
            curves.push_back(std::move(c).value());
        }
        EditController reopened;
        reopened.replaceDocument(std::move(curves), {}, data->units, false);
        QCOMPARE(reopened.document()->curveCount(), 4);
        const Curve &a = reopened.document()->curve(2), &b = reopened.document()->curve(3);
        QVERIFY(a.seam && b.seam);
        QCOMPARE(a.seam->source, reopened.document()->idAt(1));
        QCOMPARE(b.seam->source, reopened.document()->idAt(0));
        QCOMPARE(a.seam->options.distance, 1.5);
        QCOMPARE(b.seam->options.side, kontur::geo::OffsetSide::Left);
        QCOMPARE(a.seam->options.join, kontur::geo::OffsetJoin::Bevel);
        QVERIFY(a.sameState(editor.document()->curve(2)));
        QVERIFY(b.sameState(editor.document()->curve(3)));
        QCOMPARE(kontur::io::documentToJson(kontur::toDocumentData(*reopened.document())), json);
        // The reopened allowance still follows its source.
        const Curve openAllowance = b;
        QVERIFY(reopened.commands()->applyEdits(
            static_cast<int>(reopened.document()->idAt(0)),
            {QVariantMap{{QStringLiteral("row"), 1}, {QStringLiteral("y"), QStringLiteral("45")}}}));
        QVERIFY(!reopened.document()->curve(3).sameState(openAllowance));
    }
};

QTEST_MAIN(TestSeamAllowance)
#include "tst_seamallowance.moc"
