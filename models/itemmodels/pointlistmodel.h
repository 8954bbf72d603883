// PointListModel: one row per point of the selected curve (the seed's coordinates table): its
// defining points first, then the points derived from them.
#pragma once

#include "models/document/curve.h"

#include <QAbstractListModel>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class Document;

// Not final: QML (Qt 6.4) derives from registered types.
class PointListModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The point list belongs to an EditController.")
    // The id of the curve shown (0: none).
    Q_PROPERTY(int curve READ curveValue NOTIFY curveChanged)

public:
    enum Role {
        XRole = Qt::UserRole + 1,
        YRole,
        PointRoleRole, // PointRole: control point, knot, handle, tangent end
        LabelRole,     // P<i> or C<i>
        EditableRole,  // false for derived points
        NodeTypeRole,  // composite knots: smooth, symmetric, corner; -1 otherwise
        XTextRole,     // x as a cell shows it (displayNumber, 3 decimals), in the UI language
        YTextRole,
        XExactRole, // every digit of x (exactNumber): what a cell holds while edited
        YExactRole,
    };
    Q_ENUM(Role)

    explicit PointListModel(Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PointListModel)

    [[nodiscard]] CurveId curve() const { return m_curve; }
    [[nodiscard]] int curveValue() const { return static_cast<int>(m_curve); }
    // Shows the points of another curve (None: none). The rows both curves have stay (dataChanged of
    // every role), the others are removed or inserted at the end; nothing resets the model.
    void setCurve(CurveId curve);
    // The number texts follow the UI language: announce them again after a switch.
    void retranslate();

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

Q_SIGNALS:
    void curveChanged();

private:
    // Brings the row count in line with the curve's: rows come and go at the end.
    void syncRowCount();
    [[nodiscard]] const Curve *shown() const;

    Document *m_document;
    CurveId m_curve = CurveId::None;
    int m_rows = 0; // the row count the views know
};

} // namespace kontur
