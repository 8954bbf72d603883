// TeachingPainter: draws what the TeachingController's current view shows (de Casteljau levels, the
// elevated polygon, compared curves, the curvature comb and joint marks) over the canvas. It maps
// world to item coordinates through the canvas's toScreen and repaints when the view or the scene
// changes. A QQuickPaintedItem, so it draws on the GPU backends and the software one alike.
#pragma once

#include "app/canvasoverlay.h"
#include "models/teaching/teachingcontroller.h"

#include <QColor>
#include <QPointer>
#include <QVariantList>

namespace kontur {

// Not final: QML (Qt 6.4) derives from registered types.
class TeachingPainter : public CanvasOverlay
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(kontur::TeachingController *teaching READ teaching WRITE setTeaching NOTIFY teachingChanged)
    // Colours of the construction levels (level k uses entry k - 1, cycling) and of compared curves.
    Q_PROPERTY(QVariantList levelColors MEMBER m_levelColors NOTIFY styleChanged)
    Q_PROPERTY(QVariantList palette MEMBER m_palette NOTIFY styleChanged)
    Q_PROPERTY(QColor markerColor MEMBER m_markerColor NOTIFY styleChanged)
    Q_PROPERTY(QColor halfColor MEMBER m_halfColor NOTIFY styleChanged)
    Q_PROPERTY(QColor elevatedColor MEMBER m_elevatedColor NOTIFY styleChanged)
    Q_PROPERTY(QColor combColor MEMBER m_combColor NOTIFY styleChanged)
    Q_PROPERTY(QColor jointColor MEMBER m_jointColor NOTIFY styleChanged)
    Q_PROPERTY(QColor weakJointColor MEMBER m_weakJointColor NOTIFY styleChanged)
    Q_PROPERTY(QColor labelBackground MEMBER m_labelBackground NOTIFY styleChanged)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY styleChanged)
    Q_PROPERTY(double pointRadius MEMBER m_pointRadius NOTIFY styleChanged)
    Q_PROPERTY(double fontPixelSize MEMBER m_fontPixelSize NOTIFY styleChanged)

public:
    explicit TeachingPainter(QQuickItem *parent = nullptr);
    Q_DISABLE_COPY_MOVE(TeachingPainter)

    [[nodiscard]] TeachingController *teaching() const { return m_teaching; }
    void setTeaching(TeachingController *teaching);

    void paint(QPainter *painter) override;

Q_SIGNALS:
    void teachingChanged();
    void styleChanged();

protected:
    [[nodiscard]] bool hasContent() const override;

private:
    [[nodiscard]] QColor colorAt(const QVariantList &list, int index, const QColor &fallback) const;

    QPointer<TeachingController> m_teaching;
    QVariantList m_levelColors;
    QVariantList m_palette;
    QColor m_markerColor{31, 111, 209};
    QColor m_halfColor{239, 108, 0};
    QColor m_elevatedColor{0, 140, 90};
    QColor m_combColor{200, 90, 0};
    QColor m_jointColor{0, 120, 60};
    QColor m_weakJointColor{200, 0, 0};
    QColor m_labelBackground{255, 255, 255, 220};
    double m_lineWidth = 2.0;
    double m_pointRadius = 4.5;
    double m_fontPixelSize = 13.0;
};

} // namespace kontur
