// DXF import (see dxf.h): a HATCH's boundary paths as closed curves. Polyline paths (vertices and
// bulges) and edge paths (lines, circular and elliptic arcs, splines) are read in their order, because
// the group codes repeat, and their edges joined into loops. The reader's insides: dxfread_p.h.
#include "io/dxf.h"

#include "io/dxfread_p.h"
#include "io/svgpath.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::io::dxfread {

namespace {

geo::Bezier reversed(const geo::Bezier &b)
{
    std::vector<geo::Point> pts = b.controlPoints();
    std::reverse(pts.begin(), pts.end());
    return geo::Bezier(std::move(pts));
}

// The same point within what a file's printed digits can tell apart (12 significant digits and more).
bool samePoint(const geo::Point &a, const geo::Point &b)
{
    return (a - b).norm() <= 1e-9 * (1.0 + std::max(a.norm(), b.norm()));
}

// The Bézier b with its first (or last) point moved exactly onto p: joined pieces meet bit for bit.
geo::Bezier withStart(const geo::Bezier &b, const geo::Point &p)
{
    std::vector<geo::Point> pts = b.controlPoints();
    pts.front() = p;
    return geo::Bezier(std::move(pts));
}

// The edges of a path joined into loops; an edge that meets the loop backwards is turned round (as
// ezdxf joins them), one that does not meet it starts a new loop.
void joinEdges(std::vector<std::vector<geo::Bezier>> &edges, std::vector<std::vector<geo::Bezier>> &loops)
{
    std::vector<geo::Bezier> loop;
    for (std::vector<geo::Bezier> &pieces : edges) {
        if (!loop.empty() && !samePoint(loop.back().endPoint(), pieces.front().startPoint()) &&
            samePoint(loop.back().endPoint(), pieces.back().endPoint())) {
            std::reverse(pieces.begin(), pieces.end());
            for (geo::Bezier &b : pieces)
                b = reversed(b);
        }
        if (!loop.empty() && !samePoint(loop.back().endPoint(), pieces.front().startPoint())) {
            loops.push_back(std::move(loop));
            loop.clear();
        }
        for (geo::Bezier &b : pieces)
            loop.push_back(loop.empty() ? std::move(b) : withStart(b, loop.back().endPoint()));
    }
    if (!loop.empty())
        loops.push_back(std::move(loop));
}

} // namespace

// The boundary's groups in their order: a group missing where the DXF Reference puts one makes the
// hatch malformed (it is then skipped, not refused); a number that is no number is an error.
struct Reader::HatchCursor
{
    const Reader &reader;
    const std::vector<Group> &groups;
    std::size_t i = 0;
    bool malformed = false;
    bool unsupported = false; // a rational spline edge

    [[nodiscard]] bool at(int code) const { return i < groups.size() && groups[i].code == code; }
    std::optional<Error> real(int code, double &v)
    {
        if (!at(code)) {
            malformed = true;
            return std::nullopt;
        }
        return reader.number(groups[i++], v);
    }
    long long whole(int code)
    {
        if (!at(code)) {
            malformed = true;
            return 0;
        }
        return integerOf(groups[i++]);
    }
    std::optional<Error> point(int code, geo::Point &p)
    {
        if (auto e = real(code, p.x()))
            return e;
        return real(code + 10, p.y());
    }
};

// A HATCH's boundary paths (DXF Reference, "Boundary path data"), read in their order because the
// group codes repeat: polyline paths (vertices and bulges) and edge paths (lines, circular and elliptic
// arcs, splines). Each loop becomes a closed curve. A path that names its source objects (97 > 0) is
// the outline of entities drawn on their own, which are read as themselves: it is not read twice.
// Arc and ellipse edges drawn clockwise (73 = 0) store their angles as 360° minus the angle.
std::optional<Error> Reader::hatch(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    const std::vector<Group> &groups = entity.groups;
    double ex = 0, ey = 0, ez = 1;
    std::size_t i = 0;
    for (; i < groups.size() && groups[i].code != 91; ++i)
        if (groups[i].code == 210 || groups[i].code == 220 || groups[i].code == 230)
            if (auto e = number(groups[i], groups[i].code == 210 ? ex : groups[i].code == 220 ? ey : ez))
                return e;
    if (std::abs(ex) > 1e-12 || std::abs(ey) > 1e-12 || std::abs(std::abs(ez) - 1.0) > 1e-12) {
        skip(out, DxfSkipped::Solid3D);
        return std::nullopt;
    }
    if (i >= groups.size())
        return std::nullopt; // no boundary
    HatchCursor c{*this, groups, i};
    const long long paths = integerOf(groups[c.i++]);
    std::vector<Pieces> loops;
    for (long long path = 0; path < paths && !c.malformed && !c.unsupported; ++path) {
        const long long type = c.whole(92);
        // Each edge as Bézier pieces, in its own direction.
        std::vector<Pieces> edges;
        if ((type & 2) != 0) {
            if (auto e = hatchPolylinePath(c, entity.start.line, edges))
                return e;
        } else if (auto e = hatchEdgePath(c, entity.start.line, edges)) {
            return e;
        }
        long long sources = 0;
        if (c.at(97)) {
            sources = c.whole(97);
            while (c.at(330))
                ++c.i;
        }
        if (c.malformed || c.unsupported || sources > 0)
            continue;
        joinEdges(edges, loops);
    }
    if (c.malformed || c.unsupported) {
        skip(out, c.unsupported ? DxfSkipped::Spline : DxfSkipped::Other);
        return std::nullopt;
    }
    return addHatchLoops(entity, loops, ez < 0, place, out);
}

// A polyline path: its vertices (10, 20) with their bulges (42) when it has them (72).
std::optional<Error> Reader::hatchPolylinePath(HatchCursor &c, int line, std::vector<Pieces> &edges)
{
    const bool bulged = c.whole(72) != 0;
    const bool closed = c.whole(73) != 0;
    const long long count = c.whole(93);
    std::vector<geo::Point> pts;
    std::vector<double> bulges;
    for (long long k = 0; k < count && !c.malformed; ++k) {
        geo::Point p;
        double bulge = 0;
        if (auto e = c.point(10, p))
            return e;
        if (bulged && c.at(42))
            if (auto e = c.real(42, bulge))
                return e;
        if (auto e = countPoints(1, line))
            return e;
        pts.push_back(p);
        bulges.push_back(bulge);
    }
    edges.push_back(polylineSegments(pts, bulges, closed || pts.size() > 2, m_options.arcTolerance,
                                     m_options.limits.maxPoints - m_points));
    return std::nullopt;
}

// An edge path: its edges by type (72: 1 line, 2 circular arc, 3 elliptic arc, 4 spline).
std::optional<Error> Reader::hatchEdgePath(HatchCursor &c, int line, std::vector<Pieces> &edges)
{
    const long long count = c.whole(93);
    for (long long k = 0; k < count && !c.malformed && !c.unsupported; ++k) {
        const long long edge = c.whole(72);
        Pieces pieces;
        if (edge == 1) {
            geo::Point a, b;
            if (auto e = c.point(10, a))
                return e;
            if (auto e = c.point(11, b))
                return e;
            if (a != b)
                pieces.emplace_back(std::vector<geo::Point>{a, b});
        } else if (edge == 2 || edge == 3) {
            if (auto e = hatchArcEdge(c, edge, pieces))
                return e;
        } else if (edge == 4) {
            if (auto e = hatchSplineEdge(c, line, pieces))
                return e;
        } else {
            c.malformed = true;
        }
        if (!pieces.empty())
            edges.push_back(std::move(pieces));
    }
    return std::nullopt;
}

// A circular (2) or elliptic (3) arc edge. Drawn clockwise (73 = 0), it stores its angles as 360°
// minus the angle; an ellipse edge's angles are the points' angles, not the parameters.
std::optional<Error> Reader::hatchArcEdge(HatchCursor &c, long long edge, Pieces &pieces)
{
    geo::Point center, major(1, 0);
    double radius = 1, ratio = 1, a0 = 0, a1 = 360;
    if (auto e = c.point(10, center))
        return e;
    if (edge == 3) {
        if (auto e = c.point(11, major))
            return e;
        if (auto e = c.real(40, ratio))
            return e;
        radius = major.norm();
    } else if (auto e = c.real(40, radius)) {
        return e;
    }
    if (auto e = c.real(50, a0))
        return e;
    if (auto e = c.real(51, a1))
        return e;
    const bool ccw = c.whole(73) != 0;
    if (!ccw) {
        const double s = 360.0 - a1, t = 360.0 - a0;
        a0 = s;
        a1 = t;
    }
    bool full = false;
    const double sweep = sweepOf(a0, a1, 360.0, full);
    if (radius > 0 && ratio > 0 && sweep > 0) {
        const double rad = std::numbers::pi / 180.0;
        const double t0 = std::atan2(std::sin(a0 * rad) / ratio, std::cos(a0 * rad));
        double dt = full ? 2 * std::numbers::pi : std::atan2(std::sin(a1 * rad) / ratio, std::cos(a1 * rad)) - t0;
        if (!full && dt <= 0)
            dt += 2 * std::numbers::pi;
        pieces = arcToCubics(center, radius, radius * ratio, std::atan2(major.y(), major.x()), t0, dt,
                             m_options.arcTolerance);
        if (!ccw) {
            std::reverse(pieces.begin(), pieces.end());
            for (geo::Bezier &b : pieces)
                b = reversed(b);
        }
    }
    return std::nullopt;
}

// A spline edge: degree, knots and control points (weights where rational, then fit points, which
// are passed over). Unequal weights make it unsupported, knots that do not fit malformed.
std::optional<Error> Reader::hatchSplineEdge(HatchCursor &c, int line, Pieces &pieces)
{
    const long long degree = c.whole(94);
    const bool rational = c.whole(73) != 0;
    (void)c.whole(74); // periodic
    const long long knotCount = c.whole(95), controlCount = c.whole(96);
    if (degree < 1 || degree > 100 || knotCount != controlCount + degree + 1 || controlCount < degree + 1 ||
        controlCount > m_options.limits.maxPoints) {
        c.malformed = true;
        return std::nullopt;
    }
    std::vector<double> knots(static_cast<std::size_t>(knotCount));
    for (double &u : knots)
        if (auto e = c.real(40, u))
            return e;
    std::vector<geo::Point> control(static_cast<std::size_t>(controlCount));
    std::vector<double> weights;
    for (geo::Point &p : control) {
        if (auto e = c.point(10, p))
            return e;
        if (rational && c.at(42)) {
            weights.push_back(0);
            if (auto e = c.real(42, weights.back()))
                return e;
        }
    }
    if (c.at(97)) {
        const long long fit = c.whole(97);
        for (long long f = 0; f < fit && !c.malformed; ++f) {
            geo::Point p;
            if (auto e = c.point(11, p))
                return e;
        }
        for (int code : {12, 13})
            if (c.at(code)) {
                geo::Point p;
                if (auto e = c.point(code, p))
                    return e;
            }
    }
    if (c.malformed)
        return std::nullopt;
    if (std::any_of(weights.begin(), weights.end(), [&](double w) { return w != weights.front(); })) {
        c.unsupported = true;
        return std::nullopt;
    }
    bool increasing =
        knots[static_cast<std::size_t>(degree)] < knots[knots.size() - 1 - static_cast<std::size_t>(degree)];
    for (std::size_t k = 1; k < knots.size(); ++k)
        increasing = increasing && knots[k - 1] <= knots[k];
    if (!increasing) {
        c.malformed = true;
        return std::nullopt;
    }
    if (auto e = countPoints(controlCount, line))
        return e;
    pieces = bezierPieces(knots, control, static_cast<int>(degree));
    return std::nullopt;
}

// The loops as closed curves (seen from below, `mirrored`, with x the other way), each counted.
std::optional<Error> Reader::addHatchLoops(const RawEntity &entity, std::vector<Pieces> &loops, bool mirrored,
                                           const Placement &place, DxfImport &out)
{
    for (std::vector<geo::Bezier> &loop : loops) {
        if (mirrored)
            for (geo::Bezier &b : loop) {
                std::vector<geo::Point> pts = b.controlPoints();
                for (geo::Point &p : pts)
                    p.x() = 0.0 - p.x();
                b = geo::Bezier(std::move(pts));
            }
        qint64 points = 1;
        for (const geo::Bezier &b : loop)
            points += b.degree();
        if (auto e = countPoints(points, entity.start.line))
            return e;
        const bool closed = samePoint(loop.back().endPoint(), loop.front().startPoint());
        if (closed) {
            std::vector<geo::Point> last = loop.back().controlPoints();
            last.back() = loop.front().startPoint();
            loop.back() = geo::Bezier(std::move(last));
        }
        if (auto e = addCurve(out, entity.start, entity.groups, geo::PiecewiseBezier(std::move(loop), closed), place))
            return e;
    }
    return std::nullopt;
}

} // namespace kontur::io::dxfread
