// The depth pass stores what the light camera's projection says: for a floor at a known
// distance under an orthographic light (linear depth) and a perspective light (the
// perspective depth's closed form), and for a caster above the floor.
#include <gtest/gtest.h>

#include "GlTest.h"
#include "render/GpuScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

Scene floorUnderLight(Projection projection, bool withBox) {
    Scene s;
    s.name = "depth probe";
    s.materials.push_back(Material{});
    s.meshes.push_back(mesh::quad("floor", {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    if (withBox) {
        s.meshes.push_back(mesh::box("box", {0.0f, 1.0f, 0.0f}, {2.0f, 2.0f, 2.0f}));
        s.objects.push_back({"box", 1, 0, glm::mat4(1.0f), {}, true, true});
    }
    Light l;
    l.type = LightType::Point;
    l.position = {0.0f, 10.0f, 0.0f};
    l.shadowMapSize = 256;
    l.shadowCamera.policy = ShadowCameraPolicy::Manual;
    l.shadowCamera.projection = projection;
    l.shadowCamera.target = {0.0f, 0.0f, 0.0f};
    l.shadowCamera.up = {0.0f, 0.0f, -1.0f};
    l.shadowCamera.left = l.shadowCamera.bottom = -5.0f;
    l.shadowCamera.right = l.shadowCamera.top = 5.0f;
    l.shadowCamera.fovyDegrees = 60.0f;
    l.shadowCamera.near = 1.0f;
    l.shadowCamera.far = projection == Projection::Orthographic ? 21.0f : 100.0f;
    s.lights.push_back(l);
    s.camera.eye = {0.0f, 20.0f, 0.1f};
    return s;
}

double storedAt(const Image16& map, double u, double v) {
    const int x = int(u * map.width), y = int((1.0 - v) * map.height);
    return map.pixels[size_t(y) * map.width + x] / 65535.0;
}

RenderOptions exactDepth() {
    RenderOptions o;
    o.width = o.height = 64;
    o.shadow.biasSlope = 0.0f;  // polygon offset would move the stored depth
    o.shadow.biasUnits = 0.0f;
    return o;
}

constexpr double kTol = 2.0 / 65535.0;  // the 16-bit read-back's rounding, twice

TEST(DepthPass, OrthographicFloorDepthIsLinear) {
    GNOMON_NEEDS_DEPTH_READBACK();
    sharedRenderer().render(floorUnderLight(Projection::Orthographic, false), exactDepth());
    const Image16 map = sharedRenderer().shadowMaps().at(0).depth;
    ASSERT_EQ(map.width, 256);
    // Floor 10 units below the light, near 1, far 21: (10 - 1) / 20.
    for (double u : {0.1, 0.5, 0.9})
        EXPECT_NEAR(storedAt(map, u, 0.5), 0.45, kTol) << u;
}

TEST(DepthPass, OrthographicCasterIsNearer) {
    GNOMON_NEEDS_DEPTH_READBACK();
    sharedRenderer().render(floorUnderLight(Projection::Orthographic, true), exactDepth());
    const Image16 map = sharedRenderer().shadowMaps().at(0).depth;
    EXPECT_NEAR(storedAt(map, 0.5, 0.5), (10.0 - 2.0 - 1.0) / 20.0, kTol);  // box top, y = 2
    EXPECT_NEAR(storedAt(map, 0.05, 0.05), 0.45, kTol);                     // floor beside it
}

TEST(DepthPass, PerspectiveDepthFollowsClosedForm) {
    GNOMON_NEEDS_DEPTH_READBACK();
    sharedRenderer().render(floorUnderLight(Projection::Perspective, false), exactDepth());
    const Image16 map = sharedRenderer().shadowMaps().at(0).depth;
    const double n = 1.0, f = 100.0, d = 10.0;
    const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * d);
    // The floor is perpendicular to the light axis: the same view depth everywhere.
    for (double u : {0.25, 0.5, 0.75})
        EXPECT_NEAR(storedAt(map, u, 0.5), ndc * 0.5 + 0.5, kTol);
}

TEST(DepthPass, StaticMapsAreNotRenderedAgain) {
    const Scene s = floorUnderLight(Projection::Perspective, true);
    sharedRenderer().render(s, exactDepth());
    sharedRenderer().render(s, exactDepth());
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 0);
    RenderOptions moved = exactDepth();
    moved.shadow.biasSlope = 1.0f;  // depth-pass state changed: the map must be redone
    sharedRenderer().render(s, moved);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 1);
}

TEST(DepthPass, AnimationRerendersTheMap) {
    const Scene s = builtinScene("book-triangle");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    sharedRenderer().render(s, o);
    o.time = 0.5;
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 1);
}

}  // namespace
}  // namespace gnomon::test

namespace gnomon::test {
namespace {

// casters outside a light's volume are not drawn into its map, and moving
// them does not re-render it; moving a caster inside the volume does.
TEST(Cost, MapsFollowOnlyTheCastersInTheirVolume) {
    Scene s = builtinScene("course-two-lights");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    sharedRenderer().render(s, o);
    FrameStats stats = sharedRenderer().lastFrameStats();
    EXPECT_EQ(stats.shadowMaps, 2);
    EXPECT_EQ(stats.shadowPasses, 2);
    // Light 0 at (3, 0, 5) sees the second copy at (-4, 0, -4) behind the first (about 1.4
    // off its axis, inside its +-2 box); light 1 at (-3, 0, 5) does not: it culls the copy's
    // three planes. 6 + 6 triangles for light 0, 6 for light 1.
    EXPECT_EQ(stats.shadowTriangles, 18u);
    EXPECT_EQ(stats.castersCulled, 3);
    EXPECT_EQ(stats.mainTriangles, 12u);

    // Move a plane of the far copy: only light 0's map follows it; light 1 keeps its map.
    s.objects[4].worldFromModel[3] += glm::vec4(0.0f, 0.5f, 0.0f, 0.0f);
    s.revision.bump();
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 1);

    // Nothing moves: both maps are kept.
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 0);

    // Move a plane of the near copy: both maps see it, both are redrawn.
    s.objects[1].worldFromModel[3] += glm::vec4(0.1f, 0.0f, 0.0f, 0.0f);
    s.revision.bump();
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 2);
}

// The light plan is kept while nothing it is made from changes (a still view of an unchanged
// scene plans nothing); lights and the camera are not covered by the scene's revision, so an
// edit to either, unannounced, must still be seen.
TEST(Cost, ALightOrCameraEditedInPlaceIsPlannedAgain) {
    Scene s = builtinScene("tutorial-spot");
    RenderOptions o = s.options;
    o.width = o.height = 64;
    sharedRenderer().render(s, o);
    const Image before = sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 0);
    s.lights[0].position += glm::vec3(1.0f, 0.0f, 0.0f);
    const Image moved = sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowPasses, 1);
    EXPECT_NE(before.pixels, moved.pixels);
    s.lights[0].enabled = false;
    sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowMaps, 0);
    s.lights[0].enabled = true;
    s.camera.eye += glm::vec3(0.0f, 0.0f, 2.0f);
    const Image away = sharedRenderer().render(s, o);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowMaps, 1);
    EXPECT_NE(away.pixels, moved.pixels);
}

TEST(Cost, AnUnchangedSceneIsNotReadAgain) {
    // The GPU copy reads a scene's meshes, textures and objects (hashing every byte) only
    // for a revision or a time it has not synced.
    Scene s = builtinScene("tutorial-room");
    RenderOptions o = s.options;
    o.width = o.height = 32;
    sharedRenderer().render(s, o);  // a context is current from here on
    render::GpuScene gpu;
    EXPECT_TRUE(gpu.sync(s, 0.0));
    const std::uint64_t revision = gpu.revision();
    EXPECT_FALSE(gpu.sync(s, 0.0));
    // A copy has a new revision: hashed, found the same, nothing uploaded.
    const Scene copy = s;
    EXPECT_NE(copy.revision.value(), s.revision.value());
    EXPECT_FALSE(gpu.sync(copy, 0.0));
    EXPECT_EQ(gpu.revision(), revision);
    // An edit announced by a bump is seen.
    s.objects[0].worldFromModel[3] += glm::vec4(0.5f, 0.0f, 0.0f, 0.0f);
    s.revision.bump();
    EXPECT_TRUE(gpu.sync(s, 0.0));
    EXPECT_GT(gpu.revision(), revision);
    // So is a vertex moved in place, after a bump.
    s.meshes[0].positions[0].y += 0.25f;
    EXPECT_FALSE(gpu.sync(s, 0.0)) << "not announced: the copy keeps what it had";
    s.revision.bump();
    EXPECT_TRUE(gpu.sync(s, 0.0));
    // An object that stops casting changes no record the GPU holds, yet the maps must lose it:
    // the revision moves, so the renderer draws its maps and light plan again.
    const std::uint64_t casting = gpu.revision();
    s.objects[0].castsShadows = !s.objects[0].castsShadows;
    s.revision.bump();
    EXPECT_TRUE(gpu.sync(s, 0.0));
    EXPECT_GT(gpu.revision(), casting);
}

}  // namespace
}  // namespace gnomon::test
