// The .kontur document's fast scanner (see document_p.h): one pass over the text before Qt's JSON
// parser that refuses too deep nesting and too many curves early and reads each curve's points and
// node types straight from the text.
#include "io/document_p.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace kontur::io::documentjson {

namespace {

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

} // namespace

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

} // namespace kontur::io::documentjson
