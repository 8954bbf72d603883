// The points text reader and writer (see pointstext.h and docs/file-formats.md).
// Over 600 lines because the hand-written grammar (separators, comments, record lines) and its
// writer share the keywords and limits; the reader is one line-by-line pass.
#include "io/pointstext.h"

#include "geometry/composite.h"
#include "io/fileio.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>

#include <string>
#include <string_view>

namespace kontur::io {

namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

bool isLetter(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// One line of the file being parsed, with positions for errors.
class LineParser final
{
public:
    LineParser(std::string_view line, int number, const QString &file)
        : m_line(line)
        , m_number(number)
        , m_file(file)
    {
    }

    [[nodiscard]] Error error(ErrorCode code, std::size_t at, const QString &message) const
    {
        Error e;
        e.code = code;
        e.file = m_file;
        e.line = m_number;
        e.column = codePointCount(m_line.substr(0, std::min(at, m_line.size()))) + 1;
        e.message = message;
        return e;
    }
    void skipSpaces()
    {
        while (m_pos < m_line.size() && isSpace(m_line[m_pos]))
            ++m_pos;
    }
    [[nodiscard]] bool atEnd() const { return m_pos >= m_line.size() || m_line[m_pos] == '#'; }
    [[nodiscard]] std::size_t pos() const { return m_pos; }
    [[nodiscard]] std::string_view line() const { return m_line; }
    [[nodiscard]] int number() const { return m_number; }
    void setPos(std::size_t p) { m_pos = p; }

    // A run of characters up to a space, a separator, or a comment.
    std::string_view token(bool stopAtSeparators)
    {
        const std::size_t start = m_pos;
        while (m_pos < m_line.size() && !isSpace(m_line[m_pos]) && m_line[m_pos] != '#' &&
               !(stopAtSeparators && (m_line[m_pos] == ',' || m_line[m_pos] == ';')))
            ++m_pos;
        return m_line.substr(start, m_pos - start);
    }

    // A double-quoted string with \" and \\ escapes (directive values like names).
    Result<QString> quoted()
    {
        const std::size_t start = m_pos;
        ++m_pos;
        std::string out;
        while (m_pos < m_line.size() && m_line[m_pos] != '"') {
            if (m_line[m_pos] == '\\' && m_pos + 1 < m_line.size())
                ++m_pos;
            out += m_line[m_pos++];
        }
        if (m_pos >= m_line.size())
            return error(ErrorCode::UnterminatedString, start, QStringLiteral("the quoted text has no closing quote"));
        ++m_pos;
        return QString::fromUtf8(out.data(), static_cast<qsizetype>(out.size()));
    }

private:
    std::string_view m_line;
    std::size_t m_pos = 0;
    int m_number = 0;
    QString m_file;
};

QString quote(std::string_view s)
{
    return QLatin1Char('"') + QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())) + QLatin1Char('"');
}

// A point line: two numbers separated by blanks, one ',' or one ';' (with optional blanks around).
Result<geo::Point> parsePointLine(LineParser &p)
{
    geo::Point pt;
    bool comma = false;
    for (int c = 0; c < 2; ++c) {
        p.skipSpaces();
        const std::size_t at = p.pos();
        if (c == 1 && p.atEnd())
            return p.error(ErrorCode::ExpectedNumber, at, QStringLiteral("expected two numbers (x and y), found one"));
        const std::string_view tok = p.token(true);
        double v = 0.0;
        switch (parseDouble(tok, v)) {
        case NumberStatus::Ok:
            break;
        case NumberStatus::OutOfRange:
            return p.error(ErrorCode::NumberOutOfRange, at,
                           QStringLiteral("%1 is not a finite number").arg(quote(tok)));
        case NumberStatus::Malformed:
            return p.error(ErrorCode::ExpectedNumber, at,
                           tok.empty() ? QStringLiteral("expected a number")
                                       : QStringLiteral("expected a number, found %1").arg(quote(tok)));
        }
        pt[c] = v;
        if (c == 0) {
            p.skipSpaces();
            if (!p.atEnd() && (p.line()[p.pos()] == ',' || p.line()[p.pos()] == ';')) {
                comma = p.line()[p.pos()] == ',';
                p.setPos(p.pos() + 1);
            }
        }
    }
    p.skipSpaces();
    if (!p.atEnd())
        return p.error(ErrorCode::TrailingText, p.pos(),
                       comma ? QStringLiteral("unexpected text after the point (numbers use a decimal point, "
                                              "not a decimal comma)")
                             : QStringLiteral("unexpected text after the point: a line holds one point, x and y"));
    return pt;
}

// A header line of a hand-written list: "x y", "X;Y", "x,y".
bool isHeaderLine(std::string_view line)
{
    std::string letters;
    for (const char c : line) {
        if (c == '#')
            break;
        if (!isSpace(c) && c != ',' && c != ';')
            letters += static_cast<char>(c | 0x20);
    }
    return letters == "xy";
}

struct Building
{
    TextRecord record;
    bool explicitCurve = false;
    bool hasNodes = false;
    int nodesLine = 0;
    int pointsLine = 0;
};

Error recordError(const Building &b, const QString &file, const CurveProblem &problem)
{
    Error e;
    e.code = problem.code;
    e.file = file;
    e.line = (problem.field == CurveProblem::NodeType || problem.field == CurveProblem::NodeTypes) && b.hasNodes
                 ? b.nodesLine
                 : b.record.line;
    e.message = QStringLiteral("curve record: ") + problem.message;
    return e;
}

// Checks a finished record and normalises known kinds (see TextRecord).
Result<TextRecord> finishRecord(Building b, const QString &file)
{
    CurveRecord &c = b.record.curve;
    Error e;
    e.file = file;
    e.line = b.record.line;
    if (c.points.empty()) {
        e.code = ErrorCode::EmptyRecord;
        e.message = QStringLiteral("the curve record has no points");
        return e;
    }
    if (c.kind.isEmpty())
        return std::move(b.record);
    const KindInfo *info = kindInfo(c.kind);
    if (!info) {
        CurveRecord probe;
        probe.kind = c.kind;
        return recordError(b, file, *validateCurve(probe));
    }
    if (b.record.pointKind != PointKind::Unspecified) {
        const bool knots = b.record.pointKind == PointKind::Knots;
        const bool fits = QLatin1String(info->id) == QLatin1String("composite") || knots == info->definedByKnots;
        if (!fits) {
            e.line = b.pointsLine;
            e.code = ErrorCode::WrongPointKind;
            e.message = info->definedByKnots
                            ? QStringLiteral("%1 curves are defined by knots; their control points follow from them")
                                  .arg(c.kind)
                            : QStringLiteral("%1 curves are defined by control points, not knots").arg(c.kind);
            return e;
        }
    }
    if (QLatin1String(info->id) == QLatin1String("composite") && b.record.pointKind != PointKind::Control) {
        // Knots of a composite curve: the seed's construction (docs/requirements.md 1.2) gives the handles.
        const int knots = static_cast<int>(c.points.size());
        if (knots < (c.closed ? 3 : 2) || knots > info->maxPoints) {
            e.code = ErrorCode::WrongPointCount;
            e.message = QStringLiteral("curve record: %1 knots; a%2 composite curve needs %3 to %4")
                            .arg(knots)
                            .arg(c.closed ? QStringLiteral(" closed") : QStringLiteral("n open"))
                            .arg(c.closed ? 3 : 2)
                            .arg(info->maxPoints);
            return e;
        }
        geo::CompositeCurve curve(c.points);
        if (c.closed) {
            if (auto closed = curve.close(); !closed) {
                e.code = ErrorCode::GeometryError;
                e.message = QString::fromStdString(closed.error().message);
                return e;
            }
        }
        std::vector<geo::Point> control = curve.controlPoints();
        if (c.closed)
            control.pop_back(); // the repeated first knot is not stored
        c.points = std::move(control);
    }
    if (QLatin1String(info->id) == QLatin1String("composite") && !b.hasNodes) {
        const int knots = compositeKnotCount(c.points.size(), c.closed);
        c.nodeTypes.assign(static_cast<std::size_t>(std::max(knots, 0)), QStringLiteral("smooth"));
    }
    if (const auto problem = validateCurve(c))
        return recordError(b, file, *problem);
    return std::move(b.record);
}

} // namespace

Result<std::vector<TextRecord>> parsePointsText(QByteArrayView bytes, const QString &file, const Limits &limits)
{
    std::string_view text(bytes.data(), static_cast<std::size_t>(bytes.size()));
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    if (!QUtf8StringView(text.data(), static_cast<qsizetype>(text.size())).isValidUtf8()) {
        Error e;
        e.code = ErrorCode::NotUtf8;
        e.file = file;
        e.message = QStringLiteral("the file is not UTF-8 text");
        return e;
    }
    std::vector<TextRecord> records;
    std::optional<Building> current;
    qint64 totalPoints = 0;
    const auto finish = [&]() -> std::optional<Error> {
        if (!current)
            return std::nullopt;
        auto done = finishRecord(std::move(*current), file);
        current.reset();
        if (!done)
            return done.error();
        // As stored: composite knots grew to their control vector (3n - 2 points), which is what a
        // document or a record Kontur writes holds, so the limit means the same in every format.
        totalPoints += static_cast<qint64>(done->curve.points.size());
        records.push_back(std::move(done).value());
        if (totalPoints > limits.maxPoints) {
            Error e;
            e.code = ErrorCode::TooManyPoints;
            e.file = file;
            e.line = records.back().line;
            e.message =
                QStringLiteral("more than %1 points, the most Kontur reads from one file").arg(limits.maxPoints);
            return e;
        }
        return std::nullopt;
    };
    const auto start = [&](int line) {
        current.emplace();
        current->record.line = line;
    };

    LineSplitter lines(text);
    std::string_view line;
    while (lines.next(line)) {
        const int lineNo = lines.number();
        LineParser p(line, lineNo, file);
        p.skipSpaces();
        if (p.atEnd())
            continue;
        if (!isLetter(line[p.pos()])) {
            if (!current)
                start(lineNo);
            auto pt = parsePointLine(p);
            if (!pt)
                return pt.error();
            // The finished records as stored plus this one's points so far: each point counted once
            // (the record's own count joins totalPoints only when it ends, as stored).
            if (totalPoints + static_cast<qint64>(current->record.curve.points.size()) >= limits.maxPoints)
                return p.error(
                    ErrorCode::TooManyPoints, 0,
                    QStringLiteral("more than %1 points, the most Kontur reads from one file").arg(limits.maxPoints));
            current->record.curve.points.push_back(*pt);
            continue;
        }
        if (isHeaderLine(line))
            continue;
        const std::size_t wordAt = p.pos();
        const std::string_view word = p.token(false);
        p.skipSpaces();
        const auto needValue = [&]() -> std::optional<Error> {
            if (p.atEnd())
                return p.error(ErrorCode::MissingValue, p.pos(),
                               QStringLiteral("\"%1\" needs a value")
                                   .arg(QString::fromLatin1(word.data(), static_cast<qsizetype>(word.size()))));
            return std::nullopt;
        };
        if (word == "curve") {
            if (auto err = finish())
                return *err;
            if (static_cast<qint64>(records.size()) >= limits.maxCurves)
                return p.error(
                    ErrorCode::TooManyCurves, 0,
                    QStringLiteral("more than %1 curves, the most Kontur reads from one file").arg(limits.maxCurves));
            start(lineNo);
            current->explicitCurve = true;
            // "curve" alone, or followed directly by a parameterization, starts a record of unknown kind.
            const std::size_t kindAt = p.pos();
            const std::string_view kind = p.token(false);
            const QString kindText = QString::fromLatin1(kind.data(), static_cast<qsizetype>(kind.size()));
            if (kind.empty() || isParameterizationName(kindText) || kindText == QLatin1String("closed") ||
                kindText == QLatin1String("open"))
                p.setPos(kindAt);
            for (const char c : kind) {
                if (p.pos() == kindAt)
                    break;
                if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
                    return p.error(
                        ErrorCode::UnknownKind, kindAt,
                        QStringLiteral("%1 is not a curve kind (lower-case letters, digits and '-')").arg(quote(kind)));
            }
            if (p.pos() != kindAt)
                current->record.curve.kind = kindText;
            if (!current->record.curve.kind.isEmpty() && !kindInfo(current->record.curve.kind)) {
                CurveRecord probe;
                probe.kind = current->record.curve.kind;
                return p.error(ErrorCode::UnknownKind, kindAt, validateCurve(probe)->message);
            }
            while (true) {
                p.skipSpaces();
                if (p.atEnd())
                    break;
                const std::size_t at = p.pos();
                const std::string_view w = p.token(false);
                const QString ws = QString::fromUtf8(w.data(), static_cast<qsizetype>(w.size()));
                if (ws == QLatin1String("closed"))
                    current->record.curve.closed = true;
                else if (ws == QLatin1String("open"))
                    current->record.curve.closed = false;
                else if (isParameterizationName(ws))
                    current->record.curve.parameterization = ws;
                else
                    return p.error(ErrorCode::UnknownParameterization, at,
                                   QStringLiteral("%1 is neither a parameterization (uniform, chord, centripetal) nor "
                                                  "\"closed\"")
                                       .arg(quote(w)));
            }
            continue;
        }
        if (!current)
            start(lineNo);
        CurveRecord &curve = current->record.curve;
        if (word == "name" || word == "color") {
            if (auto err = needValue())
                return *err;
            const std::size_t at = p.pos();
            QString value;
            if (line[at] == '"') {
                auto q = p.quoted();
                if (!q)
                    return q.error();
                value = *q;
            } else {
                const std::string_view v = p.token(false);
                value = QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size()));
            }
            p.skipSpaces();
            if (!p.atEnd())
                return p.error(ErrorCode::TrailingText, p.pos(),
                               QStringLiteral("unexpected text after the value (quote a value with spaces)"));
            if (word == "color") {
                if (!isColorName(value))
                    return p.error(ErrorCode::InvalidValue, at,
                                   QStringLiteral("colour %1 is not \"#rrggbb\"").arg(quote(value.toStdString())));
                curve.color = value.toLower();
            } else {
                curve.name = value;
            }
        } else if (word == "points") {
            if (auto err = needValue())
                return *err;
            const std::size_t at = p.pos();
            const std::string_view v = p.token(false);
            if (v == "knots")
                current->record.pointKind = PointKind::Knots;
            else if (v == "control")
                current->record.pointKind = PointKind::Control;
            else
                return p.error(ErrorCode::UnknownPointKind, at,
                               QStringLiteral("%1: the points are \"knots\" or \"control\"").arg(quote(v)));
            current->pointsLine = lineNo;
            p.skipSpaces();
            if (!p.atEnd())
                return p.error(ErrorCode::TrailingText, p.pos(),
                               QStringLiteral("unexpected text after the point kind"));
        } else if (word == "nodes") {
            if (auto err = needValue())
                return *err;
            current->hasNodes = true;
            current->nodesLine = lineNo;
            while (!p.atEnd()) {
                const std::size_t at = p.pos();
                const std::string_view v = p.token(false);
                const QString type = QString::fromLatin1(v.data(), static_cast<qsizetype>(v.size()));
                if (!isNodeTypeName(type))
                    return p.error(ErrorCode::UnknownNodeType, at,
                                   QStringLiteral("%1 is not a node type (smooth, symmetric or corner)").arg(quote(v)));
                if (static_cast<qint64>(curve.nodeTypes.size()) >= limits.maxPoints)
                    return p.error(ErrorCode::TooManyPoints, at,
                                   QStringLiteral("more node types than points Kontur reads"));
                curve.nodeTypes.push_back(type);
                p.skipSpaces();
            }
        } else if (word == "settings") {
            if (auto err = needValue())
                return *err;
            // The rest of the line is a JSON object (no comment on this line: '#' may be in a string).
            const std::string_view json = line.substr(p.pos());
            if (json.size() > 64 * 1024)
                return p.error(ErrorCode::InvalidValue, p.pos(), QStringLiteral("the settings are longer than 64 KiB"));
            QJsonParseError perr;
            const QJsonDocument doc =
                QJsonDocument::fromJson(QByteArray(json.data(), static_cast<qsizetype>(json.size())), &perr);
            if (perr.error != QJsonParseError::NoError || !doc.isObject())
                return p.error(ErrorCode::JsonSyntax,
                               p.pos() +
                                   (perr.error != QJsonParseError::NoError ? static_cast<std::size_t>(perr.offset) : 0),
                               QStringLiteral("the settings are not a JSON object (%1)")
                                   .arg(perr.error != QJsonParseError::NoError ? perr.errorString()
                                                                               : QStringLiteral("not an object")));
            curve.settings = doc.object();
        } else {
            return p.error(ErrorCode::UnknownDirective, wordAt,
                           QStringLiteral("%1 is not a point or a directive (curve, name, color, points, nodes, "
                                          "settings)")
                               .arg(quote(word)));
        }
    }
    if (auto err = finish())
        return *err;
    if (records.empty()) {
        Error e;
        e.code = ErrorCode::NoPoints;
        e.file = file;
        e.line = lines.number() > 0 ? lines.number() : 1;
        e.message = QStringLiteral("the file holds no points");
        return e;
    }
    return records;
}

Result<CurveRecord> curveFromPoints(const QString &kind, const QString &parameterization,
                                    std::vector<geo::Point> points, PointKind pointKind, bool closed)
{
    Building b;
    b.record.curve.kind = kind;
    b.record.curve.parameterization = parameterization;
    b.record.curve.points = std::move(points);
    b.record.curve.closed = closed;
    b.record.pointKind = pointKind;
    if (kind.isEmpty() || !kindInfo(kind)) {
        CurveRecord probe;
        probe.kind = kind;
        Error e;
        e.code = ErrorCode::UnknownKind;
        e.message = validateCurve(probe)->message;
        return e;
    }
    auto done = finishRecord(std::move(b), {});
    if (!done)
        return done.error();
    return std::move(done->curve);
}

Result<std::vector<TextRecord>> readPointsText(const QString &path, const Limits &limits)
{
    auto bytes = readFileBytes(path, limits);
    if (!bytes)
        return bytes.error();
    return parsePointsText(*bytes, path, limits);
}

QByteArray formatPointsRecord(const CurveRecord &curve, std::span<const geo::Point> derivedControl)
{
    const auto quoted = [](const QString &s) {
        QByteArray out = "\"";
        for (const char c : s.toUtf8()) {
            if (c == '"' || c == '\\')
                out += '\\';
            out += (c == '\n' || c == '\r') ? ' ' : c;
        }
        return out + '"';
    };
    const KindInfo *info = kindInfo(curve.kind);
    QByteArray out = "# Kontur curve record\n";
    {
        // Always a "curve" line, so that a record of unknown kind does not run into the one before.
        out += "curve";
        if (!curve.kind.isEmpty())
            out += ' ' + curve.kind.toUtf8();
        if (!curve.parameterization.isEmpty())
            out += ' ' + curve.parameterization.toUtf8();
        if (curve.closed)
            out += " closed";
        out += '\n';
    }
    if (!curve.name.isEmpty())
        out += "name " + quoted(curve.name) + '\n';
    if (!curve.kind.isEmpty())
        out += "color " + quoted(curve.color.toLower()) + '\n';
    if (!curve.nodeTypes.empty()) {
        out += "nodes";
        for (const QString &t : curve.nodeTypes)
            out += ' ' + t.toLatin1();
        out += '\n';
    }
    if (!curve.settings.isEmpty())
        out += "settings " + QJsonDocument(curve.settings).toJson(QJsonDocument::Compact) + '\n';
    if (info)
        out += info->definedByKnots ? "points knots\n" : "points control\n";
    for (const geo::Point &p : curve.points) {
        appendDouble(out, p.x());
        out += ' ';
        appendDouble(out, p.y());
        out += '\n';
    }
    if (!derivedControl.empty()) {
        out += "# control points that follow from the knots (for reference; not read back):\n";
        for (std::size_t i = 0; i < derivedControl.size(); ++i) {
            out += "#   C" + QByteArray::number(static_cast<qulonglong>(i)) + ' ';
            appendDouble(out, derivedControl[i].x());
            out += ' ';
            appendDouble(out, derivedControl[i].y());
            out += '\n';
        }
    }
    return out;
}

Result<Ok> appendPointsRecord(const QString &path, const CurveRecord &curve, std::span<const geo::Point> derivedControl,
                              const Limits &limits)
{
    if (!curve.kind.isEmpty()) {
        if (const auto problem = validateCurve(curve)) {
            Error e;
            e.code = problem->code;
            e.file = path;
            e.message = QStringLiteral("the curve cannot be written: ") + problem->message;
            return e;
        }
    }
    Error e;
    e.file = path;
    if (static_cast<qint64>(curve.points.size()) > limits.maxPoints) {
        e.code = ErrorCode::TooManyPoints;
        e.message = QStringLiteral("the curve cannot be written: %1 points; a file holds at most %2")
                        .arg(curve.points.size())
                        .arg(limits.maxPoints);
        return e;
    }
    const NonFiniteWatch watch;
    QByteArray bytes = formatPointsRecord(curve, derivedControl);
    if (watch.seen())
        return NonFiniteWatch::error(path, QStringLiteral("the curve"));
    // A blank line between records, for the human reader.
    const qint64 existing = QFileInfo(path).size();
    if (existing > 0)
        bytes.prepend('\n');
    // What the file already holds is not parsed again on every append; its size is the cheap bound.
    if (existing + bytes.size() > limits.maxFileBytes) {
        e.code = ErrorCode::FileTooLarge;
        e.message = QStringLiteral("the curve cannot be written: the file would be larger than %1 bytes, the most "
                                   "Kontur reads")
                        .arg(limits.maxFileBytes);
        return e;
    }
    // The reader counts the points and records of the whole file: what is there already counts too,
    // so no append makes a file Kontur then refuses to open. A file that cannot be read as points
    // text now is not made worse by a record more, and is appended to as before.
    if (existing > 0) {
        if (auto old = readFileBytes(path, limits); old.ok()) {
            if (auto records = parsePointsText(*old, path, limits); records.ok()) {
                qint64 points = 0;
                for (const TextRecord &r : *records)
                    points += static_cast<qint64>(r.curve.points.size());
                // The new record as it will be read back: a composite curve by its stored points.
                points += static_cast<qint64>(curve.points.size());
                if (points > limits.maxPoints) {
                    e.code = ErrorCode::TooManyPoints;
                    e.message = QStringLiteral("the curve cannot be written: the file would hold %1 points; a "
                                               "file holds at most %2")
                                    .arg(points)
                                    .arg(limits.maxPoints);
                    return e;
                }
                if (static_cast<qint64>(records->size()) + 1 > limits.maxCurves) {
                    e.code = ErrorCode::TooManyCurves;
                    e.message = QStringLiteral("the curve cannot be written: a file holds at most %1 curves")
                                    .arg(limits.maxCurves);
                    return e;
                }
            }
        }
    }
    return appendToFile(path, bytes);
}

} // namespace kontur::io
