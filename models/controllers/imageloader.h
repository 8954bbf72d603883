// Reading picture files (the background under the curves): one place that sets Qt's allocation limit,
// so that a hostile or broken file cannot exhaust memory, and answers the picture, or its size, or a
// typed reason why it cannot be read. Used by BackgroundController (placing) and the canvas (drawing).
#pragma once

#include <QImage>
#include <QSize>
#include <QString>

namespace kontur {

enum class ImageError {
    None,
    NotAFile,   // no such file, or a folder
    NotAnImage, // no image format Qt reads, or no size in its header
    Unreadable, // the data is broken, or the picture is larger than the allocation limit
};

// The largest picture Kontur decodes, in MiB (QImageReader::setAllocationLimit).
inline constexpr int kImageAllocationLimitMiB = 512;

struct ImageRead
{
    QImage image; // readImage(): the picture as shown (the file's orientation, EXIF, applied)
    QSize size;   // its size as shown
    ImageError error = ImageError::None;
    [[nodiscard]] bool ok() const { return error == ImageError::None; }
};

// The picture's size from its header, without decoding it (`image` stays null).
[[nodiscard]] ImageRead readImageSize(const QString &path);
// The decoded picture and its size.
[[nodiscard]] ImageRead readImage(const QString &path);

} // namespace kontur
