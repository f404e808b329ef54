// gnomon score end to end (issue 4): the main pass's visibility read back from the GPU
// agrees with the ray-traced reference on the built-in scenes with the defaults (false
// shadow and leaks away from boundaries below 0.05%), and a deliberately bad bias shows up
// as false shadow; the error map and JSON carry the numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "GlTest.h"

namespace gnomon::test {
namespace {

RenderOptions small(const Scene& s) {
    RenderOptions o = s.options;
    o.width = o.height = 256;
    return o;
}

// Every built-in scene with its defaults: almost nothing wrong away from shadow edges.
// Except the course text's two scenes: their point lights cast through fixed orthographic
// cameras (the course's simplification), so surfaces outside those volumes, or shadowed
// along diverging rays, come out lit: the score measures the textbook's error.
TEST(Score, DefaultsAreRightAwayFromEdges) {
    for (const SceneInfo& info : builtinScenes()) {
        SCOPED_TRACE(info.name);
        const Scene s = builtinScene(info.name);
        const ScoreResult r = score(sharedRenderer(), s, small(s));
        ASSERT_GT(r.overall.pixels, 1000);
        if (info.name.rfind("course-", 0) == 0) {
            EXPECT_GT(r.overall.leakOutsideBand, 0.01);
            EXPECT_LT(r.overall.falseShadowOutsideBand, 0.0005);
            continue;
        }
        EXPECT_LT(r.overall.falseShadowOutsideBand, 0.0005);
        EXPECT_LT(r.overall.leakOutsideBand, 0.0005);
        EXPECT_LT(r.overall.misclassified, 0.01);
        EXPECT_EQ(r.errors.width, 256);
    }
}

// No tolerance of any kind: acne over most lit surfaces (false shadow), and the defaults
// remove it.
TEST(Score, NoBiasIsFalseShadowDefaultsAreNot) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions bad = small(s);
    bad.shadow.biasConstant = bad.shadow.biasDepthAware = 0.0f;
    bad.shadow.biasSlope = bad.shadow.biasUnits = bad.shadow.normalOffset = 0.0f;
    bad.shadow.cull = CullMode::None;
    bad.shadow.receiverPlane = false;
    const ScoreResult acne = score(sharedRenderer(), s, bad);
    EXPECT_GT(acne.overall.falseShadow, 0.10);
    EXPECT_LT(acne.overall.leak, 0.001);
    const ScoreResult good = score(sharedRenderer(), s, small(s));
    EXPECT_LT(good.overall.falseShadow, 0.001);
}

// A huge constant tolerance detaches shadows (peter-panning): leaks, no false shadow.
TEST(Score, HugeToleranceLeaks) {
    const Scene s = builtinScene("tutorial-room-thin");
    RenderOptions o = small(s);
    o.shadow.biasConstant = 0.2f;
    const ScoreResult r = score(sharedRenderer(), s, o);
    EXPECT_GT(r.overall.leakOutsideBand, 0.002);
    EXPECT_LT(r.overall.falseShadow, 0.001);
}

// PCSS is scored against the soft reference.
TEST(Score, PcssUsesTheSoftReference) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = small(s);
    o.shadow.filter = ShadowFilter::Pcss;
    ScoreOptions so;
    so.softSamples = 32;
    const ScoreResult r = score(sharedRenderer(), s, o, so);
    EXPECT_TRUE(r.softReference);
    EXPECT_LT(r.overall.meanAbsError, 0.02);
    EXPECT_LT(r.overall.misclassified, 0.01);
}

TEST(Score, JsonHasEveryField) {
    const Scene s = builtinScene("mixed-lights");
    const RenderOptions o = small(s);
    const ScoreResult r = score(sharedRenderer(), s, o);
    const nlohmann::json j = nlohmann::json::parse(toJson(r, s.name, o));
    EXPECT_EQ(j["scene"], "mixed-lights");
    EXPECT_EQ(j["lights"].size(), 16u);
    for (const char* key :
         {"light", "type", "pixels", "band_pixels", "misclassified", "false_shadow", "leak",
          "false_shadow_outside_band", "leak_outside_band", "mean_abs_error"}) {
        EXPECT_TRUE(j["overall"].contains(key)) << key;
        EXPECT_TRUE(j["lights"][0].contains(key)) << key;
    }
}

TEST(Score, BadOptionsAreErrors) {
    const Scene s = builtinScene("book-triangle");
    ScoreOptions so;
    so.softSamples = 0;
    EXPECT_THROW(score(sharedRenderer(), s, small(s), so), Error);
    RenderOptions o = small(s);
    o.debugView = DebugView::ShadowMap;
    EXPECT_THROW(score(sharedRenderer(), s, o), Error);
}

}  // namespace
}  // namespace gnomon::test
