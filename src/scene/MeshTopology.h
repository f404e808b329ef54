// Topology of a mesh's surface (no GL).
#pragma once

#include "gnomon/Scene.h"

namespace gnomon {

// Does the mesh bound a solid: with vertices at the same position taken as one (glTF and
// OBJ split them at texture and normal seams), is every edge shared by exactly two
// triangles that run along it in opposite directions? Only then does culling a face in a
// shadow pass keep the caster: the back faces behind it cast the same shadow. An open
// surface (a leaf, a sign, a wall of zero thickness) casts from both sides or from none.
// Degenerate triangles are ignored. O(triangles), one hash map.
bool isClosedSurface(const Mesh& mesh);

}  // namespace gnomon
