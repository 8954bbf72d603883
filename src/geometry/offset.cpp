// Offset curves: Hermite approximation with subdivision, corner joins, and trimming of the raw
// offset's loops by distance (see offset.h for the sources). The stages are functions: the raw
// offset (rawOffset), its crossings and arcs (offsetloops.h), the arcs judged by distance, and the
// kept arcs chained (offsetloops.h). Over 600 lines because the joins (miter, bevel, round and the
// hem's turned-back corner) are one stage with its bounds; offsetloops.cpp holds the loops' part.
#include "geometry/offset.h"

#include "geometry/offsetloops.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

namespace kontur::geo {

using namespace offsetdetail;

namespace {


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
        out.push_back({c, false, err, std::nullopt});
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
            pieces.push_back({c, false, 0.0, std::nullopt});
        }
        if (err <= tol || n >= 256) {
            out.insert(out.end(), pieces.begin(), pieces.end());
            return;
        }
    }
}


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

void pushLine(std::vector<RawPiece> &raw, const Point &a, const Point &b, double dot,
              const std::optional<Point> &corner = std::nullopt)
{
    if ((b - a).norm() > dot)
        raw.push_back({straightCubic(a, b), !corner, 0.0, corner});
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
// where the hem's offset passes Q it is cut there (the hem before the joint: now; after it: `pending`),
// and where the side's offset passes P, there.
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
        // The side's offset passing P before its end (P behind it) ends at P, for the reason below.
        if ((p - a).dot(ta) < 0.0)
            trimHem(raw, segmentStart, raw.size(), p, ta, false);
        else
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
        // The side's offset runs on through P (P ahead of its start): it begins at P, as the hem's
        // does at Q above. A line back from P to its start would lie on it, there and back, where no
        // crossing cuts it off (a straight side's offset is that very line).
        if ((bb - p).dot(tb) < 0.0)
            pending = PendingCut{p, tb};
        else
            pushLine(raw, p, bb, dot);
    }
    return true;
}

// The source's segments of one width (> 0) and how near to them a part of the offset may not come.
struct WidthGroup
{
    PiecewiseBezier segments;
    double width = 0.0;
};

std::vector<WidthGroup> widthGroups(const std::vector<Bezier> &segments, const std::vector<double> &dists)
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
        out.push_back({PiecewiseBezier(std::move(of)), w});
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

namespace {


// How stage 1 builds the raw offset.
struct RawSettings
{
    int sign = 1;                      // 1: to the segments' left, -1: to their right
    double tol = 0.0;                  // the fit's tolerance
    double widest = 0.0;               // the widest distance (the scale "no gap" is measured on)
    double distance = 0.0;             // OffsetOptions::distance (the miter limit's unit with widths per seam)
    bool perSeam = false;              // widths per seam
    OffsetJoin join = OffsetJoin::Miter;
    double miterLimit = 0.0;
};

// Stage 1, the raw offset: each segment's pieces, then the join to the next segment, the pieces
// snapped to join exactly. False once the work budget is spent or the offset was cancelled.
bool rawOffset(const std::vector<Bezier> &segments, const std::vector<double> &dists, const std::vector<bool> &hems,
               bool closed, const RawSettings &k, Work &work, std::vector<RawPiece> &raw)
{
    const std::size_t m = segments.size();
    std::optional<PendingCut> pending; // a hem's start to cut at a turned-back corner
    for (std::size_t i = 0; i < m; ++i) {
        const Bezier &b = segments[i];
        const double sd = k.sign * dists[i];
        const std::size_t segmentStart = raw.size();
        fitInterval(b, sd, 0.0, offsetAt(b, 0.0, sd), 1.0, offsetAt(b, 1.0, sd), 0.5 * k.tol, 0, work, raw);
        if (work.over())
            return false;
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
        const Point bb = v + k.sign * dNext * leftNormal(tb);
        const double gap = (a - bb).norm();
        if (gap <= 1e-9 * std::max(k.widest, scaleOf(b))) {
            continue; // tangent continuous: the next piece starts here (snapped below)
        }
        const double turn = cross(ta, tb);
        const bool convex = k.sign * turn < 0.0 || (std::abs(turn) < 1e-12 && ta.dot(tb) < 0.0);
        if (!convex) {
                // The offsets overlap on the inside of the turn: a straight connector, cut away with the
            // loop it closes in step 2.
            raw.push_back({straightCubic(a, bb), false, 0.0, std::nullopt});
            continue;
        }
        const double dot = 1e-12 * std::max(k.widest, scaleOf(b));
        const double limit = k.perSeam ? k.miterLimit * std::max(dists[i], dNext) / k.distance : k.miterLimit;
        if (hems[i] != hems[(i + 1) % m] &&
            turnedBackJoin(raw, segmentStart, v, a, ta, bb, tb, hems[(i + 1) % m], limit, dot, pending))
            continue;
        // Two widths meet: the offsets are extended to meet (a round join has no one radius).
        const bool sameWidth = dists[i] == dNext;
        switch (sameWidth || k.join != OffsetJoin::Round ? k.join : OffsetJoin::Miter) {
        case OffsetJoin::Round: {
            double sweep = std::atan2(cross(a - v, bb - v), (a - v).dot(bb - v));
            if (std::abs(turn) < 1e-12) // a full reversal: half a circle on the offset's side
                sweep = k.sign > 0 ? std::numbers::pi : -std::numbers::pi;
            roundJoin(v, dists[i], a, sweep, 0.5 * k.tol, raw);
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
                    pushLine(raw, a, tip, dot, v);
                    pushLine(raw, tip, bb, dot, v);
                    mitered = true;
                }
            }
            if (!mitered)
                raw.push_back({straightCubic(a, bb), false, 0.0, v});
            break;
        }
        case OffsetJoin::Bevel:
            raw.push_back({straightCubic(a, bb), false, 0.0, v});
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

    return true;
}

} // namespace

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

    // 1. The raw offset.
    const RawSettings settings{sign, tol, widest, d, perSeam, options.join, options.miterLimit};
    std::vector<RawPiece> raw;
    if (!rawOffset(segments, dists, hems, closed, settings, work, raw))
        return overBudget();
    for (const RawPiece &piece : raw)
        for (const Point &p : piece.curve.controlPoints())
            if (!p.allFinite())
                return Error{ErrorCode::NonFiniteInput, "the offset passes the largest number"};

    // 2. Split the raw offset at its self-intersections; drop the arcs nearer the source than the
    // distance (the loops), keep the others.
    int n = static_cast<int>(raw.size());
    // The polylines only find where crossings are (Newton then refines them), so they need not follow
    // the pieces closer than a billionth of the offset's size: a finer tolerance would cost vertices
    // as the inverse square root of it for nothing.
    const double crossingTol = std::max(0.125 * tol, 1e-9 * (size + widest));
    const std::vector<Polyline> lines = flattenPieces(raw, crossingTol, work);
    if (work.over())
        return overBudget();
    const std::vector<Crossing> crossings = selfIntersections(raw, lines, closed, crossingTol, work);
    if (work.over())
        return overBudget();
    std::vector<Arc> arcs = arcsBetween(crossings, raw, closed);
    const std::vector<WidthGroup> groups = perSeam ? widthGroups(segments, dists) : std::vector<WidthGroup>{};
    // Nearer the source than the width, by more than the piece's own error (its sampled gap to the
    // exact offset, with a margin for the gap between samples; none for a line's offset, so that the
    // shallow loops where a polyline's short chords turn inwards are judged exactly and alike on both
    // sides of every crossing): one distance, or (per seam) nearer some width's segments than it.
    // A miter's or bevel's line lies nearer its own corner than the width by design: it counts as
    // nearer only where another part of the source is nearer than its corner (a polyline's short
    // chords beside a corner, whose offsets bury the corner's lines).
    const auto nearerThanWidth = [&](const Point &q, const RawPiece &piece) {
        const double own = piece.corner ? (q - *piece.corner).norm() : std::numeric_limits<double>::infinity();
        const auto below = [&](double width) {
            return std::min(width, own) - std::max(1.5 * piece.error, 1e-9 * width);
        };
        if (!perSeam)
            return src.nearest(q).distance < below(d);
        for (const WidthGroup &g : groups) {
            work.add(1);
            if (g.segments.nearest(q).distance < below(g.width))
                return true;
        }
        return false;
    };
    int removed = 0;
    std::size_t totalPortions = 0, portionsDone = 0;
    for (const Arc &arc : arcs)
        totalPortions += portionsOf(arc, n).size();
    for (Arc &arc : arcs) {
        int inside = 0, samples = 0;
        const std::vector<Portion> portions = portionsOf(arc, n);
        work.progress(0.5 + 0.5 * static_cast<double>(portionsDone) /
                                static_cast<double>(std::max<std::size_t>(totalPortions, 1)));
        portionsDone += portions.size();
        for (const Portion &p : portions) {
            const RawPiece &piece = raw[static_cast<std::size_t>(p.piece)];
            if (piece.turnedBack)
                continue;
            const std::vector<double> us =
                portions.size() < 3 ? std::vector<double>{0.25, 0.5, 0.75} : std::vector<double>{0.5};
            for (double u : us) {
                const Point q = piece.curve.eval(p.t0 + u * (p.t1 - p.t0));
                ++samples;
                work.add(1);
                if (nearerThanWidth(q, piece))
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

    if (work.cancelled())
        return overBudget();
    // 3. Chain the kept arcs through their shared crossings into parts; keep the longest part.
    Parts chained = chainArcs(arcs);
    const auto &parts = chained.arcs;
    const auto &partClosed = chained.closed;
    if (parts.empty())
        return Error{ErrorCode::InvalidArgument, "nothing is left of the offset: the distance is wider than the curve"};
    const std::size_t best = longestPart(chained, arcs, raw);
    // A closed curve's allowance is closed. Where the kept arcs do not close into one (the curve
    // crosses itself; or a mitred or bevelled corner beside a polyline's chords far shorter than the
    // width, in a bend tighter than it, whose outline the raw offset lacks: docs/geometry.md), no
    // allowance is made of them rather than an open one.
    if (closed && !partClosed[best])
        return Error{ErrorCode::InvalidArgument,
                     "the offset does not close into one curve at this distance with these corners"};
    std::vector<Bezier> result;
    for (std::size_t a : parts[best]) {
        const Arc &arc = arcs[a];
        const std::vector<Portion> portions = portionsOf(arc, n);
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
