// Dithered 8-bit output (--dither): the point light's falloff over tutorial-point's floor is
// a smooth gradient that plain rounding turns into flat bands (rings) one step apart.
// Dithering must stay within one step of the rounded image and break the bands up.
#include <gtest/gtest.h>

#include <cstdlib>

#include "GlTest.h"

namespace gnomon::test {
namespace {

Image renderPoint(bool dither, OutputEncoding encoding) {
    Scene s = builtinScene("tutorial-point");
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shading.dither = dither;
    o.shading.output = encoding;
    return sharedRenderer().render(s, o);
}

// Mean length of the runs of equal green values along the rows: long in banded gradients.
double meanRun(const Image& image) {
    long runs = 0;
    for (int y = 0; y < image.height; ++y) {
        ++runs;
        for (int x = 1; x < image.width; ++x)
            if (image.at(x, y)[1] != image.at(x - 1, y)[1]) ++runs;
    }
    return double(image.width) * image.height / double(runs);
}

void expectDitheredWithinOneStep(OutputEncoding encoding) {
    const Image plain = renderPoint(false, encoding);
    const Image dithered = renderPoint(true, encoding);
    ASSERT_EQ(plain.pixels.size(), dithered.pixels.size());
    long changed = 0;
    for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
        const int d = std::abs(int(plain.pixels[i]) - int(dithered.pixels[i]));
        ASSERT_LE(d, 1) << "byte " << i << ": dithering moved a value by more than one step";
        changed += d;
    }
    EXPECT_GT(changed, long(plain.pixels.size() / 20)) << "dithering changed almost nothing";
    // Runs at least a third shorter; sRGB output at 128² comes close to that on some machines'
    // llvmpipe, so the bound leaves no more room than that.
    const double bandedRun = meanRun(plain), ditheredRun = meanRun(dithered);
    EXPECT_LT(ditheredRun, 0.7 * bandedRun)
        << "runs of equal values: " << ditheredRun << " dithered, " << bandedRun << " plain";
}

TEST(Dither, LinearOutputBreaksBandsWithinOneStep) {
    expectDitheredWithinOneStep(OutputEncoding::Linear);
}

TEST(Dither, SrgbOutputBreaksBandsWithinOneEncodedStep) {
    expectDitheredWithinOneStep(OutputEncoding::Srgb);
}

}  // namespace
}  // namespace gnomon::test
