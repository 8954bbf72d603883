// Cutting the raw offset's loops: see offsetloops.h.
#include "geometry/offsetloops.h"

#include <algorithm>
#include <cmath>

namespace kontur::geo::offsetdetail {

namespace {

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

} // namespace

std::vector<Polyline> flattenPieces(const std::vector<RawPiece> &pieces, double tol, Work &work)
{
    std::vector<Polyline> lines(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (work.over())
            return {};
        Polyline &pl = lines[i];
        pl.t.push_back(0.0);
        pl.p.push_back(pieces[i].curve.startPoint());
        flattenWithParams(pieces[i].curve, 0.0, 1.0, tol, 0, work, pl);
    }
    return lines;
}


std::vector<Crossing> selfIntersections(const std::vector<RawPiece> &pieces, const std::vector<Polyline> &lines,
                                        bool closed, double tol, Work &work)
{
    const int n = static_cast<int>(pieces.size());
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


std::vector<Portion> portionsOf(const Arc &arc, int n)
{
    std::vector<Portion> out;
    for (int k = static_cast<int>(std::floor(arc.g0)); k < arc.g1; ++k) {
        const double t0 = std::max(arc.g0 - k, 0.0), t1 = std::min(arc.g1 - k, 1.0);
        if (t1 - t0 > 1e-12)
            out.push_back({k % n, t0, t1});
    }
    return out;
}


std::vector<Arc> arcsBetween(const std::vector<Crossing> &crossings, const std::vector<RawPiece> &raw, bool closed)
{
    const int n = static_cast<int>(raw.size());
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
    return arcs;
}

Parts chainArcs(const std::vector<Arc> &arcs)
{
    std::vector<bool> used(arcs.size(), false);
    Parts parts;
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
        parts.arcs.push_back(std::move(part));
        parts.closed.push_back(isClosed);
    }
    return parts;
}


std::size_t longestPart(const Parts &parts, const std::vector<Arc> &arcs, const std::vector<RawPiece> &raw)
{
    const int n = static_cast<int>(raw.size());
    std::size_t best = 0;
    double bestLength = -1.0;
    for (std::size_t p = 0; p < parts.arcs.size(); ++p) {
        double len = 0.0;
        for (std::size_t a : parts.arcs[p])
            for (const Portion &portion : portionsOf(arcs[a], n)) {
                const Bezier &c = raw[static_cast<std::size_t>(portion.piece)].curve;
                len += (c.eval(portion.t1) - c.eval(portion.t0)).norm() + 1e-300;
            }
        if (len > bestLength) {
            bestLength = len;
            best = p;
        }
    }
    return best;
}

} // namespace kontur::geo::offsetdetail
