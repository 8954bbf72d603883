// The background picture for the image library; see photoimage.h.
#include "models/trace/photoimage.h"

#include "models/controllers/imageloader.h"

#include <QFileInfo>

#include <cstring>

namespace kontur {

cv::Mat grayMat(const QImage &image)
{
    if (image.isNull())
        return {};
    const QImage gray = image.convertToFormat(QImage::Format_Grayscale8);
    // QImage's rows are 4-byte aligned: copied row by row into a matrix that owns its pixels.
    cv::Mat out(gray.height(), gray.width(), CV_8UC1);
    for (int y = 0; y < gray.height(); ++y)
        std::memcpy(out.ptr(y), gray.constScanLine(y), static_cast<std::size_t>(gray.width()));
    return out;
}

const cv::Mat &PhotoCache::gray(const QString &file)
{
    const QDateTime modified = QFileInfo(file).lastModified();
    if (file != m_file || modified != m_modified) {
        m_file = file;
        m_modified = modified;
        // The picture as shown (EXIF orientation applied), the same reader as the canvas's.
        const ImageRead read = readImage(file);
        m_gray = read.ok() ? grayMat(read.image) : cv::Mat();
    }
    return m_gray;
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
