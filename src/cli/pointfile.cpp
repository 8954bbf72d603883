// Point list files for kontur-cli (see pointfile.h).
#include "cli/pointfile.h"

#include "io/fileio.h"
#include "io/pointstext.h"

#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace kontur::cli {

std::optional<double> parseNumber(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    if (!s.empty() && s.front() == '+') // from_chars does not take a leading '+'
        s.remove_prefix(1);
    if (s.empty())
        return std::nullopt;
    double v = 0.0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<std::vector<double>> parseNumberList(std::string_view s)
{
    std::vector<double> out;
    while (true) {
        const std::size_t comma = s.find(',');
        const auto v = parseNumber(s.substr(0, comma));
        if (!v)
            return std::nullopt;
        out.push_back(*v);
        if (comma == std::string_view::npos)
            break;
        s.remove_prefix(comma + 1);
    }
    return out;
}

PointFile parsePoints(std::string_view text, const QString &name)
{
    PointFile result;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t eol = text.find('\n', pos);
        std::string_view line = text.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
        pos = eol == std::string_view::npos ? text.size() + 1 : eol + 1;
        ++lineNo;
        const std::string_view original = line;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        // Tokens split at blanks, tabs, a comma or a semicolon; a carriage return ends the line.
        std::vector<std::string_view> tokens;
        std::size_t start = 0;
        auto isSep = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; };
        for (std::size_t i = 0; i <= line.size(); ++i) {
            if (i == line.size() || isSep(line[i])) {
                if (i > start)
                    tokens.push_back(line.substr(start, i - start));
                start = i + 1;
            }
        }
        if (tokens.empty())
            continue;
        std::optional<double> x, y;
        if (tokens.size() == 2) {
            x = parseNumber(tokens[0]);
            y = parseNumber(tokens[1]);
        }
        if (!x || !y) {
            std::string_view shown = original;
            if (!shown.empty() && shown.back() == '\r')
                shown.remove_suffix(1);
            result.error = QCoreApplication::translate("kontur::cli", "%1:%2: expected two numbers \"x y\", got \"%3\"")
                               .arg(name)
                               .arg(lineNo)
                               .arg(QString::fromUtf8(shown.data(), static_cast<qsizetype>(shown.size())));
            result.points.clear();
            return result;
        }
        result.points.emplace_back(*x, *y);
    }
    return result;
}

namespace {

// Whether the text holds Kontur's curve records (a line that starts with the word "curve"), as the
// app appends them; a hand-written list has none.
bool hasCurveRecords(std::string_view text)
{
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t eol = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, eol - pos);
        pos = eol + 1;
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t' || line.front() == '\xef' ||
                                 line.front() == '\xbb' || line.front() == '\xbf')) // blanks, a byte order mark
            line.remove_prefix(1);
        if (line.starts_with("curve") && (line.size() == 5 || line[5] == ' ' || line[5] == '\t' || line[5] == '\r'))
            return true;
    }
    return false;
}

// The points a curve record stands for: a composite curve's knots (every third point of its control
// vector), any other kind's defining points (a Bézier curve's control points, a spline's points).
std::vector<geo::Point> pointsOf(const io::CurveRecord &curve)
{
    if (curve.kind != QLatin1String("composite"))
        return curve.points;
    std::vector<geo::Point> knots;
    for (std::size_t i = 0; i < curve.points.size(); i += 3)
        knots.push_back(curve.points[i]);
    return knots;
}

// Why a file could not be read, in the user's language: what the path is when it is no regular file.
QString whyNotRead(const QString &path, const io::Error &error)
{
    switch (io::fileKindOf(path)) {
    case io::FileKind::Missing:
    case io::FileKind::DanglingLink:
        return QCoreApplication::translate("kontur::cli", "no such file");
    case io::FileKind::LinkLoop:
        return QCoreApplication::translate("kontur::cli", "its symbolic links form a loop");
    case io::FileKind::NoPermission:
        return QCoreApplication::translate("kontur::cli", "permission denied");
    case io::FileKind::Folder:
        return QCoreApplication::translate("kontur::cli", "it is a folder, not a file");
    case io::FileKind::Pipe:
        return QCoreApplication::translate("kontur::cli", "it is a named pipe (FIFO), not a regular file");
    case io::FileKind::Device:
        return QCoreApplication::translate("kontur::cli", "it is a device, not a regular file");
    case io::FileKind::Other:
        return QCoreApplication::translate("kontur::cli", "it is not a regular file");
    case io::FileKind::Regular:
        break;
    }
    return error.message; // too large, or a read error: the file layer's English detail
}

} // namespace

PointFile readPointFile(const QString &path)
{
    // Bounded, and refused before opening when it is no regular file (a FIFO would block, /dev/zero
    // never end): io::readFileBytes.
    const auto bytes = io::readFileBytes(path);
    if (!bytes) {
        PointFile result;
        result.path = path;
        result.error = QCoreApplication::translate("kontur::cli", "%1: cannot read the file: %2")
                           .arg(path, whyNotRead(path, bytes.error()));
        return result;
    }
    const QByteArray &data = *bytes;
    const std::string_view text(data.constData(), static_cast<std::size_t>(data.size()));
    if (!hasCurveRecords(text)) {
        PointFile result = parsePoints(text, path);
        result.path = path;
        return result;
    }
    // The records the app writes, read by the app's own reader (io/pointstext): the points of the
    // first record; the others are named on stderr, never dropped silently.
    PointFile result;
    result.path = path;
    const auto records = io::parsePointsText(data, path);
    if (!records) {
        io::Error e = records.error();
        if (e.file.isEmpty())
            e.file = path;
        result.error = e.toString();
        return result;
    }
    result.points = pointsOf(records->front().curve);
    result.records = static_cast<int>(records->size());
    result.recordLine = records->front().line;
    if (result.records > 1)
        QTextStream(stderr) << "kontur-cli: "
                            << QCoreApplication::translate(
                                   "kontur::cli",
                                   "%1: several curves in the file (%2); the points of the first one (line %3) are read")
                                   .arg(path)
                                   .arg(result.records)
                                   .arg(result.recordLine)
                            << '\n';
    return result;
}

} // namespace kontur::cli
