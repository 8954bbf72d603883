// A dark line printed or drawn on the very edge of a paper piece: how far its outer side (the paper's
// edge against the table) lies beyond its inner side (the step the tracer finds first). Internal to
// kontur_vision; docs/vision.md, "A line along the edge".
#pragma once

#include <optional>
#include <vector>

namespace kontur::vision::detail {

// The intensity across the edge, averaged over the outline: `step` px apart from `from` px, outwards,
// with 0 at each profile's paper-to-line step (the steepest fall found there).
struct MeanProfile
{
    double from = 0.0;
    double step = 0.5;
    std::vector<double> value;
};

// The line across the edge, as the model
//   I(u) = P + (L − P)·Φ((u − a)/s) + (T − L)·Φ((u − e)/s)
// (paper P, line L, table T, the line between a and e, a Gaussian blur s; Φ the normal distribution)
// fitted to the mean profile by Levenberg–Marquardt (Nocedal & Wright 2006, §10.3) gives it.
//
// Why not the steepest rise at the line's outer side as it is: for a line as narrow as the blur (a
// 0.3 mm line is 2.4 px at 8 px/mm, the blur about 1.5 px), the fall at its inner side pulls that rise
// outwards by about s²·ln((P − L)/(T − L))/(e − a), more than a pixel; the model has both steps, and
// says how far (`riseShift`). Each profile is aligned at its own step, so `outer` (e) is relative to
// what the tracer found there.
struct LineBand
{
    double outer = 0.0;     // px beyond the paper-to-line step: the paper's edge against the table
    double riseShift = 0.0; // px the steepest rise lies beyond the paper's edge
    double blur = 0.0;      // s, px
};

// Nothing when the fit does not converge or does not show a line: one darker than the table by
// `minDepth` or more (8-bit levels), between 0.5 px and the profile's end wide.
[[nodiscard]] std::optional<LineBand> fitLineBand(const MeanProfile &profile, double paper, double table,
                                                  double minDepth);

} // namespace kontur::vision::detail
