// The document: the ordered curves the user works on. Every change goes through these few
// mutators, called by undo commands, and is announced with fine-grained signals.
#pragma once

#include "models/curve.h"

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class Document : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("The document belongs to an EditController.")
    Q_PROPERTY(int curveCount READ curveCount NOTIFY curveCountChanged)

public:
    explicit Document(QObject *parent = nullptr);
    Q_DISABLE_COPY_MOVE(Document)

    [[nodiscard]] int curveCount() const { return static_cast<int>(m_curves.size()); }
    [[nodiscard]] const Curve &curve(int index) const { return m_curves.at(static_cast<std::size_t>(index)); }
    [[nodiscard]] const std::vector<Curve> &curves() const { return m_curves; }
    [[nodiscard]] bool isValidPoint(int curve, int point) const;

    void insertCurve(int index, Curve curve);
    Curve takeCurve(int index);
    void setPoint(int curve, int point, const geo::Point &position);

Q_SIGNALS:
    void curveAboutToBeInserted(int index);
    void curveInserted(int index);
    void curveAboutToBeRemoved(int index);
    void curveRemoved(int index);
    void pointMoved(int curve, int point);
    void curveCountChanged();
    // Anything visible changed: the canvas repaints on this.
    void changed();

private:
    std::vector<Curve> m_curves;
};

} // namespace kontur
