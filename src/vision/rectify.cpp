// Rectification by one cv::warpPerspective with the composed map rectified px → mm → photo px.
#include "rectify.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace kontur::vision {

Eigen::Matrix<double, 2, 3> rectifiedPixelToMm(const RectifyRequest &r)
{
    Eigen::Matrix<double, 2, 3> m;
    const double s = 1.0 / r.pxPerMm;
    m << s, 0, r.worldMinMm.x() + 0.5 * s, 0, s, r.worldMinMm.y() + 0.5 * s;
    return m;
}

Result<Rectified> rectify(const cv::Mat &photo, const RectifyRequest &r)
{
    if (photo.empty())
        return Error{ErrorCode::InvalidImage, "the photo is empty"};
    const geo::Point extent = r.worldMaxMm - r.worldMinMm;
    if (!(r.pxPerMm > 0) || !(extent.x() > 0) || !(extent.y() > 0) || !r.sheetToPhoto.allFinite())
        return Error{ErrorCode::InvalidArgument, "the scale and the rectangle must be positive"};
    const double w = std::ceil(extent.x() * r.pxPerMm), h = std::ceil(extent.y() * r.pxPerMm);
    if (w > 20000 || h > 20000)
        return Error{ErrorCode::InvalidArgument, "the rectified image would be wider than 20000 px"};

    Rectified out;
    out.pixelToMm = rectifiedPixelToMm(r);
    Eigen::Matrix3d toMm = Eigen::Matrix3d::Identity();
    toMm.topRows<2>() = out.pixelToMm;
    out.rectifiedToPhoto = r.sheetToPhoto * toMm;
    cv::Matx33d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m(i, j) = out.rectifiedToPhoto(i, j);
    // WARP_INVERSE_MAP: m maps destination pixels to source pixels, exactly our composed map.
    cv::warpPerspective(photo, out.image, cv::Mat(m), cv::Size(static_cast<int>(w), static_cast<int>(h)),
                        cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return out;
}

} // namespace kontur::vision
