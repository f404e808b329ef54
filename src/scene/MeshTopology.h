// Topology of a mesh's surface (no GL).
#pragma once

#include <cstdint>
#include <vector>

#include "gnomon/Scene.h"

namespace gnomon {

// Does the mesh bound a solid, and which way is it wound? With vertices at the same position
// taken as one (glTF and OBJ split them at texture and normal seams), is every edge shared
// by exactly two triangles that run along it in opposite directions? Only then does culling
// a face in a shadow pass keep the caster: the back faces behind it cast the same shadow. An
// open surface (a leaf, a sign, a wall of zero thickness) casts from both sides or from none.
// 0 when it is not closed and consistently wound, else 1 wound outwards (counter-clockwise
// seen from outside: a positive enclosed volume), -1 inwards. An object's transform that
// mirrors turns it over, so culling is right where this times the sign of that transform's
// determinant is positive: a closed surface wound inwards in the world (some FBX exports,
// and assimp-testmodels' spider and skinned mesh) lost its light-facing side to culling, and
// what was left in the map was the side the camera sees, lit everywhere (34 and 100 % of
// those views leaked). Degenerate triangles are ignored. Closed: every triangle in
// splitForCulling's first group.
int closedWinding(const Mesh& mesh);

// A mesh's triangles reordered for culling in shadow passes: first those that lie on solids
// (`closedIndices` indices, three per triangle), then the rest, each group in the mesh's order.
// Culling the back faces of the first group keeps every shadow when the light is outside
// (`winding` 1: they are wound outwards, -1: inwards, 0: there are none).
//
// A solid here is a part of the surface whose every edge has two triangles running along it
// in opposite directions, nearly closed on its own (the areas of its faces, as vectors, sum to
// under 1 % of their total: what is missing is a few holes, not a side), on a connected piece
// of the mesh with no edge that only one triangle has (watertight). Its holes are then filled
// by the piece's other triangles, drawn from both sides, so a ray from outside still meets one
// of its front faces or a filler before any back face. A 3DS horse with a few faces wound the
// wrong way (glmark2's: 48 of 7 172 triangles) is such a solid with fillers; an open sheet, a
// box missing a side, or one with a whole side turned are not. (A solid whose texture cuts
// its faces is no solid for light: the shadow pass does not cull alpha-tested casters.)
struct CullingSplit {
    std::vector<std::uint32_t> indices;
    std::size_t closedIndices = 0;
    int winding = 0;
};
CullingSplit splitForCulling(const Mesh& mesh);

// Where each of `original`'s triangles (three indices each) lies among `reordered`'s, which
// hold the same triangles in another order, each one's corners in the same order (as
// splitForCulling and shadow::cutIntoPieces leave them); copies of a triangle take their
// places in order. All kNoPlace when the two do not hold the same triangles.
inline constexpr std::uint32_t kNoPlace = 0xffffffffu;
std::vector<std::uint32_t> trianglePlaces(const std::vector<std::uint32_t>& original,
                                          const std::vector<std::uint32_t>& reordered);

}  // namespace gnomon
