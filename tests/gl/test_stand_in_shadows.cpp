// Stand-in casters (--caster-detail): a finely tessellated sphere over a floor, seen from
// straight above. A tenth of its triangles in the shadow pass
// cuts the pass's triangles about tenfold and leaves the shadow where it was: the floor under
// the sphere dark, beyond its radius lit, and the shadow's area within a few percent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "GlTest.h"
#include "render/GpuScene.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

constexpr float kHalfView = 3.0f;
constexpr int kSize = 128;

// A scene of that name with one matte grey material.
Scene greyScene(const std::string& name) {
    Scene s;
    s.name = name;
    Material grey;
    grey.baseColour = glm::vec3(0.8f);
    grey.specular = 0.0f;
    s.materials.push_back(grey);
    return s;
}

Scene sphereOverFloor() {
    Scene s = greyScene("sphere over floor");
    s.meshes.push_back(mesh::box("floor", {0.0f, -0.05f, 0.0f}, {8.0f, 0.1f, 8.0f}));
    s.meshes.push_back(mesh::sphere("sphere", {0.0f, 1.5f, 0.0f}, 1.0f, 128, 64));
    // The sphere receives no shadow (its own lit top is not what is measured) and casts.
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, false, true});
    s.objects.push_back({"sphere", 1, 0, glm::mat4(1.0f), {}, true, false});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    sun.shadowMapSize = 1024;
    s.lights.push_back(sun);
    s.camera = lookingStraightDown(kHalfView);
    s.ambient = glm::vec3(0.05f);
    s.options.width = s.options.height = kSize;
    return s;
}

// The camera looks straight down and would see the sphere over its own shadow: the sun is
// tilted 45 degrees so that the shadow falls beside it.
TEST(StandInCasters, TenthOfTheTrianglesCastsTheSameShadow) {
    Scene s = sphereOverFloor();
    s.lights[0].direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));  // shadow to +x
    RenderOptions full = s.options, coarse = s.options;
    coarse.shadow.casterDetail = 0.1f;
    const Image a = sharedRenderer().render(s, full);
    const std::uint64_t fullTriangles = sharedRenderer().lastFrameStats().shadowTriangles;
    const Image b = sharedRenderer().render(s, coarse);
    const std::uint64_t coarseTriangles = sharedRenderer().lastFrameStats().shadowTriangles;
    writePng(outputDir() + "/stand_in_full.png", a);
    writePng(outputDir() + "/stand_in_coarse.png", b);
    EXPECT_LE(coarseTriangles * 8, fullTriangles)
        << coarseTriangles << " triangles against " << fullTriangles;

    // The shadow of a sphere at height 1.5 under a 45-degree sun: a disc around x = 1.5
    // (stretched along x) on the floor, right of the sphere's own outline.
    const auto pixel = [&](float x, float z) {
        return std::pair<int, int>{int((x + kHalfView) / (2.0f * kHalfView) * kSize),
                                   int((z + kHalfView) / (2.0f * kHalfView) * kSize)};
    };
    for (const Image* image : {&a, &b}) {
        const auto [sx, sy] = pixel(2.2f, 0.0f);
        const auto [lx, ly] = pixel(-2.5f, 0.0f);
        EXPECT_LT(luminance(image->at(sx, sy)), 100) << "the shadow's centre is lit";
        EXPECT_GT(luminance(image->at(lx, ly)), 300) << "the lit floor is dark";
    }
    long darkA = 0, darkB = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = kSize / 2 + kSize / 6; x < kSize; ++x) {  // right of the sphere's outline
            darkA += luminance(a.at(x, y)) < 200;
            darkB += luminance(b.at(x, y)) < 200;
        }
    }
    ASSERT_GT(darkA, 100);
    EXPECT_LT(std::abs(darkA - darkB), darkA / 20) << darkA << " dark pixels against " << darkB;
}

// A mesh whose file gives a coarser version (MSFT_lod) draws that one at a detail near its
// share: its triangles are the pass's, and the shadow stays where it was.
TEST(StandInCasters, TheFilesOwnVersionCastsTheShadow) {
    Scene s = sphereOverFloor();
    s.lights[0].direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    const Mesh lod = mesh::sphere("sphere, coarse", {0.0f, 1.5f, 0.0f}, 1.0f, 32, 16);
    s.meshes[1].lods.push_back({lod.positions, lod.indices});
    RenderOptions coarse = s.options;
    coarse.shadow.casterDetail = 0.05f;
    const Image b = sharedRenderer().render(s, coarse);
    EXPECT_EQ(sharedRenderer().lastFrameStats().shadowTriangles, lod.indices.size() / 3);
    const Image a = sharedRenderer().render(s, s.options);
    long darkA = 0, darkB = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = kSize / 2 + kSize / 6; x < kSize; ++x) {
            darkA += luminance(a.at(x, y)) < 200;
            darkB += luminance(b.at(x, y)) < 200;
        }
    }
    ASSERT_GT(darkA, 100);
    EXPECT_LT(std::abs(darkA - darkB), darkA / 20) << darkA << " dark pixels against " << darkB;
}

// A bowl (the lower half of a finely tessellated sphere, its inside facing up) under a sun:
// seen from inside, a coarser stand-in's flat triangles cut across the curve in front of the
// surface they stand for and would shadow it where the full bowl does not. Its own lookups
// start off the surface by the stand-in's error, so a tenth of the triangles misclassifies
// about what the full mesh does, with nothing wrong away from shadow edges (without the lift,
// false shadow spreads over the bowl).
TEST(StandInCasters, AConcaveSurfaceIsNotShadowedByItsOwnStandIn) {
    Scene s = greyScene("bowl");
    const Mesh sphere = mesh::sphere("sphere", glm::vec3(0.0f), 2.0f, 384, 192);
    Mesh bowl = sphere;
    bowl.name = "bowl";
    bowl.indices.clear();
    for (std::size_t t = 0; t + 2 < sphere.indices.size(); t += 3) {
        const std::uint32_t a = sphere.indices[t], b = sphere.indices[t + 1],
                            c = sphere.indices[t + 2];
        if (sphere.positions[a].y + sphere.positions[b].y + sphere.positions[c].y > -0.6f) continue;
        bowl.indices.insert(bowl.indices.end(), {a, c, b});  // the inside faces out
    }
    for (glm::vec3& n : bowl.normals)
        n = -n;
    s.meshes.push_back(bowl);
    s.objects.push_back({"bowl", 0, 0, glm::mat4(1.0f), {}, true, true});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.2f));  // the rim shadows a crescent
    s.lights.push_back(sun);
    s.camera = lookingStraightDown(2.2f);
    s.ambient = glm::vec3(0.05f);
    RenderOptions full = s.options, coarse = s.options;
    full.width = full.height = coarse.width = coarse.height = 160;
    coarse.shadow.casterDetail = 0.1f;
    const ScoreResult whole = score(sharedRenderer(), s, full);
    const std::uint64_t fullTriangles = sharedRenderer().lastFrameStats().shadowTriangles;
    const ScoreResult standIn = score(sharedRenderer(), s, coarse);
    const std::uint64_t coarseTriangles = sharedRenderer().lastFrameStats().shadowTriangles;
    ASSERT_LE(coarseTriangles * 8, fullTriangles) << "the stand-in is not drawn";
    ASSERT_GT(whole.overall.pixels, 10000);
    EXPECT_LT(standIn.overall.misclassified, whole.overall.misclassified + 0.004)
        << standIn.overall.misclassified << " with a tenth of the triangles, "
        << whole.overall.misclassified << " with all";
    EXPECT_LT(standIn.overall.falseShadowOutsideBand, 0.0005);
}

// A stand-in is made once per detail and kept: going back to a detail (tune's trials alternate
// with the starting settings; the viewer's slider) switches index ranges, with no new
// simplification or upload. A new geometry drops them.
TEST(StandInCasters, GoingBackToADetailReusesItsStandIn) {
    Scene s = sphereOverFloor();
    sharedRenderer().render(s, s.options);  // a context is current from here on
    render::GpuScene gpu;
    auto triangles = [&] {
        GLsizei count = 0;
        for (const render::DrawItem& item : gpu.items())
            count += item.standInIndexCount / 3;
        return count;
    };
    gpu.sync(s, 0.0, 1.0f);
    const GLsizei full = triangles();
    gpu.sync(s, 0.0, 0.1f);
    const GLsizei tenth = triangles();
    EXPECT_LE(tenth * 8, full);
    const std::uint64_t uploads = gpu.geometryUploads();
    EXPECT_TRUE(gpu.sync(s, 0.0, 1.0f)) << "another detail is a change";
    EXPECT_EQ(triangles(), full);
    EXPECT_TRUE(gpu.sync(s, 0.0, 0.1f));
    EXPECT_EQ(triangles(), tenth);
    EXPECT_EQ(gpu.geometryUploads(), uploads);
    // The sphere made coarser: its stand-ins are made again, for the new mesh.
    s.meshes[1] = mesh::sphere("sphere", {0.0f, 1.5f, 0.0f}, 1.0f, 64, 32);
    s.revision.bump();
    EXPECT_TRUE(gpu.sync(s, 0.0, 0.1f));
    EXPECT_GT(gpu.geometryUploads(), uploads);
    EXPECT_LT(triangles(), tenth);
}

}  // namespace
}  // namespace gnomon::test
