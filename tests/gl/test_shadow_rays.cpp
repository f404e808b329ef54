// --shadow-rays all: every shadowed light's lookup is a ray through the casters' BVH in the
// main pass's fragment shader. Scored against the ray-traced reference, it must misclassify
// next to nothing on the built-in scenes, do better than a coarse map where the map errs, put
// shadows where the geometry says, and rebuild its hierarchy only when casters change.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "GlTest.h"
#include "RayTest.h"
#include "ShadowCheck.h"
#include "core/Aabb.h"
#include "render/GpuScene.h"
#include "render/RayScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

RenderOptions traced(const Scene& s, int size) {
    return withRays(s, size, ShadowRayMode::All);
}

// The bound for every lookup traced: the share for `all`, plus one pair.
void expectNearlyExact(const ScoreResult& r) {
    expectWrongAtMost(r, 0.00005, 1.0);
}

TEST(ShadowRays, AllAgreesWithTheReference) {
    for (const char* name :
         {"book-triangle", "tutorial-room", "tutorial-spot", "tutorial-point", "mixed-lights"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        const ScoreResult r = score(sharedRenderer(), s, traced(s, 128));
        std::printf("%-16s pixels %ld, misclassified %.6f %% (%.0f pairs)\n", name,
                    r.overall.pixels, 100.0 * r.overall.misclassified, wrongPairs(r));
        ASSERT_GT(r.overall.pixels, 1000);
        expectNearlyExact(r);
    }
}

// A 64-texel map with no filter misses much of tutorial-room's shadows' edges; the rays do
// not depend on it.
TEST(ShadowRays, BeatACoarseMap) {
    const Scene s = builtinScene("tutorial-room");
    RenderOptions map = s.options;
    map.width = map.height = 128;
    map.shadow.mapSize = 64;
    map.shadow.filter = ShadowFilter::None;
    map.shadow.shadowRays = ShadowRayMode::Off;
    RenderOptions rays = map;
    rays.shadow.shadowRays = ShadowRayMode::All;
    const ScoreResult m = score(sharedRenderer(), s, map);
    const ScoreResult r = score(sharedRenderer(), s, rays);
    std::printf("map %.5f %%, rays %.5f %%\n", 100.0 * m.overall.misclassified,
                100.0 * r.overall.misclassified);
    EXPECT_GT(m.overall.misclassified, 0.001);
    EXPECT_LT(r.overall.misclassified, m.overall.misclassified);
    expectNearlyExact(r);
}

// A floor all but edge-on to a low sun: its triangles' normals, from their corners, put the
// sun 1.2e-3 (cosine) above it, the edge-on bound being 1e-3; its vertex normals lean 2.5e-4
// away from the sun, under the bound. The reference takes the triangles' normals; the rays
// must too, or the whole floor turns dark where the reference lights it.
TEST(ShadowRays, AFloorAllButEdgeOnFollowsItsTriangles) {
    Scene s;
    s.name = "edge-on-floor";
    s.materials.push_back(Material{});
    Mesh floor = mesh::quad("floor", {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10});
    for (glm::vec3& n : floor.normals)
        n = glm::normalize(glm::vec3(0.0f, 1.0f, 2.5e-4f));
    s.meshes.push_back(floor);
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = -glm::normalize(glm::vec3(0.0f, 1.2e-3f, -1.0f));
    s.lights.push_back(sun);
    s.camera.eye = {0.0f, 12.0f, 4.0f};
    s.camera.centre = {0.0f, 0.0f, 0.0f};
    const ScoreResult r = score(sharedRenderer(), s, traced(s, 64));
    ASSERT_GT(r.overall.pixels, 1000);
    expectNearlyExact(r);
}

// Dark where the geometry shadows (a CPU ray cast), lit elsewhere, even under a map too
// coarse to say so itself.
TEST(ShadowRays, ShadowsWhereTheGeometrySays) {
    for (const char* name : {"tutorial-room", "tutorial-spot", "tutorial-point"}) {
        SCOPED_TRACE(name);
        const Scene s = builtinScene(name);
        RenderOptions o = traced(s, 256);
        o.shadow.mapSize = 64;
        o.shadow.filter = ShadowFilter::None;
        expectShadowsMatchGeometry(s, o);
    }
}

// The start table names, for each triangle the main pass draws (an object's mesh reordered
// and cut into pieces, two objects sharing a mesh), the hierarchy's triangle of the same
// object and mesh triangle; a receiver that casts nothing has none.
TEST(ShadowRays, StartTableNamesTheTrianglesDrawn) {
    Scene s = builtinScene("tutorial-room");
    s.meshes.push_back(mesh::sphere("sphere", glm::vec3(0.0f), 0.3f, 24, 12));
    for (float x : {-0.5f, 0.5f}) {
        Object o;
        o.mesh = std::uint32_t(s.meshes.size() - 1);
        o.worldFromModel = glm::translate(glm::mat4(1.0f), glm::vec3(x, 1.0f, 0.0f));
        s.objects.push_back(o);
    }
    s.objects[0].castsShadows = false;
    s.revision.bump();
    RenderOptions o = traced(s, 16);
    sharedRenderer().render(s, o);  // its context (and its limits) current
    if (!gl::activeCaps().drawIndirect) GTEST_SKIP() << "ES draws name no triangle: no table";
    render::GpuScene gpu;
    gpu.sync(s, 0.0);
    render::RayScene rays;
    int built = 0;
    ASSERT_NE(rays.forFrame(s, o, gpu, built), nullptr);
    // A caster moved under uncertain, which reads no table: the next frame under all reads
    // one for the hierarchy built then.
    s.objects.back().worldFromModel[3].z += 0.25f;
    s.revision.bump();
    gpu.sync(s, 0.0);
    RenderOptions uncertain = o;
    uncertain.shadow.shadowRays = ShadowRayMode::Uncertain;
    ASSERT_NE(rays.forFrame(s, uncertain, gpu, built), nullptr);
    ASSERT_EQ(built, 1);
    ASSERT_NE(rays.forFrame(s, o, gpu, built), nullptr);
    EXPECT_EQ(built, 0);
    auto texels = [](const gl::Texture& t) {
        std::vector<float> v(4 * std::size_t(t.width()) * std::size_t(t.height()));
        t.read(0, 0, 0, t.width(), t.height(), GL_RGBA, GL_FLOAT, v.size() * sizeof(float),
               v.data());
        return v;
    };
    const std::vector<float> starts = texels(rays.starts()), tris = texels(rays.triangles());
    const render::DrawnTriangles& drawn = gpu.drawnTriangles();
    std::size_t checked = 0;
    for (std::size_t obj = 0; obj < s.objects.size(); ++obj) {
        const std::uint32_t mesh = s.objects[obj].mesh;
        const std::vector<std::uint32_t>& places = drawn.places(mesh);
        ASSERT_EQ(places.size(), s.meshes[mesh].indices.size() / 3);
        for (std::size_t t = 0; t < places.size(); ++t) {
            ASSERT_NE(places[t], kNoPlace);
            const int tri = int(starts[drawn.objectFirst(obj) + places[t]]);
            if (!s.objects[obj].castsShadows) {
                EXPECT_EQ(tri, -1);
                continue;
            }
            ASSERT_GE(tri, 0);
            EXPECT_EQ(tris[12 * std::size_t(tri) + 3], float(obj));  // BvhTriangle::object
            EXPECT_EQ(tris[12 * std::size_t(tri) + 7], float(t));    // ::primitive
            ++checked;
        }
    }
    EXPECT_EQ(checked, rays.triangleCount());
}

// The hierarchy is built once per set of casters: not again for the same revision, nor for a
// new one that moved nothing that casts; again when a caster moves.
TEST(ShadowRays, BuiltOnlyWhenCastersChange) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions small = s.options;
    small.width = small.height = 16;
    sharedRenderer().render(s, small);  // its context (and its limits) current
    ShadowOptions so;
    render::RayScene rays;
    rays.update(s, 0.0, 1, 7, so);
    EXPECT_EQ(rays.builds(), 1u);
    EXPECT_GT(rays.triangleCount(), 0u);
    rays.update(s, 0.0, 1, 7, so);
    EXPECT_EQ(rays.builds(), 1u);
    std::size_t receiver = s.objects.size(), caster = s.objects.size();
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        (s.objects[i].castsShadows ? caster : receiver) = i;
    ASSERT_LT(caster, s.objects.size());
    if (receiver == s.objects.size()) {  // make one: a receiver's motion rebuilds nothing
        receiver = caster == 0 ? 1 : 0;
        s.objects[receiver].castsShadows = false;
        rays.update(s, 0.0, 2, 7, so);
        EXPECT_EQ(rays.builds(), 2u);
    }
    const std::uint64_t before = rays.builds();
    s.objects[receiver].worldFromModel[3].x += 1.0f;
    rays.update(s, 0.0, 3, 7, so);
    EXPECT_EQ(rays.builds(), before);
    s.objects[caster].worldFromModel[3].x += 1.0f;
    rays.update(s, 0.0, 4, 7, so);
    EXPECT_EQ(rays.builds(), before + 1);
    rays.update(s, 0.0, 5, 8, so);  // new geometry
    EXPECT_EQ(rays.builds(), before + 2);
}

// The radius of every object's points, as the reference's margin measures the scene.
float sceneRadius(const Scene& s) {
    Aabb box;
    for (const Object& obj : s.objects) {
        for (const glm::vec3& p : s.meshes[obj.mesh].positions)
            box.extend(glm::vec3(obj.worldFromModel * glm::vec4(p, 1.0f)));
    }
    return box.radius();
}

// The rays' margin follows the reference's scale: every object's radius, receivers' too, kept
// as a receiver moves (without building the hierarchy again) and as a mesh changes.
TEST(ShadowRays, ScaleIsEveryObjectsRadius) {
    Scene s = builtinScene("tutorial-room");
    RenderOptions small = s.options;
    small.width = small.height = 16;
    sharedRenderer().render(s, small);  // its context (and its limits) current
    std::size_t receiver = s.objects.size();
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        if (!s.objects[i].castsShadows) receiver = i;
    }
    if (receiver == s.objects.size()) {
        receiver = 0;
        s.objects[0].castsShadows = false;
    }
    ShadowOptions so;
    render::RayScene rays;
    rays.update(s, 0.0, 1, 7, so);
    EXPECT_NEAR(rays.scale(), sceneRadius(s), 1e-5f * sceneRadius(s));
    const float before = rays.scale();
    s.objects[receiver].worldFromModel[3].x += 10.0f * before;
    rays.update(s, 0.0, 2, 7, so);
    EXPECT_NEAR(rays.scale(), sceneRadius(s), 1e-5f * sceneRadius(s));
    EXPECT_GT(rays.scale(), 2.0f * before);
    EXPECT_EQ(rays.builds(), 1u);
    // A mesh's points changed in place: the GPU scene's geometry hash tells.
    for (glm::vec3& p : s.meshes[s.objects[receiver].mesh].positions)
        p *= 3.0f;
    rays.update(s, 0.0, 3, 8, so);
    EXPECT_NEAR(rays.scale(), sceneRadius(s), 1e-5f * sceneRadius(s));
}

// Through the renderer: an unchanged scene builds nothing after its first frame; the book's
// triangle, a caster, turning with time does.
TEST(ShadowRays, RendererBuildsOnlyForNewCasters) {
    const Scene s = builtinScene("book-triangle");
    RenderOptions o = traced(s, 32);
    Renderer& r = sharedRenderer();
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowRayBuilds, 1);
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowRayBuilds, 0);
    o.time = 0.5;
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowRayBuilds, 1);
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowRayBuilds, 0);
    o.shadow.shadowRays = ShadowRayMode::Off;
    r.render(s, o);
    EXPECT_EQ(r.lastFrameStats().shadowRayBuilds, 0);
}

}  // namespace
}  // namespace gnomon::test
