// Bounded reads, atomic writes, appends and number text (see fileio.h).
#include "io/fileio.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <algorithm>
#include <charconv>
#include <cmath>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace kontur::io {

namespace {

Error fileError(ErrorCode code, const QString &path, const QString &message)
{
    Error e;
    e.code = code;
    e.file = path;
    e.message = message;
    return e;
}

} // namespace

namespace {
thread_local std::uint64_t t_nonFinite = 0;
// Counts a non-finite value about to be formatted (NonFiniteWatch).
inline void note(double v)
{
    if (!std::isfinite(v))
        ++t_nonFinite;
}
} // namespace

NonFiniteWatch::NonFiniteWatch()
    : m_start(t_nonFinite)
{
}

bool NonFiniteWatch::seen() const
{
    return t_nonFinite != m_start;
}

Error NonFiniteWatch::error(const QString &path, const QString &what)
{
    return fileError(ErrorCode::NumberOutOfRange, path,
                     QStringLiteral("%1 cannot be written: a value derived from its coordinates (a size, a radius) "
                                    "passes the largest number")
                         .arg(what));
}

void syncFolderOf(const QString &path)
{
#ifdef Q_OS_UNIX
    // The rename is an entry of the folder: until the folder is synced too, a power cut can bring
    // back the old file (fsync(2), "calling fsync() does not necessarily ensure that the entry in
    // the directory containing the file has also reached disk").
    const QByteArray folder = QFile::encodeName(QFileInfo(path).absolutePath());
    const int fd = ::open(folder.constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        (void)::fsync(fd);
        ::close(fd);
    }
#else
    Q_UNUSED(path)
#endif
}

FileKind fileKindOf(const QString &path)
{
#ifdef Q_OS_UNIX
    // stat(2), not QFileInfo: it tells a loop of symbolic links (ELOOP) from a missing file, and
    // opening is never needed (opening a FIFO waits for a writer).
    struct stat st = {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0) {
        switch (errno) {
        case ELOOP:
            return FileKind::LinkLoop;
        case EACCES:
            return FileKind::NoPermission;
        case ENOTDIR:
            return FileKind::Missing;
        default:
            return QFileInfo(path).isSymLink() ? FileKind::DanglingLink : FileKind::Missing;
        }
    }
    if (S_ISDIR(st.st_mode))
        return FileKind::Folder;
    if (S_ISFIFO(st.st_mode))
        return FileKind::Pipe;
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        return FileKind::Device;
    return S_ISREG(st.st_mode) ? FileKind::Regular : FileKind::Other;
#else
    const QFileInfo info(path);
    if (!info.exists())
        return info.isSymLink() ? FileKind::DanglingLink : FileKind::Missing;
    if (info.isDir())
        return FileKind::Folder;
    return info.isFile() ? FileKind::Regular : FileKind::Other;
#endif
}

std::optional<Error> notARegularFile(const QString &path)
{
    QString why;
    switch (fileKindOf(path)) {
    case FileKind::Regular:
        return std::nullopt;
    case FileKind::Missing:
        why = QStringLiteral("no such file");
        break;
    case FileKind::DanglingLink:
        why = QStringLiteral("a symbolic link to a file that does not exist");
        break;
    case FileKind::LinkLoop:
        why = QStringLiteral("a loop of symbolic links");
        break;
    case FileKind::NoPermission:
        why = QStringLiteral("permission denied");
        break;
    case FileKind::Folder:
        why = QStringLiteral("it is a folder, not a file");
        break;
    case FileKind::Pipe:
        why = QStringLiteral("it is a named pipe (FIFO), not a regular file");
        break;
    case FileKind::Device:
        why = QStringLiteral("it is a device, not a regular file");
        break;
    case FileKind::Other:
        why = QStringLiteral("it is not a regular file");
        break;
    }
    return fileError(ErrorCode::CannotOpen, path, QStringLiteral("cannot read the file (%1)").arg(why));
}

Result<QByteArray> readFileBytes(const QString &path, const Limits &limits)
{
    if (auto refused = notARegularFile(path))
        return *refused;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fileError(ErrorCode::CannotOpen, path,
                         QStringLiteral("cannot read the file (%1)").arg(file.errorString()));
    const auto tooLarge = [&] {
        return fileError(
            ErrorCode::FileTooLarge, path,
            QStringLiteral("the file is larger than %1 bytes, the most Kontur reads").arg(limits.maxFileBytes));
    };
    if (!file.isSequential() && file.size() > limits.maxFileBytes)
        return tooLarge();
    // Read at most one byte more than allowed, so a file that grows (or a pipe) cannot take more.
    QByteArray bytes = file.read(limits.maxFileBytes + 1);
    if (bytes.size() > limits.maxFileBytes)
        return tooLarge();
    if (file.error() != QFileDevice::NoError)
        return fileError(ErrorCode::CannotOpen, path,
                         QStringLiteral("cannot read the file (%1)").arg(file.errorString()));
    return bytes;
}

Result<Ok> writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fileError(ErrorCode::CannotWrite, path,
                         QStringLiteral("cannot write the file (%1)").arg(file.errorString()));
    if (file.write(bytes) != bytes.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return fileError(ErrorCode::CannotWrite, path, QStringLiteral("cannot write the file (%1)").arg(why));
    }
    // commit() flushes the file to disk (fdatasync) before it renames it over the old one.
    if (!file.commit())
        return fileError(ErrorCode::CannotWrite, path,
                         QStringLiteral("cannot write the file (%1)").arg(file.errorString()));
    syncFolderOf(path);
    return Ok{};
}

Result<Ok> appendToFile(const QString &path, const QByteArray &bytes)
{
    // The old text and the new record go to a new file that is renamed over the old one
    // (writeFileAtomically), never written in place: a writer killed halfway (kill -9, a power cut)
    // leaves the old file or the new one, never a partial record that would make the whole file
    // unreadable. Nothing is ever truncated: the old text is the new file's beginning (seed T09).
    const auto cannot = [&path](const QString &why) {
        return fileError(ErrorCode::CannotWrite, path, QStringLiteral("cannot append to the file (%1)").arg(why));
    };
    QByteArray out;
    const QFileInfo info(path);
    if (info.isDir())
        return cannot(QStringLiteral("it is a folder"));
    if (info.exists() && !info.isFile()) // a named pipe or a device: reading it would block or never end
        return cannot(QStringLiteral("it is not a regular file"));
    if (info.exists()) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return cannot(file.errorString());
        out = file.readAll();
        if (file.error() != QFileDevice::NoError)
            return cannot(file.errorString());
        // A record must start on a line of its own.
        if (!out.isEmpty() && !out.endsWith('\n'))
            out += '\n';
    }
    out += bytes;
    if (auto written = writeFileAtomically(path, out); !written.ok())
        return cannot(written.error().message);
    return Ok{};
}

std::string formatDouble(double v)
{
    note(v);
    if (v == 0.0)
        v = 0.0; // -0 → 0
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

char *formatDoubleTo(char *out, double v)
{
    note(v);
    if (v == 0.0)
        v = 0.0;
    return std::to_chars(out, out + 24, v).ptr;
}

void appendDouble(QByteArray &out, double v)
{
    note(v);
    if (v == 0.0)
        v = 0.0;
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, res.ptr - buf);
}

std::size_t numberLength(std::string_view s)
{
    const auto digitsFrom = [&s](std::size_t i) {
        std::size_t n = 0;
        while (i + n < s.size() && s[i + n] >= '0' && s[i + n] <= '9')
            ++n;
        return n;
    };
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-'))
        ++i;
    std::size_t digits = digitsFrom(i);
    i += digits;
    if (i < s.size() && s[i] == '.') {
        const std::size_t fraction = digitsFrom(i + 1);
        i += 1 + fraction;
        digits += fraction;
    }
    if (digits == 0)
        return 0;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < s.size() && (s[j] == '+' || s[j] == '-'))
            ++j;
        if (const std::size_t exponent = digitsFrom(j); exponent > 0)
            i = j + exponent;
    }
    return i;
}

NumberStatus parseDouble(std::string_view s, double &out)
{
    // Check the grammar ourselves: from_chars also takes "inf", "nan" and hex-like forms.
    if (s.empty() || numberLength(s) != s.size())
        return NumberStatus::Malformed;
    const bool negative = s[0] == '-';
    const std::size_t mantissa = s[0] == '+' || s[0] == '-' ? 1 : 0;
    // from_chars does not accept '+' (nor an exponent '+' issue); give it the unsigned part.
    std::string_view body = s.substr(mantissa);
    double v = 0.0;
    const auto res = std::from_chars(body.data(), body.data() + body.size(), v);
    if (res.ec == std::errc::result_out_of_range) {
        // Underflow to a subnormal or zero is harmless; overflow is not.
        bool tiny = false;
        if (const std::size_t e = body.find_first_of("eE"); e != std::string_view::npos)
            tiny = body.size() > e + 1 && body[e + 1] == '-';
        if (!tiny)
            return NumberStatus::OutOfRange;
        v = 0.0;
    } else if (res.ec != std::errc() || res.ptr != body.data() + body.size()) {
        return NumberStatus::Malformed;
    }
    if (!std::isfinite(v))
        return NumberStatus::OutOfRange;
    out = negative ? -v : v;
    return NumberStatus::Ok;
}

int codePointCount(std::string_view text)
{
    int n = 0;
    for (const char c : text)
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80)
            ++n;
    return n;
}

TextPosition positionOf(std::string_view text, std::size_t offset)
{
    TextPosition pos;
    offset = std::min(offset, text.size());
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i)
        if (text[i] == '\n') {
            ++pos.line;
            lineStart = i + 1;
        }
    pos.column = codePointCount(text.substr(lineStart, offset - lineStart)) + 1;
    return pos;
}

} // namespace kontur::io
