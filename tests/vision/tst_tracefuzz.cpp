// kontur-cli trace on pictures nobody would photograph and on some a phone might: random noise, random
// shapes on a table (a round dot, a lens, a sliver), crops of synthetic photos, tiny pictures, a sheet
// with a round piece beside it (what made a two-knot closed outline that the document refused), and
// random crops of two real phone photos, at random scales (tests/data/realphotos/licensed). Every
// run must end in a document that opens again (exit 0) or in a message of kontur-cli's own (exit 1),
// never a crash, never the document's refusal of what the tracer made.
#include "matimage.h"
#include "synthphoto.h"

#include "io/document.h"

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <opencv2/imgproc.hpp>

#include <random>

using namespace kontur;

namespace {

// One picture of kind seed % 6, drawn from the seed.
cv::Mat picture(std::uint32_t seed)
{
    std::mt19937 rng(seed * 7919u + 3u);
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    switch (seed % 6) {
    case 5: { // a crop of a real photo, enlarged or reduced
        const QString name =
            seed % 12 == 5 ? QStringLiteral("image2scan-test1.jpg") : QStringLiteral("image2scan-test6.jpg");
        const QImage real =
            QImage(QStringLiteral(KONTUR_REAL_PHOTOS "/") + name).convertToFormat(QImage::Format_BGR888);
        if (real.isNull())
            return {}; // everyPictureEndsInADocumentOrAMessage says which
        const cv::Mat m(real.height(), real.width(), CV_8UC3, const_cast<uchar *>(real.constBits()),
                        static_cast<std::size_t>(real.bytesPerLine()));
        const bool whole = seed % 4 == 3; // the whole photo, else a crop
        const int w = whole ? m.cols : static_cast<int>(uniform(16, m.cols));
        const int h = whole ? m.rows : static_cast<int>(uniform(16, m.rows));
        const int x = static_cast<int>(uniform(0, m.cols - w)), y = static_cast<int>(uniform(0, m.rows - h));
        const double scale = uniform(0.3, 3.0);
        cv::Mat crop;
        cv::resize(m(cv::Rect(x, y, w, h)), crop, cv::Size(), scale, scale,
                   scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
        return crop; // a copy: the QImage's pixels go with it
    }
    case 0: { // noise
        cv::Mat m(static_cast<int>(uniform(20, 600)), static_cast<int>(uniform(20, 800)), CV_8UC1);
        cv::randu(m, 0, 256);
        return m;
    }
    case 1: { // shapes on a table, some round and small
        cv::Mat m(600, 800, CV_8UC3, cv::Scalar(uniform(30, 200), uniform(30, 200), uniform(30, 200)));
        const int n = static_cast<int>(uniform(1, 8));
        for (int i = 0; i < n; ++i) {
            const cv::Scalar c(uniform(0, 255), uniform(0, 255), uniform(0, 255));
            const cv::Point at(static_cast<int>(uniform(0, 800)), static_cast<int>(uniform(0, 600)));
            if (uniform(0, 1) < 0.5)
                cv::ellipse(m, at, cv::Size(static_cast<int>(uniform(3, 150)), static_cast<int>(uniform(3, 150))),
                            uniform(0, 180), 0, 360, c, cv::FILLED, cv::LINE_AA);
            else
                cv::rectangle(
                    m, cv::Rect(at, cv::Size(static_cast<int>(uniform(2, 300)), static_cast<int>(uniform(2, 300)))), c,
                    cv::FILLED);
        }
        cv::GaussianBlur(m, m, cv::Size(0, 0), uniform(0.5, 2.0));
        return m;
    }
    case 2: { // a crop of a synthetic photo
        const auto photo = vision::test::makeSynthPhoto(vision::test::randomSynthOptions(seed, cv::Size(1200, 900)));
        const int w = static_cast<int>(uniform(16, 1200)), h = static_cast<int>(uniform(16, 900));
        const int x = static_cast<int>(uniform(0, 1200 - w)), y = static_cast<int>(uniform(0, 900 - h));
        return photo.image(cv::Rect(x, y, w, h)).clone();
    }
    case 3: { // a tiny picture
        cv::Mat m(static_cast<int>(uniform(1, 12)), static_cast<int>(uniform(1, 12)), CV_8UC1);
        cv::randu(m, 0, 256);
        return m;
    }
    default: { // a sheet with a round or lens-shaped piece beside it, or a sliver
        auto o = vision::test::randomSynthOptions(seed, cv::Size(1200, 900));
        o.withPiece = false;
        const auto photo = vision::test::makeSynthPhoto(o);
        cv::Mat m = photo.image.clone();
        const geo::Point right = 0.5 * (photo.sheetCorners[1] + photo.sheetCorners[2]);
        const cv::Point at(static_cast<int>(right.x() + uniform(40, 200)),
                           static_cast<int>(right.y() + uniform(-100, 100)));
        const cv::Size axes(static_cast<int>(uniform(8, 80)), static_cast<int>(uniform(2, 80)));
        cv::ellipse(m, at, axes, uniform(0, 180), 0, 360, cv::Scalar(uniform(150, 240)), cv::FILLED, cv::LINE_AA);
        cv::GaussianBlur(m, m, cv::Size(0, 0), 1.0);
        return m;
    }
    }
}

} // namespace

class TestTraceFuzz final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyPictureEndsInADocumentOrAMessage()
    {
        QTemporaryDir dir;
        int written = 0, refused = 0;
        for (std::uint32_t seed = 1; seed <= 60; ++seed) {
            const QString photo = dir.filePath(QStringLiteral("p%1.png").arg(seed));
            const QString out = dir.filePath(QStringLiteral("p%1.kontur").arg(seed));
            const cv::Mat m = picture(seed);
            QVERIFY2(!m.empty(), qPrintable(QStringLiteral("seed %1: a real photo is missing").arg(seed)));
            QVERIFY(vision::test::qImageOf(m).save(photo));
            QProcess cli;
            cli.start(QStringLiteral(KONTUR_CLI), {QStringLiteral("trace"), QStringLiteral("--json"), photo, out});
            QVERIFY(cli.waitForFinished(60000));
            const QString err = QString::fromUtf8(cli.readAllStandardError());
            QVERIFY2(cli.exitStatus() == QProcess::NormalExit, qPrintable(QStringLiteral("seed %1 crashed").arg(seed)));
            QVERIFY2(cli.exitCode() == 0 || cli.exitCode() == 1,
                     qPrintable(QStringLiteral("seed %1: exit %2: %3").arg(seed).arg(cli.exitCode()).arg(err)));
            if (cli.exitCode() == 0) {
                const auto opened = io::openDocument(out);
                QVERIFY2(opened.ok(), qPrintable(QStringLiteral("seed %1: the document does not open").arg(seed)));
                QVERIFY(!opened->curves.empty());
                ++written;
            } else {
                // kontur-cli's own words about this photo, not the document's refusal of a curve.
                QVERIFY2(err.startsWith(QStringLiteral("kontur-cli: ") + photo), qPrintable(err));
                QVERIFY2(!err.contains(QStringLiteral("cannot be saved")), qPrintable(err));
                QVERIFY(!QFile::exists(out));
                ++refused;
            }
        }
        qInfo("%d documents written, %d photos refused with a message", written, refused);
        QVERIFY(written > 0); // the sheets with a piece beside them
    }
};

QTEST_GUILESS_MAIN(TestTraceFuzz)
#include "tst_tracefuzz.moc"
