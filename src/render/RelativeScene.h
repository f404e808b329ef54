// The scene a frame is drawn from, in coordinates relative to a point near it rather than to
// the world's origin (coordinateOrigin, scene/SceneUtil.h). A float keeps 24 bits: 100 000
// units out it steps by 0.008, and every matrix made there (a light's look-at, its fitted
// window, a cube face's projection) carries that much error in its translation. With only
// the GPU's matrices moved, maps drawn through such a matrix and looked up from the light's
// own position would disagree by it: rings of false shadow under a point light far out, and
// leaks all over a model a few centimetres long. So the renderer works on a copy of a far
// scene moved next to the origin, made once per scene revision; its camera and lights (which
// the revision does not cover) are moved again each frame. A scene around the origin is used
// as it is, without a copy.
#pragma once

#include <cstdint>

#include "gnomon/Scene.h"

namespace gnomon::render {

class RelativeScene {
public:
    // `scene` itself when it lies around the world's origin, else the moved copy (remade when
    // the scene's revision changed; its camera and lights follow `scene`'s every call).
    const Scene& of(const Scene& scene, double seconds);
    // A camera of the world (the fit camera of gnomon score's flicker) in those coordinates.
    Camera moved(const Camera& camera) const;

private:
    bool mValid = false;
    std::uint64_t mRevision = 0;
    glm::vec3 mOrigin{0.0f};
    Scene mCopy;
};

}  // namespace gnomon::render
