// The lights of `gnomon bench --sweep local-lights` (issue 63): N spot and point lights of
// limited range standing in the open space the view looks into, so that a sweep over N measures
// what many local lights cost on real content while the picture stays about as bright and as
// covered. Candidate places come from rays cast from the camera through a low-discrepancy
// pattern of the picture's points (Roberts' R2 sequence) into a BVH of the scene's triangles
// (the project's own, src/bvh): each light stands off the surface its ray met, towards the eye,
// clear of every other surface. The rule for ranges and intensities is in LocalLights.cpp and
// docs/results/performance.md ("Many local lights").
#pragma once

#include <vector>

#include "bvh/Bvh.h"
#include "gnomon/Scene.h"

namespace gnomon::cli {

// The most lights the sweep places: the renderer's limit on lights in one main pass.
inline constexpr int kMaxLocalLights = 256;

// The scene's triangles, every object posed at `seconds`, in world space, as a BVH (every
// triangle flagged a caster, so occluded() sees them all). Throws gnomon::Error (InvalidInput)
// for a scene without triangles, or with more than a BVH holds.
bvh::Bvh sceneHierarchy(const Scene& scene, double seconds);

// `count` (1..kMaxLocalLights) lights for `scene` seen through its camera in a picture of
// `aspect` (width / height; the camera's own aspect wins when it has one), posed at `seconds`:
// spot lights at even indices and point lights at odd ones, each with a range, inverse-square
// falloff, a shadow map of its default size, and its direction towards the surface it lights.
// The same arguments give the same lights, and the lights of any count stand on the same rays,
// in the same order, with the same kinds and directions: a larger count adds lights, and every
// light's range (and with it its distance from its surface and its intensity) follows the
// count. Throws gnomon::Error (InvalidInput) for a count out of range, a scene without
// triangles, or a view that shows too little of the scene to place `count` lights.
std::vector<Light> placeLocalLights(const Scene& scene, int count, float aspect,
                                    double seconds = 0.0);

// `gnomon bench --moving-lights`: `moved` is `base` with every spot and point light a little
// along a small horizontal circle of its own at frame `frame` (a fiftieth of its range, or of the
// scene's size without one; a full turn in 60 frames), so each frame every map changes.
// `moved` must start as a copy of `base`; only light positions are written.
void moveLights(const Scene& base, Scene& moved, int frame);

}  // namespace gnomon::cli
