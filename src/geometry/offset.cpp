// Offset curves: Hermite approximation with subdivision, corner joins, and trimming of the raw
// offset's loops by distance (see offset.h for the sources). Over 600 lines because the bounds that
// keep it finite (the resolvable tolerance, the work budget, the sorted self-intersection search)
// belong to the one algorithm they bound; split apart they would reach into each other's state.
#include "geometry/offset.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

namespace kontur::geo {

namespace {

thread_local std::uint64_t t_work = 0;

// The steps one offsetCurve call has spent (see kOffsetBudget). Every adaptive loop checks over()
// and stops refining once the budget is spent or the caller cancelled (OffsetControl); the call
// then reports WorkBudget or Cancelled.
struct Work
{
    OffsetControl *control = nullptr;
    std::uint64_t used = 0;
    std::uint64_t published = 0;
    void add(std::uint64_t n)
    {
        used += n;
        t_work += n;
        if (control && used - published >= kOffsetPublishSteps) {
            control->work.store(used, std::memory_order_relaxed);
            published = used;
        }
    }
    // A relaxed load per check: the flag orders nothing else, and a plain load costs no more than
    // the comparison beside it, so Cancel is seen within a few evaluations.
    [[nodiscard]] bool cancelled() const { return control && control->cancelled.load(std::memory_order_relaxed); }
    [[nodiscard]] bool over() const { return used > kOffsetBudget || cancelled(); }
    void progress(double p) const
    {
        if (control)
            control->progress.store(p, std::memory_order_relaxed);
    }
    void finish() const
    {
        if (control)
            control->work.store(used, std::memory_order_relaxed);
    }
};

double cross(const Point &a, const Point &b)
{
    return a.x() * b.y() - a.y() * b.x();
}
// |v| without overflow: Eigen's norm() squares first, which overflows beyond 1e154 (curves at 1e300
// are read and must be offset or refused, not looped on).
double length(const Point &v)
{
    return std::hypot(v.x(), v.y());
}

Point leftNormal(const Point &t)
{
    return Point(-t.y(), t.x());
}

Bezier line(const Point &a, const Point &b)
{
    return Bezier({a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
}

double scaleOf(const Bezier &b)
{
    double m = 0.0;
    for (const Point &p : b.controlPoints())
        m = std::max(m, p.cwiseAbs().maxCoeff());
    return std::max(m, 1e-300);
}

bool degenerate(const Bezier &b)
{
    const double eps = 1e-12 * scaleOf(b);
    for (const Point &p : b.controlPoints())
        if (length(p - b.startPoint()) > eps)
            return false;
    return true;
}

// The unit tangent at t; where the speed vanishes (a handle on its knot), the direction the curve
// leaves in (a short chord), else the whole chord.
Point unitTangent(const Bezier &b, double t)
{
    const Point d = b.derivative(t, 1);
    const double eps = 1e-12 * scaleOf(b);
    if (const double speed = length(d); speed > eps)
        return d / speed;
    const double h = 1e-6;
    const Point chord = b.eval(std::min(t + h, 1.0)) - b.eval(std::max(t - h, 0.0));
    if (const double l = length(chord); l > 1e-3 * eps)
        return chord / l;
    const Point whole = b.endPoint() - b.startPoint();
    return length(whole) > 0.0 ? Point(whole / length(whole)) : Point(1.0, 0.0);
}

struct OffsetPoint
{
    Point p;
    Point d; // O'(t)
};

// O(t) = B(t) + sd·N(t) with N the left unit normal; O'(t) = B'(t)(1 − sd·κ(t)) since N' = −κ B'
// (Frenet–Serret with the signed curvature κ).
OffsetPoint offsetAt(const Bezier &b, double t, double sd)
{
    const Point d1 = b.derivative(t, 1);
    const double speed = length(d1);
    const Point n = leftNormal(unitTangent(b, t));
    if (speed <= 1e-12 * scaleOf(b))
        return {b.eval(t) + sd * n, Point::Zero()};
    // κ = (B' × B'') / |B'|³ with both derivatives divided by the speed first: the cross product of
    // the raw ones overflows for curves beyond 1e154.
    const Point u1 = d1 / speed, u2 = b.derivative(t, 2) / speed;
    const double kappa = cross(u1, u2) / speed;
    return {b.eval(t) + sd * n, d1 * (1.0 - sd * kappa)};
}

struct RawPiece
{
    Bezier curve;
    bool convexJoin = false; // a bevel or miter line: legitimately nearer the source than the distance
};

// The cubic Hermite piece over [t0, t1] of the source: exact offset points and derivatives at both
// ends (Klass 1983); halved until the largest sampled gap to the exact offset is below `tol`.
void fitInterval(const Bezier &b, double sd, double t0, const OffsetPoint &o0, double t1, const OffsetPoint &o1,
                 double tol, int depth, Work &work, std::vector<RawPiece> &out)
{
    const double h = t1 - t0;
    work.add(8);
    const Bezier c({o0.p, o0.p + h / 3.0 * o0.d, o1.p - h / 3.0 * o1.d, o1.p});
    double err = 0.0;
    for (int k = 1; k < 8; ++k) {
        const double u = k / 8.0;
        err = std::max(err, length(c.eval(u) - offsetAt(b, t0 + u * h, sd).p));
    }
    if (err <= tol || depth >= 30 || h < 1e-9 || work.over()) {
        out.push_back({c, false});
        return;
    }
    const double tm = 0.5 * (t0 + t1);
    const OffsetPoint om = offsetAt(b, tm, sd);
    fitInterval(b, sd, t0, o0, tm, om, tol, depth + 1, work, out);
    fitInterval(b, sd, tm, om, t1, o1, tol, depth + 1, work, out);
}

// A circular arc about `centre` from a to b (both at `radius`), turning by `sweep` radians (signed,
// positive counter-clockwise), as cubics with handles 4/3·tan(φ/4)·r (the standard approximation;
// radial error below 2.8e-4 r for a quarter circle), split until the sampled error is below `tol`.
void roundJoin(const Point &centre, double radius, const Point &a, double sweep, double tol, std::vector<RawPiece> &out)
{
    const double start = std::atan2(a.y() - centre.y(), a.x() - centre.x());
    for (int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 2)))); n <= 256; n *= 2) {
        std::vector<RawPiece> pieces;
        double err = 0.0;
        const double phi = sweep / n;
        const double k = 4.0 / 3.0 * std::tan(phi / 4.0) * radius;
        for (int i = 0; i < n; ++i) {
            const double a0 = start + i * phi, a1 = a0 + phi;
            const Point p0 = i == 0 ? a : centre + radius * Point(std::cos(a0), std::sin(a0));
            const Point p3 = centre + radius * Point(std::cos(a1), std::sin(a1));
            const Bezier c(
                {p0, p0 + k * Point(-std::sin(a0), std::cos(a0)), p3 - k * Point(-std::sin(a1), std::cos(a1)), p3});
            for (double u : {0.25, 0.5})
                err = std::max(err, std::abs(length(c.eval(u) - centre) - radius));
            pieces.push_back({c, false});
        }
        if (err <= tol || n >= 256) {
            out.insert(out.end(), pieces.begin(), pieces.end());
            return;
        }
    }
}

// A polyline of a piece with the parameter of each vertex, within `tol` of the piece.
struct Polyline
{
    std::vector<double> t;
    std::vector<Point> p;
};

void flattenWithParams(const Bezier &c, double t0, double t1, double tol, int depth, Work &work, Polyline &out)
{
    work.add(1);
    const auto &cp = c.controlPoints();
    const Point chord = cp.back() - cp.front();
    const double len = chord.norm();
    double dev = 0.0;
    for (std::size_t i = 1; i + 1 < cp.size(); ++i)
        dev = std::max(dev, len > 0 ? std::abs(cross(chord, cp[i] - cp.front())) / len : (cp[i] - cp.front()).norm());
    if (dev <= tol || depth >= 18 || work.over()) {
        out.t.push_back(t1);
        out.p.push_back(cp.back());
        return;
    }
    const auto [l, r] = c.split(0.5);
    const double tm = 0.5 * (t0 + t1);
    flattenWithParams(l, t0, tm, tol, depth + 1, work, out);
    flattenWithParams(r, tm, t1, tol, depth + 1, work, out);
}

struct Crossing
{
    double ga = 0.0, gb = 0.0; // chain parameters (piece index + t), ga < gb
    Point point;
};

// Newton's method on C_i(s) − C_j(u) = 0 from the polyline estimate; the estimate stays where
// Newton leaves the pieces or does not converge.
void refine(const Bezier &ci, const Bezier &cj, double &s, double &u, Point &point, double tol)
{
    double ss = s, uu = u;
    for (int it = 0; it < 12; ++it) {
        const Point f = ci.eval(ss) - cj.eval(uu);
        const Point di = ci.derivative(ss), dj = cj.derivative(uu);
        const double det = cross(di, -dj);
        if (std::abs(det) < 1e-300)
            return;
        // [di, -dj] (ds, du)ᵀ = −f by Cramer's rule.
        const double ds = cross(-f, -dj) / det;
        const double du = cross(di, -f) / det;
        ss += ds;
        uu += du;
        if (!(ss >= 0.0 && ss <= 1.0 && uu >= 0.0 && uu <= 1.0))
            return;
    }
    const Point a = ci.eval(ss), b = cj.eval(uu);
    if ((a - b).norm() <= tol && (a - point).norm() <= 4 * tol) {
        s = ss;
        u = uu;
        point = 0.5 * (a + b);
    }
}

// Stops early (with what it found) once the work budget is spent; the caller checks work.over().
std::vector<Crossing> selfIntersections(const std::vector<RawPiece> &pieces, bool closed, double tol, Work &work)
{
    const int n = static_cast<int>(pieces.size());
    std::vector<Polyline> lines(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        if (work.over())
            return {};
        Polyline &pl = lines[static_cast<std::size_t>(i)];
        pl.t.push_back(0.0);
        pl.p.push_back(pieces[static_cast<std::size_t>(i)].curve.startPoint());
        flattenWithParams(pieces[static_cast<std::size_t>(i)].curve, 0.0, 1.0, tol, 0, work, pl);
    }
    // Sweep and prune (a sort of the edges by their left end, each compared with those that begin
    // before it ends): about linear in the edges for an offset, where the all-pairs loop it replaced
    // was quadratic in a piece's vertices.
    struct Edge
    {
        double x0, x1;
        int piece;
        std::size_t k;
    };
    std::vector<Edge> edges;
    for (int i = 0; i < n; ++i) {
        const Polyline &pl = lines[static_cast<std::size_t>(i)];
        for (std::size_t k = 0; k + 1 < pl.p.size(); ++k)
            edges.push_back({std::min(pl.p[k].x(), pl.p[k + 1].x()), std::max(pl.p[k].x(), pl.p[k + 1].x()), i, k});
    }
    work.add(edges.size());
    if (work.over())
        return {};
    std::sort(edges.begin(), edges.end(), [](const Edge &x, const Edge &y) { return x.x0 < y.x0; });
    std::vector<Crossing> out;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        if (work.over())
            return out;
        if (e % 1024 == 0)
            work.progress(0.4 + 0.1 * static_cast<double>(e) / static_cast<double>(edges.size()));
        for (std::size_t f = e + 1; f < edges.size() && edges[f].x0 <= edges[e].x1; ++f) {
            work.add(1);
            // (i, ka) before (j, kb) in the chain, as the crossing's parameters are ordered.
            Edge ea = edges[e], eb = edges[f];
            if (ea.piece > eb.piece || (ea.piece == eb.piece && ea.k > eb.k))
                std::swap(ea, eb);
            const int i = ea.piece, j = eb.piece;
            const std::size_t ka = ea.k, kb = eb.k;
            const Polyline &a = lines[static_cast<std::size_t>(i)];
            const Polyline &b = lines[static_cast<std::size_t>(j)];
            if (i == j && kb < ka + 2)
                continue; // the same edge or its neighbour
            // The joint two neighbouring pieces share is not a crossing.
            const bool next = j == i + 1 || (closed && i == 0 && j == n - 1 && n > 1);
            if (next && j == i + 1 && ka + 2 == a.p.size() && kb == 0)
                continue;
            if (next && j != i + 1 && ka == 0 && kb + 2 == b.p.size())
                continue;
            const Point pa = a.p[ka], ra = a.p[ka + 1] - pa;
            const Point pb = b.p[kb], rb = b.p[kb + 1] - pb;
            if (std::max(pa.y(), a.p[ka + 1].y()) < std::min(pb.y(), b.p[kb + 1].y()) ||
                std::max(pb.y(), b.p[kb + 1].y()) < std::min(pa.y(), a.p[ka + 1].y()))
                continue;
            const double den = cross(ra, rb);
            if (std::abs(den) <= 1e-300)
                continue;
            const double la = cross(pb - pa, rb) / den;
            const double lb = cross(pb - pa, ra) / den;
            if (!(la >= 0.0 && la < 1.0 && lb >= 0.0 && lb < 1.0))
                continue;
            double s = a.t[ka] + la * (a.t[ka + 1] - a.t[ka]);
            double u = b.t[kb] + lb * (b.t[kb + 1] - b.t[kb]);
            Point point = pa + la * ra;
            refine(pieces[static_cast<std::size_t>(i)].curve, pieces[static_cast<std::size_t>(j)].curve, s, u, point,
                   tol);
            double ga = i + s, gb = j + u;
            if (ga > gb)
                std::swap(ga, gb);
            if (gb - ga < 1e-9)
                continue;
            work.add(1 + out.size() / 16);
            bool duplicate = false;
            for (const Crossing &c : out)
                duplicate = duplicate || (std::abs(c.ga - ga) < 1e-7 && std::abs(c.gb - gb) < 1e-7);
            if (!duplicate)
                out.push_back({ga, gb, point});
        }
    }
    return out;
}

// A stretch of the raw offset between two split points, as portions of pieces.
struct Arc
{
    double g0 = 0.0, g1 = 0.0; // chain parameters; g1 may pass the piece count on a closed curve
    int startId = -1, endId = -1;
    Point startPoint, endPoint;
    bool kept = true;
};

// The turned-back corner at `v` between a side and a hem (OffsetOptions::hems): the side's offset line
// (through `side` along `sideDir`) meets the hem line (through v along `hemDir`) at P, and P + u·m,
// with m the side's direction mirrored about the hem line, meets the hem's offset line (through `hem`
// along hemDir) at Q. None when the lines are parallel.
struct TurnBack
{
    Point p, q;
};

std::optional<TurnBack> turnBack(const Point &v, const Point &side, const Point &sideDir, const Point &hem,
                                 const Point &hemDir)
{
    const double den = cross(sideDir, hemDir);
    const Point mirrored = 2.0 * sideDir.dot(hemDir) * hemDir - sideDir;
    const double den2 = cross(mirrored, hemDir);
    if (std::abs(den) < 1e-12 || std::abs(den2) < 1e-12)
        return std::nullopt;
    const Point p = side + cross(v - side, hemDir) / den * sideDir;
    return TurnBack{p, p + cross(hem - p, hemDir) / den2 * mirrored};
}

// The parameter in [0, 1] where (c(t) − q)·dir changes sign, by bisection (f(0) and f(1) differ in sign).
double crossingOf(const Bezier &c, const Point &q, const Point &dir)
{
    double lo = 0.0, hi = 1.0;
    const bool rising = (c.eval(1.0) - q).dot(dir) > (c.eval(0.0) - q).dot(dir);
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((c.eval(mid) - q).dot(dir) < 0.0) == rising ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi);
}

// The hem's offset, raw[first, last), cut at q: from its start up to where it passes q along `dir`
// (the hem's direction), dropped (`front`), or from there on to its end (else); the cut ends at q.
void trimHem(std::vector<RawPiece> &raw, std::size_t first, std::size_t last, const Point &q, const Point &dir,
             bool front)
{
    const auto ahead = [&](const Point &p) { return (p - q).dot(dir) > 0.0; };
    if (front) {
        for (std::size_t k = first; k < last; ++k) {
            const Bezier &c = raw[k].curve;
            if (!ahead(c.endPoint()))
                continue;
            std::vector<Point> cp =
                ahead(c.startPoint()) ? c.controlPoints() : c.subCurve(crossingOf(c, q, dir), 1.0).controlPoints();
            cp[1] += q - cp[0];
            cp[0] = q;
            raw[k].curve = Bezier(std::move(cp));
            raw.erase(raw.begin() + static_cast<std::ptrdiff_t>(first), raw.begin() + static_cast<std::ptrdiff_t>(k));
            return;
        }
        return;
    }
    for (std::size_t k = last; k-- > first;) {
        const Bezier &c = raw[k].curve;
        if (ahead(c.startPoint()))
            continue;
        std::vector<Point> cp =
            !ahead(c.endPoint()) ? c.controlPoints() : c.subCurve(0.0, crossingOf(c, q, dir)).controlPoints();
        cp[cp.size() - 2] += q - cp.back();
        cp.back() = q;
        raw[k].curve = Bezier(std::move(cp));
        raw.erase(raw.begin() + static_cast<std::ptrdiff_t>(k) + 1, raw.begin() + static_cast<std::ptrdiff_t>(last));
        return;
    }
}

void pushLine(std::vector<RawPiece> &raw, const Point &a, const Point &b, double dot)
{
    if ((b - a).norm() > dot)
        raw.push_back({line(a, b), true});
}

// Where the next segment's offset is to begin (a turned-back corner before a hem whose offset starts
// beyond it): cut there once it is fitted.
struct PendingCut
{
    Point q, dir;
};

// A turned-back corner (OffsetOptions::hems) at the joint v after the pieces of the segment that begin
// at raw[segmentStart]; `hemNext` when the hem is the segment after the joint. a and ta: the end of the
// offset before the joint and the tangent there; bb and tb: after it. The corner's lines are appended;
// where the hem's offset passes Q it is cut there (the hem before the joint: now; after it: `pending`).
// False, and nothing done, where the lines are parallel or P or Q lie beyond `limit` from v.
bool turnedBackJoin(std::vector<RawPiece> &raw, std::size_t segmentStart, const Point &v, const Point &a,
                    const Point &ta, const Point &bb, const Point &tb, bool hemNext, double limit, double dot,
                    std::optional<PendingCut> &pending)
{
    const auto corner = hemNext ? turnBack(v, a, ta, bb, tb) : turnBack(v, bb, tb, a, ta);
    if (!corner || (corner->p - v).norm() > limit || (corner->q - v).norm() > limit)
        return false;
    const Point p = corner->p, q = corner->q;
    if (hemNext) {
        pushLine(raw, a, p, dot);
        pushLine(raw, p, q, dot);
        if ((bb - q).dot(tb) > 0.0)
            pushLine(raw, q, bb, dot);
        else
            pending = PendingCut{q, tb};
    } else {
        if ((q - a).dot(ta) > 0.0)
            pushLine(raw, a, q, dot);
        else
            trimHem(raw, segmentStart, raw.size(), q, ta, false);
        pushLine(raw, q, p, dot);
        pushLine(raw, p, bb, dot);
    }
    return true;
}

// The source's segments of one width (> 0) and how near to them a part of the offset may not come.
struct WidthGroup
{
    PiecewiseBezier segments;
    double threshold = 0.0;
};

std::vector<WidthGroup> widthGroups(const std::vector<Bezier> &segments, const std::vector<double> &dists, double tol)
{
    std::vector<double> widths;
    for (double w : dists)
        if (w > 0.0 && std::find(widths.begin(), widths.end(), w) == widths.end())
            widths.push_back(w);
    std::vector<WidthGroup> out;
    for (double w : widths) {
        std::vector<Bezier> of;
        for (std::size_t i = 0; i < segments.size(); ++i)
            if (dists[i] == w)
                of.push_back(segments[i]);
        out.push_back({PiecewiseBezier(std::move(of)), w - std::max(0.75 * tol, 1e-9 * w)});
    }
    return out;
}

double signedArea(const PiecewiseBezier &source)
{
    std::vector<Point> poly;
    const Box box = source.boundingBox();
    const double size = std::max(box.sizes().maxCoeff(), 1e-300);
    source.flatten(1e-4 * size, poly);
    double a = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i)
        a += cross(poly[i], poly[(i + 1) % poly.size()]);
    return 0.5 * a;
}

} // namespace

const char *offsetSideId(OffsetSide side)
{
    switch (side) {
    case OffsetSide::Outside:
        return "outside";
    case OffsetSide::Inside:
        return "inside";
    case OffsetSide::Left:
        return "left";
    case OffsetSide::Right:
        return "right";
    }
    return "outside";
}

const char *offsetJoinId(OffsetJoin join)
{
    switch (join) {
    case OffsetJoin::Miter:
        return "miter";
    case OffsetJoin::Bevel:
        return "bevel";
    case OffsetJoin::Round:
        return "round";
    }
    return "miter";
}

bool offsetSideFromId(std::string_view id, OffsetSide &side)
{
    for (OffsetSide s : {OffsetSide::Outside, OffsetSide::Inside, OffsetSide::Left, OffsetSide::Right})
        if (id == offsetSideId(s)) {
            side = s;
            return true;
        }
    return false;
}

bool offsetJoinFromId(std::string_view id, OffsetJoin &join)
{
    for (OffsetJoin j : {OffsetJoin::Miter, OffsetJoin::Bevel, OffsetJoin::Round})
        if (id == offsetJoinId(j)) {
            join = j;
            return true;
        }
    return false;
}

int offsetSign(const PiecewiseBezier &source, OffsetSide side)
{
    switch (side) {
    case OffsetSide::Left:
        return 1;
    case OffsetSide::Right:
        return -1;
    case OffsetSide::Outside:
    case OffsetSide::Inside: {
        // A counter-clockwise curve (positive area, shoelace formula) has its area on the left.
        const int outside = signedArea(source) > 0.0 ? -1 : 1;
        return side == OffsetSide::Outside ? outside : -outside;
    }
    }
    return 1;
}

double resolvableOffsetTolerance(const PiecewiseBezier &source, double distance)
{
    double m = 0.0;
    for (const Bezier &b : source.segments())
        for (const Point &p : b.controlPoints())
            m = std::max(m, p.cwiseAbs().maxCoeff());
    // 64 ε: a dozen roundings in an offset point and the subtraction that measures its error, with room.
    const double floor = 64.0 * std::numeric_limits<double>::epsilon() * (m + std::abs(distance));
    return std::max(floor, std::numeric_limits<double>::min());
}

namespace detail {
std::uint64_t offsetWork()
{
    return t_work;
}
void resetOffsetWork()
{
    t_work = 0;
}
} // namespace detail

Result<OffsetResult> offsetCurve(const PiecewiseBezier &source, const OffsetOptions &options, OffsetControl *control)
{
    const double d = options.distance;
    double tol = options.tolerance;
    if (!(std::isfinite(d) && d > 0.0))
        return Error{ErrorCode::InvalidArgument, "the offset distance must be positive and finite"};
    if (!(std::isfinite(tol) && tol > 0.0))
        return Error{ErrorCode::InvalidArgument, "the offset tolerance must be positive and finite"};
    if (!(options.miterLimit >= 0.0))
        return Error{ErrorCode::InvalidArgument, "the miter limit must not be negative"};
    const bool perSeam = !options.segmentDistances.empty();
    if (perSeam && options.segmentDistances.size() != source.segments().size())
        return Error{ErrorCode::InvalidArgument, "one offset distance per segment is needed"};
    if (!options.hems.empty() && (!perSeam || options.hems.size() != source.segments().size()))
        return Error{ErrorCode::InvalidArgument, "hems need one flag and one distance per segment"};
    std::vector<Bezier> segments;
    std::vector<double> dists; // each kept segment's distance
    std::vector<bool> hems;    // each kept segment's hem flag
    for (std::size_t i = 0; i < source.segments().size(); ++i) {
        const Bezier &b = source.segments()[i];
        for (const Point &p : b.controlPoints())
            if (!p.allFinite())
                return Error{ErrorCode::NonFiniteInput, "a control point is not finite"};
        const double di = perSeam ? options.segmentDistances[i] : d;
        if (!(std::isfinite(di) && di >= 0.0))
            return Error{ErrorCode::InvalidArgument, "a segment's offset distance must be finite and not negative"};
        if (!b.isEmpty() && !degenerate(b)) {
            segments.push_back(b);
            dists.push_back(di);
            hems.push_back(!options.hems.empty() && options.hems[i]);
        }
    }
    if (segments.empty())
        return Error{ErrorCode::TooFewPoints, "no piece of non-zero size to offset"};
    const bool closed = source.isClosed();
    const PiecewiseBezier src(segments, closed);
    const double size = src.boundingBox().sizes().maxCoeff();
    if (!std::isfinite(size))
        return Error{ErrorCode::NonFiniteInput, "the curve's size passes the largest number"};
    const double widest = std::max(d, *std::max_element(dists.begin(), dists.end()));
    if (widest > kOffsetMaxRatio * size)
        return Error{ErrorCode::OutOfProportion, "the distance is more than " +
                                                     std::to_string(static_cast<int>(kOffsetMaxRatio)) +
                                                     " times the curve's size"};
    tol = std::max(tol, resolvableOffsetTolerance(src, widest));
    if (!std::isfinite(tol))
        return Error{ErrorCode::NonFiniteInput, "the offset passes the largest number"};
    const int sign = offsetSign(src, options.side);
    Work work;
    work.control = control;
    const auto overBudget = [&work] {
        work.finish();
        if (work.cancelled())
            return Error{ErrorCode::Cancelled, "the offset was cancelled"};
        return Error{ErrorCode::WorkBudget, "the offset needs more than " + std::to_string(kOffsetBudget) +
                                                " steps at this tolerance; a coarser tolerance would do"};
    };

    // 1. The raw offset: each segment's pieces, then the join to the next segment.
    std::vector<RawPiece> raw;
    const std::size_t m = segments.size();
    std::optional<PendingCut> pending; // a hem's start to cut at a turned-back corner
    for (std::size_t i = 0; i < m; ++i) {
        const Bezier &b = segments[i];
        const double sd = sign * dists[i];
        const std::size_t segmentStart = raw.size();
        fitInterval(b, sd, 0.0, offsetAt(b, 0.0, sd), 1.0, offsetAt(b, 1.0, sd), 0.5 * tol, 0, work, raw);
        if (work.over())
            return overBudget();
        if (pending) {
            trimHem(raw, segmentStart, raw.size(), pending->q, pending->dir, true);
            pending.reset();
        }
        // Stages' shares of the progress: fitting 0–0.4, crossings 0.4–0.5, trimming 0.5–1.
        work.progress(0.4 * static_cast<double>(i + 1) / static_cast<double>(m));
        if (i + 1 == m && !closed)
            break;
        const Bezier &next = segments[(i + 1) % m];
        const double dNext = dists[(i + 1) % m];
        const Point v = b.endPoint();
        const Point ta = unitTangent(b, 1.0), tb = unitTangent(next, 0.0);
        const Point a = raw.back().curve.endPoint();
        const Point bb = v + sign * dNext * leftNormal(tb);
        const double gap = (a - bb).norm();
        if (gap <= 1e-9 * std::max(widest, scaleOf(b))) {
            continue; // tangent continuous: the next piece starts here (snapped below)
        }
        const double turn = cross(ta, tb);
        const bool convex = sign * turn < 0.0 || (std::abs(turn) < 1e-12 && ta.dot(tb) < 0.0);
        if (!convex) {
            // The offsets overlap on the inside of the turn: a straight connector, cut away with the
            // loop it closes in step 2.
            raw.push_back({line(a, bb), false});
            continue;
        }
        const double dot = 1e-12 * std::max(widest, scaleOf(b));
        const double limit = perSeam ? options.miterLimit * std::max(dists[i], dNext) / d : options.miterLimit;
        if (hems[i] != hems[(i + 1) % m] &&
            turnedBackJoin(raw, segmentStart, v, a, ta, bb, tb, hems[(i + 1) % m], limit, dot, pending))
            continue;
        // Two widths meet: the offsets are extended to meet (a round join has no one radius).
        const bool sameWidth = dists[i] == dNext;
        switch (sameWidth || options.join != OffsetJoin::Round ? options.join : OffsetJoin::Miter) {
        case OffsetJoin::Round: {
            double sweep = std::atan2(cross(a - v, bb - v), (a - v).dot(bb - v));
            if (std::abs(turn) < 1e-12) // a full reversal: half a circle on the offset's side
                sweep = sign > 0 ? std::numbers::pi : -std::numbers::pi;
            roundJoin(v, dists[i], a, sweep, 0.5 * tol, raw);
            break;
        }
        case OffsetJoin::Miter: {
            const double den = cross(ta, tb);
            bool mitered = false;
            if (std::abs(den) > 1e-12) {
                const double lambda = cross(bb - a, tb) / den;
                const Point tip = a + lambda * ta;
                if (lambda > 0.0 && (tip - v).norm() <= limit) {
                    // A width of 0 on one side puts the tip on that side's end: one line, not a dot.
                    pushLine(raw, a, tip, dot);
                    pushLine(raw, tip, bb, dot);
                    mitered = true;
                }
            }
            if (!mitered)
                raw.push_back({line(a, bb), true});
            break;
        }
        case OffsetJoin::Bevel:
            raw.push_back({line(a, bb), true});
            break;
        }
    }
    if (pending) // the hem is the first segment: its start is cut at the last corner
        trimHem(raw, 0, raw.size(), pending->q, pending->dir, true);
    // Snap every piece's start to the previous piece's end (they agree to rounding), and a closed
    // chain's end to its start, so that the pieces join exactly.
    for (std::size_t k = 1; k < raw.size(); ++k) {
        std::vector<Point> c = raw[k].curve.controlPoints();
        const Point delta = raw[k - 1].curve.endPoint() - c.front();
        c[0] += delta;
        c[1] += delta;
        raw[k].curve = Bezier(std::move(c));
    }
    if (closed) {
        std::vector<Point> c = raw.back().curve.controlPoints();
        const Point delta = raw.front().curve.startPoint() - c.back();
        c[3] += delta;
        c[2] += delta;
        raw.back().curve = Bezier(std::move(c));
    }

    for (const RawPiece &piece : raw)
        for (const Point &p : piece.curve.controlPoints())
            if (!p.allFinite())
                return Error{ErrorCode::NonFiniteInput, "the offset passes the largest number"};

    // 2. Split the raw offset at its self-intersections; drop the arcs nearer the source than the
    // distance (the loops), keep the others.
    const int n = static_cast<int>(raw.size());
    // The polylines only find where crossings are (Newton then refines them), so they need not follow
    // the pieces closer than a billionth of the offset's size: a finer tolerance would cost vertices
    // as the inverse square root of it for nothing.
    const double crossingTol = std::max(0.125 * tol, 1e-9 * (size + widest));
    const std::vector<Crossing> crossings = selfIntersections(raw, closed, crossingTol, work);
    if (work.over())
        return overBudget();
    struct Event
    {
        double g;
        int id;
        Point p;
    };
    std::vector<Event> events;
    for (std::size_t c = 0; c < crossings.size(); ++c) {
        events.push_back({crossings[c].ga, static_cast<int>(c), crossings[c].point});
        events.push_back({crossings[c].gb, static_cast<int>(c), crossings[c].point});
    }
    std::sort(events.begin(), events.end(), [](const Event &x, const Event &y) { return x.g < y.g; });
    const auto evalChain = [&](double g) {
        const int k = std::clamp(static_cast<int>(std::floor(g)), 0, n - 1);
        return raw[static_cast<std::size_t>(k)].curve.eval(g - k);
    };
    std::vector<Arc> arcs;
    if (events.empty()) {
        arcs.push_back({0.0, double(n), closed ? -2 : -1, closed ? -2 : -1, evalChain(0.0), evalChain(n), true});
    } else {
        if (!closed)
            arcs.push_back({0.0, events.front().g, -1, events.front().id, evalChain(0.0), events.front().p, true});
        for (std::size_t e = 0; e + 1 < events.size(); ++e)
            arcs.push_back(
                {events[e].g, events[e + 1].g, events[e].id, events[e + 1].id, events[e].p, events[e + 1].p, true});
        if (closed)
            arcs.push_back({events.back().g, events.front().g + n, events.back().id, events.front().id, events.back().p,
                            events.front().p, true});
        else
            arcs.push_back({events.back().g, double(n), events.back().id, -1, events.back().p, evalChain(n), true});
    }
    // The portions of pieces an arc covers: (piece, t0, t1).
    struct Portion
    {
        int piece;
        double t0, t1;
    };
    const auto portionsOf = [&](const Arc &arc) {
        std::vector<Portion> out;
        for (int k = static_cast<int>(std::floor(arc.g0)); k < arc.g1; ++k) {
            const double t0 = std::max(arc.g0 - k, 0.0), t1 = std::min(arc.g1 - k, 1.0);
            if (t1 - t0 > 1e-12)
                out.push_back({k % n, t0, t1});
        }
        return out;
    };
    const double threshold = d - std::max(0.75 * tol, 1e-9 * d);
    const std::vector<WidthGroup> groups = perSeam ? widthGroups(segments, dists, tol) : std::vector<WidthGroup>{};
    // Nearer the source than the width: one distance, or (per seam) nearer some width's segments than it.
    const auto nearerThanWidth = [&](const Point &q) {
        if (!perSeam)
            return src.nearest(q).distance < threshold;
        for (const WidthGroup &g : groups) {
            work.add(1);
            if (g.segments.nearest(q).distance < g.threshold)
                return true;
        }
        return false;
    };
    int removed = 0;
    std::size_t totalPortions = 0, portionsDone = 0;
    for (const Arc &arc : arcs)
        totalPortions += portionsOf(arc).size();
    for (Arc &arc : arcs) {
        int inside = 0, samples = 0;
        const std::vector<Portion> portions = portionsOf(arc);
        work.progress(0.5 + 0.5 * static_cast<double>(portionsDone) /
                                static_cast<double>(std::max<std::size_t>(totalPortions, 1)));
        portionsDone += portions.size();
        for (const Portion &p : portions) {
            const RawPiece &piece = raw[static_cast<std::size_t>(p.piece)];
            if (piece.convexJoin)
                continue;
            const std::vector<double> us =
                portions.size() < 3 ? std::vector<double>{0.25, 0.5, 0.75} : std::vector<double>{0.5};
            for (double u : us) {
                const Point q = piece.curve.eval(p.t0 + u * (p.t1 - p.t0));
                ++samples;
                work.add(1);
                if (nearerThanWidth(q))
                    ++inside;
                // A nearest-point query on a long source costs as much as thousands of other steps:
                // Cancel is looked at after each one.
                if (work.cancelled())
                    return overBudget();
            }
        }
        arc.kept = samples == 0 || 2 * inside <= samples;
        if (!arc.kept)
            ++removed;
        if (work.over())
            return overBudget();
    }

    // 3. Chain the kept arcs through their shared crossings into parts; keep the longest part.
    std::vector<bool> used(arcs.size(), false);
    std::vector<std::vector<std::size_t>> parts;
    std::vector<bool> partClosed;
    const auto findNext = [&](std::size_t from, int id) -> std::ptrdiff_t {
        for (std::size_t k = 1; k <= arcs.size(); ++k) {
            const std::size_t c = (from + k) % arcs.size();
            if (!used[c] && arcs[c].kept && arcs[c].startId == id)
                return static_cast<std::ptrdiff_t>(c);
        }
        return -1;
    };
    for (std::size_t s = 0; s < arcs.size(); ++s) {
        if (used[s] || !arcs[s].kept)
            continue;
        if (work.cancelled())
            return overBudget();
        std::vector<std::size_t> part{s};
        used[s] = true;
        bool isClosed = arcs[s].startId == -2;
        std::size_t cur = s;
        while (!isClosed && arcs[cur].endId >= 0) {
            if (arcs[cur].endId == arcs[s].startId) {
                isClosed = true;
                break;
            }
            const std::ptrdiff_t next = findNext(cur, arcs[cur].endId);
            if (next < 0)
                break;
            cur = static_cast<std::size_t>(next);
            used[cur] = true;
            part.push_back(cur);
        }
        parts.push_back(std::move(part));
        partClosed.push_back(isClosed);
    }
    if (parts.empty())
        return Error{ErrorCode::InvalidArgument, "nothing is left of the offset: the distance is wider than the curve"};
    const auto chordLength = [&](const std::vector<std::size_t> &part) {
        double len = 0.0;
        for (std::size_t a : part)
            for (const Portion &p : portionsOf(arcs[a])) {
                const Bezier &c = raw[static_cast<std::size_t>(p.piece)].curve;
                len += (c.eval(p.t1) - c.eval(p.t0)).norm() + 1e-300;
            }
        return len;
    };
    std::size_t best = 0;
    double bestLength = -1.0;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const double len = chordLength(parts[p]);
        if (len > bestLength) {
            bestLength = len;
            best = p;
        }
    }
    std::vector<Bezier> result;
    for (std::size_t a : parts[best]) {
        const Arc &arc = arcs[a];
        const std::vector<Portion> portions = portionsOf(arc);
        for (std::size_t k = 0; k < portions.size(); ++k) {
            const Portion &p = portions[k];
            std::vector<Point> c = raw[static_cast<std::size_t>(p.piece)].curve.subCurve(p.t0, p.t1).controlPoints();
            const Point start = result.empty() ? (k == 0 ? arc.startPoint : c.front()) : result.back().endPoint();
            const Point end = k + 1 == portions.size() ? arc.endPoint : c.back();
            c[1] += start - c[0];
            c[0] = start;
            c[2] += end - c[3];
            c[3] = end;
            result.emplace_back(std::move(c));
        }
    }
    const bool resultClosed = closed && partClosed[best];
    if (resultClosed && !result.empty()) {
        std::vector<Point> c = result.back().controlPoints();
        c[2] += result.front().startPoint() - c[3];
        c[3] = result.front().startPoint();
        result.back() = Bezier(std::move(c));
    }
    OffsetResult out;
    out.curve = PiecewiseBezier(std::move(result), resultClosed);
    out.partsDropped = static_cast<int>(parts.size()) - 1;
    out.loopsRemoved = removed;
    out.tolerance = tol;
    work.finish();
    work.progress(1.0);
    return out;
}

} // namespace kontur::geo
