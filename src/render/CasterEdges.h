// The edges of the casters' meshes where an outline may run, for the edge maps
// (render/EdgeMaps.h). Each edge is a line of two vertices that both carry its two ends and the
// far corners of the two triangles that share it: the vertex stage draws it only where, seen
// from the light, both triangles fold to the same side of it (a contour: the surface turns
// away from the light there, whatever the triangles' winding). An edge of one triangle (an
// open surface's border) or of more than two is always drawn: its second corner's w is 0.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "gnomon/Scene.h"

namespace gnomon::render {

struct EdgeVertex {
    glm::vec3 position;  // this end
    glm::vec3 other;     // the other end
    glm::vec3 cornerA;   // the far corner of a triangle on the edge
    glm::vec4 cornerB;   // the other triangle's (w 1), or w 0: no second triangle
};
static_assert(sizeof(EdgeVertex) == 13 * sizeof(float), "CasterEdges::sync's attribute offsets");

// `mesh`'s edges as line vertices (two per edge). Corners at the same position are one corner
// (meshes repeat a vertex where its normal or texture coordinates change).
std::vector<EdgeVertex> meshEdges(const Mesh& mesh);

class CasterEdges {
public:
    // Makes the lines of every mesh of `scene`, unless made already for `geometryHash`.
    void sync(const Scene& scene, std::uint64_t geometryHash);
    // Binds the lines' vertex array.
    void bind() const;
    // Draws mesh `mesh`'s lines (after bind()).
    void draw(std::uint32_t mesh) const;
    std::size_t bytes() const { return mLines.size(); }

private:
    std::uint64_t mHash = 0;
    bool mMade = false;
    gl::Buffer mLines;
    gl::VertexArray mVao;
    std::vector<std::pair<GLint, GLsizei>> mRanges;  // per mesh: first vertex, count
};

}  // namespace gnomon::render
