// Reading picture files; see imageloader.h.
#include "models/controllers/imageloader.h"

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

// The picture at `path`, decoded or only its size: a file, with a format Qt reads and a size in
// its header, with the file's orientation applied.
ImageRead read(const QString &path, bool decode)
{
    limitAllocation();
    QImageReader reader(path);
    reader.setAutoTransform(true);
    ImageRead out;
    if (!QFileInfo(path).isFile()) {
        out.error = ImageError::NotAFile;
        return out;
    }
    out.size = reader.size();
    if (!reader.canRead() || !out.size.isValid() || out.size.isEmpty()) {
        out.error = ImageError::NotAnImage;
        return out;
    }
    // The header's size is that of the stored pixels; a quarter turn (EXIF orientation 5–8) shows
    // them with width and height swapped, as the decoded picture has them.
    if (reader.transformation() & QImageIOHandler::TransformationRotate90)
        out.size.transpose();
    if (decode) {
        out.image = reader.read();
        if (out.image.isNull())
            out.error = ImageError::Unreadable;
    }
    return out;
}

} // namespace

ImageRead readImageSize(const QString &path)
{
    return read(path, false);
}

ImageRead readImage(const QString &path)
{
    return read(path, true);
}

} // namespace kontur
