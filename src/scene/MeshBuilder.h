// Small procedural meshes for the built-in scenes and the tests: boxes, quads, triangles,
// with flat normals (each face its own vertices, so lighting shows the faces), and a smooth
// sphere.
#pragma once

#include "gnomon/Scene.h"

namespace gnomon::mesh {

// Axis-aligned box centred at `centre` with full extents `size`; normals point out.
Mesh box(const std::string& name, const glm::vec3& centre, const glm::vec3& size);
// Quad a-b-c-d (counter-clockwise seen from the side its normal points to).
Mesh quad(const std::string& name, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
          const glm::vec3& d);
// A UV sphere of `columns` x `rows` quads, smooth normals and texture coordinates; its first
// and last columns share positions but not coordinates (a texture seam, as loaders deliver
// meshes). Counter-clockwise seen from outside.
Mesh sphere(const std::string& name, const glm::vec3& centre, float radius, int columns, int rows);
// One triangle with per-vertex colours.
Mesh triangle(const std::string& name, const glm::vec3 (&p)[3], const glm::vec3 (&colour)[3]);

}  // namespace gnomon::mesh
