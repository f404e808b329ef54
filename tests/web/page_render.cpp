// The native side of the page's render tests (tests/web/run.js, mode picture): reads the same
// address with the page's own code (apps/web), renders it with native gnomon (OpenGL 4.5 on
// the EGL context) with and without shadows, writes native's picture, and compares the page's
// screenshot with it where shadows decide:
//   gnomon_page_render ADDRESS BUNDLE NATIVE.png [PAGE.png]
// Of the pixels lit in native's shadows-off render, those darker than 85 % of it must agree
// between the page and native's shadows-on render on at least 98 % (shadow where native has
// shadow, light where it has light): the two rasterisers may round a shadow's edge a pixel
// apart, not move or lose a shadow. Exit 0 when they agree, 1 otherwise.
#include <cstdio>
#include <exception>
#include <string>

#include "PageCheck.h"
#include "PageRequest.h"
#include "gnomon/Image.h"
#include "gnomon/Renderer.h"

namespace {

constexpr double kShadowed = 0.85;  // darker than this share of the unshadowed light
constexpr double kMinAgreement = 0.98;
constexpr int kLit = 24;  // luminance (of 765) below which a pixel counts as unlit

int luminance(const gnomon::Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return int(p[0]) + int(p[1]) + int(p[2]);
}

int run(int argc, char** argv) {
    if (argc != 4 && argc != 5) {
        std::fprintf(stderr, "usage: gnomon_page_render ADDRESS BUNDLE NATIVE.png [PAGE.png]\n");
        return 1;
    }
    const gnomon::web::PageScene page =
        gnomon::web::loadRequest(gnomon::web::parseAddress(argv[1]), argv[2]);
    gnomon::Renderer renderer;
    const gnomon::Image native = renderer.render(page.scene, page.options);
    gnomon::RenderOptions off = page.options;
    off.shadow.enabled = false;
    const gnomon::Image unshadowed = renderer.render(page.scene, off);
    gnomon::writePng(argv[3], native);
    if (argc == 4) return 0;

    const auto found = gnomon::web::check::pageShot("page_render", argv[4], native);
    if (!found) return 1;
    const gnomon::Image& shot = *found;
    long lit = 0, agree = 0, shadowed = 0;
    for (int y = 0; y < native.height; ++y) {
        for (int x = 0; x < native.width; ++x) {
            const int full = luminance(unshadowed, x, y);
            if (full < kLit) continue;
            ++lit;
            const bool n = luminance(native, x, y) < kShadowed * full;
            const bool p = luminance(shot, x, y) < kShadowed * full;
            shadowed += n;
            agree += n == p;
        }
    }
    const double share = lit ? double(agree) / double(lit) : 1.0;
    const gnomon::ImageDiff d = gnomon::compareImages(native, shot, 2);
    std::printf(
        "page_render: %s: %ld lit pixels, %ld shadowed natively; the page agrees on "
        "%.2f %% (bound %.0f %%); max channel difference %d, mean %.3f\n",
        argv[1], lit, shadowed, 100.0 * share, 100.0 * kMinAgreement, d.maxChannelDiff,
        d.meanAbsDiff);
    if (lit > 0 && share >= kMinAgreement) return 0;
    return gnomon::web::check::failWithDiff("page_render", argv[4], native, shot,
                                            "the page's shadows differ from native's");
}

}  // namespace

int main(int argc, char** argv) {
    return gnomon::web::check::guarded("page_render", [&] { return run(argc, argv); });
}
