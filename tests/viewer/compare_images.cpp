// compare_images A.png B.png: exit 0 when the two images are equal within the golden
// tolerance (tests/support/GoldenTolerance.h), 1 with the numbers otherwise.
#include <cstdio>
#include <exception>

#include "GoldenTolerance.h"
#include "gnomon/Image.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: compare_images A.png B.png\n");
        return 2;
    }
    try {
        const gnomon::Image a = gnomon::readPng(argv[1]);
        const gnomon::Image b = gnomon::readPng(argv[2]);
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
