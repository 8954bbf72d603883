// Properties of the model layer over random input: 10,000 random edits of every kind, then undo
// all gives the initial document exactly and redo all the final one, with the item models checked
// by QAbstractItemModelTester throughout; and the indexed hit test agrees with a full scan.
#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/commands.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"

#include <QAbstractItemModelTester>
#include <QtTest>

#include <algorithm>
#include <random>

using kontur::CurveKind;
using kontur::EditController;
using kontur::geo::Point;

namespace {

struct Snapshot
{
    std::vector<kontur::Curve> curves;
    kontur::Background background;
};

Snapshot snapshot(const kontur::Document &document)
{
    return {document.curves(), document.background()};
}

bool same(const Snapshot &a, const kontur::Document &document)
{
    if (a.curves.size() != document.curves().size() || !(a.background == document.background()))
        return false;
    for (std::size_t i = 0; i < a.curves.size(); ++i)
        if (!a.curves[i].sameState(document.curves()[i]))
            return false;
    return true;
}

class RandomEditor
{
public:
    explicit RandomEditor(EditController &editor, std::uint64_t seed)
        : m_editor(editor)
        , m_rng(seed)
    {
    }

    Point point() { return {coord(m_rng), coord(m_rng)}; }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }

    void addCurve()
    {
        const auto kind = static_cast<CurveKind>(pick(kontur::kKindCount));
        const kontur::KindTraits traits = kontur::traitsOf(kind);
        const int n = traits.placementCount > 0 ? traits.placementCount : traits.minPoints + pick(6);
        std::vector<Point> points;
        for (int i = 0; i < n; ++i)
            points.push_back(point());
        if (kind == CurveKind::FunctionSpline) // y(x) needs increasing x
            std::sort(points.begin(), points.end(), [](const Point &a, const Point &b) { return a.x() < b.x(); });
        QVariantList rows;
        for (const Point &p : points)
            rows << QVariant(QVariantList{p.x(), p.y()});
        m_editor.placement()->setParameterization(pick(3));
        m_editor.placement()->createFromCoordinates(static_cast<int>(kind), rows);
    }

    // One random edit through the controller's public API; refusals (messages) are part of the test.
    void step()
    {
        const int curves = m_editor.document()->curveCount();
        if (curves == 0 || pick(12) == 0) {
            addCurve();
            return;
        }
        const int c = pick(curves);
        const kontur::Curve &curve = m_editor.document()->curve(c);
        const int id = kontur::test::idAt(m_editor, c);
        kontur::CurveCommands &commands = *m_editor.commands();
        switch (pick(13)) {
        case 0:
        case 1:
        case 2: { // a drag of 1–4 steps of one point, with either handle mode
            const int row = pick(curve.rowCount());
            const Point at = curve.row(row).position;
            if (m_editor.beginDrag(QPointF(at.x(), at.y()), 1e-9, pick(2) == 0)) {
                for (int s = pick(4); s >= 0; --s) {
                    const Point p = at + Point(coord(m_rng), coord(m_rng)) * 0.1;
                    m_editor.dragTo(QPointF(p.x(), p.y()));
                }
                m_editor.endDrag();
            }
            break;
        }
        case 3:
            commands.setCurveParameterization(id, pick(3));
            break;
        case 4:
            commands.setNodeType(id, pick(std::max(1, curve.composite().knotCount())), pick(3));
            break;
        case 5: {
            const Point p = point();
            commands.insertPoint(id, pick(curve.definingCount() + 1), QPointF(p.x(), p.y()));
            break;
        }
        case 6:
            commands.removePoint(id, pick(std::max(1, curve.definingCount())));
            break;
        case 7:
            commands.insertKnotOnSegment(id, pick(std::max(1, curve.segmentCount())), 0.1 + 0.8 * unit(m_rng));
            break;
        case 8:
            commands.closeCurve(id);
            break;
        case 9:
            commands.setCurveLocked(id, pick(4) == 0);
            commands.setCurveOrder(id, 2 + pick(4));
            break;
        case 10:
            commands.setCurveVisible(id, pick(3) != 0);
            commands.setCurveColor(id, QColor::fromRgb(static_cast<QRgb>(m_rng())));
            break;
        case 11:
            if (pick(4) == 0)
                commands.deleteCurve(id);
            else
                commands.moveCurve(id, pick(curves));
            break;
        case 12: {
            QVariantList rows;
            for (int i = 0; i < curve.definingCount(); ++i) {
                const Point p = curve.definingPoint(i) + (pick(3) == 0 ? Point(1, -1) : Point(0, 0));
                rows << QVariant(QVariantList{p.x(), p.y()});
            }
            commands.applyCoordinates(id, rows);
            break;
        }
        }
        if (pick(50) == 0) {
            kontur::Background background;
            background.file = QStringLiteral("/patterns/sleeve.png");
            background.opacity = unit(m_rng);
            background.scale = 0.1 + unit(m_rng);
            m_editor.background()->setBackground(background);
        }
    }

private:
    EditController &m_editor;
    std::mt19937_64 m_rng;
    std::uniform_real_distribution<double> coord{-500.0, 500.0};
    std::uniform_real_distribution<double> unit{0.0, 1.0};
};

} // namespace

class TestUndo final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void randomEditsUndoAndRedoExactly();
    void resetAllIsOneUndoStep();
    void indexedHitTestAgreesWithAFullScan();
    void dragOfAHundredStepsIsOneUndoStep();
    void curveIdsAreUniqueAndKeptByUndo();
};

void TestUndo::randomEditsUndoAndRedoExactly()
{
    EditController editor;
    RandomEditor random(editor, 20261122);
    // Start from a document with a few curves, made without undo history.
    for (int i = 0; i < 5; ++i)
        random.addCurve();
    editor.replaceDocument(editor.document()->curves(), editor.document()->background(), editor.document()->units(),
                           false);
    const Snapshot initial = snapshot(*editor.document());

    QAbstractItemModelTester curves(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester points(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    for (int i = 0; i < 10000; ++i) {
        random.step();
        if (i % 97 == 0)
            editor.selection()->selectRow(random.pick(std::max(1, editor.document()->curveCount())));
        if (QTest::currentTestFailed())
            QFAIL(qPrintable(QStringLiteral("model check failed at edit %1").arg(i)));
    }
    const Snapshot final = snapshot(*editor.document());
    QVERIFY(editor.undoStack()->count() > 1000); // most edits were accepted

    while (editor.canUndo())
        editor.undo();
    QVERIFY(same(initial, *editor.document()));
    while (editor.canRedo())
        editor.redo();
    QVERIFY(same(final, *editor.document()));
}

void TestUndo::resetAllIsOneUndoStep()
{
    EditController editor;
    RandomEditor random(editor, 5);
    for (int i = 0; i < 6; ++i)
        random.addCurve();
    const Snapshot before = snapshot(*editor.document());
    QVERIFY(editor.isModified());
    editor.markSaved();
    QVERIFY(!editor.isModified());
    editor.commands()->resetAll();
    QCOMPARE(editor.document()->curveCount(), 0);
    QVERIFY(editor.isModified());
    editor.undo();
    QVERIFY(same(before, *editor.document()));
    QVERIFY(!editor.isModified()); // back at the saved state
}

void TestUndo::indexedHitTestAgreesWithAFullScan()
{
    EditController editor;
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
    for (int c = 0; c < 200; ++c) {
        QVariantList rows;
        for (int i = 0; i < 10; ++i)
            rows << QVariant(QVariantList{coord(rng), coord(rng)});
        QVERIFY(editor.placement()->createFromCoordinates(
            static_cast<int>(c % 2 ? CurveKind::Bezier : CurveKind::Composite), rows));
    }
    const auto bruteForce = [&](const Point &q, double radius) {
        kontur::PointRef best;
        double bestDistance = radius;
        for (int c = 0; c < editor.document()->curveCount(); ++c) {
            const kontur::Curve &curve = editor.document()->curve(c);
            // Only what is shown can be hit: a composite's handles near its selected knot.
            const int selected = c == editor.selection()->curveRow() ? editor.selection()->point() : -1;
            for (int r = 0; r < curve.rowCount(); ++r) {
                if (!curve.isRowShown(r, selected))
                    continue;
                const double d = (curve.row(r).position - q).norm();
                if (d < bestDistance) {
                    bestDistance = d;
                    best = {editor.document()->idAt(c), r};
                }
            }
        }
        return std::pair{best, bestDistance};
    };
    for (int k = 0; k < 2000; ++k) {
        const Point q(coord(rng), coord(rng));
        const double radius = k % 2 ? 15.0 : 60.0; // two zoom levels: the index rebuilds between them
        const kontur::PointRef hit = editor.hitTest(q, radius);
        const auto [expected, distance] = bruteForce(q, radius);
        QCOMPARE(hit.isValid(), expected.isValid());
        if (hit.isValid()) {
            const double d = (editor.document()->find(hit.curve)->row(hit.point).position - q).norm();
            QCOMPARE(d, distance);
        }
        // Drags keep the index up to date in place.
        if (k % 10 == 0 && hit.isValid()) {
            const Point at = editor.document()->find(hit.curve)->row(hit.point).position;
            if (editor.beginDrag(QPointF(at.x(), at.y()), 1e-9)) {
                editor.dragTo(QPointF(coord(rng), coord(rng)));
                editor.endDrag();
            }
        }
    }
}

namespace {

std::vector<std::vector<Point>> rowsOf(const kontur::Document &document)
{
    std::vector<std::vector<Point>> out;
    for (const kontur::Curve &curve : document.curves()) {
        std::vector<Point> rows;
        for (int r = 0; r < curve.rowCount(); ++r)
            rows.push_back(curve.row(r).position);
        out.push_back(std::move(rows));
    }
    return out;
}

using kontur::test::rows;

} // namespace

void TestUndo::dragOfAHundredStepsIsOneUndoStep()
{
    EditController editor;
    kontur::Document &doc = *editor.document();
    // A composite curve (a knot's drag moves its handles too) and a Bézier curve that must not move.
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Composite),
                                                      rows({{0, 0}, {10, 10}, {20, 0}, {30, 10}})));
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{100, 0}, {110, 20}, {130, 20}, {140, 0}})));
    const auto before = rowsOf(doc);
    const int count = editor.undoStack()->count();
    const int index = editor.undoStack()->index();
    QCOMPARE(index, count);

    // Every signal the document has; each must come from inside dragTo, and the first one from the
    // first step's command while QUndoStack::push runs its redo(), before the stack's index moves on.
    bool insideDragTo = false;
    int outside = 0;
    int documentSignals = 0;
    std::vector<int> indexAtRowsChanged;
    const auto heard = [&] {
        ++documentSignals;
        if (!insideDragTo)
            ++outside;
    };
    QObject guard;
    connect(&doc, &kontur::Document::rowsChanged, &guard, [&](int curve, int first, int last) {
        QCOMPARE(curve, 0);
        QVERIFY(first <= 3 && 3 <= last);
        indexAtRowsChanged.push_back(editor.undoStack()->index());
    });
    connect(&doc, &kontur::Document::rowsChanged, &guard, heard);
    connect(&doc, &kontur::Document::changed, &guard, heard);
    connect(&doc, &kontur::Document::curveChanged, &guard, heard);
    connect(&doc, &kontur::Document::curveAboutToBeInserted, &guard, heard);
    connect(&doc, &kontur::Document::curveInserted, &guard, heard);
    connect(&doc, &kontur::Document::curveAboutToBeRemoved, &guard, heard);
    connect(&doc, &kontur::Document::curveRemoved, &guard, heard);
    connect(&doc, &kontur::Document::curveAboutToBeMoved, &guard, heard);
    connect(&doc, &kontur::Document::curveMoved, &guard, heard);
    connect(&doc, &kontur::Document::curveCountChanged, &guard, heard);
    connect(&doc, &kontur::Document::backgroundChanged, &guard, heard);
    connect(&doc, &kontur::Document::unitsChanged, &guard, heard);

    // Grabbing knot 1 (row 3) changes nothing yet.
    QVERIFY(editor.beginDrag({10.25, 9.75}, 1.0));
    QVERIFY(editor.isDragging());
    QCOMPARE(editor.selection()->point(), 3);
    QCOMPARE(documentSignals, 0);
    QVERIFY(rowsOf(doc) == before);
    QCOMPARE(editor.undoStack()->count(), count);

    for (int i = 1; i <= 100; ++i) {
        insideDragTo = true;
        editor.dragTo({10.25 + 0.5 * i, 9.75 - 0.25 * i});
        insideDragTo = false;
        QCOMPARE(editor.undoStack()->count(), count + 1);
        QCOMPARE(editor.undoStack()->index(), index + 1);
    }
    editor.endDrag();
    QVERIFY(!editor.isDragging());
    QCOMPARE(outside, 0);
    QCOMPARE(indexAtRowsChanged.size(), std::size_t{100}); // one announcement per step
    QCOMPARE(indexAtRowsChanged.front(), index);           // the first step: inside push, before the index moved
    for (std::size_t i = 1; i < indexAtRowsChanged.size(); ++i)
        QCOMPARE(indexAtRowsChanged[i], index + 1); // merged into the drag's command
    QCOMPARE(editor.undoStack()->count(), count + 1);

    const auto after = rowsOf(doc);
    // The knot went by the pointer's displacement (the grab offset is kept): (10, 10) + (50, -25).
    QCOMPARE(after[0][3], Point(60, -15));
    QVERIFY(after[0] != before[0]);
    QVERIFY(after[0][0] == before[0][0]); // the first knot stays
    QVERIFY(after[1] == before[1]);       // the other curve stays

    outside = 0;
    editor.undo();
    QCOMPARE(editor.undoStack()->index(), index);
    const auto undone = rowsOf(doc);
    QCOMPARE(undone.size(), before.size());
    for (std::size_t c = 0; c < before.size(); ++c) {
        QCOMPARE(undone[c].size(), before[c].size());
        for (std::size_t r = 0; r < before[c].size(); ++r) {
            QVERIFY2(undone[c][r].x() == before[c][r].x() && undone[c][r].y() == before[c][r].y(),
                     qPrintable(QStringLiteral("curve %1 row %2").arg(c).arg(r)));
        }
    }
    editor.redo();
    const auto redone = rowsOf(doc);
    for (std::size_t c = 0; c < after.size(); ++c) {
        QCOMPARE(redone[c].size(), after[c].size());
        for (std::size_t r = 0; r < after[c].size(); ++r) {
            QVERIFY2(redone[c][r].x() == after[c][r].x() && redone[c][r].y() == after[c][r].y(),
                     qPrintable(QStringLiteral("curve %1 row %2").arg(c).arg(r)));
        }
    }
    // Undo steps before the drag are still there: the two curves' creations.
    editor.undo();
    editor.undo();
    editor.undo();
    QCOMPARE(doc.curveCount(), 0);
}

void TestUndo::curveIdsAreUniqueAndKeptByUndo()
{
    using kontur::CurveId;
    EditController editor;
    kontur::Document &doc = *editor.document();
    const auto addBezier = [&](double x) {
        return editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                         rows({{x, 0}, {x + 1, 2}, {x + 3, 2}, {x + 4, 0}}));
    };
    std::vector<CurveId> seen; // every id the document ever gave
    const auto allDistinct = [&] {
        std::vector<int> values;
        for (CurveId id : seen)
            values.push_back(static_cast<int>(id));
        std::sort(values.begin(), values.end());
        return std::adjacent_find(values.begin(), values.end()) == values.end() &&
               std::find(values.begin(), values.end(), 0) == values.end();
    };
    for (int i = 0; i < 5; ++i) {
        QVERIFY(addBezier(10.0 * i));
        seen.push_back(doc.idAt(i));
    }
    QVERIFY(allDistinct());
    for (int i = 0; i < 5; ++i) {
        QCOMPARE(doc.indexOf(seen[static_cast<std::size_t>(i)]), i);
        QCOMPARE(doc.find(seen[static_cast<std::size_t>(i)]), &doc.curve(i));
        QCOMPARE(doc.curve(i).id(), seen[static_cast<std::size_t>(i)]);
    }
    QCOMPARE(doc.idAt(5), CurveId::None);
    QCOMPARE(doc.idAt(-1), CurveId::None);
    QCOMPARE(doc.indexOf(CurveId::None), -1);
    QVERIFY(doc.find(CurveId::None) == nullptr);

    // Deleted and new curves: a new curve never gets an id that was given before, even one whose
    // curve is gone (the last one, too).
    const CurveId third = seen[2], last = seen[4];
    QVERIFY(editor.commands()->deleteCurve(static_cast<int>(third)));
    QVERIFY(editor.commands()->deleteCurve(static_cast<int>(last)));
    QVERIFY(!doc.contains(third));
    QVERIFY(!doc.contains(last));
    QCOMPARE(doc.indexOf(last), -1);
    for (int i = 0; i < 3; ++i) {
        QVERIFY(addBezier(100.0 + i));
        seen.push_back(doc.idAt(doc.curveCount() - 1));
        QVERIFY(allDistinct());
    }
    // Undoing the deletes (after undoing the new curves) brings back the same ids at their rows.
    for (int i = 0; i < 3; ++i)
        editor.undo();
    editor.undo();
    QCOMPARE(doc.indexOf(last), 3);
    editor.undo();
    QCOMPARE(doc.indexOf(third), 2);
    for (int i = 0; i < 5; ++i)
        QCOMPARE(doc.idAt(i), seen[static_cast<std::size_t>(i)]);
    // Redoing the new curves after redoing the deletes gives them their ids again.
    for (int i = 0; i < 5; ++i)
        editor.redo();
    QCOMPARE(doc.curveCount(), 6);
    for (int i = 0; i < 3; ++i)
        QCOMPARE(doc.idAt(3 + i), seen[5 + static_cast<std::size_t>(i)]);
    // A new curve after all that still gets an id never given.
    QVERIFY(addBezier(200.0));
    seen.push_back(doc.idAt(doc.curveCount() - 1));
    QVERIFY(allDistinct());

    // A copy of a curve the document holds, id and all (a paste, an import of the same curve), is
    // inserted with a new id; the original keeps its own.
    const kontur::Curve copy = doc.curve(0);
    QCOMPARE(copy.id(), seen[0]);
    editor.commands()->addCurves({copy}, QStringLiteral("Paste"));
    const CurveId pasted = doc.idAt(doc.curveCount() - 1);
    seen.push_back(pasted);
    QVERIFY(allDistinct());
    QCOMPARE(doc.idAt(0), seen[0]);
    QVERIFY(doc.find(pasted)->definingPoints() == doc.curve(0).definingPoints());
    editor.push(kontur::CurvePresenceCommand::add(&doc, 0, doc.curve(1)));
    QVERIFY(doc.idAt(0) != seen[1]);
    QCOMPARE(doc.idAt(2), seen[1]);
    seen.push_back(doc.idAt(0));
    QVERIFY(allDistinct());
    // Undo and redo of that insertion keep the id it was given.
    const CurveId copied = doc.idAt(0);
    editor.undo();
    QVERIFY(!doc.contains(copied));
    editor.redo();
    QCOMPARE(doc.idAt(0), copied);
}

QTEST_GUILESS_MAIN(TestUndo)
#include "tst_undo.moc"
