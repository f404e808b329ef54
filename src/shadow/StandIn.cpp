#include "shadow/StandIn.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gnomon::shadow {

namespace {

// Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
float distanceSquared(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                      const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    auto length2 = [](const glm::vec3& v) { return glm::dot(v, v); };
    if (d1 <= 0.0f && d2 <= 0.0f) return length2(ap);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return length2(bp);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return length2(ap - ab * (d1 / (d1 - d3)));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return length2(cp);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return length2(ap - ac * (d2 / (d2 - d6)));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f)
        return length2(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const float denominator = 1.0f / (va + vb + vc);
    return length2(ap - ab * (vb * denominator) - ac * (vc * denominator));
}

// The file's version of `mesh` nearest `detail` (by ratio of triangle shares), or -1 when
// the mesh itself is nearer.
int nearestLod(const Mesh& mesh, float detail) {
    const double full = double(mesh.indices.size());
    int best = -1;
    double bestGap = std::abs(std::log(1.0 / double(detail)));
    for (std::size_t i = 0; i < mesh.lods.size(); ++i) {
        const double share = double(mesh.lods[i].indices.size()) / full;
        if (!(share > 0.0)) continue;
        const double gap = std::abs(std::log(share / double(detail)));
        if (gap < bestGap) {
            bestGap = gap;
            best = int(i);
        }
    }
    return best;
}

}  // namespace

float lodError(const Mesh& mesh, const MeshLod& lod) {
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles == 0 || lod.positions.empty()) return 0.0f;
    const std::size_t step =
        std::max<std::size_t>(1, lod.positions.size() * triangles / kMaxDistanceTests);
    float worst = 0.0f;
    for (std::size_t v = 0; v < lod.positions.size(); v += step) {
        float nearest = std::numeric_limits<float>::max();
        for (std::size_t t = 0; t < triangles && nearest > worst; ++t) {
            nearest = std::min(
                nearest, distanceSquared(lod.positions[v], mesh.positions[mesh.indices[3 * t]],
                                         mesh.positions[mesh.indices[3 * t + 1]],
                                         mesh.positions[mesh.indices[3 * t + 2]]));
        }
        worst = std::max(worst, nearest);
    }
    return std::sqrt(worst);
}

StandIn makeStandIn(const Mesh& mesh, float detail) {
    if (detail < 1.0f && !mesh.lods.empty() && !mesh.indices.empty()) {
        const int lod = nearestLod(mesh, detail);
        if (lod < 0) return {mesh.indices, 0.0f};
        // Its vertices follow the mesh's own and the finer versions' (GpuScene's layout).
        std::size_t first = mesh.positions.size();
        for (int i = 0; i < lod; ++i)
            first += mesh.lods[std::size_t(i)].positions.size();
        StandIn s{mesh.lods[std::size_t(lod)].indices, lodError(mesh, mesh.lods[std::size_t(lod)])};
        for (std::uint32_t& index : s.indices)
            index += std::uint32_t(first);
        return s;
    }
    const std::size_t count = mesh.indices.size();
    constexpr std::size_t kMinTriangles = 64;  // smaller meshes cost nothing to draw whole
    if (!(detail < 1.0f) || count < 3 * kMinTriangles || mesh.positions.empty()) {
        return {mesh.indices, 0.0f};
    }
    const float* positions = &mesh.positions[0].x;
    const std::size_t vertices = mesh.positions.size();
    const std::size_t stride = sizeof(glm::vec3);
    // One index per distinct position: texture and normal seams no longer split the surface,
    // so the simplifier can collapse across them.
    std::vector<std::uint32_t> welded(count);
    meshopt_generateShadowIndexBuffer(welded.data(), mesh.indices.data(), count, positions,
                                      vertices, stride, stride);
    const std::size_t target = std::max<std::size_t>(
        3, std::size_t(std::lround(double(detail) * double(count) / 3.0)) * 3);
    StandIn s{std::vector<std::uint32_t>(count), 0.0f};
    std::vector<std::uint32_t>& out = s.indices;
    // Error bound 1 (the mesh's whole extent): the triangle count is the user's choice. The
    // error reached comes back relative to the mesh's extent.
    float error = 0.0f;
    std::size_t kept = meshopt_simplify(out.data(), welded.data(), count, positions, vertices,
                                        stride, target, 1.0f, 0, &error);
    if (kept > target + target / 2) {
        kept = meshopt_simplifySloppy(out.data(), welded.data(), count, positions, vertices, stride,
                                      target, 1.0f, &error);
    }
    if (kept < 3) return {mesh.indices, 0.0f};  // nothing left: keep the caster whole
    out.resize(kept);
    s.error = error * meshopt_simplifyScale(positions, vertices, stride);
    return s;
}

}  // namespace gnomon::shadow
