// scene/SceneUtil.h, what shadow fitting reads from a scene: mesh bounds in model space,
// world bounds at a time (animated objects move them; castersOnly drops non-casters), and
// which lights are on (RenderOptions::lightOnly overrides the scene's switches).
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "scene/SceneUtil.h"

namespace gnomon {
namespace {

size_t indexOf(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.objects.size(); ++i)
        if (s.objects[i].name == name) return i;
    throw std::runtime_error("no object " + name);
}

TEST(SceneUtil, MeshBoundsAreInModelSpaceAndInMeshOrder) {
    const Scene s = builtinScene("book-triangle");
    const std::vector<Aabb> boxes = meshBounds(s);
    ASSERT_EQ(boxes.size(), s.meshes.size());
    const Aabb& tri = boxes.at(s.objects.at(indexOf(s, "triangle")).mesh);
    test::expectVec(tri.min, {-0.8f, 3.5f, 0.0f}, 0.0f);
    test::expectVec(tri.max, {0.8f, 3.5f, 1.8f}, 0.0f);
    // The plane before its tilt: 6 x 5 at y = -1.7.
    const Aabb& plane = boxes.at(s.objects.at(indexOf(s, "plane")).mesh);
    test::expectVec(plane.min, {-3.0f, -1.7f, -2.5f}, 0.0f);
    test::expectVec(plane.max, {3.0f, -1.7f, 2.5f}, 0.0f);
}

TEST(SceneUtil, MeshWithoutVerticesHasEmptyBounds) {
    Scene s;
    s.meshes.resize(1);
    ASSERT_EQ(meshBounds(s).size(), 1u);
    EXPECT_TRUE(meshBounds(s)[0].empty());
    EXPECT_TRUE(worldBounds(s, meshBounds(s), 0.0, false).empty());  // no objects
}

TEST(SceneUtil, CastersOnlyDropsNonCasters) {
    Scene s = builtinScene("book-triangle");
    s.objects[indexOf(s, "plane")].castsShadows = false;
    const Aabb all = worldBounds(s, meshBounds(s), 0.0, false);
    const Aabb casters = worldBounds(s, meshBounds(s), 0.0, true);
    // Only the (unspun) triangle is left.
    test::expectVec(casters.min, {-0.8f, 3.5f, 0.0f});
    test::expectVec(casters.max, {0.8f, 3.5f, 1.8f});
    // The tilted plane reaches below the triangle.
    EXPECT_LT(all.min.y, -1.0f);
    EXPECT_LE(all.min.x, casters.min.x);
    EXPECT_GE(all.max.y, casters.max.y);
    // With every caster off, nothing is left to shadow.
    for (Object& o : s.objects)
        o.castsShadows = false;
    EXPECT_TRUE(worldBounds(s, meshBounds(s), 0.0, true).empty());
}

// At 2.25 s the triangle has turned 90 deg about y, (x, y, z) -> (z, y, -x): its bounds go
// from x [-0.8, 0.8], z [0, 1.8] to x [0, 1.8], z [-0.8, 0.8].
TEST(SceneUtil, WorldBoundsFollowAnimation) {
    Scene s = builtinScene("book-triangle");
    s.objects[indexOf(s, "plane")].castsShadows = false;
    const Aabb b = worldBounds(s, meshBounds(s), 2.25, true);
    test::expectVec(b.min, {0.0f, 3.5f, -0.8f});
    test::expectVec(b.max, {1.8f, 3.5f, 0.8f});
}

TEST(SceneUtil, WorldBoundsOfTutorialRoom) {
    // Thick variant: the floor box spans x, z in [-10.5, 10.5] and y in [-0.5, 0]; the walls
    // rise to 6; nothing else sticks out.
    const Scene s = builtinScene("tutorial-room");
    const Aabb b = worldBounds(s, meshBounds(s), 0.0, false);
    test::expectVec(b.min, {-10.5f, -0.5f, -10.5f});
    test::expectVec(b.max, {10.5f, 6.0f, 10.5f});
}

// Coordinates are taken relative to the origin for a scene around it (the numbers of scenes
// built there unchanged), and near the scene's centre when it lies far out, on a grid of
// about its size that small motions do not leave.
TEST(SceneUtil, CoordinateOriginStaysAtZeroNearItAndFollowsAFarScene) {
    EXPECT_EQ(coordinateOrigin(Aabb()), glm::vec3(0.0f));
    EXPECT_EQ(coordinateOrigin(Aabb{{-3, 0, -3}, {3, 2, 3}}), glm::vec3(0.0f));
    EXPECT_EQ(coordinateOrigin(Aabb{{3, 0, 3}, {7, 2, 7}}), glm::vec3(0.0f));  // 2.4 radii out
    const Aabb far{{9999, 0, -10001}, {10001, 2, -9999}};
    const glm::vec3 o = coordinateOrigin(far);
    EXPECT_LT(glm::length(o - far.centre()), far.radius());
    // The radius is 1.7: a grid of 2. Moved by a tenth of its size, it keeps the same origin.
    const Aabb moved{far.min + glm::vec3(0.17f, 0, 0), far.max + glm::vec3(0.17f, 0, 0)};
    EXPECT_EQ(coordinateOrigin(moved), o);
    const float grid = 2.0f;
    EXPECT_EQ(o / grid, glm::round(o / grid)) << "on the grid";
    // Not finite: no origin to take.
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(coordinateOrigin(Aabb{{inf, 0, 0}, {inf, 1, 1}}), glm::vec3(0.0f));
}

TEST(SceneUtil, LightIsOnFollowsSceneSwitchesUnlessLightOnly) {
    Scene s = builtinScene("course-two-lights");
    s.lights[1].enabled = false;
    RenderOptions o;
    EXPECT_TRUE(lightIsOn(s, o, 0));
    EXPECT_FALSE(lightIsOn(s, o, 1));
    o.lightOnly = 1;  // overrides: only light 1, even though the scene has it off
    EXPECT_FALSE(lightIsOn(s, o, 0));
    EXPECT_TRUE(lightIsOn(s, o, 1));
    o.lightOnly = 0;
    EXPECT_TRUE(lightIsOn(s, o, 0));
    EXPECT_FALSE(lightIsOn(s, o, 1));
}

TEST(SceneUtil, SpinAboutAnOffsetPivot) {
    // A spin about y through pivot (1, 0, 0) at 90 deg/s: after 1 s the point (2, 0, 0)
    // (one unit +x of the pivot) goes to one unit -z of it: (1, 0, -1).
    Object o;
    o.spin = Spin{{0.0f, 1.0f, 0.0f}, 90.0f, {1.0f, 0.0f, 0.0f}};
    test::expectVec(glm::vec3(o.worldFromModelAt(1.0) * glm::vec4(2.0f, 0.0f, 0.0f, 1.0f)),
                    {1.0f, 0.0f, -1.0f});
    // The pivot itself does not move, and the spin applies after worldFromModel.
    o.worldFromModel[3] = glm::vec4(0.0f, 5.0f, 0.0f, 1.0f);  // lift by 5
    test::expectVec(glm::vec3(o.worldFromModelAt(1.0) * glm::vec4(1.0f, -5.0f, 0.0f, 1.0f)),
                    {1.0f, 0.0f, 0.0f});
    // At time 0 there is no spin.
    test::expectVec(glm::vec3(o.worldFromModelAt(0.0) * glm::vec4(2.0f, 0.0f, 0.0f, 1.0f)),
                    {2.0f, 5.0f, 0.0f});
}

}  // namespace
}  // namespace gnomon
