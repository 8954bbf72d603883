// EditController: the edit rules. QML forwards gestures here in world coordinates; the controller
// decides what they mean (place a point, pick, drag) and changes the document through undo commands.
#pragma once

#include "models/curve.h"
#include "models/curvelistmodel.h"
#include "models/document.h"
#include "models/pointlistmodel.h"

#include <QObject>
#include <QPointF>
#include <QUndoStack>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// A point of a curve, as found by a hit test.
struct PointRef
{
    int curve = -1;
    int point = -1;
    [[nodiscard]] bool isValid() const { return curve >= 0 && point >= 0; }
    friend bool operator==(const PointRef &, const PointRef &) = default;
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
    Q_PROPERTY(int pendingCount READ pendingCount NOTIFY pendingChanged)
    Q_PROPERTY(int requiredPoints READ requiredPoints CONSTANT)
    Q_PROPERTY(int selectedCurve READ selectedCurve WRITE selectCurve NOTIFY selectionChanged)
    Q_PROPERTY(int selectedPoint READ selectedPoint NOTIFY selectionChanged)
    Q_PROPERTY(bool dragging READ isDragging NOTIFY draggingChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoStateChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoStateChanged)

public:
    enum class Mode {
        Select,      // tap picks, drag moves points (or pans on empty canvas)
        PlaceBezier, // taps place the control points of a new cubic Bézier curve
    };
    Q_ENUM(Mode)

    explicit EditController(QObject *parent = nullptr);
    ~EditController() override;
    Q_DISABLE_COPY_MOVE(EditController)

    [[nodiscard]] Document *document() const { return m_document; }
    [[nodiscard]] CurveListModel *curves() const { return m_curves; }
    [[nodiscard]] PointListModel *points() const { return m_points; }
    [[nodiscard]] QUndoStack *undoStack() { return &m_undo; }

    [[nodiscard]] Mode mode() const { return m_mode; }
    void setMode(Mode mode);

    [[nodiscard]] const std::vector<geo::Point> &pendingPoints() const { return m_pending; }
    [[nodiscard]] int pendingCount() const { return static_cast<int>(m_pending.size()); }
    [[nodiscard]] static int requiredPoints() { return 4; }
    [[nodiscard]] bool hasHover() const { return m_hasHover; }
    [[nodiscard]] geo::Point hoverPoint() const { return m_hover; }

    [[nodiscard]] int selectedCurve() const { return m_selectedCurve; }
    [[nodiscard]] int selectedPoint() const { return m_selectedPoint; }
    void selectCurve(int curve);
    [[nodiscard]] bool isDragging() const { return m_drag.isValid(); }

    // While placing, undo first takes back the placed points.
    [[nodiscard]] bool canUndo() const { return m_undo.canUndo() || !m_pending.empty(); }
    [[nodiscard]] bool canRedo() const { return m_undo.canRedo(); }

    // The point nearest to `world` within `radius` (world units), or an invalid ref.
    [[nodiscard]] PointRef hitTest(const geo::Point &world, double radius) const;

    // A tap at a world position; `hitRadius` is the touch target's radius in world units.
    Q_INVOKABLE void tap(QPointF world, double hitRadius);
    // Starts dragging the point under `world`; false when there is none (the view may pan instead).
    Q_INVOKABLE bool beginDrag(QPointF world, double hitRadius);
    Q_INVOKABLE void dragTo(QPointF world);
    Q_INVOKABLE void endDrag();
    // The pointer hovers (mouse): the rubber band runs from the last placed point to it.
    Q_INVOKABLE void hover(QPointF world);
    Q_INVOKABLE void clearHover();
    Q_INVOKABLE void cancelPlacement();
    Q_INVOKABLE void removeLastPending();
    Q_INVOKABLE void undo();
    Q_INVOKABLE void redo();
    // Refreshes translated texts held by the models after a language switch.
    Q_INVOKABLE void retranslate();

Q_SIGNALS:
    void modeChanged();
    void pendingChanged();
    void hoverChanged();
    void selectionChanged();
    void draggingChanged();
    void undoStateChanged();

private:
    void setSelection(int curve, int point);
    void finishPlacement();

    QUndoStack m_undo;
    Document *m_document;
    CurveListModel *m_curves;
    PointListModel *m_points;
    Mode m_mode = Mode::Select;
    std::vector<geo::Point> m_pending;
    geo::Point m_hover = geo::Point::Zero();
    bool m_hasHover = false;
    int m_selectedCurve = -1;
    int m_selectedPoint = -1;
    PointRef m_drag;
    geo::Point m_dragStart = geo::Point::Zero();  // the point's position when the drag began
    geo::Point m_grabOffset = geo::Point::Zero(); // point minus pointer, so the point does not jump
    int m_dragSerial = 0;
    int m_createdCount = 0;
};

} // namespace kontur
