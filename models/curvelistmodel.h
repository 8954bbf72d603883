// CurveListModel: one row per curve of the document, for the curve list panel.
#pragma once

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
        PointCountRole,
        SelectedRole,
    };
    Q_ENUM(Role)

    explicit CurveListModel(Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(CurveListModel)

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

    void setSelectedRow(int row);
    // Kind names are translated: refresh them after a language switch.
    void retranslate();

private:
    Document *m_document;
    int m_selected = -1;
};

} // namespace kontur
