// LayerPicture: the canvas's cached layer picture, painted in part or in bands.
#include "app/layerpicture.h"

#include "app/displaylist.h"
#include "app/parallel.h"

#include <QPainter>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace kontur {

namespace {

// Below this many points a whole picture is painted on one thread: starting threads would cost
// more than they save.
constexpr std::size_t kPointsPerThread = 20000;

} // namespace

void LayerPicture::clear()
{
    m_valid = false;
    m_records.clear();
    m_lastPainted = {};
}

void LayerPicture::line(const LayerCurve &curve, std::vector<QPointF> &line, QRect &bounds) const
{
    line.clear();
    bounds = {};
    if (!curve.world)
        return;
    toScreenPolyline(*curve.world, m_frame.view, line);
    if (line.size() < 2)
        return;
    const double margin = m_frame.margin, scale = m_frame.scale;
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (QPointF &point : line) {
        point = (point + QPointF(margin, margin)) * scale;
        minX = std::min(minX, point.x());
        maxX = std::max(maxX, point.x());
        minY = std::min(minY, point.y());
        maxY = std::max(maxY, point.y());
    }
    // The stroke reaches at most 1.2 (w - 1) beyond the line at a sharp turn (paintFastStroke's
    // passes spread over 1.2 w, miters at most twice that; a wide pen w / 2), plus a pixel of
    // anti-aliasing: a little more, rounded out to whole pixels.
    const double reach = 1.2 * m_frame.curveWidth * scale + 2.0;
    const QRectF picture(QPointF(0, 0), m_image.size());
    const QRectF touched = QRectF(QPointF(minX - reach, minY - reach), QPointF(maxX + reach, maxY + reach)) & picture;
    if (!touched.isEmpty())
        bounds = touched.toAlignedRect();
}

LayerPicture::Painted LayerPicture::update(const std::vector<LayerCurve> &curves, const Frame &frame,
                                           const Background &background, bool backgroundChanged, int bands)
{
    m_lastPainted = {};
    const QSize pixels(static_cast<int>(std::ceil((frame.view.size.width() + 2.0 * frame.margin) * frame.scale)),
                       static_cast<int>(std::ceil((frame.view.size.height() + 2.0 * frame.margin) * frame.scale)));
    if (pixels.isEmpty()) {
        clear();
        m_image = QImage();
        return Painted::Nothing;
    }
    const bool whole = !m_valid || backgroundChanged || !(frame == m_frame) || m_image.size() != pixels;
    m_frame = frame;
    if (m_image.size() != pixels)
        m_image = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
    if (!whole && paintPart(curves, background))
        return m_lastPainted.isEmpty() ? Painted::Nothing : Painted::Part;
    paintWhole(curves, background, bands);
    m_valid = true;
    m_lastPainted = QRegion(m_image.rect());
    return Painted::Whole;
}

bool LayerPicture::paintPart(const std::vector<LayerCurve> &curves, const Background &background)
{
    // What changed, by a merge of the curves painted and the curves now (both sorted by key).
    std::vector<Record> next;
    next.reserve(curves.size());
    QRegion dirty;
    std::vector<QPointF> points;
    auto fresh = [&](const LayerCurve &curve) {
        Record record{curve.key, curve.world, curve.color.rgba(), curve.closed, {}};
        line(curve, points, record.bounds);
        dirty += record.bounds;
        next.push_back(std::move(record));
    };
    std::size_t i = 0, j = 0;
    while (i < m_records.size() || j < curves.size()) {
        if (j == curves.size() || (i < m_records.size() && m_records[i].key < curves[j].key)) {
            dirty += m_records[i++].bounds; // no longer in the layer
        } else if (i == m_records.size() || curves[j].key < m_records[i].key) {
            fresh(curves[j++]); // new in the layer
        } else {
            if (m_records[i].sameLook(curves[j])) {
                next.push_back(m_records[i]);
            } else {
                dirty += m_records[i].bounds;
                fresh(curves[j]);
            }
            ++i;
            ++j;
        }
    }
    if (dirty.isEmpty()) {
        m_records = std::move(next);
        return true;
    }
    // Painting a part costs its curves and the clip; beyond a third of the picture the whole is
    // as cheap and is painted in bands.
    qint64 area = 0;
    for (const QRect &rect : dirty)
        area += static_cast<qint64>(rect.width()) * rect.height();
    if (3 * area > static_cast<qint64>(m_image.width()) * m_image.height())
        return false;
    QPainter painter(&m_image);
    painter.setClipRegion(dirty);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    painter.fillRect(dirty.boundingRect(), Qt::transparent);
    painter.setCompositionMode(QPainter::CompositionMode_SourceOver);
    if (background)
        background(painter);
    painter.setRenderHint(QPainter::Antialiasing, true);
    QRect ignored;
    const double width = m_frame.curveWidth * m_frame.scale;
    for (const Record &record : next) {
        if (record.bounds.isEmpty() || !dirty.intersects(record.bounds))
            continue;
        line({record.key, record.world, QColor::fromRgba(record.color), record.closed}, points, ignored);
        paintFastStroke(points, QColor::fromRgba(record.color), width, record.closed, painter);
    }
    m_records = std::move(next);
    m_lastPainted = dirty;
    return true;
}

void LayerPicture::paintWhole(const std::vector<LayerCurve> &curves, const Background &background, int bands)
{
    const std::size_t n = curves.size();
    std::size_t points = 0;
    for (const LayerCurve &curve : curves)
        points += curve.world ? curve.world->size() : 0;
    std::size_t threads = 1;
    if (bands > 0) {
        threads = std::min(static_cast<std::size_t>(bands), cores());
    } else {
        threads = threadsFor(points, kPointsPerThread);
        // More bands than threads, taken in turn: curves are seldom spread evenly.
        bands = threads == 1 ? 1 : 4 * static_cast<int>(threads);
    }
    // The lines in picture pixels, made in parallel (every curve's is needed to know its bands).
    std::vector<std::vector<QPointF>> lines(n);
    m_records.assign(n, Record{});
    {
        std::atomic<std::size_t> nextCurve{0};
        constexpr std::size_t kBatch = 32;
        onThreads(threads, [&] {
            for (std::size_t first; (first = nextCurve.fetch_add(kBatch)) < n;)
                for (std::size_t c = first; c < std::min(first + kBatch, n); ++c) {
                    m_records[c] = {curves[c].key, curves[c].world, curves[c].color.rgba(), curves[c].closed, {}};
                    line(curves[c], lines[c], m_records[c].bounds);
                }
        });
    }
    // The bands: rows of the one picture, each painted by one thread with every curve that
    // reaches it. Each thread paints through its own QImage over the whole picture's memory,
    // clipped to its rows (which no other thread writes): a painter on a band-sized image would
    // clip the lines at its edges and start their rasterization elsewhere, a few levels off.
    uchar *bits = m_image.bits();
    const qsizetype stride = m_image.bytesPerLine();
    const int height = m_image.height(), width = m_image.width();
    const int bandHeight = (height + bands - 1) / bands;
    const double strokeWidth = m_frame.curveWidth * m_frame.scale;
    std::atomic<int> nextBand{0};
    onThreads(threads, [&] {
        for (int b; (b = nextBand.fetch_add(1)) < bands;) {
            const int top = b * bandHeight, bottom = std::min(height, top + bandHeight);
            if (top >= bottom)
                continue;
            std::fill(bits + top * stride, bits + bottom * stride, uchar(0)); // transparent
            QImage whole(bits, width, height, stride, m_image.format());
            const QRect rows(0, top, width, bottom - top);
            QPainter painter(&whole);
            painter.setClipRect(rows);
            if (background)
                background(painter);
            painter.setRenderHint(QPainter::Antialiasing, true);
            for (std::size_t c = 0; c < n; ++c)
                if (m_records[c].bounds.intersects(rows))
                    paintFastStroke(lines[c], curves[c].color, strokeWidth, curves[c].closed, painter);
        }
    });
}

} // namespace kontur
