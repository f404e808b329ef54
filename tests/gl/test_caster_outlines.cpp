// The casters' outlines beside the 2D maps (render/EdgeMaps.h, render/CasterEdges.h). A mesh's
// edges pair the two triangles on each side, across the seams where loaders repeat a vertex,
// so that the light's outlines can be told from the edges inside a surface; under
// --shadow-rays uncertain a caster thinner than a texel, which the map misses, still gets
// its shadow from the rays.
#include <gtest/gtest.h>

#include <cstdio>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "GlTest.h"
#include "RayTest.h"
#include "render/CasterEdges.h"
#include "scene/MeshBuilder.h"

namespace gnomon::test {
namespace {

using render::EdgeVertex;

// Each edge is two vertices holding the same ends the other way round and the same corners.
void expectPairs(const std::vector<EdgeVertex>& lines) {
    ASSERT_EQ(lines.size() % 2, 0u);
    for (std::size_t i = 0; i < lines.size(); i += 2) {
        EXPECT_EQ(lines[i].position, lines[i + 1].other);
        EXPECT_EQ(lines[i].other, lines[i + 1].position);
        EXPECT_EQ(lines[i].cornerA, lines[i + 1].cornerA);
        EXPECT_EQ(lines[i].cornerB, lines[i + 1].cornerB);
    }
}

// edge.vert.glsl's contour rule for a light far away along `toLight`: both triangles' far
// corners on one side of the plane through the edge and the light, or a border.
bool contour(const EdgeVertex& v, const glm::vec3& toLight) {
    const glm::vec3 across = glm::cross(v.other - v.position, toLight);
    const float a = glm::dot(across, v.cornerA - v.position);
    const float b = glm::dot(across, glm::vec3(v.cornerB) - v.position);
    return v.cornerB.w == 0.0f || a * b >= 0.0f;
}

TEST(CasterOutlines, ABoxsContourIsSixEdgesFromAnyGenericSide) {
    // 24 vertices, four a face: every edge's two triangles are found through positions.
    const Mesh box = mesh::box("box", {0.0f, 0.0f, 0.0f}, {2.0f, 2.0f, 2.0f});
    ASSERT_EQ(box.positions.size(), 24u);
    const std::vector<EdgeVertex> lines = render::meshEdges(box);
    expectPairs(lines);
    ASSERT_EQ(lines.size(), 2u * 18u);  // 12 box edges, 6 faces' diagonals
    for (const glm::vec3 toLight : {glm::vec3(1, 2, 3), glm::vec3(-3, 1, 0.5f)}) {
        int contours = 0;
        for (std::size_t i = 0; i < lines.size(); i += 2) {
            EXPECT_EQ(lines[i].cornerB.w, 1.0f);
            contours += contour(lines[i], toLight) ? 1 : 0;
        }
        EXPECT_EQ(contours, 6);  // a box seen from a generic side: a hexagon
    }
}

TEST(CasterOutlines, AnOpenSurfacesBordersAreAlwaysOutlines) {
    Mesh quad = mesh::quad("quad", {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
    std::vector<EdgeVertex> lines = render::meshEdges(quad);
    expectPairs(lines);
    ASSERT_EQ(lines.size(), 2u * 5u);
    int borders = 0, contours = 0;
    for (const EdgeVertex& v : lines) {
        borders += v.cornerB.w == 0.0f ? 1 : 0;
        contours += contour(v, {0.3f, 1.0f, 0.2f}) ? 1 : 0;
    }
    EXPECT_EQ(borders, 2 * 4);
    EXPECT_EQ(contours, 2 * 4);  // the diagonal lies inside the flat quad
    // Wound either way, the diagonal's triangles lie on both sides of it.
    std::swap(quad.indices[1], quad.indices[2]);
    for (const EdgeVertex& v : render::meshEdges(quad))
        EXPECT_EQ(contour(v, {0.3f, 1.0f, 0.2f}), v.cornerB.w == 0.0f);
}

// A rod a tenth of a map texel thick, a little above a floor, under a point light whose map
// has a fixed frustum (a texel about 0.057 across at the floor): its shadow is a strip the map
// holds nowhere, and the lookups around it are sure. Under uncertain the rod's outline sends
// the floor within a texel of it to the rays.
Scene rodOverAFloor() {
    Scene s;
    s.name = "thin-rod";
    s.materials.push_back(Material{});
    s.meshes.push_back(mesh::quad("floor", {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}));
    s.meshes.push_back(mesh::box("rod", {0.0f, 0.3f, 0.0f}, {6.0f, 0.006f, 0.006f}));
    s.objects.push_back({"floor", 0, 0, glm::mat4(1.0f), {}, true, true});
    // Turned a little about y, so that the rod crosses the map's rows.
    s.objects.push_back({"rod",
                         1,
                         0,
                         glm::rotate(glm::mat4(1.0f), 0.2f, glm::vec3(0.0f, 1.0f, 0.0f)),
                         {},
                         true,
                         true});
    Light light;
    light.type = LightType::Point;
    light.position = {0.3f, 5.0f, 0.4f};
    light.shadowCamera.policy = ShadowCameraPolicy::Manual;
    light.shadowCamera.up = {0.0f, 0.0f, -1.0f};
    light.shadowCamera.fovyDegrees = 40.0f;
    light.shadowCamera.far = 20.0f;
    s.lights.push_back(light);
    s.camera = lookingStraightDown(0.2f);
    s.options.width = s.options.height = 128;
    s.options.shadow.mapSize = 64;
    return s;
}

TEST(CasterOutlines, ACasterThinnerThanATexelKeepsItsShadow) {
    if (testsGles()) GTEST_SKIP() << "the outline maps are drawn on OpenGL 4.5 only";
    const Scene s = rodOverAFloor();
    RenderOptions maps = s.options;
    maps.shadow.shadowRays = ShadowRayMode::Off;
    RenderOptions rays = maps;
    rays.shadow.shadowRays = ShadowRayMode::Uncertain;
    const ScoreResult m = score(sharedRenderer(), s, maps);
    const ScoreResult r = score(sharedRenderer(), s, rays);
    std::printf("maps alone %.3f %%, uncertain %.4f %% (traced %.2f %%)\n",
                100.0 * m.overall.misclassified, 100.0 * r.overall.misclassified,
                100.0 * r.overall.traced);
    ASSERT_GT(r.overall.pixels, 10000);
    EXPECT_GT(m.overall.misclassified, 0.005);  // the map misses the strip
    expectWrongAtMost(r, 0.0002, 1.0);
    EXPECT_LT(r.overall.traced, 0.5);  // the floor within a texel of the rod (18 pixels)
}

}  // namespace
}  // namespace gnomon::test
