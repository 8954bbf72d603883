// DXF import (see dxf.h): the entity kinds as Bézier pieces. LINE, LWPOLYLINE and POLYLINE (bulges
// as circular arcs), ARC, CIRCLE and ELLIPSE (within the options' arc tolerance), SPLINE (any
// non-rational B-spline split into its Bézier pieces by blossoming), each with its object
// coordinates, and the curve each becomes with its layer, colour and block placement. The sections
// are read in dxf.cpp (the reader's insides: dxfread_p.h).
#include "io/dxf.h"

#include "io/dxfread_p.h"
#include "io/shapes.h"
#include "io/svgpath.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace kontur::io {

double sweepOf(double start, double end, double period, bool &full)
{
    const double tolerance = kFullTurnTolerance * period;
    full = false;
    if (std::abs(end - start) <= tolerance)
        return 0.0; // the same angle: nothing is drawn (as ezdxf reads it)
    double sweep = std::fmod(end - start, period);
    if (sweep < 0)
        sweep += period;
    full = sweep <= tolerance || sweep >= period - tolerance;
    return full ? period : sweep;
}

} // namespace kontur::io

namespace kontur::io::dxfread {

namespace {

DxfSkipped skippedKind(std::string_view type)
{
    static constexpr std::pair<std::string_view, DxfSkipped> kinds[] = {
        {"TEXT", DxfSkipped::Text},
        {"MTEXT", DxfSkipped::Text},
        {"ATTRIB", DxfSkipped::Text},
        {"ATTDEF", DxfSkipped::Text},
        {"RTEXT", DxfSkipped::Text},
        {"DIMENSION", DxfSkipped::Dimension},
        {"LEADER", DxfSkipped::Dimension},
        {"MLEADER", DxfSkipped::Dimension},
        {"MULTILEADER", DxfSkipped::Dimension},
        {"TOLERANCE", DxfSkipped::Dimension},
        {"ARC_DIMENSION", DxfSkipped::Dimension},
        {"3DFACE", DxfSkipped::Solid3D},
        {"3DSOLID", DxfSkipped::Solid3D},
        {"BODY", DxfSkipped::Solid3D},
        {"REGION", DxfSkipped::Solid3D},
        {"SURFACE", DxfSkipped::Solid3D},
        {"MESH", DxfSkipped::Solid3D},
        {"POLYFACE", DxfSkipped::Solid3D},
        {"IMAGE", DxfSkipped::Image},
        {"WIPEOUT", DxfSkipped::Image},
        {"OLE2FRAME", DxfSkipped::Image},
        {"OLEFRAME", DxfSkipped::Image},
        {"PDFUNDERLAY", DxfSkipped::Image},
        {"DWFUNDERLAY", DxfSkipped::Image},
        {"DGNUNDERLAY", DxfSkipped::Image},
    };
    for (const auto &[name, kind] : kinds)
        if (name == type)
            return kind;
    return DxfSkipped::Other;
}

// What a curve on a layer of ASTM D6673 is of its piece.
const char *aamaRole(int layer)
{
    switch (layer) {
    case 1:
        return "cut line";
    case 4:
        return "notch";
    case 6:
        return "mirror line";
    case 7:
        return "grain line";
    case 8:
        return "internal line";
    case 11:
        return "internal cutout";
    case 13:
        return "drill hole";
    case 14:
        return "sew line";
    default:
        return "";
    }
}

// The cubics of a circular arc through a bulge (the tangent of a quarter of the included angle,
// negative clockwise) from a to b.
std::vector<geo::Bezier> bulgeArc(const geo::Point &a, const geo::Point &b, double bulge, double tolerance)
{
    const double theta = 4.0 * std::atan(bulge); // included angle, signed
    const geo::Point chord = b - a;
    const double c = std::hypot(chord.x(), chord.y()); // no overflow of the squares near 1e300
    const double r = c / (2.0 * std::sin(std::abs(theta) / 2.0));
    // The centre lies on the chord's perpendicular bisector, at distance r cos(θ/2) on the left of
    // a→b for a counter-clockwise arc of less than half a turn (the sagitta is c·|bulge|/2).
    const geo::Point mid = (a + b) / 2.0;
    const geo::Point left(-chord.y() / c, chord.x() / c);
    const double d = r * std::cos(theta / 2.0) * (theta > 0 ? 1.0 : -1.0);
    const geo::Point center = mid + left * d;
    const double start = std::atan2(a.y() - center.y(), a.x() - center.x());
    std::vector<geo::Bezier> arcs = arcToCubics(center, r, r, 0.0, start, theta, tolerance);
    // The exact end points (the arc's are computed).
    if (!arcs.empty()) {
        std::vector<geo::Point> first = arcs.front().controlPoints();
        first.front() = a;
        arcs.front() = geo::Bezier(std::move(first));
        std::vector<geo::Point> last = arcs.back().controlPoints();
        last.back() = b;
        arcs.back() = geo::Bezier(std::move(last));
    }
    return arcs;
}

QString entityName(std::string_view type)
{
    return QString::fromLatin1(type.data(), static_cast<qsizetype>(type.size()));
}

// Object coordinates of the planar entities (LWPOLYLINE, ARC, CIRCLE) into the world: seen from
// below (`mirrored`) the x axis points the other way.
geo::Point ocs(geo::Point p, bool mirrored)
{
    if (mirrored)
        p.x() = 0.0 - p.x();
    return p;
}

} // namespace

qint64 interiorPoints(const std::vector<geo::Bezier> &segments)
{
    qint64 n = 0;
    for (const geo::Bezier &b : segments)
        n += b.degree() - 1;
    return n;
}

std::vector<geo::Bezier> polylineSegments(const std::vector<geo::Point> &pts, const std::vector<double> &bulges,
                                          bool closed, double tolerance, qint64 budget)
{
    std::vector<geo::Bezier> segments;
    qint64 added = 0;
    const std::size_t n = pts.size();
    const std::size_t count = closed ? n : n - 1;
    for (std::size_t i = 0; i < count && n >= 2; ++i) {
        const geo::Point &a = pts[i];
        const geo::Point &b = pts[(i + 1) % n];
        if (a == b)
            continue;
        if (bulges[i] != 0.0) {
            for (geo::Bezier &arc : bulgeArc(a, b, bulges[i], tolerance)) {
                added += arc.degree() - 1;
                segments.push_back(std::move(arc));
            }
            if (added > budget)
                break;
        } else {
            segments.emplace_back(std::vector<geo::Point>{a, b});
        }
    }
    return segments;
}

// Bézier decomposition of a B-spline of degree p with knots U and control points P: the piece over
// each span [U_k, U_k+1] has the control points f(a,…,a, b,…,b) (p − j times a = U_k, j times
// b = U_k+1) of the curve's blossom f, evaluated by de Boor's algorithm with one argument per level
// (Ramshaw 1989; de Boor's recurrence as in Piegl & Tiller, "The NURBS Book", 2nd ed., §2.3 and §5.6).
// O(p²) per span. Where the knots already have multiplicity p (as Kontur writes them) every factor
// is exactly 0 or 1 and the points are copied, so Kontur's own splines come back bit for bit.
std::vector<geo::Bezier> bezierPieces(const std::vector<double> &U, const std::vector<geo::Point> &P, int p)
{
    std::vector<geo::Bezier> pieces;
    const std::size_t n = P.size() - 1;
    const std::size_t sp = static_cast<std::size_t>(p);
    std::vector<geo::Point> d(sp + 1);
    for (std::size_t k = sp; k <= n; ++k) {
        const double a = U[k], b = U[k + 1];
        if (!(a < b))
            continue;
        std::vector<geo::Point> bezier;
        bezier.reserve(sp + 1);
        for (std::size_t j = 0; j <= sp; ++j) {
            for (std::size_t i = 0; i <= sp; ++i)
                d[i] = P[k - sp + i];
            for (std::size_t r = 1; r <= sp; ++r) {
                const double t = r <= sp - j ? a : b;
                for (std::size_t i = sp; i >= r; --i) {
                    const double lo = U[i + k - sp], hi = U[i + 1 + k - r];
                    const double alpha = (t - lo) / (hi - lo);
                    if (alpha == 0.0)
                        d[i] = d[i - 1];
                    else if (alpha != 1.0)
                        d[i] = (1.0 - alpha) * d[i - 1] + alpha * d[i];
                }
            }
            bezier.push_back(d[sp]);
        }
        pieces.emplace_back(std::move(bezier));
    }
    return pieces;
}

std::optional<Error> Reader::addCurve(DxfImport &out, const Group &start, const std::vector<Group> &groups,
                                      geo::PiecewiseBezier curve, const Placement &place)
{
    if (curve.isEmpty())
        return std::nullopt;
    if (static_cast<qint64>(out.curves.size()) >= m_options.limits.maxCurves)
        return error(ErrorCode::TooManyCurves, start.line,
                     QStringLiteral("more than %1 entities, the most Kontur reads from one file")
                         .arg(m_options.limits.maxCurves));
    DxfImportedCurve c;
    std::string_view layer = "0";
    for (const Group &g : groups)
        if (g.code == 8)
            layer = g.value;
    // Block content on the layer "0" is drawn on the INSERT's layer.
    if (layer == "0" && !place.layer.empty())
        layer = place.layer;
    c.color = colorOf(groups, layer, place);
    if (layer != "0")
        c.name = dxfText(layer, m_codec);
    if (!place.piece.isEmpty()) {
        // ASTM D6673's layers: the curve is named after its piece and what it is of it.
        static constexpr std::pair<std::string_view, int> roles[] = {{"1", 1}, {"4", 4},   {"6", 6},   {"7", 7},
                                                                     {"8", 8}, {"11", 11}, {"13", 13}, {"14", 14}};
        for (const auto &[number, aama] : roles)
            if (layer == number) {
                c.name = place.piece + QLatin1Char(' ') + QLatin1String(aamaRole(aama));
                c.piece = place.piece;
                c.aamaLayer = aama;
            }
    }
    const bool placed = place.depth > 0;
    if (m_scale != 1.0 || placed) {
        std::vector<geo::Bezier> moved;
        for (const geo::Bezier &b : curve.segments()) {
            std::vector<geo::Point> pts = b.controlPoints();
            for (geo::Point &p : pts)
                p = (placed ? geo::Point(place.m * p + place.t) : p) * m_scale;
            moved.emplace_back(std::move(pts));
        }
        curve = geo::PiecewiseBezier(std::move(moved), curve.isClosed());
    }
    for (const geo::Bezier &b : curve.segments())
        for (const geo::Point &p : b.controlPoints())
            if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
                return error(
                    ErrorCode::NumberOutOfRange, start.line,
                    QStringLiteral("%1: a point lies beyond the range of numbers").arg(entityName(start.value)));
    c.curve = std::move(curve);
    c.line = start.line;
    out.curves.push_back(std::move(c));
    return std::nullopt;
}

std::optional<Error> Reader::addEntity(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                       DxfImport &out)
{
    const std::string_view type = start.value;
    // The extrusion direction: only the drawing plane, seen from above (0,0,1) or below (0,0,-1,
    // where the entity's own x axis points the other way: AutoCAD's arbitrary axis algorithm).
    double ez = 1.0, ex = 0.0, ey = 0.0;
    for (const Group &g : groups) {
        if (g.code == 210 || g.code == 220 || g.code == 230) {
            double v = 0.0;
            if (auto e = number(g, v))
                return e;
            (g.code == 210 ? ex : g.code == 220 ? ey : ez) = v;
        }
    }
    const bool mirrored = ez < 0;
    if (std::abs(ex) > 1e-12 || std::abs(ey) > 1e-12 || std::abs(std::abs(ez) - 1.0) > 1e-12) {
        // Outside the drawing plane: seen from above it is another curve (or a line), not this one.
        skip(out, DxfSkipped::Solid3D);
        return std::nullopt;
    }
    if (type == "LINE")
        return addLine(start, groups, place, out);
    if (type == "LWPOLYLINE")
        return addLwPolyline(start, groups, mirrored, place, out);
    if (type == "ARC" || type == "CIRCLE")
        return addArc(start, groups, mirrored, place, out);
    if (type == "ELLIPSE")
        return addEllipse(start, groups, mirrored, place, out);
    if (type == "SPLINE")
        return addSpline(start, groups, place, out);
    skip(out, skippedKind(type));
    return std::nullopt;
}

std::optional<Error> Reader::addLine(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                     DxfImport &out)
{
    double x1, y1, x2, y2;
    for (auto [code, v] : {std::pair{10, &x1}, {20, &y1}, {11, &x2}, {21, &y2}})
        if (auto e = number(groups, code, 0.0, *v))
            return e;
    if (auto e = countPoints(2, start.line))
        return e;
    if (geo::Point(x1, y1) == geo::Point(x2, y2))
        return std::nullopt;
    return addCurve(out, start, groups,
                    geo::PiecewiseBezier({geo::Bezier({geo::Point(x1, y1), geo::Point(x2, y2)})}, false), place);
}

std::optional<Error> Reader::addLwPolyline(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                           const Placement &place, DxfImport &out)
{
    std::vector<geo::Point> pts;
    std::vector<double> bulges;
    for (const Group &g : groups) {
        double v = 0.0;
        if (g.code == 10 || g.code == 20 || g.code == 42)
            if (auto e = number(g, v))
                return e;
        if (g.code == 10) {
            if (auto e = countPoints(1, g.line))
                return e;
            pts.emplace_back(v, 0.0);
            bulges.push_back(0.0);
        } else if (g.code == 20 && !pts.empty()) {
            pts.back().y() = v;
        } else if (g.code == 42 && !bulges.empty()) {
            bulges.back() = v;
        }
    }
    for (geo::Point &p : pts)
        p = ocs(p, mirrored);
    if (mirrored)
        for (double &b : bulges)
            b = -b;
    const bool closed = (integerOf(groups, 70) & 1) != 0;
    auto segments =
        polylineSegments(pts, bulges, closed, m_options.arcTolerance, m_options.limits.maxPoints - m_points);
    if (auto e = countPoints(interiorPoints(segments), start.line))
        return e;
    return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(segments), closed), place);
}

std::optional<Error> Reader::addArc(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                    const Placement &place, DxfImport &out)
{
    const std::string_view type = start.value;
    double cx, cy, r, a0 = 0.0, a1 = 360.0;
    for (auto [code, v] : {std::pair{10, &cx}, {20, &cy}, {40, &r}})
        if (auto e = number(groups, code, 0.0, *v))
            return e;
    if (type == "ARC") {
        if (auto e = number(groups, 50, 0.0, a0))
            return e;
        if (auto e = number(groups, 51, 360.0, a1))
            return e;
    }
    if (!(r > 0))
        return std::nullopt;
    bool full = type == "CIRCLE";
    const double sweep = full ? 360.0 : sweepOf(a0, a1, 360.0, full);
    if (sweep == 0.0)
        return std::nullopt;
    const double rad = std::numbers::pi / 180.0;
    std::vector<geo::Bezier> arcs =
        arcToCubics(geo::Point(cx, cy), r, r, 0.0, a0 * rad, sweep * rad, m_options.arcTolerance);
    if (mirrored)
        for (geo::Bezier &b : arcs) {
            std::vector<geo::Point> pts = b.controlPoints();
            for (geo::Point &p : pts)
                p = ocs(p, mirrored);
            b = geo::Bezier(std::move(pts));
        }
    return addArcs(start, groups, std::move(arcs), full, place, out);
}

std::optional<Error> Reader::addEllipse(const Group &start, const std::vector<Group> &groups, bool mirrored,
                                        const Placement &place, DxfImport &out)
{
    double cx, cy, mx, my, ratio, t0, t1;
    for (auto [code, v, fallback] : {std::tuple{10, &cx, 0.0},
                                     {20, &cy, 0.0},
                                     {11, &mx, 1.0},
                                     {21, &my, 0.0},
                                     {40, &ratio, 1.0},
                                     {41, &t0, 0.0},
                                     {42, &t1, 2 * std::numbers::pi}})
        if (auto e = number(groups, code, fallback, *v))
            return e;
    const double rx = std::hypot(mx, my);
    if (!(rx > 0) || !(ratio > 0))
        return std::nullopt;
    bool full = false;
    const double sweep = sweepOf(t0, t1, 2 * std::numbers::pi, full);
    if (sweep == 0.0)
        return std::nullopt;
    // The minor axis is the extrusion × the major axis: to the left of it seen from above.
    const double phi = std::atan2(my, mx);
    std::vector<geo::Bezier> arcs =
        arcToCubics(geo::Point::Zero(), rx, rx * ratio, phi, t0, sweep, m_options.arcTolerance);
    const geo::Point c(cx, cy);
    for (geo::Bezier &b : arcs) {
        std::vector<geo::Point> pts = b.controlPoints();
        for (geo::Point &p : pts) {
            if (mirrored) {
                // Seen from below the parameter turns clockwise: reflect across the major axis.
                const geo::Point u(mx / rx, my / rx);
                p = 2.0 * p.dot(u) * u - p;
            }
            p += c;
        }
        b = geo::Bezier(std::move(pts));
    }
    return addArcs(start, groups, std::move(arcs), full, place, out);
}

std::optional<Error> Reader::addArcs(const Group &start, const std::vector<Group> &groups,
                                     std::vector<geo::Bezier> arcs, bool full, const Placement &place, DxfImport &out)
{
    if (auto e = countPoints(static_cast<qint64>(3 * arcs.size() + 1), start.line))
        return e;
    if (full && !arcs.empty()) {
        // The circle or ellipse ends exactly where it starts.
        std::vector<geo::Point> last = arcs.back().controlPoints();
        last.back() = arcs.front().startPoint();
        arcs.back() = geo::Bezier(std::move(last));
    }
    return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(arcs), full), place);
}

std::optional<Error> Reader::addSpline(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                       DxfImport &out)
{
    const long long flags = integerOf(groups, 70);
    const long long degree = integerOf(groups, 71);
    std::vector<double> knots, weights;
    std::vector<geo::Point> control;
    bool fitPoints = false;
    for (const Group &g : groups) {
        double v = 0.0;
        if (g.code == 40 || g.code == 41 || g.code == 10 || g.code == 20)
            if (auto e = number(g, v))
                return e;
        switch (g.code) {
        case 40:
            if (knots.size() > static_cast<std::size_t>(m_options.limits.maxPoints))
                return error(ErrorCode::TooManyPoints, g.line,
                             QStringLiteral("SPLINE: more than %1 knots").arg(m_options.limits.maxPoints));
            knots.push_back(v);
            break;
        case 41:
            weights.push_back(v);
            break;
        case 10:
            if (auto e = countPoints(1, g.line))
                return e;
            control.emplace_back(v, 0.0);
            break;
        case 20:
            if (!control.empty())
                control.back().y() = v;
            break;
        case 11:
            fitPoints = true;
            break;
        default:
            break;
        }
    }
    if (control.empty() && fitPoints) {
        // Only fit points: the curve through them depends on the CAD program's own fitting.
        skip(out, DxfSkipped::Spline);
        return std::nullopt;
    }
    if (degree < 1 || degree > 100)
        return error(ErrorCode::DxfSyntax, start.line,
                     QStringLiteral("SPLINE: the degree (group 71) must be 1 to 100, found %1").arg(degree));
    const std::size_t p = static_cast<std::size_t>(degree);
    if (control.size() < p + 1 || knots.size() != control.size() + p + 1)
        return error(ErrorCode::DxfSyntax, start.line,
                     QStringLiteral("SPLINE: %1 control points and %2 knots do not fit degree %3 (knots = control "
                                    "points + degree + 1, at least degree + 1 control points)")
                         .arg(control.size())
                         .arg(knots.size())
                         .arg(degree));
    for (std::size_t i = 1; i < knots.size(); ++i)
        if (knots[i] < knots[i - 1])
            return error(ErrorCode::DxfSyntax, start.line,
                         QStringLiteral("SPLINE: the knots decrease at knot %1").arg(i + 1));
    if (!(knots[p] < knots[knots.size() - 1 - p]))
        return error(ErrorCode::DxfSyntax, start.line, QStringLiteral("SPLINE: the knots leave no domain"));
    if ((flags & 4) != 0 && !weights.empty() &&
        std::any_of(weights.begin(), weights.end(), [&](double w) { return w != weights.front(); })) {
        // A rational spline (unequal weights) has no exact Bézier form in Kontur.
        skip(out, DxfSkipped::Spline);
        return std::nullopt;
    }
    // The Bézier pieces have p points each and one more: what they add to the control points
    // is counted before they are made (nothing for the Bézier knots Kontur writes).
    qint64 spans = 0;
    for (std::size_t k = p; k + 1 < control.size() + 1; ++k)
        spans += knots[k] < knots[k + 1] ? 1 : 0;
    if (auto e = countPoints(
            std::max<qint64>(0, spans * static_cast<qint64>(p) + 1 - static_cast<qint64>(control.size())), start.line))
        return e;
    std::vector<geo::Bezier> pieces = bezierPieces(knots, control, static_cast<int>(p));
    // Kontur writes a closed curve as a spline that ends where it starts.
    const bool closed =
        !pieces.empty() && pieces.size() >= 2 && pieces.back().endPoint() == pieces.front().startPoint();
    return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(pieces), closed), place);
}

std::optional<Error> Reader::polyline(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    long long flags = 0;
    for (const Group &g : entity.groups)
        if (g.code == 70)
            flags = integerOf(g);
    if ((flags & (16 | 64)) != 0) {
        // Polygon meshes and polyface meshes are surfaces, not curves.
        skip(out, DxfSkipped::Solid3D);
        return std::nullopt;
    }
    std::vector<geo::Point> pts;
    std::vector<double> bulges;
    for (const Vertex &v : entity.vertices) {
        // A spline-fit polyline's frame (flag 16) is not drawn; its fitted vertices (8) are.
        if ((v.flags & 16) != 0)
            continue;
        if (auto e = countPoints(1, v.line))
            return e;
        pts.emplace_back(v.x, v.y);
        bulges.push_back(v.bulge);
    }
    auto segments =
        polylineSegments(pts, bulges, (flags & 1) != 0, m_options.arcTolerance, m_options.limits.maxPoints - m_points);
    if (auto e = countPoints(interiorPoints(segments), entity.start.line))
        return e;
    return addCurve(out, entity.start, entity.groups, geo::PiecewiseBezier(std::move(segments), (flags & 1) != 0),
                    place);
}

} // namespace kontur::io::dxfread
