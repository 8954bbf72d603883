// kontur-cli bench operations of the spline families (issue 4): spline-natural, spline-clamped,
// spline-periodic, global-bspline, spline-eval and natural-drag. The bench command's dispatcher
// hands these names to runSplineBench and prints the timing like its own.
#pragma once

#include "cli/benchtiming.h"

#include <QString>

#include <cstddef>
#include <optional>
#include <vector>

namespace kontur::cli {

using SplineBenchTiming = BenchTiming;

// The operation names, for the bench's help and error texts.
// (spline-natural+bezier etc. also build the flat array of Bézier control points.)
inline constexpr const char *kSplineBenchOps = "spline-natural, spline-clamped, spline-periodic, global-bspline, "
                                               "spline-eval, natural-drag";

// Empty when `op` is not a spline operation. `n` points on a random walk of size `scale`, `repeat`
// timed samples after one warm-up.
[[nodiscard]] std::optional<SplineBenchTiming> runSplineBench(const QString &op, std::size_t n, int repeat,
                                                              double scale);

} // namespace kontur::cli
