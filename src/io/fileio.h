// Reading and writing whole files for the formats: bounded reads (Limits::maxFileBytes), atomic
// replacement through QSaveFile (a failed write leaves the old file intact), appending that never
// truncates (the points text format, seed T09), and the locale-independent number text they share.
#pragma once

#include "io/error.h"
#include "io/limits.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kontur::io {

// What a path names, asked without opening it (opening a FIFO waits for a writer, a device such as
// /dev/zero never ends).
enum class FileKind { Regular, Missing, DanglingLink, LinkLoop, NoPermission, Folder, Pipe, Device, Other };
[[nodiscard]] FileKind fileKindOf(const QString &path);
// Why `path` cannot be read as a file, asked before it is opened: no such file, a loop of symbolic
// links, a folder, a named pipe or a device (which would block or never end); nullopt for a regular
// file. readFileBytes asks it first.
[[nodiscard]] std::optional<Error> notARegularFile(const QString &path);
// The whole file, or CannotOpen / FileTooLarge.
[[nodiscard]] Result<QByteArray> readFileBytes(const QString &path, const Limits &limits = {});
// Writes `bytes` to a temporary file beside `path` and renames it over `path` only when every
// byte is on disk (QSaveFile, which syncs the file before the rename; the folder is synced after
// it); on failure the old file is unchanged.
[[nodiscard]] Result<Ok> writeFileAtomically(const QString &path, const QByteArray &bytes);
// Appends `bytes` at the end of `path` (created if missing): the old text and `bytes` are written to
// a new file renamed over the old one (writeFileAtomically), so a writer killed halfway leaves the
// old file or the new one whole. What the file held is never truncated. When it does not end with a
// line break, one is added first.
[[nodiscard]] Result<Ok> appendToFile(const QString &path, const QByteArray &bytes);
// Syncs the folder holding `path` to disk (its entries: a rename is durable only then); POSIX only,
// a no-op elsewhere. writeFileAtomically calls it after the rename.
void syncFolderOf(const QString &path);

// Whether a non-finite number was formatted (formatDouble, appendDouble, formatDoubleTo) on this
// thread since the watch began. A writer builds its text inside one and refuses to write it when one
// was: a derived value (a drawing's width, a circle's radius, a scale) can overflow to inf where
// every coordinate is finite, and "inf" in a file is no number any reader takes.
class NonFiniteWatch final
{
public:
    NonFiniteWatch();
    [[nodiscard]] bool seen() const;
    // NumberOutOfRange for `path`: "<what> cannot be written: a value derived from its coordinates
    // (a size, a radius) passes the largest number".
    [[nodiscard]] static Error error(const QString &path, const QString &what);

private:
    std::uint64_t m_start;
};

// The shortest text that reads back to the same double (std::to_chars; C locale by construction).
// -0 is written as 0, so that save → open → save is byte-identical. Non-finite values give "nan"/"inf"
// (callers validate before writing).
[[nodiscard]] std::string formatDouble(double v);
void appendDouble(QByteArray &out, double v);
// Writes formatDouble(v) at `out` (room for 24 characters) and returns the end.
char *formatDoubleTo(char *out, double v);
// A whole token as a finite double: optional sign ('+' too), digits with an optional '.', optional
// exponent. nullopt for anything else (a decimal comma, "inf", "nan", hex, out of range).
enum class NumberStatus { Ok, Malformed, OutOfRange };
[[nodiscard]] NumberStatus parseDouble(std::string_view text, double &out);
// The length of the longest number at the start of `text`: sign? (digits ('.' digits?)? | '.' digits)
// exponent?, an exponent only with its digits ("1e" is the number 1 and an 'e'); 0 if none.
[[nodiscard]] std::size_t numberLength(std::string_view text);

// The lines of a text one by one, without their "\n" or "\r\n", numbered from 1.
class LineSplitter final
{
public:
    explicit LineSplitter(std::string_view text)
        : m_text(text)
    {
    }
    // The next line, or false at the end of the text.
    bool next(std::string_view &line)
    {
        if (m_pos >= m_text.size())
            return false;
        std::size_t eol = m_text.find('\n', m_pos);
        if (eol == std::string_view::npos)
            eol = m_text.size();
        line = m_text.substr(m_pos, eol - m_pos);
        m_pos = eol + 1;
        ++m_number;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        return true;
    }
    // The number of the line last returned (0 before the first).
    [[nodiscard]] int number() const { return m_number; }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_number = 0;
};

// 1-based line and column (in code points) of a byte offset in UTF-8 text.
struct TextPosition
{
    int line = 1;
    int column = 1;
};
[[nodiscard]] TextPosition positionOf(std::string_view text, std::size_t offset);
// Number of UTF-8 code points in text (for columns).
[[nodiscard]] int codePointCount(std::string_view text);

} // namespace kontur::io
