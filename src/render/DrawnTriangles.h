// Which triangle of the scene the main pass drew at a pixel, for a shadow ray to start on it
// as the reference's ray does (shaders/shadow_rays.glsl's rayStartBegin): every object's triangles
// numbered one after another, objects in the scene's order and each object's triangles in the
// order its mesh was uploaded (GpuScene reorders them for culling, splitForCulling and
// cutIntoPieces). A draw's first triangle's number rides with its record (DrawItem's
// firstTriangle, an instanced attribute) and a fragment adds gl_PrimitiveID, which counts the
// triangles of its draw; render::RayScene turns the number into its hierarchy's triangle.
// Read under --shadow-rays all and uncertain on OpenGL 4.5 only (shaders/main.frag.glsl's
// RAYS_FROM_DRAWN):
// OpenGL ES 3.0 (WebGL2) has neither base instances nor gl_PrimitiveID.
// No GL here.
#pragma once

#include <cstdint>
#include <vector>

#include "gnomon/Scene.h"
#include "scene/MeshTopology.h"

namespace gnomon::render {

class DrawnTriangles {
public:
    // Per mesh, where its triangles were uploaded: `splits`, one per mesh, in upload order.
    void setMeshes(const Scene& scene, const std::vector<CullingSplit>& splits);
    // Per object, its first triangle's number.
    void setObjects(const Scene& scene);
    std::uint32_t objectFirst(std::size_t object) const { return mObjectFirst[object]; }
    std::size_t objects() const { return mObjectFirst.size(); }
    // Mesh `mesh`'s triangle t was uploaded as its (places(mesh)[t])th (kNoPlace: unknown).
    const std::vector<std::uint32_t>& places(std::size_t mesh) const { return mPlaces[mesh]; }
    // Every object's triangles, counted.
    std::size_t total() const { return mTotal; }

private:
    std::vector<std::vector<std::uint32_t>> mPlaces;
    std::vector<std::uint32_t> mObjectFirst;
    std::size_t mTotal = 0;
};

}  // namespace gnomon::render
