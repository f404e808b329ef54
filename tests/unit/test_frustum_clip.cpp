// Which casters a light's pass skips: boxes wholly outside a map's clip volume (but those in
// front of near kept when depth clamps), and for cubes, only those beyond the far sphere.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "shadow/FrustumClip.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

// A box wholly outside any plane is culled, one inside or straddling is kept.
TEST(Culling, BoxesOutsideTheClipVolumeAreCulled) {
    const glm::mat4 clipFromWorld =
        glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 10.0f) *
        glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    auto box = [](glm::vec3 c, float h) {
        Aabb b;
        b.extend(c - glm::vec3(h));
        b.extend(c + glm::vec3(h));
        return b;
    };
    EXPECT_FALSE(shadow::outsideClipVolume(box({0, 0, 0}, 0.5f), clipFromWorld, false));
    EXPECT_FALSE(
        shadow::outsideClipVolume(box({1.2f, 0, 0}, 0.5f), clipFromWorld, false));  // straddles
    EXPECT_TRUE(shadow::outsideClipVolume(box({3, 0, 0}, 0.5f), clipFromWorld, false));
    EXPECT_TRUE(shadow::outsideClipVolume(box({0, -3, 0}, 0.5f), clipFromWorld, false));
    EXPECT_TRUE(
        shadow::outsideClipVolume(box({0, 0, -8}, 0.5f), clipFromWorld, false));  // beyond far
    // In front of the near plane (between the camera and near): culled unless depth clamps.
    EXPECT_TRUE(shadow::outsideClipVolume(box({0, 0, 4.6f}, 0.2f), clipFromWorld, false));
    EXPECT_FALSE(shadow::outsideClipVolume(box({0, 0, 4.6f}, 0.2f), clipFromWorld, true));
    EXPECT_TRUE(shadow::outsideClipVolume(Aabb{}, clipFromWorld, false));
}

// A box wholly past the near plane (whatever the sides) has no line of sight starting inside
// it; one the near plane cuts, or one behind the eye, may.
TEST(Culling, BoxesBeyondTheNearPlane) {
    const glm::mat4 clipFromWorld =
        glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 10.0f) *
        glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0.0f), glm::vec3(0, 1, 0));  // near at z 4.5
    auto box = [](glm::vec3 c, float h) {
        Aabb b;
        b.extend(c - glm::vec3(h));
        b.extend(c + glm::vec3(h));
        return b;
    };
    EXPECT_TRUE(shadow::beyondNearPlane(box({0, 0, 0}, 0.5f), clipFromWorld));
    EXPECT_TRUE(shadow::beyondNearPlane(box({30, 0, 0}, 0.5f), clipFromWorld));     // aside
    EXPECT_FALSE(shadow::beyondNearPlane(box({0, 0, 4.5f}, 0.2f), clipFromWorld));  // cut
    EXPECT_FALSE(shadow::beyondNearPlane(box({0, 0, 5}, 0.1f), clipFromWorld));     // eye in it
    EXPECT_FALSE(shadow::beyondNearPlane(box({0, 0, 8}, 0.5f), clipFromWorld));     // behind
    EXPECT_FALSE(shadow::beyondNearPlane(Aabb{}, clipFromWorld));
}

TEST(Culling, CubesCullOnlyBeyondTheirFarSphere) {
    Light point;
    point.type = LightType::Point;
    point.position = {0.0f, 0.0f, 0.0f};
    Aabb bounds;
    bounds.extend(glm::vec3(-3.0f));
    bounds.extend(glm::vec3(3.0f));
    const auto cube = shadow::lightCameraFrame(point, Camera{}, bounds, 256);
    Aabb near, far;
    near.extend(glm::vec3(-0.1f, 2.0f, 0.0f));
    near.extend(glm::vec3(0.1f, 2.5f, 0.1f));
    far.extend(glm::vec3(50.0f));
    far.extend(glm::vec3(51.0f));
    EXPECT_FALSE(shadow::outsideCube(near, cube));
    EXPECT_TRUE(shadow::outsideCube(far, cube));
}

}  // namespace
}  // namespace gnomon
