// Reading picture files (the background under the curves, the photo a pattern is traced from), for the
// app and kontur-cli alike: one place that sets Qt's allocation limit, so that a hostile or broken file
// cannot exhaust memory; that shows photos as phones took them (EXIF orientation, Qt's
// QImageReader::setAutoTransform); that opens HEIC/HEIF photos, an iPhone's default, through libheif
// (its rotation and mirroring applied); and that answers the picture, or its size, or a typed reason
// why it cannot be read.
#pragma once

#include <QImage>
#include <QSize>
#include <QString>

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
