// The canvas's picture in screen coordinates: strokes and point markers, built once per frame
// and drawn either by the GPU path (triangles with an anti-aliasing fringe) or by QPainter.
#pragma once

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QSGGeometry>

#include <array>
#include <vector>

class QPainter;

namespace kontur {

struct Stroke
{
    std::vector<QPointF> points;
    QColor color;
    float width = 1.0F; // device-independent pixels
    bool closed = false;
};

struct Disc
{
    QPointF center;
    float radius = 1.0F;
    QColor color;
};

// A circle outline (a point marker's ring).
struct Ring
{
    QPointF center;
    float radius = 1.0F;
    float width = 1.0F;
    QColor color;
};

struct DisplayList
{
    std::vector<Stroke> strokes; // drawn in order, before the discs
    std::vector<Disc> discs;
    std::vector<Stroke> overlay; // drawn over the discs (tangent-end diamonds)
    std::vector<Ring> rings;     // drawn last (point rings over everything)

    void clear()
    {
        strokes.clear();
        discs.clear();
        overlay.clear();
        rings.clear();
    }
};

// `color` with its alpha replaced (0 to 1).
[[nodiscard]] inline QColor withAlpha(QColor color, double alpha)
{
    color.setAlphaF(static_cast<float>(alpha));
    return color;
}

// Splits a polyline into dashes of `dash` pixels separated by `gap` pixels.
[[nodiscard]] std::vector<std::vector<QPointF>> dashed(const std::vector<QPointF> &polyline, double dash, double gap);

// Software path: paints the list with an anti-aliased QPainter. Discs and rings are stamped from
// small pictures painted once per size and colour when the painter only translates.
void paint(const DisplayList &list, QPainter &painter);

// A fast anti-aliased stroke for many long polylines (the software layer): a stroke up to 4 px
// wide is drawn as one-pixel cosmetic lines side by side, half a pixel apart along the joins'
// normals, which QPainter draws an order of magnitude faster than a wide pen (round joins cost
// most). Wider strokes use the pen.
// `width` in the painter's units; `deviceScale`: device pixels per unit (the painter must only
// move and scale evenly).
void paintFastStroke(const std::vector<QPointF> &line, const QColor &color, double width, bool closed,
                     QPainter &painter, double deviceScale = 1.0);

// A colour premultiplied by its alpha and by `weight` (the coverage of a line thinner than a
// pixel, kept through a fainter colour), as 8-bit red, green, blue and alpha: what the GPU path's
// vertex colours hold.
[[nodiscard]] std::array<unsigned char, 4> premultipliedRgba(const QColor &color, double weight = 1.0);

// GPU path: strokes as triangles with per-vertex premultiplied colours; a one-pixel alpha ramp on
// every outer edge gives anti-aliasing without multisampling. (Discs and rings are quads drawn by
// MarkerNode's shaders.)
struct TriangleMesh
{
    std::vector<QSGGeometry::ColoredPoint2D> vertices;
    std::vector<quint32> indices;
};
void tessellateStrokes(const std::vector<Stroke> &strokes, TriangleMesh &mesh);

} // namespace kontur
