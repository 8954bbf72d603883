// PieceMarkEdits: a garment piece's own marks as a pattern maker sets them by touch (io/piece.h):
// making a closed curve a piece, its size, quantity ("cut N") and material, the fold (mirror) line,
// the grainline by two points, notches on the seam (placed by a tap, dragged along it, of a kind and
// an angle) and drill holes. Each edit is one undo step on the EditController's stack (a drag of a
// mark one step); the rules are here, QML only binds and forwards taps in world coordinates.
#pragma once

#include "io/piece.h"
#include "models/document/curve.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class PieceMarkEdits : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // The selected curve: a closed curve that may become a piece (not a seam allowance, not locked),
    // and whether it is one; its marks as the panel shows them.
    Q_PROPERTY(bool canBePiece READ canBePiece NOTIFY stateChanged)
    Q_PROPERTY(bool isPiece READ isPiece NOTIFY stateChanged)
    Q_PROPERTY(QString size READ size NOTIFY stateChanged)
    Q_PROPERTY(int quantity READ quantity NOTIFY stateChanged)
    Q_PROPERTY(QString material READ material NOTIFY stateChanged)
    Q_PROPERTY(bool hasFold READ hasFold NOTIFY stateChanged)
    Q_PROPERTY(bool hasGrainline READ hasGrainline NOTIFY stateChanged)
    Q_PROPERTY(int notchCount READ notchCount NOTIFY stateChanged)
    Q_PROPERTY(int drillHoleCount READ drillHoleCount NOTIFY stateChanged)
    // The last refusal (empty: none); QML shows `message.text`, which follows a language switch.
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)

public:
    enum class Mark { None, Grainline, Fold, Notch, DrillHole };
    Q_ENUM(Mark)

    explicit PieceMarkEdits(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PieceMarkEdits)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);

    [[nodiscard]] bool canBePiece() const;
    [[nodiscard]] bool isPiece() const;
    [[nodiscard]] QString size() const;
    [[nodiscard]] int quantity() const;
    [[nodiscard]] QString material() const;
    [[nodiscard]] bool hasFold() const;
    [[nodiscard]] bool hasGrainline() const;
    [[nodiscard]] int notchCount() const;
    [[nodiscard]] int drillHoleCount() const;
    [[nodiscard]] Message message() const { return m_message.message(); }
    // The selected curve's marks (none when it is no piece).
    [[nodiscard]] std::optional<io::PieceMarks> marks() const;

    // --- the selected curve ---
    Q_INVOKABLE bool makePiece();
    Q_INVOKABLE bool removePiece();
    Q_INVOKABLE bool setSize(const QString &size);
    Q_INVOKABLE bool setQuantity(int quantity);
    // As typed: a whole number from 1 up (message otherwise; the number is never changed).
    Q_INVOKABLE bool setQuantityText(const QString &text);
    Q_INVOKABLE bool setMaterial(const QString &material);
    // The grainline or the fold line from (ax, ay) to (bx, by) in world coordinates; two points
    // closer than `minimum` (the touch radius in world units) are refused.
    Q_INVOKABLE bool setGrainline(double ax, double ay, double bx, double by, double minimum = 0.0);
    Q_INVOKABLE bool setFold(double ax, double ay, double bx, double by, double minimum = 0.0);
    // The fold along the seam segment (between two knots) nearest to (x, y).
    Q_INVOKABLE bool foldAlongSeam(double x, double y);
    // A notch where the seam is nearest to (x, y), square to it, of `kind` (io::NotchKind); its index.
    Q_INVOKABLE int addNotch(double x, double y, int kind = 0);
    // Notch `index` slid to the seam's point nearest (x, y); the steps of one drag share `dragSerial`.
    Q_INVOKABLE bool moveNotch(int index, double x, double y, int dragSerial = 0);
    Q_INVOKABLE bool setNotchKind(int index, int kind);
    Q_INVOKABLE bool setNotchAngle(int index, double degrees);
    Q_INVOKABLE int addDrillHole(double x, double y);
    Q_INVOKABLE bool moveDrillHole(int index, double x, double y, int dragSerial = 0);
    // The mark within `radius` of (x, y) (notches at their place on the seam, the grainline and the
    // fold line anywhere along them), nearest first: its Mark and index in `index`.
    [[nodiscard]] Mark markAt(const geo::Point &p, double radius, int &index) const;
    Q_INVOKABLE int markTypeAt(double x, double y, double radius) const;
    Q_INVOKABLE int markIndexAt(double x, double y, double radius) const;
    // Deletes the mark within `radius` of (x, y); false when there is none.
    Q_INVOKABLE bool deleteMarkAt(double x, double y, double radius);
    // A new drag serial for moveNotch / moveDrillHole.
    Q_INVOKABLE int beginDrag();

Q_SIGNALS:
    void editorChanged();
    void stateChanged();
    void messageChanged();

private:
    // The selected curve when it is a piece that may be edited (else a message and nullptr).
    [[nodiscard]] const Curve *editablePiece();
    [[nodiscard]] const Curve *selected() const;
    bool change(const Curve &curve, std::optional<io::PieceMarks> after, const QString &text, int dragSerial = 0);
    // A two-tap line of the piece (its grainline or fold), refused when not longer than `minimum`.
    bool setLine(std::optional<io::Segment> io::PieceMarks::*line, const io::Segment &s, double minimum,
                 const QString &text);

    QPointer<EditController> m_editor;
    ShownMessage m_message{this, [this] { Q_EMIT messageChanged(); }};
    int m_dragSerial = 0;
};

} // namespace kontur
