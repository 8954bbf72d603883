// The .kontur document's validating reader (see document.h): Qt's JSON parser after the fast scan
// (documentscan.cpp), then every member checked, every error with its JSON path; and the rule that
// the writer (documentwrite.cpp) writes a composite curve's handles by. Their shared insides:
// document_p.h.
#include "io/document.h"

#include "io/document_p.h"
#include "io/fileio.h"
#include "io/piece.h"

#include "geometry/composite.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <algorithm>
#include <cmath>

namespace kontur::io::documentjson {

QString documentFolder(const QString &documentPath)
{
    return QFileInfo(documentPath).absolutePath();
}

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

} // namespace kontur::io::documentjson

namespace kontur::io {

namespace {

using documentjson::FastPoints;
using documentjson::ruleControlPoints;

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

Result<DocumentData> documentFromJson(QByteArrayView json, const QString &documentPath, const Limits &limits)
{
    Reader r(documentPath, limits);
    const std::string_view text(json.data(), static_cast<std::size_t>(json.size()));
    if (json.size() > limits.maxFileBytes)
        return r.error(
            ErrorCode::FileTooLarge, {},
            QStringLiteral("the document is larger than %1 bytes, the most Kontur reads").arg(limits.maxFileBytes));
    documentjson::Scan scan = documentjson::scanDocument(text, limits);
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
            b.file = QDir::cleanPath(QDir(documentjson::documentFolder(documentPath)).absoluteFilePath(b.file));
        doc.background = b;
    }
    if (auto e = validateDocument(doc)) {
        e->file = documentPath;
        return *e;
    }
    return doc;
}

Result<DocumentData> openDocument(const QString &path, const Limits &limits)
{
    auto bytes = readFileBytes(path, limits);
    if (!bytes)
        return bytes.error();
    return documentFromJson(*bytes, path, limits);
}

} // namespace kontur::io
