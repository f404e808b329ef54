// An object that receives shadows but casts none (a ground added by --ground, glmark2's) is in
// no shadow map, so nothing a lookup finds there can be itself: the main pass looks it up with
// the plain comparison, without the tolerances against self-shadowing (RECEIVER_ONLY in
// MainPass). Its shadows must stay right where those tolerances matter most for the others: a
// low sun grazing the ground, and a spot light whose map's texels grow with distance.
#include <gtest/gtest.h>

#include "GlTest.h"
#include "GroundScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

// Posts and a block on a ground that casts nothing.
Scene postsOnAReceivingGround(const Light& light) {
    Scene s = sceneWithGround("posts on a receiving ground", 30.0f);
    s.objects.front().castsShadows = false;
    for (int i = 0; i < 4; ++i) {
        s.meshes.push_back(
            mesh::box("post", {-3.0f + 2.0f * float(i), 1.0f, -1.0f}, {0.2f, 2.0f, 0.2f}));
        s.objects.push_back(
            {"post", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
    }
    s.meshes.push_back(mesh::box("block", {0.5f, 0.5f, 2.0f}, {1.0f, 1.0f, 1.0f}));
    s.objects.push_back(
        {"block", std::uint32_t(s.meshes.size() - 1), 0, glm::mat4(1.0f), {}, true, true});
    s.lights.push_back(light);
    s.camera.eye = {2.0f, 4.0f, 9.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    s.camera.fovyDegrees = 50.0f;
    s.ambient = glm::vec3(0.1f);
    return s;
}

void expectRight(const Scene& s, const char* what) {
    ASSERT_FALSE(s.objects.front().castsShadows);
    RenderOptions o;
    o.width = o.height = 160;
    ScoreOptions so;
    so.contactRange = 0.5f;  // the posts' and the block's feet
    const ScoreResult r = score(sharedRenderer(), s, o, so);
    ASSERT_GT(r.overall.pixels, 10000) << what;
    EXPECT_LT(r.overall.misclassified, 0.01) << what;
    EXPECT_LT(r.overall.falseShadowOutsideBand, 0.0005) << what;
    EXPECT_LT(r.overall.leakOutsideBand, 0.001) << what;
    // The feet: the pixels the reference shadows within 0.5 of the occluder are shadowed as
    // rendered too (a tolerance of 0.01 stored depth on the ground would let some through).
    ASSERT_GT(r.overall.contactPixels, 50) << what;
    EXPECT_LT(r.overall.contactLeak, 0.01) << what;
}

TEST(ReceiverOnly, AGroundThatCastsNothingIsRightUnderALowSun) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-1.0f, -0.2f, -0.4f));  // 10.5 degrees high
    expectRight(postsOnAReceivingGround(sun), "low sun");
}

TEST(ReceiverOnly, AGroundThatCastsNothingIsRightUnderASpot) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {-6.0f, 5.0f, 4.0f};
    spot.direction = glm::normalize(glm::vec3(6.0f, -5.0f, -4.0f));
    spot.outerConeDegrees = 40.0f;
    spot.innerConeDegrees = 30.0f;
    expectRight(postsOnAReceivingGround(spot), "spot");
}

}  // namespace
}  // namespace gnomon::test
