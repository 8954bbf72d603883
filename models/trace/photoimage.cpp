// The background picture for the image library; see photoimage.h.
#include "models/trace/photoimage.h"

#include "picture/photomat.h"
#include "picture/picture.h"

#include <QFileInfo>

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

} // namespace kontur
