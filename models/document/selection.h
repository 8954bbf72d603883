// Selection: which curve (by id) and which of its rows the user picked. QML binds to its
// properties; the canvas, the side panel, the coordinates table and the teaching views follow its
// signals. It holds an id, so curves coming, going or moving never need it renumbered: its row is
// looked up when asked.
#pragma once

#include "models/document/curve.h"

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class Document;

// Not final: QML (Qt 6.4) derives from registered types.
class Selection : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The selection belongs to an EditController.")
    // The selected curve's id (0: none) and its row in the document (-1: none).
    Q_PROPERTY(int curveId READ curveIdValue NOTIFY curveChanged)
    Q_PROPERTY(int curveRow READ curveRow NOTIFY curveRowChanged)
    Q_PROPERTY(bool hasCurve READ hasCurve NOTIFY curveChanged)
    // The selected row of the curve's points (-1: none) and, for a composite's knot or handle, or
    // another kind's placed point, the placed point it belongs to (-1 otherwise).
    Q_PROPERTY(int point READ point NOTIFY pointChanged)
    Q_PROPERTY(int knot READ knot NOTIFY pointChanged)
    // The node type of the composite knot `knot` (a NodeType value), -1 for other rows and kinds.
    Q_PROPERTY(int nodeType READ nodeType NOTIFY nodeTypeChanged)

public:
    explicit Selection(Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(Selection)

    [[nodiscard]] CurveId curveId() const { return m_curve; }
    [[nodiscard]] int curveIdValue() const { return static_cast<int>(m_curve); }
    [[nodiscard]] int curveRow() const;
    [[nodiscard]] bool hasCurve() const { return m_curve != CurveId::None; }
    [[nodiscard]] int point() const { return m_point; }
    [[nodiscard]] int knot() const;
    [[nodiscard]] int nodeType() const;
    // The selected curve, or nullptr.
    [[nodiscard]] const Curve *curve() const;

    // Selects a curve and one of its rows (-1: the curve alone); an id the document does not hold
    // selects nothing, a row it does not have selects the curve alone.
    void select(CurveId curve, int point = -1);
    Q_INVOKABLE void selectCurve(int curveId) { select(static_cast<CurveId>(curveId)); }
    Q_INVOKABLE void selectPoint(int curveId, int point) { select(static_cast<CurveId>(curveId), point); }
    // The list views know rows: selects the curve at `row` of the document.
    Q_INVOKABLE void selectRow(int row);
    Q_INVOKABLE void clear() { select(CurveId::None); }

Q_SIGNALS:
    void curveChanged();
    void curveRowChanged();
    void pointChanged();
    void nodeTypeChanged();
    // Any of the above.
    void changed();

private:
    void followDocument();
    void announce(CurveId oldCurve, int oldPoint, int oldRow, int oldNodeType);

    Document *m_document;
    CurveId m_curve = CurveId::None;
    int m_point = -1;
    // What was announced last, so that a change of row or node type made by the document (undo, a
    // curve moved above this one) is announced exactly once.
    int m_row = -1;
    int m_nodeType = -1;
};

} // namespace kontur
