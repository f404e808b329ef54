// The native side of the web page's picture tests (tests/web/run.js): reads the same address
// with the page's own code (apps/web), traces the picture the page shows on Embree, the
// native reference, instead of the page's BVH, writes it, and compares it with the page's
// screenshot when one is given.
//   gnomon_page_truth ADDRESS BUNDLE NATIVE.png [PAGE.png]
// BUNDLE: the folder the page packages as its models (../shared/scenes). Exit 0 when the
// two agree within the bounds below, 1 when they do not or anything fails.
#include <cstdio>
#include <exception>
#include <string>

#include "PageCheck.h"
#include "PageRequest.h"
#include "TruthPicture.h"
#include "gnomon/Image.h"

namespace {

// Bounds of the comparison. Where both tracers see the same surface and light, colours agree
// to within 2 of 255: wasm's libm and glibc's may round the shading's pow apart, by at most a
// step either way after sRGB encoding. The two tracers may still disagree on a pixel whose ray
// grazes an edge two triangles share, or a shadow's edge: at most a thousandth of the
// pixels, and the mean difference stays a fraction of a step. A page that draws a different
// view, flips it or tints it fails both bounds by far.
constexpr int kThreshold = 2;
constexpr double kMaxFailing = 0.001;
constexpr double kMaxMean = 0.25;

int run(int argc, char** argv) {
    if (argc != 4 && argc != 5) {
        std::fprintf(stderr, "usage: gnomon_page_truth ADDRESS BUNDLE NATIVE.png [PAGE.png]\n");
        return 1;
    }
    const gnomon::web::PageScene page =
        gnomon::web::loadRequest(gnomon::web::parseAddress(argv[1]), argv[2]);
    const gnomon::Image native =
        gnomon::web::truthPicture(page.scene, page.options, gnomon::truth::TracerKind::Embree);
    gnomon::writePng(argv[3], native);
    if (argc == 4) return 0;

    const auto shot = gnomon::web::check::pageShot("page_truth", argv[4], native);
    if (!shot) return 1;
    const gnomon::ImageDiff d = gnomon::compareImages(native, *shot, kThreshold);
    std::printf(
        "page_truth: %s: max channel difference %d, %.3f %% of pixels beyond %d, mean "
        "%.3f (bounds: %.1f %%, mean %.2f)\n",
        argv[1], d.maxChannelDiff, 100.0 * d.failingFraction, kThreshold, d.meanAbsDiff,
        100.0 * kMaxFailing, kMaxMean);
    if (d.failingFraction <= kMaxFailing && d.meanAbsDiff <= kMaxMean) return 0;
    return gnomon::web::check::failWithDiff("page_truth", argv[4], native, *shot,
                                            "the page differs from native beyond the bounds");
}

}  // namespace

int main(int argc, char** argv) {
    return gnomon::web::check::guarded("page_truth", [&] { return run(argc, argv); });
}
