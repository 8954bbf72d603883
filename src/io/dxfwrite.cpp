// DXF export (see dxf.h): a complete, minimal AutoCAD 2000 (AC1015) drawing as Autodesk's "DXF
// Reference" (AutoCAD 2000) describes it and AutoCAD writes a new one: HEADER (version, code page,
// handle seed, units, extents), an empty CLASSES section, the nine symbol tables, BLOCKS, ENTITIES
// (one SPLINE, LINE or LWPOLYLINE per run of a curve) and OBJECTS. Every table, record, block, entity
// and object has its handle and its owner (330) and the subclass markers (100) the reference gives
// it. Curves are on layers named after them, one per name; its colour is the entity's true colour
// (420) and the layer's nearest AutoCAD Color Index (62). This file writes the entities and the
// drawing of curves; the layers' names, code pages and colours are in dxfwritelayers.cpp, the fixed
// structure (tables, blocks, objects) in dxfwritetables.cpp, and the ASTM D6673 (AAMA) form, a block
// per garment piece on the standard's numbered layers, in dxfwriteaama.cpp (the writer's insides:
// dxfwrite_p.h).
#include "io/dxf.h"

#include "io/drawnwrite.h"
#include "io/dxfwrite_p.h"
#include "io/fileio.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace kontur::io::dxfwrite {

std::pair<int, double> fileUnits(const QString &units)
{
    if (units == QLatin1String("mm"))
        return {4, 1.0};
    if (units == QLatin1String("cm"))
        return {5, 1.0};
    if (units == QLatin1String("in"))
        return {1, 1.0};
    if (units == QLatin1String("pt"))
        return {1, 1.0 / 72.0};
    return {0, 1.0};
}

std::vector<std::vector<geo::Bezier>> runsOf(const geo::PiecewiseBezier &curve, double scale)
{
    std::vector<std::vector<geo::Bezier>> runs;
    for (const geo::Bezier &b : curve.segments()) {
        if (b.isEmpty())
            continue;
        std::vector<geo::Point> pts = b.controlPoints();
        if (scale != 1.0)
            for (geo::Point &p : pts)
                p *= scale;
        if (runs.empty() || runs.back().back().endPoint() != pts.front())
            runs.emplace_back();
        runs.back().emplace_back(std::move(pts));
    }
    return runs;
}

void writeLines(Writer &w, const std::vector<geo::Point> &pts, bool closed)
{
    if (pts.size() == 2 && !closed) {
        w.entity("LINE", "AcDbLine");
        ++w.entities;
        w.points += 2;
        w.point(10, pts[0]);
        w.point(11, pts[1]);
        return;
    }
    w.entity("LWPOLYLINE", "AcDbPolyline");
    ++w.entities;
    w.points += static_cast<qint64>(pts.size());
    w.integer(90, static_cast<long long>(pts.size()));
    w.integer(70, closed ? 1 : 0);
    for (const geo::Point &p : pts) {
        w.number(10, p.x());
        w.number(20, p.y());
    }
}

namespace {

// A run of segments as one SPLINE: every piece at the run's highest degree p (lower ones elevated,
// the same curve), the knots 0 (p+1 times), 1, 2, … (p times each), n (p+1 times): the Bézier form
// of a B-spline (Piegl & Tiller, "The NURBS Book", 2nd ed., §5.6), so the control points are the
// pieces' own control points, shared ends once.
void writeSpline(Writer &w, const std::vector<geo::Bezier> &run)
{
    int degree = 1;
    for (const geo::Bezier &b : run)
        degree = std::max(degree, b.degree());
    std::vector<geo::Point> control{run.front().startPoint()};
    for (const geo::Bezier &b : run) {
        const geo::Bezier piece = b.degree() < degree ? b.elevated(degree - b.degree()) : b;
        control.insert(control.end(), piece.controlPoints().begin() + 1, piece.controlPoints().end());
    }
    const int pieces = static_cast<int>(run.size());
    w.entity("SPLINE", "AcDbSpline");
    ++w.entities;
    w.points += static_cast<qint64>(control.size());
    w.number(210, 0.0);
    w.number(220, 0.0);
    w.number(230, 1.0);
    w.integer(70, 8); // planar
    w.integer(71, degree);
    w.integer(72, static_cast<long long>(control.size()) + degree + 1);
    w.integer(73, static_cast<long long>(control.size()));
    w.integer(74, 0);
    w.number(42, 1e-10);
    w.number(43, 1e-10);
    for (int i = 0; i <= pieces; ++i) {
        const int times = (i == 0 || i == pieces) ? degree + 1 : degree;
        for (int k = 0; k < times; ++k)
            w.integer(40, i);
    }
    for (const geo::Point &p : control)
        w.point(10, p);
}

// A curve flattened within `tolerance`, its first (last) hundredth flattened apart where it begins
// (ends) at a corner, so that the chord there is no longer than that. A reader takes a polyline's end
// chord for the curve's tangent there (AAMA's turned-back hem corners are mirrored about it); a chord
// within the tolerance turns from the tangent by up to half a degree (0.9 mm at a 3 cm hem's corner),
// a hundredth of the curve's by about a hundredth of that. The pieces are split (not cut out by
// parameter), so that they share their ends exactly.
void flattenAtCorners(const geo::Bezier &b, bool cornerStart, bool cornerEnd, double tolerance,
                      std::vector<geo::Point> &pts)
{
    constexpr double kEnd = 0.01;
    geo::Bezier middle = b;
    if (cornerStart) {
        auto [head, rest] = middle.split(kEnd);
        geo::flatten(head, tolerance, pts);
        middle = std::move(rest);
    }
    std::optional<geo::Bezier> tail;
    if (cornerEnd) {
        auto [rest, end] = middle.split(1.0 - kEnd / (cornerStart ? 1.0 - kEnd : 1.0));
        middle = std::move(rest);
        tail = std::move(end);
    }
    geo::flatten(middle, tolerance, pts);
    if (tail)
        geo::flatten(*tail, tolerance, pts);
}

} // namespace

void writeRun(Writer &w, const std::vector<geo::Bezier> &run, bool closed, const DxfExportOptions &options,
              double tolerance)
{
    const bool linear = std::all_of(run.begin(), run.end(), [](const geo::Bezier &b) { return isStraight(b); });
    if (linear || options.flavour == DxfFlavour::Polyline) {
        // Where each segment starts at a corner: its tangent turns there by more than 1°
        // (PiecewiseBezier::continuity), or it starts an open run.
        std::vector<bool> cornerAtStart(run.size(), true);
        for (const geo::JointContinuity &joint : geo::PiecewiseBezier(run, closed).continuity())
            cornerAtStart[static_cast<std::size_t>(joint.right)] = joint.angle > std::numbers::pi / 180.0;
        std::vector<geo::Point> pts;
        for (std::size_t i = 0; i < run.size(); ++i) {
            const geo::Bezier &b = run[i];
            if (isStraight(b)) {
                if (pts.empty())
                    pts.push_back(b.startPoint());
                pts.push_back(b.endPoint());
            } else {
                const bool cornerAtEnd = i + 1 < run.size() ? cornerAtStart[i + 1] : !closed || cornerAtStart.front();
                flattenAtCorners(b, cornerAtStart[i], cornerAtEnd, tolerance, pts);
            }
        }
        // A closed curve: the polyline's closed flag stands for its last vertex, the first again.
        const bool close = closed && pts.size() >= 3 && pts.back() == pts.front();
        if (close)
            pts.pop_back();
        writeLines(w, pts, close);
        return;
    }
    writeSpline(w, run);
}

namespace {

QByteArray build(std::span<const DxfCurve> curves, const DxfExportOptions &options, qint64 &entities, qint64 &points)
{
    const auto [insunits, scale] = fileUnits(options.units);
    const double tolerance = (options.tolerance > 0 ? options.tolerance : defaultDxfTolerance(options.units)) * scale;
    geo::Box box;
    for (const DxfCurve &c : curves)
        if (!c.curve.isEmpty())
            box.extend(c.curve.boundingBox());
    geo::Box extents; // in the file's units
    if (!box.isEmpty()) {
        extents.extend(box.min() * scale);
        extents.extend(box.max() * scale);
    }
    std::vector<Layer> layers;
    const std::vector<int> layerOf = layersOf(curves, layers);
    std::vector<QString> names;
    for (const Layer &l : layers)
        names.push_back(l.name);
    const CodePage &page = codePageFor(names);
    for (Layer &l : layers)
        l.written = dxfText(l.name, page);

    // The entities first: $HANDSEED, in the header, must exceed their handles.
    Writer e;
    e.handle = FirstFree + static_cast<unsigned>(layers.size());
    e.pair(0, "SECTION");
    e.pair(2, "ENTITIES");
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const DxfCurve &c = curves[i];
        e.layer = layerOf[i] < 0 ? QByteArray("0") : layers[static_cast<std::size_t>(layerOf[i])].written;
        e.rgb = rgbOf(c.color);
        const auto runs = runsOf(c.curve, scale);
        for (const auto &run : runs)
            writeRun(e, run, c.curve.isClosed() && runs.size() == 1, options, tolerance);
    }
    e.pair(0, "ENDSEC");

    return writeDrawing("Written by Kontur: exact Bezier control points (SPLINE) or a flattened polyline (LWPOLYLINE)",
                        e, page, insunits, extents, layers, {}, {}, entities, points);
}

} // namespace

} // namespace kontur::io::dxfwrite

namespace kontur::io {

bool isStraight(const geo::Bezier &b)
{
    if (b.degree() <= 1)
        return true;
    const geo::Point a = b.startPoint(), d = b.endPoint() - a;
    const double length2 = d.squaredNorm();
    if (!(length2 > 0) || !std::isfinite(length2))
        return false;
    // What an elevated line's rounding leaves: a few units in the last place of the coordinates.
    const double slack = 1e-12 * (a.norm() + b.endPoint().norm() + std::sqrt(length2));
    for (const geo::Point &p : b.controlPoints()) {
        const geo::Point v = p - a;
        const double t = v.dot(d) / length2;
        const double off = std::abs(v.x() * d.y() - v.y() * d.x()) / std::sqrt(length2);
        if (off > slack || t < 0.0 || t > 1.0)
            return false;
    }
    return true;
}

double defaultDxfTolerance(const QString &units)
{
    const double mm = 0.05;
    if (units == QLatin1String("cm"))
        return mm / 10;
    if (units == QLatin1String("in"))
        return mm / 25.4;
    if (units == QLatin1String("pt"))
        return mm / 25.4 * 72;
    if (units == QLatin1String("px"))
        return mm / 25.4 * 96;
    return mm;
}

QByteArray exportDxf(std::span<const DxfCurve> curves, const DxfExportOptions &options)
{
    qint64 entities = 0, points = 0;
    return dxfwrite::build(curves, options, entities, points);
}

Result<Ok> writeDxf(const QString &path, std::span<const DxfCurve> curves, const DxfExportOptions &options,
                    const Limits &limits)
{
    if (auto e = nonFiniteCoordinate(path, curves))
        return *e;
    qint64 entities = 0, points = 0;
    const NonFiniteWatch watch;
    const QByteArray bytes = dxfwrite::build(curves, options, entities, points);
    return writeDrawing(path, bytes, watch.seen(), {entities, "entities"}, {points, "points"}, limits);
}

} // namespace kontur::io
