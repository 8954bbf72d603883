// Seam allowances in the model layer (issue #22): creating one is one undo step and gives a curve at
// the distance from its source; editing the source moves the allowance with it, and undo brings both
// back exactly; settings changes are one undo step each; the allowance's own points do not move
// while linked; deleting the source leaves the allowance, undo relinks it; detaching is one step;
// the link survives a save / open round trip (byte-identical on the second save).
#include "io/document.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/documentio.h"
#include "models/document/selection.h"
#include "models/trace/seamallowance.h"

#include <QtTest>

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
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Round, QStringLiteral("30")));
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
        QVERIFY(seam.apply(QStringLiteral("15"), SeamAllowance::Inside, SeamAllowance::Miter, QStringLiteral("30")));
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
        QVERIFY(seam.create(QStringLiteral("10"), SeamAllowance::Outside, SeamAllowance::Miter, QStringLiteral("30")));
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

    void saveOpenRoundTrip()
    {
        EditController editor;
        Curve open = Curve::make(CurveKind::NaturalSpline, {{0, 0}, {40, 30}, {80, 10}, {120, 40}});
        open.name = QStringLiteral("Armhole");
        editor.replaceDocument({open, piece()}, {}, QStringLiteral("cm"), false);
        SeamAllowance seam;
        seam.setEditor(&editor);
        editor.selection()->select(editor.document()->idAt(1));
        QVERIFY(seam.create(QStringLiteral("1.5"), SeamAllowance::Outside, SeamAllowance::Bevel, QStringLiteral("3")));
        editor.selection()->select(editor.document()->idAt(0));
        QCOMPARE(seam.distanceText(), QStringLiteral("1.5")); // the last used settings
        QVERIFY(!seam.closed());
        QVERIFY(seam.create(QStringLiteral("1"), SeamAllowance::Left, SeamAllowance::Round, QStringLiteral("3")));
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
