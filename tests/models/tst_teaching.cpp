// The teaching views' controller (issue #9 part A): the de Casteljau construction, degree
// elevation, comparison, curvature comb and continuity marks against the geometry's own answers,
// the animation steps, and the undoable edits (split at t for every kind, reduce degree, add/remove
// control point). Over 600 lines because each view's oracles and each kind's split are written out.
#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/teaching/teachingcontroller.h"

#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <random>

using kontur::Curve;
using kontur::CurveKind;
using kontur::EditController;
using kontur::TeachingController;
using kontur::TeachingScene;
using kontur::geo::Bezier;
using kontur::geo::Point;
using View = TeachingController::View;

namespace {

void addCurve(EditController &editor, CurveKind kind, std::vector<Point> points)
{
    editor.commands()->addCurves({Curve::make(kind, std::move(points))}, QStringLiteral("test"));
}

std::vector<Point> randomPoints(std::mt19937 &rng, int count)
{
    std::uniform_real_distribution<double> coord(-200.0, 200.0);
    std::vector<Point> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(coord(rng), coord(rng));
    return points;
}

const std::vector<Point> kSeed002{{0, 0}, {1, 2}, {3, 2}, {4, 0}};

} // namespace

class TestTeaching final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void deCasteljauLevelsEqualGeometry();
    void deCasteljauOnSplinePieces();
    void markerDragFindsParameter();
    void elevationSeedOracle();
    void elevationPropertyOverRandomCurves();
    void elevationNeedsBezier();
    void animationSteps();
    void splitAtParameterIsOneUndoStep();
    void splitEveryKindTracesTheSameCurve();
    void reduceDegreeAndItsError();
    void toggleControlPoints();
    void combNormalsFollowCurvatureSign();
    void combOfCircleArc();
    void continuityMarks();
    void marksOfHugeCurvesAreFinite();
    void compareKindsAndParameterizations();
    void followsSelectionAndDocument();
};

void TestTeaching::deCasteljauLevelsEqualGeometry()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, kSeed002);
    QCOMPARE(teaching.curve(), kontur::test::idAt(editor, 0));
    teaching.setView(View::DeCasteljau);
    QSignalSpy parameterSpy(&teaching, &TeachingController::parameterChanged);
    teaching.setParameter(0.3);
    QCOMPARE(parameterSpy.count(), 1);
    teaching.setParameter(0.3);
    QCOMPARE(parameterSpy.count(), 1); // no signal without a change
    QVERIFY(teaching.isApplicable());

    // De Casteljau at t = 0.3 by hand: each level interpolates the previous one at 0.3.
    const std::vector<std::vector<Point>> expected{{{0, 0}, {1, 2}, {3, 2}, {4, 0}},
                                                   {{0.3, 0.6}, {1.6, 2}, {3.3, 1.4}},
                                                   {{0.69, 1.02}, {2.11, 1.82}},
                                                   {{1.116, 1.26}}};
    const auto &levels = teaching.levels();
    QCOMPARE(levels.size(), expected.size());
    for (std::size_t k = 0; k < levels.size(); ++k) {
        QCOMPARE(levels[k].size(), 4 - k);
        for (std::size_t i = 0; i < levels[k].size(); ++i)
            QVERIFY((levels[k][i] - expected[k][i]).norm() < 1e-12);
    }
    // Hand-computed oracle: B(0.3) of seed 002's cubic = (0.441 + 0.567 + 0.108, 0.882 + 0.378).
    QVERIFY(std::abs(teaching.curvePoint().x() - 1.116) < 1e-12);
    QVERIFY(std::abs(teaching.curvePoint().y() - 1.26) < 1e-12);
    // The QML view of the same levels.
    const QVariantList list = teaching.constructionPoints();
    QCOMPARE(list.size(), 4);
    QCOMPARE(list.at(1).toList().size(), 3);
    QCOMPARE(list.at(3).toList().at(0).toPointF(), teaching.curvePoint());
    // Levels 1 and 2 are drawn as polygons, then the point B(t), plus the curve over [0, t].
    QCOMPARE(teaching.scene().polylines.size(), std::size_t{3});
    QCOMPARE(teaching.scene().curves.size(), std::size_t{1});

    // Parameters out of range are clamped, NaN is ignored.
    teaching.setParameter(1.5);
    QCOMPARE(teaching.parameter(), 1.0);
    teaching.setParameter(std::nan(""));
    QCOMPARE(teaching.parameter(), 1.0);
}

void TestTeaching::deCasteljauOnSplinePieces()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::NaturalSpline, {{0, 0}, {100, 50}, {200, 0}, {300, 80}, {400, 10}});
    teaching.setView(View::DeCasteljau);
    teaching.setParameter(0.3); // 4 segments: u = 1.2, segment 1 at 0.2
    // A cubic piece: four levels, ending at the spline's point at u = 1.2. That point by hand: the
    // natural cubic spline through the five points at unit knot spacing (M₀ = M₄ = 0 and
    // M_i−1 + 4 M_i + M_i+1 = 6 Δ²y_i, solved in exact fractions) is (120, 203/5) at u = 1.2.
    QCOMPARE(teaching.levels().size(), std::size_t{4});
    QVERIFY((teaching.levels().back().front() - Point(120, 40.6)).norm() < 1e-9);
    QCOMPARE(teaching.curvePoint(),
             QPointF(teaching.levels().back().front().x(), teaching.levels().back().front().y()));
    // Split at that t: the spline becomes its exact composite curve, cut at u = 1.2.
    QVERIFY(teaching.splitAtParameter());
    QCOMPARE(editor.document()->curveCount(), 2);
    QCOMPARE(editor.document()->curve(0).kind(), CurveKind::Composite);
    QCOMPARE(editor.document()->curve(0).segmentCount(), 2);
    QCOMPARE(editor.document()->curve(1).segmentCount(), 3);
    QVERIFY((editor.document()->curve(0).segment(1).endPoint() - Point(120, 40.6)).norm() < 1e-9);
    // The natural spline is C2: its joints are symmetric knots of the composite curve, but next to the
    // cut (a piece cut at 0.2 runs at 0.8 of its speed in its own parameter) only smooth.
    QCOMPARE(editor.document()->curve(1).composite().nodeType(1), kontur::geo::NodeType::Smooth);
    QCOMPARE(editor.document()->curve(1).composite().nodeType(2), kontur::geo::NodeType::Symmetric);
}

void TestTeaching::markerDragFindsParameter()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, kSeed002);
    teaching.setView(View::DeCasteljau);
    const Bezier b(kSeed002);
    for (double t : {0.1, 0.37, 0.5, 0.82}) {
        const Point on = b.eval(t);
        teaching.dragMarkerTo(QPointF(on.x(), on.y() + 1e-4));
        QVERIFY2(std::abs(teaching.parameter() - t) < 1e-3, qPrintable(QString::number(teaching.parameter())));
    }
}

void TestTeaching::elevationSeedOracle()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, kSeed002);
    teaching.setView(View::Elevation);
    QCOMPARE(teaching.degree(), 3);
    QCOMPARE(teaching.maximumStep(), 97); // seed 002: up to 97 elevations, degree 100
    QCOMPARE(teaching.elevatedPolygon().size(), std::size_t{4});
    teaching.setElevationStep(1);
    const std::vector<Point> expected{{0, 0}, {0.75, 1.5}, {2, 2}, {3.25, 1.5}, {4, 0}};
    QCOMPARE(teaching.elevatedPolygon().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY((teaching.elevatedPolygon()[i] - expected[i]).norm() < 1e-12);
    QCOMPARE(teaching.elevatedPoints().size(), 5);
    teaching.setElevationStep(500);
    QCOMPARE(teaching.elevationStep(), 97);
    QCOMPARE(teaching.elevatedPolygon().size(), std::size_t{101});
}

void TestTeaching::elevationPropertyOverRandomCurves()
{
    std::mt19937 rng(20260902);
    std::uniform_int_distribution<int> degreeOf(1, 12);
    for (int round = 0; round < 40; ++round) {
        EditController editor;
        TeachingController teaching;
        teaching.setEditor(&editor);
        const int n = degreeOf(rng);
        const std::vector<Point> points = randomPoints(rng, n + 1);
        addCurve(editor, CurveKind::Bezier, points);
        teaching.setView(View::Elevation);
        std::uniform_int_distribution<int> stepOf(0, 100 - n);
        const int r = stepOf(rng);
        teaching.setElevationStep(r);
        // The step-r polygon has n + r + 1 points, the curve is unchanged, the document too.
        QCOMPARE(static_cast<int>(teaching.elevatedPolygon().size()), n + r + 1);
        const Bezier original(points);
        const Bezier elevated(teaching.elevatedPolygon());
        for (int i = 0; i <= 20; ++i) {
            const double t = i / 20.0;
            QVERIFY((original.eval(t) - elevated.eval(t)).norm() < 1e-8 * 400);
        }
        QCOMPARE(editor.document()->curve(0).placedPoints().size(), points.size());
        QCOMPARE(editor.undoStack()->count(), 1); // only the curve's creation
    }
}

void TestTeaching::elevationNeedsBezier()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Composite, {{0, 0}, {50, 50}, {100, 0}});
    teaching.setView(View::Elevation);
    QVERIFY(!teaching.isApplicable());
    QVERIFY(!teaching.isBezier());
    QVERIFY(teaching.elevatedPolygon().empty());
    QCOMPARE(teaching.maximumStep(), 0);
    QVERIFY(!teaching.reduceDegree());
    QVERIFY(!teaching.toggleControlPoint(QPointF(10, 10), 1.0));
}

void TestTeaching::animationSteps()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, kSeed002);
    teaching.setView(View::DeCasteljau);
    teaching.setParameter(0.5);
    teaching.advance(1.0); // speed 1: a fifth of [0, 1] per second
    QVERIFY(std::abs(teaching.parameter() - 0.7) < 1e-12);
    teaching.setSpeed(2.0);
    teaching.setDirection(-1);
    teaching.advance(0.5);
    QVERIFY(std::abs(teaching.parameter() - 0.5) < 1e-12);
    teaching.setParameter(0.05);
    teaching.advance(0.5); // stops at the end first…
    QCOMPARE(teaching.parameter(), 0.0);
    teaching.advance(0.5); // …then starts again at the other
    QVERIFY(std::abs(teaching.parameter() - 0.8) < 1e-12);
    teaching.setSpeed(100.0);
    QCOMPARE(teaching.speed(), 4.0);

    teaching.setView(View::Elevation);
    QVERIFY(!teaching.isPlaying());
    teaching.setSpeed(1.0);
    teaching.setDirection(1);
    teaching.advance(1.0); // four steps a second
    QCOMPARE(teaching.elevationStep(), 4);
    QCOMPARE(static_cast<int>(teaching.elevatedPolygon().size()), 3 + 4 + 1);
    teaching.advance(0.1); // less than a step: nothing yet
    QCOMPARE(teaching.elevationStep(), 4);
    teaching.advance(0.15);
    QCOMPARE(teaching.elevationStep(), 5);
    teaching.setDirection(-1);
    teaching.advance(1.25);
    QCOMPARE(teaching.elevationStep(), 0);
    teaching.advance(0.25); // below 0 it wraps to the last step
    QCOMPARE(teaching.elevationStep(), 97);
    QSignalSpy playing(&teaching, &TeachingController::playingChanged);
    teaching.setPlaying(true);
    teaching.setView(View::Comb); // another view stops the animation
    QVERIFY(!teaching.isPlaying());
    QCOMPARE(playing.count(), 2);
}

void TestTeaching::splitAtParameterIsOneUndoStep()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, kSeed002);
    const Curve before = editor.document()->curve(0);
    teaching.setView(View::DeCasteljau);
    teaching.setParameter(0.3);
    const int undoBefore = editor.undoStack()->count();
    QVERIFY(teaching.splitAtParameter());
    QCOMPARE(editor.undoStack()->count(), undoBefore + 1);
    QCOMPARE(editor.document()->curveCount(), 2);
    const Bezier left = editor.document()->curve(0).segment(0);
    const Bezier right = editor.document()->curve(1).segment(0);
    const Bezier whole(kSeed002);
    QVERIFY((left.endPoint() - whole.eval(0.3)).norm() < 1e-12);
    QVERIFY((right.startPoint() - whole.eval(0.3)).norm() < 1e-12);
    // Both halves trace the original: left(s) = B(0.3 s), right(s) = B(0.3 + 0.7 s).
    for (int i = 0; i <= 10; ++i) {
        const double s = i / 10.0;
        QVERIFY((left.eval(s) - whole.eval(0.3 * s)).norm() < 1e-12);
        QVERIFY((right.eval(s) - whole.eval(0.3 + 0.7 * s)).norm() < 1e-12);
    }
    QCOMPARE(editor.document()->curve(0).name, before.name);
    editor.undo();
    QCOMPARE(editor.document()->curveCount(), 1);
    QVERIFY(editor.document()->curve(0).sameState(before));
    editor.redo();
    QCOMPARE(editor.document()->curveCount(), 2);
    // At the ends a half would be a single point: nothing happens.
    teaching.setParameter(0.0);
    QVERIFY(!teaching.splitAtParameter());
    QCOMPARE(editor.document()->curveCount(), 2);
}

// Split at t for every kind: the parts together are the curve (each sample of one lies on the other),
// one undo step that brings the curve back as it was; a closed curve opens at t; a composite curve's
// own knots keep their types; a piece of degree above 3 (the polynomial through 5 points) is refused.
void TestTeaching::splitEveryKindTracesTheSameCurve()
{
    const std::vector<Point> points{{0, 0}, {100, 50}, {200, 0}, {300, 80}, {400, 10}, {460, -60}};
    const CurveKind kinds[] = {CurveKind::NaturalSpline,  CurveKind::ClampedSpline, CurveKind::NotAKnotSpline,
                               CurveKind::PeriodicSpline, CurveKind::CatmullRom,    CurveKind::HermiteSpline,
                               CurveKind::BSpline,        CurveKind::GlobalBSpline, CurveKind::FunctionSpline,
                               CurveKind::Contour,        CurveKind::Composite,     CurveKind::LeastSquares};
    for (CurveKind kind : kinds) {
        for (double u : {0.3, 0.5, 0.77}) {
            const QString what = QStringLiteral("kind %1, u = %2").arg(static_cast<int>(kind)).arg(u);
            EditController editor;
            TeachingController teaching;
            teaching.setEditor(&editor);
            addCurve(editor, kind, points);
            Curve original = editor.document()->curve(0);
            if (kind == CurveKind::Composite) // a corner knot keeps its type through the split
                QVERIFY(editor.commands()->setNodeType(kontur::test::idAt(editor, 0), 2,
                                                       static_cast<int>(kontur::geo::NodeType::Corner)));
            original = editor.document()->curve(0);
            const kontur::geo::PiecewiseBezier whole = original.toPiecewise();
            teaching.setView(View::DeCasteljau);
            teaching.setParameter(u);
            const int undoBefore = editor.undoStack()->count();
            const Point cut(teaching.curvePoint().x(), teaching.curvePoint().y()); // the view's point at u
            QVERIFY2(teaching.splitAtParameter(), qPrintable(what));
            QCOMPARE(editor.undoStack()->count(), undoBefore + 1);
            const int parts = editor.document()->curveCount();
            QCOMPARE(parts, original.isClosed() ? 1 : 2);
            std::vector<kontur::geo::PiecewiseBezier> pieces;
            for (int i = 0; i < parts; ++i) {
                QCOMPARE(editor.document()->curve(i).kind(), CurveKind::Composite);
                QVERIFY(!editor.document()->curve(i).isClosed());
                pieces.push_back(editor.document()->curve(i).toPiecewise());
            }
            // The cut is the point the de Casteljau view showed at u.
            QVERIFY2((pieces.front().segments().back().endPoint() - cut).norm() < 1e-9, qPrintable(what));
            for (int k = 0; k <= 200; ++k) {
                const Point p = whole.eval(whole.segmentCount() * k / 200.0);
                double best = std::numeric_limits<double>::infinity();
                for (const auto &part : pieces)
                    best = std::min(best, part.nearest(p).distance);
                QVERIFY2(best < 1e-7, qPrintable(what + QStringLiteral(": sample %1 is %2 away").arg(k).arg(best)));
                for (const auto &part : pieces) {
                    const Point q = part.eval(part.segmentCount() * k / 200.0);
                    QVERIFY2(whole.nearest(q).distance < 1e-7, qPrintable(what));
                }
            }
            if (kind == CurveKind::Composite) {
                // Knot 2 is in the left part when u = 0.3 (segments 0, 1 and part of 2 of 5).
                const Curve &left = editor.document()->curve(0);
                if (u > 0.4)
                    QCOMPARE(left.composite().nodeType(2), kontur::geo::NodeType::Corner);
            }
            editor.undo();
            QCOMPARE(editor.document()->curveCount(), 1);
            QVERIFY2(editor.document()->curve(0).sameState(original), qPrintable(what));
        }
    }
    // The polynomial through 6 points is one piece of degree 5 per interval: no composite curve is it.
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Polynomial, points);
    teaching.setView(View::DeCasteljau);
    teaching.setParameter(0.5);
    QVERIFY(!teaching.splitAtParameter());
    QCOMPARE(editor.document()->curveCount(), 1);
    QCOMPARE(editor.message().id, kontur::Message::NotPossibleForKind);
}

void TestTeaching::reduceDegreeAndItsError()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    // A cubic elevated once: the reduction gives the cubic back exactly.
    addCurve(editor, CurveKind::Bezier, Bezier(kSeed002).elevated(1).controlPoints());
    teaching.setView(View::Elevation);
    QCOMPARE(teaching.degree(), 4);
    QVERIFY(teaching.reductionError() >= 0.0);
    QVERIFY(teaching.reductionError() < 1e-9);
    QVERIFY(teaching.reduceDegree());
    QCOMPARE(teaching.degree(), 3);
    const auto &points = editor.document()->curve(0).placedPoints();
    for (std::size_t i = 0; i < kSeed002.size(); ++i)
        QVERIFY((points[i] - kSeed002[i]).norm() < 1e-9);
    // A true cubic loses shape: the error is the largest distance at equal parameters.
    QVERIFY(teaching.reductionError() > 0.01);
    const Bezier cubic(kSeed002);
    const Bezier quadratic = cubic.reduced();
    double largest = 0.0;
    for (int i = 0; i <= 1000; ++i)
        largest = std::max(largest, (cubic.eval(i / 1000.0) - quadratic.eval(i / 1000.0)).norm());
    QVERIFY(std::abs(teaching.reductionError() - largest) < 1e-3 * largest);
    editor.undo();
    QCOMPARE(teaching.degree(), 4);
}

void TestTeaching::toggleControlPoints()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::Bezier, {{0, 0}, {100, 0}, {200, 0}});
    teaching.setView(View::Elevation);
    // Beyond the last point: appended at the end.
    QVERIFY(teaching.toggleControlPoint(QPointF(300, 10), 5.0));
    QCOMPARE(editor.document()->curve(0).placedPoints().size(), std::size_t{4});
    QCOMPARE(editor.document()->curve(0).placedPoints().back(), Point(300, 10));
    // Just off the middle of the first edge: inserted between P0 and P1.
    QVERIFY(teaching.toggleControlPoint(QPointF(50, 20), 5.0));
    QCOMPARE(editor.document()->curve(0).placedPoints()[1], Point(50, 20));
    QCOMPARE(teaching.degree(), 4);
    // On a point (within the radius): removed.
    QVERIFY(teaching.toggleControlPoint(QPointF(101, 1), 5.0));
    QCOMPARE(editor.document()->curve(0).placedPoints().size(), std::size_t{4});
    QCOMPARE(teaching.degree(), 3);
    editor.undo();
    QCOMPARE(teaching.degree(), 4);
    // Down to the minimum of two points, then refused with a message.
    QVERIFY(teaching.toggleControlPoint(QPointF(0, 0), 5.0));
    QVERIFY(teaching.toggleControlPoint(QPointF(50, 20), 5.0));
    QVERIFY(teaching.toggleControlPoint(QPointF(100, 0), 5.0));
    QCOMPARE(teaching.degree(), 1);
    QVERIFY(!teaching.toggleControlPoint(QPointF(200, 0), 5.0));
    QCOMPARE(editor.message().id, kontur::Message::TooFewPoints);
}

void TestTeaching::combNormalsFollowCurvatureSign()
{
    std::mt19937 rng(77);
    for (int round = 0; round < 30; ++round) {
        EditController editor;
        TeachingController teaching;
        teaching.setEditor(&editor);
        const std::vector<Point> points = randomPoints(rng, 4 + round % 4);
        addCurve(editor, round % 2 ? CurveKind::NaturalSpline : CurveKind::Bezier, points);
        teaching.setView(View::Comb);
        teaching.setCombScale(0.5);
        const Curve &c = editor.document()->curve(0);
        const double diagonal = c.bounds().diagonal().norm();
        const QVariantList teeth = teaching.combTeeth();
        QVERIFY(teeth.size() > 10);
        double ratio = -1.0; // tooth length / |κ|: one value for every tooth not cut at the diagonal
        for (const QVariant &v : teeth) {
            const QVariantMap tooth = v.toMap();
            const QPointF base = tooth.value(QStringLiteral("base")).toPointF();
            const QPointF tip = tooth.value(QStringLiteral("tip")).toPointF();
            const double kappa = tooth.value(QStringLiteral("curvature")).toDouble();
            // The tooth is on the side away from the centre of curvature: for κ > 0 (turning left)
            // it points to the right of the direction of travel, its length proportional to |κ|.
            const Point d = Point(tip.x() - base.x(), tip.y() - base.y());
            QVERIFY(d.norm() <= diagonal * (1 + 1e-12));
            if (d.norm() < diagonal * 0.999 && std::abs(kappa) > 1e-9) {
                if (ratio < 0)
                    ratio = d.norm() / std::abs(kappa);
                QVERIFY(std::abs(d.norm() / std::abs(kappa) - ratio) < 1e-9 * ratio);
            }
            if (std::abs(kappa) * diagonal > 1e-6) {
                // The sign check uses the curve's own tangent at the base, found by the nearest point.
                const auto near = c.toPiecewise().nearest(Point(base.x(), base.y()));
                const Point tangent = c.segment(near.segment).derivative(near.t);
                const double cross = tangent.x() * d.y() - tangent.y() * d.x(); // > 0: d is to the left
                QVERIFY2((cross < 0) == (kappa > 0), qPrintable(QStringLiteral("κ %1 cross %2").arg(kappa).arg(cross)));
            }
        }
    }
}

// Curves near the largest double: whatever their pieces come to, the views' scenes hold no mark,
// label or tooth at a point that is not finite (the painter drew a label box at NaN in every frame).
void TestTeaching::marksOfHugeCurvesAreFinite()
{
    const double big = 1.7e308;
    for (const CurveKind kind : {CurveKind::NaturalSpline, CurveKind::Composite, CurveKind::BSpline,
                                 CurveKind::LeastSquares, CurveKind::Contour, CurveKind::Bezier}) {
        EditController editor;
        TeachingController teaching;
        teaching.setEditor(&editor);
        addCurve(editor, kind, {{-big, 0}, {-big / 2, big}, {0, -big}, {big / 2, big}, {big, 0}});
        if (editor.document()->curveCount() == 0)
            continue;
        for (const View view : {View::Comb, View::DeCasteljau, View::Elevation, View::Compare}) {
            teaching.setView(view);
            const auto &scene = teaching.scene();
            for (const auto &label : scene.labels)
                QVERIFY2(std::isfinite(label.at.x()) && std::isfinite(label.at.y()),
                         qPrintable(QStringLiteral("kind %1 view %2").arg(int(kind)).arg(int(view))));
            for (const auto &line : scene.polylines)
                for (const auto &p : line.points)
                    QVERIFY2(std::isfinite(p.x()) && std::isfinite(p.y()),
                             qPrintable(QStringLiteral("kind %1 view %2 polyline").arg(int(kind)).arg(int(view))));
        }
    }
}

void TestTeaching::combOfCircleArc()
{
    // The standard cubic for a quarter circle of radius 100 (k = 0.5523), counter-clockwise: κ ≈ 1/100
    // everywhere, the teeth point outwards (away from the centre at the origin).
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0) * 100.0;
    addCurve(editor, CurveKind::Bezier, {{100, 0}, {100, k}, {k, 100}, {0, 100}});
    teaching.setView(View::Comb);
    for (const QVariant &v : teaching.combTeeth()) {
        const QVariantMap tooth = v.toMap();
        const QPointF base = tooth.value(QStringLiteral("base")).toPointF();
        const QPointF tip = tooth.value(QStringLiteral("tip")).toPointF();
        QVERIFY(std::abs(tooth.value(QStringLiteral("curvature")).toDouble() - 0.01) < 0.0003);
        const double rBase = std::hypot(base.x(), base.y());
        const double rTip = std::hypot(tip.x(), tip.y());
        QVERIFY(rTip > rBase + 1.0);
    }
    // A larger scale gives proportionally longer teeth.
    const QVariantMap first = teaching.combTeeth().at(0).toMap();
    const double before =
        QLineF(first.value(QStringLiteral("base")).toPointF(), first.value(QStringLiteral("tip")).toPointF()).length();
    teaching.setCombScale(2.0);
    const QVariantMap again = teaching.combTeeth().at(0).toMap();
    const double after =
        QLineF(again.value(QStringLiteral("base")).toPointF(), again.value(QStringLiteral("tip")).toPointF()).length();
    QVERIFY(std::abs(after - 2.0 * before) < 1e-9);
}

void TestTeaching::continuityMarks()
{
    // Seed 000's composite curve is G1 at its joints, the natural spline C2 (issue #9).
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    const std::vector<Point> knots{{0, 0}, {100, 80}, {220, 40}, {300, 120}, {420, 20}};
    addCurve(editor, CurveKind::Composite, knots);
    addCurve(editor, CurveKind::NaturalSpline, knots);
    teaching.setView(View::Comb);
    teaching.setCombAllCurves(true);
    QStringList composite, natural;
    const auto &labels = teaching.scene().labels;
    QCOMPARE(labels.size(), std::size_t{6});
    for (std::size_t i = 0; i < labels.size(); ++i)
        (i < 3 ? composite : natural) << labels[i].text;
    QCOMPARE(composite, QStringList({"G1", "G1", "G1"}));
    QCOMPARE(natural, QStringList({"C2", "C2", "C2"}));
    // The marks sit on the joints: the knots in between.
    QVERIFY((labels[0].at - knots[1]).norm() < 1e-9);
    QVERIFY((labels[5].at - knots[3]).norm() < 1e-9);
    // Only the chosen curve when "all curves" is off.
    teaching.setCombAllCurves(false);
    QCOMPARE(teaching.curve(), kontur::test::idAt(editor, 1));
    QCOMPARE(teaching.scene().labels.size(), std::size_t{3});
}

void TestTeaching::compareKindsAndParameterizations()
{
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    addCurve(editor, CurveKind::NaturalSpline, {{0, 0}, {10, 60}, {120, 70}, {140, 0}, {260, 30}});
    QSignalSpy legendSpy(&teaching, &TeachingController::legendChanged);
    teaching.setView(View::Compare);
    QCOMPARE(legendSpy.count(), 1);
    QVERIFY(teaching.isApplicable());
    QVariantList legend = teaching.legend();
    // Moving a point changes the curves, not the legend.
    QVERIFY(editor.beginDrag(QPointF(10, 60), 1.0));
    editor.dragTo(QPointF(12, 64));
    editor.endDrag();
    QCOMPARE(legendSpy.count(), 1);
    editor.undo();
    QCOMPARE(legend.size(), 8); // with seed 004's contour curve
    for (const QVariant &entry : legend)
        QVERIFY(entry.toMap().value(QStringLiteral("available")).toBool());
    QCOMPARE(teaching.scene().curves.size(), std::size_t{8});
    // Every compared curve of an interpolating kind passes through the same points.
    const auto &natural = teaching.scene().curves[3];
    QCOMPARE(natural.pieces.size(), std::size_t{4});
    QVERIFY((natural.pieces[1].startPoint() - Point(10, 60)).norm() < 1e-9);
    // The Bézier entry uses the points as control points: it starts and ends with them.
    QVERIFY((teaching.scene().curves[0].pieces.front().endPoint() - Point(260, 30)).norm() < 1e-9);
    // A legend entry hides its curve; the others keep their palette colours.
    teaching.setCompareShown(0, false);
    QCOMPARE(teaching.scene().curves.size(), std::size_t{7});
    QCOMPARE(teaching.scene().curves[0].index, 1);
    QVERIFY(!teaching.legend().at(0).toMap().value(QStringLiteral("shown")).toBool());
    teaching.setCompareShown(0, true);
    QCOMPARE(teaching.scene().curves.size(), std::size_t{8});

    teaching.setCompareMode(TeachingController::CompareMode::Parameterizations);
    legend = teaching.legend();
    QCOMPARE(legend.size(), 3);
    QCOMPARE(teaching.scene().curves.size(), std::size_t{3});
    // Uniform and chord-length natural splines through the same knots differ between them.
    const Point uniform = teaching.scene().curves[0].pieces[1].eval(0.5);
    const Point chord = teaching.scene().curves[1].pieces[1].eval(0.5);
    QVERIFY((uniform - chord).norm() > 0.5);

    // Too few points for some kinds: they stay in the legend, marked not available.
    EditController small;
    TeachingController other;
    other.setEditor(&small);
    addCurve(small, CurveKind::Composite, {{0, 0}, {50, 40}, {100, 0}});
    other.setView(View::Compare);
    int available = 0;
    for (const QVariant &entry : other.legend())
        available += entry.toMap().value(QStringLiteral("available")).toBool() ? 1 : 0;
    QCOMPARE(available, 7);             // not the least-squares cubic (4 points at least)
    QCOMPARE(other.legend().size(), 8); // the cubic through 4 points only comes for exactly 4

    // Exactly 4 points: the cubic through them joins, and passes through them.
    EditController four;
    TeachingController fourTeaching;
    fourTeaching.setEditor(&four);
    addCurve(four, CurveKind::Bezier, kSeed002);
    fourTeaching.setView(View::Compare);
    QCOMPARE(fourTeaching.legend().size(), 9);
    const auto &through = fourTeaching.scene().curves[1];
    QCOMPARE(through.index, 1);
    QVERIFY((through.pieces.front().startPoint() - kSeed002[0]).norm() < 1e-9);
    QVERIFY((through.pieces.back().endPoint() - kSeed002[3]).norm() < 1e-9);
}

void TestTeaching::followsSelectionAndDocument()
{
    using kontur::test::idAt;
    EditController editor;
    TeachingController teaching;
    teaching.setEditor(&editor);
    QCOMPARE(teaching.curve(), 0); // no curve
    addCurve(editor, CurveKind::Bezier, kSeed002);
    addCurve(editor, CurveKind::Bezier, {{0, 0}, {5, 5}, {10, 0}});
    const int first = idAt(editor, 0), second = idAt(editor, 1);
    QCOMPARE(teaching.curve(), second);
    editor.selection()->selectRow(0);
    QCOMPARE(teaching.curve(), first);
    // Nothing selected: the view stays on its curve.
    editor.selection()->selectRow(-1);
    QCOMPARE(teaching.curve(), first);
    teaching.setView(View::Elevation);
    QCOMPARE(teaching.degree(), 3);
    // The curve before it goes away: the view keeps its curve, now at row 0.
    editor.selection()->selectRow(1);
    QCOMPARE(teaching.curve(), second);
    editor.commands()->deleteCurve(first);
    QCOMPARE(teaching.curve(), second);
    QCOMPARE(editor.document()->indexOf(kontur::CurveId(teaching.curve())), 0);
    QCOMPARE(teaching.degree(), 2);
    editor.undo();
    QCOMPARE(teaching.curve(), second);
    QCOMPARE(editor.document()->indexOf(kontur::CurveId(teaching.curve())), 1);
    QCOMPARE(teaching.degree(), 2);
    // Opened with nothing chosen, a view starts on the first curve it suits.
    {
        EditController fresh;
        addCurve(fresh, CurveKind::NaturalSpline, {{0, 0}, {5, 5}, {10, 0}});
        addCurve(fresh, CurveKind::Bezier, kSeed002);
        fresh.selection()->selectRow(-1);
        TeachingController other;
        other.setEditor(&fresh);
        QCOMPARE(other.curve(), 0);
        other.setView(View::Elevation);
        QCOMPARE(other.curve(), idAt(fresh, 1));
        QVERIFY(other.isApplicable());
    }
    // Its own curve deleted: nothing to show.
    editor.commands()->deleteCurve(second);
    QCOMPARE(editor.selection()->curveRow(), -1);
    QVERIFY(!editor.document()->contains(kontur::CurveId(teaching.curve())));
    QVERIFY(!teaching.isApplicable());
    QCOMPARE(teaching.degree(), -1);
}

QTEST_GUILESS_MAIN(TestTeaching)
#include "tst_teaching.moc"
