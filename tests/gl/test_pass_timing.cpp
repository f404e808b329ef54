// The instruments gnomon bench stands on: per-pass timing lists each map drawn, the main
// pass and the read-back; invalidating maps forces a full shadow frame; the bare depth pass
// measures something where a 2D map exists.
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

TEST(PassTiming, ListsEveryPassInOrder) {
    Renderer& r = sharedRenderer();
    const Scene s = builtinScene("mixed-lights");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    r.setPassTiming(true);
    r.invalidateShadowMaps();
    r.render(s, o);
    const FrameStats stats = r.lastFrameStats();
    r.setPassTiming(false);
    ASSERT_EQ(stats.shadowPasses, 16);
    ASSERT_EQ(stats.passes.size(), 18u);
    std::uint64_t triangles = 0;
    for (int i = 0; i < 16; ++i) {
        EXPECT_EQ(stats.passes[size_t(i)].name, "shadow light " + std::to_string(i));
        EXPECT_EQ(stats.passes[size_t(i)].light, i);
        EXPECT_GT(stats.passes[size_t(i)].milliseconds, 0.0);
        triangles += stats.passes[size_t(i)].triangles;
    }
    EXPECT_EQ(triangles, stats.shadowTriangles);
    EXPECT_EQ(stats.passes[16].name, "main");
    EXPECT_EQ(stats.passes[16].triangles, stats.mainTriangles);
    EXPECT_EQ(stats.passes[17].name, "read-back");
    // Timing off: no passes listed.
    r.render(s, o);
    EXPECT_TRUE(r.lastFrameStats().passes.empty());
}

TEST(PassTiming, InvalidateRedrawsEveryMap) {
    Renderer& r = sharedRenderer();
    const Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    o.shadow.cascades = 3;
    r.render(s, o);
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 0);  // static: kept
    r.invalidateShadowMaps();
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 3);
}

TEST(PassTiming, BareDepthPassNeedsASingleFrustumMap) {
    Renderer& r = sharedRenderer();
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    r.render(s, o);
    EXPECT_GT(r.measureBareDepthPass(256), 0.0);
    s = builtinScene("tutorial-point");
    r.render(s, o);
    EXPECT_EQ(r.measureBareDepthPass(256), -1.0);
    EXPECT_THROW(r.measureBareDepthPass(0), Error);
}

}  // namespace
}  // namespace gnomon::test
