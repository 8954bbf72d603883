// Pictures as phones write them: a JPEG whose EXIF orientation turns it, a HEIC photo (written here by
// libheif's own encoder), a broken HEIC, each read by picture/picture.h as shown, and the sheet found in
// the photo as it is shown (its corners where the truth has them).
#include "matimage.h"
#include "picture/photomat.h"
#include "picture/picture.h"
#include "synthphoto.h"
#include "vision/sheet.h"

#include <QBuffer>
#include <QFile>
#include <QImageWriter>
#include <QTemporaryDir>
#include <QTest>

#include <libheif/heif.h>

#include <memory>

using namespace kontur;
using vision::test::makeSynthPhoto;
using vision::test::randomSynthOptions;

namespace {

double maxCornerError(const vision::Sheet &sheet, const vision::test::SynthPhoto &photo)
{
    double e = 0;
    for (std::size_t i = 0; i < 4; ++i)
        e = std::max(e, (sheet.corners[i] - photo.sheetCorners[i]).norm());
    return e;
}

// Writes `image` as HEIC with libheif's HEVC encoder; false when it cannot.
bool writeHeic(const QImage &source, const QString &path, const QByteArray &exif = {})
{
    const QImage rgba = source.convertToFormat(QImage::Format_RGBA8888);
    std::unique_ptr<heif_context, decltype(&heif_context_free)> context(heif_context_alloc(), &heif_context_free);
    heif_encoder *encoder = nullptr;
    if (heif_context_get_encoder_for_format(context.get(), heif_compression_HEVC, &encoder).code != heif_error_Ok)
        return false;
    heif_encoder_set_lossy_quality(encoder, 95);
    heif_image *image = nullptr;
    heif_image_create(rgba.width(), rgba.height(), heif_colorspace_RGB, heif_chroma_interleaved_RGBA, &image);
    heif_image_add_plane(image, heif_channel_interleaved, rgba.width(), rgba.height(), 8);
    int stride = 0;
    uint8_t *plane = heif_image_get_plane(image, heif_channel_interleaved, &stride);
    for (int y = 0; y < rgba.height(); ++y)
        std::memcpy(plane + static_cast<std::ptrdiff_t>(y) * stride, rgba.constScanLine(y),
                    static_cast<std::size_t>(rgba.width()) * 4);
    heif_image_handle *handle = nullptr;
    bool encoded = heif_context_encode_image(context.get(), image, encoder, nullptr, &handle).code == heif_error_Ok;
    // libheif writes the 4-byte offset before the block itself.
    if (encoded && !exif.isEmpty())
        encoded = heif_context_add_exif_metadata(context.get(), handle, exif.constData(), static_cast<int>(exif.size()))
                      .code == heif_error_Ok;
    if (handle)
        heif_image_handle_release(handle);
    heif_encoder_release(encoder);
    heif_image_release(image);
    return encoded &&
           heif_context_write_to_file(context.get(), QFile::encodeName(path).constData()).code == heif_error_Ok;
}

// A TIFF-structured EXIF block with IFD0 holding only the Exif IFD pointer, and the Exif IFD only
// FocalLengthIn35mmFilm (a SHORT), in either byte order.
QByteArray exifWithFocal(quint16 focal35, bool littleEndian)
{
    QByteArray b;
    const auto u16 = [&](quint16 v) {
        b.append(static_cast<char>(littleEndian ? v & 0xFF : v >> 8));
        b.append(static_cast<char>(littleEndian ? v >> 8 : v & 0xFF));
    };
    const auto u32 = [&](quint32 v) {
        for (int i = 0; i < 4; ++i)
            b.append(static_cast<char>((v >> (littleEndian ? 8 * i : 24 - 8 * i)) & 0xFF));
    };
    b.append(littleEndian ? QByteArray("II", 2) : QByteArray("MM", 2));
    u16(42);
    u32(8); // IFD0 at 8
    u16(1); // one entry: ExifIFDPointer (LONG) → 26
    u16(0x8769), u16(4), u32(1), u32(26);
    u32(0); // no next IFD; the Exif IFD starts at 8 + 2 + 12 + 4 = 26
    u16(1);
    u16(0xA405), u16(3), u32(1), u16(focal35), u16(0);
    u32(0);
    return b;
}

// A JPEG of `image` with an APP1 "Exif" segment holding `tiff`, right after its start marker.
QByteArray jpegWithExif(const QImage &image, const QByteArray &tiff)
{
    QByteArray jpeg;
    QBuffer buffer(&jpeg);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, "jpg");
    writer.write(image);
    QByteArray app1("\xFF\xE1", 2);
    const int length = 2 + 6 + static_cast<int>(tiff.size());
    app1.append(static_cast<char>(length >> 8)).append(static_cast<char>(length & 0xFF));
    app1.append(QByteArray("Exif\0\0", 6)).append(tiff);
    return jpeg.left(2) + app1 + jpeg.mid(2);
}

} // namespace

class TestPicture final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A phone keeps the sensor's rows and says in EXIF how to turn them (orientation 6: a quarter turn
    // clockwise). Read as shown, the sheet is found where it is in the photo as shown.
    void exifOrientationIsApplied()
    {
        vision::test::SynthOptions o = randomSynthOptions(401);
        o.colour = true;
        o.tableLevel = 165;
        const auto photo = makeSynthPhoto(o);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("turned.jpg"));
        // Stored turned back a quarter, tagged to be turned forward when shown.
        QImageWriter writer(path);
        writer.setQuality(95);
        writer.setTransformation(QImageIOHandler::TransformationRotate90);
        QVERIFY2(writer.write(vision::test::qImageOf(photo.image).transformed(QTransform().rotate(-90))),
                 qPrintable(writer.errorString()));
        const ImageRead read = readImage(path);
        QVERIFY(read.ok());
        QCOMPARE(read.image.size(), QSize(photo.image.cols, photo.image.rows));
        QCOMPARE(readImageSize(path).size, QSize(photo.image.cols, photo.image.rows));
        const auto sheet = vision::findSheet(bgrMat(read.image));
        QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
        const double e = maxCornerError(*sheet, photo);
        qInfo("EXIF-turned JPEG: corner error %.3f px", e);
        QVERIFY(e < 0.5);
    }

    // A phone's EXIF tells the lens's focal length as on 35 mm film (27 mm: a main camera), in either
    // byte order; the focal length in pixels follows for a picture of a camera's proportions (4:3, here)
    // and not for a crop of other proportions, where it would be wrong. A block that lies about its
    // offsets is no focal length, not a crash.
    void exifFocalLengthIsRead()
    {
        QCOMPARE(exifFocal35mm(exifWithFocal(27, true)), 27.0);
        QCOMPARE(exifFocal35mm(exifWithFocal(27, false)), 27.0);
        QCOMPARE(exifFocal35mm(exifWithFocal(0, true)), 0.0); // 0: unknown, says the standard
        QByteArray lying = exifWithFocal(27, true);
        lying[4] = '\x7F'; // IFD0 far beyond the block
        QCOMPARE(exifFocal35mm(lying), 0.0);
        QCOMPARE(exifFocal35mm(lying.left(20)), 0.0);
        QCOMPARE(exifFocal35mm(QByteArray()), 0.0);

        QTemporaryDir dir;
        const auto write = [&](const QString &name, const QImage &image) {
            const QString path = dir.filePath(name);
            QFile file(path);
            if (!file.open(QIODevice::WriteOnly))
                return QString();
            file.write(jpegWithExif(image, exifWithFocal(27, false)));
            return path;
        };
        QImage full(800, 600, QImage::Format_RGB32);
        full.fill(Qt::gray);
        const ImageRead read = readImage(write(QStringLiteral("full.jpg"), full));
        QVERIFY(read.ok());
        QCOMPARE(read.size, QSize(800, 600));
        QCOMPARE(read.focal35mm, 27.0);
        QVERIFY(std::abs(read.focalPx() - 27.0 / 43.2666 * 1000.0) < 0.01);
        QCOMPARE(readImageSize(write(QStringLiteral("size.jpg"), full)).focal35mm, 27.0);
        const ImageRead crop = readImage(write(QStringLiteral("crop.jpg"), full.copy(0, 0, 800, 500)));
        QVERIFY(crop.ok());
        QCOMPARE(crop.focal35mm, 27.0);
        QCOMPARE(crop.focalPx(), 0.0);
        // Without EXIF: nothing known.
        const QString plain = dir.filePath(QStringLiteral("plain.jpg"));
        QVERIFY(full.save(plain));
        QCOMPARE(readImage(plain).focalPx(), 0.0);
    }

    // An iPhone's default format opens: size from the header, pixels as encoded (HEVC is lossy: within
    // a few levels), and the sheet found in it.
    void heicIsRead()
    {
        vision::test::SynthOptions o = randomSynthOptions(402);
        o.colour = true;
        const auto photo = makeSynthPhoto(o);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("photo.heic"));
        QVERIFY(writeHeic(vision::test::qImageOf(photo.image), path, exifWithFocal(26, true)));
        QVERIFY(isHeif(path));
        const ImageRead size = readImageSize(path);
        QVERIFY(size.ok());
        QVERIFY(size.image.isNull());
        QCOMPARE(size.size, QSize(photo.image.cols, photo.image.rows));
        const ImageRead read = readImage(path);
        QVERIFY(read.ok());
        QCOMPARE(read.image.size(), size.size);
        QCOMPARE(read.focal35mm, 26.0); // from the HEIF file's Exif item
        const cv::Mat bgr = bgrMat(read.image);
        cv::Mat diff;
        cv::absdiff(bgr, photo.image, diff);
        const double mean = cv::mean(diff)[0];
        qInfo("HEIC: mean difference %.2f levels", mean);
        QVERIFY(mean < 4.0);
        const auto sheet = vision::findSheet(bgr);
        QVERIFY2(sheet.ok(), sheet.ok() ? "" : sheet.error().message.c_str());
        QVERIFY(maxCornerError(*sheet, photo) < 0.5);
    }

    // A file that starts as HEIC but is not one is refused with a reason, never a crash or a null image
    // taken for a picture; so are a JPEG cut short and a file named .heic that is a PNG (read as PNG).
    void brokenFilesAreRefused()
    {
        QTemporaryDir dir;
        const QString fake = dir.filePath(QStringLiteral("fake.heic"));
        QFile file(fake);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray("\0\0\0\x18"
                              "ftypheic\0\0\0\0mif1heic",
                              24));
        file.write(QByteArray(4000, '\x42'));
        file.close();
        QVERIFY(isHeif(fake));
        QVERIFY(!readImageSize(fake).ok());
        QVERIFY(!readImage(fake).ok());

        const QString png = dir.filePath(QStringLiteral("really-a-png.heic"));
        QImage small(30, 20, QImage::Format_RGB32);
        small.fill(Qt::white);
        QVERIFY(small.save(png, "PNG"));
        QVERIFY(!isHeif(png));
        QCOMPARE(readImage(png).image.size(), QSize(30, 20));

        const QString cut = dir.filePath(QStringLiteral("cut.jpg"));
        QVERIFY(QImage(400, 300, QImage::Format_RGB32).save(cut, "JPEG"));
        QFile jpeg(cut);
        QVERIFY(jpeg.open(QIODevice::ReadWrite));
        jpeg.resize(200);
        jpeg.close();
        const ImageRead read = readImage(cut);
        QVERIFY(!read.ok() || read.image.size() == QSize(400, 300));
    }
};

QTEST_GUILESS_MAIN(TestPicture)
#include "tst_picture.moc"
