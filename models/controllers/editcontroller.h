// EditController: the composition root of editing. It owns the document, the one undo stack every
// change goes through (`push`), the selection, the list models, and the controllers that each do one
// thing: Placement (new curves), CurveCommands (edits of existing curves), the background. It turns
// the canvas's gestures, forwarded in world coordinates, into those: a tap places or picks, a drag
// moves a point with the kind's rule as one mergeable undo command. Refusals become messages.
#pragma once

#include "models/controllers/backgroundcontroller.h"
#include "models/controllers/curvecommands.h"
#include "models/controllers/placement.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "models/document/pointindex.h"
#include "models/document/selection.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"
#include "models/itemmodels/selectedcurvemodel.h"
#include "models/text/messages.h"
#include "models/text/numbers.h"
#include "models/text/shownmessage.h"

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
    CurveId curve = CurveId::None;
    int point = -1;
    [[nodiscard]] bool isValid() const { return curve != CurveId::None && point >= 0; }
    friend bool operator==(const PointRef &, const PointRef &) = default;
};

// The nearest curve to a position: which curve, which segment, where on it.
struct CurveHit
{
    CurveId curve = CurveId::None;
    int segment = -1;
    double t = 0.0;
    double distance = 0.0;
    [[nodiscard]] bool isValid() const { return curve != CurveId::None; }
};

// Not final: QML (Qt 6.4) derives from registered types.
class EditController : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::Document *document READ document CONSTANT)
    Q_PROPERTY(kontur::CurveListModel *curves READ curves CONSTANT)
    Q_PROPERTY(kontur::PointListModel *points READ points CONSTANT)
    Q_PROPERTY(kontur::Selection *selection READ selection CONSTANT)
    // The selected curve's row of `curves` as a model of one row (none without a selection).
    Q_PROPERTY(kontur::SelectedCurveModel *selectedCurve READ selectedCurve CONSTANT)
    Q_PROPERTY(kontur::Placement *placement READ placement CONSTANT)
    Q_PROPERTY(kontur::CurveCommands *commands READ commands CONSTANT)
    Q_PROPERTY(Mode mode READ mode WRITE setMode NOTIFY modeChanged)
    Q_PROPERTY(HandleMode handleMode READ handleMode WRITE setHandleMode NOTIFY handleModeChanged)
    Q_PROPERTY(bool dragging READ isDragging NOTIFY draggingChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoStateChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoStateChanged)
    Q_PROPERTY(bool modified READ isModified NOTIFY undoStateChanged)
    // The message line's message: an id with its arguments; QML shows `message.text`, made in the UI
    // language when read and announced again after a language switch (ShownMessage).
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)
    // The background picture and its placement.
    Q_PROPERTY(kontur::BackgroundController *background READ background CONSTANT)
    // Message 4, the question before "Reset all", announced again after a language switch.
    Q_PROPERTY(QString resetQuestion READ resetQuestion NOTIFY textsChanged)

public:
    enum class Mode {
        Select, // tap picks, drag moves points (or pans on empty canvas)
        Place,  // taps place the points of a new curve (Placement)
    };
    Q_ENUM(Mode)
    enum class HandleMode {
        Free,        // seed: left button; the opposite handle turns to stay collinear
        Constrained, // seed: right button; only the handle's distance to its knot changes
    };
    Q_ENUM(HandleMode)

    explicit EditController(QObject *parent = nullptr);
    ~EditController() override;
    Q_DISABLE_COPY_MOVE(EditController)

    [[nodiscard]] Document *document() const { return m_document; }
    [[nodiscard]] CurveListModel *curves() const { return m_curves; }
    [[nodiscard]] PointListModel *points() const { return m_points; }
    [[nodiscard]] Selection *selection() const { return m_selection; }
    [[nodiscard]] SelectedCurveModel *selectedCurve() const { return m_selectedCurve; }
    [[nodiscard]] Placement *placement() const { return m_placement; }
    [[nodiscard]] CurveCommands *commands() const { return m_commands; }
    [[nodiscard]] BackgroundController *background() const { return m_background; }

    // --- the one undo stack: every change to the document is a command pushed here ---
    void push(QUndoCommand *command);
    [[nodiscard]] const QUndoStack *undoStack() const { return &m_undo; }
    Q_INVOKABLE void undo();
    Q_INVOKABLE void redo();
    // While placing, undo first takes back the placed points.
    [[nodiscard]] bool canUndo() const { return m_undo.canUndo() || m_placement->pendingCount() > 0; }
    [[nodiscard]] bool canRedo() const { return m_undo.canRedo(); }
    [[nodiscard]] bool isModified() const { return !m_undo.isClean(); }
    Q_INVOKABLE void markSaved() { m_undo.setClean(); }
    // Replaces everything (opening a document, recovering): a new undo history, marked saved
    // unless `modified`.
    void replaceDocument(std::vector<Curve> curves, const Background &background, const QString &units, bool modified);

    // --- modes ---
    [[nodiscard]] Mode mode() const { return m_mode; }
    void setMode(Mode mode);
    [[nodiscard]] HandleMode handleMode() const { return m_handleMode; }
    void setHandleMode(HandleMode mode);
    [[nodiscard]] geo::HandleMove handleMoveMode() const
    {
        return m_handleMode == HandleMode::Constrained ? geo::HandleMove::Constrained : geo::HandleMove::Free;
    }
    // Starts placing a new curve of `kind` (a CurveKind value).
    Q_INVOKABLE void startPlacing(int kind);

    // --- messages ---
    [[nodiscard]] Message message() const { return m_message.message(); }
    [[nodiscard]] QString messageText() const { return m_message.message().text(); }
    // Message 4, the question before "Reset all", in the current language.
    [[nodiscard]] QString resetQuestion() const { return Message{Message::ConfirmReset, {}}.text(); }
    Q_INVOKABLE void clearMessage();
    void showMessage(Message::Id id, QVariantList args = {});
    // The message that says why a geometry error refused an edit of `curve`.
    void sayError(const Curve &curve, const geo::Error &error);
    // True for a number; otherwise says message 10 (not a number) or 18 (beyond the largest double).
    [[nodiscard]] bool accepted(Parsed parsed);
    // "Bézier 3", "Composite 4": the next new curve's name.
    [[nodiscard]] QString newCurveName(CurveKind kind);

    // --- hit testing (world units) ---
    // The point nearest to `world` within `radius`, or an invalid ref.
    [[nodiscard]] PointRef hitTest(const geo::Point &world, double radius);
    // The curve nearest to `world` within `radius` (for picking a curve between its points).
    [[nodiscard]] CurveHit curveAt(const geo::Point &world, double radius);

    // --- gestures, in world coordinates; `hitRadius` is the touch target's radius ---
    // Select mode: picks the point or curve under `world`; Place mode: places a point.
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    // Starts dragging the point under `world`; false when there is none (the view may pan instead).
    // `constrained` is the per-drag override (right button or Shift) for composite handles. The
    // document does not change until the first step.
    Q_INVOKABLE bool beginDrag(QPointF world, double hitRadius, bool constrained = false);
    // One drag step: a MovePointCommand, merged with the drag's earlier steps into one undo step.
    Q_INVOKABLE void dragTo(QPointF world);
    Q_INVOKABLE void endDrag();
    [[nodiscard]] bool isDragging() const { return m_drag.isValid(); }

    // Refreshes translated texts held by the models after a language switch.
    Q_INVOKABLE void retranslate();

Q_SIGNALS:
    void modeChanged();
    void handleModeChanged();
    void draggingChanged();
    void undoStateChanged();
    void messageChanged();
    // The language changed: the translated texts (resetQuestion) read anew.
    void textsChanged();
    // Curves came from a file (opened, recovered or imported): the view may want to show them all.
    void documentReplaced();

private:
    QUndoStack m_undo;
    Document *m_document;
    CurveListModel *m_curves;
    PointListModel *m_points;
    Selection *m_selection;
    SelectedCurveModel *m_selectedCurve;
    Placement *m_placement;
    CurveCommands *m_commands;
    BackgroundController *m_background;
    PointIndex m_index;
    Mode m_mode = Mode::Select;
    HandleMode m_handleMode = HandleMode::Free;
    PointRef m_drag;
    geo::HandleMove m_dragMode = geo::HandleMove::Free;
    geo::Point m_grabOffset = geo::Point::Zero(); // point minus pointer, so the point does not jump
    int m_dragSerial = 0;
    int m_createdCount = 0;
    ShownMessage m_message{this, [this] { Q_EMIT messageChanged(); }};
};

} // namespace kontur
