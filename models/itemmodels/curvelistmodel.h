// CurveListModel: one row per curve of the document, for the curve list panel.
#pragma once

#include "models/document/curve.h"

#include <QAbstractListModel>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class Document;

// Not final: QML (Qt 6.4) derives from registered types.
class CurveListModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The curve list belongs to an EditController.")

public:
    enum Role {
        NameRole = Qt::UserRole + 1,
        KindRole,
        KindNameRole,
        ColorRole,
        VisibleRole,
        LockedRole,
        ParameterizationRole, // -1 for kinds that use none
        PointCountRole,       // placed points: control points or knots
        LengthRole,           // to 1e-9 of the curve's size (its control polygons' length)
        FitRmsRole,           // fitted kinds; -1 otherwise
        FitMaxErrorRole,      // fitted kinds; -1 otherwise
        ContinuityRole,       // the weakest joint: "G0", "G1", "C1", "G2", "C2"; empty with no joints
        ProblemRole,          // true when the curve cannot be drawn (degenerate knots)
        SelectedRole,
        CurveIdRole, // the curve's id: what QML passes to CurveCommands and Selection
        DegreeRole,  // of the first segment: a Bézier curve's degree, 3 for the cubic kinds; -1 for none
    };
    Q_ENUM(Role)

    explicit CurveListModel(Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(CurveListModel)

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

    // The selected curve's row shows `selected`; it is held by id, so rows coming and going never
    // need it renumbered.
    void setSelected(CurveId curve);
    // Kind names are translated: refresh them after a language switch.
    void retranslate();

private:
    Document *m_document;
    CurveId m_selected = CurveId::None;
};

} // namespace kontur
