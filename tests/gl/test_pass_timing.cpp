// The instruments gnomon bench stands on: per-pass timing lists the view depth pass, each
// map drawn, the main pass and the read-back; invalidating maps forces a full shadow frame; the
// bare depth pass measures something where a 2D map exists.
#include <gtest/gtest.h>

#include <vector>

#include "GlTest.h"

namespace gnomon::test {
namespace {

TEST(PassTiming, ListsEveryPassInOrder) {
    Renderer& r = sharedRenderer();
    const Scene s = builtinScene("mixed-lights");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    o.shadow.pointMaps = PointMaps::Cube;  // one map per light
    r.setPassTiming(true);
    r.invalidateShadowMaps();
    r.render(s, o);
    const FrameStats stats = r.lastFrameStats();
    ASSERT_EQ(stats.shadowPasses, 16);
    // The view depth pass (its sun is fitted to what the view sees), 16 maps, main, read-back.
    ASSERT_EQ(stats.passes.size(), 19u);
    EXPECT_EQ(stats.passes[0].name, "view depth");
    EXPECT_EQ(stats.passes[0].light, -1);
    // Nothing in the scene blends: the view's depth draws every triangle the main pass does.
    EXPECT_EQ(stats.passes[0].triangles, stats.mainTriangles);
    EXPECT_GT(stats.passes[0].triangles, 0u);
    // Each light's map once, cubes first and 2D maps layer by layer (ShadowPass::orderPasses).
    std::uint64_t triangles = 0;
    std::vector<int> seen(16, 0);
    for (int i = 0; i < 16; ++i) {
        const PassTiming& p = stats.passes[size_t(i) + 1];
        ASSERT_GE(p.light, 0);
        ASSERT_LT(p.light, 16);
        EXPECT_EQ(p.name, "shadow light " + std::to_string(p.light));
        EXPECT_GT(p.milliseconds, 0.0);
        ++seen[std::size_t(p.light)];
        triangles += p.triangles;
    }
    EXPECT_EQ(seen, std::vector<int>(16, 1));
    EXPECT_EQ(triangles, stats.shadowTriangles);
    EXPECT_EQ(stats.passes[17].name, "main");
    EXPECT_EQ(stats.passes[17].triangles, stats.mainTriangles);
    EXPECT_EQ(stats.passes[18].name, "read-back");
    // The same view again: the view depth pass keeps its samples and draws nothing.
    r.render(s, o);
    ASSERT_FALSE(r.lastFrameStats().passes.empty());
    EXPECT_EQ(r.lastFrameStats().passes[0].name, "view depth");
    EXPECT_EQ(r.lastFrameStats().passes[0].triangles, 0u);
    r.setPassTiming(false);
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
    o.shadow.pointMaps = PointMaps::Cube;
    r.render(s, o);
    EXPECT_EQ(r.measureBareDepthPass(256), -1.0);
    EXPECT_THROW(r.measureBareDepthPass(0), Error);
}

TEST(PassTiming, MainFloorRedrawsTheLastFrame) {
    Renderer r;
    EXPECT_EQ(r.measureMainFloor(), -1.0);   // no frame yet
    Scene s = builtinScene("mixed-lights");  // every kind of lookup: maps, cubes, cascades
    RenderOptions o = s.options;
    o.width = o.height = 48;
    r.render(s, o);
    EXPECT_GT(r.measureMainFloor(), 0.0);
    // The next frame is as it would have been: the floor left no state behind.
    const Image before = r.render(s, o);
    r.measureMainFloor();
    const Image after = r.render(s, o);
    EXPECT_EQ(before.pixels, after.pixels);
}

}  // namespace
}  // namespace gnomon::test
