#include "scene/MeshTopology.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

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

}  // namespace

int closedWinding(const Mesh& mesh) {
    if (mesh.indices.size() < 12) return 0;  // fewer than four triangles bound nothing
    // One id per distinct position.
    std::unordered_map<glm::vec3, std::uint32_t, PositionHash> ids;
    ids.reserve(mesh.positions.size());
    std::vector<std::uint32_t> weld(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        weld[i] = ids.emplace(mesh.positions[i], std::uint32_t(ids.size())).first->second;
    // Directed edges a -> b, counted: a closed, consistently wound surface has each once,
    // and its reverse once.
    std::unordered_map<std::uint64_t, int> edges;
    edges.reserve(mesh.indices.size());
    auto key = [](std::uint32_t a, std::uint32_t b) { return std::uint64_t(a) << 32 | b; };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t v[3] = {weld[mesh.indices[t]], weld[mesh.indices[t + 1]],
                                    weld[mesh.indices[t + 2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int e = 0; e < 3; ++e) {
            if (++edges[key(v[e], v[(e + 1) % 3])] > 1) return 0;
        }
    }
    for (const auto& edge : edges) {
        if (edges.find(edge.first << 32 | edge.first >> 32) == edges.end()) return 0;
    }
    if (edges.empty()) return 0;
    // Which way it is wound: the volume the triangles enclose is positive when they run
    // counter-clockwise seen from outside (glTF's front faces).
    const glm::dvec3 centre(mesh.positions.front());
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.indices[t]]) - centre;
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - centre;
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - centre;
        volume += glm::dot(a, glm::cross(b, c));
    }
    return volume > 0.0 ? 1 : volume < 0.0 ? -1 : 0;
}

}  // namespace gnomon
