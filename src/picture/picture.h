// Reading picture files (the background under the curves, the photo a pattern is traced from), for the
// app and kontur-cli alike: one place that sets Qt's allocation limit, so that a hostile or broken file
// cannot exhaust memory; that shows photos as phones took them (EXIF orientation, Qt's
// QImageReader::setAutoTransform); that opens HEIC/HEIF photos, an iPhone's default, through libheif
// (its rotation and mirroring applied); and that answers the picture, or its size, or a typed reason
// why it cannot be read.
#pragma once

#include "picture/exif.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <algorithm>
#include <cmath>

namespace kontur {

enum class ImageError {
    None,
    NotAFile,   // no such file, or a folder
    NotAnImage, // no image format Kontur reads, or no size in its header
    Unreadable, // the data is broken, or the picture is larger than the allocation limit
};

// The largest picture Kontur decodes, in MiB (QImageReader::setAllocationLimit; the same for HEIF).
inline constexpr int kImageAllocationLimitMiB = 512;

struct ImageRead
{
    QImage image; // readImage(): the picture as shown (the file's orientation, EXIF or HEIF's, applied)
    QSize size;   // its size as shown
    ImageError error = ImageError::None;
    // The lens's focal length as on 35 mm film, from the photo's EXIF (picture/exif.h); 0: not known.
    double focal35mm = 0;
    // The focal length in pixels of the picture as shown (`size`), or 0 when not known. Only for a
    // picture of a camera's full-frame proportions (4:3, 3:2, 16:9 or 1:1, within 0.5 %): EXIF keeps
    // the lens's focal length when a picture is cropped, and in a crop it is wrong.
    [[nodiscard]] double focalPx() const
    {
        if (!(focal35mm > 0) || size.isEmpty())
            return 0.0;
        const double aspect = static_cast<double>(std::max(size.width(), size.height())) /
                              std::min(size.width(), size.height());
        bool fullFrame = false;
        for (const double frame : {4.0 / 3.0, 3.0 / 2.0, 16.0 / 9.0, 1.0})
            fullFrame = fullFrame || std::abs(aspect / frame - 1.0) <= 0.005;
        return fullFrame ? focal35mm / kFullFrameDiagonalMm * std::hypot(size.width(), size.height()) : 0.0;
    }
    [[nodiscard]] bool ok() const { return error == ImageError::None; }
};

// The picture's size from its header, without decoding it (`image` stays null).
[[nodiscard]] ImageRead readImageSize(const QString &path);
// The decoded picture and its size.
[[nodiscard]] ImageRead readImage(const QString &path);

// Whether the file starts as a HEIF container does (HEIC, HEIF, AVIF: an ISO box "ftyp" of one of
// their brands), whatever its name.
[[nodiscard]] bool isHeif(const QString &path);

} // namespace kontur
