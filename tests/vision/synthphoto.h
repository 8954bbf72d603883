// Synthetic phone photos with ground truth, for the vision tests and benchmarks: a flat scene in mm
// (a textured table, a white sheet of known size with its top-left corner at the origin, a bodice-like
// pattern piece whose outline is a closed composite of cubic Bézier and line segments with sharp
// corners, a grainline drawn on the piece and a pencil line along part of its edge), seen by a pinhole
// camera tilted 20–45° from vertical, rendered with supersampling (so every edge is where the geometry
// says, to about 1/(2·supersample) px), then blurred, vignetted, noised and optionally quantised like
// JPEG. Deterministic for a given set of options (the seed included).
#pragma once

#include "geometry/bezier.h"
#include "vision/homography.h"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace kontur::vision::test {

struct SynthOptions
{
    std::uint32_t seed = 1;
    cv::Size size{1600, 1200};
    double tiltDeg = 35; // camera axis from the vertical
    double yawDeg = 0;   // camera turned about the vertical through the scene's centre
    double rollDeg = 0;  // camera rotated about its axis
    double focalPx = 0;  // 0: 0.75 × width (a phone's main camera)
    geo::Point sheetMm{210, 297};
    bool withSheet = true;
    bool withPiece = true;
    bool whitePiece = false; // the piece in paper as white as the sheet (else kraft paper)
    double gapMm = 30;       // between the sheet's right edge and the (rotated) piece's leftmost point
    double pieceRotationDeg = 0;
    double tableTexture = 1.0; // contrast of the table's wood grain and knots (0: a plain grey table)
    double blurSigmaPx = 1.0;
    double noiseSigma = 2.0;  // grey levels
    double vignetting = 0.25; // brightness lost at the photo's corners (0..1)
    double jpegStep = 0;      // 0: none; else the quantisation step of the 8x8 DCT's AC coefficients
    int supersample = 4;      // samples per pixel along each axis

    // What real phone photos showed (docs/vision.md, "Real photos"):
    double tableLevel = 105;               // the table's mean grey (light wood ~170, a white desk ~215, dark ~45)
    bool colour = false;                   // a BGR photo (CV_8UC3): the table tinted, paper white
    cv::Vec3d tableTint{0.62, 0.86, 1.15}; // BGR factors of the table's colour in a colour photo (wood)
    bool printedText = false;              // lines of dark print on the sheet, 12 mm from its edges
    // A box lying on the sheet (mm, the sheet's frame), of this grey (and tint in colour); empty: none.
    Eigen::AlignedBox2d objectMm;
    double objectLevel = 70;
    cv::Vec3d objectTint{1.2, 0.9, 0.7};
    // A shadow (a hand's, a phone's) falling on the scene beyond the line through shadowFromMm and
    // shadowToMm (to its right, looking from the first point to the second), its edge soft over
    // shadowSoftMm, darkening by shadowDepth (0..1).
    double shadowDepth = 0;
    geo::Point shadowFromMm{0, 0}, shadowToMm{0, 1};
    double shadowSoftMm = 15;
    // Glare: a bright spot of this many grey levels at its centre (photo px), Gaussian of glareSigmaPx.
    double glareLevels = 0;
    geo::Point glareAtPx{0, 0};
    double glareSigmaPx = 60;
    // A dark line printed along the piece's whole outline (a printed pattern, cut out): its width and
    // how far inside the outline its middle runs, in mm; 0 width: none.
    double outlineInkWidthMm = 0;
    double outlineInkInsetMm = 0;
    // A grid printed on the sheet (grid paper): lines 0.3 mm wide this far apart, from 10 mm inside its
    // edges; 0: none.
    double gridMm = 0;
    // The lens's radial distortion: a photo pixel p shows what the pinhole camera shows at
    // c + (p - c)(1 + k1 r^2), r = |p - c| / half the photo's diagonal (k1 > 0: barrel, a straight edge
    // bows outwards). worldToPhoto stays the pinhole's; lensDistorted maps it into the photo.
    double radialK1 = 0;
    // Marks on the piece: two V notches 5 mm wide and deep (in the middle of the hem and 40 % along
    // the centre front), a slit 5 mm long (in the middle of the shoulder) and a drill hole (a circle
    // 3 mm across with a dot) 25 mm beside the grainline's middle.
    bool pieceMarks = false;
    // With pieceMarks: a "place on fold" bracket too, over the middle half of the centre front, its bar
    // 12 mm inside, its arrows 1 mm short of the edge.
    bool foldBracket = false;
    // The principal point off the photo's centre by this share of its width and height (a cropped photo).
    geo::Point principalShift{0, 0};
};

struct SynthPhoto
{
    cv::Mat image;           // CV_8UC1, or CV_8UC3 (BGR) with SynthOptions::colour
    Homography worldToPhoto; // sheet mm → photo px (pixel centres at integers)
    std::array<geo::Point, 4>
        sheetCorners; // TL, TR, BR, BL in photo px (through the lens) (world (0,0), (w,0), (w,h), (0,h))
    std::vector<std::array<geo::Point, 4>> pieceSegments; // the outline's cubic segments in sheet mm
    std::vector<bool> segmentIsLine;                      // which of them are straight seams
    int pieceKnots = 0;                                   // = number of segments (closed)
    std::vector<geo::Point> pieceOutline;                 // dense closed polyline, ≤ 0.25 mm apart, in mm
    std::array<geo::Point, 2> grainline;                  // its ends in mm (not an outline)
    // With SynthOptions::pieceMarks: the notches (where each meets the outline, the square into the
    // piece there, whether it is a V or a slit) and the drill holes' centres, in mm.
    struct Notch
    {
        geo::Point at, inward;
        bool v = true;
    };
    std::vector<Notch> notches;
    std::vector<geo::Point> drillHoles;
    // With SynthOptions::foldBracket: the fold, the centre front from corner to corner, in mm.
    std::optional<std::array<geo::Point, 2>> fold;
};

[[nodiscard]] SynthPhoto makeSynthPhoto(const SynthOptions &options);

// Where the lens puts (distorted) what the pinhole puts at `pinholePx` (radialK1), and back.
[[nodiscard]] geo::Point lensDistorted(const SynthOptions &o, geo::Point pinholePx);
[[nodiscard]] geo::Point lensUndistorted(const SynthOptions &o, geo::Point photoPx);

// Options drawn from the seed: tilt 20–45°, yaw ±10°, roll ±4°, blur 0.6–1.6 px, noise 1–4 levels,
// vignetting 0–0.35, piece white or kraft, gap 15–60 mm, piece rotated ±6°, table grain 0.3–1.
[[nodiscard]] SynthOptions randomSynthOptions(std::uint32_t seed, cv::Size size = {1600, 1200});

} // namespace kontur::vision::test
