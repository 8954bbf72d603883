// A piece's marks in documents, and where they lie on its curve (see piece.h).
#include "io/piece.h"

#include "geometry/arclength.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::io {

namespace {

constexpr double kAccuracy = 1e-9;

QJsonArray pointJson(const geo::Point &p)
{
    return QJsonArray{p.x(), p.y()};
}

std::optional<geo::Point> pointFrom(const QJsonValue &v)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 2 || !a[0].isDouble() || !a[1].isDouble())
        return std::nullopt;
    const geo::Point p(a[0].toDouble(), a[1].toDouble());
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return std::nullopt;
    return p;
}

std::optional<Segment> segmentFrom(const QJsonValue &v)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 2)
        return std::nullopt;
    const auto p = pointFrom(a[0]), q = pointFrom(a[1]);
    if (!p || !q)
        return std::nullopt;
    return Segment{*p, *q};
}

} // namespace

const char *notchKindId(NotchKind kind)
{
    switch (kind) {
    case NotchKind::Slit:
        return "slit";
    case NotchKind::V:
        return "v";
    case NotchKind::Castle:
        return "castle";
    }
    return "slit";
}

std::optional<NotchKind> notchKindFromId(const QString &id)
{
    for (NotchKind k : {NotchKind::Slit, NotchKind::V, NotchKind::Castle})
        if (id == QLatin1String(notchKindId(k)))
            return k;
    return std::nullopt;
}

QJsonObject pieceToJson(const PieceMarks &piece)
{
    QJsonObject o;
    if (!piece.size.isEmpty())
        o.insert(QStringLiteral("size"), piece.size);
    o.insert(QStringLiteral("quantity"), piece.quantity);
    if (!piece.material.isEmpty())
        o.insert(QStringLiteral("material"), piece.material);
    if (piece.fold)
        o.insert(QStringLiteral("fold"), QJsonArray{pointJson(piece.fold->a), pointJson(piece.fold->b)});
    if (piece.grainline)
        o.insert(QStringLiteral("grainline"), QJsonArray{pointJson(piece.grainline->a), pointJson(piece.grainline->b)});
    if (!piece.notches.empty()) {
        QJsonArray notches;
        for (const Notch &n : piece.notches)
            notches.append(QJsonObject{{QStringLiteral("at"), n.position},
                                       {QStringLiteral("kind"), QLatin1String(notchKindId(n.kind))},
                                       {QStringLiteral("angle"), n.angle}});
        o.insert(QStringLiteral("notches"), notches);
    }
    if (!piece.drillHoles.empty()) {
        QJsonArray holes;
        for (const geo::Point &p : piece.drillHoles)
            holes.append(pointJson(p));
        o.insert(QStringLiteral("drillHoles"), holes);
    }
    if (!piece.seamWidths.empty()) {
        QJsonArray widths;
        for (const std::optional<double> &w : piece.seamWidths)
            widths.append(w ? QJsonValue(*w) : QJsonValue(QJsonValue::Null));
        o.insert(QStringLiteral("seamWidths"), widths);
    }
    if (!piece.hems.empty()) {
        QJsonArray hems;
        for (int k : piece.hems)
            hems.append(k);
        o.insert(QStringLiteral("hems"), hems);
    }
    return o;
}

std::optional<PieceMarks> pieceFromSettings(const QJsonObject &settings)
{
    const QJsonValue value = settings.value(QLatin1String(kPieceKey));
    if (!value.isObject())
        return std::nullopt;
    const QJsonObject o = value.toObject();
    PieceMarks piece;
    piece.size = o.value(QLatin1String("size")).toString();
    piece.material = o.value(QLatin1String("material")).toString();
    const double quantity = o.value(QLatin1String("quantity")).toDouble(1.0);
    piece.quantity = std::isfinite(quantity) && quantity >= 1 && quantity <= 1e6 ? static_cast<int>(quantity) : 1;
    piece.fold = segmentFrom(o.value(QLatin1String("fold")));
    piece.grainline = segmentFrom(o.value(QLatin1String("grainline")));
    for (const QJsonValue &v : o.value(QLatin1String("notches")).toArray()) {
        const QJsonObject n = v.toObject();
        const QJsonValue at = n.value(QLatin1String("at")), angle = n.value(QLatin1String("angle"));
        const auto kind = notchKindFromId(n.value(QLatin1String("kind")).toString());
        if (!at.isDouble() || !std::isfinite(at.toDouble()) || !kind)
            continue;
        const double a = angle.isDouble() && std::isfinite(angle.toDouble()) ? angle.toDouble() : 0.0;
        piece.notches.push_back({at.toDouble(), *kind, std::clamp(a, -89.0, 89.0)});
    }
    for (const QJsonValue &v : o.value(QLatin1String("drillHoles")).toArray())
        if (const auto p = pointFrom(v))
            piece.drillHoles.push_back(*p);
    // A width that is no finite number from 0 up is read as the allowance's own (none).
    for (const QJsonValue &v : o.value(QLatin1String("seamWidths")).toArray()) {
        const double w = v.toDouble(-1.0);
        piece.seamWidths.push_back(v.isDouble() && std::isfinite(w) && w >= 0 ? std::optional<double>(w)
                                                                              : std::nullopt);
    }
    while (!piece.seamWidths.empty() && !piece.seamWidths.back())
        piece.seamWidths.pop_back();
    // Seam numbers: whole numbers from 0 up, each once, ascending; others left out.
    for (const QJsonValue &v : o.value(QLatin1String("hems")).toArray()) {
        const double k = v.toDouble(-1.0);
        if (v.isDouble() && k >= 0 && k <= 1e6 && k == std::floor(k))
            piece.hems.push_back(static_cast<int>(k));
    }
    std::sort(piece.hems.begin(), piece.hems.end());
    piece.hems.erase(std::unique(piece.hems.begin(), piece.hems.end()), piece.hems.end());
    return piece;
}

CurvePlace placeAtLength(const geo::PiecewiseBezier &curve, double s)
{
    CurvePlace place;
    if (curve.isEmpty())
        return place;
    const double total = curve.length(kAccuracy);
    if (curve.isClosed() && total > 0) {
        s = std::fmod(s, total);
        if (s < 0)
            s += total;
    }
    s = std::clamp(s, 0.0, total);
    for (int i = 0; i < curve.segmentCount(); ++i) {
        const geo::Bezier &b = curve.segments()[static_cast<std::size_t>(i)];
        const double len = geo::arcLength(b, kAccuracy);
        if (s <= len || i + 1 == curve.segmentCount()) {
            const double t = len > 0 ? geo::parameterAtLength(b, std::min(s, len), kAccuracy) : 0.0;
            place.point = b.eval(t);
            geo::Point d = b.derivative(t);
            // A vanishing derivative at a handle on its knot: the chord's direction nearby.
            if (d.norm() < 1e-12 * std::max(1.0, b.controlPoints().front().norm()))
                d = b.eval(std::min(1.0, t + 1e-6)) - b.eval(std::max(0.0, t - 1e-6));
            if (d.norm() > 0)
                place.tangent = d / d.norm();
            return place;
        }
        s -= len;
    }
    return place;
}

double lengthAtNearest(const geo::PiecewiseBezier &curve, const geo::Point &p)
{
    if (curve.isEmpty())
        return 0.0;
    const geo::PiecewiseNearest n = curve.nearest(p);
    double s = 0.0;
    for (int i = 0; i < n.segment; ++i)
        s += geo::arcLength(curve.segments()[static_cast<std::size_t>(i)], kAccuracy);
    return s + geo::arcLength(curve.segments()[static_cast<std::size_t>(n.segment)], 0.0, n.t, kAccuracy);
}

std::optional<geo::Point> meetAlong(const geo::PiecewiseBezier &curve, const geo::Point &from,
                                    const geo::Point &direction)
{
    if (curve.isEmpty() || !(direction.norm() > 0.0))
        return std::nullopt;
    const geo::Point d = direction.normalized();
    const auto cross = [&](const geo::Point &v) { return d.x() * v.y() - d.y() * v.x(); };
    const geo::PiecewiseNearest start = curve.nearest(from);
    int segment = start.segment;
    double t = start.t;
    const int n = curve.segmentCount();
    for (int step = 0, moves = 0; step < 60 && moves <= 4; ++step) {
        const geo::Bezier &b = curve.segments()[static_cast<std::size_t>(segment)];
        const double f = cross(b.eval(t) - from), df = cross(b.derivative(t));
        if (std::abs(f) <= 1e-12 * std::max(1.0, (b.eval(t) - from).norm()))
            return b.eval(t);
        if (df == 0.0)
            return std::nullopt;
        const double next = t - f / df;
        if (next >= 0.0 && next <= 1.0) {
            t = next;
            continue;
        }
        // On to the neighbouring segment the step points to.
        const int to = next < 0.0 ? segment - 1 : segment + 1;
        if (!curve.isClosed() && (to < 0 || to >= n))
            return std::nullopt;
        segment = (to + n) % n;
        t = next < 0.0 ? 1.0 : 0.0;
        ++moves;
    }
    return std::nullopt;
}

double signedArea(const geo::PiecewiseBezier &curve)
{
    std::vector<geo::Point> poly;
    const geo::Box box = curve.boundingBox();
    curve.flatten(std::max(1e-9, box.sizes().norm() * 1e-4), poly);
    double area = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const geo::Point &p = poly[i], &q = poly[(i + 1) % poly.size()];
        area += p.x() * q.y() - q.x() * p.y();
    }
    return area / 2;
}

geo::Point notchDirection(const geo::PiecewiseBezier &curve, const CurvePlace &place, double angle)
{
    // Counter-clockwise the inside lies to the left of the tangent.
    const geo::Point left(-place.tangent.y(), place.tangent.x());
    const geo::Point inward = signedArea(curve) >= 0 ? left : geo::Point(-left);
    const double r = angle * std::numbers::pi / 180.0;
    return {inward.x() * std::cos(r) - inward.y() * std::sin(r), inward.x() * std::sin(r) + inward.y() * std::cos(r)};
}

} // namespace kontur::io
