// A stabilised directional fit that follows a moving view keeps its extent from frame to
// frame (shadow::HeldExtent): unchanged while it covers what the view needs and is not much
// looser than a fresh fit; refitted when the view leaves it, when it grows too loose, or when
// the light turns.
#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

// A floor that casts and receives, seen from `height` above `centre` (40 degree field of
// view): the map must cover the floor the camera sees, 2 x height x tan(20 deg) across.
shadow::FitScene floorSeenFrom(glm::vec3 centre, float height) {
    shadow::FitScene s;
    const Aabb floor = box({-50, -0.1f, -50}, {50, 0, 50});
    s.casters = {floor};
    s.receivers = {floor};
    s.viewKnown = true;
    Camera cam;
    cam.eye = centre + glm::vec3(0, height, 0.01f);
    cam.centre = centre;
    cam.fovyDegrees = 40.0f;
    cam.near = 0.5f;
    cam.far = 100.0f;
    s.viewClipFromWorld = shadow::clipFromView(cam, 1.0f) * shadow::viewFromWorld(cam);
    return s;
}

Light sun(glm::vec3 direction) {
    Light l;
    l.type = LightType::Directional;
    l.direction = glm::normalize(direction);
    return l;
}

float width(const shadow::LightCameraFrame& f) {
    return 2.0f / f.clipFromLight[0][0];
}

const glm::vec3 kDown(0.3f, -1.0f, 0.2f);

// A view that moves a little, whose needs stay inside the held box: the very same camera.
TEST(HeldExtent, SmallMovesKeepTheHeldCamera) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    ASSERT_TRUE(a.valid && held.valid);
    // Lower by 3 %: the view needs a little less floor, all of it inside the held box.
    const auto b =
        shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 9.7f), 1024, &held);
    ASSERT_TRUE(b.valid);
    EXPECT_PRED_FORMAT3(test::matNear, a.clipFromWorld(), b.clipFromWorld(), 0.0f);
    // Without the held extent the same view is fitted afresh, tighter.
    const auto fresh =
        shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 9.7f), 1024);
    EXPECT_LT(width(fresh), width(b));
}

// A view that slides beyond the held box: a new camera that covers the new view.
TEST(HeldExtent, LeavingTheHeldBoxRefits) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    const auto b = shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({5, 0, 0}, 10.0f),
                                            1024, &held);
    ASSERT_TRUE(a.valid && b.valid);
    const auto fresh =
        shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({5, 0, 0}, 10.0f), 1024);
    EXPECT_PRED_FORMAT3(test::matNear, fresh.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

// A view that comes much closer needs a much smaller box: beyond kHoldSlack the held box
// would waste the map's texels, so it is refitted.
TEST(HeldExtent, ALooseHeldBoxRefits) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    const auto b =
        shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 6.0f), 1024, &held);
    ASSERT_TRUE(a.valid && b.valid);
    EXPECT_LT(width(b), width(a) / shadow::kHoldSlack);
}

// A turned light: the held box belongs to the old light space and is not reused.
TEST(HeldExtent, ATurnedLightRefits) {
    shadow::HeldExtent held;
    (void)shadow::lightCameraFrame(sun(kDown), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f), 1024,
                                   &held);
    const glm::vec3 turned(0.31f, -1.0f, 0.2f);
    const auto b = shadow::lightCameraFrame(sun(turned), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    const auto fresh =
        shadow::lightCameraFrame(sun(turned), Camera{}, floorSeenFrom({0, 0, 0}, 10.0f), 1024);
    EXPECT_PRED_FORMAT3(test::matNear, fresh.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

}  // namespace
}  // namespace gnomon
