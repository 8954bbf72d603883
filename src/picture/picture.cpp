// Reading picture files; see picture.h.
#include "picture/picture.h"

#include <QFile>
#include <QFileInfo>
#include <QImageIOHandler>
#include <QImageReader>
#include <QtEndian>

#include <libheif/heif.h>

#include <memory>

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

// A HEIF file through libheif: its primary image, with the container's rotation and mirroring applied
// (libheif's default), as 8-bit RGBA.
ImageRead readHeif(const QString &path, bool decode)
{
    ImageRead out;
    const std::unique_ptr<heif_context, decltype(&heif_context_free)> context(heif_context_alloc(), &heif_context_free);
    if (!context || heif_context_read_from_file(context.get(), QFile::encodeName(path).constData(), nullptr).code !=
                        heif_error_Ok) {
        out.error = ImageError::NotAnImage;
        return out;
    }
    heif_image_handle *rawHandle = nullptr;
    if (heif_context_get_primary_image_handle(context.get(), &rawHandle).code != heif_error_Ok) {
        out.error = ImageError::NotAnImage;
        return out;
    }
    const std::unique_ptr<heif_image_handle, decltype(&heif_image_handle_release)> handle(rawHandle,
                                                                                          &heif_image_handle_release);
    // The EXIF item: a 4-byte offset to its TIFF header, then (usually "Exif\0\0" and) the header.
    heif_item_id exifId = 0;
    if (heif_image_handle_get_list_of_metadata_block_IDs(handle.get(), "Exif", &exifId, 1) == 1) {
        QByteArray block(static_cast<qsizetype>(heif_image_handle_get_metadata_size(handle.get(), exifId)), '\0');
        if (block.size() > 4 && heif_image_handle_get_metadata(handle.get(), exifId, block.data()).code == heif_error_Ok) {
            const qsizetype offset = qFromBigEndian<quint32>(block.constData());
            if (offset >= 0 && offset < block.size() - 4)
                out.focal35mm = exifFocal35mm(block.mid(4 + offset));
        }
    }
    // libheif reports the size as shown, after the container's rotation.
    out.size = QSize(heif_image_handle_get_width(handle.get()), heif_image_handle_get_height(handle.get()));
    if (out.size.isEmpty()) {
        out.error = ImageError::NotAnImage;
        return out;
    }
    if (static_cast<double>(out.size.width()) * out.size.height() * 4 > kImageAllocationLimitMiB * 1048576.0) {
        out.error = ImageError::Unreadable;
        return out;
    }
    if (!decode)
        return out;
    heif_image *rawImage = nullptr;
    if (heif_decode_image(handle.get(), &rawImage, heif_colorspace_RGB, heif_chroma_interleaved_RGBA, nullptr).code !=
        heif_error_Ok) {
        out.error = ImageError::Unreadable;
        return out;
    }
    const std::unique_ptr<heif_image, decltype(&heif_image_release)> image(rawImage, &heif_image_release);
    int stride = 0;
    const uint8_t *data = heif_image_get_plane_readonly(image.get(), heif_channel_interleaved, &stride);
    const int width = heif_image_get_width(image.get(), heif_channel_interleaved);
    const int height = heif_image_get_height(image.get(), heif_channel_interleaved);
    if (!data || width <= 0 || height <= 0) {
        out.error = ImageError::Unreadable;
        return out;
    }
    // Copied, so the QImage owns its pixels after libheif's image is released.
    out.image = QImage(data, width, height, stride, QImage::Format_RGBA8888).copy();
    out.size = out.image.size();
    if (out.image.isNull())
        out.error = ImageError::Unreadable;
    return out;
}

// The picture at `path`, decoded or only its size: a file, with a format Qt or libheif reads and a size
// in its header, with the file's orientation applied.
ImageRead read(const QString &path, bool decode)
{
    limitAllocation();
    ImageRead out;
    if (!QFileInfo(path).isFile()) {
        out.error = ImageError::NotAFile;
        return out;
    }
    if (isHeif(path))
        return readHeif(path, decode);
    QImageReader reader(path);
    reader.setAutoTransform(true);
    out.size = reader.size();
    if (!reader.canRead() || !out.size.isValid() || out.size.isEmpty()) {
        out.error = ImageError::NotAnImage;
        return out;
    }
    // The header's size is that of the stored pixels; a quarter turn (EXIF orientation 5–8) shows
    // them with width and height swapped, as the decoded picture has them.
    if (reader.transformation() & QImageIOHandler::TransformationRotate90)
        out.size.transpose();
    // A JPEG's EXIF comes before its image data, in its first 64 KiB segment or so. Other formats
    // carry no EXIF Kontur reads: their files are not read twice.
    if (QFile file(path); reader.format() == "jpeg" && file.open(QIODevice::ReadOnly))
        out.focal35mm = exifFocal35mm(jpegExifBlock(file.read(256 * 1024)));
    if (decode) {
        out.image = reader.read();
        if (out.image.isNull())
            out.error = ImageError::Unreadable;
    }
    return out;
}

} // namespace

bool isHeif(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    const QByteArray head = file.read(64);
    if (head.size() < 12)
        return false;
    const heif_filetype_result type =
        heif_check_filetype(reinterpret_cast<const uint8_t *>(head.constData()), static_cast<int>(head.size()));
    // A brand libheif cannot decode is still a HEIF file: reading it says so (NotAnImage), not Qt.
    return type == heif_filetype_yes_supported || type == heif_filetype_yes_unsupported;
}

ImageRead readImageSize(const QString &path)
{
    return read(path, false);
}

ImageRead readImage(const QString &path)
{
    return read(path, true);
}

} // namespace kontur
