// The synthetic photo: scene geometry in mm, a pinhole camera, supersampled rendering, then the
// sensor's blur, vignetting, noise and JPEG-like quantisation.
#include "synthphoto.h"
#include "segmentgrid.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

namespace kontur::vision::test {
namespace {

using geo::Point;

Point cubicAt(const std::array<Point, 4> &c, double t)
{
    const double u = 1 - t;
    return u * u * u * c[0] + 3 * u * u * t * c[1] + 3 * u * t * t * c[2] + t * t * t * c[3];
}

std::array<Point, 4> lineAsCubic(const Point &a, const Point &b)
{
    return {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b};
}

// Smooth value noise on a lattice of `period` mm, deterministic in the seed.
double valueNoise(double x, double y, double period, std::uint32_t seed)
{
    const auto hash = [seed](int i, int j) {
        std::uint32_t h =
            static_cast<std::uint32_t>(i) * 73856093u ^ static_cast<std::uint32_t>(j) * 19349663u ^ seed * 83492791u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return (h & 0xffff) / 65535.0 * 2.0 - 1.0;
    };
    const double fx = x / period, fy = y / period;
    const int i = static_cast<int>(std::floor(fx)), j = static_cast<int>(std::floor(fy));
    double u = fx - i, v = fy - j;
    u = u * u * (3 - 2 * u);
    v = v * v * (3 - 2 * v);
    const double a = hash(i, j) + u * (hash(i + 1, j) - hash(i, j));
    const double b = hash(i, j + 1) + u * (hash(i + 1, j + 1) - hash(i, j + 1));
    return a + v * (b - a);
}

// A wooden table: grain stripes bent by low-frequency noise, knots of darker wood, fine noise.
double tableAt(double x, double y, std::uint32_t seed, double contrast, double level)
{
    const double bend = 8.0 * valueNoise(x, y, 90.0, seed + 1);
    const double grain = std::sin(2 * M_PI * (y + bend) / 7.0);
    return level +
           contrast * (22.0 * grain + 18.0 * valueNoise(x, y, 25.0, seed + 2) + 8.0 * valueNoise(x, y, 2.0, seed + 3));
}

// The bodice: seven knots (sharp corners between them), straight shoulder, side seam, centre front and
// part of the waist, curved armhole, waist and neckline. Local mm, y down.
void buildPiece(SynthPhoto &out, const SynthOptions &o, double left, double top)
{
    const std::array<Point, 7> k{Point(70, 0),    Point(185, 30), Point(205, 155), Point(190, 350),
                                 Point(100, 362), Point(0, 355),  Point(0, 85)};
    std::vector<std::array<Point, 4>> segs{
        lineAsCubic(k[0], k[1]),
        {k[1], Point(172, 80), Point(168, 150), k[2]},
        lineAsCubic(k[2], k[3]),
        {k[3], Point(160, 362), Point(130, 368), k[4]},
        lineAsCubic(k[4], k[5]),
        lineAsCubic(k[5], k[6]),
        {k[6], Point(40, 85), Point(68, 45), k[0]},
    };
    out.segmentIsLine = {true, false, true, false, true, true, false};
    const Point centre(102, 181);
    const double a = o.pieceRotationDeg * M_PI / 180.0;
    const Eigen::Rotation2Dd rot(a);
    const Point place(left + 102, top + 181);
    const auto toWorld = [&](const Point &p) { return Point(rot * (p - centre) + place); };
    out.pieceSegments.clear();
    for (auto s : segs) {
        for (auto &p : s)
            p = toWorld(p);
        out.pieceSegments.push_back(s);
    }
    out.pieceKnots = static_cast<int>(segs.size());
    out.grainline = {toWorld(Point(100, 130)), toWorld(Point(100, 300))};
    out.pieceOutline.clear();
    for (const auto &s : out.pieceSegments) {
        double length = 0;
        for (int i = 0; i < 3; ++i)
            length += (s[i + 1] - s[i]).norm();
        const int n = std::max(4, static_cast<int>(std::ceil(length / 0.2)));
        for (int i = 0; i < n; ++i)
            out.pieceOutline.push_back(cubicAt(s, static_cast<double>(i) / n));
    }
    // The gap is measured from the rotated piece: its leftmost point lies at `left`.
    double minX = INFINITY;
    for (const auto &p : out.pieceOutline)
        minX = std::min(minX, p.x());
    const Point shift(left - minX, 0);
    for (auto &p : out.pieceOutline)
        p += shift;
    for (auto &seg : out.pieceSegments)
        for (auto &p : seg)
            p += shift;
    for (auto &p : out.grainline)
        p += shift;
}

} // namespace

SynthOptions randomSynthOptions(std::uint32_t seed, cv::Size size)
{
    std::mt19937 rng(seed * 2654435761u + 7u);
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    SynthOptions o;
    o.seed = seed;
    o.size = size;
    o.tiltDeg = uniform(20, 45);
    o.yawDeg = uniform(-10, 10);
    o.rollDeg = uniform(-4, 4);
    o.blurSigmaPx = uniform(0.6, 1.6);
    o.noiseSigma = uniform(1, 4);
    o.vignetting = uniform(0, 0.35);
    o.whitePiece = uniform(0, 1) < 0.5;
    o.gapMm = uniform(15, 60);
    o.pieceRotationDeg = uniform(-6, 6);
    o.tableTexture = uniform(0.3, 1.0);
    return o;
}

namespace {

// World (table plane, mm) → photo px of a pinhole camera aimed at `target`, as close as it can be while
// `content` stays inside the photo with a 5 % margin.
Homography cameraHomography(const SynthOptions &o, const Eigen::AlignedBox2d &content)
{
    const double f = o.focalPx > 0 ? o.focalPx : 0.75 * o.size.width;
    const double tilt = o.tiltDeg * M_PI / 180, yaw = o.yawDeg * M_PI / 180, roll = o.rollDeg * M_PI / 180;
    const Eigen::Vector3d back0(0, std::sin(tilt), std::cos(tilt)); // from the target towards the camera
    Eigen::Vector3d right(1, 0, 0), down(0, std::cos(tilt), -std::sin(tilt));
    const Eigen::Vector3d r1 = std::cos(roll) * right + std::sin(roll) * down;
    down = -std::sin(roll) * right + std::cos(roll) * down;
    right = r1;
    const Eigen::Matrix3d rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d back = rz * back0, forward = -back;
    right = rz * right;
    down = rz * down;
    const Point c2 = content.center();
    const Eigen::Vector3d target(c2.x(), c2.y(), 0);
    Eigen::Matrix3d k;
    k << f, 0, 0.5 * (o.size.width - 1) + o.principalShift.x() * o.size.width, 0, f,
        0.5 * (o.size.height - 1) + o.principalShift.y() * o.size.height, 0, 0, 1;
    const auto homographyAt = [&](double dist) {
        const Eigen::Vector3d cam = target + dist * back;
        Eigen::Matrix3d m;
        m << right.x(), right.y(), -right.dot(cam), down.x(), down.y(), -down.dot(cam), forward.x(), forward.y(),
            -forward.dot(cam);
        return Homography(k * m);
    };
    const auto fits = [&](double dist) {
        const Homography h = homographyAt(dist);
        const double mx = 0.05 * o.size.width, my = 0.05 * o.size.height;
        for (const auto corner : {Eigen::AlignedBox2d::BottomLeft, Eigen::AlignedBox2d::BottomRight,
                                  Eigen::AlignedBox2d::TopLeft, Eigen::AlignedBox2d::TopRight}) {
            const Point c = content.corner(corner);
            if (homogeneousW(h, c) <= 0)
                return false;
            const Point p = apply(h, c);
            if (p.x() < mx || p.y() < my || p.x() > o.size.width - 1 - mx || p.y() > o.size.height - 1 - my)
                return false;
        }
        return true;
    };
    double lo = 10, hi = 50000;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return homographyAt(hi);
}

// Blockwise 8x8 DCT with the coefficients rounded to multiples of `step` (DC to half of it): the
// ringing and blocking of a JPEG of middling quality.
void quantiseLikeJpeg(cv::Mat &img, double step)
{
    for (int y = 0; y + 8 <= img.rows; y += 8)
        for (int x = 0; x + 8 <= img.cols; x += 8) {
            cv::Mat block = img(cv::Rect(x, y, 8, 8)), coeffs;
            cv::dct(block, coeffs);
            for (int i = 0; i < 64; ++i) {
                const double q = i == 0 ? 0.5 * step : step;
                float &c = coeffs.at<float>(i / 8, i % 8);
                c = static_cast<float>(std::round(c / q) * q);
            }
            cv::idct(coeffs, block);
        }
}

} // namespace

Point lensUndistorted(const SynthOptions &o, Point photoPx)
{
    if (o.radialK1 == 0)
        return photoPx;
    const Point c(0.5 * (o.size.width - 1), 0.5 * (o.size.height - 1));
    const double r2 = (photoPx - c).squaredNorm() /
                      (0.25 * (double(o.size.width) * o.size.width + double(o.size.height) * o.size.height));
    return c + (1 + o.radialK1 * r2) * (photoPx - c);
}

Point lensDistorted(const SynthOptions &o, Point pinholePx)
{
    if (o.radialK1 == 0)
        return pinholePx;
    // Fixed-point iteration of p = c + (u - c) / (1 + k1 r(p)^2): a contraction for the small k1 of a lens.
    const Point c(0.5 * (o.size.width - 1), 0.5 * (o.size.height - 1));
    const double norm = 0.25 * (double(o.size.width) * o.size.width + double(o.size.height) * o.size.height);
    Point p = pinholePx;
    for (int i = 0; i < 100; ++i)
        p = c + (pinholePx - c) / (1 + o.radialK1 * (p - c).squaredNorm() / norm);
    return p;
}

namespace {

// The marks of SynthOptions::pieceMarks: V notches cut into `edge` (the outline's dense polygon, its
// points replaced by the notch's mouth and tip), the slits' strokes, the drill holes; `inwardSign`
// turns the polygon's left normal into the piece.
void markPiece(SynthPhoto &out, std::vector<Point> &edge, std::vector<Segment> &slits, double inwardSign)
{
    const std::size_t n = edge.size();
    std::vector<double> arc(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
        arc[i] = arc[i - 1] + (edge[i] - edge[i - 1]).norm();
    const auto nearest = [&](const Point &p) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < n; ++i)
            if ((edge[i] - p).squaredNorm() < (edge[best] - p).squaredNorm())
                best = i;
        return best;
    };
    const auto inwardAt = [&](std::size_t i) {
        const Point d = edge[(i + 1) % n] - edge[(i + n - 1) % n];
        return Point(inwardSign * Point(-d.y(), d.x()).normalized());
    };
    const std::size_t v1 = nearest(cubicAt(out.pieceSegments[3], 0.5));
    const std::size_t v2 = nearest(cubicAt(out.pieceSegments[5], 0.4));
    const std::size_t slit = nearest(cubicAt(out.pieceSegments[0], 0.5));
    out.notches = {{edge[v1], inwardAt(v1), true}, {edge[v2], inwardAt(v2), true}, {edge[slit], inwardAt(slit), false}};
    slits.push_back({edge[slit] - 0.3 * inwardAt(slit), edge[slit] + 5.0 * inwardAt(slit)});
    const auto [g0, g1] = out.grainline;
    const Point gd = (g1 - g0).normalized();
    out.drillHoles = {0.5 * (g0 + g1) + 25.0 * Point(-gd.y(), gd.x())};
    // The V notches, the later one first so that the earlier one's indices hold.
    for (const std::size_t at : {std::max(v1, v2), std::min(v1, v2)}) {
        std::size_t a = at, b = at;
        while (a > 0 && arc[at] - arc[a] < 2.5)
            --a;
        while (b + 1 < n && arc[b] - arc[at] < 2.5)
            ++b;
        const Point tip = edge[at] + 5.0 * inwardAt(at);
        edge.erase(edge.begin() + static_cast<std::ptrdiff_t>(a + 1), edge.begin() + static_cast<std::ptrdiff_t>(b));
        edge.insert(edge.begin() + static_cast<std::ptrdiff_t>(a + 1), tip);
    }
}

} // namespace

SynthPhoto makeSynthPhoto(const SynthOptions &o)
{
    SynthPhoto out;
    const double w = o.sheetMm.x(), h = o.sheetMm.y();
    buildPiece(out, o, w + o.gapMm, 0.5 * h - 181);
    Eigen::AlignedBox2d content(Point(-10, -10), Point(w + 10, h + 10));
    if (o.withPiece)
        for (const auto &p : out.pieceOutline)
            content.extend(p + Point(10, 10)), content.extend(p - Point(10, 10));
    out.worldToPhoto = cameraHomography(o, content);
    out.sheetCorners = {
        lensDistorted(o, apply(out.worldToPhoto, Point(0, 0))), lensDistorted(o, apply(out.worldToPhoto, Point(w, 0))),
        lensDistorted(o, apply(out.worldToPhoto, Point(w, h))), lensDistorted(o, apply(out.worldToPhoto, Point(0, h)))};

    double area = 0;
    for (std::size_t i = 0; i < out.pieceOutline.size(); ++i) {
        const Point &a = out.pieceOutline[i], &b = out.pieceOutline[(i + 1) % out.pieceOutline.size()];
        area += a.x() * b.y() - a.y() * b.x();
    }
    // The paper's edge, with the V notches cut into it; slits and drill holes are drawn.
    std::vector<Point> paperEdge = out.pieceOutline;
    std::vector<Segment> slits;
    if (o.pieceMarks && o.withPiece)
        markPiece(out, paperEdge, slits, area > 0 ? 1.0 : -1.0);
    SegmentGrid piece(polylineSegments(paperEdge, true), 0.0, 1.0);
    piece.classifyCentres();
    std::optional<SegmentGrid> slitGrid;
    if (!slits.empty())
        slitGrid.emplace(slits, 0.15, 2.0);
    Eigen::AlignedBox2d pieceBox;
    for (const auto &p : out.pieceOutline)
        pieceBox.extend(p);
    // The grainline with its arrowheads, and a pencil line 2 mm inside the armhole and the side seam.
    const auto [g0, g1] = out.grainline;
    const Point gd = (g1 - g0).normalized(), gn(-gd.y(), gd.x());
    std::vector<Segment> grain{{g0, g1},
                               {g0, g0 + 8 * gd + 3 * gn},
                               {g0, g0 + 8 * gd - 3 * gn},
                               {g1, g1 - 8 * gd + 3 * gn},
                               {g1, g1 - 8 * gd - 3 * gn}};
    if (o.pieceMarks && o.withPiece && o.foldBracket) {
        // The centre front (segment 5) is the fold; the bracket's bar 12 mm inside over its middle half,
        // a leg from each end of the bar to an arrow whose point lies 1 mm short of the edge.
        const Point a = out.pieceSegments[5][0], b = out.pieceSegments[5][3];
        out.fold = std::array<Point, 2>{a, b};
        const Point along = (b - a).normalized();
        const Point in = (area > 0 ? 1.0 : -1.0) * Point(-along.y(), along.x());
        const Point from = a + 0.25 * (b - a), to = a + 0.75 * (b - a);
        grain.push_back({from + 12.0 * in, to + 12.0 * in});
        for (const Point &end : {from, to}) {
            const Point tip = end + 1.0 * in;
            grain.push_back({end + 12.0 * in, tip});
            grain.push_back({tip, tip + 5.0 * in + 2.0 * along});
            grain.push_back({tip, tip + 5.0 * in - 2.0 * along});
        }
    }
    std::vector<Point> pencil;
    for (const int s : {1, 2}) {
        const auto &c = out.pieceSegments[s];
        for (int i = 0; i <= 400; ++i) {
            const double t = i / 400.0, u = 1 - t;
            const Point d = u * u * (c[1] - c[0]) + 2 * u * t * (c[2] - c[1]) + t * t * (c[3] - c[2]);
            const Point inward = (area > 0 ? 1.0 : -1.0) * Point(-d.y(), d.x()).normalized();
            pencil.push_back(cubicAt(c, t) + 2.0 * inward);
        }
    }
    const SegmentGrid grainGrid(grain, 0.35, 2.0), pencilGrid(polylineSegments(pencil, false), 0.25, 2.0);

    // A dark line printed along the whole outline, `outlineInkInsetMm` inside it (a printed pattern).
    std::vector<Point> ink;
    for (std::size_t i = 0; o.outlineInkWidthMm > 0 && i < out.pieceOutline.size(); ++i) {
        const std::size_t n = out.pieceOutline.size();
        const Point d = out.pieceOutline[(i + 1) % n] - out.pieceOutline[(i + n - 1) % n];
        const Point inward = (area > 0 ? 1.0 : -1.0) * Point(-d.y(), d.x()).normalized();
        ink.push_back(out.pieceOutline[i] + o.outlineInkInsetMm * inward);
    }
    std::optional<SegmentGrid> inkGrid;
    if (!ink.empty())
        inkGrid.emplace(polylineSegments(ink, true), 0.5 * o.outlineInkWidthMm + 0.1, 2.0);

    const Homography inv = out.worldToPhoto.inverse();
    const double visibleSign = (inv * Eigen::Vector3d(0.5 * (o.size.width - 1), o.size.height - 1.0, 1)).z();
    const int s = std::max(1, o.supersample);
    const double pieceValue = o.whitePiece ? 226.0 : 188.0;
    const int channels = o.colour ? 3 : 1;
    const cv::Vec3d white(1, 1, 1), kraft(0.78, 0.92, 1.06), inkTint(1, 1, 1);
    const Point shadowDir = (o.shadowToMm - o.shadowFromMm).normalized();
    cv::Mat img(o.size, CV_32FC(channels));
    cv::parallel_for_(cv::Range(0, o.size.height), [&](const cv::Range &rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            float *row = img.ptr<float>(y);
            for (int x = 0; x < o.size.width; ++x) {
                float *px = row + static_cast<std::ptrdiff_t>(x) * channels;
                const Point uc = lensUndistorted(o, Point(x, y));
                const Eigen::Vector3d qc = inv * Eigen::Vector3d(uc.x(), uc.y(), 1);
                if (qc.z() * visibleSign <= 0) {
                    for (int c = 0; c < channels; ++c)
                        px[c] = 180.0f; // sky beyond the table's horizon
                    continue;
                }
                const Point wc = qc.head<2>() / qc.z();
                const double table = tableAt(wc.x(), wc.y(), o.seed, o.tableTexture, o.tableLevel);
                const double paper = 2.5 * valueNoise(wc.x(), wc.y(), 3.0, o.seed + 5);
                double light = 1.0;
                if (o.shadowDepth > 0) {
                    const Point r = wc - o.shadowFromMm;
                    const double side = r.x() * shadowDir.y() - r.y() * shadowDir.x(); // > 0: right of the line
                    const double t = std::clamp(0.5 + side / std::max(1e-9, o.shadowSoftMm), 0.0, 1.0);
                    light = 1.0 - o.shadowDepth * t * t * (3 - 2 * t);
                }
                cv::Vec3d acc(0, 0, 0);
                for (int sy = 0; sy < s; ++sy)
                    for (int sx = 0; sx < s; ++sx) {
                        const Point u = lensUndistorted(o, Point(x + (sx + 0.5) / s - 0.5, y + (sy + 0.5) / s - 0.5));
                        const Eigen::Vector3d q = inv * Eigen::Vector3d(u.x(), u.y(), 1);
                        const double wx = q.x() / q.z(), wy = q.y() / q.z();
                        double v = table;
                        cv::Vec3d tint = o.tableTint;
                        if (o.withSheet && wx >= 0 && wx <= w && wy >= 0 && wy <= h) {
                            v = 232.0 + paper, tint = white;
                            // Print: lines 7 mm apart, 2.4 mm high, words where the noise is high.
                            const double line = std::fmod(wy - 12.0, 7.0);
                            if (o.printedText && wx > 12 && wx < w - 12 && wy > 12 && wy < h - 12 && line < 2.4 &&
                                valueNoise(wx, std::floor((wy - 12.0) / 7.0) * 7.0, 4.0, o.seed + 9) > 0.05 &&
                                valueNoise(wx, wy, 0.8, o.seed + 10) > -0.2)
                                v = 45.0, tint = inkTint;
                            if (o.gridMm > 0 && wx > 9.85 && wx < w - 9.85 && wy > 9.85 && wy < h - 9.85 &&
                                (std::abs(std::remainder(wx - 10.0, o.gridMm)) < 0.15 ||
                                 std::abs(std::remainder(wy - 10.0, o.gridMm)) < 0.15))
                                v = 90.0, tint = inkTint;
                        }
                        if (!o.objectMm.isEmpty() && o.objectMm.contains(Point(wx, wy)))
                            v = o.objectLevel + 6.0 * valueNoise(wx, wy, 5.0, o.seed + 11), tint = o.objectTint;
                        if (o.withPiece && pieceBox.contains(Point(wx, wy)) && piece.inside(wx, wy)) {
                            v = pieceValue + paper, tint = o.whitePiece ? white : kraft;
                            if (grainGrid.near(wx, wy, 0.35))
                                v = 60.0, tint = inkTint;
                            if (slitGrid && slitGrid->near(wx, wy, 0.15))
                                v = 55.0, tint = inkTint;
                            for (const Point &hole : out.drillHoles)
                                if (const double r = (Point(wx, wy) - hole).norm(); std::abs(r - 1.5) < 0.2 || r < 0.4)
                                    v = 60.0, tint = inkTint;
                        }
                        if (o.withPiece && pencilGrid.near(wx, wy, 0.25))
                            v = 85.0, tint = inkTint;
                        if (o.withPiece && inkGrid && inkGrid->near(wx, wy, 0.5 * o.outlineInkWidthMm))
                            v = 50.0, tint = inkTint;
                        acc += v * (channels == 3 ? tint : white);
                    }
                for (int c = 0; c < channels; ++c)
                    px[c] = static_cast<float>(light * acc[c] / (s * s));
            }
        }
    });
    if (o.glareLevels > 0) {
        for (int y = 0; y < img.rows; ++y) {
            float *row = img.ptr<float>(y);
            for (int x = 0; x < img.cols; ++x) {
                const double r2 = std::pow(x - o.glareAtPx.x(), 2) + std::pow(y - o.glareAtPx.y(), 2);
                const auto add =
                    static_cast<float>(o.glareLevels * std::exp(-0.5 * r2 / (o.glareSigmaPx * o.glareSigmaPx)));
                for (int c = 0; c < channels; ++c)
                    row[x * channels + c] += add;
            }
        }
    }

    if (o.blurSigmaPx > 0)
        cv::GaussianBlur(img, img, cv::Size(0, 0), o.blurSigmaPx);
    const double cx = 0.5 * (o.size.width - 1), cy = 0.5 * (o.size.height - 1), r2max = cx * cx + cy * cy;
    for (int y = 0; y < img.rows; ++y) {
        float *row = img.ptr<float>(y);
        for (int x = 0; x < img.cols; ++x)
            for (int c = 0; c < channels; ++c)
                row[x * channels + c] *=
                    static_cast<float>(1.0 - o.vignetting * ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / r2max);
    }
    std::vector<cv::Mat> planes;
    cv::split(img, planes);
    for (std::size_t c = 0; c < planes.size(); ++c) {
        if (o.noiseSigma > 0) {
            cv::Mat noise(img.size(), CV_32F);
            cv::RNG rng(0x9e3779b97f4a7c15ull ^ (o.seed + 7919u * static_cast<unsigned>(c)));
            rng.fill(noise, cv::RNG::NORMAL, 0.0, o.noiseSigma);
            planes[c] += noise;
        }
        if (o.jpegStep > 0)
            quantiseLikeJpeg(planes[c], o.jpegStep);
    }
    cv::merge(planes, img);
    img.convertTo(out.image, channels == 3 ? CV_8UC3 : CV_8U);
    return out;
}

} // namespace kontur::vision::test
