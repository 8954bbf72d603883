// SVG export and import (see svg.h). Over 600 lines because the import follows SVG's rules for what
// is drawn where (transforms, the viewBox, <use> copies, hidden content) in one pass over the XML.
#include "io/svg.h"

#include "io/drawnwrite.h"
#include "io/fileio.h"
#include "io/shapes.h"

#include <QBuffer>
#include <QHash>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cmath>
#include <numbers>
#include <optional>

namespace kontur::io {

namespace {

// ---------------------------------------------------------------- export

QString num(double v)
{
    return QString::fromStdString(formatDouble(v));
}

// SVG's y axis points down, Kontur's world y up (src/app/curvecanvas.h): the export negates y.
QString svgPoint(const geo::Point &p)
{
    return num(p.x()) + QLatin1Char(' ') + num(0.0 - p.y());
}

QString pathData(const geo::PiecewiseBezier &curve, double tolerance)
{
    QString d;
    bool first = true;
    geo::Point cur = geo::Point::Zero();
    const auto emit = [&](const geo::Bezier &b) {
        const auto &c = b.controlPoints();
        if (first || c.front() != cur) {
            d += (first ? QString() : QStringLiteral(" ")) + QStringLiteral("M ") + svgPoint(c.front());
            first = false;
        }
        switch (b.degree()) {
        case 1:
            d += QStringLiteral(" L ") + svgPoint(c[1]);
            break;
        case 2:
            d += QStringLiteral(" Q ") + svgPoint(c[1]) + QLatin1Char(' ') + svgPoint(c[2]);
            break;
        default:
            d += QStringLiteral(" C ") + svgPoint(c[1]) + QLatin1Char(' ') + svgPoint(c[2]) + QLatin1Char(' ') +
                 svgPoint(c[3]);
        }
        cur = c.back();
    };
    for (const geo::Bezier &b : curve.segments()) {
        if (b.isEmpty())
            continue;
        if (b.degree() <= 3) {
            emit(b);
        } else {
            std::vector<geo::Bezier> cubics;
            appendCubicsWithin(b, tolerance, cubics);
            for (const geo::Bezier &c : cubics)
                emit(c);
        }
    }
    if (curve.isClosed() && !first)
        d += QStringLiteral(" Z");
    return d;
}

double defaultStrokeWidth(const QString &units)
{
    const double mm = 0.25;
    if (units == QLatin1String("mm"))
        return mm;
    if (units == QLatin1String("cm"))
        return mm / 10;
    if (units == QLatin1String("in"))
        return mm / 25.4;
    if (units == QLatin1String("pt"))
        return mm / 25.4 * 72;
    return 1.0;
}

// ---------------------------------------------------------------- import

// An affine map in SVG's order: x' = a x + c y + e, y' = b x + d y + f.
struct Affine
{
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    Affine operator*(const Affine &o) const
    {
        return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
};

// transform-list (SVG 1.1 §7.6): matrix, translate, scale, rotate, skewX, skewY, separated by
// blanks or commas. Returns the character where parsing failed.
std::optional<std::size_t> parseTransform(std::string_view s, Affine &out)
{
    Affine m;
    std::size_t i = 0;
    const auto skip = [&] {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r' || s[i] == ','))
            ++i;
    };
    while (true) {
        skip();
        if (i >= s.size())
            break;
        const std::size_t nameAt = i;
        while (i < s.size() && ((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= 'A' && s[i] <= 'Z')))
            ++i;
        const std::string_view name = s.substr(nameAt, i - nameAt);
        skip();
        if (i >= s.size() || s[i] != '(')
            return i;
        ++i;
        double v[6];
        int n = 0;
        while (true) {
            skip();
            if (i < s.size() && s[i] == ')') {
                ++i;
                break;
            }
            if (n == 6)
                return i;
            std::size_t j = i;
            if (j < s.size() && (s[j] == '+' || s[j] == '-'))
                ++j;
            while (j < s.size() && ((s[j] >= '0' && s[j] <= '9') || s[j] == '.' || s[j] == 'e' || s[j] == 'E' ||
                                    ((s[j] == '-' || s[j] == '+') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
                ++j;
            if (parseDouble(s.substr(i, j - i), v[n]) != NumberStatus::Ok)
                return i;
            ++n;
            i = j;
        }
        Affine t;
        const double rad = std::numbers::pi / 180.0;
        if (name == "matrix" && n == 6) {
            t = {v[0], v[1], v[2], v[3], v[4], v[5]};
        } else if (name == "translate" && (n == 1 || n == 2)) {
            t.e = v[0];
            t.f = n == 2 ? v[1] : 0.0;
        } else if (name == "scale" && (n == 1 || n == 2)) {
            t.a = v[0];
            t.d = n == 2 ? v[1] : v[0];
        } else if (name == "rotate" && (n == 1 || n == 3)) {
            const double c = std::cos(v[0] * rad), sn = std::sin(v[0] * rad);
            const Affine r{c, sn, -sn, c, 0, 0};
            if (n == 3)
                t = Affine{1, 0, 0, 1, v[1], v[2]} * r * Affine{1, 0, 0, 1, -v[1], -v[2]};
            else
                t = r;
        } else if (name == "skewX" && n == 1) {
            t.c = std::tan(v[0] * rad);
        } else if (name == "skewY" && n == 1) {
            t.b = std::tan(v[0] * rad);
        } else {
            return nameAt;
        }
        m = m * t;
    }
    out = m;
    return std::nullopt;
}

// "#rgb" / "#rrggbb" → "#rrggbb"; anything else (names, url(), none) → empty.
QString parseColor(QString v)
{
    v = v.trimmed().toLower();
    if (isColorName(v))
        return v;
    if (v.size() == 4 && v.front() == QLatin1Char('#')) {
        QString out = QStringLiteral("#");
        for (int i = 1; i < 4; ++i)
            out += QString(2, v.at(i));
        if (isColorName(out))
            return out;
    }
    if (v == QLatin1String("black"))
        return QStringLiteral("#000000");
    return {};
}

QString styleProperty(const QString &style, QLatin1String name)
{
    for (const QString &decl : style.split(QLatin1Char(';'))) {
        const qsizetype colon = decl.indexOf(QLatin1Char(':'));
        if (colon > 0 && decl.left(colon).trimmed() == name)
            return decl.mid(colon + 1).trimmed();
    }
    return {};
}

// A length with an optional unit: "210mm" → {210, "mm"}; nullopt when malformed.
std::optional<std::pair<double, QString>> parseLength(const QString &text)
{
    QString t = text.trimmed();
    QString unit;
    for (const char *u : {"mm", "cm", "in", "pt", "px"})
        if (t.endsWith(QLatin1String(u))) {
            unit = QLatin1String(u);
            t.chop(2);
            break;
        }
    double v = 0.0;
    const QByteArray bytes = t.trimmed().toLatin1();
    if (parseDouble(std::string_view(bytes.data(), static_cast<std::size_t>(bytes.size())), v) != NumberStatus::Ok)
        return std::nullopt;
    return std::pair{v, unit};
}

// Basic shapes (SVG 1.1 §9) as path data, so one parser handles everything.
QString shapeToPathData(const QStringView name, const QXmlStreamAttributes &attrs)
{
    const auto val = [&](const char *attr) {
        double v = 0.0;
        const QByteArray bytes = attrs.value(QLatin1String(attr)).toLatin1().trimmed();
        if (parseDouble(std::string_view(bytes.data(), static_cast<std::size_t>(bytes.size())), v) != NumberStatus::Ok)
            return 0.0;
        return v;
    };
    if (name == QLatin1String("line"))
        return QStringLiteral("M %1 %2 L %3 %4").arg(num(val("x1")), num(val("y1")), num(val("x2")), num(val("y2")));
    if (name == QLatin1String("polyline") || name == QLatin1String("polygon")) {
        const QString pts = attrs.value(QLatin1String("points")).toString().trimmed();
        if (pts.isEmpty())
            return {};
        // After a moveto, further coordinate pairs are implicit linetos.
        return QStringLiteral("M ") + pts + (name == QLatin1String("polygon") ? QStringLiteral(" Z") : QString());
    }
    if (name == QLatin1String("rect")) {
        const double x = val("x"), y = val("y"), w = val("width"), h = val("height");
        if (!(w > 0) || !(h > 0))
            return {};
        double rx = val("rx"), ry = val("ry");
        if (attrs.hasAttribute(QLatin1String("rx")) && !attrs.hasAttribute(QLatin1String("ry")))
            ry = rx;
        if (attrs.hasAttribute(QLatin1String("ry")) && !attrs.hasAttribute(QLatin1String("rx")))
            rx = ry;
        rx = std::clamp(rx, 0.0, w / 2);
        ry = std::clamp(ry, 0.0, h / 2);
        if (rx == 0 || ry == 0)
            return QStringLiteral("M %1 %2 H %3 V %4 H %1 Z").arg(num(x), num(y), num(x + w), num(y + h));
        const QString arc = QStringLiteral(" A %1 %2 0 0 1 ").arg(num(rx), num(ry));
        return QStringLiteral("M ") + num(x + rx) + QLatin1Char(' ') + num(y) + QStringLiteral(" H ") +
               num(x + w - rx) + arc + num(x + w) + QLatin1Char(' ') + num(y + ry) + QStringLiteral(" V ") +
               num(y + h - ry) + arc + num(x + w - rx) + QLatin1Char(' ') + num(y + h) + QStringLiteral(" H ") +
               num(x + rx) + arc + num(x) + QLatin1Char(' ') + num(y + h - ry) + QStringLiteral(" V ") + num(y + ry) +
               arc + num(x + rx) + QLatin1Char(' ') + num(y) + QStringLiteral(" Z");
    }
    if (name == QLatin1String("circle") || name == QLatin1String("ellipse")) {
        const double cx = val("cx"), cy = val("cy");
        const double rx = name == QLatin1String("circle") ? val("r") : val("rx");
        const double ry = name == QLatin1String("circle") ? val("r") : val("ry");
        if (!(rx > 0) || !(ry > 0))
            return {};
        const QString arc = QStringLiteral(" A %1 %2 0 0 1 ").arg(num(rx), num(ry));
        return QStringLiteral("M ") + num(cx + rx) + QLatin1Char(' ') + num(cy) + arc + num(cx - rx) +
               QLatin1Char(' ') + num(cy) + arc + num(cx + rx) + QLatin1Char(' ') + num(cy) + QStringLiteral(" Z");
    }
    return {};
}

bool isDrawable(QStringView name)
{
    for (const char *n : {"path", "line", "polyline", "polygon", "rect", "circle", "ellipse"})
        if (name == QLatin1String(n))
            return true;
    return false;
}

// Elements that are shown but hold no geometry Kontur reads: counted as skipped, with their content.
std::optional<SkippedKind> skippedKindOf(QStringView name)
{
    if (name == QLatin1String("text") || name == QLatin1String("flowRoot"))
        return SkippedKind::Text;
    if (name == QLatin1String("image"))
        return SkippedKind::Image;
    for (const char *n : {"foreignObject", "video", "audio", "iframe", "canvas"})
        if (name == QLatin1String(n))
            return SkippedKind::Other;
    return std::nullopt;
}

// Elements whose content is not drawn where it stands.
bool isNotRendered(QStringView name)
{
    for (const char *n : {"defs", "symbol", "clipPath", "mask", "pattern", "marker", "metadata", "style", "script"})
        if (name == QLatin1String(n))
            return true;
    return false;
}

} // namespace

QByteArray exportSvg(std::span<const SvgCurve> curves, const SvgExportOptions &options)
{
    geo::Box box;
    for (const SvgCurve &c : curves)
        if (!c.curve.isEmpty())
            box.extend(c.curve.boundingBox());
    double minX = 0, minY = 0, w = 1, h = 1;
    if (!box.isEmpty()) {
        minX = box.min().x() - options.margin;
        minY = -box.max().y() - options.margin;
        w = box.sizes().x() + 2 * options.margin;
        h = box.sizes().y() + 2 * options.margin;
        // A straight horizontal or vertical curve has no extent across: give the view some.
        if (!(w > 0)) {
            w = 1;
            minX -= 0.5;
        }
        if (!(h > 0)) {
            h = 1;
            minY -= 0.5;
        }
    }
    const bool physical = options.units != QLatin1String("px") && isUnitName(options.units);
    const QString unit = physical ? options.units : QString();
    const double stroke = options.strokeWidth > 0 ? options.strokeWidth : defaultStrokeWidth(options.units);

    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QXmlStreamWriter xml(&buffer);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(2);
    xml.writeStartDocument();
    xml.writeComment(
        QStringLiteral(" Written by Kontur: exact Bezier segments, y axis flipped (Kontur's y points up) "));
    xml.writeStartElement(QStringLiteral("svg"));
    xml.writeDefaultNamespace(QStringLiteral("http://www.w3.org/2000/svg"));
    xml.writeAttribute(QStringLiteral("version"), QStringLiteral("1.1"));
    xml.writeAttribute(QStringLiteral("width"), num(w) + unit);
    xml.writeAttribute(QStringLiteral("height"), num(h) + unit);
    xml.writeAttribute(QStringLiteral("viewBox"),
                       QStringLiteral("%1 %2 %3 %4").arg(num(minX), num(minY), num(w), num(h)));
    for (const SvgCurve &c : curves) {
        const QString d = pathData(c.curve, options.highDegreeTolerance);
        if (d.isEmpty())
            continue;
        xml.writeStartElement(QStringLiteral("path"));
        xml.writeAttribute(QStringLiteral("d"), d);
        xml.writeAttribute(QStringLiteral("fill"), QStringLiteral("none"));
        xml.writeAttribute(QStringLiteral("stroke"),
                           isColorName(c.color) ? c.color.toLower() : QStringLiteral("#000000"));
        xml.writeAttribute(QStringLiteral("stroke-width"), num(stroke));
        if (!c.name.isEmpty())
            xml.writeTextElement(QStringLiteral("title"), c.name);
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndDocument();
    return bytes;
}

Result<Ok> writeSvg(const QString &path, std::span<const SvgCurve> curves, const SvgExportOptions &options,
                    const Limits &limits)
{
    // "nan" or "inf" in path data is no SVG, and no drawing.
    if (auto e = nonFiniteCoordinate(path, curves))
        return *e;
    // Each curve is at least one subpath, each segment at least one path segment (higher degrees
    // become several cubics, counted in the written text below): refused before the text is made.
    qint64 subpaths = 0, segments = 0;
    for (const SvgCurve &c : curves) {
        subpaths += c.curve.isEmpty() ? 0 : 1;
        segments += c.curve.segmentCount();
    }
    if (auto e = tooMany(path, {subpaths, "curves"}, limits.maxCurves, ErrorCode::TooManyCurves))
        return *e;
    if (auto e = tooMany(path, {segments, "segments"}, limits.maxPoints, ErrorCode::TooManyPoints))
        return *e;
    const NonFiniteWatch watch;
    const QByteArray bytes = exportSvg(curves, options);
    // The segments as written: every one starts with its command letter (numbers have no C, L or Q).
    const qint64 written = bytes.count(" C ") + bytes.count(" L ") + bytes.count(" Q ");
    return writeDrawing(path, bytes, watch.seen(), {subpaths, "curves"}, {written, "segments"}, limits);
}

namespace {

// Whether a presentation attribute or the style property `name` of the element says `value`.
QString presentation(const QXmlStreamAttributes &attrs, QLatin1String name)
{
    const QString inStyle = styleProperty(attrs.value(QLatin1String("style")).toString(), name);
    return inStyle.isEmpty() ? attrs.value(name).toString().trimmed() : inStyle;
}

// The reader walks the elements with the current transform; a <use> walks the element it names again
// (from the source text, with the use's transform and x, y), so clones come in like the original.
class SvgReader final
{
public:
    SvgReader(const QString &file, const SvgImportOptions &options)
        : m_file(file)
        , m_options(options)
    {
    }

    Result<SvgImport> read(QByteArrayView bytes);

private:
    // The elements of `xml` up to its end. `base` is the transform of the element that holds them;
    // in a <use>'s copy `useLine` is the use's line (errors and curves name it) and `depth` counts
    // the uses inside each other.
    std::optional<Error> walk(QXmlStreamReader &xml, const Affine &base, bool hidden, int useLine, int depth);
    std::optional<Error> use(const QXmlStreamReader &xml, const Affine &m, bool hidden, int useLine, int depth);
    void indexIds();
    Error error(const QXmlStreamReader &xml, int useLine, ErrorCode code, const QString &message) const
    {
        Error e;
        e.code = code;
        e.file = m_file;
        e.line = useLine > 0 ? useLine : static_cast<int>(xml.lineNumber());
        e.column = useLine > 0 ? 0 : static_cast<int>(xml.columnNumber());
        e.message = message;
        return e;
    }

    QString m_file;
    SvgImportOptions m_options;
    SvgImport m_result;
    QString m_source;                                      // the text, for the elements a <use> names
    QHash<QString, std::pair<qsizetype, qsizetype>> m_ids; // id → its element's range in m_source
    double m_scaleX = 1.0, m_scaleY = 1.0;                 // user units into result.units (the root's viewBox)
    qint64 m_segments = 0;
    qint64 m_uses = 0; // elements copied by <use>, against clones of clones of clones
    bool m_sawRoot = false;
};

// Every element with an id and where it stands in the text (only for files with a <use>).
void SvgReader::indexIds()
{
    QXmlStreamReader xml(m_source);
    std::vector<std::pair<QString, qsizetype>> open;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        // The reader may have read the '<' of a tag with the text before it: the tag starts at the
        // last '<' before its end (an attribute value holds none).
        if (token == QXmlStreamReader::StartElement)
            open.emplace_back(xml.attributes().value(QLatin1String("id")).toString(),
                              m_source.lastIndexOf(QLatin1Char('<'), xml.characterOffset() - 1));
        else if (token == QXmlStreamReader::EndElement && !open.empty()) {
            if (!open.back().first.isEmpty() && open.back().second >= 0 && !m_ids.contains(open.back().first))
                m_ids.insert(open.back().first, {open.back().second, xml.characterOffset()});
            open.pop_back();
        }
    }
}

std::optional<Error> SvgReader::use(const QXmlStreamReader &xml, const Affine &m, bool hidden, int useLine, int depth)
{
    const QXmlStreamAttributes attrs = xml.attributes();
    QString href = attrs.value(QLatin1String("href")).toString().trimmed();
    if (href.isEmpty())
        href = attrs.value(QLatin1String("xlink:href")).toString().trimmed();
    const auto found = href.startsWith(QLatin1Char('#')) ? m_ids.constFind(href.mid(1)) : m_ids.constEnd();
    if (found == m_ids.constEnd() || depth >= m_options.limits.maxDepth)
        return std::nullopt; // names nothing here (or clones nested past the depth limit)
    if (++m_uses > m_options.limits.maxCurves)
        return error(xml, useLine, ErrorCode::TooManyCurves,
                     QStringLiteral("more than %1 <use> copies, the most Kontur reads from one file")
                         .arg(m_options.limits.maxCurves));
    // SVG 1.1 §5.6: the use's transform, then a translation by its x and y.
    const auto length = [&](const char *name) {
        const auto v = parseLength(attrs.value(QLatin1String(name)).toString());
        return v ? v->first : 0.0;
    };
    Affine placed = m;
    placed = placed * Affine{1, 0, 0, 1, length("x"), length("y")};
    // The named element, read again from the text inside a group that declares the usual prefixes.
    const QString fragment = m_source.mid(found->first, found->second - found->first);
    QXmlStreamReader copy(QStringLiteral("<g xmlns=\"http://www.w3.org/2000/svg\" "
                                         "xmlns:xlink=\"http://www.w3.org/1999/xlink\">") +
                          fragment + QStringLiteral("</g>"));
    copy.setNamespaceProcessing(false);
    const int line = useLine > 0 ? useLine : static_cast<int>(xml.lineNumber());
    return walk(copy, placed, hidden, line, depth + 1);
}

std::optional<Error> SvgReader::walk(QXmlStreamReader &xml, const Affine &base, bool hidden, int useLine, int depth)
{
    std::vector<Affine> ctm;        // one per open element
    std::vector<bool> isPath;       // whether the open element is a drawable one (for its <title>)
    std::vector<bool> hiddenStack;  // visibility: hidden, inherited unless a child says visible
    std::size_t firstOfElement = 0; // the first curve of the last drawable element
    const bool copy = useLine > 0;
    bool first = true;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::EndElement) {
            if (!ctm.empty()) {
                ctm.pop_back();
                isPath.pop_back();
                hiddenStack.pop_back();
            }
            continue;
        }
        if (token != QXmlStreamReader::StartElement)
            continue;
        const QStringView name = xml.name();
        const QXmlStreamAttributes attrs = xml.attributes();
        const bool wrapper = copy && first;         // the group a <use>'s copy is read in
        const bool named = copy && ctm.size() == 1; // the element the <use> names
        first = false;
        if (!copy && !m_sawRoot) {
            m_sawRoot = true;
            if (name != QLatin1String("svg"))
                return error(xml, useLine, ErrorCode::NotSvg,
                             QStringLiteral("the root element is <%1>, not <svg>").arg(name));
            // SVG 1.1 §7.7: the viewBox is stretched to the width and height (uniformly, the smaller
            // of the two scales, unless preserveAspectRatio is none). With a unit, the coordinates
            // are in that unit; without one in px. The viewBox's offset is not applied: positions
            // stay in user units from the origin (a Kontur SVG re-imports bit for bit).
            const auto width = parseLength(attrs.value(QLatin1String("width")).toString());
            const auto height = parseLength(attrs.value(QLatin1String("height")).toString());
            const QStringList vb = attrs.value(QLatin1String("viewBox"))
                                       .toString()
                                       .simplified()
                                       .replace(QLatin1Char(','), QLatin1Char(' '))
                                       .split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (vb.size() == 4 && (width || height)) {
                bool okw = false, okh = false;
                const double vbw = vb.at(2).toDouble(&okw), vbh = vb.at(3).toDouble(&okh);
                const auto scaleOf = [](const std::optional<std::pair<double, QString>> &l, double size, bool ok) {
                    return l && ok && size > 0 && l->first > 0 && std::isfinite(l->first / size) ? l->first / size
                                                                                                 : 0.0;
                };
                double sx = scaleOf(width, vbw, okw), sy = scaleOf(height, vbh, okh);
                const QString unit = width && sx > 0 ? width->second : height ? height->second : QString();
                const bool stretch =
                    attrs.value(QLatin1String("preserveAspectRatio")).trimmed().startsWith(QLatin1String("none"));
                if (sx <= 0)
                    sx = sy;
                if (sy <= 0)
                    sy = sx;
                if (!stretch)
                    sx = sy = std::min(sx, sy);
                if (sx > 0) {
                    m_scaleX = sx;
                    m_scaleY = sy;
                    m_result.units = unit.isEmpty() ? QStringLiteral("px") : unit;
                }
            }
        }
        if (static_cast<int>(ctm.size()) >= m_options.limits.maxDepth)
            return error(xml, useLine, ErrorCode::TooDeep,
                         QStringLiteral("elements nested deeper than %1 levels").arg(m_options.limits.maxDepth));
        // A <symbol> is drawn only through a <use> that names it.
        if ((isNotRendered(name) && !(named && name == QLatin1String("symbol"))) ||
            presentation(attrs, QLatin1String("display")) == QLatin1String("none")) {
            xml.skipCurrentElement();
            continue;
        }
        if (name == QLatin1String("title") && !isPath.empty() && isPath.back()) {
            const QString title = xml.readElementText(QXmlStreamReader::SkipChildElements).trimmed();
            for (std::size_t i = firstOfElement; i < m_result.curves.size(); ++i)
                m_result.curves[i].name = title;
            continue;
        }
        Affine m = ctm.empty() ? base : ctm.back();
        const QString transform = wrapper ? QString() : attrs.value(QLatin1String("transform")).toString();
        if (!transform.isEmpty()) {
            Affine t;
            const QByteArray tb = transform.toUtf8();
            if (const auto at = parseTransform(std::string_view(tb.data(), static_cast<std::size_t>(tb.size())), t))
                return error(xml, useLine, ErrorCode::TransformSyntax,
                             QStringLiteral("transform attribute, character %1: expected matrix, translate, scale, "
                                            "rotate, skewX or skewY with their numbers")
                                 .arg(*at + 1));
            m = m * t;
        }
        bool isHidden = hiddenStack.empty() ? hidden : hiddenStack.back();
        const QString visibility = presentation(attrs, QLatin1String("visibility"));
        if (visibility == QLatin1String("hidden") || visibility == QLatin1String("collapse"))
            isHidden = true;
        else if (visibility == QLatin1String("visible"))
            isHidden = false;
        if (const auto skipped = skippedKindOf(name)) {
            if (!isHidden)
                ++m_result.skipped[static_cast<std::size_t>(*skipped)];
            xml.skipCurrentElement();
            continue;
        }
        ctm.push_back(m);
        hiddenStack.push_back(isHidden);
        const bool drawable = isDrawable(name) && !isHidden;
        isPath.push_back(drawable);
        if (name == QLatin1String("use")) {
            if (auto e = use(xml, m, isHidden, useLine, depth))
                return e;
            continue;
        }
        if (!drawable)
            continue;
        const QString d =
            name == QLatin1String("path") ? attrs.value(QLatin1String("d")).toString() : shapeToPathData(name, attrs);
        const QByteArray db = d.toUtf8();
        SvgPathOptions pathOptions = m_options.path;
        pathOptions.maxSegments = std::max<qint64>(0, m_options.limits.maxPoints - m_segments);
        auto parsed = parseSvgPathData(std::string_view(db.data(), static_cast<std::size_t>(db.size())), pathOptions);
        if (!parsed) {
            Error e = error(xml, useLine, parsed.error().code,
                            QStringLiteral("<%1> path data, character %2: %3")
                                .arg(name)
                                .arg(parsed.error().column)
                                .arg(parsed.error().message));
            if (parsed.error().code == ErrorCode::TooManyPoints)
                e.message = QStringLiteral("more than %1 segments, the most Kontur reads from one file")
                                .arg(m_options.limits.maxPoints);
            return e;
        }
        QString color = parseColor(attrs.value(QLatin1String("stroke")).toString());
        const QString style = attrs.value(QLatin1String("style")).toString();
        if (color.isEmpty())
            color = parseColor(styleProperty(style, QLatin1String("stroke")));
        if (color.isEmpty())
            color = QStringLiteral("#000000");
        firstOfElement = m_result.curves.size();
        // Into Kontur's world: the element's transforms, the viewBox's scale, y flipped.
        Eigen::Matrix2d linear;
        linear << m_scaleX * m.a, m_scaleX * m.c, -m_scaleY * m.b, -m_scaleY * m.d;
        const geo::Point offset(m_scaleX * m.e, -m_scaleY * m.f);
        const bool identity =
            m.a == 1 && m.b == 0 && m.c == 0 && m.d == 1 && m.e == 0 && m.f == 0 && m_scaleX == 1 && m_scaleY == 1;
        for (geo::PiecewiseBezier &sub : *parsed) {
            m_segments += sub.segmentCount();
            std::vector<geo::Bezier> mapped;
            mapped.reserve(sub.segments().size());
            for (const geo::Bezier &b : sub.segments()) {
                if (identity) {
                    // Exact: only the sign of y changes (so a Kontur SVG re-imports bit for bit).
                    std::vector<geo::Point> pts = b.controlPoints();
                    for (geo::Point &p : pts)
                        p.y() = 0.0 - p.y();
                    mapped.emplace_back(std::move(pts));
                } else {
                    mapped.push_back(b.transformed(linear, offset));
                }
            }
            geo::PiecewiseBezier curve(std::move(mapped), sub.isClosed());
            if (m_options.cubicOnly)
                curve = elevatedToCubics(curve);
            if (static_cast<qint64>(m_result.curves.size()) >= m_options.limits.maxCurves)
                return error(xml, useLine, ErrorCode::TooManyCurves,
                             QStringLiteral("more than %1 subpaths, the most Kontur reads from one file")
                                 .arg(m_options.limits.maxCurves));
            SvgImportedCurve out;
            out.name = attrs.value(QLatin1String("id")).toString();
            out.color = color;
            out.curve = std::move(curve);
            out.line = useLine > 0 ? useLine : static_cast<int>(xml.lineNumber());
            m_result.curves.push_back(std::move(out));
        }
    }
    if (xml.hasError())
        return error(xml, useLine, ErrorCode::XmlSyntax,
                     QStringLiteral("not well-formed XML: %1").arg(xml.errorString()));
    return std::nullopt;
}

Result<SvgImport> SvgReader::read(QByteArrayView bytes)
{
    QXmlStreamReader xml(bytes.toByteArray());
    if (bytes.size() > m_options.limits.maxFileBytes)
        return error(xml, 0, ErrorCode::FileTooLarge,
                     QStringLiteral("the file is larger than %1 bytes, the most Kontur reads")
                         .arg(m_options.limits.maxFileBytes));
    if (bytes.trimmed().isEmpty())
        return error(xml, 0, ErrorCode::NotSvg, QStringLiteral("the file is empty"));
    if (QByteArrayView(bytes).indexOf("<use") >= 0) {
        m_source = QString::fromUtf8(bytes);
        if (m_source.startsWith(QChar(0xfeff)))
            m_source.remove(0, 1);
        indexIds();
    }
    if (auto e = walk(xml, Affine{}, false, 0, 0))
        return *e;
    if (!m_sawRoot)
        return error(xml, 0, ErrorCode::NotSvg, QStringLiteral("the file has no <svg> element"));
    if (m_result.curves.empty()) {
        const QString skipped = skippedSummary(m_result);
        Error e = error(xml, 0, ErrorCode::NoPaths,
                        QStringLiteral("the SVG has no paths to import%1")
                            .arg(skipped.isEmpty() ? QString() : QStringLiteral("; skipped: ") + skipped));
        e.skipped = m_result.skipped;
        return e;
    }
    return std::move(m_result);
}

} // namespace

QString skippedSummary(const SvgImport &svg)
{
    return skippedSummary(svg.skipped, "other element", "other elements");
}

Result<SvgImport> importSvg(QByteArrayView bytes, const QString &file, const SvgImportOptions &options)
{
    SvgReader reader(file, options);
    return reader.read(bytes);
}

Result<SvgImport> readSvg(const QString &path, const SvgImportOptions &options)
{
    auto bytes = readFileBytes(path, options.limits);
    if (!bytes)
        return bytes.error();
    return importSvg(*bytes, path, options);
}

} // namespace kontur::io
