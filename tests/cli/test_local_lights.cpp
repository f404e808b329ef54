// bench's sweep of local lights (apps/gnomon/LocalLights.h, BenchSweep.h) without the binary or
// GL: the placement is deterministic, a smaller count's lights stand on a larger count's rays,
// every light stands in the open space the view looks into and inside the scene's box, ranges
// and intensities follow the rule; applySweep gives the lights, and bad values one clear error.
// Sponza's case skips where ../shared/scenes is not beside the repository.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "BenchSweep.h"
#include "LocalLights.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {
namespace {

constexpr float kAspect = 1.0f;

Scene room() {
    return builtinScene("tutorial-room");
}

// The message of the gnomon::Error `f` throws ("" when it throws none).
template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput) << e.what();
        return e.what();
    }
    return "";
}

// Points spread evenly over the sphere (a Fibonacci lattice): many more directions than the
// placement's own 26 probes, so the check does not share its blind spots.
glm::vec3 sphereDirection(int i, int n) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
    const float a = 2.39996323f * float(i);  // the golden angle
    return {r * std::cos(a), y, r * std::sin(a)};
}

// Every light stands in the open space the view looks into: along its direction it meets a
// surface (the one it lights), the eye sees that surface's point, so two open segments join the
// light to the eye (it is inside no wall, whatever the meshes' winding); no surface lies nearer
// it than a quarter of its distance to that point along 200 directions; and it lies inside the
// box of the scene and the eye.
void expectInOpenSpace(const Scene& scene, const std::vector<Light>& lights) {
    const bvh::Bvh bvh = sceneHierarchy(scene, 0.0);
    glm::vec3 lo, hi;
    sceneBounds(scene, lo, hi);
    const glm::vec3 eye = scene.camera.eye;
    const float slack = 1e-5f * glm::length(hi - lo);
    lo = glm::min(lo, eye) - slack;
    hi = glm::max(hi, eye) + slack;
    for (const Light& l : lights) {
        SCOPED_TRACE(l.name);
        EXPECT_FALSE(glm::any(glm::lessThan(l.position, lo)) ||
                     glm::any(glm::greaterThan(l.position, hi)));
        bvh::BvhRay aim;
        aim.origin = l.position;
        aim.dir = glm::normalize(l.direction);
        aim.tfar = std::numeric_limits<float>::max();
        const bvh::BvhHit lit = bvh.nearest(aim, nullptr, nullptr);
        ASSERT_TRUE(lit.hit()) << "its direction meets no surface";
        const glm::vec3 surface = aim.origin + lit.t * aim.dir;
        bvh::BvhRay look;
        look.origin = eye;
        look.dir = glm::normalize(surface - eye);
        look.tfar = glm::length(surface - eye) * (1.0f - 1e-3f);
        EXPECT_FALSE(bvh.occluded(look, nullptr, nullptr)) << "the eye does not see its surface";
        for (int i = 0; i < 200; ++i) {
            bvh::BvhRay probe;
            probe.origin = l.position;
            probe.dir = sphereDirection(i, 200);
            probe.tfar = 0.25f * lit.t;
            EXPECT_FALSE(bvh.occluded(probe, nullptr, nullptr))
                << "a surface within " << probe.tfar << " along " << i;
        }
    }
}

float totalIntensity(const std::vector<Light>& lights) {
    float sum = 0.0f;
    for (const Light& l : lights)
        sum += l.intensity;
    return sum;
}

TEST(LocalLights, SameCountSameLights) {
    const Scene s = room();
    EXPECT_EQ(placeLocalLights(s, 16, kAspect), placeLocalLights(s, 16, kAspect));
}

TEST(LocalLights, AlternateSpotAndPointWithRangeAndShadows) {
    const std::vector<Light> lights = placeLocalLights(room(), 9, kAspect);
    ASSERT_EQ(lights.size(), 9u);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        EXPECT_EQ(l.type, i % 2 == 0 ? LightType::Spot : LightType::Point) << i;
        EXPECT_GT(l.range, 0.0f) << i;
        EXPECT_GT(l.intensity, 0.0f) << i;
        EXPECT_TRUE(l.castsShadows && l.enabled) << i;
        EXPECT_EQ(l.shadowMapSize, 0) << i;  // the kind's default size
        EXPECT_EQ(l.attenuation, (Attenuation{0.0f, 0.0f, 1.0f})) << i;
    }
}

// The lights of 8 are those of 16 with their ranges (so their stand-offs and intensities)
// following the count: the same kinds, the same directions, on the same lines.
TEST(LocalLights, FewerLightsStandOnTheSameRays) {
    const Scene s = room();
    const std::vector<Light> few = placeLocalLights(s, 8, kAspect);
    const std::vector<Light> many = placeLocalLights(s, 16, kAspect);
    glm::vec3 lo, hi;
    sceneBounds(s, lo, hi);
    for (std::size_t i = 0; i < few.size(); ++i) {
        EXPECT_EQ(few[i].type, many[i].type) << i;
        EXPECT_EQ(few[i].direction, many[i].direction) << i;
        const glm::vec3 apart = few[i].position - many[i].position;
        EXPECT_LT(glm::length(glm::cross(apart, few[i].direction)), 1e-5f * glm::length(hi - lo))
            << i;
        EXPECT_GE(few[i].range, many[i].range) << i;
    }
}

// range ~ N^(-1/2): four times the lights, half the reach; the total intensity about holds.
TEST(LocalLights, RangesShrinkAsTheSquareRootAndTotalIntensityHolds) {
    const Scene s = room();
    const std::vector<Light> l16 = placeLocalLights(s, 16, kAspect);
    const std::vector<Light> l64 = placeLocalLights(s, 64, kAspect);
    const std::vector<Light> l256 = placeLocalLights(s, 256, kAspect);
    for (std::size_t i = 0; i < l16.size(); ++i)
        EXPECT_NEAR(l16[i].range / l64[i].range, 2.0f, 1e-4f) << i;
    const float totals[] = {totalIntensity(l16), totalIntensity(l64), totalIntensity(l256)};
    const auto [least, most] = std::minmax_element(std::begin(totals), std::end(totals));
    EXPECT_LT(*most / *least, 1.5f) << totals[0] << " " << totals[1] << " " << totals[2];
}

TEST(LocalLights, InTheOpenInsideTheRoom) {
    const Scene s = room();
    expectInOpenSpace(s, placeLocalLights(s, 64, kAspect));
    expectInOpenSpace(s, placeLocalLights(s, 256, kAspect));
}

TEST(LocalLights, SceneWithoutTrianglesIsOneClearError) {
    Scene empty = room();
    empty.objects.clear();
    EXPECT_EQ(errorOf([&] { placeLocalLights(empty, 4, kAspect); }),
              "--sweep local-lights: scene 'tutorial-room' has no triangles to place lights "
              "among");
}

TEST(LocalLights, ViewOfNothingIsOneClearError) {
    Scene s = room();
    s.camera.eye = {0.0f, 100.0f, 0.0f};
    s.camera.centre = {0.0f, 200.0f, 0.0f};  // the sky above the room
    s.camera.up = {0.0f, 0.0f, 1.0f};
    const std::string e = errorOf([&] { placeLocalLights(s, 4, kAspect); });
    EXPECT_NE(e.find("the view shows room for 0 of the 4 lights"), std::string::npos) << e;
}

TEST(LocalLightsSweep, SixteenLightsReplaceTheScenes) {
    const Scene base = room();
    Scene scene;
    RenderOptions options;
    RenderOptions baseOptions = base.options;
    baseOptions.lightOnly = 0;
    applySweep("local-lights", "16", base, baseOptions, scene, options);
    ASSERT_EQ(scene.lights.size(), 16u);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        EXPECT_EQ(scene.lights[i].type, i % 2 == 0 ? LightType::Spot : LightType::Point) << i;
        EXPECT_EQ(scene.lights[i].name.rfind("local ", 0), 0u) << scene.lights[i].name;
    }
    EXPECT_EQ(options.lightOnly, -1);  // every light on
    EXPECT_EQ(scene.camera, base.camera);
    const float aspect = float(baseOptions.width) / float(baseOptions.height);
    EXPECT_EQ(scene.lights, placeLocalLights(base, 16, aspect));
}

TEST(LocalLightsSweep, BadValuesAreOneClearError) {
    const Scene base = room();
    Scene scene;
    RenderOptions options;
    auto apply = [&](const std::string& v) {
        return errorOf([&] { applySweep("local-lights", v, base, base.options, scene, options); });
    };
    EXPECT_EQ(apply("0"), "--values: local-lights 0 is outside 1..256");
    EXPECT_EQ(apply("257"), "--values: local-lights 257 is outside 1..256");
    EXPECT_EQ(apply("many"), "--values: 'many' is not a number");
    EXPECT_EQ(apply("1.5"), "--values: '1.5' is not a number");
}

TEST(LocalLightsSweep, DefaultValuesAndTheUnknownSweepsMessage) {
    BenchArgs args;
    args.sweep = "local-lights";
    EXPECT_EQ(sweepValues(args),
              (std::vector<std::string>{"1", "2", "4", "8", "16", "32", "64", "128", "256"}));
    args.values = "3,5";
    EXPECT_EQ(sweepValues(args), (std::vector<std::string>{"3", "5"}));
    args.sweep = "colour";
    const std::string e = errorOf([&] { sweepValues(args); });
    EXPECT_NE(e.find("lights, local-lights, map-size"), std::string::npos) << e;
}

// Sponza's atrium from floor level (scripts/quality-real.py's sponza-atrium view): the lights
// stand along the arcades, in the open, inside the building.
TEST(LocalLights, SponzaAtriumInTheOpen) {
    const std::string path =
        std::string(GNOMON_SHARED_SCENES) + "/DabrovicSponza/dabrovic_sponza.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    Scene s = loadScene(path);
    s.camera.eye = {-10.5f, 1.6f, -1.2f};
    s.camera.centre = {10.0f, 4.5f, 0.0f};
    s.camera.fovyDegrees = 65.0f;
    fitCameraDepth(s, s.camera);
    const std::vector<Light> lights = placeLocalLights(s, 32, kAspect);
    ASSERT_EQ(lights.size(), 32u);
    expectInOpenSpace(s, lights);
    // Inside the building: the scene's box without the eye (which is inside it too).
    glm::vec3 lo, hi;
    sceneBounds(s, lo, hi);
    for (const Light& l : lights) {
        EXPECT_TRUE(glm::all(glm::greaterThan(l.position, lo)) &&
                    glm::all(glm::lessThan(l.position, hi)))
            << l.name;
    }
    EXPECT_EQ(placeLocalLights(s, 32, kAspect), lights);
}

// examples/sponza-local-lights.json is what the sweep places for 32 lights in its view
// (written by --write-scene; docs/results/performance.md gives the command): regenerate it
// when the rule changes.
TEST(LocalLights, SponzaExampleIsTheSweepsThirtyTwo) {
    const std::string model =
        std::string(GNOMON_SHARED_SCENES) + "/DabrovicSponza/dabrovic_sponza.glb";
    if (!std::filesystem::exists(model)) GTEST_SKIP() << model << " is absent";
    const Scene s = loadScene(std::string(GNOMON_EXAMPLES_DIR) + "/sponza-local-lights.json");
    const float aspect = float(s.options.width) / float(s.options.height);
    const std::vector<Light> placed = placeLocalLights(s, 32, aspect);
    ASSERT_EQ(s.lights.size(), placed.size());
    glm::vec3 lo, hi;
    sceneBounds(s, lo, hi);
    const float size = glm::length(hi - lo);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const Light &file = s.lights[i], &now = placed[i];
        EXPECT_EQ(file.name, now.name);
        EXPECT_EQ(file.type, now.type) << file.name;
        EXPECT_LT(glm::length(file.position - now.position), 1e-5f * size) << file.name;
        EXPECT_LT(glm::length(file.direction - now.direction), 1e-5f) << file.name;
        EXPECT_NEAR(file.range, now.range, 1e-5f * now.range) << file.name;
        EXPECT_NEAR(file.intensity, now.intensity, 1e-4f * now.intensity) << file.name;
    }
}

}  // namespace
}  // namespace gnomon::cli
