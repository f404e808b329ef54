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

}  // namespace gnomon
