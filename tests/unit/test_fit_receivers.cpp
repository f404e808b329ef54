// The Fit policy with a view: the light camera holds the visible receivers that
// casters can shadow, and those casters, and no more; it is invalid when nothing can be
// shadowed; a view-following fit does not change for small camera moves.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

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

// A 40 x 40 floor at y = 0, one 2 x 2 x 2 block standing on it at the origin, and a camera
// looking down at the floor around `centre` with a 40 degree field of view from `height`
// above (10: it sees the floor out to 10 tan(20 deg) = 3.64 either side). The floor casts shadows
// only when `floorCasts` (a box cannot tell that a flat floor never shadows itself).
shadow::FitScene blockOnFloor(glm::vec3 centre, bool floorCasts = false, float height = 10.0f) {
    shadow::FitScene s;
    const Aabb floor = box({-20, -0.1f, -20}, {20, 0, 20});
    const Aabb block = box({-1, 0, -1}, {1, 2, 1});
    s.casters = {block};
    if (floorCasts) s.casters.push_back(floor);
    s.receivers = {floor, block};
    s.viewKnown = true;
    Camera cam;
    cam.eye = centre + glm::vec3(0, height, 0.01f);
    cam.centre = centre;
    cam.fovyDegrees = 40.0f;
    cam.near = 0.5f;
    cam.far = 50.0f;
    s.viewClipFromWorld = gnomon::clipFromView(cam, 1.0f) * gnomon::viewFromWorld(cam);
    return s;
}

Light sunAlong(glm::vec3 direction) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = direction;
    return sun;
}

glm::vec3 mapCoord(const shadow::LightCameraFrame& f, glm::vec3 p) {
    const glm::vec4 c = shadow::textureFromClip() * f.clipFromWorld() * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

bool inside(glm::vec3 c) {
    return glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
           glm::all(glm::lessThanEqual(c, glm::vec3(1.0f)));
}

// Straight down onto the block: every receiver point under the block (where its shadow
// falls) and the block's own top are inside the map; the map is no wider than the block
// plus the snap's slack (a 40-unit floor would need a 20x wider map).
TEST(FitReceivers, DirectionalHoldsTheShadowedReceiversAndNoMore) {
    const shadow::FitScene s = blockOnFloor({0, 0, 0});
    const auto f = shadow::lightCameraFrame(sunAlong({0, -1, 0}), Camera{}, s, 1024);
    ASSERT_TRUE(f.valid);
    for (float x = -1.0f; x <= 1.0f; x += 0.25f) {
        for (float z = -1.0f; z <= 1.0f; z += 0.25f) {
            EXPECT_TRUE(inside(mapCoord(f, {x, 0.0f, z}))) << x << ", 0, " << z;  // floor
            EXPECT_TRUE(inside(mapCoord(f, {x, 2.0f, z}))) << x << ", 2, " << z;  // block top
        }
    }
    const float width = 2.0f / f.clipFromLight[0][0];
    EXPECT_GE(width, 2.0f);
    EXPECT_LE(width, 2.0f * 1.15f);
    EXPECT_NEAR(f.texelWorldSize, width / 1024.0f, 1e-6f);
    // Depth: from the block's top (the nearest caster) to the floor's bottom, plus margins
    // of 1/1000 at either end, then quantised (steps of 1/16 of a power of two, with a
    // step's room for snapping the near plane): at most 2/16 more.
    EXPECT_GE(f.far - f.near, 2.1f);
    EXPECT_LE(f.far - f.near, 2.1f * 1.002f * (1.0f + 2.0f / 16.0f));
}

// When the floor casts too, the map covers the floor the camera sees (7.3 wide plus the
// slack of the floor's thickness at the frustum's edge), not the 40-unit floor.
TEST(FitReceivers, DirectionalHoldsOnlyTheVisibleFloor) {
    const shadow::FitScene s = blockOnFloor({0, 0, 0}, true);
    const auto f = shadow::lightCameraFrame(sunAlong({0, -1, 0}), Camera{}, s, 1024);
    ASSERT_TRUE(f.valid);
    const float width = 2.0f / f.clipFromLight[0][0];
    EXPECT_GE(width, 7.28f);
    EXPECT_LE(width, 7.4f * 1.15f);
    for (float x = -3.6f; x <= 3.6f; x += 0.4f) {
        for (float z = -3.6f; z <= 3.6f; z += 0.4f) {
            EXPECT_TRUE(inside(mapCoord(f, {x, 0.0f, z}))) << x << ", 0, " << z;
        }
    }
}

// A slanted sun: the block's shadow on the floor reaches beyond the block; the receivers it
// can fall on (the floor's points whose ray to the light meets the block) are in the map.
TEST(FitReceivers, SlantedSunHoldsTheWholeShadow) {
    const shadow::FitScene s = blockOnFloor({2, 0, 0});
    const glm::vec3 dir = glm::normalize(glm::vec3(1, -1, 0.3f));
    const auto f = shadow::lightCameraFrame(sunAlong(dir), Camera{}, s, 1024);
    ASSERT_TRUE(f.valid);
    int shadowed = 0;
    for (float x = -6.0f; x <= 6.0f; x += 0.1f) {
        for (float z = -6.0f; z <= 6.0f; z += 0.1f) {
            const glm::vec3 p(x, 0.0f, z);
            // Does the ray from p towards the light hit the block [-1,1] x [0,2] x [-1,1]?
            const glm::vec3 o = p, d = -dir;
            float t0 = 0.0f, t1 = 1e9f;
            const glm::vec3 lo(-1, 0, -1), hi(1, 2, 1);
            for (int k = 0; k < 3; ++k) {
                if (std::fabs(d[k]) < 1e-9f) {
                    if (o[k] < lo[k] || o[k] > hi[k]) t1 = -1.0f;
                    continue;
                }
                float a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
                if (a > b) std::swap(a, b);
                t0 = std::max(t0, a);
                t1 = std::min(t1, b);
            }
            if (t0 > t1) continue;
            ++shadowed;
            EXPECT_TRUE(inside(mapCoord(f, p))) << x << ", 0, " << z;
        }
    }
    EXPECT_GT(shadowed, 100);
}

// A floor of zero thickness (what --ground adds, and most scanned ground planes): clipping
// it to the view frustum must not lose it to rounding, or the map's depth range stops at
// the caster's foot and the floor's shadowed points fall beyond its far plane (read as lit).
TEST(FitReceivers, FlatFloorStaysAReceiver) {
    for (const glm::vec3 centre : {glm::vec3(0, 0, 0), glm::vec3(2.3f, 0, -1.7f)}) {
        shadow::FitScene s = blockOnFloor(centre);
        s.receivers[0] = box({-20.123f, 0.0137f, -20.456f}, {20.789f, 0.0137f, 20.321f});
        const glm::vec3 dir = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
        const auto f = shadow::lightCameraFrame(sunAlong(dir), Camera{}, s, 1024);
        ASSERT_TRUE(f.valid);
        // The block's shadow on the floor: the floor points below its top corners.
        for (const glm::vec3 top :
             {glm::vec3(-1, 2, -1), glm::vec3(1, 2, 1), glm::vec3(-1, 2, 1), glm::vec3(1, 2, -1)}) {
            const glm::vec3 p = top + dir * ((2.0f - 0.0137f) / -dir.y);
            EXPECT_TRUE(inside(mapCoord(f, p))) << p.x << ", " << p.y << ", " << p.z;
        }
    }
}

// Receivers out of view do not count: with the camera looking at a corner of the floor far
// from the block, nothing visible can be shadowed: no map is needed.
TEST(FitReceivers, NothingVisibleToShadowNeedsNoMap) {
    const shadow::FitScene s = blockOnFloor({15, 0, 15});
    EXPECT_FALSE(shadow::lightCameraFrame(sunAlong({0, -1, 0}), Camera{}, s, 1024).valid);
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 8, 0};
    spot.direction = {0, -1, 0};
    spot.outerConeDegrees = 20.0f;
    EXPECT_FALSE(shadow::lightCameraFrame(spot, Camera{}, s, 1024).valid);
}

// No casters: nothing can be shadowed, for every light type.
TEST(FitReceivers, NoCastersNeedsNoMap) {
    shadow::FitScene s = blockOnFloor({0, 0, 0});
    s.casters.clear();
    for (LightType type :
         {LightType::Directional, LightType::Area, LightType::Spot, LightType::Point}) {
        Light l = sunAlong({0, -1, 0});
        l.type = type;
        l.position = {0, 8, 0};
        EXPECT_FALSE(shadow::lightCameraFrame(l, Camera{}, s, 512).valid) << int(type);
    }
}

// A caster farther from the light than every receiver cannot shadow one: it does not widen
// the map. Here a second block hangs below the floor, beside the first.
TEST(FitReceivers, CastersBehindTheReceiversAreIgnored) {
    shadow::FitScene s = blockOnFloor({0, 0, 0});
    s.casters.push_back(box({4, -5, -1}, {6, -3, 1}));
    const auto with = shadow::lightCameraFrame(sunAlong({0, -1, 0}), Camera{}, s, 1024);
    s.casters.pop_back();
    const auto without = shadow::lightCameraFrame(sunAlong({0, -1, 0}), Camera{}, s, 1024);
    ASSERT_TRUE(with.valid);
    EXPECT_PRED_FORMAT3(test::matNear, with.clipFromWorld(), without.clipFromWorld(), 0.0f);
}

// The spot's far plane stops at the farthest visible receiver in its cone, near at the
// nearest caster; the fov stays the cone's.
TEST(FitReceivers, SpotDepthRangeFollowsCastersAndReceivers) {
    const shadow::FitScene s = blockOnFloor({0, 0, 0});
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 8, 0};
    spot.direction = {0, -1, 0};
    spot.outerConeDegrees = 20.0f;
    const auto f = shadow::lightCameraFrame(spot, Camera{}, s, 1024);
    ASSERT_TRUE(f.valid);
    EXPECT_NEAR(f.clipFromLight[1][1], 1.0f / std::tan(glm::radians(20.0f)), 1e-5f);
    EXPECT_NEAR(f.near, 6.0f * 0.99f, 1e-3f);  // the block's top is 6 below the light
    EXPECT_NEAR(f.far, 8.1f * 1.01f, 1e-3f);   // the floor's bottom 8.1 below
}

// A point light's cube reaches the farthest visible receiver corner, not the whole floor.
TEST(FitReceivers, PointFarPlaneReachesOnlyVisibleReceivers) {
    const shadow::FitScene s = blockOnFloor({0, 0, 0});
    Light point;
    point.type = LightType::Point;
    point.position = {0, 5, 0};
    const auto f = shadow::lightCameraFrame(point, Camera{}, s, 512);
    ASSERT_TRUE(f.valid);
    // The visible floor's farthest corner, (3.64, -0.1, 3.64) from (0, 5, 0), is 7.25 away
    // (the floor's own corner is 28.7 away); far is 1% beyond it.
    EXPECT_NEAR(f.far, 1.01f * 7.25f, 0.05f);
}

// Following the view, the fit is snapped: a camera moved by less than a texel gives the
// same light camera (the cached map stays valid, nothing shimmers), and a large move a new
// one that still holds the shadow.
TEST(FitReceivers, SmallCameraMovesKeepTheSameCamera) {
    const glm::vec3 dir = glm::normalize(glm::vec3(0.4f, -1, 0.2f));
    const auto a =
        shadow::lightCameraFrame(sunAlong(dir), Camera{}, blockOnFloor({0.5f, 0, 0}), 1024);
    const auto b =
        shadow::lightCameraFrame(sunAlong(dir), Camera{}, blockOnFloor({0.5001f, 0, 0}), 1024);
    ASSERT_TRUE(a.valid && b.valid);
    EXPECT_PRED_FORMAT3(test::matNear, a.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

// A stabilised fit that follows a moving view keeps its extent from frame to frame
// (shadow::HeldExtent): unchanged while it covers what the view needs and is not much
// looser than a fresh fit; refitted when the view leaves it, when it grows too loose, or
// when the light turns. The floor casts, so the map covers the floor the view sees.
shadow::FitScene viewFrom(glm::vec3 centre, float height) {
    return blockOnFloor(centre, true, height);
}

float width(const shadow::LightCameraFrame& f) {
    return 2.0f / f.clipFromLight[0][0];
}

const glm::vec3 kDown(0.3f, -1.0f, 0.2f);

// A view that moves a little, whose needs stay inside the held box: the very same camera.
TEST(HeldExtent, SmallMovesKeepTheHeldCamera) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    ASSERT_TRUE(a.valid && held.valid);
    // Lower by 3 %: the view needs a little less floor, all of it inside the held box.
    const auto b =
        shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 9.7f), 1024, &held);
    ASSERT_TRUE(b.valid);
    EXPECT_PRED_FORMAT3(test::matNear, a.clipFromWorld(), b.clipFromWorld(), 0.0f);
    // Without the held extent the same view is fitted afresh, tighter.
    const auto fresh =
        shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 9.7f), 1024);
    EXPECT_LT(width(fresh), width(b));
}

// A view that slides beyond the held box: a new camera that covers the new view.
TEST(HeldExtent, LeavingTheHeldBoxRefits) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    const auto b = shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({5, 0, 0}, 10.0f),
                                            1024, &held);
    ASSERT_TRUE(a.valid && b.valid);
    // Refitted as a following frame with nothing held is (a still frame fits its short side
    // tighter: shadow::snapExtent).
    shadow::HeldExtent none;
    const auto fresh = shadow::lightCameraFrame(sunAlong(kDown), Camera{},
                                                viewFrom({5, 0, 0}, 10.0f), 1024, &none);
    EXPECT_PRED_FORMAT3(test::matNear, fresh.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

// A view that comes much closer needs a much smaller box: beyond kHoldSlack the held box
// would waste the map's texels, so it is refitted.
TEST(HeldExtent, ALooseHeldBoxRefits) {
    shadow::HeldExtent held;
    const auto a = shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    const auto b =
        shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 6.0f), 1024, &held);
    ASSERT_TRUE(a.valid && b.valid);
    EXPECT_LT(width(b), width(a) / shadow::kHoldSlack);
}

// A turned light: the held box belongs to the old light space and is not reused.
TEST(HeldExtent, ATurnedLightRefits) {
    shadow::HeldExtent held;
    (void)shadow::lightCameraFrame(sunAlong(kDown), Camera{}, viewFrom({0, 0, 0}, 10.0f), 1024,
                                   &held);
    const glm::vec3 turned(0.31f, -1.0f, 0.2f);
    const auto b = shadow::lightCameraFrame(sunAlong(turned), Camera{}, viewFrom({0, 0, 0}, 10.0f),
                                            1024, &held);
    shadow::HeldExtent none;
    const auto fresh = shadow::lightCameraFrame(sunAlong(turned), Camera{},
                                                viewFrom({0, 0, 0}, 10.0f), 1024, &none);
    EXPECT_PRED_FORMAT3(test::matNear, fresh.clipFromWorld(), b.clipFromWorld(), 0.0f);
}

}  // namespace
}  // namespace gnomon

namespace gnomon {
namespace {

// A spot light tilted 45 degrees over a wide floor whose box reaches behind the light: near
// sits at the nearest floor point inside the cone's frustum (~4.6 here), not at the box's
// nearest corner (behind the light: near would fall to far / 1000 and a constant tolerance
// in stored depth would span world units at the far end).
TEST(FitReceivers, SpotNearIgnoresCasterPartsOutsideTheCone) {
    shadow::FitScene s;
    s.casters = {box({-50, -0.1f, -50}, {50, 0, 50})};
    s.receivers = s.casters;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 5, 0};
    spot.direction = glm::normalize(glm::vec3(1, -1, 0));
    spot.outerConeDegrees = 20.0f;
    const auto f = shadow::lightCameraFrame(spot, Camera{}, s, 1024);
    ASSERT_TRUE(f.valid);
    EXPECT_GT(f.near, 4.0f);
    EXPECT_LT(f.near, 5.2f);
    // Every floor point the cone sees lies between near and far.
    for (float x = 0.0f; x <= 30.0f; x += 0.5f) {
        for (float z = -15.0f; z <= 15.0f; z += 0.5f) {
            const glm::vec3 p(x, 0.0f, z);
            const glm::vec3 toP = glm::normalize(p - spot.position);
            if (glm::dot(toP, spot.direction) < std::cos(glm::radians(20.0f))) continue;
            const float depth = -(f.lightFromWorld * glm::vec4(p, 1.0f)).z;
            EXPECT_GE(depth, f.near) << x << ", " << z;
            EXPECT_LE(depth, f.far) << x << ", " << z;
        }
    }
}

}  // namespace
}  // namespace gnomon
