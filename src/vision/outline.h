// Outlines found by the picture: the closed outline of every pattern piece in a rectified photo, and
// a freehand stroke snapped to the photo's edge near it, as composite cubic curves in millimetres.
// Segmentation and contour topology by OpenCV (Suzuki & Abe 1985), edge points to sub-pixel accuracy
// along the contour's normal (Devernay 1995), corners from the edge's turning, straight runs as exact
// lines, the rest by the stroke fit (Schneider 1990). See docs/vision.md, "Outlines".
#pragma once

#include "geometry/bezier.h"
#include "geometry/result.h"
#include "vision/pixelmapping.h"

#include <opencv2/core/mat.hpp>

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace kontur::vision {

struct OutlineOptions
{
    // Largest distance from a sub-pixel edge point to the fitted curve, in mm (> 0). Where the edge
    // points scatter more than a quarter of it (a coarse or noisy photo), a run of the outline is
    // fitted to four times their robust deviation instead: the curve then follows their mean.
    double tolerance = 0.2;
    // The outline turns by more than this (degrees) at a corner.
    double cornerAngle = 35.0;
    // Regions smaller than this (mm²) are not pieces (dust, table texture, marks).
    double minArea = 400.0;
    // The reference sheet's rectangle in mm (in the mapping's frame): a region that is the sheet
    // itself is not a piece.
    std::optional<geo::Box> ignoreRect;
    // One millimetre in the mapping's units (1 when it maps to mm, 0.1 for cm): the tracer's own
    // lengths (how far it looks along an edge for its turning, how short a side may be) are in mm.
    double millimetre = 1.0;
    // The length, in the mapping's units, of one pixel of the photo that the image was warped from,
    // at a point; empty: the image's own pixel. Where the photo was coarse (the far side of a
    // perspective photo) its edge points scatter more, and the tracer looks along a longer stretch.
    std::function<double(const geo::Point &)> sourcePixel;
};

// A notch cut into a piece's edge (a V, or a castle with square sides), in the mapping's units: where
// its axis meets the seam line the outline bridges it by, its deepest point, its width at the mouth and
// its depth.
struct CutNotch
{
    geo::Point at = geo::Point::Zero();
    geo::Point tip = geo::Point::Zero();
    double width = 0.0;
    double depth = 0.0;
    bool castle = false;
};

// One outline, the shape of geo::StrokeFit: 3n + 1 control points of n cubic segments, the knots at
// c_{3i}; when closed, the last point equals the first (its knot flag is the first knot's).
struct Outline
{
    std::vector<geo::Point> control;
    std::vector<bool> corner; // one per knot (n + 1)
    std::vector<bool> line;   // one per segment: a straight segment with handles at 1/3 and 2/3
    bool closed = true;
    double maxError = 0.0; // mm: the largest distance from an edge point used to its fitted segment
    int edgePoints = 0;    // sub-pixel edge points that went into the fit
    // Notches cut into the edge, 1.5–12 mm deep and at most 10 mm wide: the outline runs across
    // their mouths, as the seam line does.
    std::vector<CutNotch> notches;

    [[nodiscard]] int segmentCount() const { return control.empty() ? 0 : (static_cast<int>(control.size()) - 1) / 3; }
    [[nodiscard]] int knotCount() const { return closed ? segmentCount() : segmentCount() + 1; }
    [[nodiscard]] geo::Bezier segment(int i) const;
};

// Every piece's outline, largest first. A closed outline runs counter-clockwise in the output frame
// (positive area, y up; clockwise as seen in the image when the map keeps y down) and starts at a
// corner when it has one. `image`: 8-bit gray or BGR, the photo warped into the sheet's plane.
// Inner markings (grainlines, notches, text) do not become outlines; a piece drawn as a line on paper
// is outlined along the middle of that line. Errors: an empty image or a map that is not invertible.
[[nodiscard]] geo::Result<std::vector<Outline>> traceOutlines(const cv::Mat &image, const PixelMapping &mapping,
                                                              const OutlineOptions &options = {});

// The one outline containing `seedMm`, or else the one whose outline is nearest to it. Error when the
// image holds no piece.
[[nodiscard]] geo::Result<Outline> traceOutlineAt(const cv::Mat &image, const PixelMapping &mapping,
                                                  const geo::Point &seedMm, const OutlineOptions &options = {});

// The stroke (mm) only says where to look: each of its samples is moved to the strongest edge along
// the stroke's normal within `searchRadiusMm`, outliers are dropped and the rest is fitted as an open
// curve with corners kept. Error when no edge is found along most of the stroke.
[[nodiscard]] geo::Result<Outline> snapStrokeToEdges(const cv::Mat &image, const PixelMapping &mapping,
                                                     std::span<const geo::Point> strokeMm, double searchRadiusMm,
                                                     const OutlineOptions &options = {});

} // namespace kontur::vision
