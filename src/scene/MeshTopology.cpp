#include "scene/MeshTopology.h"

#include <array>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace gnomon {

namespace {

struct PositionHash {
    std::size_t operator()(const glm::vec3& p) const {
        const glm::vec3 q = p + glm::vec3(0.0f);  // -0 + 0 = +0: equal keys, equal hashes
        std::uint32_t b[3];
        std::memcpy(b, &q, sizeof b);
        return (std::size_t(b[0]) * 73856093u) ^ (std::size_t(b[1]) * 19349663u) ^
               (std::size_t(b[2]) * 83492791u);
    }
};

class Sets {
public:
    explicit Sets(std::size_t n) : mParent(n) { std::iota(mParent.begin(), mParent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (mParent[x] != x)
            x = mParent[x] = mParent[mParent[x]];
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) { mParent[find(a)] = find(b); }

private:
    std::vector<std::uint32_t> mParent;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return std::uint64_t(a) << 32 | b;
}
std::uint64_t reversed(std::uint64_t key) {
    return key << 32 | key >> 32;
}

// The mesh's triangles as corners welded by position (glTF and OBJ split vertices at texture
// and normal seams), and each directed edge's count and last triangle.
struct Edges {
    std::vector<std::array<std::uint32_t, 3>> corners;
    std::vector<char> degenerate;  // two corners at one position: no edges, draws nothing
    struct Use {
        std::uint32_t count = 0, triangle = 0;
    };
    std::unordered_map<std::uint64_t, Use> directed;

    explicit Edges(const Mesh& mesh) {
        std::unordered_map<glm::vec3, std::uint32_t, PositionHash> ids;
        ids.reserve(mesh.positions.size());
        std::vector<std::uint32_t> weld(mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            weld[i] = ids.emplace(mesh.positions[i], std::uint32_t(ids.size())).first->second;
        const std::size_t triangles = mesh.indices.size() / 3;
        corners.resize(triangles);
        degenerate.resize(triangles);
        directed.reserve(mesh.indices.size());
        for (std::uint32_t t = 0; t < triangles; ++t) {
            std::array<std::uint32_t, 3>& v = corners[t];
            for (int k = 0; k < 3; ++k)
                v[std::size_t(k)] = weld[mesh.indices[3 * t + std::size_t(k)]];
            degenerate[t] = v[0] == v[1] || v[1] == v[2] || v[2] == v[0];
            if (degenerate[t]) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                Use& use = directed[edgeKey(v[k], v[(k + 1) % 3])];
                ++use.count;
                use.triangle = t;
            }
        }
    }
    std::uint32_t count(std::uint64_t key) const {
        const auto it = directed.find(key);
        return it == directed.end() ? 0 : it->second.count;
    }
    // Run once each way: the triangles on its two sides agree on which side is out.
    bool good(std::uint64_t key) const { return count(key) == 1 && count(reversed(key)) == 1; }
};

}  // namespace

CullingSplit splitForCulling(const Mesh& mesh) {
    CullingSplit split;
    split.indices = mesh.indices;
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles < 4) return split;  // fewer than four triangles bound nothing
    const Edges e(mesh);
    // A mesh with an edge only one triangle uses (an open border) keeps all its faces: a thin
    // solid beside an open surface in one mesh (each square of assimp's ClearCoatTest: a slab
    // under an open dome) leaked light onto the dome under a low sun when the slab alone was
    // culled (1.9 % of the view against 0.1 %), for a cause not pinned down.
    for (const auto& [key, use] : e.directed) {
        if (use.count + e.count(reversed(key)) == 1) return split;
    }
    Sets patches(triangles);
    // Sound triangles (every edge good) joined across their edges into patches.
    std::vector<char> sound(triangles, 0);
    for (std::uint32_t t = 0; t < triangles; ++t) {
        const auto& v = e.corners[t];
        sound[t] = !e.degenerate[t] && e.good(edgeKey(v[0], v[1])) && e.good(edgeKey(v[1], v[2])) &&
                   e.good(edgeKey(v[2], v[0]));
    }
    for (const auto& [key, use] : e.directed) {
        if (use.count != 1 || !sound[use.triangle]) continue;
        const auto other = e.directed.find(reversed(key));
        if (other != e.directed.end() && sound[other->second.triangle])
            patches.join(use.triangle, other->second.triangle);
    }
    // Each patch's vector area, total area and volume (about the mesh's first corner: a
    // closed patch's volume does not depend on where, a nearly closed one's hardly).
    std::vector<glm::dvec3> vectorArea(triangles, glm::dvec3(0.0));
    std::vector<double> area(triangles, 0.0), volume(triangles, 0.0);
    const glm::dvec3 origin(mesh.positions[mesh.indices[0]]);
    for (std::uint32_t t = 0; t < triangles; ++t) {
        if (!sound[t]) continue;
        const std::uint32_t p = patches.find(t);
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.indices[3 * t]]) - origin;
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]) - origin;
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]]) - origin;
        const glm::dvec3 n = glm::cross(b - a, c - a);
        vectorArea[p] += n;
        area[p] += glm::length(n);
        volume[p] += glm::dot(a, glm::cross(b, c));
    }
    constexpr double kMostlyClosed = 0.01;  // |sum of vector areas| / area of a solid
    std::vector<int> side(triangles, 0);    // per triangle: its patch's winding, 0 none
    std::size_t outwards = 0, inwards = 0;
    for (std::uint32_t t = 0; t < triangles; ++t) {
        if (!sound[t]) continue;
        const std::uint32_t p = patches.find(t);
        if (glm::length(vectorArea[p]) > kMostlyClosed * area[p] || volume[p] == 0.0) continue;
        side[t] = volume[p] > 0.0 ? 1 : -1;
        ++(side[t] > 0 ? outwards : inwards);
    }
    if (outwards + inwards == 0) return split;
    // One winding is culled for the whole mesh: the one more triangles have.
    split.winding = outwards >= inwards ? 1 : -1;
    // Degenerate triangles draw nothing: with the solids, so a closed mesh is one group.
    auto first = [&](std::size_t t) { return side[t] == split.winding || e.degenerate[t]; };
    std::size_t at = 0;
    for (int group = 0; group < 2; ++group) {
        for (std::size_t t = 0; t < triangles; ++t) {
            if (first(t) != (group == 0)) continue;
            for (std::size_t k = 0; k < 3; ++k)
                split.indices[at++] = mesh.indices[3 * t + k];
        }
        if (group == 0) split.closedIndices = at;
    }
    return split;
}

int closedWinding(const Mesh& mesh) {
    const CullingSplit split = splitForCulling(mesh);
    return split.closedIndices == mesh.indices.size() ? split.winding : 0;
}

}  // namespace gnomon
