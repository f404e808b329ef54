#include "shadow/StandIn.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

namespace gnomon::shadow {

StandIn makeStandIn(const Mesh& mesh, float detail) {
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
