// The background picture as the image library sees it: the picture read once per file and kept, in grey
// and in colour (picture/photomat.h converts), and the
// traced outlines of src/vision turned into the document's composite curves. Included by the tools'
// sources only, so that OpenCV stays out of the QML types' headers.
#pragma once

#include "io/piece.h"
#include "models/document/curve.h"
#include "models/document/document.h"
#include "vision/marks.h"
#include "vision/outline.h"
#include "vision/tracephoto.h"

#include <QDateTime>
#include <QImage>
#include <QString>

#include <opencv2/core.hpp>

namespace kontur {

// The picture of the background, decoded once per file (and again when the file changes).
class PhotoCache final
{
public:
    // The picture of `file` in grey, or an empty matrix when it cannot be read.
    [[nodiscard]] const cv::Mat &gray(const QString &file);
    // The same picture in colour (BGR; the sheet is told from a light, coloured table by its colour).
    [[nodiscard]] const cv::Mat &colour(const QString &file);
    // The camera's focal length in the picture's pixels from its EXIF (picture.h), or 0 when unknown.
    [[nodiscard]] double focalPx(const QString &file);

private:
    void read(const QString &file);
    QString m_file;
    QDateTime m_modified;
    cv::Mat m_gray;
    cv::Mat m_colour;
    double m_focalPx = 0.0;
};

// The background picture's part covering the world box [min, max] at about `pxPerUnit` (at most
// `maxSide` px a side), y up, through Background::worldToImage().
[[nodiscard]] vision::Result<vision::WorldPatch> worldPatch(const cv::Mat &gray, const Background &background,
                                                            const geo::Point &min, const geo::Point &max,
                                                            double pxPerUnit, int maxSide = 4000);

// What the tracer reads as millimetres in the world's units: the tolerance and the smallest piece.
// mmPerUnit <= 0 (pixels): `unitsPerPhotoPixel` sets the scale instead (half a photo pixel).
[[nodiscard]] vision::OutlineOptions outlineOptionsIn(double mmPerUnit, double unitsPerPhotoPixel);

// A traced outline as a composite curve: corner knots as Corner nodes, the rest Smooth; straight
// segments keep their handles at 1/3 and 2/3, so they stay exact lines.
[[nodiscard]] geo::Result<Curve> curveFromOutline(const vision::Outline &outline);

// The marks found on a traced piece (vision/marks.h) as the piece's own, on `curve` (the outline as the
// document keeps it): notches by their place along it, at their angle against the square to the seam
// (square within 7°: the finder is within 2° of the truth, and a notch is cut square unless the pattern
// says otherwise), the grainline, drill holes and fold as found. Nothing when nothing was found.
[[nodiscard]] std::optional<io::PieceMarks> pieceMarksFrom(const vision::FoundMarks &found,
                                                           const geo::PiecewiseBezier &curve);

} // namespace kontur
