// Kontur's outline tracer beside potrace (Selinger 2003; Debian's /usr/bin/potrace, the engine of
// Inkscape's Trace Bitmap) on the same rectified synthetic photos with a known outline: knots and
// Hausdorff distance to the truth (mm), and the time, best of --repeat runs. Then the tracer alone on
// a 12-megapixel image. Run by hand: build/tests/bench/bench_trace [--repeat 5] [--quick].
#include "synthflat.h"
#include "synthphoto.h"
#include "vision/outline.h"
#include "vision/tracephoto.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace kontur;
using geo::Point;

namespace {

using Clock = std::chrono::steady_clock;

template <class F> double bestOf(int repeat, F &&f)
{
    double best = 1e300;
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        f();
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return best;
}

// The image potrace gets: a light blur against noise, Otsu's threshold, the pieces black (the class
// that holds less of the image's border), as a plain PBM.
void writePbm(const cv::Mat &bgr, const std::string &path)
{
    cv::Mat gray, bw;
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
    cv::GaussianBlur(gray, gray, cv::Size(), 1.0);
    cv::threshold(gray, bw, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    const int band = 4;
    double bright = 0, total = 0;
    for (int y = 0; y < bw.rows; ++y)
        for (int x = 0; x < bw.cols; ++x)
            if (x < band || y < band || x >= bw.cols - band || y >= bw.rows - band)
                bright += bw.at<std::uint8_t>(y, x) > 0, ++total;
    const bool pieceBright = bright < 0.5 * total;
    std::ofstream out(path, std::ios::binary);
    out << "P4\n" << bw.cols << ' ' << bw.rows << '\n';
    std::vector<unsigned char> row(static_cast<std::size_t>((bw.cols + 7) / 8));
    for (int y = 0; y < bw.rows; ++y) {
        std::fill(row.begin(), row.end(), 0);
        for (int x = 0; x < bw.cols; ++x)
            if ((bw.at<std::uint8_t>(y, x) > 0) == pieceBright)
                row[static_cast<std::size_t>(x / 8)] |= static_cast<unsigned char>(0x80 >> (x % 8));
        out.write(reinterpret_cast<const char *>(row.data()), static_cast<std::streamsize>(row.size()));
    }
}

// The closed paths of potrace's SVG (absolute M or relative m, relative l and c, z) as composite
// cubics in mm. Its coordinates are 1/unit pixel with y up from the bottom edge of the image and
// pixels as unit squares: pixel centre (u, v) is at (u + 1/2, rows - v - 1/2).
std::vector<std::vector<Point>> parsePotraceSvg(const std::string &path, int rows, double unit,
                                                const vision::PixelMapping &map)
{
    std::ifstream in(path);
    std::stringstream all;
    all << in.rdbuf();
    const std::string svg = all.str();
    std::vector<std::vector<Point>> curves;
    const auto toMm = [&](const Point &p) { return map.toMm(Point(p.x() / unit - 0.5, rows - p.y() / unit - 0.5)); };
    for (std::size_t at = svg.find(" d=\""); at != std::string::npos; at = svg.find(" d=\"", at + 1)) {
        const std::size_t end = svg.find('"', at + 4);
        std::string d = svg.substr(at + 4, end - at - 4);
        for (char &ch : d)
            if (std::isalpha(static_cast<unsigned char>(ch)))
                ch = static_cast<char>(ch == 'z' ? ' ' : ch); // z needs no token: each subpath closes itself
        std::vector<Point> ctrl;
        Point pen = Point::Zero();
        char cmd = 0;
        std::size_t i = 0;
        const auto number = [&]() {
            while (i < d.size() && (std::isspace(static_cast<unsigned char>(d[i])) || d[i] == ','))
                ++i;
            char *stop = nullptr;
            const double v = std::strtod(d.c_str() + i, &stop);
            i = static_cast<std::size_t>(stop - d.c_str());
            return v;
        };
        // Two numbers in order (a function's arguments are evaluated in no fixed order).
        const auto pair = [&]() {
            const double x = number();
            return Point(x, number());
        };
        const auto flush = [&]() {
            if (ctrl.size() >= 4)
                curves.push_back(ctrl);
            ctrl.clear();
        };
        while (true) {
            while (i < d.size() && (std::isspace(static_cast<unsigned char>(d[i])) || d[i] == ','))
                ++i;
            if (i >= d.size())
                break;
            if (std::isalpha(static_cast<unsigned char>(d[i])))
                cmd = d[i++];
            if (cmd == 'M' || cmd == 'm') {
                flush();
                const Point p = pair();
                pen = cmd == 'M' ? p : Point(pen + p);
                ctrl.push_back(toMm(pen));
                cmd = cmd == 'M' ? 'L' : 'l'; // further pairs are lines
            } else if (cmd == 'l') {
                const Point p = pen + pair();
                ctrl.push_back(toMm(pen + (p - pen) / 3.0));
                ctrl.push_back(toMm(pen + 2.0 * (p - pen) / 3.0));
                ctrl.push_back(toMm(p));
                pen = p;
            } else if (cmd == 'c') {
                const Point a = pen + pair();
                const Point b = pen + pair();
                const Point p = pen + pair();
                ctrl.push_back(toMm(a));
                ctrl.push_back(toMm(b));
                ctrl.push_back(toMm(p));
                pen = p;
            } else {
                std::fprintf(stderr, "bench_trace: unexpected SVG command '%c'\n", cmd);
                return curves;
            }
        }
        flush();
    }
    return curves;
}

struct Figures
{
    int knots = 0;
    double hausdorff = 0.0, ms = 0.0;
};

// The traced curve nearest the truth (potrace also traces the card and specks of the table).
Figures nearest(const std::vector<std::vector<Point>> &curves, const test::FlatPiece &truth)
{
    const auto t = test::sampleComposite(truth.control, 100);
    Figures best{0, 1e300, 0.0};
    for (const auto &c : curves) {
        const double h = test::hausdorff(test::sampleComposite(c, 100), t);
        if (h < best.hausdorff)
            best = {static_cast<int>(c.size() - 1) / 3, h, 0.0};
    }
    return best;
}

test::FlatScene scene(std::uint64_t seed, double pxPerMm, test::Backdrop backdrop, std::optional<geo::Box> &sheet)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> scale(0.4, 0.5);
    test::FlatSceneOptions o;
    o.sizeMm = Point(160.0 + (backdrop == test::Backdrop::Table ? 110.0 : 0.0), 170.0);
    o.pxPerMm = pxPerMm;
    o.backdrop = backdrop;
    o.seed = seed;
    if (backdrop == test::Backdrop::Table)
        sheet = geo::Box(Point(160, 20), Point(260, 150));
    o.sheet = sheet;
    return test::renderFlatScene({test::bodicePiece(rng, Point(80, 85), scale(rng))}, o);
}

} // namespace

int main(int argc, char **argv)
{
    int repeat = 5;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--quick")
            quick = true;
    }
    const bool havePotrace = std::system("potrace --version > /dev/null 2>&1") == 0;
    const auto dir = std::filesystem::temp_directory_path() / ("kontur-bench-trace-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const double unit = 100.0;

    std::printf("%-34s %7s %9s %9s | %7s %9s %9s\n", "scene (truth: 7 knots)", "knots", "hausdorff", "ms", "potrace",
                "hausdorff", "ms");
    const double scales[] = {5.0, 6.5, 8.0, 10.0};
    const int scenes = quick ? 1 : 8;
    double worstK = 0, worstP = 0, sumK = 0, sumP = 0;
    int knotsK = 0, knotsP = 0;
    for (int s = 1; s <= scenes; ++s) {
        const double px = scales[s % 4];
        const auto backdrop = s % 2 ? test::Backdrop::Table : test::Backdrop::WhiteSheet;
        std::optional<geo::Box> sheet;
        const test::FlatScene sc = scene(static_cast<std::uint64_t>(s), px, backdrop, sheet);
        vision::OutlineOptions options;
        options.ignoreRect = sheet;
        std::vector<vision::Outline> traced;
        Figures k;
        k.ms = bestOf(repeat, [&] { traced = vision::traceOutlines(sc.image, sc.mapping, options).value(); });
        std::vector<std::vector<Point>> ours;
        for (const auto &o : traced)
            ours.push_back(o.control);
        const Figures kf = nearest(ours, sc.pieces.front());
        k.knots = kf.knots, k.hausdorff = kf.hausdorff;
        Figures p{0, 0.0, 0.0};
        if (havePotrace) {
            const std::string pbm = (dir / "scene.pbm").string(), svg = (dir / "scene.svg").string();
            const std::string cmd =
                "potrace -b svg -u " + std::to_string(static_cast<int>(unit)) + " -t 100 -o " + svg + " " + pbm;
            std::vector<std::vector<Point>> curves;
            p.ms = bestOf(repeat, [&] {
                writePbm(sc.image, pbm);
                if (std::system(cmd.c_str()) != 0)
                    std::fprintf(stderr, "bench_trace: potrace failed\n");
                curves = parsePotraceSvg(svg, sc.image.rows, unit, sc.mapping);
            });
            const Figures pf = nearest(curves, sc.pieces.front());
            p.knots = pf.knots, p.hausdorff = pf.hausdorff;
        }
        char name[64];
        std::snprintf(name, sizeof name, "seed %d, %.1f px/mm, %s", s, px,
                      backdrop == test::Backdrop::Table ? "table" : "white sheet");
        std::printf("%-34s %7d %9.3f %9.1f | %7d %9.3f %9.1f\n", name, k.knots, k.hausdorff, k.ms, p.knots, p.hausdorff,
                    p.ms);
        worstK = std::max(worstK, k.hausdorff), worstP = std::max(worstP, p.hausdorff);
        sumK += k.hausdorff, sumP += p.hausdorff, knotsK += k.knots, knotsP += p.knots;
    }
    std::printf("{\"scenes\":%d,\"kontur_hausdorff_max_mm\":%.3f,\"kontur_hausdorff_mean_mm\":%.3f,"
                "\"kontur_knots_mean\":%.2f,\"potrace_hausdorff_max_mm\":%.3f,\"potrace_hausdorff_mean_mm\":%.3f,"
                "\"potrace_knots_mean\":%.2f}\n",
                scenes, worstK, sumK / scenes, static_cast<double>(knotsK) / scenes, worstP, sumP / scenes,
                static_cast<double>(knotsP) / scenes);

    if (!quick) {
        // 4000 × 3000 px: two pieces on a table at 10 px/mm.
        std::mt19937_64 rng(99);
        test::FlatSceneOptions o;
        o.sizeMm = Point(400, 300);
        o.pxPerMm = 10.0;
        const test::FlatScene big = test::renderFlatScene(
            {test::bodicePiece(rng, Point(135, 150), 0.85), test::bodicePiece(rng, Point(325, 150), 0.45)}, o);
        std::size_t count = 0;
        const double ms = bestOf(repeat, [&] { count = vision::traceOutlines(big.image, big.mapping).value().size(); });
        double h = 0.0;
        const auto traced = vision::traceOutlines(big.image, big.mapping).value();
        std::vector<std::vector<Point>> ours;
        for (const auto &t : traced)
            ours.push_back(t.control);
        for (const auto &piece : big.pieces)
            h = std::max(h, nearest(ours, piece).hausdorff);
        std::printf("{\"op\":\"trace-12mp\",\"width\":%d,\"height\":%d,\"outlines\":%zu,\"ms\":%.1f,"
                    "\"hausdorff_max_mm\":%.3f}\n",
                    big.image.cols, big.image.rows, count, ms, h);

        // The whole path of `kontur-cli trace` on a 12-megapixel phone photo (synthphoto.h): the sheet
        // found, the photo rectified at 8 px/mm, every piece outlined (vision::tracePhoto).
        const auto photo = vision::test::makeSynthPhoto(vision::test::randomSynthOptions(5, cv::Size(4000, 3000)));
        vision::PhotoTrace result;
        const double photoMs = bestOf(repeat, [&] { result = vision::tracePhoto(photo.image).value(); });
        std::vector<Point> truth;
        for (const Point &q : photo.pieceOutline)
            truth.emplace_back(q.x(), -q.y());
        double ph = 1e9;
        int pk = 0;
        for (const auto &o : result.outlines) {
            const double d = test::hausdorff(test::sampleComposite(o.control, 100), truth);
            if (d < ph)
                ph = d, pk = o.knotCount();
        }
        std::printf("{\"op\":\"trace-photo-12mp\",\"width\":%d,\"height\":%d,\"outlines\":%zu,\"ms\":%.1f,"
                    "\"px_per_mm\":%.2f,\"hausdorff_mm\":%.3f,\"knots\":%d,\"truth_knots\":%d}\n",
                    photo.image.cols, photo.image.rows, result.outlines.size(), photoMs, result.pxPerMm, ph, pk,
                    photo.pieceKnots);
    }
    if (!std::getenv("KONTUR_BENCH_KEEP"))
        std::filesystem::remove_all(dir);
    return 0;
}
