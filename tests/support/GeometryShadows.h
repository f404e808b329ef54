// Test oracle (no GL): which pixels of a view the scene's own triangles put in shadow,
// by brute-force ray casting. A shadow ray follows the light camera's model of the light
// (towards its eye for perspective cameras, against its view axis for orthographic ones) and
// only counts occluders inside the light camera's depth range: the map holds exactly those.
#pragma once

#include <vector>

#include "gnomon/Scene.h"

namespace gnomon::test {

enum class PixelClass {
    Unknown,   // near an edge, a silhouette or a shadow boundary, or too weakly lit to tell
    Shadowed,  // robustly in the shadow of at least one light that would light it
    Lit,       // robustly unshadowed by every light
    Background,
};

struct GeometryShadows {
    int width = 0, height = 0;
    std::vector<PixelClass> classes;  // row-major, top row first
    int count(PixelClass c) const;
};

// Classifies pixels on a grid with `stride` (others stay Unknown).
GeometryShadows classifyPixels(const Scene& scene, const RenderOptions& options, int stride);

}  // namespace gnomon::test
