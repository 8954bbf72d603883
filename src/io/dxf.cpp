// DXF import (see dxf.h): a file is pairs of lines, a group code (an integer) and its value (Autodesk's
// "DXF Reference", AutoCAD 2000, AC1015). Over 600 lines because one reader walks the sections (the
// header's units, the layer table's colours, the blocks) and turns each of the seven entity kinds
// (with their object coordinates, bulges and B-spline knots), the INSERTs of blocks and the hatch
// boundaries into Bézier pieces with the line of every error, and counts what it skips; the writer
// is dxfwrite.cpp.
#include "io/dxf.h"

#include "io/shapes.h"

#include "geometry/composite.h"
#include "io/fileio.h"
#include "io/svgpath.h"

#include <QHash>
#include <QStringDecoder>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <cmath>
#include <functional>
#include <map>
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

long long integerOf(const Group &g)
{
    long long v = 0;
    (void)std::from_chars(g.value.data(), g.value.data() + g.value.size(), v);
    return v;
}

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

// An entity as read: its first group ("0" and the type), the groups up to the next entity, and for a
// POLYLINE its VERTEX entities (as numbers: a polyline may have millions).
struct Vertex
{
    double x = 0, y = 0, bulge = 0;
    long long flags = 0;
    int line = 0;
};

struct RawEntity
{
    Group start;
    std::vector<Group> groups;
    std::vector<Vertex> vertices;
};

// A BLOCK: its base point (the point an INSERT puts at its insertion point) and its entities.
struct Block
{
    geo::Point base = geo::Point::Zero();
    std::vector<RawEntity> entities;
};

// Where an entity lies in the drawing: x ↦ m·x + t (the INSERTs it is inside of, composed), the layer
// that its entities on the layer "0" take (DXF's rule for block content) and the nesting depth.
struct Placement
{
    Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
    geo::Point t = geo::Point::Zero();
    std::string_view layer;
    QString color; // the INSERT's colour, for its content's colour "by block" (62 = 0)
    QString piece; // the ASTM D6673 (AAMA) piece the block is, empty when it is none
    int depth = 0;
};

// Blocks inside blocks deeper than this are a loop (a block that inserts itself) or a hostile file.
constexpr int kMaxBlockDepth = 32;

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
    std::optional<Error> readHeader(DxfImport &out, double &scale);
    // The entities of a section up to its ENDSEC, each handed to `take` (a POLYLINE with its vertices).
    std::optional<Error> readSection(const char *section,
                                     const std::function<std::optional<Error>(RawEntity &&)> &take);
    std::optional<Error> readBlocks();
    // One entity: its groups up to the next "0".
    std::optional<Error> entityGroups(std::vector<Group> &groups, Group &following, bool &end);
    std::optional<Error> process(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> insert(const RawEntity &entity, const Placement &place, DxfImport &out);
    // A POINT or TEXT of an ASTM D6673 piece's block: a notch, a drill hole or the piece's text.
    std::optional<Error> aamaMark(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> polyline(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> hatch(const RawEntity &entity, const Placement &place, DxfImport &out);
    std::optional<Error> addEntity(const Group &start, const std::vector<Group> &groups, const Placement &place,
                                   DxfImport &out);
    std::optional<Error> addCurve(DxfImport &out, const Group &start, const std::vector<Group> &groups,
                                  geo::PiecewiseBezier curve, const Placement &place);
    std::optional<Error> number(const Group &g, double &v) const;
    std::optional<Error> countPoints(qint64 n, int line);
    void skip(DxfImport &out, DxfSkipped what) { ++out.skipped[static_cast<std::size_t>(what)]; }

    LineSplitter m_lines;
    QString m_file;
    DxfImportOptions m_options;
    double m_scale = 1.0; // file units to the imported units
    QByteArray m_codec;   // the code page of the file's text (for QStringDecoder), empty for UTF-8
    qint64 m_points = 0;
    std::optional<Group> m_pending; // a pair read ahead
    std::map<std::string, Block, std::less<>> m_blocks;
    bool m_blocksRead = false;
    std::vector<RawEntity> m_deferred;     // INSERTs met before the BLOCKS section
    qint64 m_instances = 0;                // block instances exploded so far
    QHash<QString, QString> m_layerColors; // the LAYER table's colours, by case-folded layer name
    // The colour an entity is drawn in: its true colour (420), its ACI (62: 1–255; 0 by block), else
    // its layer's; black when none is given.
    QString colorOf(const std::vector<Group> &groups, std::string_view layer, const Placement &place) const;
    std::optional<Error> readTables();
    // The piece's name when `block` is an ASTM D6673 piece (its cut line on layer 1 and its "Piece
    // Name:" text or a grain line on layer 7), else empty.
    QString aamaPiece(std::string_view name, const Block &block);
    std::map<std::string, QString, std::less<>> m_pieces;
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
        if (!end && g.code == 0 && g.value == "ENDSEC") {
            // dxflib (LibreCAD's library files) closes the HEADER after $HANDSEED and writes the other
            // variables, $INSUNITS among them, after that ENDSEC and before a second one: variables
            // (group 9) right after an ENDSEC still belong to the HEADER, as ezdxf reads them.
            Group after;
            bool afterEnd = false;
            if (auto e = next(after, afterEnd))
                return e;
            if (!afterEnd && after.code == 9) {
                g = after;
            } else {
                if (!afterEnd)
                    m_pending = after; // read again as the next section's
                end = true;
            }
        }
        if (g.code == 0 && g.value != "ENDSEC" && !end) {
            // A HEADER that closes early (the next SECTION or EOF without its ENDSEC): what was read
            // of it, the units too, stands; the pair is read again as the next section's.
            m_pending = g;
            end = true;
        }
        if (end || (g.code == 0 && g.value == "ENDSEC")) {
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
            out.declaredUnits = true;
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
                out.units = m_options.unitlessUnits;
                out.declaredUnits = false;
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
                        geo::PiecewiseBezier({geo::Bezier({geo::Point(x1, y1), geo::Point(x2, y2)})}, false), place);
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
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(segments), closed), place);
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
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(arcs), full), place);
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
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(arcs), full), place);
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
                std::max<qint64>(0, spans * static_cast<qint64>(p) + 1 - static_cast<qint64>(control.size())),
                start.line))
            return e;
        std::vector<geo::Bezier> pieces = bezierPieces(knots, control, static_cast<int>(p));
        // Kontur writes a closed curve as a spline that ends where it starts.
        const bool closed =
            !pieces.empty() && pieces.size() >= 2 && pieces.back().endPoint() == pieces.front().startPoint();
        return addCurve(out, start, groups, geo::PiecewiseBezier(std::move(pieces), closed), place);
    }
    skip(out, skippedKind(type));
    return std::nullopt;
}

} // namespace

QString skippedSummary(const DxfImport &dxf)
{
    return skippedSummary(dxf.skipped, "other entity", "other entities");
}

namespace {

Result<DxfImport> Reader::read()
{
    DxfImport out;
    out.units = m_options.unitlessUnits;
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
        } else if (name.value == "TABLES") {
            if (auto e = readTables())
                return *e;
        } else if (name.value == "BLOCKS") {
            if (auto e = readBlocks())
                return *e;
        } else if (name.value == "ENTITIES") {
            sawEntities = true;
            const auto take = [&](RawEntity &&entity) -> std::optional<Error> {
                // An INSERT before the blocks it names (BLOCKS normally comes first) waits for them.
                if (entity.start.value == "INSERT" && !m_blocksRead) {
                    m_deferred.push_back(std::move(entity));
                    return std::nullopt;
                }
                return process(entity, Placement{}, out);
            };
            if (auto e = readSection("ENTITIES", take))
                return *e;
        }
    }
    for (const RawEntity &entity : m_deferred)
        if (auto e = process(entity, Placement{}, out))
            return *e;
    if (!sawEntities)
        return error(ErrorCode::NoPaths, m_lines.number(), QStringLiteral("the file has no ENTITIES section"));
    if (out.curves.empty()) {
        const QString skipped = skippedSummary(out);
        Error e = error(ErrorCode::NoPaths, m_lines.number(),
                        QStringLiteral("the DXF has no curves to import (LINE, LWPOLYLINE, POLYLINE, SPLINE, ARC, "
                                       "CIRCLE, ELLIPSE, HATCH boundaries, blocks of them)%1")
                            .arg(skipped.isEmpty() ? QString() : QStringLiteral("; skipped: ") + skipped));
        e.skipped = out.skipped;
        return e;
    }
    return out;
}

std::optional<Error> Reader::readSection(const char *section,
                                         const std::function<std::optional<Error>(RawEntity &&)> &take)
{
    Group g;
    bool end = false;
    if (auto e = next(g, end))
        return e;
    while (true) {
        if (end)
            return error(ErrorCode::DxfSyntax, m_lines.number(),
                         QStringLiteral("the file ends inside the %1 section (no ENDSEC)").arg(QLatin1String(section)));
        if (g.code != 0) {
            // Stray groups before the first entity: skip them.
            if (auto e = next(g, end))
                return e;
            continue;
        }
        if (g.value == "ENDSEC")
            return std::nullopt;
        RawEntity entity;
        entity.start = g;
        Group following;
        if (auto e = entityGroups(entity.groups, following, end))
            return e;
        g = following;
        if (entity.start.value == "POLYLINE") {
            // The old form: VERTEX entities up to SEQEND.
            std::vector<Group> vertex;
            while (!end && g.code == 0 && g.value == "VERTEX") {
                Vertex v;
                v.line = g.line;
                if (auto e = entityGroups(vertex, following, end))
                    return e;
                for (const Group &x : vertex) {
                    if (x.code == 10 || x.code == 20 || x.code == 42)
                        if (auto e = number(x, x.code == 10 ? v.x : x.code == 20 ? v.y : v.bulge))
                            return e;
                    if (x.code == 70)
                        v.flags = integerOf(x);
                }
                if (static_cast<qint64>(entity.vertices.size()) >= m_options.limits.maxPoints)
                    return error(ErrorCode::TooManyPoints, v.line,
                                 QStringLiteral("more than %1 points, the most Kontur reads from one file")
                                     .arg(m_options.limits.maxPoints));
                entity.vertices.push_back(v);
                g = following;
            }
            if (!end && g.code == 0 && g.value == "SEQEND") {
                if (auto e = entityGroups(vertex, following, end))
                    return e;
                g = following;
            }
        }
        if (auto e = take(std::move(entity)))
            return e;
    }
}

std::optional<Error> Reader::readBlocks()
{
    Block *current = nullptr;
    const auto take = [&](RawEntity &&entity) -> std::optional<Error> {
        if (entity.start.value == "BLOCK") {
            std::string name;
            geo::Point base = geo::Point::Zero();
            for (const Group &g : entity.groups) {
                if (g.code == 2)
                    name.assign(g.value);
                else if (g.code == 10 || g.code == 20)
                    if (auto e = number(g, g.code == 10 ? base.x() : base.y()))
                        return e;
            }
            current = &m_blocks[name];
            *current = Block{base, {}};
        } else if (entity.start.value == "ENDBLK") {
            current = nullptr;
        } else if (current) {
            current->entities.push_back(std::move(entity));
        }
        return std::nullopt;
    };
    if (auto e = readSection("BLOCKS", take))
        return e;
    m_blocksRead = true;
    return std::nullopt;
}

QString Reader::aamaPiece(std::string_view name, const Block &block)
{
    if (const auto found = m_pieces.find(name); found != m_pieces.end())
        return found->second;
    bool cut = false, grain = false;
    QString title;
    for (const RawEntity &e : block.entities) {
        std::string_view layer = "0", text;
        for (const Group &g : e.groups) {
            if (g.code == 8)
                layer = g.value;
            else if (g.code == 1)
                text = g.value;
        }
        const bool isText = e.start.value == "TEXT" || e.start.value == "MTEXT";
        cut = cut || (layer == "1" && !isText);
        grain = grain || layer == "7";
        if (isText && title.isEmpty()) {
            const QString t = dxfText(text, m_codec).trimmed();
            if (t.startsWith(QLatin1String("Piece Name:"), Qt::CaseInsensitive))
                title = t.mid(11).trimmed();
        }
    }
    QString piece;
    if (cut && (grain || !title.isEmpty()))
        piece = title.isEmpty() ? dxfText(name, m_codec) : title;
    m_pieces.emplace(std::string(name), piece);
    return piece;
}

QString Reader::colorOf(const std::vector<Group> &groups, std::string_view layer, const Placement &place) const
{
    long long aci = 256; // by layer
    for (const Group &g : groups) {
        if (g.code == 420) {
            const long long rgb = integerOf(g);
            if (rgb >= 0 && rgb <= 0xffffff)
                return QStringLiteral("#%1").arg(rgb, 6, 16, QLatin1Char('0'));
        } else if (g.code == 62) {
            aci = integerOf(g);
        }
    }
    if (aci >= 1 && aci <= 255)
        return aciColorName(static_cast<int>(aci));
    if (aci == 0 && !place.color.isEmpty())
        return place.color;
    const auto found = m_layerColors.constFind(dxfText(layer, m_codec).toCaseFolded());
    return found != m_layerColors.constEnd() ? *found : QStringLiteral("#000000");
}

// The LAYER table's colours (62, negative for a layer that is off; 420 a true colour).
std::optional<Error> Reader::readTables()
{
    return readSection("TABLES", [&](RawEntity &&entity) -> std::optional<Error> {
        if (entity.start.value != "LAYER")
            return std::nullopt;
        QString name, color;
        for (const Group &g : entity.groups) {
            if (g.code == 2)
                name = dxfText(g.value, m_codec);
            else if (g.code == 62 && color.isEmpty())
                color = aciColorName(static_cast<int>(std::abs(integerOf(g))));
            else if (g.code == 420 && integerOf(g) >= 0 && integerOf(g) <= 0xffffff)
                color = QStringLiteral("#%1").arg(integerOf(g), 6, 16, QLatin1Char('0'));
        }
        if (!name.isEmpty() && !color.isEmpty())
            m_layerColors.insert(name.toCaseFolded(), color);
        return std::nullopt;
    });
}

std::optional<Error> Reader::process(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    const std::string_view type = entity.start.value;
    if (type == "INSERT")
        return insert(entity, place, out);
    if (type == "POLYLINE")
        return polyline(entity, place, out);
    if (type == "HATCH")
        return hatch(entity, place, out);
    if (type == "SEQEND" || type == "VERTEX" || type == "VIEWPORT")
        return std::nullopt; // the end of an INSERT's attributes; a paper space view: nothing to draw
    if (!place.piece.isEmpty() && (type == "POINT" || type == "TEXT" || type == "MTEXT"))
        return aamaMark(entity, place, out);
    return addEntity(entity.start, entity.groups, place, out);
}

std::optional<Error> Reader::aamaMark(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    std::string_view layer = "0", text;
    double x = 0, y = 0, angle = 0;
    for (const Group &g : entity.groups) {
        double *v = g.code == 10 ? &x : g.code == 20 ? &y : g.code == 50 ? &angle : nullptr;
        if (v) {
            if (auto e = number(g, *v))
                return e;
        } else if (g.code == 8) {
            layer = g.value;
        } else if (g.code == 1) {
            text = g.value;
        }
    }
    if (layer == "0" && !place.layer.empty())
        layer = place.layer;
    auto found = std::find_if(out.pieces.begin(), out.pieces.end(),
                              [&](const DxfAamaPiece &p) { return p.name == place.piece; });
    if (found == out.pieces.end()) {
        out.pieces.push_back({});
        out.pieces.back().name = place.piece;
        found = out.pieces.end() - 1;
    }
    DxfAamaPiece &piece = *found;
    if (entity.start.value != "POINT") {
        // The standard's annotations ("Key: value"); the piece's name was read with its block.
        const QString t = dxfText(text, m_codec).trimmed();
        const auto value = [&](const char *key) {
            return t.startsWith(QLatin1String(key), Qt::CaseInsensitive)
                       ? std::optional<QString>(t.mid(static_cast<qsizetype>(std::strlen(key))).trimmed())
                       : std::nullopt;
        };
        if (value("Piece Name:")) {
            // read with the block (Reader::aamaPiece)
        } else if (const auto size = value("Size:")) {
            piece.size = *size;
        } else if (const auto material = value("Material:")) {
            piece.material = *material;
        } else if (const auto quantity = value("Quantity:")) {
            bool ok = false;
            const int n = quantity->toInt(&ok);
            if (ok && n >= 1)
                piece.quantity = n;
        } else if (const auto note = value("Annotation:"); note && note->compare(QLatin1String("On fold"),
                                                                                  Qt::CaseInsensitive) == 0) {
            piece.onFold = true;
        } else {
            skip(out, DxfSkipped::Text);
        }
        return std::nullopt;
    }
    bool isNumber = false;
    const int aama = QString::fromLatin1(layer.data(), static_cast<qsizetype>(layer.size())).toInt(&isNumber);
    if (!isNumber || (aama != 4 && aama != 13 && (aama < 80 || aama > 84))) {
        skip(out, DxfSkipped::Other);
        return std::nullopt;
    }
    const bool placed = place.depth > 0;
    const geo::Point p = (placed ? geo::Point(place.m * geo::Point(x, y) + place.t) : geo::Point(x, y)) * m_scale;
    const double a = angle * std::numbers::pi / 180.0;
    const geo::Point d = placed ? geo::Point(place.m * geo::Point(std::cos(a), std::sin(a))) :
                                  geo::Point(std::cos(a), std::sin(a));
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return error(ErrorCode::NumberOutOfRange, entity.start.line,
                     QStringLiteral("POINT: a point lies beyond the range of numbers"));
    piece.points.push_back({p, std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi, aama});
    return std::nullopt;
}

// An INSERT draws its block's entities moved by the insertion transform of the DXF Reference: the block's
// base point to the origin, scaled by (41, 42), rotated by 50 (degrees), moved to the insertion point
// (10, 20); a MINSERT repeats it in 70 columns and 71 rows spaced 44 and 45 along the rotated axes.
std::optional<Error> Reader::insert(const RawEntity &entity, const Placement &place, DxfImport &out)
{
    std::string_view blockName, layer = "0";
    double x = 0, y = 0, sx = 1, sy = 1, rotation = 0, dx = 0, dy = 0, ex = 0, ey = 0, ez = 1;
    long long columns = 1, rows = 1;
    for (const Group &g : entity.groups) {
        double *v = nullptr;
        switch (g.code) {
        case 2:
            blockName = g.value;
            break;
        case 8:
            layer = g.value;
            break;
        case 10:
            v = &x;
            break;
        case 20:
            v = &y;
            break;
        case 41:
            v = &sx;
            break;
        case 42:
            v = &sy;
            break;
        case 50:
            v = &rotation;
            break;
        case 44:
            v = &dx;
            break;
        case 45:
            v = &dy;
            break;
        case 210:
            v = &ex;
            break;
        case 220:
            v = &ey;
            break;
        case 230:
            v = &ez;
            break;
        case 70:
            columns = integerOf(g);
            break;
        case 71:
            rows = integerOf(g);
            break;
        default:
            break;
        }
        if (v)
            if (auto e = number(g, *v))
                return e;
    }
    const auto block = m_blocks.find(blockName);
    if (block == m_blocks.end() || place.depth >= kMaxBlockDepth) {
        skip(out, DxfSkipped::Other);
        return std::nullopt;
    }
    if (std::abs(ex) > 1e-12 || std::abs(ey) > 1e-12 || std::abs(std::abs(ez) - 1.0) > 1e-12) {
        skip(out, DxfSkipped::Solid3D);
        return std::nullopt;
    }
    if (sx == 0.0 || sy == 0.0)
        return std::nullopt; // flattened to a line or a point
    columns = std::max(1LL, columns);
    rows = std::max(1LL, rows);
    const double a = rotation * std::numbers::pi / 180.0;
    Eigen::Matrix2d r;
    r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    Eigen::Matrix2d scale = Eigen::Matrix2d::Zero();
    scale(0, 0) = sx;
    scale(1, 1) = sy;
    // Seen from below (extrusion 0,0,-1) the INSERT's own x axis points the other way.
    Eigen::Matrix2d flip = Eigen::Matrix2d::Identity();
    if (ez < 0)
        flip(0, 0) = -1;
    const Block &b = block->second;
    const QString piece = aamaPiece(blockName, b);
    const QString insertColor =
        colorOf(entity.groups, layer == "0" && !place.layer.empty() ? place.layer : layer, place);
    for (long long row = 0; row < rows; ++row)
        for (long long column = 0; column < columns; ++column) {
            if (++m_instances > m_options.limits.maxCurves)
                return error(ErrorCode::TooManyCurves, entity.start.line,
                             QStringLiteral("INSERT: more than %1 block instances, the most Kontur reads from one file")
                                 .arg(m_options.limits.maxCurves));
            const geo::Point at = geo::Point(x, y) + r * geo::Point(column * dx, row * dy);
            Placement inner;
            inner.m = place.m * flip * r * scale;
            inner.t = place.m * (flip * (at - r * scale * b.base)) + place.t;
            inner.layer = layer == "0" ? place.layer : layer;
            inner.color = insertColor;
            inner.piece = piece;
            inner.depth = place.depth + 1;
            for (const RawEntity &child : b.entities)
                if (auto e = process(child, inner, out))
                    return e;
        }
    return std::nullopt;
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
    const long long paths = integerOf(groups[i++]);
    bool malformed = false, unsupported = false;
    const auto at = [&](int code) { return i < groups.size() && groups[i].code == code; };
    const auto real = [&](int code, double &v) -> std::optional<Error> {
        if (!at(code)) {
            malformed = true;
            return std::nullopt;
        }
        return number(groups[i++], v);
    };
    const auto whole = [&](int code) -> long long {
        if (!at(code)) {
            malformed = true;
            return 0;
        }
        return integerOf(groups[i++]);
    };
    const auto point = [&](int code, geo::Point &p) -> std::optional<Error> {
        if (auto e = real(code, p.x()))
            return e;
        return real(code + 10, p.y());
    };
    const double tol = m_options.arcTolerance;
    const double flipX = ez < 0 ? -1.0 : 1.0;
    std::vector<std::vector<geo::Bezier>> loops;
    for (long long path = 0; path < paths && !malformed && !unsupported; ++path) {
        const long long type = whole(92);
        // Each edge as Bézier pieces, in its own direction.
        std::vector<std::vector<geo::Bezier>> edges;
        if ((type & 2) != 0) {
            const bool bulged = whole(72) != 0;
            const bool closed = whole(73) != 0;
            const long long count = whole(93);
            std::vector<geo::Point> pts;
            std::vector<double> bulges;
            for (long long k = 0; k < count && !malformed; ++k) {
                geo::Point p;
                double bulge = 0;
                if (auto e = point(10, p))
                    return e;
                if (bulged && at(42))
                    if (auto e = real(42, bulge))
                        return e;
                if (auto e = countPoints(1, entity.start.line))
                    return e;
                pts.push_back(p);
                bulges.push_back(bulge);
            }
            edges.push_back(
                polylineSegments(pts, bulges, closed || pts.size() > 2, tol, m_options.limits.maxPoints - m_points));
        } else {
            const long long count = whole(93);
            for (long long k = 0; k < count && !malformed && !unsupported; ++k) {
                const long long edge = whole(72);
                std::vector<geo::Bezier> pieces;
                if (edge == 1) {
                    geo::Point a, b;
                    if (auto e = point(10, a))
                        return e;
                    if (auto e = point(11, b))
                        return e;
                    if (a != b)
                        pieces.emplace_back(std::vector<geo::Point>{a, b});
                } else if (edge == 2 || edge == 3) {
                    geo::Point c, major(1, 0);
                    double radius = 1, ratio = 1, a0 = 0, a1 = 360;
                    if (auto e = point(10, c))
                        return e;
                    if (edge == 3) {
                        if (auto e = point(11, major))
                            return e;
                        if (auto e = real(40, ratio))
                            return e;
                        radius = major.norm();
                    } else if (auto e = real(40, radius)) {
                        return e;
                    }
                    if (auto e = real(50, a0))
                        return e;
                    if (auto e = real(51, a1))
                        return e;
                    const bool ccw = whole(73) != 0;
                    if (!ccw) {
                        const double s = 360.0 - a1, t = 360.0 - a0;
                        a0 = s;
                        a1 = t;
                    }
                    bool full = false;
                    const double sweep = sweepOf(a0, a1, 360.0, full);
                    if (radius > 0 && ratio > 0 && sweep > 0) {
                        // An ellipse edge's angles are the points' angles, not the parameters.
                        const double rad = std::numbers::pi / 180.0;
                        const double t0 = std::atan2(std::sin(a0 * rad) / ratio, std::cos(a0 * rad));
                        double dt = full ? 2 * std::numbers::pi
                                         : std::atan2(std::sin(a1 * rad) / ratio, std::cos(a1 * rad)) - t0;
                        if (!full && dt <= 0)
                            dt += 2 * std::numbers::pi;
                        pieces = arcToCubics(c, radius, radius * ratio, std::atan2(major.y(), major.x()), t0, dt, tol);
                        if (!ccw) {
                            std::reverse(pieces.begin(), pieces.end());
                            for (geo::Bezier &b : pieces)
                                b = reversed(b);
                        }
                    }
                } else if (edge == 4) {
                    const long long degree = whole(94);
                    const bool rational = whole(73) != 0;
                    (void)whole(74); // periodic
                    const long long knotCount = whole(95), controlCount = whole(96);
                    if (degree < 1 || degree > 100 || knotCount != controlCount + degree + 1 ||
                        controlCount < degree + 1 || controlCount > m_options.limits.maxPoints) {
                        malformed = true;
                        break;
                    }
                    std::vector<double> knots(static_cast<std::size_t>(knotCount));
                    for (double &u : knots)
                        if (auto e = real(40, u))
                            return e;
                    std::vector<geo::Point> control(static_cast<std::size_t>(controlCount));
                    std::vector<double> weights;
                    for (geo::Point &p : control) {
                        if (auto e = point(10, p))
                            return e;
                        if (rational && at(42)) {
                            weights.push_back(0);
                            if (auto e = real(42, weights.back()))
                                return e;
                        }
                    }
                    if (at(97)) {
                        const long long fit = whole(97);
                        for (long long f = 0; f < fit && !malformed; ++f) {
                            geo::Point p;
                            if (auto e = point(11, p))
                                return e;
                        }
                        for (int code : {12, 13})
                            if (at(code)) {
                                geo::Point p;
                                if (auto e = point(code, p))
                                    return e;
                            }
                    }
                    if (malformed)
                        break;
                    if (std::any_of(weights.begin(), weights.end(), [&](double w) { return w != weights.front(); })) {
                        unsupported = true;
                        break;
                    }
                    bool increasing = knots[static_cast<std::size_t>(degree)] <
                                      knots[knots.size() - 1 - static_cast<std::size_t>(degree)];
                    for (std::size_t k2 = 1; k2 < knots.size(); ++k2)
                        increasing = increasing && knots[k2 - 1] <= knots[k2];
                    if (!increasing) {
                        malformed = true;
                        break;
                    }
                    if (auto e = countPoints(controlCount, entity.start.line))
                        return e;
                    pieces = bezierPieces(knots, control, static_cast<int>(degree));
                } else {
                    malformed = true;
                }
                if (!pieces.empty())
                    edges.push_back(std::move(pieces));
            }
        }
        long long sources = 0;
        if (at(97)) {
            sources = whole(97);
            while (at(330))
                ++i;
        }
        if (malformed || unsupported || sources > 0)
            continue;
        // The edges joined into loops; an edge that meets the loop backwards is turned round (as ezdxf
        // joins them), one that does not meet it starts a new loop.
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
    if (malformed || unsupported) {
        skip(out, unsupported ? DxfSkipped::Spline : DxfSkipped::Other);
        return std::nullopt;
    }
    for (std::vector<geo::Bezier> &loop : loops) {
        if (flipX < 0)
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
        if (auto e = addCurve(out, entity.start, groups, geo::PiecewiseBezier(std::move(loop), closed), place))
            return e;
    }
    return std::nullopt;
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
