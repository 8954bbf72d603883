// kontur-synthphoto SEED OUT.pgm [WIDTH HEIGHT]: writes a synthetic photo (synthphoto.h, options drawn
// from the seed) as a binary PGM, and its truth (sheet corners in photo px) as JSON on stdout. For the
// kontur-cli trace tests and for trying the tools on a photo whose answer is known.
#include "synthphoto.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

int main(int argc, char *argv[])
{
    if (argc != 3 && argc != 5) {
        std::fprintf(stderr, "usage: kontur-synthphoto SEED OUT.pgm [WIDTH HEIGHT]\n");
        return 2;
    }
    const auto seed = static_cast<std::uint32_t>(std::strtoul(argv[1], nullptr, 10));
    cv::Size size(1600, 1200);
    if (argc == 5)
        size = cv::Size(std::atoi(argv[3]), std::atoi(argv[4]));
    if (size.width < 64 || size.height < 64 || size.width > 10000 || size.height > 10000) {
        std::fprintf(stderr, "kontur-synthphoto: size out of range\n");
        return 2;
    }
    const auto photo = kontur::vision::test::makeSynthPhoto(kontur::vision::test::randomSynthOptions(seed, size));
    std::ofstream out(argv[2], std::ios::binary);
    out << "P5\n" << photo.image.cols << ' ' << photo.image.rows << "\n255\n";
    for (int y = 0; y < photo.image.rows; ++y)
        out.write(reinterpret_cast<const char *>(photo.image.ptr(y)), photo.image.cols);
    if (!out) {
        std::fprintf(stderr, "kontur-synthphoto: cannot write %s\n", argv[2]);
        return 1;
    }
    std::printf("{\"corners\":[");
    for (int i = 0; i < 4; ++i)
        std::printf("%s[%.17g,%.17g]", i ? "," : "", photo.sheetCorners[i].x(), photo.sheetCorners[i].y());
    std::printf("]}\n");
    return 0;
}
