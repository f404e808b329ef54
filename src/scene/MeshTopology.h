// Topology of a mesh's surface (no GL).
#pragma once

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
// those views leaked). Degenerate triangles are ignored. O(triangles), one hash map.
int closedWinding(const Mesh& mesh);

}  // namespace gnomon
