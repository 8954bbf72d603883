// A minimal JSON writer for kontur-cli: numbers in the shortest form that reads back to the same
// double (std::to_chars, independent of the locale), so scripts and tests can compare exactly.
#pragma once

#include "geometry/bezier.h"

#include <span>
#include <string>
#include <string_view>

namespace kontur::cli {

class Json final
{
public:
    Json &beginObject();
    Json &endObject();
    Json &beginArray();
    Json &endArray();
    Json &key(std::string_view name);
    Json &value(double v);
    Json &value(long long v);
    Json &value(int v) { return value(static_cast<long long>(v)); }
    Json &value(bool v);
    Json &value(std::string_view s);
    Json &value(const char *s) { return value(std::string_view(s)); }
    Json &point(const geo::Point &p);
    Json &points(std::span<const geo::Point> pts);
    Json &numbers(std::span<const double> values);

    [[nodiscard]] const std::string &str() const { return m_out; }
    // Whether every number written was finite; if not, the key of the first one that was not. JSON
    // has no NaN or infinity, and a null where a number belongs is a wrong answer that looks right:
    // a command prints nothing then, and says so (printResult in output.h).
    [[nodiscard]] bool finite() const { return m_nonFiniteKey.empty(); }
    [[nodiscard]] const std::string &nonFiniteKey() const { return m_nonFiniteKey; }

private:
    void separate();
    // Starts an object or array (after a comma where one is due), or ends one.
    Json &open(char bracket);
    Json &close(char bracket);
    std::string m_out;
    std::string m_lastKey;
    std::string m_nonFiniteKey;
    bool m_needComma = false;
};

// The shortest round-trip text of a double; "null" for NaN and infinities (JSON has no such numbers;
// Json::finite() tells when one was written).
[[nodiscard]] std::string formatDouble(double v);

} // namespace kontur::cli
