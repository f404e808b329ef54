// gnomon's reference (Embree, float) against the independent caster (CGAL, double) on the
// built-in scenes and, where ../shared/scenes is beside the repository, on real models under
// a low sun: every score stands on the reference's answers, so they must be the same answers
// another caster gives. The two differ only where a pixel's ray or a shadow ray grazes an
// edge, which rounding decides: a few pixels in ten thousand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "IndependentCaster.h"
#include "gnomon/Error.h"

namespace gnomon {
namespace {

// Share of pairs (and of pixels) the two casters may answer differently: a few pairs that
// graze an edge, where float and double rounding decide (docs/crosscheck.md).
constexpr double kBound = 5e-4;

crosscheck::Agreement check(const Scene& scene, int size = 96) {
    RenderOptions options = presetOptions(scene, Preset::Default);
    options.width = options.height = size;
    const truth::Reference reference = truth::traceReference(scene, options, {});
    const crosscheck::Agreement a = crosscheck::compareWithReference(scene, options, reference);
    std::printf("%s\n", crosscheck::describe(a).c_str());
    return a;
}

void expectAgree(const crosscheck::Agreement& a) {
    EXPECT_GT(a.pairs, 1000u);
    EXPECT_LE(a.disagreeShare(), kBound);
    EXPECT_LE(a.otherSurfaceShare(), kBound);
    EXPECT_LE(double(a.reachDiffers), kBound * double(a.pairs));
}

// The --sun convention: azimuth from +z towards +x, where the light comes from.
Light sun(float azimuth, float elevation) {
    const float az = glm::radians(azimuth), el = glm::radians(elevation);
    Light l;
    l.type = LightType::Directional;
    l.direction =
        -glm::vec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
    return l;
}

Scene sharedUnderSun(const std::string& file, float azimuth, float elevation) {
    const std::string path = std::string(GNOMON_SHARED_SCENES) + "/" + file;
    if (!std::filesystem::exists(path)) return {};
    Scene scene = loadScene(path);
    addGround(scene);
    scene.lights = {sun(azimuth, elevation)};
    return scene;
}

TEST(CrossCheck, BuiltinScenesAgree) {
    for (const char* name : {"tutorial-room", "tutorial-point", "book-triangle", "mixed-lights"}) {
        SCOPED_TRACE(name);
        expectAgree(check(builtinScene(name)));
    }
}

TEST(CrossCheck, RealModelsUnderALowSunAgree) {
    for (const char* file : {"Suzanne/Suzanne.gltf", "Lantern/Lantern.gltf",
                             "StanfordDragon/stanford_dragon_vrip.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = sharedUnderSun(file, 200.0f, 20.0f);
        if (scene.objects.empty()) GTEST_SKIP() << "../shared/scenes is not beside the repository";
        expectAgree(check(scene));
    }
}

TEST(CrossCheck, InsideSponzaAgrees) {
    Scene scene = sharedUnderSun("DabrovicSponza/dabrovic_sponza.glb", 30.0f, 60.0f);
    if (scene.objects.empty()) GTEST_SKIP() << "../shared/scenes is not beside the repository";
    expectAgree(check(scene));
}

// The check can fail: a reference traced under a sun two degrees off, or from a camera a
// little to one side, disagrees with the caster on far more than the bound.
TEST(CrossCheck, AWrongReferenceIsCaught) {
    Scene scene = builtinScene("tutorial-room");
    scene.lights = {sun(30.0f, 40.0f)};
    RenderOptions options = presetOptions(scene, Preset::Default);
    options.width = options.height = 96;

    Scene moved = scene;
    moved.lights = {sun(32.0f, 40.0f)};
    const crosscheck::Agreement offSun =
        crosscheck::compareWithReference(scene, options, truth::traceReference(moved, options, {}));
    EXPECT_GT(offSun.disagreeShare(), 5.0 * kBound) << crosscheck::describe(offSun);

    moved = scene;
    moved.camera.eye +=
        glm::normalize(glm::cross(scene.camera.centre - scene.camera.eye, scene.camera.up)) *
        0.05f * glm::length(scene.camera.centre - scene.camera.eye);
    const crosscheck::Agreement offCamera =
        crosscheck::compareWithReference(scene, options, truth::traceReference(moved, options, {}));
    EXPECT_GT(offCamera.otherSurfaceShare() + offCamera.disagreeShare(), 5.0 * kBound)
        << crosscheck::describe(offCamera);
}

TEST(CrossCheck, OrthographicCamerasAreRefused) {
    Scene scene = builtinScene("tutorial-room");
    scene.camera.projection = Projection::Orthographic;
    RenderOptions options = presetOptions(scene, Preset::Default);
    options.width = options.height = 8;
    EXPECT_THROW(crosscheck::compareWithReference(scene, options, truth::Reference{}), Error);
}

}  // namespace
}  // namespace gnomon
