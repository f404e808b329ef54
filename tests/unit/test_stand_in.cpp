// Stand-in casters (src/shadow/StandIn.cpp): meshoptimizer's simplification of a mesh for
// shadow passes keeps the share of triangles asked for, indexes the mesh's own vertices, and
// keeps the caster's extent; a file's own coarser versions are taken instead where given.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/MeshBuilder.h"
#include "shadow/StandIn.h"

namespace gnomon {
namespace {

// A UV sphere of radius 1 with a texture seam, as loaders deliver meshes.
Mesh uvSphere(int columns, int rows) {
    return mesh::sphere("sphere", glm::vec3(0.0f), 1.0f, columns, rows);
}

TEST(StandIn, FullDetailAndSmallMeshesAreTheMeshItself) {
    const Mesh sphere = uvSphere(64, 32);
    const shadow::StandIn whole = shadow::makeStandIn(sphere, 1.0f);
    EXPECT_EQ(whole.indices, sphere.indices);
    EXPECT_EQ(whole.error, 0.0f);
    const Mesh cube = mesh::box("box", glm::vec3(0.0f), glm::vec3(1.0f));
    EXPECT_EQ(shadow::makeStandIn(cube, 0.1f).indices, cube.indices);
}

TEST(StandIn, KeepsTheShareAskedForOnTheMeshesOwnVerticesAndItsExtent) {
    const Mesh sphere = uvSphere(64, 32);
    const std::size_t full = sphere.indices.size() / 3;
    for (float detail : {0.3f, 0.1f, 0.03f}) {
        const shadow::StandIn standIn = shadow::makeStandIn(sphere, detail);
        const std::vector<std::uint32_t>& s = standIn.indices;
        ASSERT_EQ(s.size() % 3, 0u);
        const double share = double(s.size() / 3) / double(full);
        EXPECT_LE(share, 1.5 * detail) << "detail " << detail;
        EXPECT_GE(share, 0.3 * detail) << "detail " << detail;
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (std::uint32_t i : s) {
            ASSERT_LT(i, sphere.positions.size());
            lo = glm::min(lo, sphere.positions[i]);
            hi = glm::max(hi, sphere.positions[i]);
        }
        // Its error says how far it strays from the sphere. meshoptimizer measures it at the
        // vertices it removes, so the triangles' centres, where chords sag most, lie further:
        // between 1 and 2.2 times it here. Lookups of the surface start twice the error off it
        // (shadow_lookup.glsl); this pins that calibration.
        EXPECT_GT(standIn.error, 0.0f) << "detail " << detail;
        EXPECT_LT(standIn.error, 0.5f) << "detail " << detail;
        float sag = 0.0f;
        for (std::size_t t = 0; t + 2 < s.size(); t += 3) {
            const glm::vec3 c =
                (sphere.positions[s[t]] + sphere.positions[s[t + 1]] + sphere.positions[s[t + 2]]) /
                3.0f;
            sag = std::max(sag, 1.0f - glm::length(c));
        }
        EXPECT_GE(sag, standIn.error) << "detail " << detail;
        EXPECT_LE(sag, 2.5f * standIn.error) << "detail " << detail;
        // The stand-in still spans the sphere: its shadow keeps the caster's size.
        for (int a = 0; a < 3; ++a) {
            EXPECT_LT(lo[a], -0.85f) << "detail " << detail << ", axis " << a;
            EXPECT_GT(hi[a], 0.85f) << "detail " << detail << ", axis " << a;
        }
    }
}

// A file's coarser versions (MSFT_lod): the one nearest the detail asked for stands in,
// indexed past the mesh's own vertices (and the finer versions'); its error is how far its
// vertices stray from the mesh's surface.
TEST(StandIn, TheFilesVersionNearestTheDetailStandsIn) {
    Mesh sphere = uvSphere(64, 32);
    // Radius 1.1: every vertex 0.1 off the mesh's surface. Radius 1 with 8 x 4: on it.
    for (const Mesh& lod : {mesh::sphere("medium", glm::vec3(0.0f), 1.1f, 16, 8),
                            mesh::sphere("low", glm::vec3(0.0f), 1.0f, 8, 4)}) {
        sphere.lods.push_back({lod.positions, lod.indices});
    }
    const std::size_t full = sphere.indices.size() / 3;
    const double medium = double(sphere.lods[0].indices.size() / 3) / double(full);
    const shadow::StandIn a = shadow::makeStandIn(sphere, float(medium));
    ASSERT_EQ(a.indices.size(), sphere.lods[0].indices.size());
    EXPECT_EQ(a.indices[0], sphere.lods[0].indices[0] + sphere.positions.size());
    EXPECT_NEAR(a.error, 0.1f, 0.01f);
    const shadow::StandIn b = shadow::makeStandIn(sphere, 0.001f);
    ASSERT_EQ(b.indices.size(), sphere.lods[1].indices.size());
    const std::size_t past = sphere.positions.size() + sphere.lods[0].positions.size();
    for (std::uint32_t i : b.indices) {
        ASSERT_GE(i, past);
        ASSERT_LT(i, past + sphere.lods[1].positions.size());
    }
    EXPECT_LT(b.error, 1e-3f);
    // Nearer the full mesh than any version: the mesh itself.
    EXPECT_EQ(shadow::makeStandIn(sphere, 0.9f).indices, sphere.indices);
}

}  // namespace
}  // namespace gnomon
