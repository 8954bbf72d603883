// What every kontur-cli command shares for its output: translated texts and error lines on stderr.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QTextStream>

#include <cstdio>

namespace kontur::cli {

inline QString tr(const char *text)
{
    return QCoreApplication::translate("cli", text);
}

// Prints "kontur-cli: message" on stderr and returns `code` (1 bad input, 2 bad usage).
inline int fail(const QString &message, int code = 1)
{
    QTextStream err(stderr);
    err << "kontur-cli: " << message << '\n';
    return code;
}

} // namespace kontur::cli
