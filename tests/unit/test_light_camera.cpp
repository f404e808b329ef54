// shadow::lightCameraFrame, the light camera of Manual reproduces the given
// look-at and projection, Course looks at the view camera's centre with its up, Fit encloses
// the bounds tightly (directional: orthographic; spot/point: perspective) and an empty scene
// gives an invalid frame. texelWorldSize follows the volume and the map size.
#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "UnitTestUtil.h"
#include "scene/SceneUtil.h"
#include "shadow/ShadowMath.h"

namespace gnomon {
namespace {

using test::matNear;

Light manualPerspective() {
    Light l;
    l.type = LightType::Point;
    l.position = {0.0f, 7.0f, 2.0f};
    l.shadowCamera.policy = ShadowCameraPolicy::Manual;
    l.shadowCamera.projection = Projection::Perspective;
    l.shadowCamera.target = {0.0f, 0.0f, 0.0f};
    l.shadowCamera.up = {0.0f, 1.0f, 0.0f};
    l.shadowCamera.fovyDegrees = 70.0f;
    l.shadowCamera.aspect = 1.0f;
    l.shadowCamera.near = 1.0f;
    l.shadowCamera.far = 100.0f;
    return l;
}

// (a) Manual: lookAt((0,7,2), origin, +y) and perspective(70 deg, 1, 1, 100).
//   f = (0, -7, -2)/sqrt(53) = (0, -0.9615239, -0.2747211), s = (1, 0, 0),
//   u = s x f = (0, -f.z, f.y) = (0, 0.2747211, -0.9615239), translation (0, 0, -sqrt(53)).
//   m[0][0] = m[1][1] = 1/tan(35 deg) = 1.4281480, m[2][2] = -101/99, m[3][2] = -200/99.
TEST(LightCamera, ManualReproducesGivenLookAtAndProjection) {
    const shadow::LightCameraFrame f =
        shadow::lightCameraFrame(manualPerspective(), Camera{}, Aabb{}, 2048);
    ASSERT_TRUE(f.valid);  // Manual needs no bounds
    EXPECT_FALSE(f.orthographic);
    EXPECT_FLOAT_EQ(f.near, 1.0f);
    EXPECT_FLOAT_EQ(f.far, 100.0f);

    glm::mat4 view(1.0f);
    view[0] = {1.0f, 0.0f, 0.0f, 0.0f};
    view[1] = {0.0f, 0.2747211f, 0.9615239f, 0.0f};
    view[2] = {0.0f, -0.9615239f, 0.2747211f, 0.0f};
    view[3] = {0.0f, 0.0f, -7.2801099f, 1.0f};
    EXPECT_PRED_FORMAT3(matNear, f.lightFromWorld, view, 1e-5f);
    EXPECT_PRED_FORMAT3(matNear, f.lightFromWorld,
                        glm::lookAt(glm::vec3(0, 7, 2), glm::vec3(0), glm::vec3(0, 1, 0)), 0.0f);

    glm::mat4 proj(0.0f);
    proj[0][0] = proj[1][1] = 1.4281480f;
    proj[2][2] = -1.0202020f;
    proj[3][2] = -2.0202020f;
    proj[2][3] = -1.0f;
    EXPECT_PRED_FORMAT3(matNear, f.clipFromLight, proj, 1e-5f);
    // Perspective texel size at distance 1: 2 tan(35 deg) / 2048 = 6.837964e-4.
    EXPECT_NEAR(f.texelWorldSize, 6.837964e-4f, 1e-8f);
}

TEST(LightCamera, ManualIgnoresViewCameraAndBounds) {
    Camera other;
    other.eye = {5.0f, 5.0f, 5.0f};
    other.centre = {1.0f, 2.0f, 3.0f};
    Aabb box;
    box.extend(glm::vec3(-50.0f));
    box.extend(glm::vec3(50.0f));
    const auto a = shadow::lightCameraFrame(manualPerspective(), Camera{}, Aabb{}, 2048);
    const auto b = shadow::lightCameraFrame(manualPerspective(), other, box, 2048);
    EXPECT_PRED_FORMAT3(matNear, a.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

// (b) Course: course-two-lights light 0 at (3, 0, 5) looks at the view centre (origin) with
// the view's up +y:  f = (-3, 0, -5)/sqrt(34), s = (5, 0, -3)/sqrt(34) = (0.8574929, 0,
// -0.5144958), u = (0, 1, 0), translation (0, 0, -sqrt(34)) = (0, 0, -5.8309519).
TEST(LightCamera, CourseLooksAtViewCentreWithViewUp) {
    const Scene s = builtinScene("course-two-lights");
    ASSERT_EQ(s.lights.size(), 2u);
    const shadow::LightCameraFrame f = shadow::lightCameraFrame(s.lights[0], s.camera, Aabb{}, 512);
    ASSERT_TRUE(f.valid);
    glm::mat4 view(1.0f);
    view[0] = {0.8574929f, 0.0f, 0.5144958f, 0.0f};
    view[1] = {0.0f, 1.0f, 0.0f, 0.0f};
    view[2] = {-0.5144958f, 0.0f, 0.8574929f, 0.0f};
    view[3] = {0.0f, 0.0f, -5.8309519f, 1.0f};
    EXPECT_PRED_FORMAT3(matNear, f.lightFromWorld, view, 1e-5f);
    // Orthographic +-2, near 1, far 20 as given; texel size 4 / 512.
    EXPECT_TRUE(f.orthographic);
    glm::mat4 proj(0.0f);
    proj[0][0] = proj[1][1] = 0.5f;
    proj[2][2] = -0.1052632f;
    proj[3][2] = -1.1052632f;
    proj[3][3] = 1.0f;
    EXPECT_PRED_FORMAT3(matNear, f.clipFromLight, proj, 1e-6f);
    EXPECT_FLOAT_EQ(f.texelWorldSize, 4.0f / 512.0f);
}

TEST(LightCamera, CourseFollowsAMovedViewCamera) {
    Scene s = builtinScene("course-two-lights");
    s.camera.centre = {1.0f, 2.0f, -1.0f};
    s.camera.up = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    for (const Light& light : s.lights) {
        SCOPED_TRACE(light.name);
        const auto f = shadow::lightCameraFrame(light, s.camera, Aabb{}, 512);
        // The eye is the light; the view centre is on the light camera's axis.
        const glm::vec3 eye = glm::vec3(glm::inverse(f.lightFromWorld)[3]);
        EXPECT_NEAR(glm::distance(eye, light.position), 0.0f, 1e-5f);
        const glm::vec4 c = f.lightFromWorld * glm::vec4(s.camera.centre, 1.0f);
        EXPECT_NEAR(c.x, 0.0f, 1e-5f);
        EXPECT_NEAR(c.y, 0.0f, 1e-5f);
        EXPECT_NEAR(c.z, -glm::distance(light.position, s.camera.centre), 1e-5f);
        // The view's up is the light camera's up: orthogonal to its x axis, positive on y.
        const glm::vec3 up = s.camera.up;
        EXPECT_NEAR((f.lightFromWorld * glm::vec4(up, 0.0f)).x, 0.0f, 1e-5f);
        EXPECT_GT((f.lightFromWorld * glm::vec4(up, 0.0f)).y, 0.0f);
    }
}

// (e) Orthographic texel size is the volume's width over the map size.
TEST(LightCamera, OrthographicTexelSizeIsWidthOverMapSize) {
    Light l = manualPerspective();
    l.shadowCamera.projection = Projection::Orthographic;
    l.shadowCamera.left = -3.0f;
    l.shadowCamera.right = 5.0f;  // 8 wide
    l.shadowCamera.bottom = -1.0f;
    l.shadowCamera.top = 1.0f;  // 2 high
    for (int size : {64, 512, 4096}) {
        const auto f = shadow::lightCameraFrame(l, Camera{}, Aabb{}, size);
        EXPECT_FLOAT_EQ(f.texelWorldSize, 8.0f / float(size)) << "map size " << size;
    }
}

// Corner depths in front of the light camera (its view looks down -z).
void depthRange(const shadow::LightCameraFrame& f, const Aabb& b, float& nearest, float& farthest) {
    nearest = std::numeric_limits<float>::max();
    farthest = std::numeric_limits<float>::lowest();
    for (const glm::vec3& c : b.corners()) {
        const float d = -(f.lightFromWorld * glm::vec4(c, 1.0f)).z;
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
}

Aabb tutorialRoomBounds() {
    const Scene s = builtinScene("tutorial-room");
    return worldBounds(s, meshBounds(s), 0.0, false);
}

// (c) Fit for a directional light, over several directions (straight down exercises the
// safeLookAt fallback since the fit's up is +y).
struct DirectionCase {
    const char* name;
    glm::vec3 direction;
};
void PrintTo(const DirectionCase& c, std::ostream* os) {
    *os << c.name;
}
class DirectionalFit : public testing::TestWithParam<DirectionCase> {};

TEST_P(DirectionalFit, HoldsEveryCornerTightly) {
    Aabb boxes[2] = {tutorialRoomBounds(), Aabb{}};
    boxes[1].extend(glm::vec3(-1.0f, 0.5f, 2.0f));
    boxes[1].extend(glm::vec3(3.0f, 1.5f, 9.0f));
    for (const Aabb& bounds : boxes) {
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = GetParam().direction;
        sun.shadowCamera.policy = ShadowCameraPolicy::Fit;
        const auto f = shadow::lightCameraFrame(sun, Camera{}, bounds, 2048);
        ASSERT_TRUE(f.valid);
        ASSERT_TRUE(f.orthographic);
        ASSERT_TRUE(test::allFinite(f.clipFromWorld()));
        // The camera looks along the light's direction.
        const glm::vec3 forward(-f.lightFromWorld[0][2], -f.lightFromWorld[1][2],
                                -f.lightFromWorld[2][2]);
        EXPECT_NEAR(glm::dot(forward, glm::normalize(GetParam().direction)), 1.0f, 1e-5f);

        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& c : bounds.corners()) {
            const glm::vec4 clip = f.clipFromWorld() * glm::vec4(c, 1.0f);
            EXPECT_FLOAT_EQ(clip.w, 1.0f);
            lo = glm::min(lo, glm::vec3(clip));
            hi = glm::max(hi, glm::vec3(clip));
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(lo[k], -1.0f) << "axis " << k;
            EXPECT_LE(hi[k], 1.0f) << "axis " << k;
        }
        // Tight: some corner within 1% of each x and y face.
        EXPECT_LE(lo.x, -0.99f);
        EXPECT_GE(hi.x, 0.99f);
        EXPECT_LE(lo.y, -0.99f);
        EXPECT_GE(hi.y, 0.99f);
        // Near/far within 1% of the corners' depth range, and outside it.
        float nearest = 0.0f, farthest = 0.0f;
        depthRange(f, bounds, nearest, farthest);
        const float range = farthest - nearest;
        ASSERT_GT(range, 0.0f);
        EXPECT_LE(f.near, nearest);
        EXPECT_GE(f.far, farthest);
        EXPECT_NEAR(f.near, nearest, 0.01f * range);
        EXPECT_NEAR(f.far, farthest, 0.01f * range);
        // texelWorldSize is the larger side of the fitted volume over the map size.
        const float w = 2.0f / f.clipFromLight[0][0], h = 2.0f / f.clipFromLight[1][1];
        EXPECT_NEAR(f.texelWorldSize, std::max(w, h) / 2048.0f, 1e-6f);
    }
}

INSTANTIATE_TEST_SUITE_P(Directions, DirectionalFit,
                         testing::Values(DirectionCase{"TutorialSun", {0.267f, -0.802f, 0.535f}},
                                         DirectionCase{"StraightDown", {0.0f, -1.0f, 0.0f}},
                                         DirectionCase{"AlmostDown", {1e-5f, -1.0f, 0.0f}},
                                         DirectionCase{"Horizontal", {1.0f, 0.0f, 0.0f}},
                                         DirectionCase{"Diagonal", {-1.0f, -1.0f, -1.0f}}));

// Degenerate (a point) and small-but-distant bounds: the fit must still hold every corner.
// The volume's margin is 1e-3 * radius, so it must also allow for float rounding of the
// light-space coordinates, which grows with their magnitude (~6e-5 at 1000).
TEST(LightCamera, DirectionalFitHoldsPointAndDistantSmallBounds) {
    const struct {
        glm::vec3 at;
        float size;
    } cases[] = {{{1.0f, 2.0f, 3.0f}, 0.0f},
                 {{1000.0f, 500.0f, 1000.0f}, 0.1f},
                 {{10000.0f, 5000.0f, 10000.0f}, 1.0f}};
    std::string outside;
    for (const auto& c : cases) {
        Aabb bounds;
        bounds.extend(c.at);
        bounds.extend(c.at + glm::vec3(c.size));
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = {0.267f, -0.802f, 0.535f};
        const auto f = shadow::lightCameraFrame(sun, Camera{}, bounds, 2048);
        ASSERT_TRUE(f.valid);
        ASSERT_TRUE(test::allFinite(f.clipFromWorld()));
        float worst = 0.0f;
        for (const glm::vec3& corner : bounds.corners()) {
            const glm::vec4 clip = f.clipFromWorld() * glm::vec4(corner, 1.0f);
            for (int k = 0; k < 3; ++k)
                worst = std::max(worst, std::fabs(clip[k] / clip.w));
        }
        if (worst > 1.0f) {
            outside += " [box of size " + std::to_string(c.size) +
                       " at x = " + std::to_string(c.at.x) + ": |ndc| " + std::to_string(worst) +
                       "]";
        }
    }
    EXPECT_TRUE(outside.empty()) << "corners outside the clip volume:" << outside;
}

// Every corner inside the perspective volume, near/far at the corners within 2%.
void expectPerspectiveHolds(const shadow::LightCameraFrame& f, const Aabb& bounds) {
    ASSERT_TRUE(f.valid);
    ASSERT_FALSE(f.orthographic);
    ASSERT_TRUE(test::allFinite(f.clipFromWorld()));
    for (const glm::vec3& c : bounds.corners()) {
        const glm::vec4 clip = f.clipFromWorld() * glm::vec4(c, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(ndc[k], -1.0f)
                << "axis " << k << " corner " << c.x << "," << c.y << "," << c.z;
            EXPECT_LE(ndc[k], 1.0f)
                << "axis " << k << " corner " << c.x << "," << c.y << "," << c.z;
        }
    }
    float nearest = 0.0f, farthest = 0.0f;
    depthRange(f, bounds, nearest, farthest);
    EXPECT_LE(f.near, nearest);
    EXPECT_GE(f.near, 0.98f * nearest);
    EXPECT_GE(f.far, farthest);
    EXPECT_LE(f.far, 1.02f * farthest);
}

// (d) Fit for a spot light: fovy is twice the outer cone half-angle, aspect 1.
TEST(LightCamera, SpotFitHoldsBoundsInsideConeDerivedFrustum) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 10.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};  // straight down: safeLookAt fallback
    spot.outerConeDegrees = 30.0f;
    Aabb bounds;
    bounds.extend(glm::vec3(-2.0f, 0.0f, -2.0f));
    bounds.extend(glm::vec3(2.0f, 1.0f, 2.0f));
    const auto f = shadow::lightCameraFrame(spot, Camera{}, bounds, 1024);
    expectPerspectiveHolds(f, bounds);
    // 1 / tan(30 deg) = 1.7320508 on both axes.
    EXPECT_NEAR(f.clipFromLight[1][1], 1.7320508f, 1e-5f);
    EXPECT_NEAR(f.clipFromLight[0][0], 1.7320508f, 1e-5f);
    // Corners at depth 9..10 from the light: near ~ 9, far ~ 10.
    EXPECT_NEAR(f.near, 9.0f, 0.1f);
    EXPECT_NEAR(f.far, 10.0f, 0.11f);
    EXPECT_NEAR(f.texelWorldSize, 2.0f * std::tan(glm::radians(30.0f)) / 1024.0f, 1e-7f);
}

TEST(LightCamera, SpotFitAlongASlantedAxis) {
    // The tutorial's spot position, aimed at a box around (1, 0.5, 1).
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {-3.0f, 10.0f, -6.0f};
    spot.direction = glm::vec3(1.0f, 0.5f, 1.0f) - spot.position;
    spot.outerConeDegrees = 25.0f;
    Aabb bounds;
    bounds.extend(glm::vec3(-1.0f, 0.0f, -1.0f));
    bounds.extend(glm::vec3(3.0f, 1.0f, 3.0f));
    const auto f = shadow::lightCameraFrame(spot, Camera{}, bounds, 1024);
    expectPerspectiveHolds(f, bounds);
    const glm::vec3 forward(-f.lightFromWorld[0][2], -f.lightFromWorld[1][2],
                            -f.lightFromWorld[2][2]);
    EXPECT_NEAR(glm::dot(forward, glm::normalize(spot.direction)), 1.0f, 1e-5f);
}

// A fitted point light is omnidirectional: a cube whose far plane reaches every corner,
// with each corner inside the frustum of the face its direction selects.
void expectCubeHolds(const Light& point, const Aabb& bounds) {
    const auto f = shadow::lightCameraFrame(point, Camera{}, bounds, 1024);
    ASSERT_TRUE(f.valid);
    ASSERT_EQ(f.kind, shadow::FrameKind::Cube);
    EXPECT_GT(f.near, 0.0f);
    EXPECT_LT(f.near, f.far);
    EXPECT_NEAR(f.texelWorldSize, 2.0f / 1024.0f, 1e-9f);
    for (const glm::vec3& c : bounds.corners()) {
        const glm::vec3 d = c - point.position;
        EXPECT_LE(glm::length(d), f.far) << "corner beyond the far plane";
        const glm::vec3 a = glm::abs(d);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        const int face = 2 * axis + (d[axis] < 0.0f ? 1 : 0);
        const glm::vec4 clip = f.faceClipFromWorld(face) * glm::vec4(c, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        for (int k = 0; k < 2; ++k)
            EXPECT_LE(std::fabs(clip[k] / clip.w), 1.0f + 1e-5f);
        EXPECT_NEAR(0.5f * clip.z / clip.w + 0.5f, shadow::cubeStoredDepth(d, f.near, f.far),
                    1e-5f);
    }
}

TEST(LightCamera, PointFitFromOutsideIsACubeHoldingEveryCorner) {
    Light point;
    point.type = LightType::Point;
    point.position = {0.0f, 7.0f, 2.0f};
    Aabb bounds;
    bounds.extend(glm::vec3(-3.0f, -2.0f, -3.0f));
    bounds.extend(glm::vec3(3.0f, 0.0f, 3.0f));
    expectCubeHolds(point, bounds);
}

TEST(LightCamera, PointFitFromInsideIsACubeHoldingEveryCorner) {
    Light point;
    point.type = LightType::Point;
    point.position = {0.5f, 0.5f, 0.5f};
    Aabb bounds;
    bounds.extend(glm::vec3(-2.0f));
    bounds.extend(glm::vec3(2.0f));
    expectCubeHolds(point, bounds);
}

// A cube face's depth runs along its axis: a caster towards a corner of the face is nearer
// there than its Euclidean distance (here 1 against 1.41). A near plane beyond it flattens
// the caster and the receiver behind it (1.25 along the axis) to depth 0 and the receiver
// reads lit: glmark2's horse under a point light at (0, 3, 2) lost its head's shadow so.
TEST(LightCamera, PointFitNearIsInFrontOfCastersTowardsAFaceCorner) {
    Light point;
    point.type = LightType::Point;
    point.position = glm::vec3(0.0f);
    Aabb caster, receiver;
    caster.extend(glm::vec3(1.0f, 0.7f, 0.7f));
    caster.extend(glm::vec3(1.05f, 0.9f, 0.9f));
    receiver.extend(glm::vec3(1.25f, 0.5f, 0.5f));
    receiver.extend(glm::vec3(1.3f, 1.2f, 1.2f));
    shadow::FitScene scene;
    scene.casters = {caster, receiver};
    scene.receivers = {caster, receiver};
    const auto f = shadow::lightCameraFrame(point, Camera{}, scene, 1024);
    ASSERT_TRUE(f.valid);
    ASSERT_EQ(f.kind, shadow::FrameKind::Cube);
    EXPECT_LE(f.near, 1.0f) << "near cuts into the caster along the +X face's axis";
    EXPECT_GE(f.near, 0.9f) << "near no longer hugs the nearest caster: precision wasted";
    for (const glm::vec3& c : caster.corners()) {
        EXPECT_GE(shadow::cubeStoredDepth(c - point.position, f.near, f.far), 0.0f);
    }
}

// OpenGL 4.5 spec, table 8.19: for a direction r, the face of the major axis ma and
// s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2 with, per face, (sc, tc) =
// +X: (-rz, -ry)  -X: (+rz, -ry)  +Y: (+rx, +rz)  -Y: (+rx, -rz)  +Z: (+rx, -ry)  -Z: (-rx, -ry).
// Rendering face f through cubeFaceRotation(f) must put direction r at window (s, t).
TEST(CubeFaces, RenderedFacesMatchTheSamplingConvention) {
    const glm::mat4 clipFromLight = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f);
    const glm::vec3 dirs[6] = {{1.0f, 0.3f, -0.6f},  {-1.0f, 0.3f, -0.6f}, {0.3f, 1.0f, -0.6f},
                               {0.3f, -1.0f, -0.6f}, {0.3f, -0.6f, 1.0f},  {0.3f, -0.6f, -1.0f}};
    for (int face = 0; face < 6; ++face) {
        const glm::vec3 r = dirs[face];
        float sc = 0, tc = 0, ma = 0;
        switch (face) {
            case 0:
                sc = -r.z;
                tc = -r.y;
                ma = r.x;
                break;
            case 1:
                sc = r.z;
                tc = -r.y;
                ma = r.x;
                break;
            case 2:
                sc = r.x;
                tc = r.z;
                ma = r.y;
                break;
            case 3:
                sc = r.x;
                tc = -r.z;
                ma = r.y;
                break;
            case 4:
                sc = r.x;
                tc = -r.y;
                ma = r.z;
                break;
            case 5:
                sc = -r.x;
                tc = -r.y;
                ma = r.z;
                break;
        }
        const float s = 0.5f * (sc / std::fabs(ma) + 1.0f), t = 0.5f * (tc / std::fabs(ma) + 1.0f);
        const glm::vec4 clip = clipFromLight * shadow::cubeFaceRotation(face) * glm::vec4(r, 1.0f);
        EXPECT_NEAR(0.5f * clip.x / clip.w + 0.5f, s, 1e-5f) << "face " << face;
        EXPECT_NEAR(0.5f * clip.y / clip.w + 0.5f, t, 1e-5f) << "face " << face;
        EXPECT_GT(clip.w, 0.0f) << "face " << face << " looks away from its axis";
    }
}

// (f) Nothing to shadow: Fit with empty bounds gives an invalid frame, for every light type.
TEST(LightCamera, FitWithEmptyBoundsIsInvalid) {
    for (LightType type : {LightType::Directional, LightType::Spot, LightType::Point}) {
        Light l;
        l.type = type;
        l.position = {0.0f, 5.0f, 0.0f};
        l.shadowCamera.policy = ShadowCameraPolicy::Fit;
        EXPECT_FALSE(shadow::lightCameraFrame(l, Camera{}, Aabb{}, 1024).valid)
            << "light type " << int(type);
    }
}

}  // namespace
}  // namespace gnomon
