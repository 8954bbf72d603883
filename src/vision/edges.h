// The image side of the outline tracer: pieces segmented from the background (their contours'
// topology), and edge points to sub-pixel accuracy along a direction. Internal to kontur_vision.
#pragma once

#include "geometry/bezier.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <vector>

namespace kontur::vision::detail {

// The smoothed intensity and its gradient (CV_32F), the field edge points are searched in.
struct EdgeField
{
    cv::Mat smooth, gx, gy;
    [[nodiscard]] double intensity(const geo::Point &p) const;
    [[nodiscard]] geo::Point gradient(const geo::Point &p) const;
};

[[nodiscard]] EdgeField edgeField(const cv::Mat &gray, double sigmaPx);

// A piece as segmented: its outer contour (pixel centres, from findContours) and how its edge looks.
struct Region
{
    std::vector<cv::Point> contour;
    double area = 0.0;  // px², enclosed by the contour
    int polarity = 1;   // +1: the piece (or its drawn line) is brighter than its surroundings
    bool drawn = false; // the piece is a line drawn on paper: its edge is the middle of that line
};

// Regions distinct from the background (the class of most of the image's border) of at least
// `minAreaPx`; `ignore` (a polygon in px) drops the region that is that polygon (the reference sheet).
// Gaps in a region narrower than 2 × `closeRadiusPx` are closed first: a pencil line drawn along a
// piece's edge and touching it would otherwise cut the strip between them off the piece.
[[nodiscard]] std::vector<Region> segmentPieces(const cv::Mat &gray, double minAreaPx, double closeRadiusPx,
                                                const std::optional<std::vector<geo::Point>> &ignore);

// The edge along the line p + t·n, |t| <= radius: the largest step of the expected sign (polarity:
// the intensity falls along n where it is +1), or, for a drawn line, the extremum of the intensity;
// sub-pixel by a parabola through the three samples about the best (Devernay 1995). Returns t and
// the strength at it, or nothing when the best lies at the end of the search.
struct EdgeHit
{
    double t = 0.0;
    double strength = 0.0;
};
[[nodiscard]] std::optional<EdgeHit> edgeAlong(const EdgeField &field, const geo::Point &p, const geo::Point &n,
                                               double radius, int polarity, bool ridge);

// The paper's outer edge against the table along p + t·n, |t| <= reachPx, for a paper piece of
// intensity `paperLevel` brighter than the table. The table's level is the median of five samples 1 px
// apart beyond the reach; from there inwards, the first sample brighter than it by a third of the
// paper-to-table contrast is the paper's, and the falling step near it (within 1.5 px) its edge. A band
// darker than the table between the two (a line printed or drawn along the paper's edge) is reported
// with its depth and its outer side, the rising step back to the table. Nothing when the contrast is
// below kMinPaperContrast (8-bit levels).
inline constexpr double kMinPaperContrast = 12.0;
struct PaperEdge
{
    double table = 0.0;
    std::optional<EdgeHit> bright; // the paper's edge
    std::optional<EdgeHit> dark;   // a dark band's outer side beyond it
    double darkDepth = 0.0;        // how much darker than the table that band is
};
[[nodiscard]] PaperEdge paperEdge(const EdgeField &field, const geo::Point &p, const geo::Point &n, double paperLevel,
                                  double reachPx);

// The contour's points moved onto the edge along the outward normal (px); points whose edge is weaker
// than a third of the median are dropped. The result runs the way the contour does. With `lineReachPx`
// > 0, a paper piece whose outer edge against the table (paperEdge, within lineReachPx) lies beyond the
// edge found at half its points or more (a dark line printed along its edge) is outlined along the
// paper's edge; `beyondLine` then says so, with the paper's level and, where the line itself lies on
// the edge (no paper shows beyond it), its depth below the table's level.
// Where the line lies on the edge, the paper's edge is its outer step less `riseShift` px (lineband.h):
// a narrow line's blur pushes that step outwards; where the line shows too faintly for its outer step,
// the paper's edge is `lineOuter` px beyond its inner one.
struct ContourEdge
{
    std::vector<geo::Point> points;
    bool beyondLine = false;
    double paperLevel = 0.0;
    double lineDepth = 0.0;
    double riseShift = 0.0;
    std::optional<double> lineOuter;
};
[[nodiscard]] ContourEdge subpixelContour(const EdgeField &field, const Region &region, double radius,
                                          double lineReachPx = 0.0);

// The paper's outer edge along each normal p[i] + t·out[i], |t| <= reachPx (out[i] a unit vector
// pointing to the table), as the first look took it (paperEdge's bright step, or the outer side of a
// dark band as deep as `first`'s line; where no paper shows at all, the two lines merging near a tip,
// that band's outer side): a second look from an outline already near that edge.
// Near a sharp corner the first look, along the normals of the line's inner side, never reaches the
// paper's edge within (inset + width) / tan(angle / 2) of the tip; along the outline's own normals it
// does. Points off the median offset of their 13 neighbours by more than 1.5 px (a fleck of the
// table) or weaker than a third of the median are dropped.
[[nodiscard]] std::vector<geo::Point> paperEdgeAlong(const EdgeField &field, const std::vector<geo::Point> &p,
                                                     const std::vector<geo::Point> &out,
                                                     const ContourEdge &first, double reachPx);

} // namespace kontur::vision::detail

namespace kontur::vision {
struct Outline;
}

namespace kontur::vision::detail {

// Segments of a fit whose handles lie on their chord within `tolerance` become exact lines (handles
// at 1/3 and 2/3) and are flagged as such; shared by the outline and the snapped stroke.
void markStraightSegments(Outline &outline, double tolerance);

// A closed composite curve needs three knots (the document's rule): an outline of one or two segments
// (a round dot, a lens) has its longest segment halved — de Casteljau at t = ½, the same curve — until
// it has three. The new knots are smooth; a halved line stays two lines.
void atLeastThreeSegments(Outline &outline);

} // namespace kontur::vision::detail
