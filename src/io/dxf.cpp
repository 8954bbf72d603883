// DXF import (see dxf.h): the reader's first stage, the pairs of lines (a group code and its value),
// the sections they make (the header's units and code page, the layer table's colours, the blocks,
// the entities) and the entry points. The entity kinds become Bézier pieces in dxfentities.cpp,
// blocks, INSERTs and ASTM D6673 pieces in dxfblocks.cpp, hatch boundaries in dxfhatch.cpp (the
// reader's insides: dxfread_p.h); the writer is dxfwrite.cpp. Last, an imported curve as a record.
#include "io/dxf.h"

#include "io/dxfread_p.h"
#include "io/fileio.h"
#include "io/shapes.h"

#include "geometry/composite.h"

#include <QStringDecoder>

#include <algorithm>
#include <charconv>

namespace kontur::io::dxfread {

namespace {

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// A hexadecimal digit's value, -1 for any other character.
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

} // namespace

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

long long integerOf(const Group &g)
{
    long long v = 0;
    (void)std::from_chars(g.value.data(), g.value.data() + g.value.size(), v);
    return v;
}

long long integerOf(const std::vector<Group> &groups, int code)
{
    for (const Group &g : groups)
        if (g.code == code)
            return integerOf(g);
    return 0;
}

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

std::optional<Error> Reader::number(const std::vector<Group> &groups, int code, double fallback, double &v) const
{
    v = fallback;
    for (const Group &g : groups)
        if (g.code == code)
            return number(g, v);
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

} // namespace kontur::io::dxfread

namespace kontur::io {

QString skippedSummary(const DxfImport &dxf)
{
    return skippedSummary(dxf.skipped, "other entity", "other entities");
}

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
    dxfread::Reader reader(text, file, options);
    return reader.read();
}

Result<DxfImport> readDxf(const QString &path, const DxfImportOptions &options)
{
    auto bytes = readFileBytes(path, options.limits);
    if (!bytes)
        return bytes.error();
    return importDxf(*bytes, path, options);
}

namespace {

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
