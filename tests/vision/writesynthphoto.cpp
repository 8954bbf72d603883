// kontur-synthphoto SEED OUT.pgm [WIDTH HEIGHT] [--sheet W,H] [--no-piece]: writes a synthetic photo
// (synthphoto.h, options drawn from the seed; the rectangle W × H mm instead of A4, no pattern piece
// beside it) as a binary PGM, and its truth (sheet corners in photo px) as JSON on stdout. For the
// kontur-cli trace tests and for trying the tools on a photo whose answer is known.
#include "synthphoto.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

int main(int argc, char *argv[])
{
    std::vector<std::string> args(argv + 1, argv + argc);
    bool withPiece = true;
    std::optional<kontur::geo::Point> sheet;
    for (std::size_t i = 0; i < args.size();) {
        if (args[i] == "--no-piece") {
            withPiece = false;
            args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
        } else if (args[i] == "--sheet" && i + 1 < args.size()) {
            double w = 0, h = 0;
            if (std::sscanf(args[i + 1].c_str(), "%lf,%lf", &w, &h) != 2 || !(w > 0) || !(h > 0)) {
                std::fprintf(stderr, "kontur-synthphoto: --sheet needs W,H in mm\n");
                return 2;
            }
            sheet = kontur::geo::Point(w, h);
            args.erase(args.begin() + static_cast<std::ptrdiff_t>(i),
                       args.begin() + static_cast<std::ptrdiff_t>(i + 2));
        } else {
            ++i;
        }
    }
    if (args.size() != 2 && args.size() != 4) {
        std::fprintf(stderr, "usage: kontur-synthphoto SEED OUT.pgm [WIDTH HEIGHT] [--sheet W,H] [--no-piece]\n");
        return 2;
    }
    const auto seed = static_cast<std::uint32_t>(std::strtoul(args[0].c_str(), nullptr, 10));
    cv::Size size(1600, 1200);
    if (args.size() == 4)
        size = cv::Size(std::atoi(args[2].c_str()), std::atoi(args[3].c_str()));
    if (size.width < 64 || size.height < 64 || size.width > 10000 || size.height > 10000) {
        std::fprintf(stderr, "kontur-synthphoto: size out of range\n");
        return 2;
    }
    auto options = kontur::vision::test::randomSynthOptions(seed, size);
    options.withPiece = withPiece;
    if (sheet)
        options.sheetMm = *sheet;
    const auto photo = kontur::vision::test::makeSynthPhoto(options);
    std::ofstream out(args[1], std::ios::binary);
    out << "P5\n" << photo.image.cols << ' ' << photo.image.rows << "\n255\n";
    for (int y = 0; y < photo.image.rows; ++y)
        out.write(reinterpret_cast<const char *>(photo.image.ptr(y)), photo.image.cols);
    if (!out) {
        std::fprintf(stderr, "kontur-synthphoto: cannot write %s\n", args[1].c_str());
        return 1;
    }
    std::printf("{\"corners\":[");
    for (int i = 0; i < 4; ++i)
        std::printf("%s[%.17g,%.17g]", i ? "," : "", photo.sheetCorners[i].x(), photo.sheetCorners[i].y());
    std::printf("]}\n");
    return 0;
}
