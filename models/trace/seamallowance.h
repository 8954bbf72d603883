// SeamAllowance: the seam allowance of the selected curve (issue #22, Trace menu "Seam allowance…").
// It makes a linked offset curve (Curve::seam, kept up to date by the Document), changes an existing
// allowance's settings, or detaches it into a free curve: one undo step each. QML shows the settings
// of the selected allowance (or the last used ones, 1 cm at first, in the document's units) and
// passes typed texts, parsed here in the UI language's number format.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/text/messages.h"

#include <QObject>
#include <QPointer>
#include <QVariant>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class SeamAllowance : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::EditController *editor READ editor WRITE setEditor NOTIFY editorChanged)
    // A curve with segments is selected.
    Q_PROPERTY(bool available READ available NOTIFY stateChanged)
    // The selected curve is a linked seam allowance (its settings are shown and changed).
    Q_PROPERTY(bool isAllowance READ isAllowance NOTIFY stateChanged)
    // The curve the sides refer to (the allowance's source, or the selected curve) is closed: the
    // sides read Outside / Inside, else Left / Right.
    Q_PROPERTY(bool closed READ closed NOTIFY stateChanged)
    Q_PROPERTY(QString units READ units NOTIFY stateChanged)
    // The settings shown: the selected allowance's, else the ones used last (defaults at first).
    Q_PROPERTY(QString distanceText READ distanceText NOTIFY stateChanged)
    Q_PROPERTY(QString miterLimitText READ miterLimitText NOTIFY stateChanged)
    Q_PROPERTY(int side READ side NOTIFY stateChanged)
    Q_PROPERTY(int join READ join NOTIFY stateChanged)
    // Why the last Add or Apply was refused (empty after a success or a new selection), in the current
    // language: the dialog shows it next to its fields, where the message line may be covered.
    Q_PROPERTY(QString refusal READ refusal NOTIFY refusalChanged)

public:
    // The QML values of side and join: geo::OffsetSide and geo::OffsetJoin in their order.
    enum Side { Outside, Inside, Left, Right };
    Q_ENUM(Side)
    enum Join { Miter, Bevel, Round };
    Q_ENUM(Join)

    explicit SeamAllowance(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(SeamAllowance)

    [[nodiscard]] EditController *editor() const { return m_editor; }
    void setEditor(EditController *editor);
    [[nodiscard]] bool available() const;
    [[nodiscard]] bool isAllowance() const;
    [[nodiscard]] bool closed() const;
    [[nodiscard]] QString units() const;
    [[nodiscard]] QString distanceText() const;
    [[nodiscard]] QString miterLimitText() const;
    [[nodiscard]] int side() const;
    [[nodiscard]] int join() const;
    [[nodiscard]] QString refusal() const { return m_refusal.text(); }

    // Adds the allowance of the selected curve (selected afterwards); one undo step. Message 10 for a
    // distance that is not a positive number, a message when no allowance fits.
    Q_INVOKABLE bool create(const QVariant &distance, int side, int join, const QVariant &miterLimit);
    // Changes the selected allowance's settings; one undo step (none when nothing changes).
    Q_INVOKABLE bool apply(const QVariant &distance, int side, int join, const QVariant &miterLimit);
    // The selected allowance becomes a free composite curve (its shape stays); one undo step.
    Q_INVOKABLE bool detach();

Q_SIGNALS:
    void editorChanged();
    void stateChanged();
    void refusalChanged();

private:
    [[nodiscard]] const Curve *selected() const;
    [[nodiscard]] geo::OffsetOptions shown() const;
    // Typed settings on top of `base`; false (with a message) when a number is not valid.
    [[nodiscard]] bool read(const QVariant &distance, int side, int join, const QVariant &miterLimit,
                            geo::OffsetOptions &out);
    // Shows why an offset was refused (the message line and `refusal`), or clears it (None).
    void refuse(Message message);

    QPointer<EditController> m_editor;
    std::optional<geo::OffsetOptions> m_last; // the settings used last, in m_lastUnits
    QString m_lastUnits;
    Message m_refusal;
    CurveId m_refusalCurve = CurveId::None; // the curve selected when m_refusal was set
};

} // namespace kontur
