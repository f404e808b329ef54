// gnomon_page_drag BEFORE AFTER REOPENED: the native side of the viewer's drag test
// (viewer.js). BEFORE and AFTER are the page's camera view around a right drag of the
// selected light, REOPENED the view the page's new address shows in a fresh page.
//  - The shadow moved: at least 0.25 % of the view darkened and as much brightened, by a
//    quarter or more against the median change of the view (Swap below): a moving shadow
//    covers some pixels and uncovers others, which shading alone does not.
//  - The link restores the view: AFTER and REOPENED agree within 8 levels on 99.5 % of
//    pixels (the same renderer draws the same view; the margin is for the light's position
//    written to the address with rounding).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "PageCheck.h"
#include "gnomon/Image.h"

namespace {

using gnomon::Image;

float luma(const Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// Of the pixels lit enough to see a change (above 10 levels in both), the shares (%) that
// darkened and that brightened against the view's own change (the median ratio: turning the
// light dims or lights whole surfaces alike, which a moving shadow does not).
struct Swap {
    double darkened = 0.0, brightened = 0.0;
};
Swap swapped(const Image& before, const Image& after) {
    std::vector<float> ratios;
    for (int y = 0; y < before.height; ++y) {
        for (int x = 0; x < before.width; ++x) {
            const float a = luma(before, x, y), b = luma(after, x, y);
            if (a > 10.0f && b > 10.0f) ratios.push_back(b / a);
        }
    }
    if (ratios.empty()) return {};
    std::vector<float> sorted = ratios;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                     sorted.end());
    const float median = sorted[sorted.size() / 2];
    Swap s;
    for (float r : ratios) {
        s.darkened += r < 0.8f * median;
        s.brightened += r > 1.25f * median;
    }
    const double pixels = double(before.width) * double(before.height) / 100.0;
    s.darkened /= pixels;
    s.brightened /= pixels;
    return s;
}

int run(const char* beforePath, const char* afterPath, const char* reopenedPath) {
    const Image before = gnomon::readPng(beforePath), after = gnomon::readPng(afterPath);
    const Image reopened = gnomon::readPng(reopenedPath);
    if (before.width != after.width || before.height != after.height ||
        reopened.width != after.width || reopened.height != after.height || after.width == 0) {
        std::fprintf(stderr, "gnomon_page_drag: the views are %dx%d, %dx%d and %dx%d\n",
                     before.width, before.height, after.width, after.height, reopened.width,
                     reopened.height);
        return 1;
    }
    const Swap moved = swapped(before, after);
    std::size_t agree = 0;
    for (int y = 0; y < after.height; ++y) {
        for (int x = 0; x < after.width; ++x) {
            int most = 0;
            for (int c = 0; c < 3; ++c)
                most = std::max(most, std::abs(int(after.at(x, y)[c]) - int(reopened.at(x, y)[c])));
            agree += most <= 8;
        }
    }
    const double same = 100.0 * double(agree) / (double(after.width) * double(after.height));
    std::printf(
        "gnomon_page_drag: %.2f %% of the view darkened and %.2f %% brightened against the "
        "rest (each at least 0.25); the reopened link agrees on %.2f %% (at least 99.5)\n",
        moved.darkened, moved.brightened, same);
    if (moved.darkened < 0.25 || moved.brightened < 0.25) {
        std::fprintf(stderr, "gnomon_page_drag: the drag did not move the shadow\n");
        return 1;
    }
    if (same < 99.5) {
        return gnomon::web::check::failWithDiff("gnomon_page_drag", reopenedPath, after, reopened,
                                                "the reopened address shows another view");
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: gnomon_page_drag BEFORE.png AFTER.png REOPENED.png\n");
        return 2;
    }
    return gnomon::web::check::guarded("gnomon_page_drag",
                                       [&] { return run(argv[1], argv[2], argv[3]); });
}
