// PointListModel: one row per point of the selected curve (the seed's coordinates table): its
// defining points first, then the points derived from them.
#pragma once

#include <QAbstractListModel>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class Document;

// A number as the side panel shows it, in the UI language's format (QLocale's default): at most
// `decimals` decimals and 7 significant digits from 10^-decimals up to 1e9 (1,234.568, 12,345.68,
// 10,000,123), in exponent form with 3 significant digits beyond (1e+300, -1.23e-6); so a table
// cell never overflows (at most 12 narrow characters) and a tiny value never reads as 0. Shown values are
// rounded; stored ones never are. "—" for a value that is not finite.
[[nodiscard]] QString displayNumber(double value, int decimals);
// Every digit of a number, in the UI language's format without group separators: the shortest text
// that reads back as the same double (for editing a cell, and for the clipboard).
[[nodiscard]] QString exactNumber(double value);

// Not final: QML (Qt 6.4) derives from registered types.
class PointListModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The point list belongs to an EditController.")
    Q_PROPERTY(int curve READ curve NOTIFY curveChanged)

public:
    enum Role {
        XRole = Qt::UserRole + 1,
        YRole,
        PointRoleRole, // PointRole: control point, knot, handle, tangent end
        LabelRole,     // P<i> or C<i>
        EditableRole,  // false for derived points
        NodeTypeRole,  // composite knots: smooth, symmetric, corner; -1 otherwise
    };
    Q_ENUM(Role)

    explicit PointListModel(Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(PointListModel)

    [[nodiscard]] int curve() const { return m_curve; }
    // Shows the points of another curve (-1: none). Switching curves resets the model; edits never do.
    void setCurve(int curve);

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

Q_SIGNALS:
    void curveChanged();

private:
    // Brings the row count in line with the curve's: rows come and go at the end.
    void syncRowCount();

    Document *m_document;
    int m_curve = -1;
    int m_rows = 0; // the row count the views know
};

} // namespace kontur
