// The teaching views' state and geometry (issue #9 part A); see teachingcontroller.h.
// Over 600 lines because the four teaching views share the shown curve, t and the animation, and each
// builds its scene from them; the mathematics lives in src/geometry.
#include "models/teaching/teachingcontroller.h"

#include "geometry/splines/contour.h"
#include "models/text/languagewatch.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kontur {

namespace {

QPointF toQ(const geo::Point &p)
{
    return {p.x(), p.y()};
}
geo::Point toPoint(QPointF p)
{
    return {p.x(), p.y()};
}

QVariantList pointList(const std::vector<geo::Point> &points)
{
    QVariantList list;
    list.reserve(static_cast<qsizetype>(points.size()));
    for (const geo::Point &p : points)
        list.append(toQ(p));
    return list;
}

// The points a comparison is built from: the curve's own knots or control points, without the
// derived ones (a fitted cubic's control points) and without handles or tangent ends.
std::vector<geo::Point> comparePoints(const Curve &c)
{
    std::vector<geo::Point> points;
    for (int i = 0; i < c.rowCount(); ++i) {
        const PointRow row = c.row(i);
        if (row.editable && (row.role == PointRole::Knot || row.role == PointRole::ControlPoint))
            points.push_back(row.position);
    }
    return points;
}

// The kinds compared over one set of points (seed 000's figures 3.4 and 3.5 overlay the Bézier
// curve, the fitted cubics and the composite curve; the splines join them for seed 001's aim).
// The cubic through 4 knots joins them when there are exactly 4 points.
constexpr CurveKind kCompareKinds[] = {CurveKind::Bezier,    CurveKind::Interpolating, CurveKind::LeastSquares,
                                       CurveKind::Composite, CurveKind::NaturalSpline, CurveKind::CatmullRom,
                                       CurveKind::BSpline,   CurveKind::Polynomial,    CurveKind::Contour};

QString parameterizationName(geo::Parameterization p)
{
    switch (p) {
    case geo::Parameterization::Uniform:
        //: Parameterization name in lower case, shown after a kind name (“Natural spline, uniform”).
        return QCoreApplication::translate("kontur", "uniform");
    case geo::Parameterization::ChordLength:
        //: Parameterization name in lower case, shown after a kind name (“Natural spline, chord length”).
        return QCoreApplication::translate("kontur", "chord length");
    case geo::Parameterization::Centripetal:
        //: Parameterization name in lower case, shown after a kind name (“Natural spline, centripetal”).
        return QCoreApplication::translate("kontur", "centripetal");
    }
    return {};
}

// Samples per segment for the comb and the reduction error: enough for a smooth outline, but at
// most about `budget` in all on long splines.
int samplesPerSegment(int segments, int degree, int budget)
{
    const int wanted = std::clamp(8 * std::max(degree, 1), 16, 96);
    return std::clamp(budget / std::max(segments, 1), 2, wanted);
}

} // namespace

TeachingController::TeachingController(QObject *parent)
    : QObject(parent)
{
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this, &TeachingController::onTimer);
    // The legend's names are translated.
    new LanguageWatch(this, [this] { Q_EMIT legendChanged(); });
}

TeachingController::~TeachingController() = default;

void TeachingController::setEditor(EditController *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor) {
        disconnect(m_editor, nullptr, this, nullptr);
        disconnect(m_editor->document(), nullptr, this, nullptr);
    }
    m_editor = editor;
    if (m_editor) {
        Document *doc = m_editor->document();
        connect(m_editor->selection(), &Selection::curveChanged, this, &TeachingController::followSelection);
        // The view holds its curve by id: curves coming, going or moving (undo) need nothing here
        // but a new look at the document.
        for (auto signal : {&Document::curveRemoved, &Document::curveInserted})
            connect(doc, signal, this, &TeachingController::recompute);
        connect(doc, &Document::curveMoved, this, &TeachingController::recompute);
        connect(doc, &Document::changed, this, &TeachingController::recompute);
    }
    Q_EMIT editorChanged();
    followSelection();
    recompute();
}

void TeachingController::setView(View view)
{
    if (m_view == view)
        return;
    m_view = view;
    setPlaying(false);
    // Nothing chosen yet: the view starts on the first curve it suits (a Bézier curve for the
    // construction and the elevation), so that it shows something at once.
    if (m_editor && !shownCurve() && m_view != View::None) {
        const Document *doc = m_editor->document();
        const bool wantsBezier = m_view == View::DeCasteljau || m_view == View::Elevation;
        int pick = -1;
        for (int i = 0; i < doc->curveCount() && pick < 0; ++i)
            if (!wantsBezier || doc->curve(i).kind() == CurveKind::Bezier)
                pick = i;
        if (pick < 0 && doc->curveCount() > 0)
            pick = 0;
        if (pick >= 0 && m_curve != doc->idAt(pick)) {
            m_curve = doc->idAt(pick);
            Q_EMIT curveChanged();
        }
    }
    Q_EMIT viewChanged();
    recompute();
}

const Curve *TeachingController::shownCurve() const
{
    return m_editor ? m_editor->document()->find(m_curve) : nullptr;
}

void TeachingController::setCurve(CurveId curve)
{
    if (m_curve == curve)
        return;
    m_curve = curve;
    Q_EMIT curveChanged();
    recompute();
}

void TeachingController::followSelection()
{
    if (m_editor && m_editor->selection()->hasCurve())
        setCurve(m_editor->selection()->curveId());
}

bool TeachingController::isBezier() const
{
    const Curve *c = shownCurve();
    return c && c->kind() == CurveKind::Bezier;
}

void TeachingController::setParameter(double t)
{
    if (!std::isfinite(t))
        return;
    t = std::clamp(t, 0.0, 1.0);
    if (m_parameter == t)
        return;
    m_parameter = t;
    Q_EMIT parameterChanged();
    if (m_view == View::DeCasteljau)
        recompute();
}

void TeachingController::setPlaying(bool playing)
{
    if (m_playing == playing)
        return;
    m_playing = playing;
    if (m_playing) {
        m_clock.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
    Q_EMIT playingChanged();
}

void TeachingController::setSpeed(double speed)
{
    if (!std::isfinite(speed))
        return;
    speed = std::clamp(speed, 0.25, 4.0);
    if (m_speed == speed)
        return;
    m_speed = speed;
    Q_EMIT speedChanged();
}

void TeachingController::setDirection(int direction)
{
    direction = direction < 0 ? -1 : 1;
    if (m_direction == direction)
        return;
    m_direction = direction;
    Q_EMIT directionChanged();
}

int TeachingController::degree() const
{
    return isBezier() ? shownCurve()->segment(0).degree() : -1;
}

int TeachingController::maximumStep() const
{
    const int n = degree();
    return n < 1 ? 0 : std::max(0, kMaximumDegree - n);
}

void TeachingController::setElevationStep(int step)
{
    step = std::clamp(step, 0, maximumStep());
    if (m_step == step)
        return;
    m_step = step;
    Q_EMIT elevationStepChanged();
    if (m_view == View::Elevation)
        recompute();
}

void TeachingController::setCombScale(double scale)
{
    if (!std::isfinite(scale))
        return;
    scale = std::clamp(scale, 0.05, 20.0);
    if (m_combScale == scale)
        return;
    m_combScale = scale;
    Q_EMIT combScaleChanged();
    if (m_view == View::Comb)
        recompute();
}

void TeachingController::setCombAllCurves(bool all)
{
    if (m_combAll == all)
        return;
    m_combAll = all;
    Q_EMIT combAllCurvesChanged();
    if (m_view == View::Comb)
        recompute();
}

void TeachingController::setCompareMode(CompareMode mode)
{
    if (m_compareMode == mode)
        return;
    m_compareMode = mode;
    m_compareHidden.clear();
    Q_EMIT compareModeChanged();
    recompute();
}

void TeachingController::setCompareShown(int entry, bool shown)
{
    if (entry < 0 || entry >= static_cast<int>(m_compare.size()))
        return;
    const int id = m_compare[static_cast<std::size_t>(entry)].id;
    const auto it = std::find(m_compareHidden.begin(), m_compareHidden.end(), id);
    if (shown && it != m_compareHidden.end())
        m_compareHidden.erase(it);
    else if (!shown && it == m_compareHidden.end())
        m_compareHidden.push_back(id);
    else
        return;
    recompute();
}

QVariantList TeachingController::legend() const
{
    QVariantList list;
    for (const CompareEntry &e : m_compare) {
        const bool hidden = std::find(m_compareHidden.begin(), m_compareHidden.end(), e.id) != m_compareHidden.end();
        list.append(QVariantMap{{QStringLiteral("name"), e.name},
                                {QStringLiteral("palette"), e.palette},
                                {QStringLiteral("shown"), !hidden},
                                {QStringLiteral("available"), e.available}});
    }
    return list;
}

QPointF TeachingController::curvePoint() const
{
    if (m_levels.empty() || m_levels.back().empty())
        return {};
    return toQ(m_levels.back().front());
}

QVariantList TeachingController::constructionPoints() const
{
    QVariantList list;
    for (const auto &level : m_levels)
        list.append(QVariant(pointList(level)));
    return list;
}

QVariantList TeachingController::elevatedPoints() const
{
    return pointList(m_elevated);
}

QVariantList TeachingController::combTeeth() const
{
    QVariantList list;
    for (const Tooth &t : m_teeth)
        list.append(QVariantMap{{QStringLiteral("base"), toQ(t.base)},
                                {QStringLiteral("tip"), toQ(t.tip)},
                                {QStringLiteral("curvature"), t.curvature}});
    return list;
}

// --- animation and gestures -------------------------------------------------------------------

void TeachingController::onTimer()
{
    const double seconds = static_cast<double>(m_clock.restart()) / 1000.0;
    advance(std::min(seconds, 0.1)); // a stalled frame does not jump far
}

void TeachingController::advance(double seconds)
{
    if (!(seconds > 0.0))
        return;
    if (m_view == View::DeCasteljau) {
        // t runs through [0, 1] in 5 s at speed 1 and starts again at the other end.
        double t = m_parameter + m_direction * m_speed * seconds / 5.0;
        if (t > 1.0)
            t = m_parameter >= 1.0 ? t - 1.0 : 1.0;
        else if (t < 0.0)
            t = m_parameter <= 0.0 ? t + 1.0 : 0.0;
        setParameter(t);
    } else if (m_view == View::Elevation) {
        // Four steps a second at speed 1; past the last step it starts again at the other end.
        m_stepFraction += m_speed * seconds * 4.0;
        const int steps = static_cast<int>(m_stepFraction);
        if (steps == 0)
            return;
        m_stepFraction -= steps;
        const int top = maximumStep();
        int step = m_step + m_direction * steps;
        if (top == 0)
            step = 0;
        else if (step > top)
            step = 0;
        else if (step < 0)
            step = top;
        setElevationStep(step);
    }
}

void TeachingController::dragMarkerTo(QPointF world)
{
    const Curve *c = shownCurve();
    if (!c)
        return;
    const geo::PiecewiseBezier piecewise = c->toPiecewise();
    if (piecewise.isEmpty())
        return;
    const geo::PiecewiseNearest near = piecewise.nearest(toPoint(world));
    setParameter((near.segment + near.t) / piecewise.segmentCount());
}

bool TeachingController::splitAtParameter()
{
    if (!shownCurve())
        return false;
    if (m_parameter <= 0.0 || m_parameter >= 1.0)
        return false; // one of the halves would be a single point
    // Every kind: splines become their exact composite curves first (CurveCommands::splitCurve).
    return m_editor->commands()->splitCurve(m_curve, m_parameter);
}

bool TeachingController::reduceDegree()
{
    if (!shownCurve())
        return false;
    if (!isBezier() || degree() < 2) {
        m_editor->showMessage(Message::NotPossibleForKind, {static_cast<int>(CurveKind::Bezier)});
        return false;
    }
    const geo::Bezier reduced = shownCurve()->segment(0).reduced();
    return m_editor->commands()->setControlPoints(m_curve, reduced.controlPoints(),
                                                  QCoreApplication::translate("kontur", "Reduce degree"));
}

bool TeachingController::toggleControlPoint(QPointF world, double radius)
{
    if (!m_editor || !isBezier())
        return false;
    const geo::Point q = toPoint(world);
    if (!q.allFinite())
        return false;
    const std::vector<geo::Point> &points = shownCurve()->placedPoints();
    const int n = static_cast<int>(points.size());
    // A control point under the pointer goes (the nearest one)…
    int nearest = -1;
    double best = radius;
    for (int i = 0; i < n; ++i) {
        const double d = (points[static_cast<std::size_t>(i)] - q).norm();
        if (d <= best) {
            best = d;
            nearest = i;
        }
    }
    if (nearest >= 0)
        return m_editor->commands()->removePoint(curve(), nearest);
    // …otherwise a new one comes where it lengthens the polygon least: between two neighbours, or
    // before the first or after the last point.
    int index = 0;
    double cost = (q - points.front()).norm();
    if (const double end = (q - points.back()).norm(); end < cost) {
        cost = end;
        index = n;
    }
    for (int i = 1; i < n; ++i) {
        const geo::Point &a = points[static_cast<std::size_t>(i - 1)];
        const geo::Point &b = points[static_cast<std::size_t>(i)];
        const double c = (q - a).norm() + (q - b).norm() - (b - a).norm();
        if (c < cost) {
            cost = c;
            index = i;
        }
    }
    return m_editor->commands()->insertPoint(curve(), index, world);
}

// --- geometry ---------------------------------------------------------------------------------

void TeachingController::recompute()
{
    m_scene = {};
    m_levels.clear();
    m_elevated.clear();
    m_teeth.clear();
    m_reductionError = -1.0;
    const QVariantList legendBefore = legend();
    m_compare.clear();
    m_applicable = false;

    const Document *doc = m_editor ? m_editor->document() : nullptr;
    const Curve *shown = doc ? doc->find(m_curve) : nullptr;
    if (shown && shown->segmentCount() > 0 && !shown->problem()) {
        const Curve &c = *shown;
        if (m_view == View::Elevation && isBezier() && degree() >= 2) {
            // Largest distance at equal parameters between the curve and its reduction (an upper
            // bound of the distance between the two curves).
            const geo::Bezier b = c.segment(0);
            const geo::Bezier r = b.reduced();
            double error = 0.0;
            for (int i = 0; i <= 256; ++i) {
                const double t = i / 256.0;
                error = std::max(error, (b.eval(t) - r.eval(t)).norm());
            }
            m_reductionError = error;
        }
        switch (m_view) {
        case View::None:
            break;
        case View::DeCasteljau:
            buildDeCasteljau(c);
            break;
        case View::Elevation:
            buildElevation(c);
            break;
        case View::Compare:
            buildCompare(c);
            break;
        case View::Comb:
            buildComb();
            break;
        }
    } else if (m_view == View::Comb && doc && m_combAll) {
        buildComb();
    }
    if (m_step > maximumStep()) {
        m_step = maximumStep();
        Q_EMIT elevationStepChanged();
    }
    Q_EMIT sceneChanged();
    if (legend() != legendBefore)
        Q_EMIT legendChanged();
}

void TeachingController::buildDeCasteljau(const Curve &c)
{
    // The parameter runs over the whole curve: segment floor(t·m) at its own local parameter, so the
    // construction also shows how each piece of a spline is a Bézier curve.
    const int m = c.segmentCount();
    const double u = m_parameter * m;
    const int s = std::clamp(static_cast<int>(std::floor(u)), 0, m - 1);
    const double local = std::clamp(u - s, 0.0, 1.0);
    const geo::Bezier segment = c.segment(s);
    m_levels = segment.deCasteljau(local);
    m_applicable = true;
    for (std::size_t k = 1; k < m_levels.size(); ++k) {
        if (m_levels[k].size() >= 2)
            m_scene.polylines.push_back({TeachingScene::Role::Level, static_cast<int>(k), m_levels[k], true});
    }
    if (local > 0.0) {
        TeachingScene::Curves left{TeachingScene::Role::LeftHalf, 0, {}};
        for (int i = 0; i < s; ++i)
            left.pieces.push_back(c.segment(i));
        left.pieces.push_back(segment.split(local).first);
        m_scene.curves.push_back(std::move(left));
    }
    m_scene.polylines.push_back({TeachingScene::Role::CurvePoint, 0, {m_levels.back().front()}, true});
    if (c.kind() == CurveKind::Contour) {
        // Seed 004's joints: the midpoint of P2 and P3, of P4 and P5, …, each named after its pair.
        const std::vector<geo::Point> joints = geo::contourJoints(c.placedPoints());
        m_scene.polylines.push_back({TeachingScene::Role::Midpoint, 0, joints, true});
        for (std::size_t j = 0; j < joints.size(); ++j)
            m_scene.labels.push_back({TeachingScene::Role::Midpoint, static_cast<int>(geo::Continuity::C1), joints[j],
                                      QStringLiteral("M%1%2").arg(2 * j + 2).arg(2 * j + 3)});
    }
}

void TeachingController::buildElevation(const Curve &c)
{
    if (c.kind() != CurveKind::Bezier)
        return;
    m_applicable = true;
    const geo::Bezier b = c.segment(0);
    const int step = std::clamp(m_step, 0, std::max(0, kMaximumDegree - b.degree()));
    m_elevated = b.elevated(step).controlPoints();
    m_scene.polylines.push_back({TeachingScene::Role::ElevatedPolygon, step, m_elevated, true});
}

void TeachingController::buildCompare(const Curve &c)
{
    const std::vector<geo::Point> points = comparePoints(c);
    const int n = static_cast<int>(points.size());
    struct Plan
    {
        int id;
        CurveKind kind;
        geo::Parameterization parameterization;
        QString name;
    };
    std::vector<Plan> plans;
    if (m_compareMode == CompareMode::Kinds) {
        // The curve's own parameterization where it has one (so that its own kind matches it),
        // else chord length.
        const geo::Parameterization p =
            traitsOf(c.kind()).usesParameterization ? c.parameterization() : geo::Parameterization::ChordLength;
        for (CurveKind kind : kCompareKinds)
            plans.push_back({static_cast<int>(kind), kind, p, kindName(kind)});
    } else {
        // The curve's own kind when it has a parameterization, else the natural spline.
        const CurveKind kind = traitsOf(c.kind()).usesParameterization ? c.kind() : CurveKind::NaturalSpline;
        for (geo::Parameterization p :
             {geo::Parameterization::Uniform, geo::Parameterization::ChordLength, geo::Parameterization::Centripetal})
            plans.push_back(
                {static_cast<int>(p), kind, p,
                 //: Legend in the Compare view: %1 is a curve kind, %2 a parameterization (“Natural spline, uniform”).
                 QCoreApplication::translate("kontur", "%1, %2").arg(kindName(kind), parameterizationName(p))});
    }
    int palette = 0;
    for (const Plan &plan : plans) {
        if (plan.kind == CurveKind::Interpolating && n != traitsOf(plan.kind).minPoints)
            continue; // only for exactly 4 points: otherwise it would only clutter the legend
        CompareEntry entry{plan.id, plan.name, palette++, false};
        const KindTraits traits = traitsOf(plan.kind);
        const bool hidden = std::find(m_compareHidden.begin(), m_compareHidden.end(), plan.id) != m_compareHidden.end();
        if (n >= traits.minPoints && n <= traits.maxPoints) {
            const Curve made = Curve::make(plan.kind, points, plan.parameterization);
            if (!made.problem() && made.segmentCount() > 0) {
                entry.available = true;
                if (!hidden) {
                    TeachingScene::Curves curves{TeachingScene::Role::CompareCurve, entry.palette, {}};
                    const int count = made.segmentCount();
                    curves.pieces.reserve(static_cast<std::size_t>(count));
                    for (int i = 0; i < count; ++i)
                        curves.pieces.push_back(made.segment(i));
                    m_scene.curves.push_back(std::move(curves));
                }
            }
        }
        m_compare.push_back(entry);
    }
    m_applicable = n >= 2;
}

QRectF TeachingController::sceneBounds() const
{
    double minX = std::numeric_limits<double>::infinity(), minY = minX;
    double maxX = -minX, maxY = -minX;
    auto include = [&](const geo::Point &p) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    };
    for (const TeachingScene::Polyline &line : m_scene.polylines)
        std::for_each(line.points.begin(), line.points.end(), include);
    for (const TeachingScene::Curves &curves : m_scene.curves)
        for (const geo::Bezier &piece : curves.pieces)
            std::for_each(piece.controlPoints().begin(), piece.controlPoints().end(), include);
    if (!(minX <= maxX) || !std::isfinite(minX + maxX + minY + maxY))
        return {};
    return QRectF(QPointF(minX, minY), QPointF(maxX, maxY));
}

void TeachingController::buildComb()
{
    const Document *doc = m_editor->document();
    double diagonal = 0.0;
    if (m_combAll) {
        // About 20 000 teeth in all on large documents, at least 200 a curve.
        const auto shown = [](const Curve &c) { return c.visible && c.segmentCount() > 0 && !c.problem(); };
        const auto count = std::count_if(doc->curves().begin(), doc->curves().end(), shown);
        const int budget = std::max(200, static_cast<int>(20000 / std::max<std::ptrdiff_t>(count, 1)));
        for (const Curve &c : doc->curves())
            if (shown(c))
                addComb(c, diagonal, std::min(budget, 4000));
    } else if (const Curve *c = doc->find(m_curve)) {
        addComb(*c, diagonal, 4000);
    }
    m_applicable = !m_teeth.empty();
    if (m_teeth.empty())
        return;
    // One scale for all teeth, so that curves shown together compare: at scale 1 a curvature of
    // the 90th percentile of |κ| gets a tooth an eighth of the largest curve's diagonal (the
    // percentile rather than the maximum, so that a near-cusp does not flatten everything else).
    std::vector<double> magnitudes;
    magnitudes.reserve(m_teeth.size());
    for (const Tooth &t : m_teeth)
        magnitudes.push_back(std::abs(t.curvature));
    const auto nth = magnitudes.begin() + static_cast<std::ptrdiff_t>((magnitudes.size() - 1) * 9 / 10);
    std::nth_element(magnitudes.begin(), nth, magnitudes.end());
    const double reference = *nth;
    const double factor = reference > 0.0 ? m_combScale * diagonal / 8.0 / reference : 0.0;
    // Teeth point away from the centre of curvature (the usual drawing of a comb), so the outline
    // stays outside the curve; a tooth is at most as long as the diagonal.
    TeachingScene::Polyline outline{TeachingScene::Role::CombOutline, 0, {}, false};
    for (std::size_t i = 0; i < m_teeth.size(); ++i) {
        Tooth &t = m_teeth[i];
        const double length = std::clamp(factor * t.curvature, -diagonal, diagonal);
        t.tip = t.base - length * t.normal;
        m_scene.polylines.push_back({TeachingScene::Role::CombTooth, 0, {t.base, t.tip}, false});
        if (i > 0 && m_teeth[i - 1].curve != t.curve) {
            m_scene.polylines.push_back(std::move(outline));
            outline = {TeachingScene::Role::CombOutline, 0, {}, false};
        }
        outline.points.push_back(t.tip);
    }
    m_scene.polylines.push_back(std::move(outline));
}

void TeachingController::addComb(const Curve &c, double &diagonal, int budget)
{
    const int m = c.segmentCount();
    const geo::Box box = c.bounds();
    const double size = box.isEmpty() ? 0.0 : box.diagonal().norm();
    // A curve whose size overflows a double (knots near ±1.8e308) has no comb to draw: its teeth
    // would end at infinity, and their points at NaN.
    if (!(size > 0.0) || !std::isfinite(size))
        return;
    diagonal = std::max(diagonal, size);
    const int id = m_teeth.empty() ? 0 : m_teeth.back().curve + 1;
    const int degree = c.segment(0).degree();
    const int samples = samplesPerSegment(m, degree, budget);
    for (int s = 0; s < m; ++s) {
        const geo::Bezier b = c.segment(s);
        for (int i = 0; i <= samples; ++i) {
            if (s > 0 && i == 0)
                continue; // the joint was the last tooth of the previous segment
            const double t = static_cast<double>(i) / samples;
            const geo::Point d = b.derivative(t);
            const double speed = d.norm();
            if (!(speed > 1e-12) || !std::isfinite(speed))
                continue;
            const geo::Point base = b.eval(t);
            const double curvature = b.curvature(t);
            if (!std::isfinite(base.x()) || !std::isfinite(base.y()) || !std::isfinite(curvature))
                continue;
            m_teeth.push_back({base, base, curvature, geo::Point(-d.y() / speed, d.x() / speed), id});
        }
    }
    // Continuity marks at the joints (G0 … C2), as the info panel reports them; long splines get none.
    const geo::PiecewiseBezier piecewise = c.toPiecewise();
    if (piecewise.segmentCount() > 1 && piecewise.segmentCount() <= 200) {
        for (const geo::JointContinuity &j : piecewise.continuity()) {
            m_scene.labels.push_back({TeachingScene::Role::Joint, static_cast<int>(j.level),
                                      piecewise.segments()[static_cast<std::size_t>(j.right)].startPoint(),
                                      QString::fromLatin1(geo::nameOf(j.level))});
        }
    }
}

} // namespace kontur
