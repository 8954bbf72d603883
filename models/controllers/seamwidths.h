// SeamWidths: a garment piece's seam allowance per seam, set by touch (issue #44). A seam is the
// piece's outline between two corner knots (geometry/seams.h); tapping one in the piece bar's Seam
// allowance tool selects it, and the bar shows its width with − / + steps of 0.5 cm and a field to
// type it. The widths are part of the piece (io::PieceMarks::seamWidths), each change one undo step;
// the Document computes the piece's allowance again from them. The rules are here; QML binds.
#pragma once

#include "geometry/piecewise.h"
#include "models/document/commands.h"
#include "models/document/curve.h"
#include "models/text/shownmessage.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QtQml/qqmlregistration.h>

#include <optional>

namespace kontur {

class EditController;

// Not final: QML (Qt 6.4) derives from registered types.
class SeamWidths : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // The selected piece's seams, the one chosen (-1: none) and its width as the bar shows it, in the
    // document's units; whether it has a width of its own (else the allowance's).
    Q_PROPERTY(int seamCount READ seamCount NOTIFY stateChanged)
    Q_PROPERTY(int seam READ seam NOTIFY stateChanged)
    Q_PROPERTY(QString widthText READ widthText NOTIFY stateChanged)
    Q_PROPERTY(bool ownWidth READ ownWidth NOTIFY stateChanged)
    // The chosen seam is a hem: its allowance's corners are turned back (io::PieceMarks::hems).
    Q_PROPERTY(bool hem READ hem NOTIFY stateChanged)
    Q_PROPERTY(QString units READ units NOTIFY stateChanged)
    // The step of − and + (0.5 cm in the document's units) as the bar shows it.
    Q_PROPERTY(QString stepText READ stepText NOTIFY stateChanged)
    // The last refusal (empty: none); QML shows `message.text`, which follows a language switch.
    Q_PROPERTY(kontur::Message message READ message NOTIFY messageChanged)

public:
    explicit SeamWidths(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(SeamWidths)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);

    [[nodiscard]] int seamCount() const;
    [[nodiscard]] int seam() const { return m_seam; }
    [[nodiscard]] QString widthText() const;
    [[nodiscard]] bool ownWidth() const;
    [[nodiscard]] bool hem() const;
    [[nodiscard]] QString units() const;
    [[nodiscard]] QString stepText() const;
    [[nodiscard]] Message message() const { return m_message.message(); }
    // The chosen seam's width (the allowance's where it has none of its own); none without a seam.
    [[nodiscard]] std::optional<double> width() const;
    [[nodiscard]] double step() const;
    // The chosen seam of the selected piece as a curve (for the canvas to highlight); none without one.
    [[nodiscard]] std::optional<geo::PiecewiseBezier> seamShape() const;

    // The seam of the selected piece nearest (x, y) in world units, when within `radius`: chosen.
    Q_INVOKABLE bool selectSeamAt(double x, double y, double radius);
    Q_INVOKABLE bool selectSeam(int seam);
    // The chosen seam's width one step (0.5 cm) wider (direction > 0) or narrower, not below 0; one
    // undo step each. The allowance follows on the Document's worker, never on this thread (the
    // steps are tapped fast; Document::beginStepEdit), in the undo and redo of the step too.
    Q_INVOKABLE bool stepWidth(int direction);
    // As typed, in the UI language's number format (or with a decimal point); 0 and up.
    Q_INVOKABLE bool setWidthText(const QString &text);
    Q_INVOKABLE bool setWidth(double width);
    // The chosen seam back to the allowance's own width.
    Q_INVOKABLE bool resetWidth();
    // The chosen seam a hem (turned-back corners) or not.
    Q_INVOKABLE bool setHem(bool hem);

Q_SIGNALS:
    void editorChanged();
    void stateChanged();
    void messageChanged();

private:
    [[nodiscard]] const Curve *piece() const;
    // The selected piece's seam allowance (a curve linked to it), if it has one.
    [[nodiscard]] const Curve *allowance() const;
    // Seam k's new width (none: the allowance's own), one undo step.
    bool change(std::optional<double> width, AllowancesFollow follow = AllowancesFollow::AtOnce);
    // The piece's new marks, one undo step; refused when the allowance they give cannot be made (found
    // out at once; `Later`: on the worker, the message shown when it has, the step kept).
    bool push(const Curve &piece, const Curve &allowance, io::PieceMarks marks, const QString &text,
              AllowancesFollow follow = AllowancesFollow::AtOnce);
    // The selected piece and its allowance with a seam chosen (else a message and false).
    bool editable(const Curve *&piece, const Curve *&allowance);

    QPointer<EditController> m_editor;
    CurveId m_piece = CurveId::None;
    int m_seam = -1;
    ShownMessage m_message{this, [this] { Q_EMIT messageChanged(); }};
};

} // namespace kontur
