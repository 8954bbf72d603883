// The teaching views' overlay; see teachingpainter.h.
#include "app/teachingpainter.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kontur {

namespace {
using Role = TeachingScene::Role;
}

TeachingPainter::TeachingPainter(QQuickItem *parent)
    : CanvasOverlay(parent)
{
    connect(this, &TeachingPainter::styleChanged, this, [this] { update(); });
}

void TeachingPainter::setTeaching(TeachingController *teaching)
{
    if (m_teaching == teaching)
        return;
    if (m_teaching)
        disconnect(m_teaching, nullptr, this, nullptr);
    m_teaching = teaching;
    if (m_teaching)
        connect(m_teaching, &TeachingController::sceneChanged, this, [this] { update(); });
    Q_EMIT teachingChanged();
    update();
}

bool TeachingPainter::hasContent() const
{
    return canvas() && m_teaching && m_teaching->view() != TeachingController::View::None &&
           !m_teaching->scene().isEmpty();
}

QColor TeachingPainter::colorAt(const QVariantList &list, int index, const QColor &fallback) const
{
    if (list.isEmpty() || index < 0)
        return fallback;
    const QColor c = list.at(index % list.size()).value<QColor>();
    return c.isValid() ? c : fallback;
}

// A point QPainter can draw around: finite and within a billion pixels of the item. Near the largest
// double, or zoomed far into a huge curve, a point maps to infinity or NaN, and Qt's stroker warns for
// every round cap and join at such a point in every frame; such points (and pieces) are left out.
static bool drawable(const QPointF &p)
{
    constexpr double limit = 1e9;
    return std::abs(p.x()) < limit && std::abs(p.y()) < limit; // false for NaN too
}

void TeachingPainter::paint(QPainter *painter)
{
    if (!hasContent())
        return;
    const TeachingScene &scene = m_teaching->scene();
    painter->setRenderHint(QPainter::Antialiasing);
    const auto screen = [this](const geo::Point &p) { return canvas()->toScreen(QPointF(p.x(), p.y())); };

    // Whole curves first (they lie under the constructions): flattened in item pixels to a quarter
    // pixel, after mapping the control points (Bézier curves are affinely invariant).
    std::vector<geo::Point> flat;
    for (const TeachingScene::Curves &curves : scene.curves) {
        QColor color = colorAt(m_palette, curves.index, Qt::darkGray);
        double width = m_lineWidth;
        if (curves.role == Role::LeftHalf) {
            // The part over [0, t], broad and pale under the curve: the first curve of a split.
            color = m_halfColor;
            color.setAlphaF(0.45);
            width = m_lineWidth * 4.0;
        }
        QPainterPath path;
        for (const geo::Bezier &piece : curves.pieces) {
            std::vector<geo::Point> points;
            points.reserve(piece.controlPoints().size());
            for (const geo::Point &p : piece.controlPoints()) {
                const QPointF s = screen(p);
                points.emplace_back(s.x(), s.y());
            }
            if (!std::all_of(points.begin(), points.end(),
                             [](const geo::Point &p) { return drawable(QPointF(p.x(), p.y())); }))
                continue;
            flat.clear();
            geo::flatten(geo::Bezier(std::move(points)), 0.25, flat);
            for (std::size_t i = 0; i < flat.size(); ++i) {
                const QPointF q(flat[i].x(), flat[i].y());
                if (i == 0 && (path.isEmpty() || path.currentPosition() != q))
                    path.moveTo(q);
                else
                    path.lineTo(q);
            }
        }
        painter->setPen(QPen(color, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->setBrush(Qt::NoBrush);
        painter->drawPath(path);
    }

    for (const TeachingScene::Polyline &line : scene.polylines) {
        QColor color;
        double width = m_lineWidth * 0.75;
        double radius = m_pointRadius * 0.8;
        switch (line.role) {
        case Role::Level:
            color = colorAt(m_levelColors, line.index - 1, m_markerColor);
            break;
        case Role::CurvePoint:
            color = m_markerColor;
            radius = m_pointRadius * 1.6;
            break;
        case Role::ElevatedPolygon:
            color = m_elevatedColor;
            radius = line.points.size() > 40 ? m_pointRadius * 0.6 : m_pointRadius * 0.9;
            break;
        case Role::CombTooth:
            color = m_combColor;
            color.setAlphaF(0.6);
            width = std::max(1.0, m_lineWidth * 0.5);
            break;
        case Role::CombOutline:
            color = m_combColor;
            break;
        case Role::Midpoint:
            color = m_jointColor;
            radius = m_pointRadius * 1.1;
            break;
        default:
            color = m_markerColor;
            break;
        }
        QPolygonF polygon;
        polygon.reserve(static_cast<qsizetype>(line.points.size()));
        for (const geo::Point &p : line.points)
            polygon.append(screen(p));
        if (polygon.size() >= 2 && line.role != Role::Midpoint) { // midpoints are dots, not a path
            painter->setPen(QPen(color, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            painter->setBrush(Qt::NoBrush);
            // Each run of drawable points as a polyline of its own.
            QPolygonF run;
            for (qsizetype i = 0; i <= polygon.size(); ++i) {
                if (i < polygon.size() && drawable(polygon[i])) {
                    run.append(polygon[i]);
                    continue;
                }
                if (run.size() >= 2)
                    painter->drawPolyline(run);
                run.clear();
            }
        }
        if (line.dots) {
            painter->setPen(line.role == Role::CurvePoint ? QPen(Qt::white, 2.0) : Qt::NoPen);
            painter->setBrush(color);
            for (const QPointF &p : polygon)
                if (drawable(p))
                    painter->drawEllipse(p, radius, radius);
        }
    }

    // Joint marks: the continuity in a small box next to the joint, red where it is only G0 or less.
    QFont font = painter->font();
    font.setPixelSize(static_cast<int>(std::lround(m_fontPixelSize)));
    font.setBold(true);
    painter->setFont(font);
    const QFontMetricsF metrics(font);
    for (const TeachingScene::Label &label : scene.labels) {
        const QPointF at = screen(label.at);
        if (!drawable(at))
            continue;
        const QColor color = label.index <= static_cast<int>(geo::Continuity::G0) ? m_weakJointColor : m_jointColor;
        const double w = metrics.horizontalAdvance(label.text) + 8.0;
        const double h = metrics.height() + 2.0;
        const QRectF box(at.x() + m_pointRadius + 2.0, at.y() - h - m_pointRadius, w, h);
        painter->setPen(QPen(color, 1.0));
        painter->setBrush(m_labelBackground);
        painter->drawRoundedRect(box, 3.0, 3.0);
        painter->drawText(box, Qt::AlignCenter, label.text);
        painter->setBrush(color);
        painter->setPen(Qt::NoPen);
        painter->drawEllipse(at, m_pointRadius * 0.9, m_pointRadius * 0.9);
    }
}

} // namespace kontur
