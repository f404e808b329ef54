// Depth storage: every format renders shadows where the geometry says;
// the WebGL book's precision failure is reproduced (the far light loses its shadow with depth
// in the red channel, keeps it with packed RGBA and native depth), and maps read back the
// same depth whatever the format, within the format's precision.
#include <gtest/gtest.h>

#include "GeometryShadows.h"
#include "GlTest.h"
#include "ShadowCheck.h"
#include "shadow/DepthPacking.h"

namespace gnomon::test {
namespace {

class Formats : public testing::TestWithParam<DepthFormat> {};

// Every format on the room with the default options: the depth-aware tolerance (one step of
// the format's stored-depth spacing) is what lets r8 and packed-256, good only to ~0.002,
// keep the defaults acne-free. r8 also on the book scene with the book's 0.005.
TEST_P(Formats, ShadowsWhereGeometrySaysWithDefaults) {
    const DepthFormat f = GetParam();
    const Scene room = builtinScene("tutorial-room");
    RenderOptions o = room.options;
    o.shadow.depthFormat = f;
    expectShadowsMatchGeometry(room, o);
    if (f == DepthFormat::R8) {
        const Scene book = builtinScene("book-triangle");
        RenderOptions b = book.options;
        b.shadow.depthFormat = f;
        b.shadow.biasConstant = 0.005f;
        b.shadow.biasDepthAware = 0.0f;
        expectShadowsMatchGeometry(book, b);
    }
}

// Without the depth-aware step, the default constant tolerance is too small for the coarse
// formats: acne (lit pixels darkened) shows, which is what the option is for.
TEST(Formats, CoarseFormatsNeedTheDepthAwareStep) {
    const Scene room = builtinScene("tutorial-room");
    RenderOptions o = room.options;
    o.width = o.height = 256;
    o.shadow.depthFormat = DepthFormat::Rgba8Packed256;
    RenderOptions plain = o;
    plain.shadow.biasDepthAware = 0.0f;
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image a = sharedRenderer().render(room, o), b = sharedRenderer().render(room, plain),
                c = sharedRenderer().render(room, off);
    const GeometryShadows truth = classifyPixels(room, o, 2);
    int acneWith = 0, acneWithout = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            if (truth.classes[size_t(y) * 256 + x] != PixelClass::Lit) continue;
            acneWith += luminance(a.at(x, y)) + 6 < luminance(c.at(x, y));
            acneWithout += luminance(b.at(x, y)) + 6 < luminance(c.at(x, y));
        }
    }
    EXPECT_EQ(acneWith, 0);
    EXPECT_GT(acneWithout, 50);
}

std::string formatName(const testing::TestParamInfo<DepthFormat>& info) {
    std::string n = toString(info.param);
    for (char& c : n)
        c = c == '-' ? '_' : c;
    return n;
}

INSTANTIATE_TEST_SUITE_P(All, Formats,
                         testing::Values(DepthFormat::R8, DepthFormat::Rgba8Packed256,
                                         DepthFormat::Rgba8Packed255, DepthFormat::Depth16,
                                         DepthFormat::Depth24, DepthFormat::Depth32F),
                         formatName);

// Fraction of the oracle's shadowed pixels that the render darkens.
double shadowCoverage(const Scene& scene, const RenderOptions& o) {
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image on = sharedRenderer().render(scene, o), plain = sharedRenderer().render(scene, off);
    const GeometryShadows truth = classifyPixels(scene, o, 2);
    int shadowed = 0, darker = 0;
    for (int y = 0; y < truth.height; ++y) {
        for (int x = 0; x < truth.width; ++x) {
            if (truth.classes[size_t(y) * truth.width + x] != PixelClass::Shadowed) continue;
            ++shadowed;
            darker += luminance(on.at(x, y)) + 6 <= luminance(plain.at(x, y));
        }
    }
    EXPECT_GT(shadowed, 100);
    return shadowed > 0 ? double(darker) / shadowed : 0.0;
}

// The book's own settings: r8 with LINEAR lookups and 0.005; packed with NEAREST and 0.0015.
RenderOptions bookSettings(const Scene& s, DepthFormat f) {
    RenderOptions o = s.options;
    o.width = o.height = 256;
    o.shadow.depthFormat = f;
    o.shadow.filter = ShadowFilter::None;
    o.shadow.biasSlope = o.shadow.biasUnits = o.shadow.normalOffset = 0.0f;
    o.shadow.mapFilter = f == DepthFormat::R8 ? MapFilter::Linear : MapFilter::Nearest;
    o.shadow.biasConstant = f == DepthFormat::R8 ? 0.005f : 0.0015f;
    o.shadow.biasDepthAware = 0.0f;
    return o;
}

TEST(PrecisionFailure, FarLightLosesItsShadowInTheRedChannelOnly) {
    const Scene near = builtinScene("book-triangle"), far = builtinScene("book-triangle-far");
    EXPECT_GT(shadowCoverage(near, bookSettings(near, DepthFormat::R8)), 0.99);
    EXPECT_LT(shadowCoverage(far, bookSettings(far, DepthFormat::R8)), 0.01)
        << "at (0, 40, 2) the red channel cannot hold the depth difference";
    EXPECT_GT(shadowCoverage(far, bookSettings(far, DepthFormat::Rgba8Packed256)), 0.99);
    EXPECT_GT(shadowCoverage(far, bookSettings(far, DepthFormat::Rgba8Packed255)), 0.99);
    EXPECT_GT(shadowCoverage(far, bookSettings(far, DepthFormat::Depth32F)), 0.99);
}

// The same map read back in every format agrees with depth32f within the format's precision
// (colour formats are decoded on the CPU by the code the shaders mirror).
TEST(Formats, MapsAgreeWithinTheFormatsPrecision) {
    GNOMON_NEEDS_DEPTH_READBACK();
    const Scene s = builtinScene("book-triangle");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    o.shadow.mapSize = 256;
    o.shadow.biasSlope = o.shadow.biasUnits = 0.0f;
    sharedRenderer().render(s, o);
    const Image16 reference = sharedRenderer().shadowMaps().at(0).depth;
    for (DepthFormat f : {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
                          DepthFormat::Depth16, DepthFormat::Depth24}) {
        o.shadow.depthFormat = f;
        sharedRenderer().render(s, o);
        const Image16 map = sharedRenderer().shadowMaps().at(0).depth;
        ASSERT_EQ(map.pixels.size(), reference.pixels.size());
        double worst = 0.0;
        for (size_t i = 0; i < map.pixels.size(); ++i) {
            if (reference.pixels[i] == 65535) continue;  // nothing drawn there
            worst = std::max(worst, std::abs(map.pixels[i] - reference.pixels[i]) / 65535.0);
        }
        EXPECT_LE(worst, shadow::depthRoundTripBound(f) + 2.0 / 65535.0) << toString(f);
    }
}

}  // namespace
}  // namespace gnomon::test

namespace gnomon::test {
namespace {

// Lit pixels (by the oracle) that a render darkens: acne.
int acnePixels(const Scene& scene, const RenderOptions& o) {
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image a = sharedRenderer().render(scene, o), c = sharedRenderer().render(scene, off);
    const GeometryShadows truth = classifyPixels(scene, o, 2);
    int acne = 0;
    for (int y = 0; y < truth.height; ++y) {
        for (int x = 0; x < truth.width; ++x) {
            if (truth.classes[size_t(y) * truth.width + x] != PixelClass::Lit) continue;
            acne += luminance(a.at(x, y)) + 6 < luminance(c.at(x, y));
        }
    }
    return acne;
}

// the course text's tolerance of 0.00001 holds with LINEAR lookups of its depth
// texture (interpolating a plane's depth gives the plane's depth) and fails with NEAREST.
TEST(Lookups, LinearDepthLookupsCureTheCourseTextsAcne) {
    const Scene s = builtinScene("course-two-lights");
    RenderOptions linear = presetOptions(s, Preset::Textbook);
    linear.width = linear.height = 256;
    RenderOptions nearest = linear;
    nearest.shadow.mapFilter = MapFilter::Nearest;
    EXPECT_EQ(acnePixels(s, linear), 0);
    EXPECT_GT(acnePixels(s, nearest), 200);
}

// The textbook preset keeps the book's shadow where its geometry says.
TEST(Presets, TextbookBookTriangleShadowsWhereGeometrySays) {
    const Scene s = builtinScene("book-triangle");
    expectShadowsMatchGeometry(s, presetOptions(s, Preset::Textbook));
}

}  // namespace
}  // namespace gnomon::test
