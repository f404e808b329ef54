// Debug views: --debug-view shadow-map shows exactly the stored depths --shadow-maps writes
// (2D maps, cascades side by side, a cube's faces in two rows); --debug-view light-frusta
// draws the shadow cameras' volumes over the unchanged scene.
#include <gtest/gtest.h>

#include <cstdlib>

#include "GlTest.h"

namespace gnomon::test {
namespace {

// Compares panel pixels of `view` with the read-back map (16-bit grey, top row first):
// the panel of side `size` at (x0, y0) (top-left, pixels) against face `face` of `map`.
int mismatches(const Image& view, int x0, int y0, const Image16& map, int face, int size) {
    int bad = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const int want = map.pixels[size_t(y) * map.width + face * size + x] >> 8;
            bad += std::abs(int(view.at(x0 + x, y0 + y)[0]) - want) > 1;
        }
    }
    return bad;
}

TEST(DebugViews, ShadowMapShowsTheStoredDepths) {
    GNOMON_NEEDS_DEPTH_READBACK();
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 256;
    o.shadow.mapSize = 256;  // one texel per pixel
    o.debugView = DebugView::ShadowMap;
    const Image view = sharedRenderer().render(s, o);
    const auto maps = sharedRenderer().shadowMaps();
    ASSERT_EQ(maps.size(), 1u);
    EXPECT_EQ(mismatches(view, 0, 0, maps[0].depth, 0, 256), 0);
}

TEST(DebugViews, ShadowMapUnfoldsACubeInTwoRows) {
    GNOMON_NEEDS_DEPTH_READBACK();
    Scene s = builtinScene("tutorial-point");
    RenderOptions o = s.options;
    o.width = 3 * 128;
    o.height = 2 * 128;
    o.shadow.mapSize = 128;
    o.shadow.pointMaps = PointMaps::Cube;
    o.debugView = DebugView::ShadowMap;
    const Image view = sharedRenderer().render(s, o);
    const auto maps = sharedRenderer().shadowMaps();
    ASSERT_EQ(maps.size(), 1u);
    for (int face = 0; face < 6; ++face) {
        EXPECT_EQ(mismatches(view, (face % 3) * 128, (face / 3) * 128, maps[0].depth, face, 128), 0)
            << "face " << face;
    }
}

TEST(DebugViews, ShadowMapPutsCascadesSideBySide) {
    GNOMON_NEEDS_DEPTH_READBACK();
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = 3 * 64;
    o.height = 100;  // letterboxed: panels 64 high, 18 rows of background above
    o.shadow.mapSize = 64;
    o.shadow.cascades = 3;
    o.debugView = DebugView::ShadowMap;
    const Image view = sharedRenderer().render(s, o);
    const auto maps = sharedRenderer().shadowMaps();
    ASSERT_EQ(maps.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(maps[size_t(k)].cascade, k);
        EXPECT_EQ(mismatches(view, k * 64, 18, maps[size_t(k)].depth, 0, 64), 0) << "cascade " << k;
    }
}

TEST(DebugViews, ShadowMapOfALightWithoutAMapIsAnError) {
    Scene s = builtinScene("tutorial-room");
    s.lights[0].castsShadows = false;
    RenderOptions o = s.options;
    o.width = o.height = 64;
    o.debugView = DebugView::ShadowMap;
    try {
        sharedRenderer().render(s, o);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("has a shadow map"), std::string::npos) << e.what();
    }
}

// The frusta view is the scene plus lines in the light's colour (yellow for light 0).
TEST(DebugViews, LightFrustaDrawLinesOverTheScene) {
    Scene s = builtinScene("tutorial-spot");
    RenderOptions o = s.options;
    o.width = o.height = 256;
    const Image plain = sharedRenderer().render(s, o);
    o.debugView = DebugView::LightFrusta;
    const Image lines = sharedRenderer().render(s, o);
    int changed = 0, yellow = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const std::uint8_t* a = plain.at(x, y);
            const std::uint8_t* b = lines.at(x, y);
            if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) {
                ++changed;
                yellow += b[0] == 255 && b[1] >= 225 && b[1] <= 235 && b[2] <= 60;
            }
        }
    }
    EXPECT_GT(yellow, 200) << "the spot's frustum edges should cross the picture";
    EXPECT_EQ(yellow, changed) << "only line pixels may differ from the plain render";
}

}  // namespace
}  // namespace gnomon::test
