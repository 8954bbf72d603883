// SelectedCurveModel: the selected curve's row of the curve list, as a model of one row (none when
// nothing is selected). The side panel's settings read the curve's roles from it as a delegate's
// required properties, so they follow every dataChanged of that row, and nothing in QML copies rows.
// A change of selection keeps the row and announces new data (the panel's controls stay, no flicker).
#pragma once

#include "models/document/curve.h"

#include <QAbstractListModel>
#include <QtQml/qqmlregistration.h>

namespace kontur {

class CurveListModel;
class Document;

// Not final: QML (Qt 6.4) derives from registered types.
class SelectedCurveModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The selected curve's model belongs to an EditController.")

public:
    SelectedCurveModel(CurveListModel *curves, Document *document, QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(SelectedCurveModel)

    void setCurve(CurveId curve);
    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QHash<int, QByteArray> roleNames() const override;

private:
    CurveListModel *m_curves;
    Document *m_document;
    CurveId m_curve = CurveId::None;
};

} // namespace kontur
