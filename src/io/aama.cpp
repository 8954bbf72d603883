// ASTM D6673 pieces read back as pieces (see aama.h).
#include "io/aama.h"

#include "geometry/offset.h"
#include "geometry/seams.h"
#include "io/piece.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace kontur::io {

namespace {

// The curves of one piece by the standard's layer.
struct PieceCurves
{
    int cut = -1, sew = -1;
    std::vector<int> marks; // layers 4, 6, 7, 13: become marks, not curves
};

geo::Point firstPoint(const geo::PiecewiseBezier &c)
{
    return c.segments().front().controlPoints().front();
}

geo::Point lastPoint(const geo::PiecewiseBezier &c)
{
    return c.segments().back().controlPoints().back();
}

// The distance of `cut` around `sew` when it is one all along (sampled on the sew line: at a corner
// the cut line's miter lies farther, but each sew point is the distance from the cut line), else 0.
double allowanceDistance(const geo::PiecewiseBezier &sew, const geo::PiecewiseBezier &cut)
{
    if (!sew.isClosed() || !cut.isClosed() || std::abs(signedArea(cut)) <= std::abs(signedArea(sew)))
        return 0.0;
    std::vector<double> d;
    constexpr int kPerSegment = 8;
    for (const geo::Bezier &b : sew.segments())
        for (int i = 0; i < kPerSegment; ++i)
            d.push_back(cut.nearest(b.eval((i + 0.5) / kPerSegment)).distance);
    std::sort(d.begin(), d.end());
    const double median = d[d.size() / 2];
    if (!(median > 0))
        return 0.0;
    // The polyline flavour lies within 0.05 mm of the curves; a percent covers it at any usual width.
    const double tolerance = 0.01 * median;
    return d.front() >= median - tolerance && d.back() <= median + tolerance ? median : 0.0;
}

// A cut line whose distance differs from seam to seam (a hem wider than the sides): the allowance's
// own width (the one most seams have), each seam's where it differs and the hems (seams whose corners
// are turned back), when the allowance computed from them lies on the cut line both ways (within 1 %
// of the widest, sampled; `exact`), or near it with hems (below); else none. Hems are looked for among
// the seams wider than the rest: first none, then all of them, then each alone.
struct SeamWidthsFound
{
    double width = 0.0;
    std::vector<std::optional<double>> seams;
    std::vector<int> hems;
    bool exact = true; // the allowance made from them is the cut line (within 1 % of the widest)
};

double farthest(const geo::PiecewiseBezier &from, const geo::PiecewiseBezier &to)
{
    double worst = 0.0;
    for (const geo::Bezier &b : from.segments())
        for (int i = 0; i <= 8; ++i)
            worst = std::max(worst, to.nearest(b.eval(i / 8.0)).distance);
    return worst;
}

std::optional<SeamWidthsFound> seamWidthsOf(const geo::PiecewiseBezier &sew, const geo::PiecewiseBezier &cut,
                                            const QString &units)
{
    if (!sew.isClosed() || !cut.isClosed() || std::abs(signedArea(cut)) <= std::abs(signedArea(sew)))
        return std::nullopt;
    const std::vector<geo::SeamSpan> spans = geo::seamSpans(sew);
    std::vector<double> widths; // each seam's median distance, sampled along its middle half
    for (const geo::SeamSpan &s : spans) {
        std::vector<double> d;
        for (int k = 0; k < s.count; ++k) {
            const geo::Bezier &b = sew.segments()[static_cast<std::size_t>((s.first + k) % sew.segmentCount())];
            for (int i = 0; i < 8; ++i) {
                const double u = (k + (i + 0.5) / 8.0) / s.count;
                if (u > 0.25 && u < 0.75)
                    d.push_back(cut.nearest(b.eval((i + 0.5) / 8.0)).distance);
            }
        }
        if (d.empty())
            return std::nullopt;
        std::sort(d.begin(), d.end());
        widths.push_back(d[d.size() / 2]);
    }
    // A width a user typed (10, 12.5, 30 mm) comes back a few thousandths short, from the sampled
    // distances to a cut line within the offset's and the file's tolerance: within 0.02 of a tenth of
    // the units it is that tenth.
    for (double &w : widths)
        if (const double tenth = std::round(w * 10.0) / 10.0; std::abs(w - tenth) <= 0.02)
            w = tenth;
    SeamWidthsFound found;
    std::size_t most = 0;
    for (double w : widths) {
        const auto same = static_cast<std::size_t>(std::count_if(
            widths.begin(), widths.end(), [&](double v) { return std::abs(v - w) <= 0.01 * std::max(v, w); }));
        if (w > 0 && same > most) {
            most = same;
            found.width = w;
        }
    }
    if (!(found.width > 0))
        return std::nullopt;
    for (double w : widths)
        found.seams.push_back(std::abs(w - found.width) <= 0.01 * found.width ? std::nullopt
                                                                              : std::optional<double>(w));
    geo::OffsetOptions options = defaultSeamOptions(units);
    options.distance = found.width;
    options.segmentDistances = geo::segmentDistancesOf(sew.segmentCount(), spans, found.seams, found.width);
    const double widest = *std::max_element(widths.begin(), widths.end());
    // How far the allowance made with these hems lies from the cut line, both ways.
    const auto offBy = [&](const std::vector<int> &hems) {
        options.hems = hems.empty() ? std::vector<bool>{} : geo::segmentHemsOf(sew.segmentCount(), spans, hems);
        const auto made = geo::offsetCurve(sew, options);
        return made ? std::max(farthest(made->curve, cut), farthest(cut, made->curve)) : 1e300;
    };
    const auto fits = [&](const std::vector<int> &hems) { return offBy(hems) <= 0.01 * widest; };
    std::vector<int> wider;
    for (std::size_t k = 0; k < found.seams.size(); ++k)
        if (found.seams[k] && *found.seams[k] > found.width)
            wider.push_back(static_cast<int>(k));
    std::vector<std::vector<int>> tries{{}};
    if (!wider.empty())
        tries.push_back(wider);
    for (int k : wider)
        if (wider.size() > 1)
            tries.push_back({k});
    auto hems = std::find_if(tries.begin(), tries.end(), fits);
    found.exact = hems != tries.end();
    if (!found.exact) {
        // A hem's turned-back corner mirrors the side's allowance about the hem's end tangent, which a
        // sew line written as a polyline gives only as its last chord's: where that chord is long (as
        // other software writes them, and Kontur did before it ended a curve at a corner with a chord
        // of its last hundredth) the allowance made from it lies up to 6 % of the hem's width
        // off the cut line near those corners (1.7 mm at a 30 mm hem, measured). The widths and hems
        // are the piece's then, the cut line stays as drawn.
        hems = std::find_if(tries.begin() + 1, tries.end(), [&](const auto &h) { return offBy(h) <= 0.06 * widest; });
        if (hems == tries.end())
            return std::nullopt;
    }
    found.hems = *hems;
    while (!found.seams.empty() && !found.seams.back())
        found.seams.pop_back();
    return found;
}

// The notch at reference point `at` with direction `degrees` (absolute), as the piece keeps it.
Notch notchAt(const geo::PiecewiseBezier &own, const geo::Point &at, double degrees, NotchKind kind)
{
    Notch n;
    n.kind = kind;
    // Back from the cut line along the notch's own direction, as it was carried there.
    const double r0 = degrees * std::numbers::pi / 180.0;
    n.position = lengthAtNearest(own, meetAlong(own, at, geo::Point(std::cos(r0), std::sin(r0))).value_or(at));
    const geo::Point square = notchDirection(own, placeAtLength(own, n.position), 0.0);
    const double r = degrees * std::numbers::pi / 180.0;
    const geo::Point d(std::cos(r), std::sin(r));
    const double relative =
        std::atan2(square.x() * d.y() - square.y() * d.x(), square.dot(d)) * 180.0 / std::numbers::pi;
    // A sew line written as a polyline (AAMA's) turns from the curve's tangent by up to half a degree
    // along a chord, and rounding in the file leaves a square notch a few 1e-10 degrees off: within a
    // degree of square is square.
    n.angle = std::abs(relative) < 1.0 ? 0.0 : std::clamp(relative, -89.0, 89.0);
    return n;
}

} // namespace

Result<std::vector<CurveRecord>> dxfRecords(const DxfImport &dxf, const QString &path)
{
    auto all = importedRecords(dxf.curves, path, [](const geo::PiecewiseBezier &c) { return recordFromDxfCurve(c); });
    if (!all)
        return all;
    std::map<QString, PieceCurves> pieces;
    for (int i = 0; i < static_cast<int>(dxf.curves.size()); ++i) {
        const DxfImportedCurve &c = dxf.curves[static_cast<std::size_t>(i)];
        if (c.piece.isEmpty())
            continue;
        PieceCurves &p = pieces[c.piece];
        if (c.aamaLayer == 1 && c.curve.isClosed() && p.cut < 0)
            p.cut = i;
        else if (c.aamaLayer == 14 && c.curve.isClosed() && p.sew < 0)
            p.sew = i;
        else if (c.aamaLayer == 4 || c.aamaLayer == 6 || c.aamaLayer == 7 || c.aamaLayer == 13)
            p.marks.push_back(i);
    }
    std::vector<bool> dropped(dxf.curves.size(), false);
    std::map<int, std::pair<int, double>> allowanceOf; // cut line → its sew line (curve indices), width
    std::map<int, int> sewOf;                          // cut line → its piece's sew line: the piece comes first
    for (auto &[name, p] : pieces) {
        const int ownIndex = p.sew >= 0 ? p.sew : p.cut;
        if (ownIndex < 0)
            continue; // no closed outline: its curves stay curves
        const geo::PiecewiseBezier &own = dxf.curves[static_cast<std::size_t>(ownIndex)].curve;
        const geo::PiecewiseBezier *cut = p.cut >= 0 ? &dxf.curves[static_cast<std::size_t>(p.cut)].curve : nullptr;
        PieceMarks marks;
        const auto text =
            std::find_if(dxf.pieces.begin(), dxf.pieces.end(), [&](const DxfAamaPiece &t) { return t.name == name; });
        if (text != dxf.pieces.end()) {
            marks.size = text->size;
            marks.material = text->material;
            marks.quantity = text->quantity;
            const auto sameAt = [&](const DxfAamaPoint &a, int layer) {
                return std::any_of(text->points.begin(), text->points.end(), [&](const DxfAamaPoint &b) {
                    return b.layer == layer && (b.at - a.at).norm() <= 1e-9 * std::max(1.0, a.at.norm());
                });
            };
            for (const DxfAamaPoint &pt : text->points) {
                if (pt.layer == 13)
                    marks.drillHoles.push_back(pt.at);
                if (pt.layer != 4)
                    continue;
                // D6673's kinds: 81 castle, 84 V; 82 (check) is how Kontur wrote a V before, and reads
                // as one still; a T (80) or U (83) notch, which Kontur has no kind for, as a slit.
                const NotchKind kind = sameAt(pt, 81)                     ? NotchKind::Castle
                                       : sameAt(pt, 84) || sameAt(pt, 82) ? NotchKind::V
                                                                          : NotchKind::Slit;
                marks.notches.push_back(notchAt(own, pt.at, pt.angle, kind));
            }
        }
        for (int i : p.marks) {
            const DxfImportedCurve &c = dxf.curves[static_cast<std::size_t>(i)];
            const Segment s{firstPoint(c.curve), lastPoint(c.curve)};
            if (c.aamaLayer == 7)
                marks.grainline = s;
            else if (c.aamaLayer == 6)
                marks.fold = s;
            else if (c.aamaLayer == 13)
                marks.drillHoles.push_back(c.curve.boundingBox().center());
            else if (c.aamaLayer == 4 && !c.curve.isClosed()) {
                // A notch drawn as a line (other software): from its end on the cut line into the piece.
                const geo::PiecewiseBezier &edge = cut ? *cut : own;
                const bool startOnEdge = edge.nearest(s.a).distance <= edge.nearest(s.b).distance;
                const geo::Point on = startOnEdge ? s.a : s.b, in = startOnEdge ? s.b : s.a;
                const geo::Point d = in - on;
                marks.notches.push_back(
                    notchAt(own, on, std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi, NotchKind::Slit));
            } else {
                continue; // a closed notch shape: kept as a curve
            }
            dropped[static_cast<std::size_t>(i)] = true;
        }
        std::sort(marks.notches.begin(), marks.notches.end(),
                  [](const Notch &a, const Notch &b) { return a.position < b.position; });
        CurveRecord &record = (*all)[static_cast<std::size_t>(ownIndex)];
        record.name = name;
        if (p.sew >= 0 && p.cut >= 0) {
            sewOf[p.cut] = p.sew;
            if (const double d = allowanceDistance(own, *cut); d > 0) {
                allowanceOf[p.cut] = {p.sew, d};
            } else if (const auto widths = seamWidthsOf(own, *cut, dxf.units)) {
                if (widths->exact)
                    allowanceOf[p.cut] = {p.sew, widths->width};
                marks.seamWidths = widths->seams;
                marks.hems = widths->hems;
            }
        }
        record.settings.insert(QLatin1String(kPieceKey), pieceToJson(marks));
    }
    // The records kept, and where each went (for the allowances' links): a piece before its cut line.
    std::vector<CurveRecord> records;
    std::vector<int> newIndex(dxf.curves.size(), -1);
    const auto keep = [&](std::size_t i) {
        if (dropped[i] || newIndex[i] >= 0)
            return;
        newIndex[i] = static_cast<int>(records.size());
        records.push_back(std::move((*all)[i]));
    };
    for (std::size_t i = 0; i < all->size(); ++i) {
        if (const auto sew = sewOf.find(static_cast<int>(i)); sew != sewOf.end())
            keep(static_cast<std::size_t>(sew->second));
        keep(i);
    }
    for (const auto &[cut, sewAndWidth] : allowanceOf) {
        const int sew = sewAndWidth.first;
        CurveRecord &record = records[static_cast<std::size_t>(newIndex[static_cast<std::size_t>(cut)])];
        if (record.kind != QLatin1String("composite"))
            continue;
        SeamSettings seam;
        seam.source = newIndex[static_cast<std::size_t>(sew)];
        seam.options = defaultSeamOptions(dxf.units);
        seam.options.distance = sewAndWidth.second;
        record.settings.insert(QLatin1String(kSeamKey), seamToJson(seam));
    }
    return records;
}

void scaleRecord(CurveRecord &record, double factor)
{
    for (geo::Point &p : record.points)
        p *= factor;
    if (auto marks = pieceFromSettings(record.settings)) {
        for (std::optional<Segment> *s : {&marks->fold, &marks->grainline})
            if (*s)
                **s = Segment{(*s)->a * factor, (*s)->b * factor};
        for (Notch &n : marks->notches)
            n.position *= factor;
        for (geo::Point &p : marks->drillHoles)
            p *= factor;
        for (std::optional<double> &w : marks->seamWidths)
            if (w)
                *w *= factor;
        record.settings.insert(QLatin1String(kPieceKey), pieceToJson(*marks));
    }
    if (auto seam = seamFromSettings(record.settings, std::numeric_limits<int>::max())) {
        seam->options.distance *= factor;
        seam->options.miterLimit *= factor;
        seam->options.tolerance *= factor;
        record.settings.insert(QLatin1String(kSeamKey), seamToJson(*seam));
    }
}

} // namespace kontur::io
