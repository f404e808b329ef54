// Stand-in casters: a coarser copy of a mesh drawn into shadow maps instead of the full one
// (the cheaper shadow geometry of W. Brown's course text, §12.6; engines call them shadow
// LODs or proxies). Made at load time with meshoptimizer: vertices welded by position (a
// depth pass needs no normals or texture seams), then simplified to the share of triangles
// asked for, or taken from the file where it gives coarser versions (glTF's MSFT_lod). The
// indices refer to the mesh's own vertices (a file's versions', after them), so the stand-in
// shares its vertex buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gnomon/Scene.h"

namespace gnomon::shadow {

struct StandIn {
    std::vector<std::uint32_t> indices;  // into the mesh's own vertices
    // meshoptimizer's reported error, in the mesh's units: how far the vertices it removed
    // lie from the stand-in's surface (faces sag up to about twice that further); 0 for the
    // mesh itself.
    float error = 0.0f;
};

// A stand-in keeping about `detail` (0 < detail <= 1) of the mesh's triangles: the mesh
// itself for 1 or for meshes too small to simplify. Simplification keeps the surface where
// it can (meshoptimizer's edge collapses); where seams and borders stop it short of the
// target, a cruder grid-based pass reaches it. A mesh whose file gives coarser versions
// (Mesh::lods) takes the one whose share of the triangles lies nearest `detail` (by ratio;
// the mesh itself when that is nearer), indexed past the mesh's own vertices: the versions'
// vertices follow them, in order (render::GpuScene lays them out so).
StandIn makeStandIn(const Mesh& mesh, float detail);
// How far the furthest vertex of `lod` lies from the surface of `mesh`: what the lookups'
// lift covers for a file's version, as meshoptimizer's reported error does for its own. At
// most kMaxDistanceTests vertex-triangle pairs are measured (vertices spread evenly).
float lodError(const Mesh& mesh, const MeshLod& lod);
constexpr std::size_t kMaxDistanceTests = 20'000'000;

}  // namespace gnomon::shadow
