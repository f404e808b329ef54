// The native side of the page's score tests (tests/web/run.js, mode picture with
// picture=score): reads the same address with the page's own code, scores it natively
// (OpenGL 4.5, the reference on Embree), writes native's error map and compares the page's
// (its screenshot) with it:
//   gnomon_page_score ADDRESS BUNDLE NATIVE.png [PAGE.png [BOUND]]
//   gnomon_page_score ADDRESS BUNDLE NATIVE.png misclassified=POINTS [BOUND]
// (the second: the share the page's viewer reported, compared with native's as a number)
// The error maps colour misclassified pixels (red false shadow, blue leak; truth/Metrics.h)
// over the render in grey. The page's misclassified share, counted from its map as native's
// is, must lie within BOUND points (default 0.05) of native's: the same geometric errors, a
// pixel apart at most. Acne, whose rounding differs between rasterisers, gets a wider BOUND.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "PageCheck.h"
#include "PageRequest.h"
#include "gnomon/Image.h"
#include "gnomon/Renderer.h"
#include "gnomon/Score.h"

namespace {

// An error map's pixel is coloured (misclassified for some light), not the render's grey.
bool marked(const gnomon::Image& map, int x, int y) {
    const std::uint8_t* p = map.at(x, y);
    return std::abs(int(p[0]) - int(p[1])) > 20 || std::abs(int(p[1]) - int(p[2])) > 20;
}

long markedPixels(const gnomon::Image& map) {
    long n = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            n += marked(map, x, y);
    return n;
}

int run(int argc, char** argv) {
    if (argc < 4 || argc > 6) {
        std::fprintf(stderr,
                     "usage: gnomon_page_score ADDRESS BUNDLE NATIVE.png "
                     "[PAGE.png|misclassified=POINTS [BOUND]]\n");
        return 1;
    }
    const gnomon::web::PageScene page =
        gnomon::web::loadRequest(gnomon::web::parseAddress(argv[1]), argv[2]);
    const std::string page4 = argc > 4 ? argv[4] : "";
    const bool viewer = page4.rfind("misclassified=", 0) == 0;
    gnomon::Renderer renderer;
    // The viewer scores the frame it shows: maps that follow the view (Renderer::
    // setFollowing), fitted at its first frame, as `gnomon view` draws them.
    renderer.setFollowing(viewer);
    if (viewer) renderer.draw(page.scene, page.options);
    const gnomon::ScoreResult native = gnomon::score(renderer, page.scene, page.options);
    gnomon::writePng(argv[3], native.errors);
    if (argc == 4) return 0;
    const double bound = argc == 6 ? std::atof(argv[5]) : 0.05;
    if (viewer) {  // the viewer's own number (its title)
        const double pagePoints = std::atof(page4.c_str() + 14);
        const double nativePoints = 100.0 * native.overall.misclassified;
        std::printf(
            "page_score: %s: native misclassifies %.4f %%, the page's viewer %.4f %%; "
            "bound %.2f points\n",
            argv[1], nativePoints, pagePoints, bound);
        return std::abs(pagePoints - nativePoints) <= bound ? 0 : 1;
    }

    const auto found = gnomon::web::check::pageShot("page_score", argv[4], native.errors);
    if (!found) return 1;
    const gnomon::Image& shot = *found;
    // Both maps counted the same way, scaled to native's share of pixel x light pairs.
    const long nativeMarked = markedPixels(native.errors), pageMarked = markedPixels(shot);
    const double pairs = double(std::max(native.overall.pixels, 1L));
    const double nativePoints = 100.0 * native.overall.misclassified;
    const double pagePoints = nativePoints + 100.0 * double(pageMarked - nativeMarked) / pairs;
    std::printf(
        "page_score: %s: native misclassifies %.3f %% (%ld pixels marked), the page "
        "%.3f %% (%ld marked); bound %.2f points\n",
        argv[1], nativePoints, nativeMarked, pagePoints, pageMarked, bound);
    if (std::abs(pagePoints - nativePoints) <= bound) return 0;
    return gnomon::web::check::failWithDiff("page_score", argv[4], native.errors, shot,
                                            "the page's score differs from native's");
}

}  // namespace

int main(int argc, char** argv) {
    return gnomon::web::check::guarded("page_score", [&] { return run(argc, argv); });
}
