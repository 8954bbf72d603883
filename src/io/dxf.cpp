// DXF import (see dxf.h): a file is pairs of lines, a group code (an integer) and its value (Autodesk's
// "DXF Reference", AutoCAD 2000, AC1015). Over 600 lines because one reader walks the sections and
// turns each of the seven entity kinds (with their object coordinates, bulges and B-spline knots) into
// Bézier pieces with the line of every error; the writer is dxfwrite.cpp.
#include "io/dxf.h"

#include "io/shapes.h"

#include "geometry/composite.h"
#include "io/fileio.h"
#include "io/svgpath.h"

#include <QStringDecoder>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

namespace kontur::io {

namespace {

struct Group
{
    int code = 0;
    std::string_view value; // trimmed
    int line = 0;           // the line of the group code
};

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// Text as a DXF file holds it: UTF-8 (AutoCAD 2007 on) or in the drawing's code page (`codec`, from
// $DWGCODEPAGE, before), with AutoCAD's escape \U+XXXX (four hex digits) for a character outside it.
int hexDigit(QChar c)
{
    const char16_t u = c.unicode();
    if (u >= u'0' && u <= u'9')
        return u - u'0';
    if (u >= u'a' && u <= u'f')
        return u - u'a' + 10;
    if (u >= u'A' && u <= u'F')
        return u - u'A' + 10;
    return -1;
}

QString dxfText(std::string_view value, const QByteArray &codec)
{
    const QByteArrayView bytes(value.data(), static_cast<qsizetype>(value.size()));
    QString in;
    if (!codec.isEmpty()) {
        QStringDecoder decoder(codec.constData());
        if (decoder.isValid())
            in = decoder.decode(bytes);
    }
    if (in.isEmpty())
        in = QString::fromUtf8(bytes);
    QString out;
    for (qsizetype i = 0; i < in.size(); ++i) {
        if (in.at(i) == QLatin1Char('\\') && i + 6 < in.size() && in.at(i + 1).toUpper() == QLatin1Char('U') &&
            in.at(i + 2) == QLatin1Char('+')) {
            int code = 0;
            for (qsizetype k = i + 3; k < i + 7 && code >= 0; ++k)
                code = hexDigit(in.at(k)) < 0 ? -1 : code * 16 + hexDigit(in.at(k));
            if (code > 0) {
                out += QChar(static_cast<char16_t>(code));
                i += 6;
                continue;
            }
        }
        out += in.at(i);
    }
    return out;
}

class Reader final
{
public:
    Reader(std::string_view text, const QString &file, const DxfImportOptions &options)
        : m_lines(text)
        , m_file(file)
        , m_options(options)
    {
    }

    Result<DxfImport> read();

private:
    Error error(ErrorCode code, int line, const QString &message) const
    {
        Error e;
        e.code = code;
        e.file = m_file;
        e.line = line;
        e.message = message;
        return e;
    }
    // The next pair, or false at the end of the text (an error when it ends after a group code).
    std::optional<Error> next(Group &g, bool &end);
    std::optional<Error> readEntities(DxfImport &out);
    std::optional<Error> readHeader(DxfImport &out, double &scale);
    // One entity: its groups up to the next "0".
    std::optional<Error> entityGroups(std::vector<Group> &groups, Group &following, bool &end);
    std::optional<Error> addEntity(const Group &start, const std::vector<Group> &groups, DxfImport &out);
    std::optional<Error> addCurve(DxfImport &out, const Group &start, const std::vector<Group> &groups,
                                  geo::PiecewiseBezier curve);
    std::optional<Error> number(const Group &g, double &v) const;
    std::optional<Error> countPoints(qint64 n, int line);

    LineSplitter m_lines;
    QString m_file;
    DxfImportOptions m_options;
    double m_scale = 1.0; // file units to the imported units
    QByteArray m_codec;   // the code page of the file's text (for QStringDecoder), empty for UTF-8
    qint64 m_points = 0;
    std::optional<Group> m_pending; // a pair read ahead
};

std::optional<Error> Reader::next(Group &g, bool &end)
{
    if (m_pending) {
        g = *m_pending;
        m_pending.reset();
        end = false;
        return std::nullopt;
    }
    std::string_view codeText;
    if (!m_lines.next(codeText)) {
        end = true;
        return std::nullopt;
    }
    codeText = trimmed(codeText);
    const int line = m_lines.number();
    int code = 0;
    const auto [ptr, ec] = std::from_chars(codeText.data(), codeText.data() + codeText.size(), code);
    if (ec != std::errc() || ptr != codeText.data() + codeText.size() || codeText.empty())
        return error(ErrorCode::DxfSyntax, line,
                     QStringLiteral("expected a group code (an integer), found \"%1\"")
                         .arg(QString::fromUtf8(codeText.data(),
                                                static_cast<qsizetype>(std::min<std::size_t>(codeText.size(), 40)))));
    std::string_view value;
    if (!m_lines.next(value))
        return error(ErrorCode::DxfSyntax, line,
                     QStringLiteral("the file ends after group code %1, without its value").arg(code));
    g = {code, trimmed(value), line};
    end = false;
    return std::nullopt;
}

std::optional<Error> Reader::number(const Group &g, double &v) const
{
    if (parseDouble(g.value, v) != NumberStatus::Ok)
        return error(ErrorCode::DxfSyntax, g.line + 1,
                     QStringLiteral("group code %1 needs a finite number, found \"%2\"")
                         .arg(g.code)
                         .arg(QString::fromUtf8(g.value.data(),
                                                static_cast<qsizetype>(std::min<std::size_t>(g.value.size(), 40)))));
    return std::nullopt;
}

std::optional<Error> Reader::countPoints(qint64 n, int line)
{
    m_points += n;
    if (n < 0 || m_points > m_options.limits.maxPoints)
        return error(
            ErrorCode::TooManyPoints, line,
            QStringLiteral("more than %1 points, the most Kontur reads from one file").arg(m_options.limits.maxPoints));
    return std::nullopt;
}

std::optional<Error> Reader::readHeader(DxfImport &out, double &scale)
{
    Group g;
    bool end = false;
    bool insunits = false;
    std::string_view variable, version, codePage;
    while (true) {
        if (auto e = next(g, end))
            return e;
        if (end)
            return error(ErrorCode::DxfSyntax, m_lines.number(), QStringLiteral("the HEADER section has no ENDSEC"));
        if (g.code == 0 && g.value == "ENDSEC") {
            // Text before AutoCAD 2007 (AC1021) is in the drawing's code page, ANSI_<n> (Windows' <n>).
            if (version < "AC1021" && codePage.starts_with("ANSI_"))
                m_codec = QByteArray("windows-") +
                          QByteArray(codePage.substr(5).data(), static_cast<qsizetype>(codePage.size() - 5));
            return std::nullopt;
        }
        if (g.code == 9) {
            variable = g.value;
            insunits = g.value == "$INSUNITS";
        } else if (variable == "$ACADVER" && g.code == 1)
            version = g.value;
        else if (variable == "$DWGCODEPAGE" && g.code == 3)
            codePage = g.value;
        else if (insunits && g.code == 70) {
            int u = 0;
            const auto [ptr, ec] = std::from_chars(g.value.data(), g.value.data() + g.value.size(), u);
            if (ec != std::errc() || ptr != g.value.data() + g.value.size())
                return error(ErrorCode::DxfSyntax, g.line + 1, QStringLiteral("$INSUNITS needs an integer"));
            switch (u) {
            case 1:
                out.units = QStringLiteral("in");
                break;
            case 2: // feet
                out.units = QStringLiteral("in");
                scale = 12.0;
                break;
            case 4:
                out.units = QStringLiteral("mm");
                break;
            case 5:
                out.units = QStringLiteral("cm");
                break;
            case 6: // metres
                out.units = QStringLiteral("mm");
                scale = 1000.0;
                break;
            case 14: // decimetres
                out.units = QStringLiteral("cm");
                scale = 10.0;
                break;
            default:
                out.units = QStringLiteral("px");
            }
            insunits = false;
        }
    }
}

std::optional<Error> Reader::entityGroups(std::vector<Group> &groups, Group &following, bool &end)
{
    groups.clear();
    while (true) {
        if (auto e = next(following, end))
            return e;
        if (end || following.code == 0)
            return std::nullopt;
        groups.push_back(following);
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

// The control points a polyline's arcs add to its vertices (none for a polyline of lines).
qint64 interiorPoints(const std::vector<geo::Bezier> &segments)
{
    qint64 n = 0;
    for (const geo::Bezier &b : segments)
        n += b.degree() - 1;
    return n;
}

// Vertices with bulges as segments: lines, or arcs where the bulge is not 0. Stops once the arcs'
// control points pass `budget` (the points the file may still have), so that a hostile file of many
// huge arcs is refused before it fills the memory; the caller's count then refuses it.
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

} // namespace

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

namespace {

QString entityName(std::string_view type)
{
    return QString::fromLatin1(type.data(), static_cast<qsizetype>(type.size()));
}

std::optional<Error> Reader::addCurve(DxfImport &out, const Group &start, const std::vector<Group> &groups,
                                      geo::PiecewiseBezier curve)
{
    if (curve.isEmpty())
        return std::nullopt;
    if (static_cast<qint64>(out.curves.size()) >= m_options.limits.maxCurves)
        return error(ErrorCode::TooManyCurves, start.line,
                     QStringLiteral("more than %1 entities, the most Kontur reads from one file")
                         .arg(m_options.limits.maxCurves));
    DxfImportedCurve c;
    for (const Group &g : groups) {
        if (g.code == 8 && g.value != "0")
            c.name = dxfText(g.value, m_codec);
        if (g.code == 420) {
            int rgb = 0;
            const auto [ptr, ec] = std::from_chars(g.value.data(), g.value.data() + g.value.size(), rgb);
            if (ec == std::errc() && rgb >= 0 && rgb <= 0xffffff)
                c.color = QStringLiteral("#%1").arg(rgb, 6, 16, QLatin1Char('0'));
        }
    }
    if (m_scale != 1.0) {
        std::vector<geo::Bezier> scaled;
        for (const geo::Bezier &b : curve.segments()) {
            std::vector<geo::Point> pts = b.controlPoints();
            for (geo::Point &p : pts)
                p *= m_scale;
            scaled.emplace_back(std::move(pts));
        }
        curve = geo::PiecewiseBezier(std::move(scaled), curve.isClosed());
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

std::optional<Error> Reader::addEntity(const Group &start, const std::vector<Group> &groups, DxfImport &out)
{
    const std::string_view type = start.value;
    const QString name = entityName(type);
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
    if (std::abs(ex) > 1e-12 || std::abs(ey) > 1e-12 || std::abs(std::abs(ez) - 1.0) > 1e-12)
        return error(ErrorCode::DxfUnsupported, start.line,
                     QStringLiteral("%1: the entity does not lie in the drawing plane (extrusion %2 %3 %4)")
                         .arg(name)
                         .arg(ex)
                         .arg(ey)
                         .arg(ez));
    // Object coordinates of the planar entities (LWPOLYLINE, ARC, CIRCLE) into the world.
    const auto ocs = [mirrored](geo::Point p) {
        if (mirrored)
            p.x() = 0.0 - p.x();
        return p;
    };
    const auto value = [&](int code, double fallback, double &v) -> std::optional<Error> {
        v = fallback;
        for (const Group &g : groups)
            if (g.code == code)
                return number(g, v);
        return std::nullopt;
    };
    const auto integer = [&](int code) {
        for (const Group &g : groups)
            if (g.code == code) {
                long long v = 0;
                const auto [ptr, ec] = std::from_chars(g.value.data(), g.value.data() + g.value.size(), v);
                return ec == std::errc() ? v : 0LL;
            }
        return 0LL;
    };
    const double tol = m_options.arcTolerance;

    if (type == "LINE") {
        double x1, y1, x2, y2;
        for (auto [code, v] : {std::pair{10, &x1}, {20, &y1}, {11, &x2}, {21, &y2}})
            if (auto e = value(code, 0.0, *v))
                return e;
        if (auto e = countPoints(2, start.line))
            return e;
        if (geo::Point(x1, y1) == geo::Point(x2, y2))
            return std::nullopt;
        return addCurve(out, start, groups,
                        geo::PiecewiseBezier({geo::Bezier({geo::Point(x1, y1), geo::Point(x2, y2)})}, false));
    }
    if (type == "LWPOLYLINE") {
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
            p = ocs(p);
        if (mirrored)
            for (double &b : bulges)
                b = -b;
        const bool closed = (integer(70) & 1) != 0;
        auto segments = polylineSegments(pts, bulges, closed, tol, m_options.limits.maxPoints - m_points);
        if (auto e = countPoints(interiorPoints(segments), start.line))
            return e;
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(segments), closed));
    }
    if (type == "ARC" || type == "CIRCLE") {
        double cx, cy, r, a0 = 0.0, a1 = 360.0;
        for (auto [code, v] : {std::pair{10, &cx}, {20, &cy}, {40, &r}})
            if (auto e = value(code, 0.0, *v))
                return e;
        if (type == "ARC") {
            if (auto e = value(50, 0.0, a0))
                return e;
            if (auto e = value(51, 360.0, a1))
                return e;
        }
        if (!(r > 0))
            return std::nullopt;
        bool full = type == "CIRCLE";
        const double sweep = full ? 360.0 : sweepOf(a0, a1, 360.0, full);
        if (sweep == 0.0)
            return std::nullopt;
        const double rad = std::numbers::pi / 180.0;
        std::vector<geo::Bezier> arcs = arcToCubics(geo::Point(cx, cy), r, r, 0.0, a0 * rad, sweep * rad, tol);
        if (mirrored)
            for (geo::Bezier &b : arcs) {
                std::vector<geo::Point> pts = b.controlPoints();
                for (geo::Point &p : pts)
                    p = ocs(p);
                b = geo::Bezier(std::move(pts));
            }
        if (auto e = countPoints(static_cast<qint64>(3 * arcs.size() + 1), start.line))
            return e;
        if (full && !arcs.empty()) {
            // The circle ends exactly where it starts.
            std::vector<geo::Point> last = arcs.back().controlPoints();
            last.back() = arcs.front().startPoint();
            arcs.back() = geo::Bezier(std::move(last));
        }
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(arcs), full));
    }
    if (type == "ELLIPSE") {
        double cx, cy, mx, my, ratio, t0, t1;
        for (auto [code, v, fallback] : {std::tuple{10, &cx, 0.0},
                                         {20, &cy, 0.0},
                                         {11, &mx, 1.0},
                                         {21, &my, 0.0},
                                         {40, &ratio, 1.0},
                                         {41, &t0, 0.0},
                                         {42, &t1, 2 * std::numbers::pi}})
            if (auto e = value(code, fallback, *v))
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
        std::vector<geo::Bezier> arcs = arcToCubics(geo::Point::Zero(), rx, rx * ratio, phi, t0, sweep, tol);
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
        if (auto e = countPoints(static_cast<qint64>(3 * arcs.size() + 1), start.line))
            return e;
        if (full && !arcs.empty()) {
            std::vector<geo::Point> last = arcs.back().controlPoints();
            last.back() = arcs.front().startPoint();
            arcs.back() = geo::Bezier(std::move(last));
        }
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(arcs), full));
    }
    if (type == "SPLINE") {
        const long long flags = integer(70);
        const long long degree = integer(71);
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
        if (control.empty() && fitPoints)
            return error(ErrorCode::DxfUnsupported, start.line,
                         QStringLiteral("SPLINE: a spline given only by fit points is not supported (Kontur reads "
                                        "control points and knots)"));
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
            std::any_of(weights.begin(), weights.end(), [&](double w) { return w != weights.front(); }))
            return error(ErrorCode::DxfUnsupported, start.line,
                         QStringLiteral("SPLINE: a rational spline (unequal weights) has no exact Bézier form in "
                                        "Kontur"));
        // The Bézier pieces have p points each and one more: what they add to the control points
        // is counted before they are made (nothing for the Bézier knots Kontur writes).
        qint64 spans = 0;
        for (std::size_t k = p; k + 1 < control.size() + 1; ++k)
            spans += knots[k] < knots[k + 1] ? 1 : 0;
        if (auto e = countPoints(
                std::max<qint64>(0, spans * static_cast<qint64>(p) + 1 - static_cast<qint64>(control.size())),
                start.line))
            return e;
        std::vector<geo::Bezier> pieces = bezierPieces(knots, control, static_cast<int>(p));
        // Kontur writes a closed curve as a spline that ends where it starts.
        const bool closed =
            !pieces.empty() && pieces.size() >= 2 && pieces.back().endPoint() == pieces.front().startPoint();
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(pieces), closed));
    }
    return std::nullopt; // text, dimensions, hatches, points …: nothing to trace
}

Result<DxfImport> Reader::read()
{
    DxfImport out;
    Group g;
    bool end = false;
    bool sawEntities = false;
    while (true) {
        if (auto e = next(g, end))
            return *e;
        if (end)
            break;
        if (g.code == 0 && g.value == "EOF")
            break;
        if (g.code != 0 || g.value != "SECTION")
            continue;
        Group name;
        if (auto e = next(name, end))
            return *e;
        if (end || name.code != 2)
            return error(ErrorCode::DxfSyntax, end ? g.line : name.line,
                         QStringLiteral("a SECTION needs its name (group code 2)"));
        if (name.value == "HEADER") {
            if (auto e = readHeader(out, m_scale))
                return *e;
        } else if (name.value == "ENTITIES") {
            sawEntities = true;
            if (auto e = readEntities(out))
                return *e;
        }
    }
    if (!sawEntities)
        return error(ErrorCode::NoPaths, m_lines.number(), QStringLiteral("the file has no ENTITIES section"));
    if (out.curves.empty())
        return error(ErrorCode::NoPaths, m_lines.number(),
                     QStringLiteral("the DXF has no curves to import (LINE, LWPOLYLINE, POLYLINE, SPLINE, ARC, CIRCLE, "
                                    "ELLIPSE)"));
    return out;
}

std::optional<Error> Reader::readEntities(DxfImport &out)
{
    Group g;
    bool end = false;
    if (auto e = next(g, end))
        return e;
    std::vector<Group> groups;
    while (true) {
        if (end)
            return error(ErrorCode::DxfSyntax, m_lines.number(),
                         QStringLiteral("the file ends inside the ENTITIES section (no ENDSEC)"));
        if (g.code != 0) {
            // Stray groups before the first entity: skip them.
            if (auto e = next(g, end))
                return e;
            continue;
        }
        if (g.value == "ENDSEC")
            return std::nullopt;
        const Group start = g;
        Group following;
        if (auto e = entityGroups(groups, following, end))
            return e;
        if (start.value == "POLYLINE") {
            // The old form: VERTEX entities up to SEQEND.
            const long long flags = [&] {
                for (const Group &x : groups)
                    if (x.code == 70) {
                        long long v = 0;
                        (void)std::from_chars(x.value.data(), x.value.data() + x.value.size(), v);
                        return v;
                    }
                return 0LL;
            }();
            if ((flags & (16 | 64)) != 0)
                return error(ErrorCode::DxfUnsupported, start.line,
                             QStringLiteral("POLYLINE: polygon meshes and polyface meshes are not curves"));
            std::vector<geo::Point> pts;
            std::vector<double> bulges;
            std::vector<Group> vertex;
            g = following;
            while (!end && g.code == 0 && g.value == "VERTEX") {
                const Group vertexStart = g;
                if (auto e = entityGroups(vertex, following, end))
                    return e;
                double x = 0, y = 0, bulge = 0;
                long long vflags = 0;
                for (const Group &x2 : vertex) {
                    double v = 0;
                    if (x2.code == 10 || x2.code == 20 || x2.code == 42)
                        if (auto e = number(x2, v))
                            return e;
                    if (x2.code == 10)
                        x = v;
                    else if (x2.code == 20)
                        y = v;
                    else if (x2.code == 42)
                        bulge = v;
                    else if (x2.code == 70)
                        (void)std::from_chars(x2.value.data(), x2.value.data() + x2.value.size(), vflags);
                }
                (void)vertexStart;
                g = following;
                // A spline-fit polyline's frame (flag 16) is not drawn; its fitted vertices (8) are.
                if ((vflags & 16) != 0)
                    continue;
                if (auto e = countPoints(1, vertexStart.line))
                    return e;
                pts.emplace_back(x, y);
                bulges.push_back(bulge);
            }
            if (!end && g.code == 0 && g.value == "SEQEND") {
                if (auto e = entityGroups(vertex, following, end))
                    return e;
                g = following;
            }
            auto segments = polylineSegments(pts, bulges, (flags & 1) != 0, m_options.arcTolerance,
                                             m_options.limits.maxPoints - m_points);
            if (auto e = countPoints(interiorPoints(segments), start.line))
                return e;
            if (auto e = addCurve(out, start, groups, geo::PiecewiseBezier(std::move(segments), (flags & 1) != 0)))
                return e;
            continue;
        }
        if (auto e = addEntity(start, groups, out))
            return e;
        g = following;
    }
}

const char *nodeTypeName(geo::NodeType t)
{
    switch (t) {
    case geo::NodeType::Symmetric:
        return "symmetric";
    case geo::NodeType::Corner:
        return "corner";
    case geo::NodeType::Smooth:
        break;
    }
    return "smooth";
}

} // namespace

Result<DxfImport> importDxf(QByteArrayView bytes, const QString &file, const DxfImportOptions &options)
{
    if (bytes.size() > options.limits.maxFileBytes) {
        Error e;
        e.code = ErrorCode::FileTooLarge;
        e.file = file;
        e.message =
            QStringLiteral("the file is larger than %1 bytes, the most Kontur reads").arg(options.limits.maxFileBytes);
        return e;
    }
    if (bytes.startsWith("AutoCAD Binary DXF")) {
        Error e;
        e.code = ErrorCode::DxfUnsupported;
        e.file = file;
        e.line = 1;
        e.message = QStringLiteral("a binary DXF; Kontur reads DXF as text (save it as ASCII DXF)");
        return e;
    }
    std::string_view text(bytes.data(), static_cast<std::size_t>(bytes.size()));
    if (text.starts_with("\xEF\xBB\xBF"))
        text.remove_prefix(3);
    Reader reader(text, file, options);
    return reader.read();
}

Result<DxfImport> readDxf(const QString &path, const DxfImportOptions &options)
{
    auto bytes = readFileBytes(path, options.limits);
    if (!bytes)
        return bytes.error();
    return importDxf(*bytes, path, options);
}

Result<CurveRecord> recordFromDxfCurve(const geo::PiecewiseBezier &curve, double tolerance)
{
    Error e;
    e.code = ErrorCode::GeometryError;
    if (curve.isEmpty()) {
        e.message = QStringLiteral("the entity has no segments");
        return e;
    }
    CurveRecord r;
    if (curve.segmentCount() == 1 && curve.segments().front().degree() > 3 &&
        curve.segments().front().degree() <= 100) {
        r.kind = QStringLiteral("bezier");
        r.points = curve.segments().front().controlPoints();
        return r;
    }
    std::vector<geo::Bezier> pieces;
    for (const geo::Bezier &b : curve.segments()) {
        if (b.degree() <= 3)
            pieces.push_back(b);
        else
            appendCubicsWithin(b, tolerance, pieces);
    }
    const bool closed = curve.isClosed() && pieces.size() >= 3;
    auto composite = geo::compositeFromPieces(pieces, closed);
    if (!composite) {
        e.message = QString::fromStdString(composite.error().message);
        return e;
    }
    r.kind = QStringLiteral("composite");
    r.closed = closed;
    r.points = composite->controlPoints();
    if (closed)
        r.points.pop_back(); // the record does not repeat the first knot
    for (int k = 0; k < composite->knotCount(); ++k)
        r.nodeTypes.push_back(QLatin1String(nodeTypeName(composite->nodeType(k))));
    return r;
}

} // namespace kontur::io
