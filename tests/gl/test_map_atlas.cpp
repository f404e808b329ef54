// Maps of different sizes share layers of the 2D array (shadow::packMaps): four 512² maps
// and one 1024² take two 1024² layers, not five, and each light's shadow is the same as when
// its map is alone at the corner of a layer (lookups, gathers and clamps stay in its square).
#include <gtest/gtest.h>

#include "GlTest.h"

namespace gnomon::test {
namespace {

Scene fiveSpots() {
    Scene s = builtinScene("tutorial-room");
    s.lights.clear();
    const glm::vec3 positions[5] = {{-3, 10, -6}, {4, 9, -3}, {-5, 8, 4}, {2, 11, 5}, {0, 12, 0}};
    for (int i = 0; i < 5; ++i) {
        Light spot;
        spot.type = LightType::Spot;
        spot.position = positions[i];
        spot.direction = glm::normalize(glm::vec3(0.0f) - spot.position);
        spot.innerConeDegrees = 30.0f;
        spot.outerConeDegrees = 40.0f;
        spot.intensity = 0.3f;
        spot.shadowMapSize = i == 4 ? 1024 : 512;
        spot.shadowCamera.policy = ShadowCameraPolicy::Fit;
        s.lights.push_back(spot);
    }
    return s;
}

TEST(MapAtlas, SmallMapsShareALayerAndShadowAsIfAlone) {
    const Scene s = fiveSpots();
    Renderer& r = sharedRenderer();
    RenderOptions o;
    o.width = o.height = 128;
    ShadowVisibility all;
    r.render(s, o, all);
    EXPECT_EQ(r.lastFrameStats().shadowMaps, 5);
    EXPECT_EQ(r.lastFrameStats().shadowMapBytes, std::size_t(2) * 1024 * 1024 * 4);
    int shadowed = 0;
    for (int light = 0; light < 5; ++light) {
        RenderOptions alone = o;
        alone.lightOnly = light;
        ShadowVisibility one;
        r.render(s, alone, one);
        int differ = 0;
        float largest = 0.0f;
        for (int p = 0; p < o.width * o.height; ++p) {
            const float a = all.visibility[std::size_t(p) * 5 + std::size_t(light)];
            const float b = one.visibility[std::size_t(p) * 5 + std::size_t(light)];
            // Not bit for bit: a texel's position in a layer at an offset rounds differently
            // (a filter weight of a 512² map at uv 0.75 is good to ~1e-4).
            differ += std::abs(a - b) > 0.01f ? 1 : 0;
            largest = std::max(largest, std::abs(a - b));
            shadowed += b < 0.5f ? 1 : 0;
        }
        EXPECT_EQ(differ, 0) << "light " << light << ": largest difference " << largest;
    }
    EXPECT_GT(shadowed, 500);  // the lights do shadow something
}

// A kind of map the frame does not use gives its memory back: after a point light's frame,
// a frame with none holds (and counts) no cubes.
TEST(MapAtlas, CubesUnusedAreReleased) {
    Renderer& r = sharedRenderer();
    RenderOptions o;
    o.width = o.height = 64;
    r.render(builtinScene("tutorial-point"), o);
    ASSERT_GT(r.lastFrameStats().shadowMapBytes, 0u);
    Scene fives = fiveSpots();
    r.render(fives, o);
    EXPECT_EQ(r.lastFrameStats().shadowMapBytes, std::size_t(2) * 1024 * 1024 * 4)
        << "the point light's cubes are still held";
}

}  // namespace
}  // namespace gnomon::test
