// The GPU copy of a Scene: all meshes in one vertex and one index buffer (uploaded once per
// distinct geometry), and one std430 record per object (re-uploaded only when transforms or
// materials change, e.g. animation). Passes draw through draw().
#pragma once

#include <cstdint>
#include <vector>

#include "core/Aabb.h"
#include "gl/Objects.h"
#include "gnomon/Scene.h"

namespace gnomon::render {

struct GpuObject {
    glm::mat4 worldFromModel;
    glm::mat4 worldFromModelNormal;
    glm::vec4 baseColour;
    glm::vec4 material;  // specular, shininess, unlit, double-sided
    glm::vec4 flags;     // receives shadows
};

struct DrawItem {
    std::uint32_t object = 0;
    GLsizei indexCount = 0;
    std::size_t firstIndexByte = 0;
    GLint baseVertex = 0;
    bool doubleSided = false;
    bool casts = true;
    bool receives = true;
    Aabb bounds;                 // world space, at the synced time
    std::uint64_t dataHash = 0;  // of the object's GPU record: changes when it moves
};

class GpuScene {
public:
    // Makes the GPU copy match `scene` at `seconds`; returns true when anything changed.
    bool sync(const Scene& scene, double seconds);
    // Binds the vertex array and the object buffer (binding 0).
    void bind() const;
    // Issues one draw (`instances` copies); uniform location 0 receives the object index.
    void draw(const DrawItem& item, GLsizei instances = 1) const;
    const std::vector<DrawItem>& items() const { return mItems; }
    // World bounds of all objects (or casters only) at the synced time.
    const Aabb& bounds() const { return mBounds; }
    const Aabb& casterBounds() const { return mCasterBounds; }
    // Changes whenever geometry or object data changed.
    std::uint64_t revision() const { return mRevision; }
    // Content hash of all vertex and index data.
    std::uint64_t geometryHash() const { return mGeometryHash; }

private:
    void uploadGeometry(const Scene& scene);

    std::uint64_t mGeometryHash = 0;
    bool mHaveGeometry = false;
    gl::Buffer mVertices, mIndices, mObjects;
    gl::VertexArray mVao;
    std::vector<GpuObject> mObjectData;  // reused every frame, no allocation once sized
    std::vector<DrawItem> mItems;
    std::vector<std::pair<std::size_t, GLint>> mMeshRanges;  // first index byte, base vertex
    std::vector<Aabb> mMeshBounds;
    Aabb mBounds, mCasterBounds;
    std::uint64_t mRevision = 0;
};

}  // namespace gnomon::render
