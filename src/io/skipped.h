// What a drawing may hold that Kontur does not draw (DXF entities, SVG elements), counted by kind
// while the rest is read, so the app's message line and kontur-cli's stderr say it in one way.
#pragma once

#include <QString>

#include <array>
#include <cstddef>

namespace kontur::io {

// What a file held that Kontur does not draw, by kind: the one list, which the messages (errortext.h,
// skippedList) and the CLI (skippedSummary) name in this order.
enum class SkippedKind {
    Text = 0,      // DXF TEXT, MTEXT, ATTRIB, ATTDEF; SVG <text>, Inkscape's <flowRoot>
    Dimension = 1, // DXF DIMENSION, LEADER, MLEADER, TOLERANCE
    Solid3D = 2,   // DXF 3DFACE, meshes (also POLYLINE meshes), solids, surfaces, anything outside the plane
    Image = 3,     // DXF IMAGE, WIPEOUT, underlays, OLE frames; SVG <image>
    Spline = 4,    // DXF SPLINEs given only by fit points, rational ones (also as hatch boundaries)
    Other = 5,     // DXF POINT, SOLID, XLINE, missing or too deeply nested blocks, anything else;
                   // SVG <foreignObject>, <video>, <audio>, <iframe>, <canvas>
};
inline constexpr std::size_t kSkippedKinds = 6;
using SkippedCounts = std::array<int, kSkippedKinds>;

[[nodiscard]] inline bool anySkipped(const SkippedCounts &counts)
{
    for (const int n : counts)
        if (n > 0)
            return true;
    return false;
}

// The counts in English for kontur-cli ("12 texts, 1 3D object"), the last kind named `otherOne`
// or `otherMany` ("other entity" in a DXF, "other element" in an SVG); empty when nothing was skipped.
[[nodiscard]] QString skippedSummary(const SkippedCounts &counts, const char *otherOne, const char *otherMany);

} // namespace kontur::io
