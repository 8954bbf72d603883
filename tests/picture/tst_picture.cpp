// Pictures as phones write them: a JPEG whose EXIF orientation turns it, a HEIC photo (written here by
// libheif's own encoder), a broken HEIC, each read by picture/picture.h as shown, and the sheet found in
// the photo as it is shown (its corners where the truth has them).
#include "matimage.h"
#include "picture/photomat.h"
#include "picture/picture.h"
#include "synthphoto.h"
#include "vision/sheet.h"

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
bool writeHeic(const QImage &source, const QString &path)
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
    const bool encoded =
        heif_context_encode_image(context.get(), image, encoder, nullptr, nullptr).code == heif_error_Ok;
    heif_encoder_release(encoder);
    heif_image_release(image);
    return encoded &&
           heif_context_write_to_file(context.get(), QFile::encodeName(path).constData()).code == heif_error_Ok;
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

    // An iPhone's default format opens: size from the header, pixels as encoded (HEVC is lossy: within
    // a few levels), and the sheet found in it.
    void heicIsRead()
    {
        vision::test::SynthOptions o = randomSynthOptions(402);
        o.colour = true;
        const auto photo = makeSynthPhoto(o);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("photo.heic"));
        QVERIFY(writeHeic(vision::test::qImageOf(photo.image), path));
        QVERIFY(isHeif(path));
        const ImageRead size = readImageSize(path);
        QVERIFY(size.ok());
        QVERIFY(size.image.isNull());
        QCOMPARE(size.size, QSize(photo.image.cols, photo.image.rows));
        const ImageRead read = readImage(path);
        QVERIFY(read.ok());
        QCOMPARE(read.image.size(), size.size);
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
