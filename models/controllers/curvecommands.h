// CurveCommands: the undoable edits of existing curves (delete, reorder, style, settings, points,
// structure) and the queries the side panel asks about one curve. Curves are named by id (QML passes
// ints: Selection::curveId, CurveListModel's curveId role). Each edit checks the rules (locked
// curves, the kind's point limits, results beyond the largest double), says why it refuses, and
// otherwise pushes one command.
#pragma once

#include "models/document/commands.h"
#include "models/document/curve.h"

#include <QColor>
#include <QObject>
#include <QPointF>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <optional>
#include <vector>

namespace kontur {

class Document;
class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class CurveCommands : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("Curve commands belong to an EditController.")

public:
    explicit CurveCommands(EditController *editor);
    Q_DISABLE_COPY_MOVE(CurveCommands)

    // Every `curveId` here is a curve's stable id (CurveListModel's curveId role, Selection::curveId),
    // never a row; rows appear only where a name says so (`toRow`).
    // --- whole curves ---
    Q_INVOKABLE bool deleteCurve(int curveId);
    // Moves a curve to row `toRow` of the list.
    Q_INVOKABLE bool moveCurve(int curveId, int toRow);
    // Moves a curve `steps` places down the list (negative: up), for the list's arrows: no row
    // arithmetic in QML. False at the list's ends.
    Q_INVOKABLE bool moveCurveBy(int curveId, int steps);
    Q_INVOKABLE bool setCurveParameterization(int curveId, int parameterization);
    Q_INVOKABLE bool setCurveName(int curveId, const QString &name);
    Q_INVOKABLE bool setCurveColor(int curveId, const QColor &color);
    Q_INVOKABLE bool setCurveVisible(int curveId, bool visible);
    Q_INVOKABLE bool setCurveLocked(int curveId, bool locked);
    Q_INVOKABLE bool setNodeType(int curveId, int knot, int type);
    // The order k of a B-spline (2..10, at most its number of control points).
    Q_INVOKABLE bool setCurveOrder(int curveId, int order);
    // Splits a composite curve's segment at t (the shape stays); closes a composite curve.
    Q_INVOKABLE bool insertKnotOnSegment(int curveId, int segment, double t);
    Q_INVOKABLE bool closeCurve(int curveId);
    // Teaching views: new control points for a Bézier curve (degree reduction), and a Bézier curve
    // split at t into two curves, the second inserted after the first. One undo step each.
    bool setControlPoints(CurveId curveId, const std::vector<geo::Point> &points, const QString &text);
    bool splitBezier(CurveId curveId, double t);
    // Any curve split at u in (0, 1) of its whole parameter (segment floor(u·m) at its local
    // parameter, as the de Casteljau view runs): a Bézier curve into two Bézier curves; every other
    // kind first becomes its exact composite curve (pieces of degree 1 and 2 elevated, joints typed by
    // their continuity), then two of them — a closed curve one open curve from u round to u. One undo
    // step. Refused with a message where a piece is of degree above 3 (no composite curve is the same).
    bool splitCurve(CurveId curveId, double u);
    // Removes every curve and the background (after the UI asked with message 4); one undo step.
    Q_INVOKABLE void resetAll();
    // Appends curves (an import): one undo step; the last one is selected.
    void addCurves(std::vector<Curve> curves, const QString &text);
    // Appends one new curve (placed, typed or traced): one undo step, named `text` when given; the
    // curve is selected and its id answered. The view is not asked to show everything (addCurves is).
    CurveId appendCurve(Curve curve, const QString &text = {});

    // --- points ---
    // Adds a placed point before `index` (the table's "Add row"); deletes one ("Delete row").
    Q_INVOKABLE bool insertPoint(int curveId, int index, QPointF position);
    Q_INVOKABLE bool removePoint(int curveId, int index);
    // Typed coordinates: `rows` is a list of [x, y] texts in the UI language's number format (or
    // with a decimal point), one per defining point. Message 10 for empty or bad values; composite
    // handles keep the handle mode's constraint.
    Q_INVOKABLE bool applyCoordinates(int curveId, const QVariantList &rows);
    // The coordinates table's "OK": `edits` lists only the cells the user typed, as {row, x, y}
    // with x and y as typed; an axis left out keeps the full double it holds, whatever the table
    // shows of it. One undo step; message 10 for empty or bad values, message 18 for numbers beyond
    // the largest double.
    Q_INVOKABLE bool applyEdits(int curveId, const QVariantList &edits);
    // Moves the selected point by `delta` (world units), as the arrow keys do: one undo step each.
    // The curve's seam allowances follow on the Document's worker, never on this thread (a held key
    // auto-repeats; Document::beginStepEdit), in the undo and redo of the nudge too.
    Q_INVOKABLE bool nudgeSelected(QPointF delta);
    // Delete: the selected point if it can go (a placed point above the kind's minimum), otherwise
    // the selected curve.
    Q_INVOKABLE bool deleteSelection();
    // The table's "Add row": a point after the selected one (halfway to the next, or beyond the
    // last), or at the end; "Delete row": the selected placed point, within the kind's limits.
    Q_INVOKABLE bool addRowAfterSelection();
    Q_INVOKABLE bool deleteSelectedRow();

    // --- queries ---
    // The curve's points as text for the clipboard: label, x, y per line, tab separated, numbers in
    // the UI language's format with every digit (the shortest text that reads back as the same double).
    Q_INVOKABLE QString coordinatesText(int curveId) const;
    // The joints of a curve for the info panel: [{joint, level, angle (degrees), c1Jump}], at most `limit`.
    Q_INVOKABLE QVariantList jointReport(int curveId, int limit = 200) const;
    // Degree of a Bézier curve, or 3 for the cubic kinds; -1 for none.
    Q_INVOKABLE int degreeOf(int curveId) const;

private:
    // A row's new coordinates; an axis without a value keeps what the row holds.
    struct RowEdit
    {
        int row;
        std::optional<double> x, y;
    };
    [[nodiscard]] const Curve *find(int curveId) const;
    // The curve if it may change (message 13 for a locked one), else nullptr.
    [[nodiscard]] const Curve *editable(int curveId);
    // Applies `edit` to a copy of the curve and pushes the change as one undo step, its seam
    // allowances following as `follow` says.
    template <typename Edit>
    bool editCurve(int curveId, const QString &text, Edit edit, AllowancesFollow follow = AllowancesFollow::AtOnce);
    // Pushes the curve after a change of style or lock, which locked curves allow.
    bool replaceStyle(int curveId, Curve after, const QString &text);
    // Applies new positions of defining points in order, with the handle mode's rule; one undo step.
    bool moveRows(int curveId, const std::vector<RowEdit> &moves, const QString &text,
                  AllowancesFollow follow = AllowancesFollow::AtOnce);

    EditController *m_editor;
    Document *m_document;
};

} // namespace kontur
