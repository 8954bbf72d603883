// Drawing the display list: QPainter for the software backend, triangles for the GPU backend.
#include "app/displaylist.h"

#include <QLineF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>

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

std::vector<QPointF> circle(QPointF center, double radius)
{
    // Segments of about 2 px, at least 12: the chord error stays far below a pixel.
    const int n = std::clamp(static_cast<int>(std::ceil(2.0 * std::numbers::pi * radius / 2.0)), 12, 256);
    std::vector<QPointF> points;
    points.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        points.emplace_back(center.x() + radius * std::cos(a), center.y() + radius * std::sin(a));
    }
    return points;
}

namespace {

void paintStroke(const Stroke &stroke, QPainter &painter)
{
    if (stroke.points.size() < 2)
        return;
    QPen pen(stroke.color, stroke.width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    const QPolygonF polygon(QList<QPointF>(stroke.points.begin(), stroke.points.end()));
    if (stroke.closed)
        painter.drawPolygon(polygon);
    else
        painter.drawPolyline(polygon);
}

} // namespace

void paint(const DisplayList &list, QPainter &painter)
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (const Stroke &stroke : list.strokes)
        paintStroke(stroke, painter);
    painter.setPen(Qt::NoPen);
    for (const Disc &disc : list.discs) {
        painter.setBrush(disc.color);
        painter.drawEllipse(disc.center, disc.radius, disc.radius);
    }
    for (const Stroke &stroke : list.overlay)
        paintStroke(stroke, painter);
}

namespace {

QSGGeometry::ColoredPoint2D vertex(QPointF p, const QColor &color, float alpha)
{
    // Premultiplied alpha, as QSGVertexColorMaterial expects.
    const float a = static_cast<float>(color.alphaF()) * alpha;
    QSGGeometry::ColoredPoint2D v;
    v.set(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<uchar>(std::lround(color.red() * a)),
          static_cast<uchar>(std::lround(color.green() * a)), static_cast<uchar>(std::lround(color.blue() * a)),
          static_cast<uchar>(std::lround(255.0F * a)));
    return v;
}

QPointF unitNormal(QPointF from, QPointF to)
{
    const QPointF d = to - from;
    const double length = std::hypot(d.x(), d.y());
    return length > 0.0 ? QPointF(-d.y() / length, d.x() / length) : QPointF();
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

void tessellateDisc(const Disc &disc, TriangleMesh &mesh)
{
    const std::vector<QPointF> ring = circle(QPointF(0, 0), 1.0);
    const auto n = static_cast<quint32>(ring.size());
    const auto base = static_cast<quint32>(mesh.vertices.size());
    const double inner = std::max(disc.radius - 0.5, 0.0);
    const double outer = disc.radius + 0.5;
    mesh.vertices.push_back(vertex(disc.center, disc.color, 1.0F));
    for (const QPointF &u : ring) {
        mesh.vertices.push_back(vertex(disc.center + u * inner, disc.color, 1.0F));
        mesh.vertices.push_back(vertex(disc.center + u * outer, disc.color, 0.0F));
    }
    for (quint32 i = 0; i < n; ++i) {
        const quint32 j = (i + 1) % n;
        const quint32 in0 = base + 1 + 2 * i, out0 = in0 + 1;
        const quint32 in1 = base + 1 + 2 * j, out1 = in1 + 1;
        mesh.indices.insert(mesh.indices.end(), {base, in0, in1, in0, out0, in1, in1, out0, out1});
    }
}

} // namespace

void tessellate(const DisplayList &list, TriangleMesh &mesh)
{
    mesh.vertices.clear();
    mesh.indices.clear();
    for (const Stroke &stroke : list.strokes)
        tessellateStroke(stroke, mesh);
    for (const Disc &disc : list.discs)
        tessellateDisc(disc, mesh);
    for (const Stroke &stroke : list.overlay)
        tessellateStroke(stroke, mesh);
}

} // namespace kontur
