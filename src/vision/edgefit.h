// A straight edge between a bright and a dark region measured to sub-pixel accuracy: edge points
// where the intensity falls fastest along the edge's normal (the gradient maximum of Canny 1986,
// located between samples by a parabola through the three largest values as in Devernay 1995),
// then a line through them by total least squares with outliers removed (RANSAC, Fischler & Bolles
// 1981, then iterated 3-sigma trimming). The fit also gives the variances of the line's angle and
// offset that the calibration error is computed from (docs/vision.md).
#pragma once

#include "visionresult.h"

#include "geometry/bezier.h"

#include <opencv2/core.hpp>

#include <optional>
#include <span>
#include <utility>

namespace kontur::vision {

struct EdgeLine
{
    geo::Point point = geo::Point::Zero();      // the centroid of the edge points used
    geo::Point direction = geo::Point::UnitX(); // unit, along the edge
    geo::Point outward = geo::Point::UnitY();   // unit normal pointing to the dark side
    double rms = 0;                             // RMS distance of the edge points from the line (px)
    int count = 0;                              // edge points used
    int sampled = 0;                            // profiles taken along the edge
    double angleVariance = 0;                   // rad^2: sigma^2 / sum of squared positions along the line
    double offsetVariance = 0;                  // px^2 at the centroid: sigma^2 / count
    double contrast = 0;                        // median greatest fall of intensity per px at the edge points
    double bow = 0; // px: edgeBend along the fitted line, where the sheet finder measured it
};

struct EdgeSearch
{
    geo::Point from = geo::Point::Zero(); // the stretch to sample, approximately on the edge
    geo::Point to = geo::Point::Zero();
    geo::Point outward = geo::Point::UnitY(); // approximate normal towards the dark side
    double radiusPx = 6;                      // search this far either side of the stretch
    double stepPx = 2;                        // distance between profiles along the stretch
    double inlierPx = 1;                      // RANSAC's inlier band (more for a first, wide search)
};

// Measures the edge near the stretch in an 8-bit single-channel image. Fails (NoSheetFound) when fewer
// than 12 edge points or fewer than 40 % of the profiles agree on one line.
[[nodiscard]] Result<EdgeLine> fitEdge(const cv::Mat &gray, const EdgeSearch &search);

// How far the edge near the stretch bends (px): in eight equal parts of the stretch, the median offset
// of the edge points (found as fitEdge finds them, within radiusPx) from the stretch's line; the
// largest less the smallest. A straight edge gives its noise, a sheet's edge bowed by a crease or held
// up by a hand gives the bow. 0 when no part has four edge points.
[[nodiscard]] double edgeBend(const cv::Mat &gray, const EdgeSearch &search);

// The share of an edge's profiles (every stepPx between `from` and `to`, on the line) beyond which the
// image turns bright again within `reachPx`: by at least half the fall from the paper's level (4 px
// inside) to the darkest point beyond. A sheet's edge against the table stays dark beyond it; a line
// printed or drawn on paper (a grid's line, a frame) is dark only for its width, and a block of a
// printed grid would otherwise pass for a sheet of its proportions (real photos of grid paper).
[[nodiscard]] double lineShare(const cv::Mat &gray, const EdgeLine &edge, geo::Point from, geo::Point to,
                               double reachPx, double stepPx);

// The total least squares line through points (the major axis of their scatter): their centroid and
// the unit direction. Nothing for fewer than two points. The one line fit of the sheet finder and the
// outline tracer.
[[nodiscard]] std::optional<std::pair<geo::Point, geo::Point>> fitLineTls(std::span<const geo::Point> pts);

// Where two lines meet; empty when they are within `minAngleRad` of parallel.
[[nodiscard]] std::optional<geo::Point> intersect(const EdgeLine &a, const EdgeLine &b, double minAngleRad = 0.05);

} // namespace kontur::vision
