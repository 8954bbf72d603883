// DXF export (see dxf.h): the header with the units and the ENTITIES section, one SPLINE, LINE or
// LWPOLYLINE per curve. Group codes and entities as in Autodesk's "DXF Reference" (AutoCAD 2000, AC1015).
#include "io/dxf.h"

#include "io/fileio.h"

#include <algorithm>
#include <cmath>

namespace kontur::io {

namespace {

struct Writer
{
    QByteArray out;
    unsigned handle = 0x100; // entity handles (group 5), hexadecimal; $HANDSEED is the next one
    qint64 entities = 0;     // as the reader counts them: entities
    qint64 points = 0;       // and points (vertices, a LINE's two ends, control points)

    void pair(int code, QByteArrayView value)
    {
        out += QByteArray::number(code).rightJustified(3, ' ');
        out += '\n';
        out += value.toByteArray();
        out += '\n';
    }
    void number(int code, double v)
    {
        QByteArray text;
        appendDouble(text, v);
        pair(code, text);
    }
    void integer(int code, long long v) { pair(code, QByteArray::number(v)); }
    void point(int code, const geo::Point &p)
    {
        number(code, p.x());
        number(code + 10, p.y());
        number(code + 20, 0.0);
    }
    void entity(const char *type, const char *subclass)
    {
        pair(0, type);
        pair(5, QByteArray::number(handle++, 16).toUpper());
        pair(100, "AcDbEntity");
        pair(8, "0");
        pair(100, subclass);
    }
};

// What $INSUNITS says for Kontur's units, and the factor from document units to the file's.
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

// Runs of segments that meet exactly (a curve's segments always do; a gap starts a new entity).
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

void writeRun(Writer &w, const std::vector<geo::Bezier> &run, bool closed, const DxfExportOptions &options,
              double tolerance)
{
    const bool linear = std::all_of(run.begin(), run.end(), [](const geo::Bezier &b) { return b.degree() == 1; });
    if (linear || options.flavour == DxfFlavour::Polyline) {
        std::vector<geo::Point> pts;
        for (const geo::Bezier &b : run) {
            if (b.degree() == 1) {
                if (pts.empty())
                    pts.push_back(b.startPoint());
                pts.push_back(b.endPoint());
            } else {
                geo::flatten(b, tolerance, pts);
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

} // namespace

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

namespace {

QByteArray build(std::span<const DxfCurve> curves, const DxfExportOptions &options, qint64 &entities, qint64 &points)
{
    const auto [insunits, scale] = fileUnits(options.units);
    const double tolerance = (options.tolerance > 0 ? options.tolerance : defaultDxfTolerance(options.units)) * scale;
    geo::Box box;
    for (const DxfCurve &c : curves)
        if (!c.curve.isEmpty())
            box.extend(c.curve.boundingBox());
    Writer w;
    w.pair(999, "Written by Kontur: exact Bezier control points (SPLINE) or a flattened polyline (LWPOLYLINE)");
    w.pair(0, "SECTION");
    w.pair(2, "HEADER");
    w.pair(9, "$ACADVER");
    w.pair(1, "AC1015");
    w.pair(9, "$INSUNITS");
    w.integer(70, insunits);
    w.pair(9, "$MEASUREMENT");
    w.integer(70, insunits == 1 ? 0 : 1);
    if (!box.isEmpty()) {
        w.pair(9, "$EXTMIN");
        w.point(10, box.min() * scale);
        w.pair(9, "$EXTMAX");
        w.point(10, box.max() * scale);
    }
    // $HANDSEED must exceed every handle: the entities are written first.
    Writer e;
    e.pair(0, "SECTION");
    e.pair(2, "ENTITIES");
    for (const DxfCurve &c : curves) {
        const auto runs = runsOf(c.curve, scale);
        for (const auto &run : runs)
            writeRun(e, run, c.curve.isClosed() && runs.size() == 1, options, tolerance);
    }
    e.pair(0, "ENDSEC");
    e.pair(0, "EOF");
    w.pair(9, "$HANDSEED");
    w.pair(5, QByteArray::number(e.handle, 16).toUpper());
    w.pair(0, "ENDSEC");
    w.out += e.out;
    entities = e.entities;
    points = e.points;
    return std::move(w.out);
}

} // namespace

QByteArray exportDxf(std::span<const DxfCurve> curves, const DxfExportOptions &options)
{
    qint64 entities = 0, points = 0;
    return build(curves, options, entities, points);
}

Result<Ok> writeDxf(const QString &path, std::span<const DxfCurve> curves, const DxfExportOptions &options,
                    const Limits &limits)
{
    Error e;
    e.file = path;
    for (const DxfCurve &c : curves)
        for (const geo::Bezier &b : c.curve.segments())
            for (const geo::Point &p : b.controlPoints())
                if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
                    e.code = ErrorCode::NumberOutOfRange;
                    e.message =
                        QStringLiteral("the drawing cannot be written: a coordinate of \"%1\" is not a finite number")
                            .arg(c.name);
                    return e;
                }
    qint64 entities = 0, points = 0;
    const QByteArray bytes = build(curves, options, entities, points);
    if (entities > limits.maxCurves) {
        e.code = ErrorCode::TooManyCurves;
        e.message = QStringLiteral("the drawing cannot be written: %1 entities; a file holds at most %2")
                        .arg(entities)
                        .arg(limits.maxCurves);
        return e;
    }
    if (points > limits.maxPoints || bytes.size() > limits.maxFileBytes) {
        e.code = points > limits.maxPoints ? ErrorCode::TooManyPoints : ErrorCode::FileTooLarge;
        e.message = QStringLiteral("the drawing cannot be written: %1 points in %2 bytes; a file holds at most %3 "
                                   "points in %4 bytes")
                        .arg(points)
                        .arg(bytes.size())
                        .arg(limits.maxPoints)
                        .arg(limits.maxFileBytes);
        return e;
    }
    return writeFileAtomically(path, bytes);
}

} // namespace kontur::io
