// Reading picture files; see imageloader.h.
#include "models/imageloader.h"

#include <QFileInfo>
#include <QImageIOHandler>
#include <QImageReader>

namespace kontur {

namespace {

// Qt refuses images that would take more memory than this. The limit is process-wide, so it is
// set once, before the first reader exists.
void limitAllocation()
{
    static const bool limited = [] {
        QImageReader::setAllocationLimit(kImageAllocationLimitMiB);
        return true;
    }();
    Q_UNUSED(limited)
}

// The checks both entry points share: a file, with a format Qt reads and a size in its header.
ImageError check(QImageReader &reader, const QString &path)
{
    if (!QFileInfo(path).isFile())
        return ImageError::NotAFile;
    const QSize size = reader.size();
    if (!reader.canRead() || !size.isValid() || size.isEmpty())
        return ImageError::NotAnImage;
    return ImageError::None;
}

} // namespace

ImageSize readImageSize(const QString &path)
{
    limitAllocation();
    QImageReader reader(path);
    reader.setAutoTransform(true);
    ImageSize out;
    out.error = check(reader, path);
    if (out.ok()) {
        out.size = reader.size();
        // The header's size is that of the stored pixels; a quarter turn (EXIF orientation 5–8)
        // shows them with width and height swapped, as readImage() answers them.
        if (reader.transformation() & QImageIOHandler::TransformationRotate90)
            out.size.transpose();
    }
    return out;
}

ImageRead readImage(const QString &path)
{
    limitAllocation();
    QImageReader reader(path);
    reader.setAutoTransform(true);
    ImageRead out;
    out.error = check(reader, path);
    if (!out.ok())
        return out;
    out.image = reader.read();
    if (out.image.isNull())
        out.error = ImageError::Unreadable;
    return out;
}

} // namespace kontur
