// Depth in 8-bit colour channels: each scheme's CPU round trip through RGBA8
// storage stays within its stated bound, and the bounds order as the textbooks say: r8 is
// coarse (1/256-ish, hence the book's 0.005), packed-256 is good to the book's 0.0015, and
// packed-255, matching 8-bit storage, is far finer.
#include <gtest/gtest.h>

#include <cmath>

#include "shadow/DepthPacking.h"

namespace gnomon {
namespace {

float worstRoundTrip(DepthFormat f, float from = 0.0f, float to = 1.0f) {
    float worst = 0.0f;
    for (int i = 0; i <= 100000; ++i) {
        const float d = from + (to - from) * float(i) / 100000.0f * 0.999999f;
        const float back =
            shadow::decodeDepth(f, shadow::quantizeUnorm8(shadow::encodeDepth(f, d)));
        worst = std::max(worst, std::abs(back - d));
    }
    return worst;
}

TEST(DepthPacking, EachSchemeKeepsItsStatedPrecision) {
    for (DepthFormat f :
         {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255}) {
        SCOPED_TRACE(toString(f));
        EXPECT_LE(worstRoundTrip(f), shadow::depthRoundTripBound(f) * 1.01f);
    }
}

TEST(DepthPacking, PrecisionOrdersAsTheTextbooksSay) {
    const float r8 = worstRoundTrip(DepthFormat::R8);
    const float p256 = worstRoundTrip(DepthFormat::Rgba8Packed256);
    const float p255 = worstRoundTrip(DepthFormat::Rgba8Packed255);
    EXPECT_GT(r8, 0.001f);  // coarse: the book needs a 0.005 tolerance
    EXPECT_LT(r8, 0.005f);
    // Base 256 is no better than r8 in the worst case (8-bit storage rounds to 255ths)...
    EXPECT_GT(p256, 0.0015f);
    // ...but where the book's perspective depths lie (near 1) it keeps its 0.0015 tolerance.
    EXPECT_LT(worstRoundTrip(DepthFormat::Rgba8Packed256, 0.9f, 1.0f), 0.0015f);  // ~0.0004
    EXPECT_LT(p255, 1e-6f);  // the tutorial's base matches 8-bit storage
}

TEST(DepthPacking, ChannelsStayInTheStorableRange) {
    for (DepthFormat f : {DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255}) {
        for (float d : {0.0f, 0.1234567f, 0.5f, 0.97749f, 0.98093f, 0.999f}) {
            const glm::vec4 c = shadow::encodeDepth(f, d);
            for (int k = 0; k < 4; ++k) {
                EXPECT_GE(c[k], 0.0f) << toString(f) << " " << d;
                EXPECT_LT(c[k], 1.0f) << toString(f) << " " << d;
            }
        }
    }
}

// In numbers: with the light at (0, 40, 2), far 200, the triangle and the plane are
// about 0.0034 apart in stored depth; r8 cannot tell them apart by more than its 0.005
// tolerance, packed formats can by more than theirs.
TEST(DepthPacking, BookFarLightDepthsAreBelowR8Resolution) {
    auto stored = [](float d) {
        const float n = 1.0f, f = 200.0f;
        return 0.5f * ((f + n) / (f - n) - 2.0f * f * n / ((f - n) * d)) + 0.5f;
    };
    const float triangle = stored(36.5f), plane = stored(41.7f);
    const float gap = plane - triangle;
    EXPECT_LT(gap, 0.005f);
    auto roundTrip = [](DepthFormat f, float d) {
        return shadow::decodeDepth(f, shadow::quantizeUnorm8(shadow::encodeDepth(f, d)));
    };
    EXPECT_LE(roundTrip(DepthFormat::R8, plane) - roundTrip(DepthFormat::R8, triangle), 0.005f);
    EXPECT_GT(roundTrip(DepthFormat::Rgba8Packed256, plane) -
                  roundTrip(DepthFormat::Rgba8Packed256, triangle),
              0.0015f);
}

TEST(DepthPacking, NamesRoundTrip) {
    for (DepthFormat f : {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
                          DepthFormat::Depth16, DepthFormat::Depth24, DepthFormat::Depth32F}) {
        EXPECT_EQ(parseDepthFormat(toString(f)), f);
        EXPECT_EQ(isColourFormat(f), f == DepthFormat::R8 || f == DepthFormat::Rgba8Packed256 ||
                                         f == DepthFormat::Rgba8Packed255);
    }
    EXPECT_FALSE(parseDepthFormat("rgba16").has_value());
    EXPECT_EQ(parseMapFilter("linear"), MapFilter::Linear);
    EXPECT_FALSE(parseMapFilter("cubic").has_value());
}

}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {

// checked against a naive reference: step the stored depth through its
// representable values and measure the gap directly.
TEST(DepthAware, SpacingMatchesNaiveStepping) {
    for (float s : {0.01f, 0.25f, 0.5f, 0.97f, 0.999f}) {
        // depth32f: the next float.
        float next = s;
        for (double step = 1e-12; next == s; step *= 1.001)
            next = float(double(s) + step);
        EXPECT_NEAR(shadow::storedDepthSpacing(DepthFormat::Depth32F, s), next - s, 1e-12f);
        // depth16: a 16-bit unorm step, the same everywhere.
        EXPECT_FLOAT_EQ(shadow::storedDepthSpacing(DepthFormat::Depth16, s), 1.0f / 65535.0f);
    }
    // Float spacing grows with the stored depth: errors are larger near 1 (the course text).
    EXPECT_GT(shadow::storedDepthSpacing(DepthFormat::Depth32F, 0.99f),
              shadow::storedDepthSpacing(DepthFormat::Depth32F, 0.01f) * 10.0f);
}

TEST(DepthAware, ToleranceCoversEachFormatsRoundTrip) {
    for (DepthFormat f : {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Rgba8Packed255,
                          DepthFormat::Depth16, DepthFormat::Depth24}) {
        EXPECT_GE(shadow::toleranceStep(f), shadow::depthRoundTripBound(f) * 0.999f) << toString(f);
    }
    EXPECT_FLOAT_EQ(shadow::toleranceStep(DepthFormat::Depth16), 1.0f / 65535.0f);
    // depth32f: one ulp of 0.5 (2^-24) whatever the depth, not the finer ulp of a depth
    // near 0 that the perspective's terms near 1 cannot reach.
    EXPECT_FLOAT_EQ(shadow::toleranceStep(DepthFormat::Depth32F), std::ldexp(1.0f, -24));
    EXPECT_GT(shadow::toleranceStep(DepthFormat::Depth32F),
              100.0f * shadow::storedDepthSpacing(DepthFormat::Depth32F, 1e-3f));
}

// The course text's graph (near 4, far 50): the distance one stored step spans grows with z^2.
TEST(DepthAware, WorldResolutionGrowsWithTheSquareOfDistance) {
    const float at10 = shadow::worldDepthResolution(10.0f, 4.0f, 50.0f, 16);
    const float at40 = shadow::worldDepthResolution(40.0f, 4.0f, 50.0f, 16);
    EXPECT_NEAR(at40 / at10, 16.0f, 1e-3f);
    // Naive reference: invert the stored depth at z and one step further.
    auto viewDepth = [](double stored, double n, double f) {
        const double ndc = 2.0 * stored - 1.0;
        return 2.0 * f * n / ((f + n) - ndc * (f - n));
    };
    auto stored = [](double z, double n, double f) {
        return 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * z)) + 0.5;
    };
    const double step = 1.0 / 65535.0;
    const double naive = viewDepth(stored(40.0, 4.0, 50.0) + step, 4.0, 50.0) - 40.0;
    EXPECT_NEAR(at40, naive, naive * 0.01);
}

}  // namespace
}  // namespace gnomon
