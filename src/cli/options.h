// The command line that several kontur-cli commands share, each option read and checked in one place.
// Every reader returns 0, or prints the usage error and returns its exit code (2); parseCommandLine
// returns -1 after printing the help.
#pragma once

#include "geometry/parameterization.h"

#include <QCommandLineParser>
#include <QStringList>

#include <vector>

namespace kontur::cli {

// Parses `args` (the command name first) with `parser`, adding --help, and requires `positional`
// file names (none: any positional argument is unexpected).
[[nodiscard]] int parseCommandLine(QCommandLineParser &parser, const QStringList &args, int positional = 0);

// --param: uniform, chord or centripetal.
[[nodiscard]] int readParam(const QCommandLineParser &parser, geo::Parameterization &out);

// --at u1,u2,…: the list of parameters to evaluate at (empty when the option is not given).
[[nodiscard]] int readAt(const QCommandLineParser &parser, std::vector<double> &out);

} // namespace kontur::cli
