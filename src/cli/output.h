// What every kontur-cli command shares for its output: translated texts and error lines on stderr.
#pragma once

#include "cli/json.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QString>
#include <QTextStream>

#include <cstdio>

namespace kontur::cli {

inline QString tr(const char *text)
{
    return QCoreApplication::translate("kontur::cli", text);
}

// A command's help, with "kontur-cli <command>" in its usage line: QCommandLineParser names the
// program by the process's own argv[0], which lacks the command. `args` is what the command parsed.
inline void printHelp(const QCommandLineParser &parser, const QStringList &args)
{
    QString text = parser.helpText();
    const QString program = QCoreApplication::arguments().value(0);
    const qsizetype at = text.indexOf(program);
    if (!program.isEmpty() && at >= 0 && !args.isEmpty())
        text.replace(at, program.size(), QStringLiteral("kontur-cli ") + args.first().section(QLatin1Char(' '), -1));
    QTextStream(stdout) << text;
}

// Prints "kontur-cli: message" on stderr and returns `code` (1 bad input, 2 bad usage).
inline int fail(const QString &message, int code = 1)
{
    QTextStream err(stderr);
    err << "kontur-cli: " << message << '\n';
    return code;
}

// Prints a command's JSON result on stdout and returns 0, or, when a number in it is not finite
// (the input is beyond what doubles can compute), prints nothing there, says so on stderr and returns 1:
// exit code 0 always comes with finite numbers only (issue 17).
inline int printResult(const Json &json)
{
    if (!json.finite())
        return fail(tr("could not compute \"%1\" as a finite number: the numbers involved exceed the range of "
                       "double precision")
                        .arg(QString::fromStdString(json.nonFiniteKey())));
    std::fwrite(json.str().data(), 1, json.str().size(), stdout);
    std::fputc('\n', stdout);
    return 0;
}

} // namespace kontur::cli
