// The kontur-cli commands. Each takes the arguments after its name, prints JSON to stdout and
// messages to stderr, and returns the process exit code (0 success, 1 bad input, 2 bad usage).
#pragma once

#include <QStringList>

namespace kontur::cli {

int runFit(const QStringList &args);
int runBezier(const QStringList &args);
int runComposite(const QStringList &args);
int runBench(const QStringList &args);

} // namespace kontur::cli
