// The view camera's matrices (no GL), used by the renderer, the shadow fits and the
// ray-traced reference alike, so the three agree on what a pixel looks at. Matrices are named
// bFromA: `viewFromWorld` takes world points into the camera's view space.
#pragma once

#include <glm/glm.hpp>

#include "gnomon/Scene.h"

namespace gnomon {

// A right-handed look-at that survives `up` parallel to the view direction (it then picks
// the world axis least aligned with the direction).
glm::mat4 safeLookAt(const glm::vec3& eye, const glm::vec3& centre, const glm::vec3& up);

// View-camera matrices for an output of `aspect` (width / height; the camera's own aspect
// wins where it has one).
glm::mat4 viewFromWorld(const Camera& camera);
glm::mat4 clipFromView(const Camera& camera, float aspect);

// The terms each pixel's ray is cast from, for an output of width x height: the view's own
// axes (the rows of viewFromWorld) and the projection's terms, not an inverted projection
// (with near and far as far apart as 0.05 and 10^6 that inverse keeps too few digits). The
// reference casts its camera rays from them (truth::Reference) and the renderer's shadow rays
// the same rays (render::PixelRayCamera), operation for operation.
struct PixelRayTerms {
    glm::vec3 right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f}, ahead{0.0f, 0.0f, -1.0f};
    float tanHalf = 1.0f, viewAspect = 1.0f;  // perspective: tan(fovy / 2), width / height
    float pixelAtUnit = 0.0f;                 // a pixel's size at view depth 1 (orthographic: any)
    bool ortho = false;
};
PixelRayTerms pixelRayTerms(const Camera& camera, int width, int height);

}  // namespace gnomon
