#include "render/CasterEdges.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

namespace gnomon::render {

namespace {

struct PositionHash {
    std::size_t operator()(const glm::vec3& p) const {
        std::uint32_t b[3];
        std::memcpy(b, &p, sizeof b);
        return std::size_t(b[0]) * 73856093u ^ std::size_t(b[1]) * 19349663u ^
               std::size_t(b[2]) * 83492791u;
    }
};

// One triangle's side: its corners' welded numbers, lower first, and the triangle's far
// corner (an index into the mesh's positions).
struct Side {
    std::uint64_t key;
    std::uint32_t far;
    std::uint32_t ends[2];
};

}  // namespace

std::vector<EdgeVertex> meshEdges(const Mesh& mesh) {
    std::unordered_map<glm::vec3, std::uint32_t, PositionHash> welded;
    std::vector<std::uint32_t> corner(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        corner[i] =
            welded.try_emplace(mesh.positions[i], std::uint32_t(welded.size())).first->second;

    std::vector<Side> sides;
    sides.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t* v = &mesh.indices[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = v[k], b = v[(k + 1) % 3], far = v[(k + 2) % 3];
            const std::uint32_t p = corner[a], q = corner[b];
            if (p == q) continue;  // a degenerate side draws nothing
            sides.push_back({(std::uint64_t(std::min(p, q)) << 32) | std::max(p, q), far, {a, b}});
        }
    }
    std::sort(sides.begin(), sides.end(),
              [](const Side& x, const Side& y) { return x.key < y.key; });

    std::vector<EdgeVertex> lines;
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        while (j < sides.size() && sides[j].key == sides[i].key)
            ++j;
        const Side& s = sides[i];
        const glm::vec3 a = mesh.positions[s.ends[0]], b = mesh.positions[s.ends[1]];
        const glm::vec3 cornerA = mesh.positions[s.far];
        const glm::vec4 cornerB =
            j - i == 2 ? glm::vec4(mesh.positions[sides[i + 1].far], 1.0f) : glm::vec4(0.0f);
        lines.push_back({a, b, cornerA, cornerB});
        lines.push_back({b, a, cornerA, cornerB});
        i = j;
    }
    return lines;
}

void CasterEdges::sync(const Scene& scene, std::uint64_t geometryHash) {
    if (mMade && mHash == geometryHash) return;
    std::vector<EdgeVertex> all;
    mRanges.clear();
    for (const Mesh& mesh : scene.meshes) {
        std::vector<EdgeVertex> lines = meshEdges(mesh);
        mRanges.emplace_back(GLint(all.size()), GLsizei(lines.size()));
        all.insert(all.end(), lines.begin(), lines.end());
    }
    mLines = gl::Buffer("caster edges", std::max<std::size_t>(all.size(), 1) * sizeof(EdgeVertex),
                        all.empty() ? nullptr : all.data(), 0);
    mVao = gl::VertexArray("caster edges");
    mVao.vertexBuffer(0, mLines, 0, sizeof(EdgeVertex));
    for (int a = 0; a < 4; ++a)
        mVao.attribute(a, 0, a == 3 ? 4 : 3, GL_FLOAT, std::size_t(a) * sizeof(glm::vec3));
    mHash = geometryHash;
    mMade = true;
}

void CasterEdges::bind() const {
    glBindVertexArray(mVao.id());
}

void CasterEdges::draw(std::uint32_t mesh) const {
    const auto [first, count] = mRanges[mesh];
    if (count > 0) glDrawArrays(GL_LINES, first, count);
}

}  // namespace gnomon::render
