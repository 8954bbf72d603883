// The JSON writer of kontur-cli (see json.h).
#include "cli/json.h"

#include <charconv>
#include <cmath>

namespace kontur::cli {

std::string formatDouble(double v)
{
    if (!std::isfinite(v))
        return "null";
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

void Json::separate()
{
    if (m_needComma)
        m_out += ',';
    m_needComma = true;
}

Json &Json::open(char bracket)
{
    separate();
    m_out += bracket;
    m_needComma = false;
    return *this;
}

Json &Json::close(char bracket)
{
    m_out += bracket;
    m_needComma = true;
    return *this;
}

Json &Json::beginObject()
{
    return open('{');
}

Json &Json::endObject()
{
    return close('}');
}

Json &Json::beginArray()
{
    return open('[');
}

Json &Json::endArray()
{
    return close(']');
}

Json &Json::key(std::string_view name)
{
    separate();
    m_lastKey = name;
    m_out += '"';
    m_out += name;
    m_out += "\":";
    m_needComma = false;
    return *this;
}

Json &Json::value(double v)
{
    if (!std::isfinite(v) && m_nonFiniteKey.empty())
        m_nonFiniteKey = m_lastKey.empty() ? std::string("value") : m_lastKey;
    separate();
    m_out += formatDouble(v);
    return *this;
}

Json &Json::value(long long v)
{
    separate();
    m_out += std::to_string(v);
    return *this;
}

Json &Json::value(bool v)
{
    separate();
    m_out += v ? "true" : "false";
    return *this;
}

Json &Json::value(std::string_view s)
{
    separate();
    m_out += '"';
    for (char c : s) {
        if (c == '"' || c == '\\') {
            m_out += '\\';
            m_out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            static const char hex[] = "0123456789abcdef";
            m_out += "\\u00";
            m_out += hex[(c >> 4) & 0xf];
            m_out += hex[c & 0xf];
        } else {
            m_out += c;
        }
    }
    m_out += '"';
    return *this;
}

Json &Json::point(const geo::Point &p)
{
    beginArray();
    value(p.x());
    value(p.y());
    return endArray();
}

Json &Json::points(std::span<const geo::Point> pts)
{
    beginArray();
    for (const geo::Point &p : pts)
        point(p);
    return endArray();
}

Json &Json::numbers(std::span<const double> values)
{
    beginArray();
    for (double v : values)
        value(v);
    return endArray();
}

} // namespace kontur::cli
