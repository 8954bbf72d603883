// Properties of the model layer over random input: 10,000 random edits of every kind, then undo
// all gives the initial document exactly and redo all the final one, with the item models checked
// by QAbstractItemModelTester throughout; and the indexed hit test agrees with a full scan.
#include "models/curvelistmodel.h"
#include "models/document.h"
#include "models/editcontroller.h"
#include "models/pointlistmodel.h"

#include <QAbstractItemModelTester>
#include <QtTest>

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
        m_editor.setParameterization(pick(3));
        m_editor.createFromCoordinates(static_cast<int>(kind), rows);
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
            m_editor.setCurveParameterization(c, pick(3));
            break;
        case 4:
            m_editor.setNodeType(c, pick(std::max(1, curve.composite().knotCount())), pick(3));
            break;
        case 5: {
            const Point p = point();
            m_editor.insertPoint(c, pick(curve.definingCount() + 1), QPointF(p.x(), p.y()));
            break;
        }
        case 6:
            m_editor.removePoint(c, pick(std::max(1, curve.definingCount())));
            break;
        case 7:
            m_editor.insertKnotOnSegment(c, pick(std::max(1, curve.segmentCount())), 0.1 + 0.8 * unit(m_rng));
            break;
        case 8:
            m_editor.closeCurve(c);
            break;
        case 9:
            m_editor.setCurveLocked(c, pick(4) == 0);
            m_editor.setCurveOrder(c, 2 + pick(4));
            break;
        case 10:
            m_editor.setCurveVisible(c, pick(3) != 0);
            m_editor.setCurveColor(c, QColor::fromRgb(static_cast<QRgb>(m_rng())));
            break;
        case 11:
            if (pick(4) == 0)
                m_editor.deleteCurve(c);
            else
                m_editor.moveCurve(c, pick(curves));
            break;
        case 12: {
            QVariantList rows;
            for (int i = 0; i < curve.definingCount(); ++i) {
                const Point p = curve.definingPoint(i) + (pick(3) == 0 ? Point(1, -1) : Point(0, 0));
                rows << QVariant(QVariantList{p.x(), p.y()});
            }
            m_editor.applyCoordinates(c, rows);
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
};

void TestUndo::randomEditsUndoAndRedoExactly()
{
    EditController editor;
    RandomEditor random(editor, 20261122);
    // Start from a document with a few curves, made without undo history.
    for (int i = 0; i < 5; ++i)
        random.addCurve();
    editor.undoStack()->clear();
    const Snapshot initial = snapshot(*editor.document());

    QAbstractItemModelTester curves(editor.curves(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester points(editor.points(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    for (int i = 0; i < 10000; ++i) {
        random.step();
        if (i % 97 == 0)
            editor.selectCurve(random.pick(std::max(1, editor.document()->curveCount())));
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
    editor.resetAll();
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
        QVERIFY(editor.createFromCoordinates(static_cast<int>(c % 2 ? CurveKind::Bezier : CurveKind::Composite), rows));
    }
    const auto bruteForce = [&](const Point &q, double radius) {
        kontur::PointRef best;
        double bestDistance = radius;
        for (int c = 0; c < editor.document()->curveCount(); ++c) {
            const kontur::Curve &curve = editor.document()->curve(c);
            for (int r = 0; r < curve.rowCount(); ++r) {
                const double d = (curve.row(r).position - q).norm();
                if (d < bestDistance) {
                    bestDistance = d;
                    best = {c, r};
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
            const double d = (editor.document()->curve(hit.curve).row(hit.point).position - q).norm();
            QCOMPARE(d, distance);
        }
        // Drags keep the index up to date in place.
        if (k % 10 == 0 && hit.isValid()) {
            const Point at = editor.document()->curve(hit.curve).row(hit.point).position;
            if (editor.beginDrag(QPointF(at.x(), at.y()), 1e-9)) {
                editor.dragTo(QPointF(coord(rng), coord(rng)));
                editor.endDrag();
            }
        }
    }
}

QTEST_GUILESS_MAIN(TestUndo)
#include "tst_undo.moc"
