// EditController: the edit rules. QML forwards gestures and commands here in world coordinates;
// the controller decides what they mean (place a point, pick, drag with the kind's rule, refuse with
// a message) and changes the document through undo commands.
#pragma once

#include "models/curve.h"
#include "models/curvelistmodel.h"
#include "models/document.h"
#include "models/messages.h"
#include "models/pointindex.h"
#include "models/pointlistmodel.h"

#include <QObject>
#include <QPointF>
#include <QUndoStack>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <optional>

namespace kontur {

// A point of a curve, as found by a hit test.
struct PointRef
{
    int curve = -1;
    int point = -1;
    [[nodiscard]] bool isValid() const { return curve >= 0 && point >= 0; }
    friend bool operator==(const PointRef &, const PointRef &) = default;
};

// The nearest curve to a position: which curve, which segment, where on it.
struct CurveHit
{
    int curve = -1;
    int segment = -1;
    double t = 0.0;
    double distance = 0.0;
    [[nodiscard]] bool isValid() const { return curve >= 0; }
};

// Not final: QML (Qt 6.4) derives from registered types.
class EditController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::Document *document READ document CONSTANT)
    Q_PROPERTY(kontur::CurveListModel *curves READ curves CONSTANT)
    Q_PROPERTY(kontur::PointListModel *points READ points CONSTANT)
    Q_PROPERTY(Mode mode READ mode WRITE setMode NOTIFY modeChanged)
    Q_PROPERTY(int placementKind READ placementKind WRITE setPlacementKind NOTIFY placementChanged)
    Q_PROPERTY(int placementDegree READ placementDegree WRITE setPlacementDegree NOTIFY placementChanged)
    Q_PROPERTY(int parameterization READ parameterization WRITE setParameterization NOTIFY placementChanged)
    Q_PROPERTY(HandleMode handleMode READ handleMode WRITE setHandleMode NOTIFY handleModeChanged)
    Q_PROPERTY(int pendingCount READ pendingCount NOTIFY pendingChanged)
    Q_PROPERTY(int requiredPoints READ requiredPoints NOTIFY placementChanged)
    Q_PROPERTY(bool placementOpenEnded READ placementOpenEnded NOTIFY placementChanged)
    Q_PROPERTY(int selectedCurve READ selectedCurve WRITE selectCurve NOTIFY selectionChanged)
    Q_PROPERTY(int selectedPoint READ selectedPoint NOTIFY selectionChanged)
    Q_PROPERTY(bool dragging READ isDragging NOTIFY draggingChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoStateChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoStateChanged)
    Q_PROPERTY(bool modified READ isModified NOTIFY undoStateChanged)
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)
    // Translated texts: announced again when the language changes (LanguageWatch).
    Q_PROPERTY(QString messageText READ messageText NOTIFY messageChanged)
    Q_PROPERTY(QVariantList kinds READ kinds NOTIFY textsChanged)
    Q_PROPERTY(QString resetQuestion READ resetQuestion NOTIFY textsChanged)
    Q_PROPERTY(QString backgroundFile READ backgroundFile NOTIFY backgroundChanged)
    Q_PROPERTY(bool backgroundVisible READ backgroundVisible WRITE setBackgroundVisible NOTIFY backgroundChanged)
    Q_PROPERTY(double backgroundOpacity READ backgroundOpacity WRITE setBackgroundOpacity NOTIFY backgroundChanged)

public:
    enum class Mode {
        Select, // tap picks, drag moves points (or pans on empty canvas)
        Place,  // taps place the points of a new curve of `placementKind`
    };
    Q_ENUM(Mode)
    enum class HandleMode {
        Free,        // seed: left button; the opposite handle turns to stay collinear
        Constrained, // seed: right button; only the handle's distance to its knot changes
    };
    Q_ENUM(HandleMode)
    // The kinds as QML sees them (values of CurveKind).
    enum Kind {
        BezierKind = static_cast<int>(CurveKind::Bezier),
        InterpolatingKind = static_cast<int>(CurveKind::Interpolating),
        LeastSquaresKind = static_cast<int>(CurveKind::LeastSquares),
        CompositeKind = static_cast<int>(CurveKind::Composite),
        NaturalSplineKind = static_cast<int>(CurveKind::NaturalSpline),
        ClampedSplineKind = static_cast<int>(CurveKind::ClampedSpline),
        NotAKnotSplineKind = static_cast<int>(CurveKind::NotAKnotSpline),
        PeriodicSplineKind = static_cast<int>(CurveKind::PeriodicSpline),
        CatmullRomKind = static_cast<int>(CurveKind::CatmullRom),
        HermiteSplineKind = static_cast<int>(CurveKind::HermiteSpline),
        BSplineKind = static_cast<int>(CurveKind::BSpline),
        GlobalBSplineKind = static_cast<int>(CurveKind::GlobalBSpline),
        PolynomialKind = static_cast<int>(CurveKind::Polynomial),
        FunctionSplineKind = static_cast<int>(CurveKind::FunctionSpline),
    };
    Q_ENUM(Kind)
    enum Parameterization {
        Uniform = static_cast<int>(geo::Parameterization::Uniform),
        ChordLength = static_cast<int>(geo::Parameterization::ChordLength),
        Centripetal = static_cast<int>(geo::Parameterization::Centripetal),
    };
    Q_ENUM(Parameterization)
    enum NodeType {
        Smooth = static_cast<int>(geo::NodeType::Smooth),
        Symmetric = static_cast<int>(geo::NodeType::Symmetric),
        Corner = static_cast<int>(geo::NodeType::Corner),
    };
    Q_ENUM(NodeType)

    explicit EditController(QObject *parent = nullptr);
    ~EditController() override;
    Q_DISABLE_COPY_MOVE(EditController)

    [[nodiscard]] Document *document() const { return m_document; }
    [[nodiscard]] CurveListModel *curves() const { return m_curves; }
    [[nodiscard]] PointListModel *points() const { return m_points; }
    [[nodiscard]] QUndoStack *undoStack() { return &m_undo; }

    // --- modes and settings for new curves ---
    [[nodiscard]] Mode mode() const { return m_mode; }
    void setMode(Mode mode);
    [[nodiscard]] int placementKind() const { return static_cast<int>(m_placementKind); }
    void setPlacementKind(int kind);
    [[nodiscard]] int placementDegree() const { return m_placementDegree; }
    void setPlacementDegree(int degree);
    [[nodiscard]] int parameterization() const { return static_cast<int>(m_parameterization); }
    void setParameterization(int parameterization);
    [[nodiscard]] HandleMode handleMode() const { return m_handleMode; }
    void setHandleMode(HandleMode mode);
    // Starts placing a new curve of `kind` (a CurveKind value).
    Q_INVOKABLE void startPlacing(int kind);
    // The kinds a user can create, for menus: [{kind, name}], names translated.
    [[nodiscard]] QVariantList kinds() const;

    // --- placing ---
    [[nodiscard]] const std::vector<geo::Point> &pendingPoints() const { return m_pending; }
    [[nodiscard]] int pendingCount() const { return static_cast<int>(m_pending.size()); }
    // Points that finish the placement by themselves; 0 for open-ended kinds (they need "Done").
    [[nodiscard]] int requiredPoints() const;
    [[nodiscard]] bool placementOpenEnded() const { return requiredPoints() == 0; }
    // The segments to preview while placing (the seed shows composite segments from the 3rd knot).
    [[nodiscard]] std::vector<geo::Bezier> pendingSegments() const;
    [[nodiscard]] bool hasHover() const { return m_hasHover; }
    [[nodiscard]] geo::Point hoverPoint() const { return m_hover; }

    // --- selection ---
    [[nodiscard]] int selectedCurve() const { return m_selectedCurve; }
    [[nodiscard]] int selectedPoint() const { return m_selectedPoint; }
    void selectCurve(int curve);
    Q_INVOKABLE void selectPoint(int curve, int row);
    [[nodiscard]] bool isDragging() const { return m_drag.isValid(); }

    // --- undo ---
    // While placing, undo first takes back the placed points.
    [[nodiscard]] bool canUndo() const { return m_undo.canUndo() || !m_pending.empty(); }
    [[nodiscard]] bool canRedo() const { return m_undo.canRedo(); }
    [[nodiscard]] bool isModified() const { return !m_undo.isClean(); }
    Q_INVOKABLE void markSaved() { m_undo.setClean(); }

    // --- messages ---
    [[nodiscard]] Message message() const { return m_message; }
    // The current message in the current language.
    [[nodiscard]] QString messageText() const { return m_message.text(); }
    // Message 4, the question before "Reset all", in the current language.
    [[nodiscard]] QString resetQuestion() const { return Message{Message::ConfirmReset, {}}.text(); }
    Q_INVOKABLE void clearMessage();
    void showMessage(Message::Id id, QVariantList args = {}) { say(id, std::move(args)); }
    // Replaces everything (opening a document, recovering): a new undo history, marked saved
    // unless `modified`.
    void replaceDocument(std::vector<Curve> curves, const Background &background, const QString &units, bool modified);
    // Appends curves (an import): one undo step.
    void addCurves(std::vector<Curve> curves, const QString &text);

    // --- hit testing (world units) ---
    // The point nearest to `world` within `radius`, or an invalid ref.
    [[nodiscard]] PointRef hitTest(const geo::Point &world, double radius);
    // The curve nearest to `world` within `radius` (for picking a curve between its points).
    [[nodiscard]] CurveHit curveAt(const geo::Point &world, double radius);

    // --- gestures, in world coordinates; `hitRadius` is the touch target's radius ---
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    // Starts dragging the point under `world`; false when there is none (the view may pan instead).
    // `constrained` is the per-drag override (right button or Shift) for composite handles.
    Q_INVOKABLE bool beginDrag(QPointF world, double hitRadius, bool constrained = false);
    Q_INVOKABLE void dragTo(QPointF world);
    Q_INVOKABLE void endDrag();
    Q_INVOKABLE void hover(QPointF world);
    Q_INVOKABLE void clearHover();
    Q_INVOKABLE void cancelPlacement();
    Q_INVOKABLE void removeLastPending();
    // "Done": finishes an open-ended placement (or a Bézier curve of fewer points).
    Q_INVOKABLE bool finishPlacement();

    // --- commands on curves (all undoable; refusals come as messages) ---
    Q_INVOKABLE void undo();
    Q_INVOKABLE void redo();
    Q_INVOKABLE bool deleteCurve(int curve);
    Q_INVOKABLE bool moveCurve(int from, int to);
    Q_INVOKABLE bool setCurveParameterization(int curve, int parameterization);
    Q_INVOKABLE bool setCurveName(int curve, const QString &name);
    Q_INVOKABLE bool setCurveColor(int curve, const QColor &color);
    Q_INVOKABLE bool setCurveVisible(int curve, bool visible);
    Q_INVOKABLE bool setCurveLocked(int curve, bool locked);
    Q_INVOKABLE bool setNodeType(int curve, int knot, int type);
    // The order k of a B-spline (2..10, at most its number of control points).
    Q_INVOKABLE bool setCurveOrder(int curve, int order);
    // Adds a defining point before `index` (the table's "Add row"); deletes one ("Delete row").
    Q_INVOKABLE bool insertPoint(int curve, int index, QPointF position);
    Q_INVOKABLE bool removePoint(int curve, int index);
    // Splits a composite curve's segment at t (the shape stays); closes a composite curve.
    Q_INVOKABLE bool insertKnotOnSegment(int curve, int segment, double t);
    Q_INVOKABLE bool closeCurve(int curve);
    // Teaching views: new control points for a Bézier curve (degree reduction), and a Bézier curve
    // split at t into two curves, the second inserted after the first. One undo step each.
    bool setControlPoints(int curve, const std::vector<geo::Point> &points, const QString &text);
    bool splitBezier(int curve, double t);
    // Typed coordinates: `rows` is a list of [x, y] texts in the UI language's number format (or
    // with a decimal point). Moves the defining points of `curve` (message 10 for empty or bad
    // values; composite handles keep the handle mode's constraint).
    Q_INVOKABLE bool applyCoordinates(int curve, const QVariantList &rows);
    // The coordinates table's "OK": `edits` lists only the cells the user typed, as {row, x, y}
    // with x and y as typed (the UI language's number format, or a decimal point); an axis left
    // out keeps the full double it holds, whatever the table shows of it. One undo step; message
    // 10 for empty or bad values, message 18 for numbers beyond the largest double.
    Q_INVOKABLE bool applyEdits(int curve, const QVariantList &edits);
    // Moves the selected point by `delta` (world units), as the arrow keys do.
    Q_INVOKABLE bool nudgeSelected(QPointF delta);
    // Delete: the selected point if it can go (a defining point above the kind's minimum),
    // otherwise the selected curve.
    Q_INVOKABLE bool deleteSelection();
    // The table's "Add row": a point after the selected one (halfway to the next, or beyond the
    // last), or at the end; "Delete row": the selected placed point, within the kind's limits.
    Q_INVOKABLE bool addRowAfterSelection();
    Q_INVOKABLE bool deleteSelectedRow();
    // The selected curve's points as text for the clipboard: label, x, y per line, tab separated,
    // numbers in the UI language's format (spreadsheets of that language read them) with every
    // digit: the shortest text that reads back as the same double.
    Q_INVOKABLE QString coordinatesText(int curve) const;
    // The joints of a curve for the info panel: [{joint, level, angle (degrees), c1Jump}], at most `limit`.
    Q_INVOKABLE QVariantList jointReport(int curve, int limit = 200) const;
    // Degree of a Bézier curve, or 3 for the cubic kinds; -1 for none.
    Q_INVOKABLE int degreeOf(int curve) const;
    // A new curve of `kind` from typed coordinates (the seed's "w/ Keyboard" input).
    Q_INVOKABLE bool createFromCoordinates(int kind, const QVariantList &rows);
    // Removes every curve (after the UI asked with message 4); one undo step.
    Q_INVOKABLE void resetAll();
    void setBackground(const Background &background);
    // Loads a background picture (seed: "Upload background"); it is placed centred on the world
    // origin at one world unit per pixel. Message 1 when the file is no readable image or too large.
    Q_INVOKABLE bool loadBackground(const QUrl &file);
    Q_INVOKABLE void clearBackground();
    [[nodiscard]] QString backgroundFile() const { return m_document->background().file; }
    [[nodiscard]] bool backgroundVisible() const { return m_document->background().visible; }
    void setBackgroundVisible(bool visible);
    [[nodiscard]] double backgroundOpacity() const { return m_document->background().opacity; }
    void setBackgroundOpacity(double opacity);
    // A number as the side panel shows it (displayNumber in pointlistmodel.h), in the UI language.
    Q_INVOKABLE QString displayNumber(double value, int decimals) const
    {
        return kontur::displayNumber(value, decimals);
    }
    // Every digit of a number (exactNumber in pointlistmodel.h): what a table cell holds for editing.
    Q_INVOKABLE QString exactNumber(double value) const { return kontur::exactNumber(value); }

Q_SIGNALS:
    void modeChanged();
    void placementChanged();
    void handleModeChanged();
    void pendingChanged();
    void hoverChanged();
    void selectionChanged();
    void draggingChanged();
    void undoStateChanged();
    void messageChanged();
    // The language changed: every translated text (kinds, resetQuestion) reads anew.
    void textsChanged();
    void backgroundChanged();
    // Curves came from a file (opened, recovered or imported): the view may want to show them all.
    void documentReplaced();

private:
    void setSelection(int curve, int point);
    // After a language switch: the texts held by the models and the message read anew.
    void retranslate();
    void say(Message::Id id, QVariantList args = {});
    void sayError(const Curve &curve, const geo::Error &error);
    [[nodiscard]] bool editable(int curve);
    // Applies `edit` to a copy of the curve and pushes the change as one undo step.
    template <typename Edit> bool editCurve(int curve, const QString &text, Edit edit);
    [[nodiscard]] QString newCurveName(CurveKind kind);
    [[nodiscard]] bool parseRows(const QVariantList &rows, std::vector<geo::Point> &out);
    // A row's new coordinates; an axis without a value keeps what the row holds.
    struct RowEdit
    {
        int row;
        std::optional<double> x, y;
    };
    // Applies new positions of defining points in order, with the handle mode's rule; one undo step.
    bool moveRows(int curve, const std::vector<RowEdit> &moves, const QString &text);
    // pendingSegments before the check that they are finite.
    [[nodiscard]] std::vector<geo::Bezier> previewSegments() const;
    // The defining point a row stands for (a composite's knot index for knot rows), or -1.
    [[nodiscard]] int pointIndexOfRow(int curve, int row) const;

    QUndoStack m_undo;
    Document *m_document;
    CurveListModel *m_curves;
    PointListModel *m_points;
    PointIndex m_index;
    Mode m_mode = Mode::Select;
    CurveKind m_placementKind = CurveKind::Bezier;
    int m_placementDegree = 3;
    geo::Parameterization m_parameterization = geo::Parameterization::Uniform;
    HandleMode m_handleMode = HandleMode::Free;
    std::vector<geo::Point> m_pending;
    geo::Point m_hover = geo::Point::Zero();
    bool m_hasHover = false;
    int m_selectedCurve = -1;
    int m_selectedPoint = -1;
    PointRef m_drag;
    geo::HandleMove m_dragMode = geo::HandleMove::Free;
    geo::Point m_grabOffset = geo::Point::Zero(); // point minus pointer, so the point does not jump
    int m_dragSerial = 0;
    int m_createdCount = 0;
    Message m_message;
};

} // namespace kontur
