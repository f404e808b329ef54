// What every model loader (glTF through tinygltf, other formats through assimp) and the
// scene-file reader do once the file's own content is read: defaults for what the file left
// out (a sun, a camera) and the settings a model is shown with. One place, so that a model
// looks the same whichever loader read it.
#pragma once

#include <functional>
#include <string>

#include "core/Aabb.h"
#include "gnomon/Scene.h"

namespace gnomon {

// What a loader read, for the step the loaders share (finishModelScene).
struct LoadedModel {
    std::string file;                // named in the error when nothing was read
    long zeroAreaTriangles = 0;      // skipped by the loader; reported once
    bool photometricLights = false;  // intensities in candela and lux (glTF)
    UpAxis up = UpAxis::Y;           // the model's up axis, turned to +y (--up)
    // Places the file's own camera, given the bounds of what is drawn; empty when the file
    // has no camera (one framing the model is added).
    std::function<void(Camera&, const Aabb& bounds)> placeCamera;
};

// The rotation that takes `up` to +y: Z-up models turn -90 degrees about x (+z to +y, +y to
// -z), X-up ones +90 degrees about z.
glm::mat4 worldFromUp(UpAxis up);

// The loaders' last step: the model turned by worldFromUp(loaded.up), objects whose material is
// textured but whose mesh has no texture coordinates untextured, skipped triangles reported,
// photometric lights scaled for display, a default sun when there is no light, the file's camera or
// one framing the model, and a model's render settings (512x512, sRGB output as viewers show
// authored colours). Throws gnomon::Error (InvalidInput, naming the file) when there is nothing to
// draw or the result is inconsistent.
void finishModelScene(Scene& scene, const LoadedModel& loaded);

// Objects whose material is textured but whose mesh has no texture coordinates get an
// untextured copy of that material (one copy per material).
void untextureObjectsWithoutUvs(Scene& scene);
// When `scene` has no lights, adds a default sun placed for scene.camera
// (defaultSunDirection) and says so in its warnings.
void addDefaultSun(Scene& scene);
// The default sun's direction of travel for a camera: over the camera's shoulder.
glm::vec3 defaultSunDirection(const Camera& camera);
// A 45-degree camera framing `bounds`, and a warning.
void frameWithCamera(Scene& scene, const Aabb& bounds);

}  // namespace gnomon
