// The .kontur document writer and validating reader (see document.h).
// Over 600 lines because the writer, the fast point scanner and the validating reader must agree on one
// grammar and its limits; each part is short, and split apart they would only reach into each other.
#include "io/document.h"

#include "io/piece.h"

#include "io/fileio.h"
#include "io/piece.h"

#include "geometry/composite.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <string_view>

namespace kontur::io {

namespace {

// ---------------------------------------------------------------- writing

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

QString documentFolder(const QString &documentPath)
{
    return QFileInfo(documentPath).absolutePath();
}

// ---------------------------------------------------------------- reading

// A number as JSON writes it (RFC 8259 §6: no '+', no leading zeros, digits around the point), as
// a finite double; nullopt for anything else, which then takes the general path with its errors.
std::optional<double> jsonNumber(std::string_view text, std::size_t &i)
{
    const std::size_t start = i;
    if (i < text.size() && text[i] == '-')
        ++i;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9')
            ++i;
        return i - from;
    };
    const std::size_t intAt = i;
    const std::size_t intDigits = digits();
    if (intDigits == 0 || (intDigits > 1 && text[intAt] == '0'))
        return std::nullopt;
    if (i < text.size() && text[i] == '.') {
        ++i;
        if (digits() == 0)
            return std::nullopt;
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-'))
            ++i;
        if (digits() == 0)
            return std::nullopt;
    }
    double v = 0.0;
    const auto res = std::from_chars(text.data() + start, text.data() + i, v);
    if (res.ec != std::errc() || res.ptr != text.data() + i || !std::isfinite(v))
        return std::nullopt;
    return v;
}

bool isJsonSpace(char c)
{
    return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

// The points of one curve, read straight from the text (see scanDocument).
struct FastPoints
{
    qint64 count = 0;               // points in the array
    std::vector<geo::Point> points; // empty when the file's points went over the limit
    std::vector<std::size_t> ruled; // the indices written as null (see ruleControlPoints)
};

// An array of [x, y] pairs of numbers starting at text[i] == '[': its points, with i past its end;
// nullopt when it is anything else (then Qt's parser and the reader's checks say what is wrong).
// Points past `budget` are counted, not kept.
std::optional<FastPoints> fastPointArray(std::string_view text, std::size_t &i, qint64 budget)
{
    const auto skip = [&] {
        while (i < text.size() && isJsonSpace(text[i]))
            ++i;
    };
    const auto expect = [&](char c) {
        skip();
        if (i >= text.size() || text[i] != c)
            return false;
        ++i;
        return true;
    };
    FastPoints out;
    ++i; // '['
    skip();
    if (i < text.size() && text[i] == ']') {
        ++i;
        return out;
    }
    while (true) {
        skip();
        if (text.substr(i, 4) == "null") {
            // A composite curve's handle that follows the construction rule (see ruleControlPoints).
            i += 4;
            if (++out.count <= budget) {
                out.ruled.push_back(out.points.size());
                out.points.emplace_back(std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::quiet_NaN());
            }
        } else {
            if (!expect('['))
                return std::nullopt;
            skip();
            const auto x = jsonNumber(text, i);
            if (!x || !expect(','))
                return std::nullopt;
            skip();
            const auto y = jsonNumber(text, i);
            if (!y || !expect(']'))
                return std::nullopt;
            if (++out.count <= budget)
                out.points.emplace_back(*x, *y);
        }
        skip();
        if (i < text.size() && text[i] == ',') {
            ++i;
            continue;
        }
        if (i < text.size() && text[i] == ']') {
            ++i;
            break;
        }
        return std::nullopt;
    }
    if (out.count > budget) {
        out.points = {};
        out.ruled = {};
    }
    return out;
}

// An array of plain strings (no escapes) starting at text[i] == '[', as node types: the three names
// share one QString each. nullopt for anything else, or more than `budget` strings.
std::optional<std::vector<QString>> fastNodeTypes(std::string_view text, std::size_t &i, qint64 budget)
{
    static const QString names[] = {QStringLiteral("smooth"), QStringLiteral("symmetric"), QStringLiteral("corner")};
    std::vector<QString> out;
    ++i; // '['
    while (true) {
        while (i < text.size() && isJsonSpace(text[i]))
            ++i;
        if (i < text.size() && text[i] == ']' && out.empty()) {
            ++i;
            return out;
        }
        if (i >= text.size() || text[i] != '"')
            return std::nullopt;
        const std::size_t start = ++i;
        while (i < text.size() && text[i] != '"' && text[i] != '\\' && static_cast<unsigned char>(text[i]) >= 0x20)
            ++i;
        if (i >= text.size() || text[i] != '"' || static_cast<qint64>(out.size()) >= budget)
            return std::nullopt;
        const std::string_view name = text.substr(start, i - start);
        ++i;
        const auto known = std::find_if(std::begin(names), std::end(names),
                                        [&](const QString &n) { return n == QLatin1String(name.data(), name.size()); });
        out.push_back(known != std::end(names) ? *known
                                               : QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
        while (i < text.size() && isJsonSpace(text[i]))
            ++i;
        if (i < text.size() && text[i] == ',') {
            ++i;
            continue;
        }
        if (i < text.size() && text[i] == ']') {
            ++i;
            return out;
        }
        return std::nullopt;
    }
}

// One pass over the text before Qt's parser: nesting deeper than the limit is refused before anything
// is built (Qt's own limit is far higher, and every level costs memory), and each curve's "points"
// array is read straight into points, its text replaced by a placeholder 0 for Qt's parser (the
// cuts are kept to map its error offsets back to the file). A QJsonArray per point would make a million-knot document
// take seconds and a gigabyte to open.
struct Scan
{
    std::optional<std::size_t> tooDeepAt;
    // Where the curve after the last one a file may hold begins: counted while scanning, so that a
    // document of a million curves is refused before Qt's parser builds them (1.4 GB before).
    std::optional<std::size_t> tooManyCurvesAt;
    QByteArray rest;                        // the text for Qt's parser (empty: the original text)
    std::map<qsizetype, FastPoints> points; // by curve index
    std::map<qsizetype, std::vector<QString>> nodeTypes;
    // Where the cut arrays were: {offset in rest just after the placeholder, bytes cut before it},
    // so that an offset of Qt's parser maps back to the file.
    std::vector<std::pair<qsizetype, qsizetype>> cuts;

    [[nodiscard]] std::size_t originalOffset(qsizetype restOffset) const
    {
        qsizetype shift = 0;
        for (const auto &[at, cut] : cuts)
            if (restOffset >= at)
                shift = cut;
        return static_cast<std::size_t>(restOffset + shift);
    }
};

Scan scanDocument(std::string_view text, const Limits &limits)
{
    struct Frame
    {
        char type = '{';
        bool expectKey = true;
        std::string_view key;
        qsizetype index = 0;
    };
    Scan scan;
    std::vector<Frame> stack;
    qint64 total = 0;
    std::size_t copied = 0; // text before this offset is in scan.rest
    qsizetype cut = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"') {
            const std::size_t start = ++i;
            while (i < text.size() && text[i] != '"')
                i += text[i] == '\\' ? 2 : 1;
            if (!stack.empty() && stack.back().type == '{' && stack.back().expectKey)
                stack.back().key = text.substr(start, std::min(i, text.size()) - start);
        } else if (c == ':') {
            if (!stack.empty())
                stack.back().expectKey = false;
        } else if (c == ',') {
            if (!stack.empty()) {
                stack.back().expectKey = true;
                ++stack.back().index;
                // A comma in the root's "curves" array: index + 1 curves so far.
                if (stack.size() == 2 && stack[0].key == "curves" && stack[1].type == '[' &&
                    stack[1].index >= limits.maxCurves) {
                    scan.tooManyCurvesAt = i;
                    return scan;
                }
            }
        } else if (c == '[' || c == '{') {
            const bool curveMember = c == '[' && stack.size() == 3 && stack[0].key == "curves" &&
                                     stack[1].type == '[' && stack[2].type == '{' && !stack[2].expectKey &&
                                     stack.size() + 2 <= static_cast<std::size_t>(limits.maxDepth);
            std::size_t end = i;
            bool fastRead = false;
            if (curveMember && stack[2].key == "points") {
                if (auto fast = fastPointArray(text, end, std::max<qint64>(0, limits.maxPoints - total))) {
                    total += fast->count;
                    scan.points[stack[1].index] = std::move(*fast);
                    fastRead = true;
                }
            } else if (curveMember && stack[2].key == "nodeTypes") {
                if (auto fast = fastNodeTypes(text, end, limits.maxPoints)) {
                    scan.nodeTypes[stack[1].index] = std::move(*fast);
                    fastRead = true;
                }
            }
            if (fastRead) {
                scan.rest.append(text.data() + copied, static_cast<qsizetype>(i - copied));
                scan.rest += '0';
                cut += static_cast<qsizetype>(end - i) - 1;
                scan.cuts.emplace_back(scan.rest.size(), cut);
                copied = end;
                i = end - 1;
                continue;
            }
            if (static_cast<int>(stack.size()) >= limits.maxDepth) {
                scan.tooDeepAt = i;
                return scan;
            }
            stack.push_back({c, c == '{', {}, 0});
        } else if (c == ']' || c == '}') {
            if (!stack.empty())
                stack.pop_back();
        }
    }
    if (copied > 0)
        scan.rest.append(text.data() + copied, static_cast<qsizetype>(text.size() - copied));
    return scan;
}

QString indexPath(const QString &base, qsizetype i)
{
    return base + QLatin1Char('[') + QString::number(i) + QLatin1Char(']');
}

QString memberPath(const QString &base, const char *name)
{
    return base.isEmpty() ? QString::fromLatin1(name) : base + QLatin1Char('.') + QLatin1String(name);
}

const char *typeName(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
        return "null";
    case QJsonValue::Bool:
        return "a boolean";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String:
        return "a string";
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    case QJsonValue::Undefined:
        break;
    }
    return "missing";
}

// A composite curve's handles are mostly where the construction rule (docs/requirements.md 1.2) puts them; a
// document writes those as null and the reader computes them again from the knots, so a curve of a
// million knots takes 40 % of the space (issue 17: 145 MB, above the reader's limit, became under
// 60 MB). The rule is computed by the same function when writing and reading, so the points come
// back bit for bit; a handle the user moved differs from the rule and is written as a number.
// The control vector the rule gives for `c`'s knots, or an empty one when `c` is no well-formed
// composite record (then every point is written as a number).
std::vector<geo::Point> ruleControlPoints(const CurveRecord &c)
{
    if (c.kind != QLatin1String("composite"))
        return {};
    const int knots = compositeKnotCount(c.points.size(), c.closed);
    if (knots < 2 || (c.closed && knots < 3))
        return {};
    std::vector<geo::Point> k;
    k.reserve(static_cast<std::size_t>(knots));
    for (int i = 0; i < knots; ++i) {
        const geo::Point &p = c.points[static_cast<std::size_t>(3 * i)];
        if (!p.allFinite())
            return {};
        k.push_back(p);
    }
    geo::CompositeCurve rule(k);
    if (c.closed && !rule.close().ok())
        return {};
    std::vector<geo::Point> out = rule.controlPoints();
    if (c.closed && !out.empty())
        out.pop_back(); // the record does not store the repeated first knot
    if (out.size() != c.points.size())
        return {};
    return out;
}

// The index into `ruled` of the first null the rule cannot fill (a knot, a point of another kind,
// a record the rule does not fit), or ruled.size() when the rule fills them all.
std::size_t firstUnruledNull(const CurveRecord &c, const std::vector<std::size_t> &ruled)
{
    for (std::size_t r = 0; r < ruled.size(); ++r)
        if (ruled[r] % 3 == 0 || c.kind != QLatin1String("composite"))
            return r;
    return ruleControlPoints(c).empty() ? 0 : ruled.size();
}

class Reader final
{
public:
    Reader(QString file, const Limits &limits)
        : m_file(std::move(file))
        , m_limits(limits)
    {
    }

    Error error(ErrorCode code, const QString &path, const QString &message) const
    {
        Error e;
        e.code = code;
        e.file = m_file;
        e.path = path;
        e.message = message;
        return e;
    }
    Error wrongType(const QString &path, const QJsonValue &v, const char *expected) const
    {
        return error(ErrorCode::WrongType, path,
                     QStringLiteral("expected %1, found %2").arg(QLatin1String(expected), QLatin1String(typeName(v))));
    }

    // A member: `required` ones must be there; optional ones keep the default when absent.
    std::optional<Error> getString(const QJsonObject &o, const QString &base, const char *name, QString &out,
                                   bool required) const
    {
        const QJsonValue v = o.value(QLatin1String(name));
        if (v.isUndefined())
            return required ? std::optional(error(ErrorCode::MissingField, memberPath(base, name),
                                                  QStringLiteral("required member is missing")))
                            : std::nullopt;
        if (!v.isString())
            return wrongType(memberPath(base, name), v, "a string");
        out = v.toString();
        return std::nullopt;
    }
    std::optional<Error> getBool(const QJsonObject &o, const QString &base, const char *name, bool &out) const
    {
        const QJsonValue v = o.value(QLatin1String(name));
        if (v.isUndefined())
            return std::nullopt;
        if (!v.isBool())
            return wrongType(memberPath(base, name), v, "true or false");
        out = v.toBool();
        return std::nullopt;
    }
    std::optional<Error> number(const QJsonValue &v, const QString &path, double &out) const
    {
        if (!v.isDouble())
            return wrongType(path, v, "a number");
        out = v.toDouble();
        if (!std::isfinite(out))
            return error(ErrorCode::NumberOutOfRange, path, QStringLiteral("the number is not finite"));
        return std::nullopt;
    }
    std::optional<Error> getNumber(const QJsonObject &o, const QString &base, const char *name, double &out) const
    {
        const QJsonValue v = o.value(QLatin1String(name));
        if (v.isUndefined())
            return std::nullopt;
        return number(v, memberPath(base, name), out);
    }
    std::optional<Error> point(const QJsonValue &v, const QString &path, geo::Point &out) const
    {
        if (!v.isArray())
            return wrongType(path, v, "a point [x, y]");
        const QJsonArray a = v.toArray();
        if (a.size() != 2)
            return error(ErrorCode::WrongType, path,
                         QStringLiteral("a point has two coordinates [x, y], not %1").arg(a.size()));
        for (int c = 0; c < 2; ++c)
            if (auto e = number(a.at(c), indexPath(path, c), out[c]))
                return e;
        return std::nullopt;
    }

    // `fast`: the curve's points when scanDocument read them (its "points" member is then a placeholder).
    std::optional<Error> curve(const QJsonValue &value, const QString &path, CurveRecord &c, FastPoints *fast,
                               std::vector<QString> *fastNodes)
    {
        if (!value.isObject())
            return wrongType(path, value, "a curve object");
        const QJsonObject o = value.toObject();
        if (auto e = getString(o, path, "kind", c.kind, true))
            return e;
        if (!kindInfo(c.kind)) {
            CurveRecord probe;
            probe.kind = c.kind;
            return error(ErrorCode::UnknownKind, memberPath(path, "kind"), validateCurve(probe)->message);
        }
        for (const auto &[name, field] : {std::pair{"name", &c.name}, std::pair{"color", &c.color}})
            if (auto e = getString(o, path, name, *field, false))
                return e;
        for (const auto &[name, field] :
             {std::pair{"visible", &c.visible}, std::pair{"locked", &c.locked}, std::pair{"closed", &c.closed}})
            if (auto e = getBool(o, path, name, *field))
                return e;
        if (auto e = getString(o, path, "parameterization", c.parameterization, kindInfo(c.kind)->usesParameterization))
            return e;
        const QString pointsPath = memberPath(path, "points");
        const QJsonValue points = o.value(QLatin1String("points"));
        if (points.isUndefined())
            return error(ErrorCode::MissingField, pointsPath, QStringLiteral("required member is missing"));
        if (!fast && !points.isArray())
            return wrongType(pointsPath, points, "an array of points");
        const QJsonArray pa = fast ? QJsonArray() : points.toArray();
        m_points += fast ? fast->count : pa.size();
        if (m_points > m_limits.maxPoints)
            return error(
                ErrorCode::TooManyPoints, pointsPath,
                QStringLiteral("more than %1 points, the most Kontur reads from one file").arg(m_limits.maxPoints));
        std::vector<std::size_t> ruled;
        if (fast) {
            c.points = std::move(fast->points);
            ruled = std::move(fast->ruled);
        } else {
            c.points.resize(static_cast<std::size_t>(pa.size()));
            for (qsizetype i = 0; i < pa.size(); ++i) {
                if (pa.at(i).isNull()) {
                    ruled.push_back(static_cast<std::size_t>(i));
                    continue;
                }
                if (auto e = point(pa.at(i), indexPath(pointsPath, i), c.points[static_cast<std::size_t>(i)]))
                    return e;
            }
        }
        const QJsonValue nodes = o.value(QLatin1String("nodeTypes"));
        const QString nodesPath = memberPath(path, "nodeTypes");
        if (fastNodes) {
            c.nodeTypes = std::move(*fastNodes);
        } else if (!nodes.isUndefined()) {
            if (!nodes.isArray())
                return wrongType(nodesPath, nodes, "an array of node types");
            const QJsonArray na = nodes.toArray();
            if (na.size() > m_limits.maxPoints)
                return error(ErrorCode::TooManyPoints, nodesPath,
                             QStringLiteral("more node types than points Kontur reads"));
            for (qsizetype i = 0; i < na.size(); ++i) {
                if (!na.at(i).isString())
                    return wrongType(indexPath(nodesPath, i), na.at(i), "a node type (a string)");
                c.nodeTypes.push_back(na.at(i).toString());
            }
        } else if (c.kind == QLatin1String("composite")) {
            return error(ErrorCode::MissingField, nodesPath, QStringLiteral("required member is missing"));
        }
        if (!ruled.empty()) {
            const std::size_t bad = firstUnruledNull(c, ruled);
            if (bad != ruled.size())
                return error(ErrorCode::WrongType, indexPath(pointsPath, static_cast<qsizetype>(ruled[bad])),
                             QStringLiteral("a point is null; only a composite curve's handles may be (they then "
                                            "follow the construction rule)"));
            const std::vector<geo::Point> rule = ruleControlPoints(c);
            for (std::size_t index : ruled)
                c.points[index] = rule[index];
        }
        const QJsonValue settings = o.value(QLatin1String("settings"));
        if (!settings.isUndefined()) {
            if (!settings.isObject())
                return wrongType(memberPath(path, "settings"), settings, "an object");
            c.settings = settings.toObject();
        }
        if (const auto problem = validateCurve(c))
            return error(problem->code, problemPath(path, *problem), problem->message);
        return std::nullopt;
    }

    static QString problemPath(const QString &path, const CurveProblem &p)
    {
        switch (p.field) {
        case CurveProblem::Kind:
            return memberPath(path, "kind");
        case CurveProblem::Parameterization:
            return memberPath(path, "parameterization");
        case CurveProblem::Points:
            return memberPath(path, "points");
        case CurveProblem::Point: {
            QString s = indexPath(memberPath(path, "points"), p.index);
            return p.coordinate >= 0 ? indexPath(s, p.coordinate) : s;
        }
        case CurveProblem::NodeTypes:
            return memberPath(path, "nodeTypes");
        case CurveProblem::NodeType:
            return indexPath(memberPath(path, "nodeTypes"), p.index);
        case CurveProblem::Color:
            return memberPath(path, "color");
        case CurveProblem::Closed:
            return memberPath(path, "closed");
        }
        return path;
    }

    std::optional<Error> background(const QJsonValue &value, BackgroundRecord &b) const
    {
        const QString path = QStringLiteral("background");
        if (!value.isObject())
            return wrongType(path, value, "an object or null");
        const QJsonObject o = value.toObject();
        if (auto e = getString(o, path, "file", b.file, true))
            return e;
        for (const auto &[name, field] : {std::pair{"visible", &b.visible}, std::pair{"locked", &b.locked}})
            if (auto e = getBool(o, path, name, *field))
                return e;
        for (const auto &[name, field] :
             {std::pair{"opacity", &b.opacity}, std::pair{"originX", &b.originX}, std::pair{"originY", &b.originY},
              std::pair{"scale", &b.scale}, std::pair{"rotation", &b.rotation}})
            if (auto e = getNumber(o, path, name, *field))
                return e;
        const QJsonValue cal = o.value(QLatin1String("calibration"));
        const QString calPath = memberPath(path, "calibration");
        if (!cal.isUndefined() && !cal.isNull()) {
            if (!cal.isObject())
                return wrongType(calPath, cal, "an object or null");
            const QJsonObject co = cal.toObject();
            b.calibrated = true;
            geo::Point a, bp;
            for (const auto &[name, pt] : {std::pair{"a", &a}, std::pair{"b", &bp}}) {
                const QJsonValue v = co.value(QLatin1String(name));
                if (v.isUndefined())
                    return error(ErrorCode::MissingField, memberPath(calPath, name),
                                 QStringLiteral("required member is missing"));
                if (auto e = point(v, memberPath(calPath, name), *pt))
                    return e;
            }
            b.ax = a.x(), b.ay = a.y(), b.bx = bp.x(), b.by = bp.y();
            if (co.value(QLatin1String("distance")).isUndefined())
                return error(ErrorCode::MissingField, memberPath(calPath, "distance"),
                             QStringLiteral("required member is missing"));
            if (auto e = getNumber(co, calPath, "distance", b.distance))
                return e;
        }
        // Absent in documents written before the perspective calibration (issue #22).
        const QJsonValue persp = o.value(QLatin1String("perspective"));
        const QString perspPath = memberPath(path, "perspective");
        if (!persp.isUndefined() && !persp.isNull()) {
            if (!persp.isObject())
                return wrongType(perspPath, persp, "an object or null");
            const QJsonObject po = persp.toObject();
            b.perspective = true;
            const QJsonValue corners = po.value(QLatin1String("corners"));
            const QString cornersPath = memberPath(perspPath, "corners");
            if (corners.isUndefined())
                return error(ErrorCode::MissingField, cornersPath, QStringLiteral("required member is missing"));
            if (!corners.isArray() || corners.toArray().size() != 4)
                return wrongType(cornersPath, corners, "an array of four points");
            for (int i = 0; i < 4; ++i) {
                geo::Point c;
                if (auto e = point(corners.toArray().at(i), indexPath(cornersPath, i), c))
                    return e;
                b.corners[2 * i] = c.x();
                b.corners[2 * i + 1] = c.y();
            }
            geo::Point at;
            const QJsonValue origin = po.value(QLatin1String("origin"));
            if (origin.isUndefined())
                return error(ErrorCode::MissingField, memberPath(perspPath, "origin"),
                             QStringLiteral("required member is missing"));
            if (auto e = point(origin, memberPath(perspPath, "origin"), at))
                return e;
            b.rectX = at.x();
            b.rectY = at.y();
            for (const auto &[name, field] : {std::pair{"width", &b.rectWidth}, std::pair{"height", &b.rectHeight}}) {
                if (po.value(QLatin1String(name)).isUndefined())
                    return error(ErrorCode::MissingField, memberPath(perspPath, name),
                                 QStringLiteral("required member is missing"));
                if (auto e = getNumber(po, perspPath, name, *field))
                    return e;
            }
        }
        return std::nullopt;
    }

    qint64 m_points = 0;

private:
    QString m_file;
    Limits m_limits;
};

} // namespace

std::optional<Error> validateDocument(const DocumentData &doc)
{
    Reader r({}, Limits{});
    if (!isUnitName(doc.units))
        return r.error(ErrorCode::InvalidValue, QStringLiteral("units"),
                       QStringLiteral("unknown units \"%1\" (px, mm, cm, in or pt)").arg(doc.units));
    for (std::size_t i = 0; i < doc.curves.size(); ++i)
        if (const auto problem = validateCurve(doc.curves[i]))
            return r.error(
                problem->code,
                Reader::problemPath(indexPath(QStringLiteral("curves"), static_cast<qsizetype>(i)), *problem),
                problem->message);
    if (doc.background) {
        const BackgroundRecord &b = *doc.background;
        const QString path = QStringLiteral("background");
        for (const auto &[name, v] :
             {std::pair{"opacity", b.opacity}, std::pair{"originX", b.originX}, std::pair{"originY", b.originY},
              std::pair{"scale", b.scale}, std::pair{"rotation", b.rotation}})
            if (!std::isfinite(v))
                return r.error(ErrorCode::NumberOutOfRange, memberPath(path, name),
                               QStringLiteral("the number is not finite"));
        if (!(b.opacity >= 0.0 && b.opacity <= 1.0))
            return r.error(ErrorCode::InvalidValue, memberPath(path, "opacity"),
                           QStringLiteral("the opacity lies in 0..1"));
        if (!(b.scale > 0.0))
            return r.error(ErrorCode::InvalidValue, memberPath(path, "scale"),
                           QStringLiteral("the scale must be positive"));
        if (b.calibrated) {
            const QString cal = memberPath(path, "calibration");
            for (const auto &[name, v] : {std::pair{"a", b.ax}, std::pair{"a", b.ay}, std::pair{"b", b.bx},
                                          std::pair{"b", b.by}, std::pair{"distance", b.distance}})
                if (!std::isfinite(v))
                    return r.error(ErrorCode::NumberOutOfRange, memberPath(cal, name),
                                   QStringLiteral("the number is not finite"));
            if (!(b.distance > 0.0))
                return r.error(ErrorCode::InvalidValue, memberPath(cal, "distance"),
                               QStringLiteral("the calibration distance must be positive"));
        }
        if (b.perspective) {
            const QString persp = memberPath(path, "perspective");
            for (double v : b.corners)
                if (!std::isfinite(v))
                    return r.error(ErrorCode::NumberOutOfRange, memberPath(persp, "corners"),
                                   QStringLiteral("the number is not finite"));
            if (!std::isfinite(b.rectX) || !std::isfinite(b.rectY))
                return r.error(ErrorCode::NumberOutOfRange, memberPath(persp, "origin"),
                               QStringLiteral("the number is not finite"));
            for (const auto &[name, v] : {std::pair{"width", b.rectWidth}, std::pair{"height", b.rectHeight}})
                if (!(std::isfinite(v) && v > 0.0))
                    return r.error(ErrorCode::InvalidValue, memberPath(persp, name),
                                   QStringLiteral("the rectangle's sides must be positive"));
        }
    }
    return std::nullopt;
}

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
        rules.push_back(ruleControlPoints(c));
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
            file = QDir(documentFolder(documentPath)).relativeFilePath(file);
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

Result<DocumentData> documentFromJson(QByteArrayView json, const QString &documentPath, const Limits &limits)
{
    Reader r(documentPath, limits);
    const std::string_view text(json.data(), static_cast<std::size_t>(json.size()));
    if (json.size() > limits.maxFileBytes)
        return r.error(
            ErrorCode::FileTooLarge, {},
            QStringLiteral("the document is larger than %1 bytes, the most Kontur reads").arg(limits.maxFileBytes));
    Scan scan = scanDocument(text, limits);
    if (const auto at = scan.tooDeepAt) {
        Error e = r.error(ErrorCode::TooDeep, {}, QStringLiteral("nested deeper than %1 levels").arg(limits.maxDepth));
        const TextPosition pos = positionOf(text, *at);
        e.line = pos.line;
        e.column = pos.column;
        return e;
    }
    if (const auto at = scan.tooManyCurvesAt) {
        Error e =
            r.error(ErrorCode::TooManyCurves, QStringLiteral("curves"),
                    QStringLiteral("more than %1 curves, the most Kontur reads from one file").arg(limits.maxCurves));
        const TextPosition pos = positionOf(text, *at);
        e.line = pos.line;
        e.column = pos.column;
        return e;
    }
    QJsonParseError perr;
    const QJsonDocument parsed = QJsonDocument::fromJson(scan.rest.isEmpty() ? json.toByteArray() : scan.rest, &perr);
    scan.rest = {};
    if (perr.error != QJsonParseError::NoError) {
        Error e = r.error(ErrorCode::JsonSyntax, {}, QStringLiteral("not valid JSON: %1").arg(perr.errorString()));
        const TextPosition pos = positionOf(text, scan.originalOffset(std::max(perr.offset, 0)));
        e.line = pos.line;
        e.column = pos.column;
        return e;
    }
    if (!parsed.isObject())
        return r.error(ErrorCode::NotKontur, {}, QStringLiteral("not a Kontur document (the JSON is not an object)"));
    const QJsonObject root = parsed.object();
    const QJsonValue format = root.value(QLatin1String("format"));
    if (format.toString() != QLatin1String("kontur"))
        return r.error(ErrorCode::NotKontur, QStringLiteral("format"),
                       QStringLiteral("not a Kontur document (\"format\" is not \"kontur\")"));
    const QJsonValue version = root.value(QLatin1String("version"));
    if (version.isUndefined())
        return r.error(ErrorCode::MissingField, QStringLiteral("version"),
                       QStringLiteral("required member is missing"));
    if (!version.isDouble() || version.toDouble() != std::floor(version.toDouble()))
        return r.wrongType(QStringLiteral("version"), version, "a whole number");
    if (version.toDouble() > kDocumentVersion)
        return r.error(ErrorCode::UnsupportedVersion, QStringLiteral("version"),
                       QStringLiteral("the document has format version %1, written by a newer Kontur; this version "
                                      "reads version %2 and older")
                           .arg(version.toDouble())
                           .arg(kDocumentVersion));
    if (version.toDouble() < 1)
        return r.error(ErrorCode::InvalidValue, QStringLiteral("version"),
                       QStringLiteral("format version %1 does not exist").arg(version.toDouble()));

    DocumentData doc;
    if (auto e = r.getString(root, {}, "units", doc.units, false))
        return *e;
    if (!isUnitName(doc.units))
        return r.error(ErrorCode::InvalidValue, QStringLiteral("units"),
                       QStringLiteral("unknown units \"%1\" (px, mm, cm, in or pt)").arg(doc.units));
    const QJsonValue curves = root.value(QLatin1String("curves"));
    if (curves.isUndefined())
        return r.error(ErrorCode::MissingField, QStringLiteral("curves"), QStringLiteral("required member is missing"));
    if (!curves.isArray())
        return r.wrongType(QStringLiteral("curves"), curves, "an array of curves");
    const QJsonArray ca = curves.toArray();
    if (ca.size() > limits.maxCurves)
        return r.error(
            ErrorCode::TooManyCurves, QStringLiteral("curves"),
            QStringLiteral("more than %1 curves, the most Kontur reads from one file").arg(limits.maxCurves));
    doc.curves.resize(static_cast<std::size_t>(ca.size()));
    for (qsizetype i = 0; i < ca.size(); ++i) {
        const auto fast = scan.points.find(i);
        const auto fastNodes = scan.nodeTypes.find(i);
        if (auto e = r.curve(ca.at(i), indexPath(QStringLiteral("curves"), i), doc.curves[static_cast<std::size_t>(i)],
                             fast == scan.points.end() ? nullptr : &fast->second,
                             fastNodes == scan.nodeTypes.end() ? nullptr : &fastNodes->second))
            return *e;
    }
    const QJsonValue bg = root.value(QLatin1String("background"));
    if (!bg.isUndefined() && !bg.isNull()) {
        BackgroundRecord b;
        if (auto e = r.background(bg, b))
            return *e;
        if (!documentPath.isEmpty() && !b.file.isEmpty() && QFileInfo(b.file).isRelative())
            b.file = QDir::cleanPath(QDir(documentFolder(documentPath)).absoluteFilePath(b.file));
        doc.background = b;
    }
    if (auto e = validateDocument(doc)) {
        e->file = documentPath;
        return *e;
    }
    return doc;
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

Result<DocumentData> openDocument(const QString &path, const Limits &limits)
{
    auto bytes = readFileBytes(path, limits);
    if (!bytes)
        return bytes.error();
    return documentFromJson(*bytes, path, limits);
}

} // namespace kontur::io
