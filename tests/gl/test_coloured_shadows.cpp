// Coloured shadows (--blend-shadows coloured): blended casters tint the light through them in
// 2D maps and cubes, by the colour of their texture where they are textured; a receiver
// nearer the light than the glass stays untinted; the transmitted light matches the ray-traced
// reference's within 4/255 on average; the transmittance pass runs only for maps drawn and
// only when something blended casts; every depth format tints, and so do shadow rays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "GlTest.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

constexpr int kSize = 128;
constexpr float kHalfView = 5.0f;  // the orthographic camera sees x, z in [-5, 5]

const std::uint8_t* at(const Image& image, float x, float z) {
    auto pixel = [](float v) { return int((v + kHalfView) / (2.0f * kHalfView) * float(kSize)); };
    return image.at(pixel(x), pixel(z));
}

// A pane at height 2 over x in [-3, 3], z in [-2, 2], blended at alpha 0.6 and textured with
// two texels: red on the left half (u < 0.5), blue on the right. A white cap stands on its
// left half (x in [-2.5, -1.5], z in [-2, -1], up to 2.5). A sun at 45 degrees shifts the
// pane's shadow 2 along +z: red light on x in [-3, 0], blue on [0, 3], for z in [0, 4]; the
// camera looks straight down, so beyond z = 2 the floor is seen past the pane. `point`: a
// point light at (0, 8, -6) instead: red on x in [-4, 0], blue [0, 4], z in [-0.7, 4.7].
Scene glassPane(bool point, std::uint8_t alpha = 153) {
    Scene s;
    s.name = "glass pane";
    Material white;
    white.baseColour = glm::vec3(0.8f);
    white.specular = 0.0f;
    s.materials.push_back(white);
    Material glass = white;
    glass.baseColour = glm::vec3(1.0f);
    glass.doubleSided = true;
    glass.alphaMode = AlphaMode::Blend;
    glass.alpha = 1.0f;
    glass.baseColourTexture = 0;
    s.materials.push_back(glass);
    Texture t;
    t.name = "red | blue";
    t.width = 2;
    t.height = 1;
    t.rgba = {255, 30, 30, alpha, 30, 30, 255, alpha};  // alpha 0.6 by default
    t.nearest = true;
    s.textures.push_back(t);
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {14.0f, 0.1f, 14.0f}));
    Mesh pane;
    pane.name = "pane";
    pane.positions = {{-3, 2, -2}, {-3, 2, 2}, {3, 2, 2}, {3, 2, -2}};
    pane.normals.assign(4, glm::vec3(0, 1, 0));
    pane.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    pane.indices = {0, 1, 2, 0, 2, 3};
    s.meshes.push_back(pane);
    s.meshes.push_back(mesh::box("cap", {-2.0f, 2.25f, -1.5f}, {1.0f, 0.5f, 1.0f}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"pane", 1, 1, glm::mat4(1.0f), {}, true, true});
    s.objects.push_back({"cap", 2, 0, glm::mat4(1.0f), {}, true, true});
    Light light;
    light.type = point ? LightType::Point : LightType::Directional;
    light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
    light.position = {0.0f, 8.0f, -6.0f};
    light.attenuation = {1.0f, 0.0f, 0.0f};
    light.shadowMapSize = 1024;
    s.lights.push_back(light);
    s.camera = lookingStraightDown(kHalfView);
    s.ambient = glm::vec3(0.05f);
    s.options.width = s.options.height = kSize;
    s.options.shadow.blendShadows = BlendShadows::Coloured;
    return s;
}

class ColouredShadows : public ::testing::TestWithParam<bool> {};

TEST_P(ColouredShadows, GlassTintsTheLightThroughIt) {
    const Scene s = glassPane(GetParam());
    const Image image = sharedRenderer().render(s, s.options);
    writePng(outputDir() + std::string("/coloured_") + (GetParam() ? "point" : "sun") + ".png",
             image);
    const std::uint8_t* r = at(image, -1.5f, 3.2f);
    const std::uint8_t* b = at(image, 1.5f, 3.2f);
    const std::uint8_t* open = at(image, -4.5f, 3.5f);
    std::printf("under red %d %d %d, under blue %d %d %d, open %d %d %d\n", r[0], r[1], r[2], b[0],
                b[1], b[2], open[0], open[1], open[2]);
    EXPECT_GT(r[0], r[1] * 3 / 2) << "red light under the red half";
    EXPECT_GT(b[2], b[1] * 3 / 2) << "blue light under the blue half";
    EXPECT_NEAR(open[0], open[2], 2) << "open floor: untinted";
    EXPECT_LT(luminance(r), luminance(open)) << "the glass passes less than all the light";
    // Dithered, the same glass gives grey partial shadow: the test can tell them apart.
    RenderOptions o = s.options;
    o.shadow.blendShadows = BlendShadows::Dithered;
    const Image dithered = sharedRenderer().render(s, o);
    const std::uint8_t* grey = at(dithered, -1.5f, 3.2f);
    EXPECT_NEAR(grey[0], grey[1], 4);
}

TEST_P(ColouredShadows, MatchesTheReference) {
    const Scene s = glassPane(GetParam());
    const ScoreResult result = score(sharedRenderer(), s, s.options);
    std::printf("coloured shadows (%s): %.2f/255 over %ld tinted cells\n",
                GetParam() ? "point" : "sun", 255.0 * result.tint.meanError, result.tint.cells);
    EXPECT_GT(result.tint.cells, kSize * kSize / 20) << "a good part of the view is tinted";
    EXPECT_LT(result.tint.meanError, 4.0 / 255.0);
    EXPECT_LT(result.overall.misclassified, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Lights, ColouredShadows, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Point" : "Sun"; });

TEST(ColouredShadowsPass, NearerTheLightThanTheGlassStaysUntinted) {
    const Scene s = glassPane(false);
    const Image image = sharedRenderer().render(s, s.options);
    const std::uint8_t* cap = at(image, -2.0f, -1.5f);
    EXPECT_NEAR(cap[0], cap[1], 2) << "the cap's top, above the red glass: white light";
    EXPECT_NEAR(cap[0], cap[2], 2);
    EXPECT_GT(cap[0], 150);
}

TEST(ColouredShadowsPass, DrawnOnlyForMapsDrawnAndOnlyForBlendedCasters) {
    const Scene s = glassPane(false);
    Renderer& r = sharedRenderer();
    r.invalidateShadowMaps();
    (void)r.render(s, s.options);
    const FrameStats first = r.lastFrameStats();
    ASSERT_GE(first.shadowPasses, 1);
    EXPECT_EQ(first.transmittancePasses, first.shadowPasses);
    (void)r.render(s, s.options);
    EXPECT_EQ(r.lastFrameStats().shadowPasses, 0);
    EXPECT_EQ(r.lastFrameStats().transmittancePasses, 0) << "kept maps keep their tint";
    // Moving the glass redraws the map and its tint.
    Scene moved = s;
    moved.objects[1].worldFromModel = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0, 0));
    (void)r.render(moved, moved.options);
    EXPECT_EQ(r.lastFrameStats().transmittancePasses, first.shadowPasses);
    // Nothing blended casts: no pass, no memory for it.
    Scene opaque = s;
    opaque.objects[1].castsShadows = false;
    (void)r.render(opaque, opaque.options);
    EXPECT_EQ(r.lastFrameStats().transmittancePasses, 0);
    RenderOptions dithered = opaque.options;
    dithered.shadow.blendShadows = BlendShadows::Dithered;
    const std::size_t bytes = r.lastFrameStats().shadowMapBytes;
    (void)r.render(opaque, dithered);
    EXPECT_EQ(r.lastFrameStats().shadowMapBytes, bytes);
}

// Many exported models mark opaque materials BLEND: their fully opaque texels shadow as an
// opaque caster's do (depth map, filtering, self-shadowing), not as a black tint.
TEST(ColouredShadowsPass, FullyOpaqueBlendedCastersShadowAsOpaqueOnes) {
    const Scene blended = glassPane(false, 255);
    Scene opaque = blended;
    opaque.materials[1].alphaMode = AlphaMode::Opaque;
    ShadowVisibility vb, vo;
    const Image b = sharedRenderer().render(blended, blended.options, vb);
    const Image o = sharedRenderer().render(opaque, opaque.options, vo);
    EXPECT_TRUE(vo.tint.empty()) << "nothing blended: no transmittance maps";
    ASSERT_EQ(vb.visibility.size(), vo.visibility.size());
    for (float z : {0.5f, 3.2f}) {
        for (float x : {-1.5f, 1.5f}) {
            SCOPED_TRACE("floor at " + std::to_string(x) + ", " + std::to_string(z));
            EXPECT_NEAR(luminance(at(b, x, z)), luminance(at(o, x, z)), 6);
        }
    }
    // Where the camera sees the floor in both (not the pane, which only the opaque one hides
    // the floor with): the same shadow, from the depth maps.
    int differ = 0, compared = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float wx = (float(x) + 0.5f) / kSize * 2.0f * kHalfView - kHalfView;
            const float wz = (float(y) + 0.5f) / kSize * 2.0f * kHalfView - kHalfView;
            if (std::abs(wx) < 3.2f && std::abs(wz) < 2.2f) continue;
            const std::size_t cell = std::size_t(y) * kSize + std::size_t(x);  // one light
            ++compared;
            differ += std::abs(vb.visibility[cell] - vo.visibility[cell]) > 0.01f;
        }
    }
    EXPECT_LT(differ, compared / 200) << "the same shadow in the depth maps";
    const ScoreResult result = score(sharedRenderer(), blended, blended.options);
    EXPECT_LT(result.overall.misclassified, 0.01);
}

// Under --shadow-rays all a ray decides each light's visibility and the transmittance maps
// still tint it: they are drawn, against the depth maps as their depth test, which are drawn
// for them; the moments, which nothing reads, are not.
TEST(ColouredShadowsPass, RaysAllKeepTheTint) {
    Renderer& r = sharedRenderer();
    for (int light = 0; light < 3; ++light) {  // sun, point light's faces, point light's cube
        for (ShadowFilter filter : {ShadowFilter::Pcf, ShadowFilter::Evsm2}) {
            SCOPED_TRACE(std::to_string(light) + " " + toString(filter));
            const Scene s = glassPane(light > 0);
            RenderOptions o = s.options;
            o.shadow.shadowRays = ShadowRayMode::All;
            o.shadow.filter = filter;
            o.shadow.pointMaps = light == 2 ? PointMaps::Cube : PointMaps::Faces;
            r.invalidateShadowMaps();
            const Image image = r.render(s, o);
            const FrameStats& stats = r.lastFrameStats();
            EXPECT_GE(stats.shadowPasses, 1);
            EXPECT_EQ(stats.transmittancePasses, stats.shadowPasses);
            EXPECT_EQ(stats.momentPasses, 0);
            const std::uint8_t* red = at(image, -1.5f, 3.2f);
            const std::uint8_t* blue = at(image, 1.5f, 3.2f);
            EXPECT_GT(red[0], red[1] * 3 / 2) << "red light under the red half";
            EXPECT_GT(blue[2], blue[1] * 3 / 2) << "blue light under the blue half";
            o.shadow.shadowRays = ShadowRayMode::Off;
            const Image maps = r.render(s, o);
            EXPECT_NEAR(luminance(at(maps, -1.5f, 3.2f)), luminance(red), 3)
                << "the maps' tinted light";
        }
    }
}

TEST(ColouredShadowsPass, EveryDepthFormatTints) {
    // Encoded formats test the glass against the depth buffer drawn beside their maps.
    for (DepthFormat f : {DepthFormat::R8, DepthFormat::Rgba8Packed256, DepthFormat::Depth16}) {
        const Scene s = glassPane(false);
        RenderOptions o = s.options;
        o.shadow.depthFormat = f;
        const Image image = sharedRenderer().render(s, o);
        const std::uint8_t* r = at(image, -1.5f, 3.2f);
        EXPECT_GT(r[0], r[1] * 3 / 2) << toString(f);
        const std::uint8_t* cap = at(image, -2.0f, -1.5f);
        EXPECT_NEAR(cap[0], cap[1], 2) << toString(f) << ": above the glass, untinted";
    }
}

}  // namespace
}  // namespace gnomon::test
