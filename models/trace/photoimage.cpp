// The background picture for the image library; see photoimage.h.
#include "models/trace/photoimage.h"

#include "picture/photomat.h"
#include "picture/picture.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur {

void PhotoCache::read(const QString &file)
{
    const QDateTime modified = QFileInfo(file).lastModified();
    if (file != m_file || modified != m_modified) {
        m_file = file;
        m_modified = modified;
        // The picture as shown (EXIF orientation applied), the same reader as the canvas's.
        const ImageRead read = readImage(file);
        m_gray = read.ok() ? grayMat(read.image) : cv::Mat();
        m_colour = read.ok() && !read.image.isGrayscale() ? bgrMat(read.image) : m_gray;
        m_focalPx = read.ok() ? read.focalPx() : 0.0;
    }
}

double PhotoCache::focalPx(const QString &file)
{
    read(file);
    return m_focalPx;
}

const cv::Mat &PhotoCache::gray(const QString &file)
{
    read(file);
    return m_gray;
}

const cv::Mat &PhotoCache::colour(const QString &file)
{
    read(file);
    return m_colour;
}

vision::Result<vision::WorldPatch> worldPatch(const cv::Mat &gray, const Background &background, const geo::Point &min,
                                              const geo::Point &max, double pxPerUnit, int maxSide)
{
    return vision::rectifyWorld(gray, background.worldToImage().matrix(), min, max, pxPerUnit, true, maxSide);
}

vision::OutlineOptions outlineOptionsIn(double mmPerUnit, double unitsPerPhotoPixel)
{
    vision::OutlineOptions options;
    if (mmPerUnit > 0.0) {
        options.tolerance /= mmPerUnit;
        options.minArea /= mmPerUnit * mmPerUnit;
        options.millimetre = 1.0 / mmPerUnit;
    } else {
        // No physical unit: a tenth of the defaults' millimetre as a photo pixel, about right for a
        // phone photo of a table (5–10 px/mm).
        options.tolerance = 0.5 * unitsPerPhotoPixel;
        options.minArea = 400.0 * 25.0 * unitsPerPhotoPixel * unitsPerPhotoPixel;
        options.millimetre = 10.0 * unitsPerPhotoPixel;
    }
    return options;
}

geo::Result<Curve> curveFromOutline(const vision::Outline &outline)
{
    const int knots = outline.knotCount();
    std::vector<geo::NodeType> types;
    for (int k = 0; k < knots; ++k)
        types.push_back(outline.corner.at(static_cast<std::size_t>(k)) ? geo::NodeType::Corner : geo::NodeType::Smooth);
    auto composite = geo::CompositeCurve::fromParts(outline.control, std::move(types), outline.closed);
    if (!composite)
        return composite.error();
    composite->finish();
    return Curve::makeComposite(std::move(*composite));
}

std::optional<io::PieceMarks> pieceMarksFrom(const vision::FoundMarks &found, const geo::PiecewiseBezier &curve)
{
    if (!found.grainline && found.notches.empty() && found.drillHoles.empty() && !found.fold)
        return std::nullopt;
    io::PieceMarks marks;
    if (found.grainline)
        marks.grainline = io::Segment{(*found.grainline)[0], (*found.grainline)[1]};
    if (found.fold)
        marks.fold = io::Segment{(*found.fold)[0], (*found.fold)[1]};
    for (const vision::FoundNotch &f : found.notches) {
        io::Notch notch;
        notch.position = io::lengthAtNearest(curve, f.at);
        notch.kind = f.kind == vision::FoundNotch::Kind::V        ? io::NotchKind::V
                     : f.kind == vision::FoundNotch::Kind::Castle ? io::NotchKind::Castle
                                                                  : io::NotchKind::Slit;
        const geo::Point square = io::notchDirection(curve, io::placeAtLength(curve, notch.position), 0.0);
        const double angle = std::atan2(square.x() * f.into.y() - square.y() * f.into.x(), square.dot(f.into)) * 180.0 /
                             std::numbers::pi;
        constexpr double squareWithin = 7.0, steepest = 80.0;
        notch.angle = std::abs(angle) < squareWithin ? 0.0 : std::clamp(angle, -steepest, steepest);
        marks.notches.push_back(notch);
    }
    std::stable_sort(marks.notches.begin(), marks.notches.end(),
                     [](const io::Notch &a, const io::Notch &b) { return a.position < b.position; });
    marks.drillHoles = found.drillHoles;
    return marks;
}

} // namespace kontur
