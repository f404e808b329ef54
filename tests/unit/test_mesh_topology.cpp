#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "scene/MeshBuilder.h"
#include "scene/MeshTopology.h"

namespace gnomon {
namespace {

// A box's faces have their own vertices (flat normals): welded by position it is closed.
TEST(MeshTopology, ABoxWithSplitVerticesIsClosed) {
    EXPECT_EQ(1, closedWinding(mesh::box("box", glm::vec3(0.0f), glm::vec3(1, 2, 3))));
}

TEST(MeshTopology, AQuadIsOpen) {
    EXPECT_EQ(0, closedWinding(mesh::quad("quad", {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0})));
}

TEST(MeshTopology, ABoxWithoutOneFaceIsOpen) {
    Mesh m = mesh::box("box", glm::vec3(0.0f), glm::vec3(1.0f));
    m.indices.resize(m.indices.size() - 6);  // the last face's two triangles
    EXPECT_EQ(0, closedWinding(m));
}

// A face turned inside out: every edge still has two triangles, but they run the same way
// along it, so a face culled in a shadow pass would leave a hole.
TEST(MeshTopology, ABoxWithOneFaceInsideOutIsNotClosed) {
    Mesh m = mesh::box("box", glm::vec3(0.0f), glm::vec3(1.0f));
    for (std::size_t t = m.indices.size() - 6; t < m.indices.size(); t += 3)
        std::swap(m.indices[t + 1], m.indices[t + 2]);
    EXPECT_EQ(0, closedWinding(m));
}

// Every face turned: closed and consistent, but wound inwards (a negative volume), as some
// FBX exports are. Culling its back faces would keep the faces the camera sees.
TEST(MeshTopology, ABoxWoundInwardsIsTold) {
    Mesh m = mesh::box("box", glm::vec3(2.0f), glm::vec3(1.0f));
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
        std::swap(m.indices[t + 1], m.indices[t + 2]);
    EXPECT_EQ(-1, closedWinding(m));
}

// Two boxes in one mesh are still a closed surface; a degenerate triangle changes nothing.
TEST(MeshTopology, TwoBoxesAndADegenerateTriangleAreClosed) {
    Mesh m = mesh::box("a", glm::vec3(0.0f), glm::vec3(1.0f));
    const Mesh b = mesh::box("b", glm::vec3(3.0f), glm::vec3(1.0f));
    const auto base = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
    for (std::uint32_t i : b.indices)
        m.indices.push_back(base + i);
    m.indices.insert(m.indices.end(), {0, 0, 1});
    EXPECT_EQ(1, closedWinding(m));
}

TEST(MeshTopology, AnEmptyMeshIsNotClosed) {
    EXPECT_EQ(0, closedWinding(Mesh{}));
}

}  // namespace
}  // namespace gnomon
