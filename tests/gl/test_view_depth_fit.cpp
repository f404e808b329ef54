// Fitting to what the view sees (sample distribution shadow maps, Lauritzen et al. 2011) on
// the GPU: a wide ground seen close up gets a map over the part in view, so its shadows are
// sharper and no less right than with a map over the whole ground; auto cascades follow the
// depth range the view sees (one map looking down, several looking to the horizon).
#include <gtest/gtest.h>

#include "GlTest.h"
#include "GroundScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

// A 400 x 400 ground with a row of posts along z and a sun; the camera stands among them,
// a wall 40 ahead hides the rest of the ground (which the view frustum still holds).
Scene postsOnAWideGround(bool wall = true) {
    Scene s = sceneWithGround("posts on a wide ground", 400.0f);
    for (int i = 0; i < 12; ++i) {
        s.meshes.push_back(mesh::box("post", {0.0f, 1.0f, -3.0f * float(i)}, {0.15f, 2.0f, 0.15f}));
        s.objects.push_back(
            {"post", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
    }
    if (wall) {
        s.meshes.push_back(mesh::box("wall", {0.0f, 25.0f, -40.0f}, {400.0f, 50.0f, 1.0f}));
        s.objects.push_back(
            {"wall", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
    }
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.3f));
    sun.shadowMapSize = 1024;
    sun.shadowCamera.policy = ShadowCameraPolicy::Fit;
    s.lights.push_back(sun);
    s.camera.eye = {3.0f, 1.7f, 4.0f};
    s.camera.centre = {0.0f, 0.5f, -6.0f};
    s.camera.fovyDegrees = 60.0f;
    s.camera.near = 0.1f;
    s.camera.far = 500.0f;
    s.ambient = glm::vec3(0.1f);
    return s;
}

RenderOptions options(FitTo fit, int cascades) {
    RenderOptions o;
    o.width = o.height = 192;
    o.shadow.fitTo = fit;
    o.shadow.cascades = cascades;
    return o;
}

TEST(ViewDepthFit, WideGroundSeenCloseUpIsSharperAndStillRight) {
    const Scene s = postsOnAWideGround();
    const ScoreResult boxes = score(sharedRenderer(), s, options(FitTo::Boxes, 1));
    const ScoreResult sampled = score(sharedRenderer(), s, options(FitTo::ViewDepth, 1));
    ASSERT_GT(sampled.overall.pixels, 10000);
    // One map over the ground behind the wall too: texels wider than the posts.
    EXPECT_GT(boxes.overall.misclassified, 0.002);
    EXPECT_LT(sampled.overall.misclassified, 0.4 * boxes.overall.misclassified);
    EXPECT_LT(sampled.overall.falseShadowOutsideBand, 0.0005);
    EXPECT_LT(sampled.overall.leakOutsideBand, 0.001);
}

TEST(ViewDepthFit, AutoCascadesFollowTheDepthTheViewSees) {
    Scene s = postsOnAWideGround(false);
    Renderer& r = sharedRenderer();
    // Along the ground to the horizon: depths from ~2 to hundreds.
    s.camera.centre = {0.0f, 1.5f, -100.0f};
    r.render(s, options(FitTo::ViewDepth, 0));
    EXPECT_GE(r.lastFrameStats().shadowMaps, 2);
    // Straight down from 4 above: one depth octave, one map.
    s.camera.eye = {0.0f, 4.0f, -6.0f};
    s.camera.centre = {0.0f, 0.0f, -6.01f};
    r.render(s, options(FitTo::ViewDepth, 0));
    EXPECT_EQ(r.lastFrameStats().shadowMaps, 1);
    // Boxes have no view depth to count from: one map.
    s.camera = postsOnAWideGround().camera;
    r.render(s, options(FitTo::Boxes, 0));
    EXPECT_EQ(r.lastFrameStats().shadowMaps, 1);
}

}  // namespace
}  // namespace gnomon::test
