// Stand-in casters (src/shadow/StandIn.cpp): meshoptimizer's simplification of a mesh for
// shadow passes keeps the share of triangles asked for, indexes the mesh's own vertices, and
// keeps the caster's extent.
#include <gtest/gtest.h>

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
    EXPECT_EQ(shadow::standInIndices(sphere, 1.0f), sphere.indices);
    const Mesh cube = mesh::box("box", glm::vec3(0.0f), glm::vec3(1.0f));
    EXPECT_EQ(shadow::standInIndices(cube, 0.1f), cube.indices);
}

TEST(StandIn, KeepsTheShareAskedForOnTheMeshesOwnVerticesAndItsExtent) {
    const Mesh sphere = uvSphere(64, 32);
    const std::size_t full = sphere.indices.size() / 3;
    for (float detail : {0.3f, 0.1f, 0.03f}) {
        const std::vector<std::uint32_t> s = shadow::standInIndices(sphere, detail);
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
        // The stand-in still spans the sphere: its shadow keeps the caster's size.
        for (int a = 0; a < 3; ++a) {
            EXPECT_LT(lo[a], -0.85f) << "detail " << detail << ", axis " << a;
            EXPECT_GT(hi[a], 0.85f) << "detail " << detail << ", axis " << a;
        }
    }
}

}  // namespace
}  // namespace gnomon
