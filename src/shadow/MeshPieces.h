// A large mesh cut into pieces of nearby triangles, each with its own bounds, so that what sees
// only part of the mesh draws only the pieces it sees: a local light's map, whose range or
// cone holds a few metres of a building modelled as a handful of meshes, culls the pieces
// beyond it instead of drawing the whole mesh (the shadow passes cost per triangle drawn).
// The triangles are ordered along a space-filling curve first (meshoptimizer's spatial sort),
// so a run of them stays in one place. No GL here.
#pragma once

#include <cstdint>
#include <vector>

#include "core/Aabb.h"
#include "gnomon/Scene.h"

namespace gnomon::shadow {

struct MeshPiece {
    std::uint32_t firstIndex = 0;  // into the mesh's (reordered) indices
    std::uint32_t indexCount = 0;
    bool closed = false;  // lies in the group of triangles on solids (CullingSplit)
    Aabb bounds;          // model space
};

// Triangles in a piece, at most; meshes with fewer than twice as many stay whole.
inline constexpr std::uint32_t kPieceTriangles = 128;

// Cuts `indices` (a mesh's triangles, the first `closedIndices` of them on solids, as
// splitForCulling orders them) into pieces: each of the two groups is reordered in place
// along a space-filling curve and cut into runs of kPieceTriangles, so no piece mixes the
// groups. A mesh under 2 kPieceTriangles triangles keeps its order and is one piece.
std::vector<MeshPiece> cutIntoPieces(const std::vector<glm::vec3>& positions,
                                     std::vector<std::uint32_t>& indices,
                                     std::size_t closedIndices);

}  // namespace gnomon::shadow
