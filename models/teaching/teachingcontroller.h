// TeachingController: the state of the teaching views (issue #9 part A) — de Casteljau construction
// (seed 004), degree elevation (seed 002), comparison of curve kinds or parameterizations over one
// set of points, curvature comb with continuity marks — and the geometry each view shows, computed
// here in world coordinates for the overlay item to draw. Edits the views offer (split at t, reduce
// the degree, add or remove a control point) go through the EditController as undoable commands.
#pragma once

#include "models/controllers/editcontroller.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QRectF>
#include <QTimer>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace kontur {

// What a teaching view asks the overlay to draw, in world coordinates. Colours and widths are the
// overlay's business: each element names its role and an index (construction level, palette entry,
// continuity level).
struct TeachingScene
{
    enum class Role {
        Level,           // a polygon of the de Casteljau construction (index: level k >= 1)
        CurvePoint,      // the point B(t) (the marker)
        LeftHalf,        // the curve over [0, t]
        ElevatedPolygon, // the elevated control polygon (elevation view)
        CombTooth,       // one tooth of the curvature comb
        CombOutline,     // the line through the tips of the teeth
        CompareCurve,    // one compared curve (index: palette entry)
        Joint,           // a joint with its continuity (index: geo::Continuity value)
        Midpoint,        // the inserted joints of a contour curve (seed 004), as dots
    };
    struct Polyline
    {
        Role role;
        int index = 0;
        std::vector<geo::Point> points;
        bool dots = false; // draw the vertices as dots too
    };
    struct Curves
    {
        Role role;
        int index = 0;
        std::vector<geo::Bezier> pieces; // flattened by the overlay in screen space
    };
    struct Label
    {
        Role role;
        int index = 0;
        geo::Point at = geo::Point::Zero();
        QString text;
    };
    std::vector<Polyline> polylines;
    std::vector<Curves> curves;
    std::vector<Label> labels;
    [[nodiscard]] bool isEmpty() const { return polylines.empty() && curves.empty() && labels.empty(); }
};

// Not final: QML (Qt 6.4) derives from registered types.
class TeachingController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    Q_PROPERTY(View view READ view WRITE setView NOTIFY viewChanged)
    // The curve the view works on: the selected one, or the last one selected while nothing is.
    Q_PROPERTY(int curve READ curve NOTIFY curveChanged)
    // Whether the view can show anything for that curve (elevation needs a Bézier curve).
    Q_PROPERTY(bool applicable READ isApplicable NOTIFY sceneChanged)
    Q_PROPERTY(bool isBezier READ isBezier NOTIFY sceneChanged)
    // The curve parameter t in [0, 1] of the de Casteljau view (the basis plot's marker follows it).
    Q_PROPERTY(double parameter READ parameter WRITE setParameter NOTIFY parameterChanged)
    Q_PROPERTY(bool playing READ isPlaying WRITE setPlaying NOTIFY playingChanged)
    // Animation speed, a factor 0.25..4 (1: t runs through [0, 1] in 5 s; 4 elevation steps a second).
    Q_PROPERTY(double speed READ speed WRITE setSpeed NOTIFY speedChanged)
    // +1 forward, -1 backward.
    Q_PROPERTY(int direction READ direction WRITE setDirection NOTIFY directionChanged)
    // Elevation: r successive elevations, 0..maximumStep (degree n + r at most 100).
    Q_PROPERTY(int elevationStep READ elevationStep WRITE setElevationStep NOTIFY elevationStepChanged)
    Q_PROPERTY(int maximumStep READ maximumStep NOTIFY sceneChanged)
    Q_PROPERTY(int degree READ degree NOTIFY sceneChanged)
    // The largest distance between the curve and its reduction by one degree (-1: not possible).
    Q_PROPERTY(double reductionError READ reductionError NOTIFY sceneChanged)
    Q_PROPERTY(double combScale READ combScale WRITE setCombScale NOTIFY combScaleChanged)
    Q_PROPERTY(bool combAllCurves READ combAllCurves WRITE setCombAllCurves NOTIFY combAllCurvesChanged)
    Q_PROPERTY(CompareMode compareMode READ compareMode WRITE setCompareMode NOTIFY compareModeChanged)
    // The compared curves: [{name, palette, shown, available}], names translated.
    Q_PROPERTY(QVariantList legend READ legend NOTIFY legendChanged)
    // B(t) in world coordinates (de Casteljau view).
    Q_PROPERTY(QPointF curvePoint READ curvePoint NOTIFY sceneChanged)

public:
    enum class View { None, DeCasteljau, Elevation, Compare, Comb };
    Q_ENUM(View)
    enum class CompareMode { Kinds, Parameterizations };
    Q_ENUM(CompareMode)
    static constexpr int kMaximumDegree = 100; // seed 002's demo goes to degree 100

    explicit TeachingController(QObject *parent = nullptr);
    ~TeachingController() override;
    Q_DISABLE_COPY_MOVE(TeachingController)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] View view() const { return m_view; }
    void setView(View view);
    // The id of the curve the view shows (0: none).
    [[nodiscard]] int curve() const { return static_cast<int>(m_curve); }
    [[nodiscard]] bool isApplicable() const { return m_applicable; }
    [[nodiscard]] bool isBezier() const;
    [[nodiscard]] double parameter() const { return m_parameter; }
    void setParameter(double t);
    [[nodiscard]] bool isPlaying() const { return m_playing; }
    void setPlaying(bool playing);
    [[nodiscard]] double speed() const { return m_speed; }
    void setSpeed(double speed);
    [[nodiscard]] int direction() const { return m_direction; }
    void setDirection(int direction);
    [[nodiscard]] int elevationStep() const { return m_step; }
    void setElevationStep(int step);
    [[nodiscard]] int maximumStep() const;
    [[nodiscard]] int degree() const;
    [[nodiscard]] double reductionError() const { return m_reductionError; }
    [[nodiscard]] double combScale() const { return m_combScale; }
    void setCombScale(double scale);
    [[nodiscard]] bool combAllCurves() const { return m_combAll; }
    void setCombAllCurves(bool all);
    [[nodiscard]] CompareMode compareMode() const { return m_compareMode; }
    void setCompareMode(CompareMode mode);
    [[nodiscard]] QVariantList legend() const;
    [[nodiscard]] QPointF curvePoint() const;

    [[nodiscard]] const TeachingScene &scene() const { return m_scene; }
    // The de Casteljau levels at t (level 0 is the control polygon of the segment t falls in).
    [[nodiscard]] const std::vector<std::vector<geo::Point>> &levels() const { return m_levels; }
    [[nodiscard]] const std::vector<geo::Point> &elevatedPolygon() const { return m_elevated; }

    // For QML and tests: the levels as [[{x, y}, …], …], the elevated polygon as [{x, y}, …].
    Q_INVOKABLE QVariantList constructionPoints() const;
    Q_INVOKABLE QVariantList elevatedPoints() const;
    // The comb's teeth as [{base, tip, curvature}] (world coordinates).
    Q_INVOKABLE QVariantList combTeeth() const;
    // Shows or hides one compared curve (a legend entry).
    Q_INVOKABLE void setCompareShown(int entry, bool shown);
    // The world rectangle around everything the view draws (the compared curves' control points
    // bound the curves); a null rectangle when it draws nothing. The canvas fits it into view.
    Q_INVOKABLE QRectF sceneBounds() const;

    // The marker dragged along the curve: t becomes the parameter of the nearest curve point.
    Q_INVOKABLE void dragMarkerTo(QPointF world);
    // One animation step of `seconds` (the timer calls this; tests call it directly).
    Q_INVOKABLE void advance(double seconds);
    // Splits the Bézier curve at t into two curves (one undo step).
    Q_INVOKABLE bool splitAtParameter();
    // Replaces the Bézier curve by its least-squares reduction by one degree (one undo step).
    Q_INVOKABLE bool reduceDegree();
    // Elevation view, Alt+click or long press at `world`: removes the control point within `radius`,
    // or adds one where it lengthens the control polygon least. Returns whether something changed.
    Q_INVOKABLE bool toggleControlPoint(QPointF world, double radius);

Q_SIGNALS:
    void editorChanged();
    void viewChanged();
    void curveChanged();
    void parameterChanged();
    void playingChanged();
    void speedChanged();
    void directionChanged();
    void elevationStepChanged();
    void combScaleChanged();
    void combAllCurvesChanged();
    void compareModeChanged();
    // The geometry to draw changed.
    void sceneChanged();
    // The compared curves' names, availability or visibility changed (not on every edit).
    void legendChanged();

private:
    void setCurve(CurveId curve);
    // The curve the view shows, if the document still holds it.
    [[nodiscard]] const Curve *shownCurve() const;
    void followSelection();
    void recompute();
    void buildDeCasteljau(const Curve &c);
    void buildElevation(const Curve &c);
    void buildCompare(const Curve &c);
    void buildComb();
    // Samples one curve for the comb with about `budget` teeth (tips still unscaled) and adds its
    // joint marks.
    void addComb(const Curve &c, double &diagonal, int budget);
    void onTimer();

    QPointer<EditController> m_editor;
    View m_view = View::None;
    CurveId m_curve = CurveId::None;
    bool m_applicable = false;
    double m_parameter = 0.5;
    bool m_playing = false;
    double m_speed = 1.0;
    int m_direction = 1;
    int m_step = 0;
    double m_stepFraction = 0.0; // animation progress between two steps
    double m_combScale = 1.0;
    bool m_combAll = false;
    CompareMode m_compareMode = CompareMode::Kinds;
    std::vector<int> m_compareHidden; // legend entries switched off, by entry id
    double m_reductionError = -1.0;

    struct CompareEntry
    {
        int id = 0; // kind value, or parameterization value
        QString name;
        int palette = 0;
        bool available = false;
    };
    std::vector<CompareEntry> m_compare;
    std::vector<std::vector<geo::Point>> m_levels;
    std::vector<geo::Point> m_elevated;
    struct Tooth
    {
        geo::Point base, tip;
        double curvature = 0.0;
        geo::Point normal = geo::Point::Zero(); // unit left normal at the base
        int curve = 0;                          // which curve it belongs to (one outline each)
    };
    std::vector<Tooth> m_teeth;
    TeachingScene m_scene;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace kontur
