// kontur-cli spline: the spline families of issue 4 through the points of a file, as JSON
// {"knots": […], "segments": [Bézier control points of each piece], "points": [[u, x, y]…]}.
#pragma once

#include <QStringList>

namespace kontur::cli {

// `args` starts with the command name (as the other commands). Exit code 0, 1 (bad input), 2 (usage).
int runSpline(const QStringList &args);

} // namespace kontur::cli
