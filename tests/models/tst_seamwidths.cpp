// A piece's seam allowance per seam (SeamWidths, issue #44): a seam chosen by a tap near it, its
// width stepped by 0.5 cm, typed, clamped at 0, refused when not a number or too wide for the piece;
// a hem's corners turned back. The document's allowance is each time the geometry's offset with those
// widths (geo::offsetCurve, checked both ways by sampling); every change is one undo step; saving and
// opening keeps the widths and hems and gives the same allowance.
#include "../straightpiece.h"
#include "geometry/offset.h"
#include "geometry/seams.h"
#include "io/seam.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/seamwidths.h"
#include "models/document/document.h"
#include "models/document/selection.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using kontur::Curve;
using kontur::EditController;
using kontur::SeamWidths;
using kontur::geo::PiecewiseBezier;
using kontur::geo::Point;
namespace io = kontur::io;
namespace geo = kontur::geo;

namespace {

// A skirt panel, counter-clockwise: the hem along y = 0 from (0, 0) to (300, 0), the sides flared by
// 20 mm in 400 mm, the waist at y = 400 (seams 0 hem, 1 right side, 2 waist, 3 left side).
Curve panel()
{
    Curve c = kontur::test::straightOutline({Point(0, 0), Point(300, 0), Point(280, 400), Point(20, 400)},
                                            QStringLiteral("Skirt"))
                  .value();
    c.piece = io::PieceMarks{};
    return c;
}

// The largest distance from a sample of one curve to the other, both ways.
double apart(const PiecewiseBezier &a, const PiecewiseBezier &b)
{
    double worst = 0.0;
    for (const auto &[from, to] : {std::pair{&a, &b}, std::pair{&b, &a}})
        for (const geo::Bezier &s : from->segments())
            for (int j = 0; j <= 16; ++j)
                worst = std::max(worst, to->nearest(s.eval(j / 16.0)).distance);
    return worst;
}

} // namespace

class TestSeamWidths final : public QObject
{
    Q_OBJECT

    EditController m_editor;
    SeamWidths m_seams;

    const Curve &allowance() const { return m_editor.document()->curve(1); }
    // The allowance the geometry makes of the panel with these widths and hems.
    PiecewiseBezier expected(const std::vector<std::optional<double>> &widths, const std::vector<int> &hems) const
    {
        const PiecewiseBezier outline = m_editor.document()->curve(0).toPiecewise();
        geo::OffsetOptions o = io::defaultSeamOptions(QStringLiteral("mm"));
        o.segmentDistances = geo::segmentDistancesOf(outline, widths, o.distance);
        if (!hems.empty())
            o.hems = geo::segmentHemsOf(outline, hems);
        return geo::offsetCurve(outline, o)->curve;
    }
    void load(bool withAllowance)
    {
        std::vector<Curve> curves{panel()};
        if (withAllowance) {
            const geo::OffsetOptions options = io::defaultSeamOptions(QStringLiteral("mm"));
            Curve seam = *Curve::makeOffset(curves[0], options);
            seam.seam = kontur::SeamLink{kontur::CurveId::None, options, 0};
            curves.push_back(seam);
        }
        m_editor.replaceDocument(curves, kontur::Background{}, QStringLiteral("mm"), false);
        m_editor.selection()->select(m_editor.document()->curve(0).id(), -1);
    }

private Q_SLOTS:
    void init() { m_seams.setEditor(&m_editor); }

    void stepsTypedAndUndone()
    {
        load(true);
        QCOMPARE(m_seams.seamCount(), 4);
        QVERIFY(!m_seams.selectSeamAt(150, 30, 5)); // not near a seam
        QCOMPARE(m_seams.seam(), -1);
        QVERIFY(m_seams.selectSeamAt(150, 2, 5));
        QCOMPARE(m_seams.seam(), 0);
        QCOMPARE(m_seams.width().value_or(-1), 10.0);
        QCOMPARE(m_seams.step(), 5.0);
        const int start = m_editor.undoStack()->count();
        for (int i = 0; i < 4; ++i)
            QVERIFY(m_seams.stepWidth(1));
        QCOMPARE(m_seams.width().value_or(-1), 30.0);
        QCOMPARE(m_editor.undoStack()->count(), start + 4);
        // The steps' allowance is made on the worker (issue #45): it lands through the event loop.
        QTRY_VERIFY(m_editor.document()->allowancesSettled());
        QVERIFY(apart(allowance().toPiecewise(), expected({30.0}, {})) <= 1e-3);
        // The right side typed 15; then back to the allowance's own width.
        QVERIFY(m_seams.selectSeamAt(291, 200, 5));
        QCOMPARE(m_seams.seam(), 1);
        QVERIFY(m_seams.setWidthText(QStringLiteral(" 15 ")));
        QVERIFY(apart(allowance().toPiecewise(), expected({30.0, 15.0}, {})) <= 1e-3);
        QVERIFY(m_seams.resetWidth());
        QVERIFY(!m_seams.ownWidth());
        QCOMPARE(m_editor.document()->curve(0).piece->seamWidths, (std::vector<std::optional<double>>{30.0}));
        // Refused, nothing changed: not a number, below 0, far too wide for the piece.
        const int before = m_editor.undoStack()->count();
        for (const char *text : {"abc", "-1", "1e9"}) {
            QVERIFY2(!m_seams.setWidthText(QString::fromLatin1(text)), text);
            QVERIFY2(!m_seams.message().isEmpty(), text);
        }
        QCOMPARE(m_editor.undoStack()->count(), before);
        // A step below 0 stops at 0: the allowance follows the seam.
        QVERIFY(m_seams.setWidthText(QStringLiteral("3")));
        QVERIFY(m_seams.stepWidth(-1));
        QCOMPARE(m_seams.width().value_or(-1), 0.0);
        QVERIFY(m_seams.message().isEmpty());
        QTRY_VERIFY(m_editor.document()->allowancesSettled());
        QVERIFY(allowance().toPiecewise().nearest(Point(290, 200)).distance <= 1e-9);
        // Undo, step by step, to the 10 mm allowance all round.
        while (m_editor.undoStack()->index() > start)
            m_editor.undo();
        QTRY_VERIFY(m_editor.document()->allowancesSettled());
        QVERIFY(m_editor.document()->curve(0).piece->seamWidths.empty());
        QVERIFY(apart(allowance().toPiecewise(), expected({}, {})) <= 1e-3);
    }

    // The seams follow the outline, though the document finds them once for a change (issue #45): a
    // corner made smooth joins its two seams, and the undo parts them again.
    void seamsFollowTheOutline()
    {
        load(true);
        const kontur::Document &doc = *m_editor.document();
        const int id = static_cast<int>(doc.curve(0).id());
        QCOMPARE(m_seams.seamCount(), 4);
        QVERIFY(m_editor.commands()->setNodeType(id, 1, static_cast<int>(geo::NodeType::Smooth)));
        QCOMPARE(m_seams.seamCount(), 3);
        QCOMPARE(doc.seamsOf(doc.curve(0)), geo::seamSpans(doc.curve(0).toPiecewise()));
        m_editor.undo();
        QCOMPARE(m_seams.seamCount(), 4);
        QCOMPARE(doc.seamsOf(doc.curve(0)), geo::seamSpans(doc.curve(0).toPiecewise()));
    }

    // The hem turned back: the allowance is the geometry's turned-back one, not the mitred one.
    void hemTurnedBack()
    {
        load(true);
        QVERIFY(m_seams.selectSeamAt(150, 0, 1));
        QVERIFY(m_seams.setWidthText(QStringLiteral("30")));
        QVERIFY(!m_seams.hem());
        QVERIFY(m_seams.setHem(true));
        QVERIFY(m_seams.hem());
        QCOMPARE(m_editor.document()->curve(0).piece->hems, std::vector<int>{0});
        const PiecewiseBezier turned = expected({30.0}, {0}), mitred = expected({30.0}, {});
        QVERIFY(apart(turned, mitred) > 1.0); // the flare makes them differ
        QVERIFY(apart(allowance().toPiecewise(), turned) <= 1e-3);
        m_editor.undo();
        QVERIFY(!m_seams.hem());
        QVERIFY(apart(allowance().toPiecewise(), mitred) <= 1e-3);
        m_editor.redo();

        // Saved and opened: the same widths, hems and allowance.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        kontur::DocumentFiles files;
        files.setEditor(&m_editor);
        const QUrl file = QUrl::fromLocalFile(dir.filePath(QStringLiteral("skirt.kontur")));
        QVERIFY(files.saveAs(file));
        files.newDocument();
        QVERIFY(files.open(file));
        QCOMPARE(m_editor.document()->curveCount(), 2);
        QCOMPARE(m_editor.document()->curve(0).piece->hems, std::vector<int>{0});
        QCOMPARE(m_editor.document()->curve(0).piece->seamWidths, (std::vector<std::optional<double>>{30.0}));
        QVERIFY(apart(allowance().toPiecewise(), turned) <= 1e-3);
    }

    // A step to a width that gives no allowance (issue #45): the step is made (its allowance is made
    // on the worker, not tried first), the allowance keeps its shape, and the message says so once
    // the worker has found out. A typed width is still refused at once.
    void stepThatDoesNotFit()
    {
        load(true);
        QVERIFY(m_seams.selectSeamAt(150, 0, 1));
        // 1000 times the panel's larger side (400 mm) is the widest an allowance may be.
        QVERIFY(!m_seams.setWidthText(QStringLiteral("400005")));
        QCOMPARE(m_seams.message().id, kontur::Message::SeamWidthDoesNotFit);
        QVERIFY(m_seams.setWidthText(QStringLiteral("400000")));
        QVERIFY(m_seams.message().isEmpty());
        const Curve widest = allowance();
        const int before = m_editor.undoStack()->count();
        QVERIFY(m_seams.stepWidth(1));
        QCOMPARE(m_editor.undoStack()->count(), before + 1);
        QCOMPARE(m_seams.width().value_or(-1), 400005.0);
        QTRY_VERIFY(m_editor.document()->allowancesSettled());
        QCOMPARE(m_seams.message().id, kontur::Message::SeamWidthDoesNotFit);
        QVERIFY(allowance().sameState(widest));
        // Back one step: the allowance that was made, remembered.
        m_editor.undo();
        QVERIFY(m_editor.document()->allowancesSettled());
        QVERIFY(allowance().sameState(widest));
        QCOMPARE(m_seams.width().value_or(-1), 400000.0);
    }

    // Without an allowance a seam can be chosen, but it has no width to set.
    void noAllowanceNoWidth()
    {
        load(false);
        QVERIFY(m_seams.selectSeamAt(150, 0, 1));
        QVERIFY(!m_seams.width());
        QVERIFY(!m_seams.message().isEmpty());
        QVERIFY(!m_seams.stepWidth(1));
        QVERIFY(!m_seams.setHem(true));
        QVERIFY(!m_editor.document()->curve(0).piece->hems.size());
    }
};

QTEST_MAIN(TestSeamWidths)
#include "tst_seamwidths.moc"
