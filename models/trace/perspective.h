// The perspective calibration of the background picture (issue #22): a photo of a paper pattern taken
// at an angle shows a known rectangle (an A4 sheet, a cutting mat's square) as a quadrilateral; the
// homography that takes that quadrilateral to the rectangle in real units rectifies the picture.
// Free functions on Qt value types: the corners' order, the homography, and which part of the
// picture can be drawn through it.
#pragma once

#include "geometry/projective.h"
#include "models/document/document.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>

#include <array>
#include <optional>

namespace kontur::perspective {

using Quad = std::array<QPointF, 4>;

// The four points in the order top-left, top-right, bottom-right, bottom-left as seen in the picture
// (image pixels, y down: clockwise on the screen), starting from the point with the smallest x + y;
// nothing when they are not the corners of a strictly convex quadrilateral (three on a line, one
// inside the triangle of the others, two equal). Any of the 24 orders of the same points gives the
// same result.
[[nodiscard]] std::optional<Quad> orderCorners(const Quad &points);

// Whether the ordered quadrilateral is wider than high in the picture: the mean of its top and
// bottom sides against the mean of its left and right sides.
[[nodiscard]] bool looksLandscape(const Quad &ordered);

// The map for QPainter and the scene graph: the one picture → world mapping (Background::imageToWorld)
// goes to Qt drawing only through here.
[[nodiscard]] QTransform toQTransform(const geo::Projective2D &map);

// The part of the picture (image pixels) that is drawn: all of it for an affine placement, and for a
// perspective one drawnRect below.
[[nodiscard]] QRectF drawnRect(const Background &background, QSizeF imageSize);

// The part of the picture (image pixels) that is drawn through a homography: its
// denominator is affine in the picture and vanishes on the picture of the horizon, where the world
// runs to infinity; the rectangle kept reaches from the calibrated quadrilateral towards the picture's
// edges as far as that denominator stays above `minimumScale` of its value at the quadrilateral's
// centre (so the world is magnified at most 1 / minimumScale² there, and nothing beyond the horizon
// is drawn), or of its value at a corner of the quadrilateral where that is less: the quadrilateral
// is always drawn.
[[nodiscard]] QRectF drawnRect(const geo::Projective2D &imageToWorld, const Quad &ordered, QSizeF imageSize,
                               double minimumScale = 0.25);

} // namespace kontur::perspective
