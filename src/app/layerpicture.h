// LayerPicture: the canvas's cached picture of the curves other than the selected one, painted
// with QPainter (Qt Quick's software backend, and OpenGL where it rasterizes on the processor).
// It remembers where each curve went, so that when only a few curves changed (a selection
// change swaps two: the one selected now leaves the picture, the one selected before returns)
// only their pixels are painted again; a whole picture is painted in horizontal bands on the
// machine's cores. Both give the same pixels as painting the whole picture on one thread
// (tst_layerpicture).
#pragma once

#include "app/viewstate.h"

#include <QColor>
#include <QImage>
#include <QRect>
#include <QRegion>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

class QPainter;

namespace kontur {

// A curve drawn into the layer: `key` names it among the layer's curves (its document row).
struct LayerCurve
{
    std::size_t key = 0;
    std::shared_ptr<const std::vector<geo::Point>> world;
    QColor color;
    bool closed = false;
};

class LayerPicture
{
public:
    // Where the picture is: the view it shows (its size without the margin), `margin` item
    // pixels around it, `scale` picture pixels per item pixel; and the curves' width in item pixels.
    struct Frame
    {
        ViewState view;
        double margin = 0.0;
        double scale = 1.0;
        float curveWidth = 2.0F;
        bool operator==(const Frame &) const = default;
    };
    // Paints what lies under the curves (the grid) into the picture; the painter is in picture
    // pixels and clipped to what is painted anew.
    using Background = std::function<void(QPainter &)>;

    enum class Painted { Nothing, Part, Whole };

    // Brings the picture up to `curves` (sorted by key) at `frame`: nothing when nothing changed,
    // only the changed curves' pixels when the frame and the background are the same and they
    // cover less than a third of it, else the whole picture. `bands` > 0 forces the number of
    // bands a whole picture is painted in (tests); 0 chooses from the cores and the work.
    Painted update(const std::vector<LayerCurve> &curves, const Frame &frame, const Background &background,
                   bool backgroundChanged, int bands = 0);

    [[nodiscard]] const QImage &image() const { return m_image; }
    // The pixels painted anew by the last update (empty when nothing was).
    [[nodiscard]] const QRegion &lastPainted() const { return m_lastPainted; }
    // Forgets the picture: the next update paints it whole.
    void clear();

private:
    // A curve as painted: what it was painted from, and the pixels it may have touched.
    struct Record
    {
        std::size_t key = 0;
        std::shared_ptr<const std::vector<geo::Point>> world;
        QRgb color = 0;
        bool closed = false;
        QRect bounds;
        [[nodiscard]] bool sameLook(const LayerCurve &curve) const
        {
            return key == curve.key && world == curve.world && color == curve.color.rgba() && closed == curve.closed;
        }
    };

    // The curve's line in picture pixels and the pixels its stroke may touch.
    void line(const LayerCurve &curve, std::vector<QPointF> &line, QRect &bounds) const;
    void paintWhole(const std::vector<LayerCurve> &curves, const Background &background, int bands);
    bool paintPart(const std::vector<LayerCurve> &curves, const Background &background);

    QImage m_image;
    Frame m_frame;
    bool m_valid = false;
    std::vector<Record> m_records;
    QRegion m_lastPainted;
};

} // namespace kontur
