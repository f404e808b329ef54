#include "scene/MeshTopology.h"

#include <algorithm>
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

// The mesh's edges, its corners welded by position (glTF and OBJ split vertices at texture
// and normal seams). Sorted by edge rather than hashed: the Stanford Dragon's 2.6 M edge uses
// took seconds through a hash map.
struct Edges {
    // Connected pieces (triangles sharing an edge, joined), and the triangles on an edge
    // no other triangle has (an open border: their pieces are not watertight).
    Sets pieces;
    std::vector<std::uint32_t> onOpenEdges;
    std::vector<char> sound;       // per triangle: every edge run once each way
    std::vector<char> degenerate;  // two corners at one position: no edges, draws nothing
    // Triangles on either side of each edge run once each way.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> partners;

    explicit Edges(const Mesh& mesh) : pieces(mesh.indices.size() / 3) {
        std::unordered_map<glm::vec3, std::uint32_t, PositionHash> ids;
        ids.reserve(mesh.positions.size());
        std::vector<std::uint32_t> weld(mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            weld[i] = ids.emplace(mesh.positions[i], std::uint32_t(ids.size())).first->second;
        const std::size_t triangles = mesh.indices.size() / 3;
        degenerate.assign(triangles, 0);
        sound.assign(triangles, 0);
        // Each use of an edge: its two ends, lower id first, and whether it runs that way.
        struct Use {
            std::uint64_t edge;
            std::uint32_t triangle;
            bool forward;
        };
        std::vector<Use> uses;
        uses.reserve(3 * triangles);
        for (std::uint32_t t = 0; t < triangles; ++t) {
            std::uint32_t v[3];
            for (std::size_t k = 0; k < 3; ++k)
                v[k] = weld[mesh.indices[3 * t + k]];
            degenerate[t] = v[0] == v[1] || v[1] == v[2] || v[2] == v[0];
            sound[t] = !degenerate[t];
            if (degenerate[t]) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t a = v[k], b = v[(k + 1) % 3];
                uses.push_back({std::uint64_t(std::min(a, b)) << 32 | std::max(a, b), t, a < b});
            }
        }
        std::sort(uses.begin(), uses.end(),
                  [](const Use& x, const Use& y) { return x.edge < y.edge; });
        for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {
            while (j < uses.size() && uses[j].edge == uses[i].edge)
                ++j;
            if (j - i == 1) onOpenEdges.push_back(uses[i].triangle);
            for (std::size_t k = i + 1; k < j; ++k)
                pieces.join(uses[i].triangle, uses[k].triangle);
            if (j - i == 2 && uses[i].forward != uses[i + 1].forward) {
                partners.emplace_back(uses[i].triangle, uses[i + 1].triangle);
            } else {
                for (std::size_t k = i; k < j; ++k)
                    sound[uses[k].triangle] = 0;
            }
        }
    }
};

}  // namespace

CullingSplit splitForCulling(const Mesh& mesh) {
    CullingSplit split;
    split.indices = mesh.indices;
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles < 4) return split;  // fewer than four triangles bound nothing
    Edges e(mesh);
    // A patch counts only on a watertight piece, whose other triangles fill its holes.
    std::vector<char> openPiece(triangles, 0);
    for (std::uint32_t t : e.onOpenEdges)
        openPiece[e.pieces.find(t)] = 1;
    const std::vector<char>& sound = e.sound;
    // Sound triangles joined across their edges into patches.
    Sets patches(triangles);
    for (const auto& [a, b] : e.partners) {
        if (sound[a] && sound[b]) patches.join(a, b);
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
        if (!sound[t] || openPiece[e.pieces.find(t)]) continue;
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

namespace {

using Corners = std::array<std::uint32_t, 3>;

Corners cornersOf(const std::vector<std::uint32_t>& indices, std::uint32_t t) {
    return {indices[3 * std::size_t(t)], indices[3 * std::size_t(t) + 1],
            indices[3 * std::size_t(t) + 2]};
}

// `indices`' triangles sorted by their corners, ties in their order.
std::vector<std::uint32_t> sortedTriangles(const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint32_t> order(indices.size() / 3);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return cornersOf(indices, a) < cornersOf(indices, b);
    });
    return order;
}

}  // namespace

std::vector<std::uint32_t> trianglePlaces(const std::vector<std::uint32_t>& original,
                                          const std::vector<std::uint32_t>& reordered) {
    std::vector<std::uint32_t> places(original.size() / 3, kNoPlace);
    if (original.size() != reordered.size()) return places;
    // The same triangles sorted the same way pair up, copies in their order on both sides.
    const std::vector<std::uint32_t> a = sortedTriangles(original), b = sortedTriangles(reordered);
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (cornersOf(original, a[k]) != cornersOf(reordered, b[k])) {
            std::fill(places.begin(), places.end(), kNoPlace);
            return places;
        }
        places[a[k]] = b[k];
    }
    return places;
}

}  // namespace gnomon
