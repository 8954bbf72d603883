// The .kontur document's writer (see document.h): Kontur's own JSON writer, one member a line, a
// curve's points and node types compact on one line each, numbers in the shortest round-trip form
// (std::to_chars), so that save → open → save is byte-identical; saved atomically through QSaveFile.
#include "io/document.h"

#include "io/document_p.h"
#include "io/fileio.h"
#include "io/piece.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

namespace kontur::io {

namespace {

void writeString(QByteArray &out, const QString &s)
{
    out += '"';
    for (const char c : s.toUtf8()) {
        const auto u = static_cast<unsigned char>(c);
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (u < 0x20) {
                static const char hex[] = "0123456789abcdef";
                out += "\\u00";
                out += hex[u >> 4];
                out += hex[u & 15];
            } else {
                out += c;
            }
        }
    }
    out += '"';
}

// Any JSON value (settings), compact, keys in QJsonObject's sorted order. Whole numbers beyond 2^53
// keep their integer digits (QJsonValue stores them as qint64); the rest are shortest round-trip doubles.
void writeValue(QByteArray &out, const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        out += "null";
        break;
    case QJsonValue::Bool:
        out += v.toBool() ? "true" : "false";
        break;
    case QJsonValue::Double: {
        const qint64 a = v.toInteger(1), b = v.toInteger(2);
        if (a == b && (a > (qint64(1) << 53) || a < -(qint64(1) << 53)))
            out += QByteArray::number(a);
        else
            appendDouble(out, v.toDouble());
        break;
    }
    case QJsonValue::String:
        writeString(out, v.toString());
        break;
    case QJsonValue::Array: {
        out += '[';
        bool first = true;
        for (const QJsonValue &item : v.toArray()) {
            if (!first)
                out += ", ";
            first = false;
            writeValue(out, item);
        }
        out += ']';
        break;
    }
    case QJsonValue::Object: {
        const QJsonObject o = v.toObject();
        out += '{';
        bool first = true;
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!first)
                out += ", ";
            first = false;
            writeString(out, it.key());
            out += ": ";
            writeValue(out, it.value());
        }
        out += '}';
        break;
    }
    }
}

// Pretty-printing helper: one member per line, indented by two spaces per level.
class Writer final
{
public:
    QByteArray out;

    void open(char c)
    {
        out += c;
        out += '\n';
        ++m_level;
        m_first = true;
    }
    void close(char c)
    {
        --m_level;
        out += '\n';
        indent();
        out += c;
        m_first = false;
    }
    void key(const char *name)
    {
        item();
        writeString(out, QString::fromLatin1(name));
        out += ": ";
    }
    void item()
    {
        if (!m_first)
            out += ",\n";
        m_first = false;
        indent();
    }
    void number(const char *name, double v)
    {
        key(name);
        appendDouble(out, v);
    }
    void boolean(const char *name, bool v)
    {
        key(name);
        out += v ? "true" : "false";
    }
    void string(const char *name, const QString &v)
    {
        key(name);
        writeString(out, v);
    }
    void point(double x, double y)
    {
        // Built in a buffer and appended once: a million-knot curve has three million points.
        char buf[64];
        char *p = buf;
        *p++ = '[';
        p = formatDoubleTo(p, x);
        *p++ = ',';
        p = formatDoubleTo(p, y);
        *p++ = ']';
        out.append(buf, p - buf);
    }

private:
    void indent() { out += QByteArray(2 * m_level, ' '); }
    int m_level = 0;
    bool m_first = true;
};

} // namespace

QByteArray documentToJson(const DocumentData &doc, const QString &documentPath)
{
    Writer w;
    w.open('{');
    w.string("format", QStringLiteral("kontur"));
    std::vector<std::vector<geo::Point>> rules;
    rules.reserve(doc.curves.size());
    bool ruled = false, pieces = false;
    for (const CurveRecord &c : doc.curves) {
        pieces = pieces || c.settings.contains(QLatin1String(kPieceKey));
        rules.push_back(documentjson::ruleControlPoints(c));
        for (std::size_t i = 1; !ruled && i < rules.back().size(); ++i)
            ruled = i % 3 != 0 && rules.back()[i] == c.points[i];
    }
    // The lowest version that says what the document holds, so that older Kontur versions open what
    // they can: 3 for pieces' marks (an older version would drop them when saving), 2 for handles by
    // the rule, else 1.
    w.number("version", pieces ? 3 : ruled ? 2 : 1);
    w.string("units", doc.units);
    w.key("curves");
    if (doc.curves.empty()) {
        w.out += "[]";
    } else {
        w.open('[');
        for (std::size_t index = 0; index < doc.curves.size(); ++index) {
            const CurveRecord &c = doc.curves[index];
            w.item();
            w.open('{');
            w.string("kind", c.kind);
            w.string("name", c.name);
            w.string("color", c.color.toLower());
            w.boolean("visible", c.visible);
            w.boolean("locked", c.locked);
            if (!c.parameterization.isEmpty())
                w.string("parameterization", c.parameterization);
            w.boolean("closed", c.closed);
            // Points and node types compact, on one line each: indenting a million points took a
            // third of a 145 MB file (issue 17). The rest stays one member a line, for the reader.
            w.key("points");
            w.out.reserve(w.out.size() + static_cast<qsizetype>(c.points.size()) * 48 + 1024);
            w.out += '[';
            const std::vector<geo::Point> &rule = rules[index];
            for (std::size_t i = 0; i < c.points.size(); ++i) {
                if (i > 0)
                    w.out += ',';
                if (!rule.empty() && i % 3 != 0 && rule[i] == c.points[i])
                    w.out += "null";
                else
                    w.point(c.points[i].x(), c.points[i].y());
            }
            w.out += ']';
            if (!c.nodeTypes.empty() || c.kind == QLatin1String("composite")) {
                w.key("nodeTypes");
                w.out += '[';
                for (std::size_t i = 0; i < c.nodeTypes.size(); ++i) {
                    if (i > 0)
                        w.out += ',';
                    writeString(w.out, c.nodeTypes[i]);
                }
                w.out += ']';
            }
            w.key("settings");
            writeValue(w.out, c.settings);
            w.close('}');
        }
        w.close(']');
    }
    if (doc.background) {
        const BackgroundRecord &b = *doc.background;
        QString file = b.file;
        if (!documentPath.isEmpty() && !file.isEmpty() && QFileInfo(file).isAbsolute())
            file = QDir(documentjson::documentFolder(documentPath)).relativeFilePath(file);
        w.key("background");
        w.open('{');
        w.string("file", file);
        w.boolean("visible", b.visible);
        w.number("opacity", b.opacity);
        w.number("originX", b.originX);
        w.number("originY", b.originY);
        w.number("scale", b.scale);
        w.number("rotation", b.rotation);
        if (b.locked)
            w.boolean("locked", true);
        w.key("calibration");
        if (b.calibrated) {
            w.open('{');
            w.key("a");
            w.point(b.ax, b.ay);
            w.key("b");
            w.point(b.bx, b.by);
            w.number("distance", b.distance);
            w.close('}');
        } else {
            w.out += "null";
        }
        // Written only when set, so that a document without it reads as before in older versions.
        if (b.perspective) {
            w.key("perspective");
            w.open('{');
            w.key("corners");
            w.open('[');
            for (int i = 0; i < 4; ++i) {
                w.item();
                w.point(b.corners[2 * i], b.corners[2 * i + 1]);
            }
            w.close(']');
            w.number("width", b.rectWidth);
            w.number("height", b.rectHeight);
            w.key("origin");
            w.point(b.rectX, b.rectY);
            w.close('}');
        }
        w.close('}');
    }
    w.close('}');
    w.out += '\n';
    return w.out;
}

Result<Ok> saveDocument(const QString &path, const DocumentData &doc, const Limits &limits)
{
    if (auto e = validateDocument(doc)) {
        e->file = path;
        e->message = QStringLiteral("the document cannot be saved: ") + e->message;
        return *e;
    }
    // What Kontur would refuse to open is not written (a clear error now, not lost work later).
    Error e;
    e.file = path;
    qint64 points = 0;
    for (const CurveRecord &c : doc.curves)
        points += static_cast<qint64>(c.points.size());
    if (static_cast<qint64>(doc.curves.size()) > limits.maxCurves) {
        e.code = ErrorCode::TooManyCurves;
        e.path = QStringLiteral("curves");
        e.message = QStringLiteral("the document cannot be saved: %1 curves; a file holds at most %2")
                        .arg(doc.curves.size())
                        .arg(limits.maxCurves);
        return e;
    }
    if (points > limits.maxPoints) {
        e.code = ErrorCode::TooManyPoints;
        e.path = QStringLiteral("curves");
        e.message = QStringLiteral("the document cannot be saved: %1 points; a file holds at most %2")
                        .arg(points)
                        .arg(limits.maxPoints);
        return e;
    }
    const NonFiniteWatch watch;
    const QByteArray json = documentToJson(doc, path);
    if (watch.seen())
        return NonFiniteWatch::error(path, QStringLiteral("the document"));
    if (json.size() > limits.maxFileBytes) {
        e.code = ErrorCode::FileTooLarge;
        e.message = QStringLiteral("the document cannot be saved: %1 bytes; a file holds at most %2")
                        .arg(json.size())
                        .arg(limits.maxFileBytes);
        return e;
    }
    return writeFileAtomically(path, json);
}

} // namespace kontur::io
