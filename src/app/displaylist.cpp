// Drawing the display list: QPainter for the software backend, triangles for the GPU backend.
#include "app/displaylist.h"

#include <QLineF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace kontur {

std::vector<std::vector<QPointF>> dashed(const std::vector<QPointF> &polyline, double dash, double gap)
{
    std::vector<std::vector<QPointF>> dashes;
    if (polyline.size() < 2 || dash <= 0.0 || gap < 0.0)
        return dashes;
    bool on = true;
    double left = dash; // length left in the current dash or gap
    std::vector<QPointF> current{polyline.front()};
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
        QPointF a = polyline[i];
        const QPointF b = polyline[i + 1];
        double length = QLineF(a, b).length();
        while (length > 0.0) {
            const double step = std::min(left, length);
            const QPointF p = a + (b - a) * (step / length);
            if (on)
                current.push_back(p);
            left -= step;
            length -= step;
            a = p;
            if (left <= 0.0) {
                if (on && current.size() >= 2)
                    dashes.push_back(std::move(current));
                current.clear();
                on = !on;
                left = on ? dash : gap;
                if (on)
                    current.push_back(a);
            }
        }
    }
    if (on && current.size() >= 2)
        dashes.push_back(std::move(current));
    return dashes;
}

namespace {

QPointF unitNormal(QPointF from, QPointF to)
{
    const QPointF d = to - from;
    const double length = std::hypot(d.x(), d.y());
    return length > 0.0 ? QPointF(-d.y() / length, d.x() / length) : QPointF();
}

// `deviceScale` > 0: device pixels per unit when the painter only moves and scales evenly, which
// allows the fast stroke for opaque lines; translucent ones (the halo) would darken where the fast
// stroke's lines overlap, so they keep the pen (bevel joins: half the cost of round ones).
void paintStroke(const Stroke &stroke, QPainter &painter, double deviceScale)
{
    if (stroke.points.size() < 2)
        return;
    if (deviceScale > 0.0 && stroke.color.alpha() == 255 && stroke.width * deviceScale <= 4.0) {
        paintFastStroke(stroke.points, stroke.color, stroke.width, stroke.closed, painter, deviceScale);
        return;
    }
    const bool translucent = stroke.color.alpha() < 255;
    QPen pen(stroke.color, stroke.width, Qt::SolidLine, translucent ? Qt::FlatCap : Qt::RoundCap,
             translucent ? Qt::BevelJoin : Qt::RoundJoin);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    const QPolygonF polygon(QList<QPointF>(stroke.points.begin(), stroke.points.end()));
    if (stroke.closed)
        painter.drawPolygon(polygon);
    else
        painter.drawPolyline(polygon);
}

} // namespace

void paintFastStroke(const std::vector<QPointF> &line, const QColor &color, double width, bool closed,
                     QPainter &painter, double deviceScale)
{
    // Widths and spacing in device pixels, offsets in the painter's units.
    const double unit = 1.0 / deviceScale;
    width *= deviceScale;
    const std::size_t n = line.size();
    if (n < 2)
        return;
    painter.setBrush(Qt::NoBrush);
    if (width > 4.0) {
        painter.setPen(QPen(color, width * unit, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        const QPolygonF polygon(QList<QPointF>(line.begin(), line.end()));
        if (closed)
            painter.drawPolygon(polygon);
        else
            painter.drawPolyline(polygon);
        return;
    }
    QPen pen(color, std::min(width, 1.0));
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::FlatCap);
    painter.setPen(pen);
    // One-pixel lines every half pixel across the width: a w-pixel stroke takes 2w - 1 of them
    // (three for the usual two pixels), dense enough that the middle is fully covered.
    const int passes = std::max(1, static_cast<int>(std::ceil(2.0 * width - 1.0 - 1e-9)));
    if (passes == 1) {
        painter.drawPolyline(line.data(), static_cast<int>(n));
        if (closed)
            painter.drawLine(line.back(), line.front());
        return;
    }
    // Per point: the miter offset (unit normal over the cosine of half the turn, at most 2×).
    std::vector<QPointF> miter(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasPrev = i > 0 || closed;
        const bool hasNext = i + 1 < n || closed;
        const QPointF nIn = hasPrev ? unitNormal(line[(i + n - 1) % n], line[i]) : QPointF();
        const QPointF nOut = hasNext ? unitNormal(line[i], line[(i + 1) % n]) : QPointF();
        QPointF m = nIn + nOut;
        double length = std::hypot(m.x(), m.y());
        if (length < 1e-9) {
            m = hasNext ? nOut : nIn;
            length = 1.0;
        }
        m /= length;
        const QPointF ref = hasNext ? nOut : nIn;
        miter[i] = m / std::max(m.x() * ref.x() + m.y() * ref.y(), 0.5);
    }
    // Overlapping anti-aliased lines blend (1 - (1 - a)(1 - b) < a + b): spread them 20 % wider
    // than end to end, which gives the wide pen's ink within 7 % on curves (tst_canvasrender).
    const double spacing = passes > 1 ? 1.2 * (width - 1.0) / (passes - 1) * unit : 0.0;
    std::vector<QPointF> shifted(n);
    for (int k = 0; k < passes; ++k) {
        const double offset = (k - (passes - 1) / 2.0) * spacing;
        for (std::size_t i = 0; i < n; ++i)
            shifted[i] = line[i] + miter[i] * offset;
        painter.drawPolyline(shifted.data(), static_cast<int>(n));
        if (closed)
            painter.drawLine(shifted.back(), shifted.front());
    }
}

namespace {

// A marker picture: a filled disc (width 0) or a ring, centred in a square of device pixels.
const QImage &markerSprite(float radius, float width, const QColor &color, double scale)
{
    struct Entry
    {
        float radius, width;
        QRgb color;
        double scale;
        QImage image;
    };
    thread_local std::vector<Entry> cache;
    for (const Entry &e : cache)
        if (e.radius == radius && e.width == width && e.color == color.rgba() && e.scale == scale)
            return e.image;
    if (cache.size() >= 64)
        cache.erase(cache.begin());
    const double half = radius + width / 2.0 + 1.0; // logical pixels from the centre to the edge
    const int side = static_cast<int>(std::ceil(2.0 * half * scale));
    QImage image(side, side, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    {
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.scale(scale, scale);
        const QPointF centre(side / scale / 2.0, side / scale / 2.0);
        if (width <= 0.0F) {
            p.setPen(Qt::NoPen);
            p.setBrush(color);
        } else {
            p.setPen(QPen(color, width));
            p.setBrush(Qt::NoBrush);
        }
        p.drawEllipse(centre, radius, radius);
    }
    image.setDevicePixelRatio(scale);
    cache.push_back({radius, width, color.rgba(), scale, std::move(image)});
    return cache.back().image;
}

} // namespace

std::array<unsigned char, 4> premultipliedRgba(const QColor &color, double weight)
{
    const double a = color.alphaF() * weight;
    const auto channel = [a](double value) { return static_cast<unsigned char>(std::lround(value * a)); };
    return {channel(color.red()), channel(color.green()), channel(color.blue()), channel(255.0)};
}

void paint(const DisplayList &list, QPainter &painter)
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Stamps and fast strokes when the painter only moves and scales evenly (the usual case);
    // drawn shapes otherwise.
    const QTransform t = painter.combinedTransform();
    const bool stamps = t.type() <= QTransform::TxScale && std::abs(t.m11() - t.m22()) < 1e-9 && t.m11() > 0.0;
    const double scale = stamps ? t.m11() * painter.device()->devicePixelRatioF() : 1.0;
    const double strokeScale = stamps ? scale : 0.0;
    for (const Stroke &stroke : list.strokes)
        paintStroke(stroke, painter, strokeScale);
    const auto stamp = [&](QPointF center, float radius, float width, const QColor &color) {
        const QImage &sprite = markerSprite(radius, width, color, scale);
        const double half = sprite.width() / scale / 2.0;
        painter.drawImage(center - QPointF(half, half), sprite);
    };
    painter.setPen(Qt::NoPen);
    for (const Disc &disc : list.discs) {
        if (stamps) {
            stamp(disc.center, disc.radius, 0.0F, disc.color);
            continue;
        }
        painter.setBrush(disc.color);
        painter.drawEllipse(disc.center, disc.radius, disc.radius);
    }
    for (const Stroke &stroke : list.overlay)
        paintStroke(stroke, painter, strokeScale);
    for (const Ring &ring : list.rings) {
        if (stamps) {
            stamp(ring.center, ring.radius, ring.width, ring.color);
            continue;
        }
        painter.setPen(QPen(ring.color, ring.width));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(ring.center, ring.radius, ring.radius);
    }
}

namespace {

QSGGeometry::ColoredPoint2D vertex(QPointF p, const QColor &color, float alpha)
{
    // Premultiplied alpha, as QSGVertexColorMaterial expects.
    const std::array<unsigned char, 4> rgba = premultipliedRgba(color, alpha);
    QSGGeometry::ColoredPoint2D v;
    v.set(static_cast<float>(p.x()), static_cast<float>(p.y()), rgba[0], rgba[1], rgba[2], rgba[3]);
    return v;
}

void tessellateStroke(const Stroke &stroke, TriangleMesh &mesh)
{
    // Drop repeated points: they have no direction.
    std::vector<QPointF> pts;
    pts.reserve(stroke.points.size());
    for (const QPointF &p : stroke.points)
        if (pts.empty() || QLineF(pts.back(), p).length() > 1e-6)
            pts.push_back(p);
    if (stroke.closed && pts.size() > 2 && QLineF(pts.back(), pts.front()).length() <= 1e-6)
        pts.pop_back();
    const std::size_t n = pts.size();
    if (n < 2)
        return;

    // Four rails along the line: outer edge (transparent), inner edge (opaque), both sides.
    const float half = std::max(stroke.width, 1.0F) / 2.0F;
    const double inner = std::max(half - 0.5F, 0.0F);
    const double outer = half + 0.5F;
    // Lines thinner than a pixel keep their weight through a fainter colour.
    const float weight = std::min(stroke.width, 1.0F);

    const auto base = static_cast<quint32>(mesh.vertices.size());
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasPrev = i > 0 || stroke.closed;
        const bool hasNext = i + 1 < n || stroke.closed;
        const QPointF prev = pts[(i + n - 1) % n];
        const QPointF next = pts[(i + 1) % n];
        const QPointF nIn = hasPrev ? unitNormal(prev, pts[i]) : QPointF();
        const QPointF nOut = hasNext ? unitNormal(pts[i], next) : QPointF();
        QPointF m = nIn + nOut;
        double length = std::hypot(m.x(), m.y());
        if (length < 1e-9) { // a reversal: fall back to one side's normal
            m = hasNext ? nOut : nIn;
            length = 1.0;
        }
        m /= length;
        // Miter: stretch the offset so the rails stay parallel to both segments, limited to 2×.
        const QPointF ref = hasNext ? nOut : nIn;
        const double cosine = std::max(m.x() * ref.x() + m.y() * ref.y(), 0.5);
        const QPointF offset = m / cosine;
        mesh.vertices.push_back(vertex(pts[i] - offset * outer, stroke.color, 0.0F));
        mesh.vertices.push_back(vertex(pts[i] - offset * inner, stroke.color, weight));
        mesh.vertices.push_back(vertex(pts[i] + offset * inner, stroke.color, weight));
        mesh.vertices.push_back(vertex(pts[i] + offset * outer, stroke.color, 0.0F));
    }
    const std::size_t segments = stroke.closed ? n : n - 1;
    for (std::size_t s = 0; s < segments; ++s) {
        const quint32 a = base + static_cast<quint32>(4 * s);
        const quint32 b = base + static_cast<quint32>(4 * ((s + 1) % n));
        for (quint32 rail = 0; rail < 3; ++rail) {
            mesh.indices.insert(mesh.indices.end(),
                                {a + rail, a + rail + 1, b + rail, b + rail, a + rail + 1, b + rail + 1});
        }
    }
}

} // namespace

void tessellateStrokes(const std::vector<Stroke> &strokes, TriangleMesh &mesh)
{
    mesh.vertices.clear();
    mesh.indices.clear();
    for (const Stroke &stroke : strokes)
        tessellateStroke(stroke, mesh);
}

} // namespace kontur
