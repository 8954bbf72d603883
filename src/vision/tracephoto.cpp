// A photo traced into a plane; see tracephoto.h.
#include "vision/tracephoto.h"

#include "geometry/projective.h"
#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace kontur::vision {
namespace {

// A point well inside a closed outline (the grid point farthest inside its control polygon, which
// stays close to the curve at the tracer's tolerance): the seed that picks the piece again.
geo::Point insidePoint(const Outline &outline)
{
    std::vector<cv::Point2f> polygon;
    geo::Box box;
    for (const geo::Point &p : outline.control) {
        polygon.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
        box.extend(p);
    }
    geo::Point best = box.center();
    double deepest = -1e300;
    const int n = 24;
    for (int i = 1; i < n; ++i)
        for (int j = 1; j < n; ++j) {
            const geo::Point q = box.min() + box.sizes().cwiseProduct(geo::Point(double(i) / n, double(j) / n));
            const double d =
                cv::pointPolygonTest(polygon, cv::Point2f(static_cast<float>(q.x()), static_cast<float>(q.y())), true);
            if (d > deepest)
                deepest = d, best = q;
        }
    return best;
}

} // namespace

Result<WorldPatch> rectifyWorld(const cv::Mat &photo, const Homography &worldToPhoto, const geo::Point &worldMin,
                                const geo::Point &worldMax, double pxPerUnit, bool yUp, int maxSidePx)
{
    if (photo.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty"};
    const geo::Point extent = worldMax - worldMin;
    if (!(pxPerUnit > 0) || !std::isfinite(pxPerUnit) || !(extent.x() > 0) || !(extent.y() > 0) ||
        !extent.allFinite() || !worldToPhoto.allFinite() || maxSidePx < 16)
        return Error{ErrorCode::InvalidArgument, "the box and the scale must be positive"};
    const double s = std::min(pxPerUnit, maxSidePx / std::max(extent.x(), extent.y()));
    const int w = std::max(1, static_cast<int>(std::ceil(extent.x() * s)));
    const int h = std::max(1, static_cast<int>(std::ceil(extent.y() * s)));

    WorldPatch out;
    out.pxPerUnit = s;
    // Pixel centres at integers (pixelmapping.h): pixel (0, 0) is the box's top-left (y up) or
    // bottom-left (y down) corner, half a pixel in.
    out.mapping.linear << 1.0 / s, 0.0, 0.0, yUp ? -1.0 / s : 1.0 / s;
    out.mapping.offset = geo::Point(worldMin.x() + 0.5 / s, yUp ? worldMax.y() - 0.5 / s : worldMin.y() + 0.5 / s);
    Eigen::Matrix3d toWorld = Eigen::Matrix3d::Identity();
    toWorld.topLeftCorner<2, 2>() = out.mapping.linear;
    toWorld.topRightCorner<2, 1>() = out.mapping.offset;
    const Eigen::Matrix3d patchToPhoto = worldToPhoto * toWorld;
    cv::Matx33d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m(i, j) = patchToPhoto(i, j);
    // WARP_INVERSE_MAP: m takes the patch's pixels to the photo's. The border repeated, so that the
    // outside of the photo looks like its edge (the table) and not like a dark piece.
    cv::warpPerspective(photo, out.image, cv::Mat(m), cv::Size(w, h), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                        cv::BORDER_REPLICATE);
    return out;
}

std::optional<geo::Box> photoExtentInWorld(cv::Size photo, const Homography &photoToWorld, const geo::Box &limit)
{
    if (photo.width <= 0 || photo.height <= 0)
        return std::nullopt;
    // The side of the horizon that is drawn: the photo's centre's.
    const geo::Point centre(0.5 * (photo.width - 1), 0.5 * (photo.height - 1));
    const double sign = homogeneousW(photoToWorld, centre) > 0 ? 1.0 : -1.0;
    geo::Box box;
    const int n = 64; // samples per side: a border that crosses the horizon is cut at the last one in front
    for (int side = 0; side < 4; ++side) {
        for (int i = 0; i <= n; ++i) {
            const double t = double(i) / n;
            const double x = side == 0   ? t * (photo.width - 1)
                             : side == 1 ? photo.width - 1
                             : side == 2 ? (1 - t) * (photo.width - 1)
                                         : 0.0;
            const double y = side == 0   ? 0.0
                             : side == 1 ? t * (photo.height - 1)
                             : side == 2 ? photo.height - 1
                                         : (1 - t) * (photo.height - 1);
            const geo::Point p(x, y);
            if (sign * homogeneousW(photoToWorld, p) <= 1e-12)
                continue;
            const geo::Point w = apply(photoToWorld, p);
            if (w.allFinite())
                box.extend(limit.contains(w) ? w : geo::Point(w.cwiseMax(limit.min()).cwiseMin(limit.max())));
        }
    }
    if (box.isEmpty() || !(box.sizes().minCoeff() > 0))
        return std::nullopt;
    return box;
}

Result<PhotoTrace> tracePhoto(const cv::Mat &photo, const PhotoTraceOptions &options)
{
    auto sheet = findSheet(photo, options.sheet);
    if (!sheet)
        return sheet.error();
    return tracePieces(photo, *sheet, options);
}

Result<PhotoTrace> tracePieces(const cv::Mat &photo, const Sheet &theSheet, const PhotoTraceOptions &options)
{
    const cv::Mat gray = toGray(photo);
    if (gray.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty or not an 8-bit gray or colour image"};
    const Sheet *sheet = &theSheet;
    PhotoTrace out;
    out.sheet = theSheet;
    out.calibrationErrorMm = calibrationErrorAtPhotoCornersMm(theSheet, gray.size());

    // The world: the sheet's mm with y up (flipped), so that outlines come out as the app draws them.
    Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
    flip(1, 1) = -1.0;
    const Homography photoToWorld = flip * sheet->photoToSheet;
    const Homography worldToPhoto = sheet->sheetToPhoto * flip;
    const geo::Point size = sheet->sizeMm;
    const geo::Box sheetBox(geo::Point(0.0, -size.y()), geo::Point(size.x(), 0.0));
    const geo::Point reach(options.reachMm, options.reachMm);
    const auto extent =
        photoExtentInWorld(gray.size(), photoToWorld, geo::Box(sheetBox.min() - reach, sheetBox.max() + reach));
    if (!extent)
        return Error{ErrorCode::Degenerate, "the photo shows nothing in front of the camera"};
    // First the whole photo coarsely, to find the pieces; then each piece alone at the full scale
    // (the photo around the sheet may span metres, more than one image at 8 px/mm can hold).
    auto coarse = rectifyWorld(gray, worldToPhoto, extent->min(), extent->max(), options.pxPerMm, true, 1500);
    if (!coarse)
        return coarse.error();
    OutlineOptions outline = options.outline;
    outline.ignoreRect = sheetBox;
    // A photo pixel's length in mm where the piece lies: the far side of the photo is coarser.
    if (const auto toPhoto = geo::Projective2D::fromMatrix(worldToPhoto))
        outline.sourcePixel = [map = *toPhoto](const geo::Point &p) {
            return 1.0 / std::sqrt(std::abs(map.jacobian(p).determinant()));
        };
    OutlineOptions rough = outline;
    rough.tolerance = std::max(outline.tolerance, 1.0 / coarse->pxPerUnit);
    auto found = traceOutlines(coarse->image, coarse->mapping, rough);
    if (!found)
        return Error{ErrorCode::InvalidArgument, found.error().message};
    std::vector<Outline> outlines;
    for (const Outline &piece : *found) {
        geo::Box box;
        for (const geo::Point &p : piece.control)
            box.extend(p);
        const geo::Point margin = geo::Point(10.0, 10.0) + geo::Point::Constant(10.0 / coarse->pxPerUnit);
        box = geo::Box(box.min() - margin, box.max() + margin).intersection(*extent);
        auto fine = rectifyWorld(gray, worldToPhoto, box.min(), box.max(), options.pxPerMm, true, options.maxSidePx);
        if (!fine)
            return fine.error();
        out.pxPerMm = fine->pxPerUnit;
        out.rectified = fine->image.size();
        auto traced = traceOutlineAt(fine->image, fine->mapping, insidePoint(piece), outline);
        if (traced)
            outlines.push_back(std::move(*traced));
    }
    if (outlines.empty())
        return Error{ErrorCode::NoPieceFound, "no pattern piece found beside the sheet"};
    out.outlines = std::move(outlines);
    return out;
}

} // namespace kontur::vision
