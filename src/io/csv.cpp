// CSV points (see csv.h).
#include "io/csv.h"

#include "io/fileio.h"

#include <cmath>
#include <string>
#include <string_view>

namespace kontur::io {

namespace {

struct Field
{
    std::string text;
    std::size_t at = 0; // byte offset in the line, for the column of errors
};

bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

// Splits one line at `sep`; a field may be double-quoted with "" for a quote inside. Blanks around
// fields are dropped (unless the separator is a tab). Returns the offset of an unterminated quote.
std::optional<std::size_t> splitLine(std::string_view line, char sep, std::vector<Field> &out)
{
    out.clear();
    std::size_t i = 0;
    while (true) {
        Field f;
        while (i < line.size() && isBlank(line[i]) && line[i] != sep)
            ++i;
        f.at = i;
        if (i < line.size() && line[i] == '"') {
            const std::size_t open = i++;
            while (true) {
                if (i >= line.size())
                    return open;
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        f.text += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                f.text += line[i++];
            }
            while (i < line.size() && isBlank(line[i]) && line[i] != sep)
                ++i;
            // Text between a closing quote and the separator stays in the field, and fails as a number.
            while (i < line.size() && line[i] != sep)
                f.text += line[i++];
        } else {
            while (i < line.size() && line[i] != sep)
                f.text += line[i++];
            while (!f.text.empty() && isBlank(f.text.back()) && f.text.back() != sep)
                f.text.pop_back();
        }
        out.push_back(std::move(f));
        if (i >= line.size())
            return std::nullopt;
        ++i; // the separator
    }
}

} // namespace

Result<std::vector<geo::Point>> parseCsvPoints(QByteArrayView bytes, const QString &file, const Limits &limits)
{
    std::string_view text(bytes.data(), static_cast<std::size_t>(bytes.size()));
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    const auto error = [&](ErrorCode code, int line, std::string_view lineText, std::size_t at,
                           const QString &message) {
        Error e;
        e.code = code;
        e.file = file;
        e.line = line;
        e.column =
            line > 0 && !lineText.empty() ? codePointCount(lineText.substr(0, std::min(at, lineText.size()))) + 1 : 0;
        e.message = message;
        return e;
    };
    if (!QUtf8StringView(text.data(), static_cast<qsizetype>(text.size())).isValidUtf8())
        return error(ErrorCode::NotUtf8, 0, {}, 0, QStringLiteral("the file is not UTF-8 text"));

    std::vector<geo::Point> points;
    std::vector<Field> fields;
    char sep = 0;
    LineSplitter lines(text);
    std::string_view line;
    while (lines.next(line)) {
        const int lineNo = lines.number();
        if (line.find_first_not_of(" \t") == std::string_view::npos)
            continue;
        if (sep == 0) {
            // The header decides the separator: the first of ',', ';', tab that splits it into x and y.
            for (const char candidate : {',', ';', '\t'}) {
                if (const auto open = splitLine(line, candidate, fields))
                    return error(ErrorCode::UnterminatedString, lineNo, line, *open,
                                 QStringLiteral("the quoted field has no closing quote"));
                if (fields.size() == 2) {
                    std::string x = fields[0].text, y = fields[1].text;
                    for (char &c : x)
                        c = static_cast<char>(c | 0x20);
                    for (char &c : y)
                        c = static_cast<char>(c | 0x20);
                    if (x == "x" && y == "y") {
                        sep = candidate;
                        break;
                    }
                }
            }
            if (sep == 0)
                return error(ErrorCode::MissingHeader, lineNo, line, 0,
                             QStringLiteral("the first row must be the header x,y"));
            continue;
        }
        if (const auto open = splitLine(line, sep, fields))
            return error(ErrorCode::UnterminatedString, lineNo, line, *open,
                         QStringLiteral("the quoted field has no closing quote"));
        if (fields.size() != 2)
            return error(ErrorCode::WrongFieldCount, lineNo, line, fields.size() > 2 ? fields[2].at : line.size(),
                         QStringLiteral("a row holds two fields, x and y; this one has %1").arg(fields.size()));
        geo::Point p;
        for (int c = 0; c < 2; ++c) {
            const std::string &t = fields[static_cast<std::size_t>(c)].text;
            const std::size_t at = fields[static_cast<std::size_t>(c)].at;
            switch (parseDouble(t, p[c])) {
            case NumberStatus::Ok:
                break;
            case NumberStatus::OutOfRange:
                return error(ErrorCode::NumberOutOfRange, lineNo, line, at,
                             QStringLiteral("\"%1\" is not a finite number").arg(QString::fromStdString(t)));
            case NumberStatus::Malformed:
                return error(ErrorCode::ExpectedNumber, lineNo, line, at,
                             t.empty() ? QStringLiteral("expected a number")
                                       : QStringLiteral("expected a number (with a decimal point), found \"%1\"")
                                             .arg(QString::fromStdString(t)));
            }
        }
        if (static_cast<qint64>(points.size()) >= limits.maxPoints)
            return error(
                ErrorCode::TooManyPoints, lineNo, line, 0,
                QStringLiteral("more than %1 points, the most Kontur reads from one file").arg(limits.maxPoints));
        points.push_back(p);
    }
    if (sep == 0)
        return error(ErrorCode::MissingHeader, lines.number() > 0 ? lines.number() : 1, {}, 0,
                     QStringLiteral("the file is empty: expected the header x,y"));
    if (points.empty())
        return error(ErrorCode::NoPoints, lines.number(), {}, 0, QStringLiteral("the file holds no points"));
    return points;
}

Result<std::vector<geo::Point>> readCsvPoints(const QString &path, const Limits &limits)
{
    auto bytes = readFileBytes(path, limits);
    if (!bytes)
        return bytes.error();
    return parseCsvPoints(*bytes, path, limits);
}

QByteArray formatCsvPoints(std::span<const geo::Point> points)
{
    QByteArray out = "x,y\n";
    for (const geo::Point &p : points) {
        appendDouble(out, p.x());
        out += ',';
        appendDouble(out, p.y());
        out += '\n';
    }
    return out;
}

Result<Ok> writeCsvPoints(const QString &path, std::span<const geo::Point> points, const Limits &limits)
{
    // Never a file the reader refuses (its rows are far shorter than limits.maxFileBytes allows per point).
    if (static_cast<qint64>(points.size()) > limits.maxPoints) {
        Error e;
        e.code = ErrorCode::TooManyPoints;
        e.file = path;
        e.message = QStringLiteral("the points cannot be written: %1 points; a file holds at most %2")
                        .arg(points.size())
                        .arg(limits.maxPoints);
        return e;
    }
    for (const geo::Point &p : points)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
            Error e;
            e.code = ErrorCode::NumberOutOfRange;
            e.file = path;
            e.message = QStringLiteral("the points cannot be written: a coordinate is not a finite number");
            return e;
        }
    const NonFiniteWatch watch;
    const QByteArray bytes = formatCsvPoints(points);
    if (watch.seen())
        return NonFiniteWatch::error(path, QStringLiteral("the points"));
    return writeFileAtomically(path, bytes);
}

} // namespace kontur::io
