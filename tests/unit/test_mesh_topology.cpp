#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "GridSolid.h"
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

// A solid of 6 x 24 x 24 squares (6912 triangles).
Mesh solid() {
    return test::gridSolid(24);
}
// A mesh's indices as a set of triangles, to compare.
std::multiset<std::array<std::uint32_t, 3>> triangles(const std::vector<std::uint32_t>& indices,
                                                      std::size_t from, std::size_t to) {
    std::multiset<std::array<std::uint32_t, 3>> set;
    for (std::size_t i = from; i + 2 < to; i += 3)
        set.insert({indices[i], indices[i + 1], indices[i + 2]});
    return set;
}

TEST(MeshTopology, ASolidIsOneGroup) {
    const Mesh m = solid();
    const CullingSplit split = splitForCulling(m);
    EXPECT_EQ(1, split.winding);
    EXPECT_EQ(m.indices.size(), split.closedIndices);
    EXPECT_EQ(m.indices, split.indices);
}

// A few faces wound the wrong way (as in glmark2's 3DS horse): they, and the faces beside
// them, are drawn from both sides; the rest of the solid is still culled. Every triangle is
// kept, once.
TEST(MeshTopology, AFewFacesWoundTheWrongWayLeaveTheRestASolid) {
    Mesh m = solid();
    const std::size_t perSide = m.indices.size() / 3 / 6, middle = 2 * (24 * 12 + 12);
    const std::size_t turned[2] = {2 * perSide + middle, 4 * perSide + middle + 1};
    for (std::size_t t : turned)
        test::turnTriangle(m, t);
    const CullingSplit split = splitForCulling(m);
    EXPECT_EQ(0, closedWinding(m));
    EXPECT_EQ(1, split.winding);
    const std::size_t open = (m.indices.size() - split.closedIndices) / 3;
    EXPECT_EQ(2u * 4u, open);  // each turned face and its three neighbours
    EXPECT_EQ(triangles(m.indices, 0, m.indices.size()),
              triangles(split.indices, 0, split.indices.size()));
    const auto rest = triangles(split.indices, split.closedIndices, split.indices.size());
    for (std::size_t t : turned)
        EXPECT_EQ(1u, rest.count({m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]}));
}

// A hole leaves an edge with one triangle: nothing on that piece is a solid.
TEST(MeshTopology, ASolidWithAHoleIsNotCulled) {
    Mesh m = solid();
    m.indices.erase(m.indices.begin() + std::ptrdiff_t(m.indices.size() / 2),
                    m.indices.begin() + std::ptrdiff_t(m.indices.size() / 2 + 3));
    EXPECT_EQ(0u, splitForCulling(m).closedIndices);
}

// Many faces turned together (a patch of the surface wound the wrong way): what is left of
// each patch is far from closed, so nothing is called a solid whose outside is unknown.
TEST(MeshTopology, AHalfTurnedSolidIsNotCulled) {
    Mesh m = solid();
    for (std::size_t t = 0; t < m.indices.size() / 6; ++t)
        std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
    EXPECT_EQ(0u, splitForCulling(m).closedIndices);
}

// A solid beside an open sheet in one mesh: the solid is culled, the sheet is not.
TEST(MeshTopology, ASolidBesideASheetIsCulledAlone) {
    Mesh m = solid();
    const std::size_t solid = m.indices.size();
    const Mesh q = mesh::quad("sheet", {30, 0, 0}, {31, 0, 0}, {31, 1, 0}, {30, 1, 0});
    const auto base = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), q.positions.begin(), q.positions.end());
    m.normals.insert(m.normals.end(), q.normals.begin(), q.normals.end());
    for (std::uint32_t i : q.indices)
        m.indices.push_back(base + i);
    const CullingSplit split = splitForCulling(m);
    EXPECT_EQ(1, split.winding);
    EXPECT_EQ(solid, split.closedIndices);
    EXPECT_EQ(0, closedWinding(m));
}

// The places of a mesh's triangles in the order the GPU scene uploads them (split for culling,
// then cut into pieces) name the same corners, copies of a triangle included.
TEST(MeshTopology, TrianglePlacesFollowAReordering) {
    const std::vector<std::uint32_t> original = {0, 1, 2, 2, 1, 3, 0, 1, 2, 4, 5, 6};
    const std::vector<std::uint32_t> reordered = {4, 5, 6, 0, 1, 2, 2, 1, 3, 0, 1, 2};
    const std::vector<std::uint32_t> places = trianglePlaces(original, reordered);
    ASSERT_EQ(places.size(), 4u);
    EXPECT_EQ(places, (std::vector<std::uint32_t>{1, 2, 3, 0}));
    Mesh m = mesh::sphere("sphere", glm::vec3(0.0f), 1.0f, 24, 12);
    const CullingSplit split = splitForCulling(m);
    const std::vector<std::uint32_t> p = trianglePlaces(m.indices, split.indices);
    std::set<std::uint32_t> seen;
    for (std::size_t t = 0; t < p.size(); ++t) {
        ASSERT_LT(p[t], p.size());
        seen.insert(p[t]);
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(m.indices[3 * t + k], split.indices[3 * std::size_t(p[t]) + k]);
    }
    EXPECT_EQ(seen.size(), p.size());
}

// A triangle turned (its corners rotated) or missing is not the same triangle: no places.
TEST(MeshTopology, TrianglePlacesOfOtherTrianglesAreNone) {
    const std::vector<std::uint32_t> original = {0, 1, 2, 2, 1, 3};
    for (const std::vector<std::uint32_t>& other :
         {std::vector<std::uint32_t>{1, 2, 0, 2, 1, 3}, std::vector<std::uint32_t>{0, 1, 2}}) {
        const std::vector<std::uint32_t> places = trianglePlaces(original, other);
        EXPECT_EQ(places, (std::vector<std::uint32_t>{kNoPlace, kNoPlace}));
    }
}

}  // namespace
}  // namespace gnomon
