// Flat synthetic scenes: see synthflat.h.
#include "synthflat.h"

#include "geometry/polyline.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::test {

using geo::Point;

FlatPiece bodicePiece(std::mt19937_64 &rng, const Point &centre, double scale, double jitter)
{
    // Knots and handles in mm (y up), counter-clockwise from the hem at the centre front.
    std::vector<Point> c = {{0, 0},     {47, -6},   {93, -6},   {140, 0}, // hem
                            {143, 50},  {147, 100}, {150, 150},           // side seam (line)
                            {130, 158}, {112, 170}, {113, 190},           // armhole, lower
                            {114, 210}, {118, 232}, {125, 240},           // armhole, upper
                            {103, 245}, {82, 250},  {60, 255},            // shoulder (line)
                            {58, 230},  {30, 215},  {0, 215},             // neckline
                            {0, 143.3}, {0, 71.7},  {0, 0}};              // centre front (line)
    // Knots move by up to `jitter`, handles with their knot and by a third of that on their own (more
    // would hook a segment's end within a millimetre, a shape no pattern has).
    std::uniform_real_distribution<double> u(-jitter, jitter), v(-jitter / 3, jitter / 3);
    const std::size_t knots = (c.size() - 1) / 3;
    for (std::size_t k = 0; k < knots; ++k) {
        const Point move(u(rng), u(rng));
        const std::size_t at = 3 * k;
        c[at] += move;
        c[at + 1] += move + Point(v(rng), v(rng));
        c[(at + c.size() - 2) % (c.size() - 1)] += move + Point(v(rng), v(rng));
    }
    c.back() = c.front();
    // Lines keep their handles at thirds; the armhole's middle knot stays smooth.
    for (int seg : {1, 4, 6}) {
        const auto a = static_cast<std::size_t>(3 * seg);
        c[a + 1] = c[a] + (c[a + 3] - c[a]) / 3.0;
        c[a + 2] = c[a] + 2.0 * (c[a + 3] - c[a]) / 3.0;
    }
    c[10] = c[9] + (c[9] - c[8]).normalized() * (c[10] - c[9]).norm();
    std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi);
    const double a = turn(rng);
    Eigen::Matrix2d r;
    r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    const Point mid(75, 125);
    FlatPiece p;
    for (const auto &q : c)
        p.control.push_back(centre + scale * (r * (q - mid)));
    p.corner = {true, true, true, false, true, true, true, true};
    p.grain[0] = centre + scale * (r * (Point(65, 35) - mid));
    p.grain[1] = centre + scale * (r * (Point(65, 185) - mid));
    // The centre front is the edge a piece cut on the fold has.
    p.foldEnds[0] = p.control[18];
    p.foldEnds[1] = p.control[21];
    return p;
}

std::vector<Point> sampleComposite(const std::vector<Point> &control, int perSegment)
{
    std::vector<Point> out;
    for (std::size_t a = 0; a + 3 < control.size(); a += 3) {
        const geo::Bezier b({control[a], control[a + 1], control[a + 2], control[a + 3]});
        for (int k = 0; k < perSegment; ++k)
            out.push_back(b.eval(static_cast<double>(k) / perSegment));
    }
    out.push_back(control.back());
    return out;
}

std::vector<double> distances(const std::vector<Point> &a, const std::vector<Point> &b)
{
    std::vector<double> out;
    out.reserve(a.size());
    for (const Point &p : a)
        out.push_back((geo::nearestOnPolyline(b, p, false).point - p).norm());
    return out;
}

double directedDistance(const std::vector<Point> &a, const std::vector<Point> &b)
{
    const std::vector<double> d = distances(a, b);
    return d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
}

double compositeLength(const std::vector<Point> &control)
{
    const std::vector<Point> pts = sampleComposite(control, 400);
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        length += (pts[i + 1] - pts[i]).norm();
    return length;
}

CompositePlace placeOnComposite(const std::vector<Point> &control, double s)
{
    const std::vector<Point> pts = sampleComposite(control, 400);
    const double total = compositeLength(control);
    s = std::fmod(s, total);
    if (s < 0.0)
        s += total;
    double run = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Point d = pts[i + 1] - pts[i];
        const double len = d.norm();
        if (run + len >= s && len > 0.0)
            return {pts[i] + d * ((s - run) / len), d / len};
        run += len;
    }
    return {pts.back(), (pts.back() - pts[pts.size() - 2]).normalized()};
}

double hausdorff(const std::vector<Point> &a, const std::vector<Point> &b)
{
    return std::max(directedDistance(a, b), directedDistance(b, a));
}

namespace {

// Coverage (0..1, CV_32F) of shapes given as polygons in pixels, by filling them at `s` samples per
// pixel side and averaging: the centre of sample k of pixel u lies at u - 1/2 + (k + 1/2) / s.
class Coverage
{
public:
    Coverage(cv::Size size, int s)
        : m_s(s)
        , m_fine(size.height * s, size.width * s, CV_8U, cv::Scalar(0))
        , m_size(size)
    {
    }
    // Fills the polygon, or clears it with `erase` (a cut out of what was filled before).
    void polygon(const std::vector<Point> &px, bool erase = false)
    {
        constexpr int shift = 8;
        std::vector<cv::Point> pts;
        pts.reserve(px.size());
        for (const Point &p : px)
            pts.emplace_back(static_cast<int>(std::lround(((p.x() + 0.5) * m_s - 0.5) * (1 << shift))),
                             static_cast<int>(std::lround(((p.y() + 0.5) * m_s - 0.5) * (1 << shift))));
        cv::fillPoly(m_fine, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(erase ? 0 : 255), cv::LINE_8, shift);
    }
    // A stroke of width w (px) along a polyline: quads per piece and discs at the joints.
    void stroke(const std::vector<Point> &line, double w)
    {
        for (std::size_t i = 0; i + 1 < line.size(); ++i) {
            const Point d = line[i + 1] - line[i];
            if (d.norm() == 0.0)
                continue;
            const Point n = Point(-d.y(), d.x()).normalized() * (w / 2);
            polygon({line[i] + n, line[i + 1] + n, line[i + 1] - n, line[i] - n});
        }
        for (const Point &p : line) {
            std::vector<Point> disc;
            for (int k = 0; k < 16; ++k)
                disc.push_back(p +
                               (w / 2) * Point(std::cos(k * std::numbers::pi / 8), std::sin(k * std::numbers::pi / 8)));
            polygon(disc);
        }
    }
    [[nodiscard]] cv::Mat result() const
    {
        cv::Mat small, f;
        cv::resize(m_fine, small, m_size, 0, 0, cv::INTER_AREA);
        small.convertTo(f, CV_32F, 1.0 / 255.0);
        return f;
    }

private:
    int m_s;
    cv::Mat m_fine;
    cv::Size m_size;
};

// Paints `colour` over img where the coverage is, by `alpha`.
void paint(cv::Mat &img, const cv::Mat &coverage, const cv::Vec3f &colour, float alpha = 1.0f)
{
    for (int y = 0; y < img.rows; ++y) {
        auto *row = img.ptr<cv::Vec3f>(y);
        const float *c = coverage.ptr<float>(y);
        for (int x = 0; x < img.cols; ++x)
            if (c[x] > 0.0f)
                row[x] += (colour - row[x]) * (alpha * c[x]);
    }
}

// Smooth random texture in [-1, 1]-ish: white noise blurred at `sigmaPx`, normalised.
cv::Mat texture(cv::Size size, double sigmaPx, cv::RNG &rng)
{
    cv::Mat t(size, CV_32F);
    rng.fill(t, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(t, t, cv::Size(), sigmaPx);
    cv::Scalar mean, dev;
    cv::meanStdDev(t, mean, dev);
    return (t - mean[0]) / std::max(1e-9, dev[0]);
}

} // namespace

FlatScene renderFlatScene(const std::vector<FlatPiece> &pieces, const FlatSceneOptions &o)
{
    FlatScene scene;
    scene.pieces = pieces;
    const double mmpp = 1.0 / o.pxPerMm;
    // Pixel (0, 0) is the scene's corner (0, h) mm with y up, (0, 0) with y down.
    scene.mapping = vision::PixelMapping::uniform(mmpp, Point(0.0, o.yUp ? o.sizeMm.y() : 0.0), o.yUp);
    const cv::Size size(static_cast<int>(std::ceil(o.sizeMm.x() * o.pxPerMm)),
                        static_cast<int>(std::ceil(o.sizeMm.y() * o.pxPerMm)));
    const int s = o.supersample > 0 ? o.supersample : (size.area() > 8'000'000 ? 2 : 4);
    cv::RNG rng(o.seed);
    const auto toPx = [&](const std::vector<Point> &mm) {
        std::vector<Point> px;
        for (const Point &p : mm)
            px.push_back(scene.mapping.toPixel(p));
        return px;
    };

    cv::Mat img(size, CV_32FC3);
    if (o.backdrop == Backdrop::Table) {
        // Wood: a brown base, grain stripes that wander, fine and coarse blotches.
        const cv::Mat fine = texture(size, 0.3 * o.pxPerMm, rng), coarse = texture(size, 15.0 * o.pxPerMm, rng);
        for (int y = 0; y < size.height; ++y)
            for (int x = 0; x < size.width; ++x) {
                const double ymm = y * mmpp + 4.0 * coarse.at<float>(y, x);
                const double k = 1.0 + 0.08 * std::sin(2 * std::numbers::pi * ymm / 3.5) + 0.05 * fine.at<float>(y, x) +
                                 0.06 * coarse.at<float>(y, x);
                img.at<cv::Vec3f>(y, x) = cv::Vec3f(0.22f, 0.36f, 0.50f) * static_cast<float>(k);
            }
    } else {
        const cv::Mat fine = texture(size, 0.2 * o.pxPerMm, rng);
        for (int y = 0; y < size.height; ++y)
            for (int x = 0; x < size.width; ++x)
                img.at<cv::Vec3f>(y, x) = cv::Vec3f(0.90f, 0.91f, 0.92f) * (1.0f + 0.01f * fine.at<float>(y, x));
    }
    if (o.sheet) {
        Coverage c(size, s);
        c.polygon(toPx({o.sheet->corner(geo::Box::BottomLeft), o.sheet->corner(geo::Box::BottomRight),
                        o.sheet->corner(geo::Box::TopRight), o.sheet->corner(geo::Box::TopLeft)}));
        paint(img, c.result(), cv::Vec3f(0.93f, 0.94f, 0.94f));
    }
    std::mt19937_64 wobble(o.seed * 7919u + 1u);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
    for (const FlatPiece &piece : pieces) {
        const std::vector<Point> outline = sampleComposite(piece.control, 400);
        double signedArea = 0.0;
        for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
            signedArea += outline[j].x() * outline[i].y() - outline[i].x() * outline[j].y();
        // The square to the edge into the piece at a place.
        const auto inwardAt = [&](const CompositePlace &at) {
            return Point((signedArea > 0.0 ? 1.0 : -1.0) * Point(-at.tangent.y(), at.tangent.x()));
        };
        if (o.look == PieceLook::Paper) {
            Coverage c(size, s);
            c.polygon(toPx(outline));
            for (const FlatNotch &notch : piece.notches) {
                if (notch.kind != FlatNotch::Kind::V)
                    continue;
                const CompositePlace mid = placeOnComposite(piece.control, notch.at);
                const CompositePlace p1 = placeOnComposite(piece.control, notch.at - notch.width / 2);
                const CompositePlace p2 = placeOnComposite(piece.control, notch.at + notch.width / 2);
                const Point tip = mid.point + notch.depth * inwardAt(mid);
                c.polygon(toPx({p1.point - inwardAt(p1), p1.point, tip, p2.point, p2.point - inwardAt(p2)}), true);
            }
            const cv::Vec3f paper = o.backdrop == Backdrop::Table && !o.kraft ? cv::Vec3f(0.85f, 0.87f, 0.88f)
                                                                              : cv::Vec3f(0.45f, 0.60f, 0.72f); // kraft
            const cv::Mat onPaper = c.result();
            paint(img, onPaper, paper);
            if (o.edgeLineWidthMm > 0.0) {
                // The line's middle at inset + width/2 inside the outline, painted on the paper only.
                std::vector<Point> line;
                const double in = o.edgeLineInsetMm + 0.5 * o.edgeLineWidthMm;
                double area = 0.0;
                for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
                    area += outline[j].x() * outline[i].y() - outline[i].x() * outline[j].y();
                for (std::size_t i = 0; i + 1 < outline.size(); ++i) {
                    const Point d = outline[i + 1] - outline[i > 0 ? i - 1 : outline.size() - 2];
                    const Point inward = (area > 0.0 ? 1.0 : -1.0) * Point(-d.y(), d.x()).normalized();
                    line.push_back(outline[i] + in * inward);
                }
                line.push_back(line.front());
                Coverage ink(size, s);
                ink.stroke(toPx(line), o.edgeLineWidthMm * o.pxPerMm);
                cv::Mat clipped;
                cv::min(ink.result(), onPaper, clipped); // on the paper only, exact where the two edges meet
                paint(img, clipped, cv::Vec3f(0.16f, 0.16f, 0.18f));
            }
            // A slit's cut shows as a dark hairline from the edge into the paper.
            Coverage slits(size, s);
            bool anySlit = false;
            for (const FlatNotch &notch : piece.notches) {
                if (notch.kind != FlatNotch::Kind::Slit)
                    continue;
                const CompositePlace at = placeOnComposite(piece.control, notch.at);
                slits.stroke(toPx({at.point - 0.5 * inwardAt(at), at.point + notch.depth * inwardAt(at)}),
                             0.3 * o.pxPerMm);
                anySlit = true;
            }
            if (anySlit) {
                cv::Mat clipped;
                cv::min(slits.result(), onPaper, clipped);
                paint(img, clipped, cv::Vec3f(0.18f, 0.18f, 0.2f));
            }
        } else {
            Coverage c(size, s);
            c.stroke(toPx(outline), 0.5 * o.pxPerMm);
            paint(img, c.result(), cv::Vec3f(0.25f, 0.25f, 0.28f));
        }
        if (o.grainline) {
            // A line with an arrowhead at each end, as drawn on a pattern.
            const Point a = piece.grain[0], b = piece.grain[1], d = (b - a).normalized(), n(-d.y(), d.x());
            Coverage c(size, s);
            const double w = 0.4 * o.pxPerMm;
            c.stroke(toPx({a, b}), w);
            for (const auto &[tip, back] : {std::pair{a, d}, std::pair{b, Point(-d)}}) {
                if (!o.grainArrows)
                    break;
                c.stroke(toPx({tip, tip + 6.0 * back + 2.5 * n}), w);
                c.stroke(toPx({tip, tip + 6.0 * back - 2.5 * n}), w);
            }
            paint(img, c.result(), cv::Vec3f(0.2f, 0.2f, 0.25f));
        }
        if (piece.foldBracket) {
            // The bar, then each leg from the bar to its arrow's tip, `gap` short of the edge.
            const FlatPiece::FoldBracket &f = *piece.foldBracket;
            const Point along = (f.to - f.from).normalized();
            Point in(-along.y(), along.x());
            const Point middle = 0.5 * (f.from + f.to);
            if ((0.5 * (piece.grain[0] + piece.grain[1]) - middle).dot(in) < 0.0)
                in = -in; // towards the piece's inside, where its grainline is
            Coverage c(size, s);
            const double w = 0.4 * o.pxPerMm;
            c.stroke(toPx({f.from + f.inset * in, f.to + f.inset * in}), w);
            for (const Point &end : {f.from, f.to}) {
                const Point tip = end + f.gap * in;
                c.stroke(toPx({end + f.inset * in, tip}), w);
                c.stroke(toPx({tip, tip + 4.0 * in + 1.8 * along}), w);
                c.stroke(toPx({tip, tip + 4.0 * in - 1.8 * along}), w);
            }
            paint(img, c.result(), cv::Vec3f(0.2f, 0.2f, 0.25f));
        }
        if (!piece.drillHoles.empty()) {
            Coverage c(size, s);
            for (const Point &hole : piece.drillHoles) {
                std::vector<Point> ring;
                for (int k = 0; k <= 48; ++k)
                    ring.push_back(
                        hole + 1.5 * Point(std::cos(k * std::numbers::pi / 24), std::sin(k * std::numbers::pi / 24)));
                c.stroke(toPx(ring), 0.4 * o.pxPerMm);
                c.stroke(toPx({hole, hole}), 0.8 * o.pxPerMm);
            }
            paint(img, c.result(), cv::Vec3f(0.2f, 0.2f, 0.25f));
        }
        if (o.pencil) {
            // Pencil along a quarter of the edge, on the edge, wandering by 0.05 mm over a few centimetres.
            std::vector<Point> line;
            const double p0 = phase(wobble);
            const std::size_t from = outline.size() / 8, to = from + outline.size() / 4;
            for (std::size_t i = from; i < to; ++i) {
                const Point d = outline[i + 1] - outline[i - 1];
                const Point out = Point(d.y(), -d.x()).normalized();
                line.push_back(outline[i] + out * (0.05 * std::sin(p0 + 0.01 * static_cast<double>(i))));
            }
            Coverage c(size, s);
            c.stroke(toPx(line), 0.2 * o.pxPerMm);
            paint(img, c.result(), cv::Vec3f(0.35f, 0.35f, 0.37f), 0.7f);
        }
    }
    if (o.blurPx > 0.0)
        cv::GaussianBlur(img, img, cv::Size(), o.blurPx);
    const Point centre(size.width / 2.0, size.height / 2.0);
    const double r2 = centre.squaredNorm();
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            const double d2 = (Point(x, y) - centre).squaredNorm() / r2;
            img.at<cv::Vec3f>(y, x) *= static_cast<float>(1.0 - o.vignette * d2);
        }
    cv::Mat noise(size, CV_32FC3);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, o.noise / 255.0);
    img += noise;
    img.convertTo(scene.image, CV_8UC3, 255.0);
    return scene;
}

} // namespace kontur::test
