// The perspective calibration's geometry: see perspective.h.
#include "models/trace/perspective.h"

#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace kontur::perspective {

namespace {

double cross(QPointF a, QPointF b)
{
    return a.x() * b.y() - a.y() * b.x();
}

double denominator(const geo::Projective2D &t, QPointF p)
{
    return t.denominator(geo::Point(p.x(), p.y()));
}

} // namespace

std::optional<Quad> orderCorners(const Quad &points)
{
    QPointF centre;
    for (const QPointF &p : points)
        centre += p / 4.0;
    // Around the centroid by angle: on the screen (y down) increasing atan2 runs clockwise. For a
    // convex quadrilateral the centroid of its corners lies inside it, so this is its cyclic order.
    Quad q = points;
    std::sort(q.begin(), q.end(), [&](QPointF a, QPointF b) {
        return std::atan2(a.y() - centre.y(), a.x() - centre.x()) < std::atan2(b.y() - centre.y(), b.x() - centre.x());
    });
    // Strictly convex: every turn the same way and none straight. The scale of the picture enters the
    // threshold, so that three nearly collinear taps are refused at any size.
    double extent = 0.0;
    for (const QPointF &p : q)
        extent = std::max(extent, QLineF(centre, p).length());
    const double tiny = 1e-6 * extent * extent;
    for (int i = 0; i < 4; ++i) {
        const QPointF a = q[i], b = q[(i + 1) % 4], c = q[(i + 2) % 4];
        if (!(cross(b - a, c - b) > tiny))
            return std::nullopt;
    }
    // Start at the top-left: the smallest x + y (on a tie the higher point).
    const auto first = std::min_element(q.begin(), q.end(), [](QPointF a, QPointF b) {
        const double sa = a.x() + a.y(), sb = b.x() + b.y();
        return sa < sb || (sa == sb && a.y() < b.y());
    });
    std::rotate(q.begin(), first, q.end());
    return q;
}

bool looksLandscape(const Quad &q)
{
    const double across = QLineF(q[0], q[1]).length() + QLineF(q[3], q[2]).length();
    const double down = QLineF(q[0], q[3]).length() + QLineF(q[1], q[2]).length();
    return across > down;
}

QTransform toQTransform(const geo::Projective2D &map)
{
    // QTransform maps row vectors: (x, y, 1) · M, so its matrix is H transposed.
    const Eigen::Matrix3d &h = map.matrix();
    return {h(0, 0), h(1, 0), h(2, 0), h(0, 1), h(1, 1), h(2, 1), h(0, 2), h(1, 2), h(2, 2)};
}

QRectF drawnRect(const Background &background, QSizeF imageSize)
{
    if (const auto h = background.perspectiveMap())
        return drawnRect(*h, background.corners, imageSize);
    return {QPointF(0.0, 0.0), imageSize};
}

QRectF drawnRect(const geo::Projective2D &t, const Quad &ordered, QSizeF imageSize, double minimumScale)
{
    const QRectF inner = QPolygonF(QList<QPointF>(ordered.begin(), ordered.end())).boundingRect();
    const QRectF outer(QPointF(0.0, 0.0), imageSize);
    QPointF centre;
    for (const QPointF &p : ordered)
        centre += p / 4.0;
    const double w0 = denominator(t, centre);
    // The quadrilateral itself is always drawn, however steep the view.
    double least = minimumScale;
    for (const QPointF &p : ordered)
        least = std::min(least, denominator(t, p) / w0);
    // The bounding box's corners on the quadrilateral's sides may lie at its corners' own limit: a
    // rounding's worth of slack, so that a homography found numerically does not shut them out.
    least -= 1e-12;
    // The denominator is affine, so over a rectangle it is smallest at a corner.
    const auto fits = [&](const QRectF &r) {
        for (const QPointF &c : {r.topLeft(), r.topRight(), r.bottomLeft(), r.bottomRight()})
            if (!(denominator(t, c) / w0 >= least))
                return false;
        return true;
    };
    const auto between = [&](double s) {
        return QRectF(
            QPointF(inner.left() + s * (outer.left() - inner.left()), inner.top() + s * (outer.top() - inner.top())),
            QPointF(inner.right() + s * (outer.right() - inner.right()),
                    inner.bottom() + s * (outer.bottom() - inner.bottom())));
    };
    if (fits(between(1.0)))
        return outer;
    // Each side moves out at its own pace: as far as the denominator allows on its own, found by
    // bisection (the condition is monotone along each side's path).
    QRectF r = inner;
    for (int side = 0; side < 4; ++side) {
        double lo = 0.0, hi = 1.0;
        const auto moved = [&](double s) {
            QRectF m = r;
            switch (side) {
            case 0:
                m.setLeft(inner.left() + s * (outer.left() - inner.left()));
                break;
            case 1:
                m.setTop(inner.top() + s * (outer.top() - inner.top()));
                break;
            case 2:
                m.setRight(inner.right() + s * (outer.right() - inner.right()));
                break;
            default:
                m.setBottom(inner.bottom() + s * (outer.bottom() - inner.bottom()));
                break;
            }
            return m;
        };
        if (fits(moved(1.0))) {
            r = moved(1.0);
            continue;
        }
        for (int i = 0; i < 30; ++i) {
            const double mid = (lo + hi) / 2;
            (fits(moved(mid)) ? lo : hi) = mid;
        }
        r = moved(lo);
    }
    return r.intersected(outer);
}

} // namespace kontur::perspective
