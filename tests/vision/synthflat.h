// Flat synthetic scenes for the vision tests and benchmarks: pattern pieces with a known outline in
// mm, rendered onto a rectified "photo" (supersampled, so edges are exact to a small fraction of a
// pixel) with a table or a white sheet behind, blur, noise, vignetting, a grainline and pencil marks.
#pragma once

#include "geometry/bezier.h"
#include "vision/pixelmapping.h"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace kontur::test {

// A notch on a piece's edge: at arc length `at` (mm) from the outline's start. A V is a triangle cut
// out of the paper (its mouth `width` wide along the edge, `depth` deep); a slit is a cut `depth` long
// square into the paper, seen as a dark hairline (0.3 mm).
struct FlatNotch
{
    enum class Kind { V, Slit };
    double at = 0.0;
    Kind kind = Kind::V;
    double width = 5.0;
    double depth = 5.0;
};

// A closed composite cubic: 3n + 1 control points (last == first), a corner flag per knot (n + 1).
struct FlatPiece
{
    std::vector<geo::Point> control;
    std::vector<bool> corner;
    [[nodiscard]] int knotCount() const { return (static_cast<int>(control.size()) - 1) / 3; }
    [[nodiscard]] geo::Bezier segment(int i) const
    {
        const auto a = static_cast<std::size_t>(3 * i);
        return geo::Bezier({control[a], control[a + 1], control[a + 2], control[a + 3]});
    }
    geo::Point grain[2]; // the grainline's ends, inside the piece
    // Marks rendered only where given: notches on the edge, drill holes (a circle 3 mm across, 0.4 mm
    // line, with a dot at its centre) inside.
    std::vector<FlatNotch> notches;
    std::vector<geo::Point> drillHoles;
    // A "place on fold" bracket, as printed patterns draw it: a bar `inset` mm inside the straight edge
    // from `from` to `to` (both on that edge), with a leg square to the edge at each end that ends in
    // an arrowhead `gap` mm short of the edge. The edge from `foldEnds[0]` to `foldEnds[1]` is the fold.
    struct FoldBracket
    {
        geo::Point from, to;
        double inset = 12.0;
        double gap = 0.8;
    };
    std::optional<FoldBracket> foldBracket;
    geo::Point foldEnds[2];
};

// Where arc length `s` (mm, from the start, wrapped) lies on a closed composite: the point and the unit
// tangent there.
struct CompositePlace
{
    geo::Point point;
    geo::Point tangent;
};
[[nodiscard]] CompositePlace placeOnComposite(const std::vector<geo::Point> &control, double s);
[[nodiscard]] double compositeLength(const std::vector<geo::Point> &control);

// A bodice-like front, 7 knots: hem (slight curve), side seam (line), armhole (two cubics joined
// smoothly), shoulder (line), neckline (curve), centre front (line); six sharp corners. The control
// points are jittered by up to `jitter` mm, then the piece is scaled, turned and moved to `centre`.
[[nodiscard]] FlatPiece bodicePiece(std::mt19937_64 &rng, const geo::Point &centre, double scale, double jitter = 5.0);

enum class Backdrop { Table, WhiteSheet };
enum class PieceLook { Paper, Drawn };

struct FlatSceneOptions
{
    geo::Point sizeMm{250.0, 300.0}; // the scene spans [0, w] × [0, h] mm, y up
    double pxPerMm = 8.0;
    Backdrop backdrop = Backdrop::Table;
    PieceLook look = PieceLook::Paper;
    std::optional<geo::Box> sheet; // a white reference sheet lying in the scene, mm
    bool grainline = true;
    bool grainArrows = true; // an arrowhead at each of the grainline's ends
    bool pencil = true;      // a pencil line drawn along part of each piece's edge
    // A dark line printed along each paper piece's whole outline, on the paper: its width and how far its
    // outer side lies inside the paper's edge (a printed pattern cut out along, or just outside, its line).
    double edgeLineWidthMm = 0.0;
    double edgeLineInsetMm = 0.0;
    bool kraft = false;    // paper pieces on the table in kraft paper (else white)
    double blurPx = 1.0;   // Gaussian sigma of the optics
    double noise = 3.0;    // Gaussian sigma, 8-bit levels
    double vignette = 0.2; // the corners are this much darker
    int supersample = 0;   // samples per pixel side; 0: 4, or 2 for images above 8 megapixels
    std::uint64_t seed = 1;
    bool yUp = true; // the mm frame's y grows upwards (the app's world); false: downwards, as the image's
};

struct FlatScene
{
    cv::Mat image; // 8-bit BGR
    vision::PixelMapping mapping;
    std::vector<FlatPiece> pieces;
};

[[nodiscard]] FlatScene renderFlatScene(const std::vector<FlatPiece> &pieces, const FlatSceneOptions &options);

// Points along a composite cubic, `perSegment` per segment, the last point included.
[[nodiscard]] std::vector<geo::Point> sampleComposite(const std::vector<geo::Point> &control, int perSegment);
// The distance from each point of `a` to the polyline `b`.
[[nodiscard]] std::vector<double> distances(const std::vector<geo::Point> &a, const std::vector<geo::Point> &b);
// The largest of them.
[[nodiscard]] double directedDistance(const std::vector<geo::Point> &a, const std::vector<geo::Point> &b);
// Both ways.
[[nodiscard]] double hausdorff(const std::vector<geo::Point> &a, const std::vector<geo::Point> &b);

} // namespace kontur::test
