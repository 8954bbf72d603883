// PieceEdits: the edits that finish a traced pattern piece by touch — extend a curve by a new stroke,
// join two curves, close at a corner, make a segment a line, delete a knot, set a node type, simplify
// to a tolerance. The rules are here and in geometry/compositeedit.h; each edit is one undo step on
// the EditController's stack. QML binds the can* properties to its actions' enabled state.
#pragma once

#include "models/document/curve.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class PieceEdits : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // What applies to the selection now (an editable composite curve, with a knot or handle selected
    // for the knot and segment edits).
    Q_PROPERTY(bool canEditKnot READ canEditKnot NOTIFY stateChanged)
    Q_PROPERTY(bool canDeleteKnot READ canDeleteKnot NOTIFY stateChanged)
    Q_PROPERTY(bool canMakeLine READ canMakeLine NOTIFY stateChanged)
    Q_PROPERTY(bool canClose READ canClose NOTIFY stateChanged)
    Q_PROPERTY(bool canJoin READ canJoin NOTIFY stateChanged)
    Q_PROPERTY(bool canSimplify READ canSimplify NOTIFY stateChanged)
    // The last refusal (empty: none); QML shows `message.text`, which follows a language switch.
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)

public:
    // The joint of a join or close is a corner where the tangents turn by more than this (degrees).
    static constexpr double cornerAngle = 30.0;

    explicit PieceEdits(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PieceEdits)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);

    [[nodiscard]] bool canEditKnot() const;
    [[nodiscard]] bool canDeleteKnot() const;
    [[nodiscard]] bool canMakeLine() const;
    [[nodiscard]] bool canClose() const;
    [[nodiscard]] bool canJoin() const;
    [[nodiscard]] bool canSimplify() const;
    [[nodiscard]] Message message() const { return m_message.message(); }

    // --- the selection's knot or segment ---
    // The segment a selected row names: a handle's own segment; a knot's outgoing one (the last knot
    // of an open curve: its incoming one). -1 without a composite curve's row selected.
    [[nodiscard]] int selectedSegment() const;
    Q_INVOKABLE bool makeLine(int curveId, int segment);
    Q_INVOKABLE bool makeSelectedLine();
    Q_INVOKABLE bool deleteSelectedKnot();
    // A geo::NodeType value for the selected knot (or the knot of the selected handle).
    Q_INVOKABLE bool setSelectedNodeType(int type);

    // --- whole curves; `mergeDistance` (world units) is how near two ends count as one point (the
    // touch radius at the zoom the user sees) ---
    Q_INVOKABLE bool closeCurve(int curveId, double mergeDistance);
    Q_INVOKABLE bool closeSelected(double mergeDistance);
    // The selected curve joined with the open composite curve whose end is nearest to one of its
    // ends (reversed as needed): the selected curve keeps its id and style, the other one goes.
    Q_INVOKABLE bool joinSelected(double mergeDistance);
    Q_INVOKABLE bool joinCurves(int firstId, int secondId, double mergeDistance);
    Q_INVOKABLE bool simplify(int curveId, double tolerance);
    // The tolerance as typed, in the UI language's number format (or with a decimal point).
    Q_INVOKABLE bool simplifyText(int curveId, const QString &tolerance);
    // A proposed tolerance for the selected curve: a thousandth of its size, as the UI shows numbers.
    Q_INVOKABLE QString suggestedToleranceText() const;

    // A new traced curve: appended to the end of the nearest open, editable composite curve whose end
    // is within `radius` of one of the new curve's ends (one undo step, the old part unchanged), or
    // else added as a new curve. Answers the id of the curve that holds it.
    static CurveId addOrExtend(EditController *editor, Curve curve, double radius, const QString &addText);

Q_SIGNALS:
    void editorChanged();
    void stateChanged();
    void messageChanged();

private:
    [[nodiscard]] const Curve *editableComposite(int curveId, bool open);

    QPointer<EditController> m_editor;
    ShownMessage m_message{this, [this] { Q_EMIT messageChanged(); }};
};

} // namespace kontur
