// compare_images A.png B.png [X,Y,W,H [BX,BY]]: exit 0 when the two images are equal within
// the golden tolerance (tests/support/GoldenTolerance.h), 1 with the numbers otherwise. With a
// rectangle, A's W x H pixels at X,Y (a view inside a window shot) are compared with B's at
// BX,BY (default 0,0; B whole when it is W x H); channels beyond B's (a window's alpha) are
// dropped.
#include <cstdio>
#include <exception>

#include "GoldenTolerance.h"
#include "gnomon/Image.h"

namespace {

gnomon::Image crop(const gnomon::Image& a, int x, int y, int w, int h, int channels) {
    gnomon::Image out(w, h, channels);
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            for (int c = 0; c < channels; ++c)
                out.at(col, row)[c] = a.at(x + col, y + row)[c];
        }
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc > 5) {
        std::fprintf(stderr, "usage: compare_images A.png B.png [X,Y,W,H [BX,BY]]\n");
        return 2;
    }
    try {
        gnomon::Image a = gnomon::readPng(argv[1]);
        gnomon::Image b = gnomon::readPng(argv[2]);
        if (argc >= 4) {
            int x = 0, y = 0, w = 0, h = 0;
            if (std::sscanf(argv[3], "%d,%d,%d,%d", &x, &y, &w, &h) != 4 || x < 0 || y < 0 ||
                w <= 0 || h <= 0 || x + w > a.width || y + h > a.height ||
                a.channels < b.channels) {
                std::fprintf(stderr, "compare_images: %s: no %s rectangle in a %dx%d image\n",
                             argv[1], argv[3], a.width, a.height);
                return 2;
            }
            a = crop(a, x, y, w, h, b.channels);
            int bx = 0, by = 0;
            if (argc == 5 && (std::sscanf(argv[4], "%d,%d", &bx, &by) != 2 || bx < 0 || by < 0 ||
                              bx + w > b.width || by + h > b.height)) {
                std::fprintf(stderr, "compare_images: %s: no %dx%d rectangle at %s\n", argv[2], w,
                             h, argv[4]);
                return 2;
            }
            if (argc == 5) b = crop(b, bx, by, w, h, b.channels);
        }
        if (a.width != b.width || a.height != b.height) {
            std::fprintf(stderr, "%s is %dx%d, %s is %dx%d\n", argv[1], a.width, a.height, argv[2],
                         b.width, b.height);
            return 1;
        }
        using namespace gnomon::test;
        const gnomon::ImageDiff d = gnomon::compareImages(a, b, kChannelThreshold);
        const bool ok = d.failingFraction <= kMaxFailingFraction && d.meanAbsDiff <= kMaxMeanDiff;
        std::printf(
            "%s vs %s: %.3f%% pixels over %d (allowed %.3f%%), mean %.3f (allowed %.1f), "
            "max %d: %s\n",
            argv[1], argv[2], d.failingFraction * 100.0, kChannelThreshold,
            kMaxFailingFraction * 100.0, d.meanAbsDiff, kMaxMeanDiff, d.maxChannelDiff,
            ok ? "equal" : "DIFFERENT");
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "compare_images: %s\n", e.what());
        return 2;
    }
}
