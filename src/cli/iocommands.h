// kontur-cli convert and info: the file formats of src/io from the command line. Each takes the
// arguments after its name and returns the exit code (0 success, 1 bad input, 2 bad usage).
#pragma once

#include <QStringList>

namespace kontur::cli {

int runConvert(const QStringList &args);
int runInfo(const QStringList &args);

} // namespace kontur::cli
