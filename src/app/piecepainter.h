// PiecePainter: a garment piece's marks on the canvas and their touch editing (io/piece.h,
// PieceMarkEdits). It draws every visible piece's grainline (a double-headed arrow), notches (a
// short mark across the seam: a slit, a V or a castle), drill holes (a ring with a cross) and fold
// line (dash-dotted); and while a tool is chosen it takes one finger, the stylus or the left button:
// Grainline and Fold by two taps (the first shown until the second), Notch by a tap on the seam (a
// press on a notch drags it along the seam), Drill hole by a tap, Delete by a tap on a mark. Two
// fingers are left to the canvas (zoom and pan). Seam by a tap on a seam chooses it for its own
// allowance width (SeamWidths), drawn wide in the highlight colour. A QQuickPaintedItem, as the other
// overlays.
#pragma once

#include "app/canvasoverlay.h"
#include "models/controllers/piecemarks.h"
#include "models/controllers/seamwidths.h"

#include <QColor>
#include <QPointer>

#include <optional>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class PiecePainter : public CanvasOverlay
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::PieceMarkEdits *marks READ marks WRITE setMarks NOTIFY marksChanged)
    Q_PROPERTY(kontur::SeamWidths *seams READ seams WRITE setSeams NOTIFY marksChanged)
    Q_PROPERTY(QColor seamColor MEMBER m_seamColor NOTIFY styleChanged)
    Q_PROPERTY(Tool tool READ tool WRITE setTool NOTIFY toolChanged)
    // The notch kind a new notch gets (io::NotchKind: 0 slit, 1 V, 2 castle).
    Q_PROPERTY(int notchKind MEMBER m_notchKind NOTIFY toolChanged)
    // The first point of a grainline or fold while the second is awaited.
    Q_PROPERTY(bool pending READ pending NOTIFY pendingChanged)
    Q_PROPERTY(QColor markColor MEMBER m_markColor NOTIFY styleChanged)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY styleChanged)

public:
    enum class Tool { None, Grainline, Fold, Notch, DrillHole, Delete, Seam };
    Q_ENUM(Tool)

    explicit PiecePainter(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PiecePainter)

    [[nodiscard]] PieceMarkEdits *marks() const { return m_marks; }
    void setMarks(PieceMarkEdits *marks);
    [[nodiscard]] SeamWidths *seams() const { return m_seams; }
    void setSeams(SeamWidths *seams);
    [[nodiscard]] Tool tool() const { return m_tool; }
    void setTool(Tool tool);
    [[nodiscard]] bool pending() const { return m_first.has_value(); }

    void paint(QPainter *painter) override;

Q_SIGNALS:
    void marksChanged();
    void toolChanged();
    void pendingChanged();
    void styleChanged();

protected:
    [[nodiscard]] bool hasContent() const override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void touchEvent(QTouchEvent *event) override;

private:
    void updateInput();
    [[nodiscard]] QPointF world(QPointF item) const;
    [[nodiscard]] double hitRadius() const;
    void pressed(QPointF position);
    void moved(QPointF position);
    void released(QPointF position);
    void tapped(QPointF position);
    void paintPiece(QPainter *painter, const Curve &curve) const;
    void paintSeam(QPainter *painter) const;

    QPointer<PieceMarkEdits> m_marks;
    QPointer<SeamWidths> m_seams;
    QColor m_seamColor{255, 143, 0};
    Tool m_tool = Tool::None;
    int m_notchKind = 0;
    std::optional<QPointF> m_first; // world
    QColor m_markColor{123, 31, 162};
    double m_lineWidth = 2.0;
    // The pointer: where it went down (item), whether it moved beyond a tap, the notch it drags.
    QPointF m_press;
    QPointF m_last;
    bool m_down = false;
    bool m_moved = false;
    int m_dragNotch = -1;
    int m_dragSerial = 0;
    bool m_touching = false;
};

} // namespace kontur
