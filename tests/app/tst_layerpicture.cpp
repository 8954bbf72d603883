// The canvas's layer picture without a window: a picture painted in bands on several threads is
// the picture painted on one, and a picture brought up to changed curves by painting only their
// pixels is the picture painted whole from the new curves, pixel for pixel, over random curves,
// changes, widths and pixel ratios. And its input: curves flattened in parallel are the curves
// flattened one by one.
#include "app/displaylist.h"
#include "app/flatcache.h"
#include "app/layerpicture.h"
#include "app/scenebuilder.h"
#include "geometry/composite.h"
#include "geometry/polyline.h"
#include "models/document/curve.h"

#include <QPainter>
#include <QTest>

#include <cmath>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

using namespace kontur;

namespace {

using Polyline = std::shared_ptr<const std::vector<geo::Point>>;

// An area that holds every test curve: nothing is left out of the flattenings.
const QRectF everywhere(-1e300, -1e300, 2e300, 2e300);

// The distance from p to the (open) polyline.
double distanceToPolyline(const geo::Point &p, const std::vector<geo::Point> &line)
{
    return (geo::nearestOnPolyline(line, p, false).point - p).norm();
}

// A wavy open or closed line of about 60 points around a random centre in the world square
// ±span: turns sharp enough to test the miters.
Polyline randomLine(std::mt19937_64 &rng, double span, bool closed)
{
    std::uniform_real_distribution<double> where(-span, span), size(0.02 * span, 0.2 * span), turn(0.0, 6.283);
    const double cx = where(rng), cy = where(rng), r = size(rng), phase = turn(rng);
    auto points = std::make_shared<std::vector<geo::Point>>();
    const int n = 60;
    for (int k = 0; k < n; ++k) {
        const double t = closed ? 6.283185307179586 * k / n : 3.0 * k / n;
        const double wobble = 1.0 + 0.3 * std::sin(7.0 * t + phase);
        if (closed)
            points->emplace_back(cx + r * wobble * std::cos(t), cy + r * wobble * std::sin(t));
        else
            points->emplace_back(cx + r * (t - 1.5), cy + r * 0.5 * wobble * std::sin(3.0 * t + phase));
    }
    return points;
}

QColor randomColor(std::mt19937_64 &rng)
{
    std::uniform_int_distribution<int> channel(0, 255), alpha(120, 255);
    return QColor(channel(rng), channel(rng), channel(rng), alpha(rng));
}

std::vector<LayerCurve> randomCurves(std::mt19937_64 &rng, std::size_t count, double span)
{
    std::vector<LayerCurve> curves;
    for (std::size_t c = 0; c < count; ++c) {
        const bool closed = rng() % 3 == 0;
        curves.push_back({c, randomLine(rng, span, closed), randomColor(rng), closed});
    }
    return curves;
}

// The grid under the curves, as the canvas paints it into the picture.
LayerPicture::Background gridOf(const LayerPicture::Frame &frame)
{
    return [frame](QPainter &painter) {
        DisplayList lines;
        const QSizeF size = frame.view.size + QSizeF(2 * frame.margin, 2 * frame.margin);
        addGrid(lines, ViewState{frame.view.zoom, frame.view.center, size}, QColor(200, 200, 200), QColor(90, 90, 90));
        painter.save();
        painter.scale(frame.scale, frame.scale);
        paint(lines, painter);
        painter.restore();
    };
}

// How many pixels differ, and by how much at most (in any channel).
std::pair<qsizetype, int> difference(const QImage &a, const QImage &b)
{
    if (a.size() != b.size() || a.format() != b.format())
        return {-1, 256};
    qsizetype pixels = 0;
    int most = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto *p = reinterpret_cast<const QRgb *>(a.constScanLine(y));
        const auto *q = reinterpret_cast<const QRgb *>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            if (p[x] != q[x]) {
                ++pixels;
                most = std::max({most, std::abs(qRed(p[x]) - qRed(q[x])), std::abs(qGreen(p[x]) - qGreen(q[x])),
                                 std::abs(qBlue(p[x]) - qBlue(q[x])), std::abs(qAlpha(p[x]) - qAlpha(q[x]))});
            }
    }
    return {pixels, most};
}

// Ink: pixels not transparent.
qsizetype inked(const QImage &image)
{
    qsizetype count = 0;
    for (int y = 0; y < image.height(); ++y) {
        const auto *p = reinterpret_cast<const QRgb *>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            count += qAlpha(p[x]) != 0;
    }
    return count;
}

} // namespace

class TestLayerPicture final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void bandsPaintWhatOneThreadPaints_data()
    {
        QTest::addColumn<double>("scale");
        QTest::addColumn<float>("width");
        QTest::addColumn<double>("span");
        QTest::newRow("1x, 2 px, world 1") << 1.0 << 2.0F << 1.0;
        QTest::newRow("2x, 2 px, world 1e4") << 2.0 << 2.0F << 1e4;
        QTest::newRow("1.5x, 3 px, world 1e-3") << 1.5 << 3.0F << 1e-3;
        QTest::newRow("1x, 6 px (wide pen), world 100") << 1.0 << 6.0F << 100.0;
    }

    void bandsPaintWhatOneThreadPaints()
    {
        QFETCH(double, scale);
        QFETCH(float, width);
        QFETCH(double, span);
        std::mt19937_64 rng(7);
        const std::vector<LayerCurve> curves = randomCurves(rng, 300, span);
        // The world square fills the 400 × 300 view.
        const LayerPicture::Frame frame{{300.0 / (2.0 * span), QPointF(0, 0), QSizeF(400, 300)}, 40.0, scale, width};
        LayerPicture one, banded;
        QCOMPARE(one.update(curves, frame, gridOf(frame), false, 1), LayerPicture::Painted::Whole);
        QVERIFY(inked(one.image()) > one.image().width() * one.image().height() / 4);
        for (const int bands : {2, 3, 7, 16}) {
            banded.clear();
            QCOMPARE(banded.update(curves, frame, gridOf(frame), false, bands), LayerPicture::Painted::Whole);
            const auto [pixels, most] = difference(one.image(), banded.image());
            QVERIFY2(
                pixels == 0,
                qPrintable(QStringLiteral("%1 bands: %2 pixels differ, by up to %3").arg(bands).arg(pixels).arg(most)));
        }
    }

    // Curves leave, arrive, change colour or shape: painting only their pixels gives what
    // painting the whole picture from the new curves gives.
    void partEqualsWhole_data()
    {
        QTest::addColumn<double>("scale");
        QTest::addColumn<float>("width");
        QTest::addColumn<bool>("grid");
        QTest::newRow("1x, 2 px, grid") << 1.0 << 2.0F << true;
        QTest::newRow("2x, 2 px") << 2.0 << 2.0F << false;
        QTest::newRow("1.25x, 4 px, grid") << 1.25 << 4.0F << true;
        QTest::newRow("1x, 8 px (wide pen)") << 1.0 << 8.0F << false;
    }

    void partEqualsWhole()
    {
        QFETCH(double, scale);
        QFETCH(float, width);
        QFETCH(bool, grid);
        std::mt19937_64 rng(11);
        const double span = 50.0;
        const LayerPicture::Frame frame{{300.0 / (2.0 * span), QPointF(3, -2), QSizeF(400, 300)}, 30.0, scale, width};
        const LayerPicture::Background background = grid ? gridOf(frame) : LayerPicture::Background();
        std::vector<LayerCurve> curves = randomCurves(rng, 200, span);
        LayerPicture kept;
        QCOMPARE(kept.update(curves, frame, background, false), LayerPicture::Painted::Whole);
        QCOMPARE(kept.update(curves, frame, background, false), LayerPicture::Painted::Nothing);
        QVERIFY(kept.lastPainted().isEmpty());
        int parts = 0;
        for (int round = 0; round < 40; ++round) {
            // One to three changes, as a selection change (one leaves, one returns) or an edit.
            const int changes = 1 + static_cast<int>(rng() % 3);
            std::vector<std::size_t> touched;
            for (int k = 0; k < changes; ++k) {
                const std::size_t at = rng() % curves.size();
                touched.push_back(curves[at].key);
                switch (rng() % 4) {
                case 0: // leaves the layer (selected)
                    curves.erase(curves.begin() + static_cast<std::ptrdiff_t>(at));
                    break;
                case 1: // a curve returns (deselected) or is added, at a free key
                {
                    std::size_t key = 1000 + rng() % 1000;
                    while (std::any_of(curves.begin(), curves.end(), [&](const LayerCurve &c) { return c.key == key; }))
                        ++key;
                    const bool closed = rng() % 2 == 0;
                    curves.push_back({key, randomLine(rng, span, closed), randomColor(rng), closed});
                    std::sort(curves.begin(), curves.end(),
                              [](const LayerCurve &a, const LayerCurve &b) { return a.key < b.key; });
                    break;
                }
                case 2: // another colour
                    curves[at].color = randomColor(rng);
                    break;
                default: // edited: flattened anew
                    curves[at].world = randomLine(rng, span, curves[at].closed);
                    break;
                }
            }
            const LayerPicture::Painted painted = kept.update(curves, frame, background, false);
            QVERIFY(painted != LayerPicture::Painted::Nothing);
            parts += painted == LayerPicture::Painted::Part ? 1 : 0;
            if (painted == LayerPicture::Painted::Part) {
                const QRect all = kept.image().rect();
                qint64 area = 0;
                for (const QRect &rect : kept.lastPainted())
                    area += static_cast<qint64>(rect.width()) * rect.height();
                QVERIFY2(3 * area <= static_cast<qint64>(all.width()) * all.height(), "a part is at most a third");
            }
            LayerPicture fresh;
            fresh.update(curves, frame, background, false, 1);
            const auto [pixels, most] = difference(kept.image(), fresh.image());
            QVERIFY2(
                pixels == 0,
                qPrintable(QStringLiteral("round %1: %2 pixels differ, by up to %3").arg(round).arg(pixels).arg(most)));
        }
        // Most rounds changed few enough pixels to be painted in part.
        QVERIFY2(parts >= 30, qPrintable(QString::number(parts)));
    }

    // A new frame (the view moved, another pixel ratio or width) or a new background paints the
    // whole picture; many changed curves do too.
    void wholeWhenTheFrameChanges()
    {
        std::mt19937_64 rng(3);
        std::vector<LayerCurve> curves = randomCurves(rng, 100, 10.0);
        LayerPicture::Frame frame{{15.0, QPointF(0, 0), QSizeF(400, 300)}, 20.0, 1.0, 2.0F};
        LayerPicture picture;
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
        QCOMPARE(picture.update(curves, frame, {}, true), LayerPicture::Painted::Whole);
        frame.view.center = QPointF(1, 0);
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
        frame.scale = 2.0;
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
        QCOMPARE(picture.image().size(), QSize(880, 680));
        frame.curveWidth = 3.0F;
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
        for (LayerCurve &curve : curves)
            curve.color = QColor(10, 20, 30);
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
        curves.erase(curves.begin());
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Part);
        // The part painted holds the pixels the removed curve had.
        QVERIFY(!picture.lastPainted().isEmpty());
        picture.clear();
        QCOMPARE(picture.update(curves, frame, {}, false), LayerPicture::Painted::Whole);
    }

    // 400 composite curves of 40 segments (16,000: several threads) at scales 1e-3…1e3.
    void flattenedInParallelAsOneByOne()
    {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<Curve> curves;
        for (int c = 0; c < 400; ++c) {
            const double scale = std::pow(10.0, -3 + c % 7);
            std::vector<geo::Point> knots;
            for (int k = 0; k <= 40; ++k)
                knots.emplace_back(scale * (k + 0.3 * unit(rng)), scale * unit(rng));
            auto made = Curve::makeComposite(geo::CompositeCurve(knots));
            QVERIFY(made.ok());
            curves.push_back(made.value());
        }
        std::vector<std::size_t> all(curves.size());
        std::iota(all.begin(), all.end(), std::size_t{0});
        for (const double zoom : {1e-2, 3.0, 1e4}) {
            FlatCache parallel, serial;
            parallel.resize(curves.size());
            serial.resize(curves.size());
            QCOMPARE(parallel.ensureMany(all, curves, zoom, everywhere), curves.size());
            for (std::size_t c = 0; c < curves.size(); ++c) {
                QVERIFY(serial.ensure(c, curves[c], zoom, everywhere));
                QVERIFY(parallel.world(c));
                QVERIFY(*parallel.world(c) == *serial.world(c));
                // Versions increase in the order given, as one by one.
                QCOMPARE(parallel.version(c), serial.version(c));
                QVERIFY(!parallel.stale(c, curves[c], zoom, everywhere));
            }
            // Within the zoom band nothing is redone; beyond it, every curve.
            QCOMPARE(parallel.ensureMany(all, curves, 1.9 * zoom, everywhere), std::size_t{0});
            QCOMPARE(parallel.ensureMany(all, curves, 2.1 * zoom, everywhere), curves.size());
            parallel.invalidate(7);
            QCOMPARE(parallel.ensureMany(all, curves, 2.1 * zoom, everywhere), std::size_t{1});
        }
    }

    // A curve whose control points' box holds the view but whose line passes far from it (an arc
    // of 1e150 or 1e300 around a view at zoom 1) is a handful of chords, not 4 million points at
    // an eighth of a pixel (3 to 9 s a frame); a curve across the view is exact (within the eighth
    // of a pixel) where it is seen; pans within a view reuse the flattening, farther ones redo it.
    void curvesOutOfSightNotFlattened()
    {
        const QRectF view(-400, -300, 800, 600);
        for (const double scale : {1e150, 1e300}) {
            const Curve far = Curve::make(
                CurveKind::Bezier,
                {{-scale / 2, -scale / 2}, {-scale / 2, scale}, {scale / 2, scale}, {scale / 2, -scale / 2}});
            std::vector<Curve> curves{far};
            FlatCache cache;
            cache.resize(1);
            QVERIFY(cache.meets(0, far, view)); // its box holds the view: not culled as a whole
            QVERIFY(cache.ensure(0, far, 1.0, view));
            QVERIFY(cache.world(0));
            QVERIFY2(cache.world(0)->size() < 5000, qPrintable(QString::number(cache.world(0)->size())));
            QVERIFY(cache.pointsMade() < 5000);
            QCOMPARE(cache.ensureMany({0}, curves, 1.0, view), std::size_t{0});
        }

        // Through the view: the curve at t = 1/2 is (0, 5e5), where the view is.
        const Curve across = Curve::make(CurveKind::Bezier, {{-1e6, -1e6}, {-3e5, 1e6}, {3e5, 1e6}, {1e6, -1e6}});
        const QRectF seen = view.translated(0, 5e5);
        FlatCache cache;
        cache.resize(1);
        QVERIFY(cache.ensure(0, across, 1.0, seen));
        const std::vector<geo::Point> &line = *cache.world(0);
        QVERIFY2(line.size() < 20000, qPrintable(QString::number(line.size())));
        const geo::Bezier exact = across.segment(0);
        int inView = 0;
        for (int k = 0; k <= 200000; ++k) {
            const geo::Point p = exact.eval(k / 200000.0);
            if (!seen.contains(QPointF(p.x(), p.y())))
                continue;
            ++inView;
            QVERIFY2(distanceToPolyline(p, line) <= 0.125, qPrintable(QString::number(distanceToPolyline(p, line))));
        }
        QVERIFY(inView > 50);
        QVERIFY(!cache.ensure(0, across, 1.0, seen.translated(400, 0)));
        QVERIFY(cache.ensure(0, across, 1.0, seen.translated(5000, 0)));
    }
};

QTEST_MAIN(TestLayerPicture)
#include "tst_layerpicture.moc"
