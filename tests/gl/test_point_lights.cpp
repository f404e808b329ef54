// Omnidirectional point lights (SPEC S21): a caster on each of the six axes, offset to one
// side so a face rendered with the wrong orientation would put its shadow on the mirrored
// side, must shadow the receiver behind it exactly where rays from the light say. The
// six-pass fallback must write the same cube maps as the layered single pass.
#include <gtest/gtest.h>

#include "GeometryShadows.h"
#include "GlTest.h"
#include "render/GpuScene.h"
#include "render/ShadowPass.h"
#include "scene/MeshBuilder.h"
#include "scene/SceneUtil.h"

namespace gnomon::test {
namespace {

// Light at the origin; on axis a: a caster near the light, offset along b, and a receiver
// plate facing the light further out. Camera looking at plate `face` from beside the light.
Scene sixAxes(int face) {
    Scene s;
    s.name = "six axes";
    Material m;
    m.baseColour = glm::vec3(0.9f);
    m.doubleSided = true;
    s.materials.push_back(m);
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 a = axes[i];
        // Offset directions that differ per face and are never along the axis.
        const glm::vec3 b = glm::abs(a.x) > 0.5f   ? glm::vec3(0, 0.5f, 0.25f)
                            : glm::abs(a.y) > 0.5f ? glm::vec3(0.25f, 0, 0.5f)
                                                   : glm::vec3(0.5f, 0.25f, 0);
        s.meshes.push_back(
            mesh::box("caster", 2.0f * a + b, glm::vec3(0.5f) - 0.45f * glm::abs(a)));
        s.objects.push_back(
            {"caster", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
        s.meshes.push_back(mesh::box("plate", 5.0f * a, glm::vec3(4.0f) - 3.9f * glm::abs(a)));
        s.objects.push_back(
            {"plate", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
    }
    Light l;
    l.type = LightType::Point;
    l.position = glm::vec3(0.0f);
    l.intensity = 1.0f;
    l.shadowMapSize = 512;
    s.lights.push_back(l);
    const glm::vec3 a = axes[face];
    const glm::vec3 side = glm::abs(a.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    s.camera.eye = 0.6f * side - 0.5f * a;
    s.camera.centre = 5.0f * a;
    s.camera.up = glm::abs(a.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    s.camera.fovyDegrees = 50.0f;
    s.camera.near = 0.1f;
    s.camera.far = 20.0f;
    s.ambient = glm::vec3(0.1f);
    return s;
}

class SixAxes : public testing::TestWithParam<int> {};

TEST_P(SixAxes, CasterShadowsTheRightSideOfItsFace) {
    const Scene s = sixAxes(GetParam());
    RenderOptions o;
    o.width = o.height = 256;
    RenderOptions off = o;
    off.shadow.enabled = false;
    const Image on = sharedRenderer().render(s, o), plain = sharedRenderer().render(s, off);
    const GeometryShadows truth = classifyPixels(s, o, 2);
    int shadowed = 0, darker = 0, lit = 0, same = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const PixelClass c = truth.classes[size_t(y) * 256 + x];
            const int a = luminance(on.at(x, y)), b = luminance(plain.at(x, y));
            if (c == PixelClass::Shadowed) {
                ++shadowed;
                darker += a <= b - 6;
            } else if (c == PixelClass::Lit) {
                ++lit;
                same += std::abs(a - b) <= 6;
            }
        }
    }
    EXPECT_GE(shadowed, 100);
    EXPECT_GE(lit, 1000);
    EXPECT_EQ(darker, shadowed) << "a face's shadow is missing or mirrored";
    EXPECT_EQ(same, lit) << "light where the geometry says lit was taken away";
}

std::string faceName(const testing::TestParamInfo<int>& info) {
    static const char* const kNames[6] = {"PosX", "NegX", "PosY", "NegY", "PosZ", "NegZ"};
    return kNames[info.param];
}

INSTANTIATE_TEST_SUITE_P(Faces, SixAxes, testing::Range(0, 6), faceName);

TEST(PointLights, SixPassFallbackWritesTheSameCubes) {
    sharedRenderer().glInfo();  // context current
    const Scene s = sixAxes(0);
    render::GpuScene gpu;
    gpu.sync(s, 0.0);
    const Light& light = s.lights[0];
    const shadow::LightCameraFrame frame =
        shadow::lightCameraFrame(light, s.camera, gpu.bounds(), light.shadowMapSize);
    ASSERT_EQ(frame.kind, shadow::FrameKind::Cube);
    std::vector<render::ShadowedLight> a{{0, light.shadowMapSize, frame, true, 0}}, b = a;
    render::ShadowPass layered(true), sixPasses(false);
    const ShadowOptions options;
    ASSERT_EQ(layered.render(gpu, a, options).rendered, 1);
    ASSERT_EQ(sixPasses.render(gpu, b, options).rendered, 1);
    const Image16 ma = layered.readBack(a[0]), mb = sixPasses.readBack(b[0]);
    ASSERT_EQ(ma.width, 6 * light.shadowMapSize);
    EXPECT_EQ(ma.pixels, mb.pixels);
    // Every face saw something nearer than the far plane (its caster and plate).
    for (int face = 0; face < 6; ++face) {
        int nearer = 0;
        for (int y = 0; y < ma.height; ++y) {
            for (int x = 0; x < light.shadowMapSize; ++x) {
                nearer += ma.pixels[size_t(y) * ma.width + face * light.shadowMapSize + x] < 65535;
            }
        }
        EXPECT_GT(nearer, 1000) << "face " << face;
    }
}

}  // namespace
}  // namespace gnomon::test
