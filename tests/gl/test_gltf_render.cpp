// glTF scenes render (issue 5): the lamp's five point lights each cast through their own
// cube, and every shared scene renders something. Skips where ../shared/scenes is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "GlTest.h"

namespace gnomon::test {
namespace {

std::string shared(const std::string& file) {
    return std::string(GNOMON_SHARED_SCENES) + "/" + file;
}

TEST(GltfRender, LampsFivePointLightsCastShadows) {
    GNOMON_NEEDS_DEPTH_READBACK();
    const std::string file = shared("LightsPunctualLamp/LightsPunctualLamp.gltf");
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is absent";
    const Scene s = loadScene(file);
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shadow.pointMaps = PointMaps::Cube;
    sharedRenderer().render(s, o);
    auto maps = sharedRenderer().shadowMaps();
    EXPECT_EQ(maps.size(), 5u);
    // Fitted to what the view sees, a light may need one frustum rather than six faces;
    // fitted to boxes, every point light gets a cube.
    for (const ShadowMapImage& m : maps)
        EXPECT_TRUE(m.depth.width == m.depth.height || m.depth.width == 6 * m.depth.height);
    // With faces of their own, every light still has a map, and only squares.
    o.shadow.pointMaps = PointMaps::Faces;
    sharedRenderer().render(s, o);
    maps = sharedRenderer().shadowMaps();
    std::set<int> lights;
    for (const ShadowMapImage& m : maps) {
        lights.insert(m.light);
        EXPECT_EQ(m.depth.width, m.depth.height);
    }
    EXPECT_EQ(lights.size(), 5u);
    o.shadow.fitTo = FitTo::Boxes;
    sharedRenderer().render(s, o);
    maps = sharedRenderer().shadowMaps();
    EXPECT_EQ(maps.size(), 5u);
    for (const ShadowMapImage& m : maps)
        EXPECT_EQ(m.depth.width, 6 * m.depth.height) << "light " << m.light << " is not a cube";
}

TEST(GltfRender, EverySharedSceneRenders) {
    const char* files[] = {"Box/Box.glb",
                           "Duck/Duck.glb",
                           "Suzanne/Suzanne.gltf",
                           "Fox/Fox.glb",
                           "Lantern/Lantern.gltf",
                           "LightsPunctualLamp/LightsPunctualLamp.gltf",
                           "SimpleInstancing/SimpleInstancing.glb",
                           "AlphaBlendModeTest/AlphaBlendModeTest.glb",
                           "TwoSidedPlane/TwoSidedPlane.gltf",
                           "OrientationTest/OrientationTest.glb",
                           "NegativeScaleTest/NegativeScaleTest.glb",
                           "ToyCar/ToyCar.gltf",
                           "DabrovicSponza/dabrovic_sponza.glb"};
    int rendered = 0;
    for (const char* f : files) {
        const std::string file = shared(f);
        if (!std::filesystem::exists(file)) continue;
        SCOPED_TRACE(f);
        const Scene s = loadScene(file);
        RenderOptions o = s.options;
        o.width = o.height = 64;
        const Image image = sharedRenderer().render(s, o);
        int lit = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                lit += luminance(image.at(x, y)) > 30;
        EXPECT_GT(lit, 40) << "hardly anything visible";
        ++rendered;
    }
    if (rendered == 0) GTEST_SKIP() << "the shared scenes are absent";
}

}  // namespace
}  // namespace gnomon::test
